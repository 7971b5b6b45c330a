/* interp/scheme_decoupled.c: DECOUPLED and DECOUPLED_C2 (path.h), rotation
 * and translation interpolated apart through the group's to_qt/from_qt:
 * slerp and the position's line, or scipy's RotationSpline and the
 * not-a-knot CubicSpline (de Boor, A Practical Guide to Splines, ch. IV),
 * with SO(3)'s right Jacobian in closed form (Sola, Deray, Atchuthan 2018).
 * The rates of DECOUPLED_C2 solve the C2 system of c2_solve.c.
 */
#include <math.h>
#include <string.h>

#include <garotor/path.h>

#include "ga/internal/series.h"
#include "internal/path.h"

/* Layout of p->dec: per key DK doubles (q (w, x, y, z), p, the body angular
 * rate w at the key, the position slope s), then per segment DS doubles (the
 * rotation vector's cubic a, b, c: r(tau) = a tau + b tau^2 + c tau^3; the
 * position's cubic y, s, c2, c3, as scipy's PPoly: y + s tau + c2 tau^2 +
 * c3 tau^3; tau = t - t_i), then per key DX doubles of solver scratch. */
#define DK 13
#define DS 21
#define DX 12

size_t gip_dec_doubles(size_t N) { return N * (DK + DX) + (N - 1) * DS; }

/* ---- SO(3): the right Jacobian and unit quaternions ------------------------------ */

static double dot3(const double *a, const double *b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
static void cross3(const double *a, const double *b, double *o)
{
    double x = a[1] * b[2] - a[2] * b[1], y = a[2] * b[0] - a[0] * b[2], z = a[0] * b[1] - a[1] * b[0];
    o[0] = x;
    o[1] = y;
    o[2] = z;
}

/* The coefficient functions of the SO(3) right Jacobian J_r(r) = I - k0 [r]x
 * + k1 [r]x^2, k0 = (1 - cos th)/th^2, k1 = (th - sin th)/th^3, and of its
 * inverse J_r^-1(r) = I + [r]x/2 + ki [r]x^2, ki = (1 - (th/2) cot(th/2))/th^2
 * (Sola, Deray, Atchuthan 2018, "A micro Lie theory for state estimation in
 * robotics", the right Jacobian of SO(3) and its inverse), and of
 * d/dt(J_r(r)) r' = (r.r')(n1 (r x r') + n2 r x (r x r')) + k1 r' x (r x r'),
 * n1 = (2 - 2 cos th - th sin th)/th^4, n2 = (3 sin th - 2 th - th cos th)/th^5:
 * the product rule on J_r(r) r' with d th/dt = r.r'/th (scipy's
 * RotationSpline, _angular_acceleration_nonlinear_term, has the same).
 * Below th = 1 (ki: 1/2) by their Taylor series, where the closed forms
 * cancel: 2 - 2 cos th - th sin th is th^4/12 formed from terms of size 2
 * (scipy switches at 1e-4, where this loses up to 5e-3 relative).
 * so3_coef has k0, k1, n1, n2, formed once for the several products at one
 * r (a pose's velocity and acceleration take three); so3_ki has ki. */
typedef struct {
    double k0, k1, n1, n2;
} so3_k;
static so3_k so3_coef(double th)
{
    double x = th * th;
    so3_k k;
    if (th < 1.0) {
        /* k0 = f_2, k1 = f_3, n1, n2: rows of series.h; 14 (n1, n2: 13)
           terms leave under 1/28! at x = 1 */
        k.k0 = ga__series(GA__SERIES_F2, 14, x);
        k.k1 = ga__series(GA__SERIES_F3, 14, x);
        k.n1 = ga__series(GA__SERIES_N1, 13, x);
        k.n2 = ga__series(GA__SERIES_N2, 13, x);
    } else {
        double s = sin(th), co = cos(th);
        k.k0 = (1.0 - co) / x;
        k.k1 = (th - s) / (x * th);
        k.n1 = (2.0 - 2.0 * co - th * s) / (x * x);
        k.n2 = (3.0 * s - 2.0 * th - th * co) / (x * x * th);
    }
    return k;
}
static double so3_ki(double th)
{
    double x = th * th;
    /* the Bernoulli series of ki (row COT of series.h) to x^5 below 1/2: the
       next term is below 1e-17 of the first */
    return th < 0.5 ? ga__series(GA__SERIES_COT, 6, x) : (1.0 - 0.5 * th / tan(0.5 * th)) / x;
}
static so3_k so3_coef_of(const double *r) { return so3_coef(sqrt(dot3(r, r))); }

/* out = J_r(r) y, k = so3_coef_of(r) */
static void jr_apply(const so3_k *k, const double *r, const double *y, double *out)
{
    double c[3], cc[3];
    cross3(r, y, c);
    cross3(r, c, cc);
    for (int i = 0; i < 3; ++i) out[i] = y[i] - k->k0 * c[i] + k->k1 * cc[i];
}
/* out = J_r(r)^-1 y */
static void jrinv_apply(const double *r, const double *y, double *out)
{
    double ki = so3_ki(sqrt(dot3(r, r))), c[3], cc[3];
    cross3(r, y, c);
    cross3(r, c, cc);
    for (int i = 0; i < 3; ++i) out[i] = y[i] + 0.5 * c[i] + ki * cc[i];
}
/* out = d/dt(J_r(r(t))) r'(t), the angular acceleration's term beyond J_r r'',
   k = so3_coef_of(r) */
static void jr_nonlin(const so3_k *k, const double *r, const double *rd, double *out)
{
    double cp[3], ccp[3], dccp[3], dp = dot3(r, rd);
    cross3(r, rd, cp);
    cross3(r, cp, ccp);
    cross3(rd, cp, dccp);
    for (int i = 0; i < 3; ++i) out[i] = dp * (k->n1 * cp[i] + k->n2 * ccp[i]) + k->k1 * dccp[i];
}

/* Hamilton product and the unit quaternion's exp and principal log (angle in
 * [0, pi], the sign with w >= 0). */
static void qmul(const double *a, const double *b, double *o)
{
    double w = a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3];
    double x = a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2];
    double y = a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1];
    double z = a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0];
    o[0] = w;
    o[1] = x;
    o[2] = y;
    o[3] = z;
}
/* conj(a) b, each component's terms paired so that a = +-b gives exactly
   (+-1, 0, 0, 0): a constant segment turns by exactly 0 */
