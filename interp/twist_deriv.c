/* interp/twist_deriv.c: the body velocity, acceleration and jerk of
 * A(t) = exp(X(t)) for a curve X(t) of twists (the rigid groups, cga and
 * se3), in closed form: the derivatives of X carried through SE(3)'s
 * exp by Taylor jets in t (f, f', f'', f'''), in place of the 4x4 jet of
 * jet.c, which the affine group keeps.
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

void gip_twist_exp_derivs(const double *const *x, int m, double *v, double *a, double *j)
{
    if (m == 2)
        twist_derivs(x, 2, v, a, j);
    else if (m == 3)
        twist_derivs(x, 3, v, a, j);
    else
        twist_derivs(x, 1, v, a, j);
}
