/* ga/jacobian.c: the Lie-group Jacobians of rigid motions (jacobian.h).
 *
 * Twists are (w, v), angular part first. With W = [w]x, V = [v]x, th = |w|:
 *
 *   J_l(w)   = I + A W + B W^2,        J_r(w) = J_l(-w) = I - A W + B W^2,
 *   J_l(w)^-1 = I - W/2 + C W^2,       J_r(w)^-1 = I + W/2 + C W^2,
 *   Q_l(w, v) = V/2 + B (WV + VW + WVW) + D (WWV + VWW - 3 WVW)
 *             + E (WVWW + WWVW)                        (Barfoot-Furgale eq. 102)
 *   J_l(xi)  = [J_l(w), 0; Q_l, J_l(w)],  J_l(xi)^-1 = [J_l^-1, 0; -J_l^-1 Q_l J_l^-1, J_l^-1]
 *   J_r(xi)  = J_l(-xi),                  J_r(xi)^-1 = J_l(-xi)^-1
 *
 * A = (1 - cos th)/th^2, B = (th - sin th)/th^3, C = (1 - (th/2) cot(th/2))/th^2,
 * D = (th^2 + 2 cos th - 2)/(2 th^4), E = (2 th - 3 sin th + th cos th)/(2 th^5):
 * the rows F2, F3, COT, F4, JC of ga/internal/series.h, summed as series for
 * th < 2 (x = th^2 < 4: 18 terms leave less than 1e-30), where the closed
 * forms cancel.
 */
#include <garotor/jacobian.h>
#include <garotor/mat4.h>

#include <math.h>
#include <string.h>

#include "internal/series.h"

/* ---- 3x3 helpers (row-major) ---------------------------------------------- */

typedef struct {
    double m[9];
} m3;

static m3 m3_skew(double x, double y, double z)
{
    m3 s = {{0, -z, y, z, 0, -x, -y, x, 0}};
    return s;
}

static m3 m3_mul(m3 a, m3 b)
{
    m3 c;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            c.m[3 * i + j] = a.m[3 * i] * b.m[j] + a.m[3 * i + 1] * b.m[3 + j] + a.m[3 * i + 2] * b.m[6 + j];
    return c;
}

/* sum_k c[k] a[k] over n matrices, plus `id` times I */
static m3 m3_comb(double id, int n, const double *c, const m3 *a)
{
    m3 s = {{id, 0, 0, 0, id, 0, 0, 0, id}};
    for (int k = 0; k < n; k++)
        for (int i = 0; i < 9; i++) s.m[i] += c[k] * a[k].m[i];
    return s;
}

static m3 m3_transpose(m3 a)
{
    m3 t;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) t.m[3 * i + j] = a.m[3 * j + i];
    return t;
}

/* the 6x6 [a, 0; c, d] */
static ga_mat6 m6_blocks(m3 a, m3 c, m3 d)
{
    ga_mat6 o;
    memset(&o, 0, sizeof o);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            o.m[6 * i + j] = a.m[3 * i + j];
            o.m[6 * (i + 3) + j] = c.m[3 * i + j];
            o.m[6 * (i + 3) + j + 3] = d.m[3 * i + j];
        }
    return o;
}

static ga_mat6 m6_identity(void)
{
    ga_mat6 o;
    memset(&o, 0, sizeof o);
    for (int i = 0; i < 6; i++) o.m[7 * i] = 1.0;
    return o;
}

static ga_mat6 m6_neg(ga_mat6 a)
{
    for (int i = 0; i < 36; i++) a.m[i] = -a.m[i];
    return a;
}

static int m6_finite(const ga_mat6 *a)
{
    for (int i = 0; i < 36; i++)
        if (!isfinite(a->m[i]))
            return 0;
    return 1;
}

/* ---- the algebra ------------------------------------------------------------ */

/* A, B, D, E of the header comment at th^2 = t2 */
static void coeffs(double t2, double *a, double *b, double *d, double *e)
{
    if (t2 < 4.0) {
        *a = ga__series(GA__SERIES_F2, GA__SERIES_TERMS, t2);
        *b = ga__series(GA__SERIES_F3, GA__SERIES_TERMS, t2);
        *d = ga__series(GA__SERIES_F4, GA__SERIES_TERMS, t2);
        *e = ga__series(GA__SERIES_JC, GA__SERIES_TERMS, t2);
    } else {
        double th = sqrt(t2), s = sin(th), c = cos(th), h = sin(0.5 * th) / th;
        *a = 2.0 * h * h;
        *b = (th - s) / (t2 * th);
        *d = (t2 + 2.0 * c - 2.0) / (2.0 * t2 * t2);
        *e = (2.0 * th - 3.0 * s + th * c) / (2.0 * t2 * t2 * th);
    }
}