static void qrel(const double *a, const double *b, double *o)
{
    double w = a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
    double x = (a[0] * b[1] - a[1] * b[0]) + (a[3] * b[2] - a[2] * b[3]);
    double y = (a[0] * b[2] - a[2] * b[0]) + (a[1] * b[3] - a[3] * b[1]);
    double z = (a[0] * b[3] - a[3] * b[0]) + (a[2] * b[1] - a[1] * b[2]);
    o[0] = w;
    o[1] = x;
    o[2] = y;
    o[3] = z;
}
/* exp of the rotation vector r: (cos(th/2), sin(th/2) r/th) */
static void qexp(const double *r, double *q)
{
    double th = sqrt(dot3(r, r)), f = th < 1e-4 ? 0.5 - th * th / 48.0 : sin(0.5 * th) / th;
    q[0] = cos(0.5 * th);
    for (int k = 0; k < 3; ++k) q[k + 1] = f * r[k];
}
/* the rotation vector of q: 2 atan2(|v|, w) v/|v| with w >= 0 */
static void qlog(const double *q, double *r)
{
    double sg = q[0] < 0 ? -1.0 : 1.0, w = sg * q[0], v[3] = {sg * q[1], sg * q[2], sg * q[3]};
    double s = sqrt(dot3(v, v)), f = s > 0 ? 2.0 * atan2(s, w) / s : 2.0 / w;
    for (int k = 0; k < 3; ++k) r[k] = f * v[k];
}
/* out = R(q)^T x = x - 2w (u x x) + 2 u x (u x x), q = (w, u) unit */
static void qrot_inv(const double *q, const double *x, double *out)
{
    double c[3], cc[3];
    cross3(q + 1, x, c);
    cross3(q + 1, c, cc);
    for (int k = 0; k < 3; ++k) out[k] = x[k] - 2.0 * q[0] * c[k] + 2.0 * cc[k];
}

/* ---- DECOUPLED and DECOUPLED_C2 ------------------------------------------------- */

