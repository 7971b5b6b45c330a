/* garotor/group.c: the three implementations of the group interface (group.h).
 *
 *   ga_group_cga     ga_rotor, Wareham-Lasenby's closed forms (rotor.h); the
 *                    algebra element is a twist, carried to the generator
 *                    B(xi) = -(w I3 + v n)/2 and back (docs/conventions.md).
 *   ga_group_se3     ga_mat4 rigid motions, Eberly's closed forms (mat4.h).
 *   ga_group_affine  ga_mat4 homogeneous matrices with det > 0, the general
 *                    expm/logm (mat4.h); algebra = top three rows of a 4x4
 *                    whose last row is zero.
 *
 * cga and se3 share the twist coordinates, so they share dexp (the closed-form
 * right Jacobian of SE(3)); affine computes dexp by its series.
 */
#include <math.h>
#include <string.h>

#include <garotor/group.h>
#include <garotor/mat4.h>
#include <garotor/rotor.h>

/* ---- twist helpers ------------------------------------------------------ */

static ga_twist twist_of(const double *x)
{
    ga_twist t = {{x[0], x[1], x[2]}, {x[3], x[4], x[5]}};
    return t;
}

static void twist_put(ga_twist t, double *x)
{
    x[0] = t.w.x;
    x[1] = t.w.y;
    x[2] = t.w.z;
    x[3] = t.v.x;
    x[4] = t.v.y;
    x[5] = t.v.z;
}

/* xi^ = [[w]x, v; 0 0 0 0] and back, for cga and se3 alike. vee reads the
 * skew part of the 3x3 block (ga_twist_vee) after checking that a is in the
 * algebra: last row zero, symmetric part within 1e-9 of the largest entry. */
static ga_mat4 twist_hat(const double *x) { return ga_twist_hat(twist_of(x)); }
static int twist_vee(ga_mat4 a, double *x)
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
    twist_put(ga_twist_vee(a), x);
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
    /* a rotation so small that |k| ~ 2 pi/th overflows (th ~ 1e-308) has no
     * representable other branch: x is kept (found by CI's libFuzzer run:
     * fuzz/regress/path/smooth-branch-tiny-rotation) */
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
static void twist_half_turn(double *x)
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
 * random: inside the half-turn band x is kept. */
static void twist_branch(const double *prev, double *x)
{
    double q0[4], q1[4];
    twist_quat(prev, q0);
    twist_quat(x, q1);
    if (q0[0] * q1[0] + q0[1] * q1[1] + q0[2] * q1[2] + q0[3] * q1[3] < -0.5 * GA_GROUP_HALF_TURN_BAND)
        twist_other_branch(x);
}

static ga_vec3 v3(double x, double y, double z)
{
    ga_vec3 r = {x, y, z};
    return r;
}

/* sum_{k=0}^{11} (-1)^k m_k th^2k/(2k+d)!, m_k = k+1 if weighted else 1: the
 * Taylor series of the Jacobian coefficients below, used for th < 1 where the
 * closed forms cancel (the next term is below 1e-23 there). */
static double jac_series(double t2, int d, int weighted)
{
    double term = 1.0, s = 0.0;
    for (int j = 2; j <= d; ++j) term /= j;
    for (int k = 0; k < 12; ++k) {
        s += (weighted ? k + 1 : 1) * term;
        term *= -t2 / ((2.0 * k + d + 1) * (2.0 * k + d + 2));
    }
    return s;
}

/* The right Jacobian of SE(3) in twist coordinates (w, v): J_r(xi) = J_l(-xi),
 * with J_l of Barfoot & Furgale (2014, eqs. 100-102), here in (w, v) order:
 *   J_r(xi) (w', v') = ( Jr(w) w',  Q w' + Jr(w) v' ),
 *   Jr(w) = I - ((1 - cos th)/th^2) W + ((th - sin th)/th^3) W^2,
 *   Q = -V/2 + a (WV + VW - WVW) - b (WWV + VWW - 3 WVW) + c (WVWW + WWVW),
 * W = [w]x, V = [v]x, th = |w|, a = (th - sin th)/th^3,
 * b = (th^2 + 2 cos th - 2)/(2 th^4), c = (2 th - 3 sin th + th cos th)/(2 th^5).
 * Every matrix is applied as a chain of cross products. Tested against finite
 * differences of exp and against the affine series (tests/test_interp.c). */
