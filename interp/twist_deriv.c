/* interp/twist_deriv.c: the body velocity, acceleration and jerk of
 * A(t) = exp(X(t)) for a curve X(t) of twists (the rigid groups, cga and
 * se3), in closed form: the derivatives of X carried through SE(3)'s
 * exp by Taylor jets in t (f, f', f'', f'''), in place of the 4x4 jet of
 * jet.c, which the affine group keeps. The acceleration alone has its own
 * shorter form (twist_accel below), used wherever an acceleration is asked.
 *
 * For X = (w, v): exp(X) = (R, p), R = exp([w]x), p = J_l(w) v, and
 * R^T J_l(w) = J_r(w) = I - k0 [w]x + k1 [w]x^2 (k0 = (1 - cos th)/th^2,
 * k1 = (th - sin th)/th^3, th = |w|; Sola, Deray, Atchuthan 2018). So
 * q = R^T p = J_r(w) v, and with the body angular velocity
 * W = J_r(w) w' (the rotation part of J_r(X) X'):
 *   body velocity      (W,   q' + W x q)          (p' = R (q' + W x q))
 *   body acceleration  (W',  q'' + W' x q + W x q')
 *   body jerk          (W'', q''' + W'' x q + 2 W' x q' + W x q'')
 * q, W and their derivatives are products of the jets of w, v and of
 * k0(s), k1(s), s = w.w; k0, k1 and their derivatives in s by their
 * series (rows F2, F3 of series.h, differentiated term by term) for
 * s < 4, else by the jets of th = sqrt(s), sin th and cos th.
 */
#include <math.h>
#include <string.h>

#include <garotor/path.h>

#include "ga/internal/series.h"
#include "internal/path.h"

/* A scalar jet: f and its first three derivatives in t (not Taylor
 * coefficients); a vector jet: x[k] the k-th derivative of a 3-vector.
 * Order m: only the derivatives 0 .. m are formed. */
static const double binom[4][4] = {{1, 0, 0, 0}, {1, 1, 0, 0}, {1, 2, 1, 0}, {1, 3, 3, 1}};

/* phi(s(t)) from phi and its derivatives f[k] = phi^(k)(s(t)) (Faa di Bruno) */
static inline void tj_compose(int m, const double *f, const double *s, double *o)
{
    o[0] = f[0];
    if (m >= 1)
        o[1] = f[1] * s[1];
    if (m >= 2)
        o[2] = f[2] * s[1] * s[1] + f[1] * s[2];
    if (m >= 3)
        o[3] = f[3] * s[1] * s[1] * s[1] + 3.0 * f[2] * s[1] * s[2] + f[1] * s[3];
}

static inline void tj_mul(int m, const double *a, const double *b, double *o)
{
    double c[4] = {0, 0, 0, 0};
    for (int k = 0; k <= m; ++k)
        for (int i = 0; i <= k; ++i) c[k] += binom[k][i] * a[i] * b[k - i];
    for (int k = 0; k <= m; ++k) o[k] = c[k];
}

/* the series sum_k c_k x^k of row f and its derivatives in x up to order
 * m, in one Horner pass (d_i: the i-th derivative over i!); 14 terms leave
 * under 1e-17 of each for x < 4 (F2's next, 4^14/30!, times 14^3) */
static inline void series_derivs(int f, int m, double x, double *o)
{
    const double *c = GA__SERIES[f];
    double p = c[13], d1 = 0.0, d2 = 0.0, d3 = 0.0;
    for (int k = 12; k >= 0; --k) {
        d3 = d3 * x + d2;
        d2 = d2 * x + d1;
        d1 = d1 * x + p;
        p = p * x + c[k];
    }
    o[0] = p;
    o[1] = d1;
    o[2] = 2.0 * d2;
    o[3] = 6.0 * d3;
    (void)m;
}