static double *dkey(const ga_path *p, size_t i) { return p->dec + i * DK; }
static double *dseg(const ga_path *p, size_t i) { return p->dec + p->cap * DK + i * DS; }
static double *dscr(const ga_path *p, size_t i) { return p->dec + p->cap * DK + (p->cap - 1) * DS + i * DX; }

/* m = the 3 x 3 matrix (row-major) of J_r(r) (inv = 0) or of J_r(r)^-1 (inv = 1) */
static void m3_of_jr(const double *r, int inv, double *m)
{
    so3_k k = so3_coef_of(r);
    for (int j = 0; j < 3; ++j) {
        double e[3] = {j == 0, j == 1, j == 2}, c[3];
        if (inv)
            jrinv_apply(r, e, c);
        else
            jr_apply(&k, r, e, c);
        for (int i = 0; i < 3; ++i) m[3 * i + j] = c[i];
    }
}

/* The not-a-knot slopes s_i of the cubic spline through (t_i, y_i), one
 * coordinate (stride DK in y and s), as scipy's CubicSpline has them: the
 * interior rows h_i s_{i-1} + 2(h_{i-1} + h_i) s_i + h_{i-1} s_{i+1} =
 * 3(h_i m_{i-1} + h_{i-1} m_i), m_i = (y_{i+1} - y_i)/h_i (de Boor ch. IV),
 * and the not-a-knot rows h_1 s_0 + (h_0 + h_1) s_1 = ((h_0 + 2(h_0 + h_1))
 * h_1 m_0 + h_0^2 m_1)/(h_0 + h_1) and its mirror (scipy's b[0], b[-1]). Each
 * end row is used to eliminate s_0 (s_{n-1}) from its neighbour, leaving a
 * strictly diagonally dominant tridiagonal system in s_1..s_{n-2} (rows:
 * (h_0 + h_1) s_1 + h_0 s_2 = r_1 - r_0, ...), solved by Thomas' algorithm.
 * 2 keys: the line; 3 keys: the parabola (scipy's special cases). */
static void notaknot(const ga_path *p, const double *y, double *s, double *cp, double *rp)
{
    size_t n = p->n;
#define Y(i) y[(i)*DK]
#define S(i) s[(i)*DK]
    double h0 = gip_seg_len(p, 0), m0 = (Y(1) - Y(0)) / h0;
    if (n == 2) {
        S(0) = S(1) = m0;
        return;
    }
    double h1 = gip_seg_len(p, 1), m1 = (Y(2) - Y(1)) / h1;
    if (n == 3) { /* the parabola: its slope at t_1, and 2 m - s at the ends */
        S(1) = (h1 * m0 + h0 * m1) / (h0 + h1);
        S(0) = 2.0 * m0 - S(1);
        S(2) = 2.0 * m1 - S(1);
        return;
    }
    double r0 = ((h0 + 2.0 * (h0 + h1)) * h1 * m0 + h0 * h0 * m1) / (h0 + h1);
    double ha = gip_seg_len(p, n - 3), hb = gip_seg_len(p, n - 2);
    double ma = (Y(n - 2) - Y(n - 3)) / ha, mb = (Y(n - 1) - Y(n - 2)) / hb;
    double rl = (hb * hb * ma + (2.0 * (ha + hb) + hb) * ha * mb) / (ha + hb);
    /* forward sweep over rows k = 1..n-2 (cp: modified upper diagonal, rp: rhs) */
    for (size_t k = 1; k + 1 < n; ++k) {
        double hl = gip_seg_len(p, k - 1), hr = gip_seg_len(p, k);
        double ml = (Y(k) - Y(k - 1)) / hl, mr = (Y(k + 1) - Y(k)) / hr;
        double lo = hr, di = 2.0 * (hl + hr), up = hl, r = 3.0 * (hr * ml + hl * mr);
        if (k == 1) { /* s_0 eliminated */
            lo = 0.0;
            di -= hl + hr;
            r -= r0;
        }
        if (k == n - 2) { /* s_{n-1} eliminated */
            up = 0.0;
            di -= hl + hr;
            r -= rl;
        }
        if (k > 1) {
            di -= lo * cp[k - 1];
            r -= lo * rp[k - 1];
        }
        cp[k] = up / di;
        rp[k] = r / di;
    }
    S(n - 2) = rp[n - 2];
    for (size_t k = n - 2; k-- > 1;) S(k) = rp[k] - cp[k] * S(k + 1);
    S(0) = (r0 - (h0 + h1) * S(1)) / h1;
    S(n - 1) = (rl - (ha + hb) * S(n - 2)) / ha;
#undef Y
#undef S
}