/* C = (1 - (th/2) cot(th/2))/th^2, for th < 2 pi */
static double coeff_cot(double t2)
{
    if (t2 < 4.0)
        return ga__series(GA__SERIES_COT, GA__SERIES_TERMS, t2);
    double th = sqrt(t2), h = 0.5 * th;
    return (1.0 - h * cos(h) / sin(h)) / t2;
}

/* J_l(w), Q_l(w, v) (sgn = 1) or J_r(w), Q_r (sgn = -1: w, v negated) */
static void jl_parts(ga_twist xi, double sgn, m3 *j, m3 *q)
{
    double wx = sgn * xi.w.x, wy = sgn * xi.w.y, wz = sgn * xi.w.z;
    double t2 = wx * wx + wy * wy + wz * wz, a, b, d, e;
    coeffs(t2, &a, &b, &d, &e);
    m3 W = m3_skew(wx, wy, wz), V = m3_skew(sgn * xi.v.x, sgn * xi.v.y, sgn * xi.v.z);
    m3 WW = m3_mul(W, W), WV = m3_mul(W, V), VW = m3_mul(V, W), WVW = m3_mul(WV, W);
    m3 WWV = m3_mul(W, WV), VWW = m3_mul(VW, W), WVWW = m3_mul(WVW, W), WWVW = m3_mul(W, WVW);
    const double cj[2] = {a, b};
    const m3 mj[2] = {W, WW};
    *j = m3_comb(1.0, 2, cj, mj);
    const double cq[9] = {0.5, b, b, b, d, d, -3.0 * d, e, e};
    const m3 mq[9] = {V, WV, VW, WVW, WWV, VWW, WVW, WVWW, WWVW};
    *q = m3_comb(0.0, 9, cq, mq);
}

ga_mat6 ga_twist_ad(ga_twist xi)
{
    m3 W = m3_skew(xi.w.x, xi.w.y, xi.w.z);
    return m6_blocks(W, m3_skew(xi.v.x, xi.v.y, xi.v.z), W);
}

static ga_mat6 jac(ga_twist xi, double sgn)
{
    m3 j, q;
    jl_parts(xi, sgn, &j, &q);
    return m6_blocks(j, q, j);
}

ga_mat6 ga_twist_jl(ga_twist xi) { return jac(xi, 1.0); }
ga_mat6 ga_twist_jr(ga_twist xi) { return jac(xi, -1.0); }

static ga_status jac_inverse(ga_twist xi, double sgn, ga_mat6 *out)
{
    if (!out)
        return GA_ERR_ARG;
    double x[6] = {xi.w.x, xi.w.y, xi.w.z, xi.v.x, xi.v.y, xi.v.z};
    for (int i = 0; i < 6; i++)
        if (!isfinite(x[i]))
            return GA_ERR_NOTFINITE;
    double t2 = xi.w.x * xi.w.x + xi.w.y * xi.w.y + xi.w.z * xi.w.z;
    if (!(sqrt(t2) < 2.0 * GA_PI))
        return GA_ERR_DOMAIN;
    m3 j, q;
    jl_parts(xi, sgn, &j, &q);
    m3 W = m3_skew(sgn * xi.w.x, sgn * xi.w.y, sgn * xi.w.z);
    const double c[2] = {-0.5, coeff_cot(t2)};
    const m3 mw[2] = {W, m3_mul(W, W)};
    m3 ji = m3_comb(1.0, 2, c, mw);
    m3 lower = m3_mul(m3_mul(ji, q), ji);
    for (int i = 0; i < 9; i++) lower.m[i] = -lower.m[i];
    ga_mat6 r = m6_blocks(ji, lower, ji);
    if (!m6_finite(&r))
        return GA_ERR_DOMAIN;
    *out = r;
    return GA_OK;
}

ga_status ga_twist_jl_inverse(ga_twist xi, ga_mat6 *out) { return jac_inverse(xi, 1.0, out); }
ga_status ga_twist_jr_inverse(ga_twist xi, ga_mat6 *out) { return jac_inverse(xi, -1.0, out); }

/* ---- the group ---------------------------------------------------------------- */

static m3 rot_of(ga_mat4 m)
{
    m3 r = {{m.m[0], m.m[1], m.m[2], m.m[4], m.m[5], m.m[6], m.m[8], m.m[9], m.m[10]}};
    return r;
}

