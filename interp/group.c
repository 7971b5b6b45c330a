/* interp/group.c: what the groups of group.h have in common: the list of
 * them (ga_group_nth, ga_group_by_name) with their internal fast operations
 * (internal/group_fast.h), the twist coordinates that cga and se3 share
 * (hat and vee, the half-turn and branch rules, the closed-form right
 * Jacobian of SE(3)), and the 4x4 basics of se3 and affine. The groups
 * themselves: group_cga.c, group_se3.c, group_affine.c.
 */
#include <math.h>
#include <string.h>

#include <garotor/group.h>
#include <garotor/mat4.h>
#include <garotor/rotor.h>

#include "ga/internal/series.h"
#include "ga/internal/vec3.h"
#include "internal/group_fast.h"
#include "internal/groups.h"

/* ---- twists: hat and vee ----------------------------------------------------------- */

/* xi^ = [[w]x, v; 0 0 0 0] and back, for cga and se3 alike. vee reads the
 * skew part of the 3x3 block (ga_twist_vee) after checking that a is in the
 * algebra: last row zero, symmetric part within 1e-9 of the largest entry. */
ga_mat4 gig_twist_hat(const double *x) { return ga_twist_hat(gig_twist_of(x)); }
int gig_twist_vee(ga_mat4 a, double *x)
{
    double big = 0.0, sym = 0.0;
    for (int i = 0; i < 16; ++i) {
        if (!isfinite(a.m[i]))
            return GA_ERR_NOTFINITE;
        big = fmax(big, fabs(a.m[i]));
    }
    for (int r = 0; r < 3; ++r)
        for (int c = r; c < 3; ++c) sym = fmax(sym, fabs(a.m[4 * r + c] + a.m[4 * c + r]));
    if (a.m[12] != 0.0 || a.m[13] != 0.0 || a.m[14] != 0.0 || a.m[15] != 0.0 || sym > 1e-9 * big)
        return GA_ERR_ARG;
    gig_twist_put(ga_twist_vee(a), x);
    return GA_OK;
}

/* ---- the half-turn and branch rules of twists (group.h) ------------------- */

#define PI 3.14159265358979323846

/* |w|, also where the squares would underflow or overflow (|w| below ~1e-154
 * or above ~1e154): the other branch scales w by (th - 2 pi)/th, so th keeps
 * its relative accuracy at any size (bit for bit the plain formula between). */
static double twist_angle(const double *x)
{
    double s = x[0] * x[0] + x[1] * x[1] + x[2] * x[2];
    double m = fmax(fabs(x[0]), fmax(fabs(x[1]), fabs(x[2])));
    if ((s >= 0x1p-1000 && s <= 0x1p1000) || !(m > 0) || isinf(m))
        return sqrt(s);
    double a = x[0] / m, b = x[1] / m, c = x[2] / m;
    return m * sqrt(a * a + b * b + c * c);
}

/* The other branch of a twist of angle th > 0: angle th - 2 pi about the same
 * axis, w' = k w, v' = k v_perp + v_par, k = (th - 2 pi)/th. Same motion:
 * Eberly's V of eq. 20 acts as 1 along w and as i(1 - e^{i th})/th across it,
 * so V(w')^-1 V(w) = k across, 1 along. */
static void twist_other_branch(double *x)
{
    double th = twist_angle(x);
    if (th == 0.0)
        return;
    double k = (th - 2.0 * PI) / th;
    /* v_par = (w.v / th^2) w; where th^2 would underflow, through the unit axis */
    double vp = th >= 0x1p-500 ? (x[0] * x[3] + x[1] * x[4] + x[2] * x[5]) / (th * th)
                               : ((x[0] / th) * x[3] + (x[1] / th) * x[4] + (x[2] / th) * x[5]) / th;
    double y[6];
    for (int i = 0; i < 3; ++i) {
        double par = vp * x[i];
        y[3 + i] = k * (x[3 + i] - par) + par;
        y[i] = k * x[i];
    }
    /* an other branch that overflows (|k| v_perp near DBL_MAX; |k| itself at
     * th ~ 1e-308, which the branch rule no longer offers) is not
     * representable: x is kept */
    for (int i = 0; i < 6; ++i)
        if (!isfinite(y[i]))
            return;
    memcpy(x, y, sizeof y);
}

/* The rotation quaternion (cos(th/2), sin(th/2) w/th) of a twist. */
static void twist_quat(const double *x, double q[4])
{
    double th = twist_angle(x), h = 0.5 * th;
    double f = h > 0 ? 0.5 * sin(h) / h : 0.5; /* sin(th/2)/th */
    q[0] = cos(h);
    q[1] = f * x[0];
    q[2] = f * x[1];
    q[3] = f * x[2];
}

/* Deterministic axis at a half turn (group.h half_turn): within
 * GA_GROUP_HALF_TURN_BAND of pi, the first axis component larger than 0.3 in
 * magnitude is made positive. */