/* the jets of k0(s(t)) and k1(s(t)) */
static inline void kjets(int m, const double *s, double *k0, double *k1)
{
    if (s[0] < 4.0) {
        double f[4];
        series_derivs(GA__SERIES_F2, m, s[0], f);
        tj_compose(m, f, s, k0);
        series_derivs(GA__SERIES_F3, m, s[0], f);
        tj_compose(m, f, s, k1);
        return;
    }
    /* th = sqrt(s), then k0 = (1 - cos th)/s, k1 = (th - sin th)/(th s) */
    double th0 = sqrt(s[0]), f[4], th[4], sn[4], cs[4], is[4], ith[4], a[4], b[4];
    f[0] = th0;
    f[1] = 0.5 / th0;
    f[2] = -0.25 / (th0 * s[0]);
    f[3] = 0.375 / (th0 * s[0] * s[0]);
    tj_compose(m, f, s, th);
    double sv = sin(th0), cv = cos(th0);
    f[0] = sv, f[1] = cv, f[2] = -sv, f[3] = -cv;
    tj_compose(m, f, th, sn);
    f[0] = cv, f[1] = -sv, f[2] = -cv, f[3] = sv;
    tj_compose(m, f, th, cs);
    f[0] = 1.0 / s[0];
    f[1] = -f[0] * f[0];
    f[2] = -2.0 * f[1] * f[0];
    f[3] = -3.0 * f[2] * f[0];
    tj_compose(m, f, s, is);
    f[0] = 1.0 / th0;
    f[1] = -f[0] * f[0];
    f[2] = -2.0 * f[1] * f[0];
    f[3] = -3.0 * f[2] * f[0];
    tj_compose(m, f, th, ith);
    for (int k = 0; k <= m; ++k) {
        a[k] = (k == 0 ? 1.0 : 0.0) - cs[k];
        b[k] = th[k] - sn[k];
    }
    tj_mul(m, a, is, k0);
    tj_mul(m, b, ith, b);
    tj_mul(m, b, is, k1);
}

/* o = a x b, as vector jets (o may not be a or b) */
static inline void vj_cross(int m, const double (*a)[3], const double (*b)[3], double (*o)[3])
{
    for (int k = 0; k <= m; ++k) {
        double x = 0.0, y = 0.0, z = 0.0;
        for (int i = 0; i <= k; ++i) {
            const double *p = a[i], *q = b[k - i], c = binom[k][i];
            x += c * (p[1] * q[2] - p[2] * q[1]);
            y += c * (p[2] * q[0] - p[0] * q[2]);
            z += c * (p[0] * q[1] - p[1] * q[0]);
        }
        o[k][0] = x;
        o[k][1] = y;
        o[k][2] = z;
    }
}

/* o = J_r(w) y = y - k0 (w x y) + k1 w x (w x y), as jets */
static inline void vj_jr(int m, const double (*w)[3], const double *k0, const double *k1,
                         const double (*y)[3], double (*o)[3])
{
    double c[4][3], cc[4][3];
    vj_cross(m, w, y, c);
    vj_cross(m, w, (const double(*)[3])c, cc);
    for (int k = 0; k <= m; ++k)
        for (int e = 0; e < 3; ++e) {
            double s = y[k][e];
            for (int i = 0; i <= k; ++i) s += binom[k][i] * (k1[i] * cc[k - i][e] - k0[i] * c[k - i][e]);
            o[k][e] = s;
        }
}

static inline void cross_acc(double s, const double *a, const double *b, double *o)
{
    o[0] += s * (a[1] * b[2] - a[2] * b[1]);
    o[1] += s * (a[2] * b[0] - a[0] * b[2]);
    o[2] += s * (a[0] * b[1] - a[1] * b[0]);
}

/* m a constant in each call below, so that the compiler unrolls the loops */
static inline void twist_derivs(const double *const *x, int m, double *v, double *a, double *j)
{
    double w[4][3], y[4][3], s[4], k0[4], k1[4], Q[4][3], W[3][3];
    for (int k = 0; k <= m; ++k)
        for (int c = 0; c < 3; ++c) {
            w[k][c] = x[k][c];
            y[k][c] = x[k][3 + c];
        }
    /* s = w.w */
    for (int k = 0; k <= m; ++k) {
        double t = 0.0;
        for (int i = 0; i <= k; ++i)
            t += binom[k][i] * (w[i][0] * w[k - i][0] + w[i][1] * w[k - i][1] + w[i][2] * w[k - i][2]);
        s[k] = t;
    }
    kjets(m, s, k0, k1);
    vj_jr(m, (const double(*)[3])w, k0, k1, (const double(*)[3])y, Q);
    vj_jr(m - 1, (const double(*)[3])w, k0, k1, (const double(*)[3])(w + 1), W);
    if (v) {
        double o[3] = {Q[1][0], Q[1][1], Q[1][2]};
        cross_acc(1.0, W[0], Q[0], o);
        memcpy(v, W[0], 3 * sizeof(double));
        memcpy(v + 3, o, sizeof o);
    }
    if (a && m >= 2) {
        double o[3] = {Q[2][0], Q[2][1], Q[2][2]};
        cross_acc(1.0, W[1], Q[0], o);
        cross_acc(1.0, W[0], Q[1], o);
        memcpy(a, W[1], 3 * sizeof(double));
        memcpy(a + 3, o, sizeof o);
    }
    if (j && m >= 3) {
        double o[3] = {Q[3][0], Q[3][1], Q[3][2]};
        cross_acc(1.0, W[2], Q[0], o);
        cross_acc(2.0, W[1], Q[1], o);
        cross_acc(1.0, W[0], Q[2], o);
        memcpy(j, W[2], 3 * sizeof(double));
        memcpy(j + 3, o, sizeof o);
    }
}