/* The relative rotation vector theta_i = plog(R_i^-1 R_{i+1}) of segment i,
   through the group's half-turn rule as a twist (theta, 0), parked in slot a. */
static void dec_rel_rotation(ga_path *p, size_t i)
{
    double qr[4], x[GIP_MAXD] = {0};
    qrel(dkey(p, i), dkey(p, i + 1), qr);
    qlog(qr, x);
    if (p->group->half_turn)
        p->group->half_turn(x);
    memcpy(dseg(p, i), x, 3 * sizeof(double));
}

/* DECOUPLED segment i from its theta: position slope and rotation rate the
   chords, at key i and (for the last segment) at key i + 1 too. Depends on
   keys i and i + 1 alone, which ga_path_append relies on. */
static void dec_linear(ga_path *p, size_t i)
{
    double h = gip_seg_len(p, i), *rc = dseg(p, i), *pc = rc + 9, th[3];
    double *k0 = dkey(p, i), *k1 = dkey(p, i + 1);
    memcpy(th, rc, sizeof th);
    for (int c = 0; c < 3; ++c) {
        double m = (k1[4 + c] - k0[4 + c]) / h;
        k0[10 + c] = m;
        pc[c] = k0[4 + c];
        pc[3 + c] = m;
        pc[6 + c] = pc[9 + c] = 0.0;
    }
    for (int k = 0; k < 3; ++k) {
        k0[7 + k] = k1[7 + k] = th[k] / h; /* key i + 1: overwritten by segment i + 1 */
        rc[k] = th[k] / h;
        rc[3 + k] = rc[6 + k] = 0.0;
    }
}

/* ga_path_append's DECOUPLED segment i to the new key i + 1 (the path q
   already holds it): GA_ERR_DOMAIN, with key i's rate and slope restored,
   where the segment is not finite. */
int gip_dec_append(ga_path *q, size_t i, const void *key)
{
    const ga_group *g = q->group;
    double *k0 = dkey(q, i), saved[6];
    memcpy(saved, k0 + 7, sizeof saved); /* key i's rate and slope, restored on failure */
    if (i == 0)                          /* one key: nothing was built */
        g->to_qt(gip_key_of(q, 0), k0, k0 + 4);
    g->to_qt(key, dkey(q, i + 1), dkey(q, i + 1) + 4);
    dec_rel_rotation(q, i);
    dec_linear(q, i);
    if (!gip_allfinite(dkey(q, i), 2 * DK) || !gip_allfinite(dseg(q, i), DS)) {
        memcpy(k0 + 7, saved, sizeof saved);
        return GA_ERR_DOMAIN;
    }
    return GA_OK;
}

/* DECOUPLED_C2: the rotation vectors, with SO(3)'s closed forms */
static const double *dec_theta(const ga_path *p, size_t i) { return dseg(p, i); }
static double *dec_rate(const ga_path *p, size_t i) { return dkey(p, i) + 7; }
static double *dec_scratch(const ga_path *p, size_t i) { return dscr(p, i); }
static int dec_jr(const ga_path *p, const double *th, int inv, double *m)
{
    (void)p;
    m3_of_jr(th, inv, m);
    return GA_OK;
}
static int dec_nonlin(const ga_path *p, const double *th, const double *y, double *o)
{
    (void)p;
    so3_k k = so3_coef_of(th);
    jr_nonlin(&k, th, y, o);
    return GA_OK;
}

static void dec_start(ga_path *p)
{
    for (size_t i = 0; i < p->n; ++i) {
        size_t j = i + 1 < p->n ? i : i - 1;
        double h = gip_seg_len(p, j);
        for (int k = 0; k < 3; ++k) dkey(p, i)[7 + k] = dseg(p, j)[k] / h;
    }
}