ga_mat6 ga_se3_adjoint_matrix(ga_mat4 m)
{
    m3 R = rot_of(m);
    return m6_blocks(R, m3_mul(m3_skew(m.m[3], m.m[7], m.m[11]), R), R);
}

ga_mat6 ga_rotor_adjoint_matrix(ga_rotor r) { return ga_se3_adjoint_matrix(ga_rotor_to_mat4(r)); }

/* Ad(m^-1) = [R^T, 0; -R^T [t]x, R^T] */
static ga_mat6 adjoint_inv(ga_mat4 m)
{
    m3 Rt = m3_transpose(rot_of(m)), c = m3_mul(Rt, m3_skew(m.m[3], m.m[7], m.m[11]));
    for (int i = 0; i < 9; i++) c.m[i] = -c.m[i];
    return m6_blocks(Rt, c, Rt);
}

static int side_ok(ga_jac_side side) { return side == GA_JAC_RIGHT || side == GA_JAC_LEFT; }

static ga_status rotor_in(ga_rotor r, ga_rotor *out)
{
    ga_status st = ga_rotor_check(r, GA_ROTOR_DRIFT_MAX);
    if (st == GA_OK)
        st = ga_rotor_normalize(r, out);
    return st;
}

/* compose: the right Jacobian of A wants Ad(B^-1), the left one of B Ad(A) */
static void compose_from(ga_mat4 a, ga_mat4 b, ga_jac_side side, ga_mat6 *ja, ga_mat6 *jb)
{
    if (side == GA_JAC_RIGHT)
        *ja = adjoint_inv(b), *jb = m6_identity();
    else
        *ja = m6_identity(), *jb = ga_se3_adjoint_matrix(a);
}

ga_status ga_se3_jac_compose(ga_mat4 a, ga_mat4 b, ga_jac_side side, ga_mat6 *ja, ga_mat6 *jb)
{
    if (!ja || !jb || !side_ok(side))
        return GA_ERR_ARG;
    ga_status st = ga_se3_check(a, GA_SE3_TOL);
    if (st == GA_OK)
        st = ga_se3_check(b, GA_SE3_TOL);
    if (st == GA_OK)
        compose_from(a, b, side, ja, jb);
    return st;
}

ga_status ga_rotor_jac_compose(ga_rotor a, ga_rotor b, ga_jac_side side, ga_mat6 *ja, ga_mat6 *jb)
{
    if (!ja || !jb || !side_ok(side))
        return GA_ERR_ARG;
    ga_rotor ra, rb;
    ga_status st = rotor_in(a, &ra);
    if (st == GA_OK)
        st = rotor_in(b, &rb);
    if (st == GA_OK)
        compose_from(ga_rotor_to_mat4(ra), ga_rotor_to_mat4(rb), side, ja, jb);
    return st;
}

ga_status ga_se3_jac_inverse(ga_mat4 a, ga_jac_side side, ga_mat6 *j)
{
    if (!j || !side_ok(side))
        return GA_ERR_ARG;
    ga_status st = ga_se3_check(a, GA_SE3_TOL);
    if (st == GA_OK)
        *j = m6_neg(side == GA_JAC_RIGHT ? ga_se3_adjoint_matrix(a) : adjoint_inv(a));
    return st;
}

ga_status ga_rotor_jac_inverse(ga_rotor a, ga_jac_side side, ga_mat6 *j)
{
    if (!j || !side_ok(side))
        return GA_ERR_ARG;
    ga_rotor ra;
    ga_status st = rotor_in(a, &ra);
    if (st == GA_OK) {
        ga_mat4 m = ga_rotor_to_mat4(ra);
        *j = m6_neg(side == GA_JAC_RIGHT ? ga_se3_adjoint_matrix(m) : adjoint_inv(m));
    }
    return st;
}

/* between: right J_A = -Ad(B^-1 A) (binva: the matrix of B^-1 A), J_B = I;
 * left J_A = -Ad(A^-1), J_B = Ad(A^-1) */
static void between_from(ga_mat4 a, ga_mat4 binva, ga_jac_side side, ga_mat6 *ja, ga_mat6 *jb)
{
    if (side == GA_JAC_RIGHT) {
        *ja = m6_neg(ga_se3_adjoint_matrix(binva));
        *jb = m6_identity();
    } else {
        *jb = adjoint_inv(a);
        *ja = m6_neg(*jb);
    }
}

