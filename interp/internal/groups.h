/* interp/internal/groups.h (internal, not installed): what the three groups
 * of group.h share: the twist coordinates of cga and se3 (hat and vee, the
 * half-turn and branch rules, the right Jacobian of SE(3)), the 4x4 helpers
 * of se3 and affine, and the status of an exp or log that came out not
 * finite. Defined in group.c; the groups in group_cga.c, group_se3.c,
 * group_affine.c. Prefix gig_; nothing here is exported.
 */
#ifndef GA_INTERP_INTERNAL_GROUPS_H
#define GA_INTERP_INTERNAL_GROUPS_H

#include <math.h>

#include <garotor/group.h>
#include <garotor/mat4.h>

#include "group_fast.h"

static inline ga_twist gig_twist_of(const double *x)
{
    ga_twist t = {{x[0], x[1], x[2]}, {x[3], x[4], x[5]}};
    return t;
}

static inline void gig_twist_put(ga_twist t, double *x)
{
    x[0] = t.w.x;
    x[1] = t.w.y;
    x[2] = t.w.z;
    x[3] = t.v.x;
    x[4] = t.v.y;
    x[5] = t.v.z;
}

/* exp and log report a result that is not finite (the group's contract: a
 * status, never Inf or NaN with GA_OK). NaN/Inf in is GA_ERR_NOTFINITE; finite
 * in and not finite out is GA_ERR_DOMAIN: ga_rotor_exp of a translation near
 * DBL_MAX, a twist = 2 generator beyond DBL_MAX. */
static inline int gig_finite_status(const double *in, int n_in, const double *out, int n_out)
{
    /* The common case in a few operations and one branch: v - v is 0 for a
     * finite v and NaN for Inf and NaN, and NaN survives the sums (summed as
     * a tree, so the check adds little latency). A non-finite input makes
     * these exps' results non-finite too, so finite results need no look at
     * the input; the rest is sorted out only when the check fails. */
    double z[4] = {0.0, 0.0, 0.0, 0.0};
    for (int i = 0; i < n_out; ++i) z[i & 3] += out[i] - out[i];
    if ((z[0] + z[1]) + (z[2] + z[3]) == 0.0)
        return GA_OK;
    for (int i = 0; i < n_in; ++i)
        if (!isfinite(in[i]))
            return GA_ERR_NOTFINITE;
    return GA_ERR_DOMAIN;
}

/* xi^ = [[w]x, v; 0 0 0 0] and back (group.h hat, vee) */
ga_mat4 gig_twist_hat(const double *x);
int gig_twist_vee(ga_mat4 a, double *x);
/* group.h half_turn and branch for twists */
void gig_twist_half_turn(double *x);
void gig_twist_branch(const double *prev, double *x);
/* group.h dexp for twists: the right Jacobian of SE(3) */
void gig_se3_dexp(const double *x, const double *y, double *out);

/* identity, product and to_mat4 of the 4x4 groups (se3, affine) */
void gig_m4_identity(void *out);
void gig_m4_compose(const void *a, const void *b, void *out);
ga_mat4 gig_m4_to_mat4(const void *g);

#endif