int gip_build_decoupled(ga_path *p)
{
    const ga_group *g = p->group;
    size_t n = p->n;
    /* every slot defined (the linear scheme leaves slopes and scratch unused,
       and path.c's build() checks the whole block for finiteness) */
    memset(p->dec, 0, gip_scheme_doubles(p->scheme, p->cap, g->dim) * sizeof(double));
    for (size_t i = 0; i < n; ++i) g->to_qt(gip_key_of(p, i), dkey(p, i), dkey(p, i) + 4);
    for (size_t i = 0; i + 1 < n; ++i) dec_rel_rotation(p, i);
    if (p->scheme == GA_SCHEME_DECOUPLED) {
        for (size_t i = 0; i + 1 < n; ++i) dec_linear(p, i);
        return GA_OK;
    }
    /* DECOUPLED_C2: positions */
    for (int c = 0; c < 3; ++c) {
        double *cp = dscr(p, 0), *rp = cp + n; /* scratch: 2n doubles of the DX n */
        notaknot(p, dkey(p, 0) + 4 + c, dkey(p, 0) + 10 + c, cp, rp);
        for (size_t i = 0; i + 1 < n; ++i) {
            /* scipy's CubicSpline coefficients: t = (s_i + s_{i+1} - 2m)/h,
               c3 = t/h, c2 = (m - s_i)/h - t */
            double h = gip_seg_len(p, i), y0 = dkey(p, i)[4 + c], m = (dkey(p, i + 1)[4 + c] - y0) / h;
            double *pc = dseg(p, i) + 9;
            double s0 = dkey(p, i)[10 + c], s1 = dkey(p, i + 1)[10 + c], t = (s0 + s1 - 2.0 * m) / h;
            pc[c] = y0;
            pc[3 + c] = s0;
            pc[6 + c] = (m - s0) / h - t;
            pc[9 + c] = t / h;
        }
    }
    /* angular rates: the chord rates to start (and for good at the ends) */
    dec_start(p);
    if (n > 2) {
        gip_c2_sys sys = {p, 3, dec_theta, dec_rate, dec_scratch, dec_jr, dec_nonlin, dec_start, NULL, NULL};
        int st = gip_c2_solve(&sys);
        if (st != GA_OK)
            return st;
    }
    /* rotation cubics: a = w_i, r'(h) = J_r^-1(theta) w_{i+1},
       b = (3 theta - 2h a - h r'(h))/h^2, c = (-2 theta + h a + h r'(h))/h^3
       (Hermite; scipy's RotationSpline coefficients) */
    for (size_t i = 0; i + 1 < n; ++i) {
        double *rc = dseg(p, i), th[3], re[3], h = gip_seg_len(p, i);
        const double *a = dkey(p, i) + 7;
        memcpy(th, rc, sizeof th);
        jrinv_apply(th, dkey(p, i + 1) + 7, re);
        for (int k = 0; k < 3; ++k) {
            rc[k] = a[k];
            rc[3 + k] = (3.0 * th[k] - 2.0 * h * a[k] - h * re[k]) / (h * h);
            rc[6 + k] = (-2.0 * th[k] + h * a[k] + h * re[k]) / (h * h * h);
        }
    }
    return GA_OK;
}

/* DECOUPLED's pose from constants of its segment (c: GIP_DEC_CONST doubles,
 * gip_dec_prep): the rotation q_i exp(a n) with a = u th/2, n the unit axis
 * of the segment's rotation vector th, is cos(a) q_i + sin(a) (q_i n), so a
 * pose costs cos and sin of one angle and a linear combination of two fixed
 * quaternions; the position is the chord, y_i + m tau as gip_dec_eval has
 * it. Layout: c[0..3] q_i, c[4..7] q_i n (Hamilton product with (0, n)),
 * c[8] |th|/(2h), c[9..11] y_i, c[12..14] m, c[15] h. */
void gip_dec_prep(const ga_path *p, size_t seg, double *c)
{
    const double *rc = dseg(p, seg), *q0 = dkey(p, seg);
    double mx = fmax(fabs(rc[0]), fmax(fabs(rc[1]), fabs(rc[2]))), n[4] = {0, 0, 0, 0}, half = 0.0;
    if (mx > 0.0) { /* the norm scaled: no overflow where h is tiny, no underflow where th is */
        double v[3] = {rc[0] / mx, rc[1] / mx, rc[2] / mx}, l = sqrt(dot3(v, v));
        for (int k = 0; k < 3; ++k) n[k + 1] = v[k] / l;
        half = 0.5 * (mx * l);
    }
    memcpy(c, q0, 4 * sizeof(double));
    qmul(q0, n, c + 4);
    c[8] = half;
    memcpy(c + 9, rc + 9, 3 * sizeof(double));
    memcpy(c + 12, rc + 12, 3 * sizeof(double));
    c[15] = gip_seg_len(p, seg);
}