void gig_twist_half_turn(double *x)
{
    double th = twist_angle(x);
    if (!(th >= PI - GA_GROUP_HALF_TURN_BAND))
        return;
    for (int i = 0; i < 3; ++i)
        if (fabs(x[i]) > 0.3 * th) {
            if (x[i] < 0)
                twist_other_branch(x);
            return;
        }
}

/* The branch of x that continues prev (group.h branch): W-L's rotor rule
 * <R_i ~R_{i-1}>_0 >= 0 in twist coordinates. A relative half turn
 * (dot = cos(relative angle/2) ~ 0) is a tie that rounding would break at
 * random: inside the half-turn band x is kept. So is a rotation th below the
 * band, whose other branch is a full turn less th: its w' and v_perp' are
 * |k| ~ 2 pi/th times the principal's (a turn about an axis at distance
 * |v_perp|/th), and its axis rests on the key's rounding (found by CI's fuzz
 * run: fuzz/regress/path/smooth-matrix-velocity-domain, th = 2.5e-307 and
 * |v'| = 3.1e306). */
void gig_twist_branch(const double *prev, double *x)
{
    double q0[4], q1[4];
    if (twist_angle(x) < GA_GROUP_HALF_TURN_BAND)
        return;
    twist_quat(prev, q0);
    twist_quat(x, q1);
    if (q0[0] * q1[0] + q0[1] * q1[1] + q0[2] * q1[2] + q0[3] * q1[3] < -0.5 * GA_GROUP_HALF_TURN_BAND)
        twist_other_branch(x);
}

/* The right Jacobian of SE(3) in twist coordinates (w, v): J_r(xi) = J_l(-xi),
 * with J_l of Barfoot & Furgale (2014, eqs. 100-102), here in (w, v) order:
 *   J_r(xi) (w', v') = ( Jr(w) w',  Q w' + Jr(w) v' ),
 *   Jr(w) = I - ((1 - cos th)/th^2) W + ((th - sin th)/th^3) W^2,
 *   Q = -V/2 + a (WV + VW - WVW) - b (WWV + VWW - 3 WVW) + c (WVWW + WWVW),
 * W = [w]x, V = [v]x, th = |w|, a = (th - sin th)/th^3,
 * b = (th^2 + 2 cos th - 2)/(2 th^4), c = (2 th - 3 sin th + th cos th)/(2 th^5).
 * Every matrix is applied as a chain of cross products. */
void gig_se3_dexp(const double *x, const double *y, double *out)
{
    ga_vec3 w = ga__v3(x[0], x[1], x[2]), v = ga__v3(x[3], x[4], x[5]);
    ga_vec3 dw = ga__v3(y[0], y[1], y[2]), dv = ga__v3(y[3], y[4], y[5]);
    double t2 = ga__v3_dot(w, w), th = sqrt(t2);
    double h = 0.5 * th, sh = h > 0 ? sin(h) / h : 1.0; /* sinc(th/2) */
    double a1 = 0.5 * sh * sh;                          /* (1 - cos th)/th^2 */
    double a, b, c;
    if (th < 1.0) {
        /* their Taylor series (rows F3, F4, JC of series.h) where the closed
           forms cancel; 12 terms: the next is below 1e-23 for th < 1 */
        a = ga__series(GA__SERIES_F3, 12, t2);
        b = ga__series(GA__SERIES_F4, 12, t2);
        c = ga__series(GA__SERIES_JC, 12, t2);
    } else {
        double s = sin(th), co = cos(th);
        a = (th - s) / (t2 * th);
        b = (t2 + 2.0 * co - 2.0) / (2.0 * t2 * t2);
        c = (2.0 * th - 3.0 * s + th * co) / (2.0 * t2 * t2 * th);
    }
    /* Jr(w) dw, Q dw + Jr(w) dv as chains of cross products: written by
     * gen/generate.py from the formula above (`python3 gen/generate.py` rewrites it) */
#include "se3_dexp.inc"
}

/* ---- 4x4 matrices (se3, affine) ---------------------------------------------------- */

void gig_m4_identity(void *out) { *(ga_mat4 *)out = ga_mat4_identity(); }
void gig_m4_compose(const void *a, const void *b, void *out)
{
    *(ga_mat4 *)out = ga_mat4_mul(*(const ga_mat4 *)a, *(const ga_mat4 *)b);
}
ga_mat4 gig_m4_to_mat4(const void *g) { return *(const ga_mat4 *)g; }

/* ---- the list of groups ------------------------------------------------------------- */

static const ga_group *const groups[] = {&ga_group_cga, &ga_group_se3, &ga_group_affine};

const ga_group *ga_group_nth(size_t i) { return i < sizeof groups / sizeof groups[0] ? groups[i] : NULL; }

const ga_group *ga_group_by_name(const char *name)
{
    for (size_t i = 0; name && i < sizeof groups / sizeof groups[0]; ++i)
        if (strcmp(name, groups[i]->name) == 0)
            return groups[i];
    return NULL;
}