static void se3_dexp(const double *x, const double *y, double *out)
{
    ga_vec3 w = v3(x[0], x[1], x[2]), v = v3(x[3], x[4], x[5]);
    ga_vec3 dw = v3(y[0], y[1], y[2]), dv = v3(y[3], y[4], y[5]);
    double t2 = w.x * w.x + w.y * w.y + w.z * w.z, th = sqrt(t2);
    double h = 0.5 * th, sh = h > 0 ? sin(h) / h : 1.0; /* sinc(th/2) */
    double a1 = 0.5 * sh * sh;                          /* (1 - cos th)/th^2 */
    double a, b, c;
    if (th < 1.0) {
        a = jac_series(t2, 3, 0);
        b = jac_series(t2, 4, 0);
        c = jac_series(t2, 5, 1);
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

/* ---- cga: rotors ---------------------------------------------------------- */

static void cga_identity(void *out) { *(ga_rotor *)out = ga_rotor_identity(); }
static void cga_compose(const void *a, const void *b, void *out)
{
    *(ga_rotor *)out = ga_rotor_mul(*(const ga_rotor *)a, *(const ga_rotor *)b);
}
static int cga_inverse(const void *a, void *out)
{
    *(ga_rotor *)out = ga_rotor_reverse(*(const ga_rotor *)a);
    return GA_OK;
}
/* exp and log report a result that is not finite (the group's contract: a
 * status, never Inf or NaN with GA_OK). NaN/Inf in is GA_ERR_NOTFINITE; finite
 * in and not finite out is GA_ERR_DOMAIN: ga_rotor_exp of a translation near
 * DBL_MAX (an angle beyond ~1e154 was one too, until its phi^2 no longer
 * overflowed), a twist = 2 generator
 * beyond DBL_MAX (found by fuzz/fuzz_path and fuzz/fuzz_tool: `garotor exp`
 * printed nan; fuzz/regress/path/cga-exp-overflow replays it). */
static int finite_status(const double *in, int n_in, const double *out, int n_out)
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
static int cga_exp(const double *x, void *out)
{
    /* B(xi) = -(w I3 + v n)/2 (ga_twist_to_generator), read from x in place */
    ga_generator b = {-0.5 * x[2], 0.5 * x[1], -0.5 * x[0], -0.5 * x[3], -0.5 * x[4], -0.5 * x[5]};
    ga_rotor r = ga_rotor_exp(b);
    int st = finite_status(x, 6, &r.s, 8);
    if (st == GA_OK)
        *(ga_rotor *)out = r;
    return st;
}
static int cga_log(const void *g, double *x)
{
    ga_generator b;
    int st = ga_rotor_log(*(const ga_rotor *)g, &b);
    if (st != GA_OK)
        return st;
    ga_twist t = ga_generator_to_twist(b);
    st = finite_status(NULL, 0, &t.w.x, 6);
    if (st == GA_OK)
        twist_put(t, x);
    return st;
}
/* Ad_R B = R B ~R, computed in the compact 8-component form, which is closed
 * under the product for any q, P (rotor.h); B sits in its bivector slots. */
static void cga_adjoint(const void *g, const double *x, double *out)
{
    ga_rotor r = *(const ga_rotor *)g;
    ga_generator b = ga_twist_to_generator(twist_of(x));
    ga_rotor bb = {0.0, b.e12, b.e13, b.e23, b.e1n, b.e2n, b.e3n, 0.0};
    ga_rotor s = ga_rotor_mul(ga_rotor_mul(r, bb), ga_rotor_reverse(r));
    ga_generator o = {s.e12, s.e13, s.e23, s.e1n, s.e2n, s.e3n};
    twist_put(ga_generator_to_twist(o), out);
}
/* (quaternion, translation) of a rotor: r = T_t q (rotor.h) */
static void cga_to_qt(const void *g, double q[4], double p[3])
{
    ga_rotor r = *(const ga_rotor *)g;
    ga_quat a = ga_rotor_to_quat(r);
    ga_vec3 t = ga_rotor_to_translation(r);
    q[0] = a.w;
    q[1] = a.x;
    q[2] = a.y;
    q[3] = a.z;
    p[0] = t.x;
    p[1] = t.y;
    p[2] = t.z;
}
static void cga_from_qt(const double q[4], const double p[3], void *out)
{
    ga_quat a = {q[0], q[1], q[2], q[3]};
    *(ga_rotor *)out = ga_rotor_from_quat(a, v3(p[0], p[1], p[2]));
}
static int cga_from_mat4(ga_mat4 m, void *out) { return ga_rotor_from_mat4(m, (ga_rotor *)out); }
static ga_mat4 cga_to_mat4(const void *g) { return ga_rotor_to_mat4(*(const ga_rotor *)g); }

const ga_group ga_group_cga = {
    .name = "cga",
    .elem_size = sizeof(ga_rotor),
    .dim = 6,
    .rigid = 1,
    .identity = cga_identity,
    .compose = cga_compose,
    .inverse = cga_inverse,
    .exp = cga_exp,
    .log = cga_log,
    .adjoint = cga_adjoint,
    .dexp = se3_dexp,
    .from_mat4 = cga_from_mat4,
    .to_mat4 = cga_to_mat4,
    .hat = twist_hat,
    .vee = twist_vee,
    .half_turn = twist_half_turn,
    .branch = twist_branch,
    .to_qt = cga_to_qt,
    .from_qt = cga_from_qt,
};

/* ---- se3: rigid-motion matrices ----------------------------------------- */

static void m4_identity(void *out) { *(ga_mat4 *)out = ga_mat4_identity(); }
static void m4_compose(const void *a, const void *b, void *out)
{
    *(ga_mat4 *)out = ga_mat4_mul(*(const ga_mat4 *)a, *(const ga_mat4 *)b);
}
static int se3_inverse(const void *a, void *out)
{
    *(ga_mat4 *)out = ga_se3_inverse(*(const ga_mat4 *)a);
    return GA_OK;
}
static int se3_exp(const double *x, void *out)
{
    ga_mat4 m = ga_se3_exp(twist_of(x));
    int st = finite_status(x, 6, m.m, 16);
    if (st == GA_OK)
        *(ga_mat4 *)out = m;
    return st;
}
static int se3_log(const void *g, double *x)
{
    ga_twist t;
    int st = ga_se3_log(*(const ga_mat4 *)g, &t);
    if (st == GA_OK)
        twist_put(t, x);
    return st;
}
static void se3_adjoint(const void *g, const double *x, double *out)
{
    twist_put(ga_se3_adjoint(*(const ga_mat4 *)g, twist_of(x)), out);
}
static int se3_from_mat4(ga_mat4 m, void *out)
{
    int st = ga_se3_check(m, GA_SE3_TOL);
    if (st == GA_OK)
        *(ga_mat4 *)out = m;
    return st;
}
static ga_mat4 m4_to_mat4(const void *g) { return *(const ga_mat4 *)g; }

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
    .identity = m4_identity,
    .compose = m4_compose,
    .inverse = se3_inverse,
    .exp = se3_exp,
    .log = se3_log,
    .adjoint = se3_adjoint,
    .dexp = se3_dexp,
    .from_mat4 = se3_from_mat4,
    .to_mat4 = m4_to_mat4,
    .hat = twist_hat,
    .vee = twist_vee,
    .half_turn = twist_half_turn,
    .branch = twist_branch,
    .to_qt = se3_to_qt,
    .from_qt = se3_from_qt,
};

/* ---- affine: homogeneous matrices, general expm/logm ------------------------ */

/* Algebra element (12 doubles, rows 0..2) <-> 4x4 with a zero last row. */
static ga_mat4 aff_hat(const double *x)
{
    ga_mat4 a;
    memcpy(a.m, x, 12 * sizeof(double));
    a.m[12] = a.m[13] = a.m[14] = a.m[15] = 0.0;
    return a;
}
static void aff_vee(ga_mat4 a, double *x) { memcpy(x, a.m, 12 * sizeof(double)); }
static int aff_vee_checked(ga_mat4 a, double *x)
{
    for (int i = 0; i < 16; ++i)
        if (!isfinite(a.m[i]))
            return GA_ERR_NOTFINITE;
    if (a.m[12] != 0.0 || a.m[13] != 0.0 || a.m[14] != 0.0 || a.m[15] != 0.0)
        return GA_ERR_ARG;
    aff_vee(a, x);
    return GA_OK;
}

static int aff_inverse(const void *a, void *out)
{
    ga_mat4 r;
    int st = ga_mat4_inverse(*(const ga_mat4 *)a, &r);
    if (st != GA_OK)
        return st;
    r.m[12] = r.m[13] = r.m[14] = 0.0;
    r.m[15] = 1.0; /* exactly homogeneous */
    *(ga_mat4 *)out = r;
    return GA_OK;
}
static int aff_exp(const double *x, void *out)
{
    ga_mat4 r;
    int st = ga_mat4_expm(aff_hat(x), &r);
    if (st != GA_OK)
        return st;
    r.m[12] = r.m[13] = r.m[14] = 0.0;
    r.m[15] = 1.0; /* exp of a zero last row */
    *(ga_mat4 *)out = r;
    return GA_OK;
}
static int aff_log(const void *g, double *x)
{
    ga_mat4 l;
    int st = ga_mat4_logm(*(const ga_mat4 *)g, &l);
    if (st == GA_OK)
        aff_vee(l, x);
    return st;
}
static void aff_adjoint(const void *g, const double *x, double *out)
{
    ga_mat4 gi, m = *(const ga_mat4 *)g;
    if (aff_inverse(&m, &gi) != GA_OK) {
        for (int i = 0; i < 12; ++i) out[i] = NAN;
        return;
    }
    aff_vee(ga_mat4_mul(ga_mat4_mul(m, aff_hat(x)), gi), out);
}
/* GA_ERR_NOTFINITE for NaN/Inf; GA_ERR_DOMAIN if the last row is not 0 0 0 1 to
 * 1e-12 or det < 0 (a reflection: no real log); GA_ERR_SINGULAR if det = 0. */
static int aff_from_mat4(ga_mat4 m, void *out)
{
    for (int i = 0; i < 16; ++i)
        if (!isfinite(m.m[i]))
            return GA_ERR_NOTFINITE;
    if (fabs(m.m[12]) > 1e-12 || fabs(m.m[13]) > 1e-12 || fabs(m.m[14]) > 1e-12 ||
        fabs(m.m[15] - 1.0) > 1e-12)
        return GA_ERR_DOMAIN;
    double det = m.m[0] * (m.m[5] * m.m[10] - m.m[6] * m.m[9]) -
                 m.m[1] * (m.m[4] * m.m[10] - m.m[6] * m.m[8]) + m.m[2] * (m.m[4] * m.m[9] - m.m[5] * m.m[8]);
    if (!(det > 0.0))
        return det == 0.0 ? GA_ERR_SINGULAR : GA_ERR_DOMAIN;
    m.m[12] = m.m[13] = m.m[14] = 0.0;
    m.m[15] = 1.0;
    *(ga_mat4 *)out = m;
    return GA_OK;
}

static ga_mat4 m4_lin(double s, ga_mat4 a, double t, ga_mat4 b) /* s a + t b */
{
    for (int i = 0; i < 16; ++i) a.m[i] = s * a.m[i] + t * b.m[i];
    return a;
}

/* J_r(X) Y = sum_k (-ad_X)^k Y/(k+1)! for any 4x4 X: the series at X/2^s
 * (||X/2^s||_1 <= 1/2, 20 terms, truncation below 1e-20), then s doublings by
 *   J_r(2X)(2Y) = Ad_{exp(-X)} J_r(X) Y + J_r(X) Y,
 * which is the body velocity of exp(X)exp(X) (product rule). exp(+-X/2^s) are
 * summed from their Taylor series (18 terms) and squared along. */
static void aff_dexp(const double *x, const double *y, double *out)
{
    ga_mat4 X = aff_hat(x), Y = aff_hat(y);
    double nx = ga_mat4_norm1(X);
    int s = 0;
    while (nx > 0.5 && s < 1100) {
        nx *= 0.5;
        ++s;
    }
    double sc = ldexp(1.0, -s);
    X = m4_lin(sc, X, 0.0, X);
    Y = m4_lin(sc, Y, 0.0, Y);
    /* b = sum (-1)^k ad^k Y/(k+1)!, term_k = ad^k Y */
    ga_mat4 term = Y, b = Y;
    double f = 1.0;
    for (int k = 1; k <= 20; ++k) {
        term = m4_lin(1.0, ga_mat4_mul(X, term), -1.0, ga_mat4_mul(term, X));
        f *= (double)(k + 1);
        b = m4_lin(1.0, b, (k % 2 ? -1.0 : 1.0) / f, term);
    }
    ga_mat4 E = ga_mat4_identity(), F = E, pe = E, pf = E;
    double g = 1.0;
    for (int k = 1; k <= 18; ++k) {
        g *= (double)k;
        pe = ga_mat4_mul(pe, X);
        pf = ga_mat4_mul(pf, m4_lin(-1.0, X, 0.0, X));
        E = m4_lin(1.0, E, 1.0 / g, pe);
        F = m4_lin(1.0, F, 1.0 / g, pf);
    }
    for (int i = 0; i < s; ++i) {
        b = m4_lin(1.0, ga_mat4_mul(ga_mat4_mul(F, b), E), 1.0, b);
        E = ga_mat4_mul(E, E);
        F = ga_mat4_mul(F, F);
    }
    aff_vee(b, out);
}

const ga_group ga_group_affine = {
    .name = "affine",
    .elem_size = sizeof(ga_mat4),
    .dim = 12,
    .rigid = 0,
    .identity = m4_identity,
    .compose = m4_compose,
    .inverse = aff_inverse,
    .exp = aff_exp,
    .log = aff_log,
    .adjoint = aff_adjoint,
    .dexp = aff_dexp,
    .from_mat4 = aff_from_mat4,
    .to_mat4 = m4_to_mat4,
    .hat = aff_hat,
    .vee = aff_vee_checked,
    .half_turn = NULL,
    .branch = NULL,
    .to_qt = NULL,
    .from_qt = NULL,
};

static const ga_group *const groups[] = {&ga_group_cga, &ga_group_se3, &ga_group_affine};

const ga_group *ga_group_nth(size_t i) { return i < sizeof groups / sizeof groups[0] ? groups[i] : NULL; }

const ga_group *ga_group_by_name(const char *name)
{
    for (size_t i = 0; name && i < sizeof groups / sizeof groups[0]; ++i)
        if (strcmp(name, groups[i]->name) == 0)
            return groups[i];
    return NULL;
}