ga_status ga_se3_jac_between(ga_mat4 a, ga_mat4 b, ga_jac_side side, ga_mat6 *ja, ga_mat6 *jb)
{
    if (!ja || !jb || !side_ok(side))
        return GA_ERR_ARG;
    ga_status st = ga_se3_check(a, GA_SE3_TOL);
    if (st == GA_OK)
        st = ga_se3_check(b, GA_SE3_TOL);
    if (st == GA_OK)
        between_from(a, ga_mat4_mul(ga_se3_inverse(b), a), side, ja, jb);
    return st;
}

ga_status ga_rotor_jac_between(ga_rotor a, ga_rotor b, ga_jac_side side, ga_mat6 *ja, ga_mat6 *jb)
{
    if (!ja || !jb || !side_ok(side))
        return GA_ERR_ARG;
    ga_rotor ra, rb;
    ga_status st = rotor_in(a, &ra);
    if (st == GA_OK)
        st = rotor_in(b, &rb);
    if (st == GA_OK)
        between_from(ga_rotor_to_mat4(ra), ga_rotor_to_mat4(ga_rotor_mul(ga_rotor_reverse(rb), ra)), side, ja,
                     jb);
    return st;
}

/* act: right J_A = [-R [p]x, R], left [-[y]x, I]; J_p = R */
static void act_from(ga_mat4 m, ga_vec3 p, ga_vec3 y, ga_jac_side side, ga_mat36 *ja, ga_mat3 *jp)
{
    m3 R = rot_of(m), rot, lin;
    if (side == GA_JAC_RIGHT) {
        rot = m3_mul(R, m3_skew(-p.x, -p.y, -p.z));
        lin = R;
    } else {
        rot = m3_skew(-y.x, -y.y, -y.z);
        lin = m3_comb(1.0, 0, NULL, NULL);
    }
    for (int i = 0; i < 3; i++)
        for (int k = 0; k < 3; k++) {
            ja->m[6 * i + k] = rot.m[3 * i + k];
            ja->m[6 * i + k + 3] = lin.m[3 * i + k];
        }
    memcpy(jp->m, R.m, sizeof R.m);
}

static int vec_finite(ga_vec3 p) { return isfinite(p.x) && isfinite(p.y) && isfinite(p.z); }

ga_status ga_se3_jac_act(ga_mat4 a, ga_vec3 p, ga_jac_side side, ga_mat36 *ja, ga_mat3 *jp)
{
    if (!ja || !jp || !side_ok(side))
        return GA_ERR_ARG;
    ga_status st = ga_se3_check(a, GA_SE3_TOL);
    if (st == GA_OK && !vec_finite(p))
        st = GA_ERR_NOTFINITE;
    if (st != GA_OK)
        return st;
    ga_vec3 y = {a.m[0] * p.x + a.m[1] * p.y + a.m[2] * p.z + a.m[3],
                 a.m[4] * p.x + a.m[5] * p.y + a.m[6] * p.z + a.m[7],
                 a.m[8] * p.x + a.m[9] * p.y + a.m[10] * p.z + a.m[11]};
    act_from(a, p, y, side, ja, jp);
    return GA_OK;
}

ga_status ga_rotor_jac_act(ga_rotor a, ga_vec3 p, ga_jac_side side, ga_mat36 *ja, ga_mat3 *jp)
{
    if (!ja || !jp || !side_ok(side))
        return GA_ERR_ARG;
    ga_rotor ra;
    ga_status st = rotor_in(a, &ra);
    if (st == GA_OK && !vec_finite(p))
        st = GA_ERR_NOTFINITE;
    if (st == GA_OK)
        act_from(ga_rotor_to_mat4(ra), p, ga_rotor_apply(ra, p), side, ja, jp);
    return st;
}

/* log: J_r^-1 or J_l^-1 at the principal log; its angle is at most pi, so
 * the inverse cannot fail */
static ga_status log_from(ga_twist xi, ga_jac_side side, ga_mat6 *j)
{
    return side == GA_JAC_RIGHT ? ga_twist_jr_inverse(xi, j) : ga_twist_jl_inverse(xi, j);
}

ga_status ga_se3_jac_log(ga_mat4 a, ga_jac_side side, ga_mat6 *j)
{
    if (!j || !side_ok(side))
        return GA_ERR_ARG;
    ga_twist xi;
    ga_status st = ga_se3_log(a, &xi);
    return st == GA_OK ? log_from(xi, side, j) : st;
}

ga_status ga_rotor_jac_log(ga_rotor a, ga_jac_side side, ga_mat6 *j)
{
    if (!j || !side_ok(side))
        return GA_ERR_ARG;
    ga_generator g;
    ga_status st = ga_rotor_log(a, &g);
    return st == GA_OK ? log_from(ga_generator_to_twist(g), side, j) : st;
}