/* ---- the acceleration alone, in fewer operations -----------------------------------
 * With w x (w x y) = (w.y) w - s y and sinc th = 1 - s k1,
 * J_r(w) y = A y - k0 (w x y) + k1 (w.y) w (A = sinc th), and w.w' = s'/2:
 *   W  = A w' - k0 (w x w') + K w,  K = k1 s'/2,
 *   W' = A' w' + A w'' - k0' (w x w') - k0 (w x w'') + K' w + K w',
 *   q  = A y - k0 c + P w,  c = w x y, P = k1 (w.y),
 * q' and q'' by Leibniz on the three products, and the acceleration
 * (W', q'' + W' x q + W x q'): 10 cross products against twist_derivs's 18
 * with its jets of every product. The functions f_n(s) = sum_k (-s)^k/(2k+n)!
 * (f_1 = A, f_2 = k0, f_3 = k1) and their derivatives in s: for s < 9,
 * f_6 and f_7 by their series (13 terms: the next is under 1e-20 of each),
 * then f_n = 1/n! - s f_{n+2} and f_n' = (n f_{n+2} - f_{n+1})/2; else from
 * th = sqrt(s), sin th, cos th, with 2 s f_n' = f_{n-1} - n f_n. */
static const double F6[13] = {0.001388888888888889,    -2.48015873015873e-05,  2.755731922398589e-07,
                              -2.08767569878681e-09,   1.1470745597729725e-11, -4.779477332387385e-14,
                              1.5619206968586225e-16,  -4.110317623312165e-19, 8.896791392450574e-22,
                              -1.6117375710961184e-24, 2.4795962632247976e-27, -3.279889237069838e-30,
                              3.7699876288159054e-33};
static const double F7[13] = {0.0001984126984126984,   -2.7557319223985893e-06, 2.505210838544172e-08,
                              -1.6059043836821613e-10, 7.647163731819816e-13,   -2.8114572543455206e-15,
                              8.22063524662433e-18,    -1.9572941063391263e-20, 3.868170170630684e-23,
                              -6.446950284384474e-26,  9.183689863795546e-29,   -1.1309962886447716e-31,
                              1.216125041553518e-34};

/* f_1, f_2, f_3 at s and their first two derivatives in s: f[n-1][0..2] */
static inline void fseries(double s, double f[3][3])
{
    if (s < 9.0) {
        double f6 = F6[12], f7 = F7[12];
        for (int k = 11; k >= 0; --k) {
            f6 = f6 * s + F6[k];
            f7 = f7 * s + F7[k];
        }
        double f5 = 1.0 / 120.0 - s * f7, f4 = 1.0 / 24.0 - s * f6, f3 = 1.0 / 6.0 - s * f5,
               f2 = 0.5 - s * f4;
        f[0][0] = 1.0 - s * f3;
        f[1][0] = f2;
        f[2][0] = f3;
        f[1][1] = f4 - 0.5 * f3;
        f[2][1] = 0.5 * (3.0 * f5 - f4);
        f[1][2] = 0.25 * ((8.0 * f6 - 5.0 * f5) + f4);
        f[2][2] = 0.25 * ((15.0 * f7 - 7.0 * f6) + f5);
    } else {
        double th = sqrt(s), sn = sin(th), cs = cos(th), h = 0.5 / s;
        double f1 = sn / th, f2 = (1.0 - cs) / s, f3 = (1.0 - f1) / s;
        double d1 = h * (cs - f1), d2 = h * (f1 - 2.0 * f2), d3 = h * (f2 - 3.0 * f3);
        f[0][0] = f1;
        f[1][0] = f2;
        f[2][0] = f3;
        f[1][1] = d2;
        f[2][1] = d3;
        f[1][2] = h * (d1 - 4.0 * d2);
        f[2][2] = h * (d2 - 5.0 * d3);
    }
    /* f_1' = (f_3 - f_2)/2 */
    f[0][1] = 0.5 * (f[2][0] - f[1][0]);
    f[0][2] = 0.5 * (f[2][1] - f[1][1]);
}