/* the rotation q of gip_dec_at at tau = u h */
static inline void dec_rot(const double *c, double tau, double *q)
{
    double a = c[8] * tau, a2 = a * a, cs, sn;
    if (a2 <= (GA_PI / 4) * (GA_PI / 4)) { /* ga_rotor_exp's series: no trig call */
        double y2 = a2 * a2, y4 = y2 * y2, y8 = y4 * y4;
        cs = ga__series_estrin9(GA__SERIES_F0, a2, y2, y4, y8);
        sn = a * ga__series_estrin9(GA__SERIES_F1, a2, y2, y4, y8);
    } else if (a > 0.0 && a <= 3 * GA_PI / 4) { /* r = pi/2 - a: sin a = cos r, cos a = r sinc r */
        double r = (GA_PIO2_HI - a) + GA_PIO2_LO, y = r * r, y2 = y * y, y4 = y2 * y2, y8 = y4 * y4;
        sn = ga__series_estrin9(GA__SERIES_F0, y, y2, y4, y8);
        cs = r * ga__series_estrin9(GA__SERIES_F1, y, y2, y4, y8);
    } else { /* beyond the segment (u > 3/2 at a half turn, or u < 0) */
        cs = cos(a);
        sn = sin(a);
    }
    for (int k = 0; k < 4; ++k) q[k] = cs * c[k] + sn * c[4 + k];
}

int gip_dec_at(const ga_path *p, const double *c, double u, void *out)
{
    double tau = u * c[15], q[4], pos[3];
    dec_rot(c, tau, q);
    for (int k = 0; k < 3; ++k) pos[k] = c[12 + k] * tau + c[9 + k];
    p->group->from_qt(q, pos, out);
    const double *o = out;
    double z = 0.0;
    for (size_t k = 0; k < p->group->elem_size / sizeof(double); ++k)
        z += o[k] - o[k]; /* 0 for finite, NaN for Inf and NaN (gip_finite_elem) */
    return z == 0.0 ? GA_OK : GA_ERR_DOMAIN;
}

/* DECOUPLED's derivatives from its segment's constants: the rotation turns
 * at the constant rate w = th/h about a fixed axis, so the body angular
 * velocity is w and its derivatives are 0; the position moves on its chord,
 * p' = m and p'' = p''' = 0 in world axes, so in the body (d/dt R^T y =
 * R^T y' - w x R^T y) the velocity is v = R^T m, the acceleration -w x v and
 * the jerk w x (w x v), R the pose's rotation (gip_dec_at). That is what
 * gip_dec_eval's general forms give for this curve (J_r(r) w = w where r is
 * parallel to w, N(r, w) = 0), without their rounding and their cost. */
static void dec_linear_derivs(const ga_path *p, size_t seg, double u, double *v, double *a, double *j,
                              double *pw)
{
    const double *w = dseg(p, seg);
    double c[GIP_DEC_CONST], q[4], lv[3], al[3];
    gip_dec_prep(p, seg, c);
    if (pw) {
        memcpy(pw, c + 12, 3 * sizeof(double));
        memset(pw + 3, 0, 6 * sizeof(double));
    }
    if (!v && !a && !j)
        return;
    dec_rot(c, u * c[15], q);
    qrot_inv(q, c + 12, lv);
    if (v) {
        memcpy(v, w, 3 * sizeof(double));
        memcpy(v + 3, lv, sizeof lv);
    }
    cross3(w, lv, al);
    for (int k = 0; k < 3; ++k) al[k] = -al[k];
    if (a) {
        memset(a, 0, 3 * sizeof(double));
        memcpy(a + 3, al, sizeof al);
    }
    if (j) {
        memset(j, 0, 3 * sizeof(double));
        cross3(w, al, j + 3);
        for (int k = 3; k < 6; ++k) j[k] = -j[k];
    }
}

