/* interp/group_se3.c: ga_group_se3 ("matrix"), SE(3) as 4x4 rigid-motion
 * matrices (ga_mat4) with Eberly's closed forms (mat4.h), in the twist
 * coordinates it shares with cga (group.c).
 */
#include <math.h>
#include <string.h>

#include <garotor/group.h>
#include <garotor/mat4.h>

#include "internal/groups.h"

static int se3_inverse(const void *a, void *out)
{
    *(ga_mat4 *)out = ga_se3_inverse(*(const ga_mat4 *)a);
    return GA_OK;
}
static int se3_exp(const double *x, void *out)
{
    ga_mat4 m = ga_se3_exp(gig_twist_of(x));
    int st = gig_finite_status(x, 6, m.m, 16);
    if (st == GA_OK)
        *(ga_mat4 *)out = m;
    return st;
}
static int se3_log(const void *g, double *x)
{
    ga_twist t;
    int st = ga_se3_log(*(const ga_mat4 *)g, &t);
    if (st == GA_OK)
        gig_twist_put(t, x);
    return st;
}
static void se3_adjoint(const void *g, const double *x, double *out)
{
    gig_twist_put(ga_se3_adjoint(*(const ga_mat4 *)g, gig_twist_of(x)), out);
}
static int se3_from_mat4(ga_mat4 m, void *out)
{
    int st = ga_se3_check(m, GA_SE3_TOL);
    if (st == GA_OK)
        *(ga_mat4 *)out = m;
    return st;
}

/* The quaternion of the rotation block by Shepperd's method (the largest of
 * 1 + trace, 1 + 2 m_kk - trace gives the divisor; Shepperd 1978), written
 * here for the matrix group on its own, not through the rotor bridge, so that
 * cga and matrix stay two computations (group.h). */
static void se3_to_qt(const void *g, double q[4], double p[3])
{
    const double *m = ((const ga_mat4 *)g)->m;
    double tr = m[0] + m[5] + m[10],
           c[4] = {1.0 + tr, 1.0 + 2 * m[0] - tr, 1.0 + 2 * m[5] - tr, 1.0 + 2 * m[10] - tr};
    int k = 0;
    for (int i = 1; i < 4; ++i)
        if (c[i] > c[k])
            k = i;
    double s = 0.5 * sqrt(c[k]), f = 0.25 / s;
    /* 4 w x = m21 - m12, 4 w y = m02 - m20, 4 w z = m10 - m01,
       4 x y = m01 + m10, 4 x z = m02 + m20, 4 y z = m12 + m21 */
    double wx = m[9] - m[6], wy = m[2] - m[8], wz = m[4] - m[1], xy = m[1] + m[4], xz = m[2] + m[8],
           yz = m[6] + m[9];
    switch (k) {
    case 0: q[0] = s, q[1] = wx * f, q[2] = wy * f, q[3] = wz * f; break;
    case 1: q[0] = wx * f, q[1] = s, q[2] = xy * f, q[3] = xz * f; break;
    case 2: q[0] = wy * f, q[1] = xy * f, q[2] = s, q[3] = yz * f; break;
    default: q[0] = wz * f, q[1] = xz * f, q[2] = yz * f, q[3] = s; break;
    }
    p[0] = m[3];
    p[1] = m[7];
    p[2] = m[11];
}
/* [Rot(q), p; 0 0 0 1] with Rot(q) the usual rotation matrix of a unit quaternion */
static void se3_from_qt(const double q[4], const double p[3], void *out)
{
    double w = q[0], x = q[1], y = q[2], z = q[3];
    ga_mat4 m = {{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y), p[0],
                  2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x), p[1],
                  2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y), p[2], 0, 0, 0, 1}};
    *(ga_mat4 *)out = m;
}

const ga_group ga_group_se3 = {
    .name = "matrix",
    .elem_size = sizeof(ga_mat4),
    .dim = 6,
    .rigid = 1,
    .identity = gig_m4_identity,
    .compose = gig_m4_compose,
    .inverse = se3_inverse,
    .exp = se3_exp,
    .log = se3_log,
    .adjoint = se3_adjoint,
    .dexp = gig_se3_dexp,
    .from_mat4 = se3_from_mat4,
    .to_mat4 = gig_m4_to_mat4,
    .hat = gig_twist_hat,
    .vee = gig_twist_vee,
    .half_turn = gig_twist_half_turn,
    .branch = gig_twist_branch,
    .to_qt = se3_to_qt,
    .from_qt = se3_from_qt,
};