static inline void cross3(const double *a, const double *b, double *o)
{
    o[0] = a[1] * b[2] - a[2] * b[1];
    o[1] = a[2] * b[0] - a[0] * b[2];
    o[2] = a[0] * b[1] - a[1] * b[0];
}
static inline double dot3(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* the t-jet (g, g', g'') of f(s(t)) from f, df/ds, d2f/ds2 and s, s', s'' */
static inline void sjet(const double *f, double s1, double s2, double *o)
{
    o[0] = f[0];
    o[1] = f[1] * s1;
    o[2] = f[2] * (s1 * s1) + f[1] * s2;
}

/* the body acceleration of exp(X(t)), x[0..2] = X, X', X'' */
static void twist_accel(const double *const *x, double *acc)
{
    const double *w0 = x[0], *w1 = x[1], *w2 = x[2], *y0 = x[0] + 3, *y1 = x[1] + 3, *y2 = x[2] + 3;
    double s0 = dot3(w0, w0), s1 = 2.0 * dot3(w0, w1), s2 = 2.0 * (dot3(w1, w1) + dot3(w0, w2));
    double f[3][3], A[3], K0[3], K1[3];
    fseries(s0, f);
    sjet(f[0], s1, s2, A);
    sjet(f[1], s1, s2, K0);
    sjet(f[2], s1, s2, K1);
    /* the angular part */
    double c1[3], c2[3], W[3], Wd[3];
    cross3(w0, w1, c1);
    cross3(w0, w2, c2);
    double K = 0.5 * K1[0] * s1, Kd = 0.5 * (K1[1] * s1 + K1[0] * s2);
    for (int e = 0; e < 3; ++e) {
        W[e] = (A[0] * w1[e] - K0[0] * c1[e]) + K * w0[e];
        Wd[e] = ((A[1] * w1[e] + A[0] * w2[e]) - (K0[1] * c1[e] + K0[0] * c2[e])) + (Kd * w0[e] + K * w1[e]);
    }
    /* q = J_r(w) y and its derivatives */
    double c[3], ca[3], cb[3], cc[3], cd[3], ce[3];
    cross3(w0, y0, c);
    cross3(w1, y0, ca);
    cross3(w0, y1, cb);
    cross3(w2, y0, cc);
    cross3(w1, y1, cd);
    cross3(w0, y2, ce);
    double p0 = dot3(w0, y0), p1 = dot3(w1, y0) + dot3(w0, y1),
           p2 = (dot3(w2, y0) + 2.0 * dot3(w1, y1)) + dot3(w0, y2);
    double P0 = K1[0] * p0, P1 = K1[1] * p0 + K1[0] * p1, P2 = (K1[2] * p0 + 2.0 * K1[1] * p1) + K1[0] * p2;
    double q0[3], q1[3], q2[3];
    for (int e = 0; e < 3; ++e) {
        double d1 = ca[e] + cb[e], d2 = (cc[e] + 2.0 * cd[e]) + ce[e];
        q0[e] = (A[0] * y0[e] - K0[0] * c[e]) + P0 * w0[e];
        q1[e] = ((A[1] * y0[e] + A[0] * y1[e]) - (K0[1] * c[e] + K0[0] * d1)) + (P1 * w0[e] + P0 * w1[e]);
        q2[e] = ((A[2] * y0[e] + 2.0 * A[1] * y1[e]) + A[0] * y2[e]) -
                ((K0[2] * c[e] + 2.0 * K0[1] * d1) + K0[0] * d2) +
                ((P2 * w0[e] + 2.0 * P1 * w1[e]) + P0 * w2[e]);
    }
    double o[3] = {q2[0], q2[1], q2[2]};
    cross_acc(1.0, Wd, q0, o);
    cross_acc(1.0, W, q1, o);
    memcpy(acc, Wd, sizeof Wd);
    memcpy(acc + 3, o, sizeof o);
}

void gip_twist_exp_derivs(const double *const *x, int m, double *v, double *a, double *j)
{
    /* the acceleration by twist_accel wherever it is asked (alone or with the
       jerk: the same bits), the velocity and the jerk by the jets */
    if (a && m >= 2)
        twist_accel(x, a);
    if (j && m >= 3)
        twist_derivs(x, 3, v, NULL, j);
    else if (v)
        twist_derivs(x, 1, v, NULL, NULL);
}