/* The pose on segment seg at u, and (each may be NULL) the body velocity,
 * acceleration and jerk per unit t, and pw: the position's derivatives p',
 * p'', p''' in world axes (9 doubles). DECOUPLED's derivatives (out NULL)
 * come from its segment's constants (dec_linear_derivs). */
int gip_dec_eval(const ga_path *p, size_t seg, double u, void *out, double *v, double *a, double *j,
                 double *pw)
{
    if (p->scheme == GA_SCHEME_DECOUPLED && !out) {
        dec_linear_derivs(p, seg, u, v, a, j, pw);
        return GA_OK;
    }
    const double *rc = dseg(p, seg), *pc = rc + 9, *q0 = dkey(p, seg);
    double tau = u * gip_seg_len(p, seg), r[3], rd[3], rdd[3], pos[3], pd[3], pdd[3], pddd[3], qe[4], q[4];
    for (int k = 0; k < 3; ++k) {
        r[k] = ((rc[6 + k] * tau + rc[3 + k]) * tau + rc[k]) * tau;
        rd[k] = (3.0 * rc[6 + k] * tau + 2.0 * rc[3 + k]) * tau + rc[k];
        rdd[k] = 6.0 * rc[6 + k] * tau + 2.0 * rc[3 + k];
        pos[k] = ((pc[9 + k] * tau + pc[6 + k]) * tau + pc[3 + k]) * tau + pc[k];
        pd[k] = (3.0 * pc[9 + k] * tau + 2.0 * pc[6 + k]) * tau + pc[3 + k];
        pdd[k] = 6.0 * pc[9 + k] * tau + 2.0 * pc[6 + k];
        pddd[k] = 6.0 * pc[9 + k];
    }
    qexp(r, qe);
    qmul(q0, qe, q);
    if (out) {
        p->group->from_qt(q, pos, out);
        int st = gip_finite_elem(p->group, out);
        if (st != GA_OK)
            return st;
    }
    if (pw) {
        memcpy(pw, pd, sizeof pd);
        memcpy(pw + 3, pdd, sizeof pdd);
        memcpy(pw + 6, pddd, sizeof pddd);
    }
    if (v || a || j) {
        /* w = J_r(r) r', v = R^T p'; w' = J_r(r) r'' + N(r, r'),
           d/dt (R^T p') = R^T p'' - w x R^T p' */
        double w[3], lv[3], wd[3], nl[3], la[3], c[3], al[3];
        so3_k k = so3_coef_of(r);
        jr_apply(&k, r, rd, w);
        qrot_inv(q, pd, lv);
        if (v) {
            memcpy(v, w, sizeof w);
            memcpy(v + 3, lv, sizeof lv);
        }
        jr_apply(&k, r, rdd, wd);
        jr_nonlin(&k, r, rd, nl);
        qrot_inv(q, pdd, la);
        cross3(w, lv, c);
        for (int k = 0; k < 3; ++k) {
            wd[k] += nl[k];
            al[k] = la[k] - c[k];
        }
        if (a) {
            memcpy(a, wd, sizeof wd);
            memcpy(a + 3, al, sizeof al);
        }
        if (j) {
            /* the rotation's jerk from exp(r(t)) (twist_deriv.c, no translation);
               d/dt (R^T p'' - w x v) = R^T p''' - w x R^T p'' - w' x v - w x (R^T p'' - w x v) */
            double z[3] = {0, 0, 0}, x0[6], x1[6], x2[6], x3[6], jr[6], lj[3], t[3];
            const double *xs[4] = {x0, x1, x2, x3};
            for (int k = 0; k < 3; ++k) {
                x0[k] = r[k];
                x1[k] = rd[k];
                x2[k] = rdd[k];
                x3[k] = 6.0 * rc[6 + k];
                x0[3 + k] = x1[3 + k] = x2[3 + k] = x3[3 + k] = z[k];
            }
            gip_twist_exp_derivs(xs, 3, NULL, NULL, jr);
            qrot_inv(q, pddd, lj);
            cross3(w, la, t);
            for (int k = 0; k < 3; ++k) lj[k] -= t[k];
            cross3(wd, lv, t);
            for (int k = 0; k < 3; ++k) lj[k] -= t[k];
            cross3(w, al, t);
            for (int k = 0; k < 3; ++k) {
                j[k] = jr[k];
                j[3 + k] = lj[k] - t[k];
            }
        }
    }
    return GA_OK;
}
