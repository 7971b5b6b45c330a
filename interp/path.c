/* garotor/path.c: the schemes and evaluators of path.h, written once against
 * the group interface (group.h). See path.h for the mathematics and the
 * paper equations; each function below cites the ones it implements.
 */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#include <garotor/mat4.h>
#include <garotor/path.h>
#include <garotor/rotor_inline.h>

/* the series of ga_rotor_exp, for the screw sampler on rotors */
#include "../ga/rotor_series.h"
#define MAXD GA_GROUP_MAX_DIM
#define MAXE GA_GROUP_MAX_ELEM

/* ---- names ---------------------------------------------------------------- */

static const char *const scheme_names[GA_SCHEME_COUNT] = {"screw",   "bivector", "quadratic", "smooth",
                                                          "lihao2",  "lihao3",   "decoupled", "decoupled-c2",
                                                          "bspline", "c2"};
static const char *const eval_names[] = {"direct", "euler", "exact"};

const char *ga_scheme_name(ga_scheme s) { return (unsigned)s < GA_SCHEME_COUNT ? scheme_names[s] : "?"; }

ga_status ga_scheme_by_name(const char *name, ga_scheme *out)
{
    for (unsigned i = 0; name && i < GA_SCHEME_COUNT; ++i)
        if (strcmp(name, scheme_names[i]) == 0) {
            *out = (ga_scheme)i;
            return GA_OK;
        }
    return GA_ERR_ARG;
}

const char *ga_eval_name(ga_eval e) { return (unsigned)e < 3 ? eval_names[e] : "?"; }

ga_status ga_eval_by_name(const char *name, ga_eval *out)
{
    for (unsigned i = 0; name && i < 3; ++i)
        if (strcmp(name, eval_names[i]) == 0) {
            *out = (ga_eval)i;
            return GA_OK;
        }
    return GA_ERR_ARG;
}

size_t ga_scheme_min_keys(ga_scheme s)
{
    return s == GA_SCHEME_BSPLINE ? 4 : (s == GA_SCHEME_QUADRATIC || s == GA_SCHEME_SMOOTH) ? 3 : 2;
}

size_t ga_times_uneven(size_t n, const double *times)
{
    if (!times || n <= 2)
        return 0;
    double t0 = times[0], span = times[n - 1] - t0, h = span / (double)(n - 1);
    double tol = GA_PATH_SPACING_TOL * fabs(h) + 4 * DBL_EPSILON * fmax(fabs(t0), fabs(times[n - 1]));
    for (size_t i = 1; i + 1 < n; ++i) {
        /* t_0 + i h formed as a weighted mean of the ends: no error growing with i */
        double w = (double)i / (double)(n - 1), grid = t0 + w * span;
        if (!(fabs(times[i] - grid) <= tol))
            return i;
    }
    return 0;
}

/* Schemes whose segment i depends on keys 0..i+1 only, BSPLINE's on keys
 * i..i+3 (path.h, ga_path_append). */
int ga_scheme_can_append(ga_scheme s)
{
    return s == GA_SCHEME_SCREW || s == GA_SCHEME_LIHAO2 || s == GA_SCHEME_BIVECTOR ||
           s == GA_SCHEME_DECOUPLED || s == GA_SCHEME_BSPLINE;
}

/* ---- small helpers ---------------------------------------------------------- */

/* The exponent polynomials p_j(u) = c0 + c1 u + c2 u^2 + c3 u^3 of the
 * factors exp(p_j(u) X_j). Li-Hao: u (eq. 9), u^2 (eq. 14), u^3 - u^2
 * (eq. 21); factor j has degree j + 1. BSPLINE: the cumulative cubic basis
 * (path.h), each of degree 3. */
static const double lihao_poly[3][4] = {{0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, -1, 1}};
static const double bspline_poly[3][4] = {
    {5.0 / 6, 0.5, -0.5, 1.0 / 6}, {1.0 / 6, 0.5, 0.5, -1.0 / 3}, {0, 0, 0, 1.0 / 6}};

static const double *fac_poly(ga_scheme s, size_t j)
{
    return s == GA_SCHEME_BSPLINE ? bspline_poly[j] : lihao_poly[j];
}
static size_t fac_deg(ga_scheme s, size_t j) { return s == GA_SCHEME_BSPLINE ? 3 : j + 1; }

static size_t nfac(ga_scheme s)
{
    return s == GA_SCHEME_SCREW                            ? 1
         : s == GA_SCHEME_LIHAO2                           ? 2
         : s == GA_SCHEME_LIHAO3 || s == GA_SCHEME_BSPLINE ? 3
                                                           : 0;
}

/* The order-m forward difference of p with step d at u (m = 0: p(u) itself),
 * expanded so that no difference of nearby values is formed. */
static double poly_diff(const double *c, size_t m, double u, double d)
{
    switch (m) {
    case 0: return c[0] + u * (c[1] + u * (c[2] + u * c[3]));
    case 1: return c[1] * d + c[2] * d * (2 * u + d) + c[3] * d * (3 * u * u + 3 * u * d + d * d);
    case 2: return c[2] * 2 * d * d + c[3] * 6 * d * d * (u + d);
    default: return c[3] * 6 * d * d * d;
    }
}

static double poly_deriv(const double *c, double u) { return c[1] + u * (2 * c[2] + 3 * u * c[3]); }
static double poly_deriv2(const double *c, double u) { return 2 * c[2] + 6 * c[3] * u; }

static double *key_of(const ga_path *p, size_t i) { return p->key + i * p->key_stride; }
/* Segment i runs from knot i to knot i + 1: the key times, except BSPLINE,
 * whose segment i is [t_{i+1}, t_{i+2}] (path.h). */
static size_t knot_off(const ga_path *p) { return p->scheme == GA_SCHEME_BSPLINE && p->n > 1; }
static double knot(const ga_path *p, size_t i) { return p->t[i + knot_off(p)]; }
static size_t nseg(const ga_path *p) { return p->n > 1 ? p->n - 1 - 2 * knot_off(p) : 0; }
static double seg_len(const ga_path *p, size_t i) { return knot(p, i + 1) - knot(p, i); }
/* X_1 of segment seg; X_2, X_3 follow at strides of dim. Li-Hao: B, C, D per
 * segment; BSPLINE: the n - 1 relative logs d_i, shared by the segments. */
static const double *seg_coef(const ga_path *p, size_t seg)
{
    return p->coef + seg * (p->scheme == GA_SCHEME_BSPLINE ? 1 : nfac(p->scheme)) * p->group->dim;
}

/* Element sizes of 8 and 16 doubles (a rotor, a 4x4 matrix) get a memcpy of
 * constant size, which the compiler turns into a few moves (a call to memcpy
 * per copy was a tenth of the time of sampling a screw path on rotors). */
static void copy_elem(const ga_group *g, void *dst, const void *src)
{
    if (g->elem_size == 8 * sizeof(double))
        memcpy(dst, src, 8 * sizeof(double));
    else if (g->elem_size == 16 * sizeof(double))
        memcpy(dst, src, 16 * sizeof(double));
    else
        memcpy(dst, src, g->elem_size);
}

static void lin(size_t d, double *out, double s, const double *a, double r, const double *b)
{
    for (size_t k = 0; k < d; ++k) out[k] = s * a[k] + r * b[k];
}

static int allfinite(const double *x, size_t n)
{
    for (size_t i = 0; i < n; ++i)
        if (!isfinite(x[i]))
            return 0;
    return 1;
}

/* Results are checked before they are handed out: finite input can still
 * overflow on the way (a velocity divided by a subnormal segment length, a
 * lihao2 velocity scaled by a ratio h_{i+1}/h_i near DBL_MAX, products of
 * keys near DBL_MAX), and a result that is not finite is GA_ERR_DOMAIN, never
 * GA_OK with Inf or NaN (docs/errors.md; found by fuzz/fuzz_path, replayed by
 * fuzz/regress/path/velocity-subnormal-spacing and
 * fuzz/regress/path/affine-lihao3-velocity-overflow). */
static int finite_elem(const ga_group *g, const void *x)
{
    return allfinite(x, g->elem_size / sizeof(double)) ? GA_OK : GA_ERR_DOMAIN;
}

/* The principal log, made deterministic at half turns (group.h half_turn). */
static int plog(const ga_group *g, const void *a, double *x)
{
    int st = g->log(a, x);
    if (st == GA_OK && g->half_turn)
        g->half_turn(x);
    return st;
}

/* x = plog(a^-1 b) */
static int rel_log(const ga_group *g, const void *a, const void *b, double *x, double *rel)
{
    double ai[MAXE];
    int st = g->inverse(a, ai);
    if (st != GA_OK)
        return st;
    g->compose(ai, b, rel);
    return plog(g, rel, x);
}

/* ---- decoupled schemes: rotation and translation apart ------------------------ */

/* Layout of p->dec: per key DK doubles (q (w, x, y, z), p, the body angular
 * rate w at the key, the position slope s), then per segment DS doubles (the
 * rotation vector's cubic a, b, c: r(tau) = a tau + b tau^2 + c tau^3; the
 * position's cubic y, s, c2, c3, as scipy's PPoly: y + s tau + c2 tau^2 +
 * c3 tau^3; tau = t - t_i), then per key DX doubles of solver scratch. */
#define DK 13
#define DS 21
#define DX 12

static size_t scheme_doubles(ga_scheme s, size_t N, size_t D);
static int is_decoupled(ga_scheme s) { return s == GA_SCHEME_DECOUPLED || s == GA_SCHEME_DECOUPLED_C2; }
/* Schemes defined on the rigid groups only (group.h rigid, to_qt/from_qt). */
static int rigid_only(const ga_group *g, ga_scheme s)
{
    return (is_decoupled(s) && (!g->to_qt || !g->from_qt)) || (s == GA_SCHEME_C2 && !g->rigid);
}

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
 * (scipy switches at 1e-4, where this loses up to 5e-3 relative). */
static void so3_coef(double th, double *k0, double *k1, double *n1, double *n2, double *ki)
{
    double x = th * th;
    if (th < 1.0) {
        /* k0 = sum_{m>=1} (-1)^(m+1) x^(m-1)/(2m)!, k1 the same over (2m+1)!,
           n1 = sum_{m>=2} (-1)^m (2m-2)/(2m)! x^(m-2),
           n2 = sum_{m>=2} (-1)^m (2-2m)/(2m+1)! x^(m-2); 14 terms leave under
           1/28! at x = 1 */
        double a = 0, b = 0, c = 0, d = 0, f2 = 2.0, f3 = 6.0, xp = 1.0, xq = 1.0, sg = 1.0;
        for (int m = 1; m <= 14; ++m) {
            a += sg * xp / f2; /* xp = x^(m-1) */
            b += sg * xp / f3;
            if (m >= 2) { /* xq = x^(m-2) */
                c += -sg * (2.0 * m - 2.0) / f2 * xq;
                d += -sg * (2.0 - 2.0 * m) / f3 * xq;
                xq *= x;
            }
            sg = -sg;
            xp *= x;
            f2 *= (2.0 * m + 1) * (2.0 * m + 2);
            f3 *= (2.0 * m + 2) * (2.0 * m + 3);
        }
        *k0 = a;
        *k1 = b;
        *n1 = c;
        *n2 = d;
    } else {
        double s = sin(th), co = cos(th);
        *k0 = (1.0 - co) / x;
        *k1 = (th - s) / (x * th);
        *n1 = (2.0 - 2.0 * co - th * s) / (x * x);
        *n2 = (3.0 * s - 2.0 * th - th * co) / (x * x * th);
    }
    if (th < 0.5) {
        /* (th/2) cot(th/2) = sum_n (-1)^n B_2n th^2n/(2n)!: ki = 1/12 + x/720 +
           x^2/30240 + x^3/1209600 + x^4/47900160 + 691 x^5/1307674368000
           (Bernoulli numbers; the next term is below 1e-17 of the first) */
        *ki = 1.0 / 12 +
              x * (1.0 / 720 + x * (1.0 / 30240 + x * (1.0 / 1209600 +
                                                       x * (1.0 / 47900160 + x * 691.0 / 1307674368000.0))));
    } else {
        *ki = (1.0 - 0.5 * th / tan(0.5 * th)) / x;
    }
}

/* out = J_r(r) y */
static void jr_apply(const double *r, const double *y, double *out)
{
    double k0, k1, n1, n2, ki, c[3], cc[3];
    so3_coef(sqrt(dot3(r, r)), &k0, &k1, &n1, &n2, &ki);
    cross3(r, y, c);
    cross3(r, c, cc);
    for (int k = 0; k < 3; ++k) out[k] = y[k] - k0 * c[k] + k1 * cc[k];
}
/* out = J_r(r)^-1 y */
static void jrinv_apply(const double *r, const double *y, double *out)
{
    double k0, k1, n1, n2, ki, c[3], cc[3];
    so3_coef(sqrt(dot3(r, r)), &k0, &k1, &n1, &n2, &ki);
    cross3(r, y, c);
    cross3(r, c, cc);
    for (int k = 0; k < 3; ++k) out[k] = y[k] + 0.5 * c[k] + ki * cc[k];
}
/* out = d/dt(J_r(r(t))) r'(t), the angular acceleration's term beyond J_r r'' */
static void jr_nonlin(const double *r, const double *rd, double *out)
{
    double k0, k1, n1, n2, ki, cp[3], ccp[3], dccp[3], dp = dot3(r, rd);
    so3_coef(sqrt(dot3(r, r)), &k0, &k1, &n1, &n2, &ki);
    cross3(r, rd, cp);
    cross3(r, cp, ccp);
    cross3(rd, cp, dccp);
    for (int k = 0; k < 3; ++k) out[k] = dp * (n1 * cp[k] + n2 * ccp[k]) + k1 * dccp[k];
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

static double *dkey(const ga_path *p, size_t i) { return p->dec + i * DK; }
static double *dseg(const ga_path *p, size_t i) { return p->dec + p->cap * DK + i * DS; }
static double *dscr(const ga_path *p, size_t i) { return p->dec + p->cap * DK + (p->cap - 1) * DS + i * DX; }

/* d x d helpers (d <= MAXD, row-major) for the block-tridiagonal solve */
static void m3_of_jr(const double *r, int inv, double *m)
{
    for (int j = 0; j < 3; ++j) {
        double e[3] = {j == 0, j == 1, j == 2}, c[3];
        if (inv)
            jrinv_apply(r, e, c);
        else
            jr_apply(r, e, c);
        for (int i = 0; i < 3; ++i) m[3 * i + j] = c[i];
    }
}
static void md_mul(size_t d, const double *a, const double *b, double *o)
{
    double t[MAXD * MAXD];
    for (size_t i = 0; i < d; ++i)
        for (size_t j = 0; j < d; ++j) {
            double s = 0.0;
            for (size_t k = 0; k < d; ++k) s += a[d * i + k] * b[d * k + j];
            t[d * i + j] = s;
        }
    memcpy(o, t, d * d * sizeof(double));
}
static void md_vec(size_t d, const double *a, const double *x, double *o)
{
    double t[MAXD];
    for (size_t i = 0; i < d; ++i) {
        double s = 0.0;
        for (size_t k = 0; k < d; ++k) s += a[d * i + k] * x[k];
        t[i] = s;
    }
    memcpy(o, t, d * sizeof(double));
}
/* o = a^-1 by Gauss-Jordan elimination with partial pivoting; GA_ERR_DOMAIN
 * for a matrix singular to working precision (or not finite) */
static int md_inv(size_t d, const double *a, double *o)
{
    double m[MAXD * MAXD], r[MAXD * MAXD];
    memcpy(m, a, d * d * sizeof(double));
    for (size_t i = 0; i < d * d; ++i) r[i] = (i % (d + 1) == 0);
    for (size_t c = 0; c < d; ++c) {
        size_t pv = c;
        for (size_t i = c + 1; i < d; ++i)
            if (fabs(m[d * i + c]) > fabs(m[d * pv + c]))
                pv = i;
        double piv = m[d * pv + c];
        if (!(fabs(piv) > 0) || !isfinite(piv))
            return GA_ERR_DOMAIN;
        for (size_t j = 0; j < d; ++j) {
            double x = m[d * c + j], y = r[d * c + j];
            m[d * c + j] = m[d * pv + j];
            r[d * c + j] = r[d * pv + j];
            m[d * pv + j] = x;
            r[d * pv + j] = y;
            m[d * c + j] /= piv;
            r[d * c + j] /= piv;
        }
        for (size_t i = 0; i < d; ++i) {
            double f = m[d * i + c];
            if (i == c || f == 0.0)
                continue;
            for (size_t j = 0; j < d; ++j) {
                m[d * i + j] -= f * m[d * c + j];
                r[d * i + j] -= f * r[d * c + j];
            }
        }
    }
    memcpy(o, r, d * d * sizeof(double));
    return GA_OK;
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
    double h0 = seg_len(p, 0), m0 = (Y(1) - Y(0)) / h0;
    if (n == 2) {
        S(0) = S(1) = m0;
        return;
    }
    double h1 = seg_len(p, 1), m1 = (Y(2) - Y(1)) / h1;
    if (n == 3) { /* the parabola: its slope at t_1, and 2 m - s at the ends */
        S(1) = (h1 * m0 + h0 * m1) / (h0 + h1);
        S(0) = 2.0 * m0 - S(1);
        S(2) = 2.0 * m1 - S(1);
        return;
    }
    double r0 = ((h0 + 2.0 * (h0 + h1)) * h1 * m0 + h0 * h0 * m1) / (h0 + h1);
    double ha = seg_len(p, n - 3), hb = seg_len(p, n - 2);
    double ma = (Y(n - 2) - Y(n - 3)) / ha, mb = (Y(n - 1) - Y(n - 2)) / hb;
    double rl = (hb * hb * ma + (2.0 * (ha + hb) + hb) * ha * mb) / (ha + hb);
    /* forward sweep over rows k = 1..n-2 (cp: modified upper diagonal, rp: rhs) */
    for (size_t k = 1; k + 1 < n; ++k) {
        double hl = seg_len(p, k - 1), hr = seg_len(p, k);
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

/* The C2 system of key velocities, shared by DECOUPLED_C2 (the rotation
 * vector, d = 3, SO(3)'s closed forms) and C2 (the twist, d = g->dim, through
 * the group's dexp and the 4x4 jet). On segment i the motion is
 * exp(x(tau)), x a cubic with x(0) = 0, x(h_i) = theta_i, x'(0) = w_i and
 * J_r(theta_i) x'(h_i) = w_{i+1}; its body acceleration is
 * J_r(x) x'' + N(x, x'), N = (d/dt J_r(x)) x'. Row k (interior key): the
 * accelerations of segments k-1 (at its end) and k (at its start) equal,
 *   2/h_{k-1} J_r(theta_{k-1}) w_{k-1} + (4/h_{k-1} + 4/h_k) w_k
 *     + 2/h_k J_r^-1(theta_k) w_{k+1}
 *   = 6 theta_{k-1}/h_{k-1}^2 + 6 theta_k/h_k^2 - N(theta_{k-1}, J_r^-1(theta_{k-1}) w_k)
 * (scipy's RotationSpline._solve_for_angular_rates for SO(3), which iterates
 * it as a fixed point, 10 sweeps at most). Each sweep here linearises N at
 * the current rates (Newton) and solves the block-tridiagonal system by block
 * Thomas (without N it is block diagonally dominant: |J_r| <= 1,
 * |J_r^-1| <= pi/2 on SO(3)); the full Newton step is taken (halving steps
 * that raise the largest residual failed more often: docs/schemes.md). At
 * most C2_SWEEPS; converged when no rate moves by more than 4 DBL_EPSILON of the
 * largest, or the change stops shrinking once it is below 1e-12 of it. Where
 * that fails, continuation (c2_solve). */
#define C2_SWEEPS 200
#define C2_CONTINUATION_SWEEPS 1200 /* all the continuation's sweeps together */

typedef struct {
    ga_path *p;
    size_t d;
    const double *(*theta)(const ga_path *p, size_t seg); /* theta_i */
    double *(*rate)(const ga_path *p, size_t key);        /* w_i */
    double *(*scratch)(const ga_path *p, size_t key);     /* d*d + d doubles */
    /* m = the d x d matrix of J_r(th) (inv = 0) or of J_r(th)^-1 (inv = 1) */
    int (*jr)(const ga_path *p, const double *th, int inv, double *m);
    /* o = N(th, y) */
    int (*nonlin)(const ga_path *p, const double *th, const double *y, double *o);
    /* the interior rates set to where the sweeps start */
    void (*start)(ga_path *p);
} c2_sys;

/* Newton sweeps on the system with N scaled by lam (1: the system itself),
 * from the current rates, at most *budget of them (counted down). GA_OK
 * when converged: to the rule above when final, else to 1e-9 of the
 * largest rate (a start for the next lam). */
static int c2_newton(const c2_sys *s, double lam, int final, int *budget)
{
    ga_path *p = s->p;
    size_t n = p->n, d = s->d, dd = d * d;
    double prev = INFINITY;
    int st;
    for (; *budget > 0; --*budget) {
        double big = 0.0, delta = 0.0;
        for (size_t k = 1; k + 1 < n; ++k) {
            const double *tl = s->theta(p, k - 1), *tr = s->theta(p, k);
            double hl = seg_len(p, k - 1), hr = seg_len(p, k);
            double L[MAXD * MAXD], U[MAXD * MAXD], D[MAXD * MAXD], Ji[MAXD * MAXD], Jn[MAXD * MAXD];
            double rhs[MAXD], rde[MAXD], nl[MAXD], t3[MAXD], jw[MAXD], sc = 0.0;
            double *C = s->scratch(p, k), *y = C + dd;
            const double *wk = s->rate(p, k);
            if ((st = s->jr(p, tl, 0, L)) || (st = s->jr(p, tr, 1, U)) || (st = s->jr(p, tl, 1, Ji)))
                return st;

            /* N(theta_{k-1}, J_r^-1(theta_{k-1}) w_k), linearised at the current
               w_k: N + Jn (w - w_k), Jn = dN/dr' J_r^-1, dN/dr' by polarisation
               (N is quadratic in r': dN/dr' e = (N(r' + s e) - N(r' - s e))/(2s),
               exact for any s; s = |r'| keeps the rounding relative) */
            md_vec(d, Ji, wk, rde);
            if ((st = s->nonlin(p, tl, rde, nl)))
                return st;
            for (size_t j = 0; j < d; ++j) sc += rde[j] * rde[j];
            sc = sqrt(sc);
            if (!(sc > 0) || !isfinite(sc))
                sc = 1.0;
            for (size_t c = 0; c < d; ++c) {
                double xp[MAXD], xm[MAXD], np[MAXD], nm[MAXD];
                for (size_t j = 0; j < d; ++j) {
                    xp[j] = rde[j] + (j == c ? sc : 0.0);
                    xm[j] = rde[j] - (j == c ? sc : 0.0);
                }
                if ((st = s->nonlin(p, tl, xp, np)) || (st = s->nonlin(p, tl, xm, nm)))
                    return st;
                for (size_t j = 0; j < d; ++j) Jn[d * j + c] = (np[j] - nm[j]) / (2.0 * sc);
            }
            md_mul(d, Jn, Ji, Jn);
            for (size_t j = 0; j < dd; ++j) Jn[j] *= lam;
            md_vec(d, Jn, wk, jw);
            for (size_t j = 0; j < d; ++j)
                rhs[j] = 6.0 * tl[j] / (hl * hl) + 6.0 * tr[j] / (hr * hr) - lam * nl[j] + jw[j];
            for (size_t j = 0; j < dd; ++j) {
                L[j] *= 2.0 / hl;
                U[j] *= 2.0 / hr;
                D[j] = (j % (d + 1) == 0 ? 4.0 / hl + 4.0 / hr : 0.0) + Jn[j];
            }
            if (k == 1) {
                md_vec(d, L, s->rate(p, 0), t3);
                for (size_t j = 0; j < d; ++j) rhs[j] -= t3[j];
            } else {
                double LC[MAXD * MAXD];
                const double *Cp = s->scratch(p, k - 1), *yp = Cp + dd;
                md_mul(d, L, Cp, LC);
                for (size_t j = 0; j < dd; ++j) D[j] -= LC[j];
                md_vec(d, L, yp, t3);
                for (size_t j = 0; j < d; ++j) rhs[j] -= t3[j];
            }
            if (k == n - 2) {
                md_vec(d, U, s->rate(p, n - 1), t3);
                for (size_t j = 0; j < d; ++j) rhs[j] -= t3[j];
                for (size_t j = 0; j < dd; ++j) U[j] = 0.0;
            }
            double Di[MAXD * MAXD];
            if ((st = md_inv(d, D, Di)))
                return st;
            md_mul(d, Di, U, C);
            md_vec(d, Di, rhs, y);
        }
        double nxt[MAXD] = {0};
        for (size_t k = n - 1; k-- > 1;) {
            double *C = s->scratch(p, k), *y = C + dd, *w = s->rate(p, k), nw[MAXD];
            md_vec(d, C, nxt, nw);
            for (size_t j = 0; j < d; ++j) {
                nw[j] = y[j] - nw[j];
                delta = fmax(delta, fabs(nw[j] - w[j]));
                big = fmax(big, fabs(nw[j]));
            }
            memcpy(w, nw, d * sizeof(double));
            memcpy(nxt, nw, d * sizeof(double));
        }
        if (!isfinite(delta) || !isfinite(big))
            return GA_ERR_DOMAIN;
        if (delta <= 4 * DBL_EPSILON * big || (delta <= 1e-12 * big && delta >= prev))
            return GA_OK;
        if (!final && delta <= 1e-9 * big)
            return GA_OK;
        prev = delta;
    }
    return GA_ERR_DOMAIN;
}

/* Newton from the start; where it does not converge, continuation: from
 * the start again, the systems with N scaled by 1/m, 2/m, ..., 1, each
 * solved from the last one's rates, for m = 4, 16 and 64 in turn (the
 * system without N is linear and block diagonally dominant, and a small
 * change of lam moves the solution little); C2_SWEEPS at most for each,
 * C2_CONTINUATION_SWEEPS for all, which bounds the time a key set that
 * has no solution within reach takes to fail (docs/schemes.md: about a
 * second at 32 keys). Uncapped steps failed more often (on 600 key sets of
 * soak_c2_spacing's kind, rho = 1000: 3 and 1 against 2 and 1), and so did
 * steps capped at 30 sweeps (3 and 4). */
static int c2_solve(const c2_sys *s)
{
    int budget = C2_SWEEPS, st = c2_newton(s, 1.0, 1, &budget);
    budget = C2_CONTINUATION_SWEEPS;
    for (int m = 4; st == GA_ERR_DOMAIN && m <= 64 && budget > 0; m *= 4) {
        s->start(s->p);
        st = GA_OK;
        for (int j = 1; j <= m && st == GA_OK; ++j) {
            int step = budget < C2_SWEEPS ? budget : C2_SWEEPS, left = step;
            st = c2_newton(s, (double)j / m, j == m, &left);
            budget -= step - left;
        }
    }
    return st;
}

/* The relative rotation vector theta_i = plog(R_i^-1 R_{i+1}) of segment i,
   through the group's half-turn rule as a twist (theta, 0), parked in slot a. */
static void dec_rel_rotation(ga_path *p, size_t i)
{
    double qc[4], qr[4], x[MAXD] = {0};
    const double *q0 = dkey(p, i), *q1 = dkey(p, i + 1);
    qc[0] = q0[0];
    for (int k = 1; k < 4; ++k) qc[k] = -q0[k];
    qmul(qc, q1, qr);
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
    double h = seg_len(p, i), *rc = dseg(p, i), *pc = rc + 9, th[3];
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
    jr_nonlin(th, y, o);
    return GA_OK;
}

static void dec_start(ga_path *p)
{
    for (size_t i = 0; i < p->n; ++i) {
        size_t j = i + 1 < p->n ? i : i - 1;
        double h = seg_len(p, j);
        for (int k = 0; k < 3; ++k) dkey(p, i)[7 + k] = dseg(p, j)[k] / h;
    }
}

static int build_decoupled(ga_path *p)
{
    const ga_group *g = p->group;
    size_t n = p->n;
    /* every slot defined (the linear scheme leaves slopes and scratch unused,
       and build() checks the whole block for finiteness) */
    memset(p->dec, 0, scheme_doubles(p->scheme, p->cap, g->dim) * sizeof(double));
    for (size_t i = 0; i < n; ++i) g->to_qt(key_of(p, i), dkey(p, i), dkey(p, i) + 4);
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
            double h = seg_len(p, i), y0 = dkey(p, i)[4 + c], m = (dkey(p, i + 1)[4 + c] - y0) / h;
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
        c2_sys sys = {p, 3, dec_theta, dec_rate, dec_scratch, dec_jr, dec_nonlin, dec_start};
        int st = c2_solve(&sys);
        if (st != GA_OK)
            return st;
    }
    /* rotation cubics: a = w_i, r'(h) = J_r^-1(theta) w_{i+1},
       b = (3 theta - 2h a - h r'(h))/h^2, c = (-2 theta + h a + h r'(h))/h^3
       (Hermite; scipy's RotationSpline coefficients) */
    for (size_t i = 0; i + 1 < n; ++i) {
        double *rc = dseg(p, i), th[3], re[3], h = seg_len(p, i);
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

/* The pose on segment seg at u, and (either may be NULL) the body velocity and
 * acceleration per unit t. */
static int dec_eval(const ga_path *p, size_t seg, double u, void *out, double *v, double *a)
{
    const double *rc = dseg(p, seg), *pc = rc + 9, *q0 = dkey(p, seg);
    double tau = u * seg_len(p, seg), r[3], rd[3], rdd[3], pos[3], pd[3], pdd[3], qe[4], q[4];
    for (int k = 0; k < 3; ++k) {
        r[k] = ((rc[6 + k] * tau + rc[3 + k]) * tau + rc[k]) * tau;
        rd[k] = (3.0 * rc[6 + k] * tau + 2.0 * rc[3 + k]) * tau + rc[k];
        rdd[k] = 6.0 * rc[6 + k] * tau + 2.0 * rc[3 + k];
        pos[k] = ((pc[9 + k] * tau + pc[6 + k]) * tau + pc[3 + k]) * tau + pc[k];
        pd[k] = (3.0 * pc[9 + k] * tau + 2.0 * pc[6 + k]) * tau + pc[3 + k];
        pdd[k] = 6.0 * pc[9 + k] * tau + 2.0 * pc[6 + k];
    }
    qexp(r, qe);
    qmul(q0, qe, q);
    if (out) {
        p->group->from_qt(q, pos, out);
        int st = finite_elem(p->group, out);
        if (st != GA_OK)
            return st;
    }
    if (v || a) {
        /* w = J_r(r) r', v = R^T p'; w' = J_r(r) r'' + N(r, r'),
           d/dt (R^T p') = R^T p'' - w x R^T p' */
        double w[3], lv[3], wd[3], nl[3], la[3], c[3];
        jr_apply(r, rd, w);
        qrot_inv(q, pd, lv);
        if (v) {
            memcpy(v, w, sizeof w);
            memcpy(v + 3, lv, sizeof lv);
        }
        if (a) {
            jr_apply(r, rdd, wd);
            jr_nonlin(r, rd, nl);
            qrot_inv(q, pdd, la);
            cross3(w, lv, c);
            for (int k = 0; k < 3; ++k) {
                a[k] = wd[k] + nl[k];
                a[3 + k] = la[k] - c[k];
            }
        }
    }
    return GA_OK;
}

/* ---- workspace ---------------------------------------------------------------- */

static size_t scheme_doubles(ga_scheme s, size_t N, size_t D)
{
    size_t S = N - 1;
    switch (s) {
    case GA_SCHEME_SCREW:
    case GA_SCHEME_BSPLINE: return S * D;
    case GA_SCHEME_LIHAO2: return 2 * S * D + N * D;
    case GA_SCHEME_LIHAO3: return 3 * S * D + N * D;
    case GA_SCHEME_BIVECTOR: return N * D;
    case GA_SCHEME_QUADRATIC:
    case GA_SCHEME_SMOOTH: return N * D + S * D + S;
    case GA_SCHEME_DECOUPLED:
    case GA_SCHEME_DECOUPLED_C2: return N * (DK + DX) + S * DS;
    case GA_SCHEME_C2: return 3 * S * D + N * D + N * (D * D + D);
    }
    return 0;
}

size_t ga_path_workspace_size(const ga_group *g, ga_scheme s, size_t n)
{
    if (!g || n < 1 || (unsigned)s >= GA_SCHEME_COUNT || rigid_only(g, s))
        return 0;
    size_t stride = (g->elem_size + sizeof(double) - 1) / sizeof(double);
    return sizeof(double) * (n + n * stride + scheme_doubles(s, n, g->dim));
}

/* Check the arguments and lay the arrays out in the workspace. */
static int layout(ga_path *p, const ga_group *g, ga_scheme s, size_t n, const double *times, const void *keys,
                  void *work, size_t bytes)
{
    if (!p || !g || !times || !keys || !work || (unsigned)s >= GA_SCHEME_COUNT)
        return GA_ERR_ARG;
    if (rigid_only(g, s))
        return GA_ERR_ARG; /* rotation and translation apart, screw motions: rigid groups only */
    if (n != 1 && (n < ga_scheme_min_keys(s) || (s == GA_SCHEME_QUADRATIC && n != 3)))
        return GA_ERR_ARG; /* one key: the constant path, on every scheme */
    if (bytes < ga_path_workspace_size(g, s, n) || (uintptr_t)work % _Alignof(double))
        return GA_ERR_ARG;
    if (!allfinite(times, n))
        return GA_ERR_NOTFINITE;
    for (size_t i = 0; i + 1 < n; ++i)
        if (!(times[i] < times[i + 1]))
            return GA_ERR_ARG;
    if (s == GA_SCHEME_BSPLINE && ga_times_uneven(n, times))
        return GA_ERR_ARG;
    size_t d = g->dim, m = n;
    if (ga_scheme_can_append(s)) { /* every key the workspace has room for */
        size_t one = ga_path_workspace_size(g, s, 1), per = ga_path_workspace_size(g, s, 2) - one;
        m += (bytes - ga_path_workspace_size(g, s, n)) / per;
    }
    double *w = work;
    memset(p, 0, sizeof *p);
    p->group = g;
    p->scheme = s;
    p->n = n;
    p->cap = m;
    p->key_stride = (g->elem_size + sizeof(double) - 1) / sizeof(double);
    p->t = w;
    w += m;
    p->key = w;
    w += m * p->key_stride;
    memcpy(p->t, times, n * sizeof(double));
    switch (s) {
    case GA_SCHEME_SCREW:
    case GA_SCHEME_BSPLINE: p->coef = w; break;
    case GA_SCHEME_LIHAO2:
        p->coef = w;
        p->vel = w + 2 * (m - 1) * d;
        break;
    case GA_SCHEME_LIHAO3:
        p->coef = w;
        p->vel = w + 3 * (m - 1) * d;
        break;
    case GA_SCHEME_BIVECTOR: p->gen = w; break;
    case GA_SCHEME_QUADRATIC:
    case GA_SCHEME_SMOOTH:
        p->gen = w;
        p->slope = w + m * d;
        break;
    case GA_SCHEME_DECOUPLED:
    case GA_SCHEME_DECOUPLED_C2: p->dec = w; break;
    case GA_SCHEME_C2:
        p->coef = w;
        p->vel = w + 3 * (n - 1) * d;
        break;
    }
    return GA_OK;
}

/* ---- building the schemes ------------------------------------------------------ */

/* LIHAO2 and LIHAO3 segment i from the velocity at key i (and LIHAO3: at key
 * i + 1); LIHAO2 writes the velocity at key i + 1. */
static int lihao_segment(ga_path *p, size_t i)
{
    const ga_group *g = p->group;
    size_t d = g->dim, nf = nfac(p->scheme);
    double rel[MAXE], reli[MAXE], e[MAXE], m[MAXE], x[MAXD], ad[MAXD], ai[MAXE];
    int st;
    double h = seg_len(p, i);
    double *B = p->coef + i * nf * d, *C = B + d, *D = C + d;
    const double *vi = p->vel + i * d;
    /* eq. 26: B_i = velocity at the key, per unit u */
    lin(d, B, h, vi, 0.0, vi);
    if (!allfinite(B, d))
        return GA_ERR_DOMAIN;
    /* eq. 16 (and 27 corrected): exp(B_i) exp(C_i) = A_i^-1 A_{i+1} */
    if ((st = g->inverse(key_of(p, i), ai)))
        return st;
    g->compose(ai, key_of(p, i + 1), rel);
    lin(d, x, -1.0, B, 0.0, B);
    if ((st = g->exp(x, e)))
        return st;
    g->compose(e, rel, m);
    if ((st = plog(g, m, C)))
        return st;
    /* body velocity of exp(uB)exp(u^2 C) at u = 1: Ad_{rel^-1} B + 2 C (eqs. 15, 17) */
    if ((st = g->inverse(rel, reli)))
        return st;
    g->adjoint(reli, B, ad);
    const double *vn = p->vel + (i + 1) * d;
    if (p->scheme == GA_SCHEME_LIHAO2) /* eq. 17, per unit t: the next key's velocity */
        lin(d, p->vel + (i + 1) * d, 1.0 / h, ad, 2.0 / h, C);
    else /* eq. 28: D_i = h V_{i+1} - Ad_{rel^-1} B_i - 2 C_i */
        for (size_t k = 0; k < d; ++k) D[k] = h * vn[k] - ad[k] - 2.0 * C[k];
    return GA_OK;
}

/* SCREW (Li-Hao eq. 10), LIHAO2 (eqs. 14-17), LIHAO3 (eqs. 21-28), all in u
 * units on each segment: B_i = h_i V_i where V_i is a velocity per unit t. */
static int build_lihao(ga_path *p, const double *vel)
{
    const ga_group *g = p->group;
    size_t n = p->n, d = g->dim;
    double rel[MAXE];
    int st;
    if (p->scheme == GA_SCHEME_SCREW || p->scheme == GA_SCHEME_BSPLINE) {
        /* BSPLINE: the d_i of path.h, as SCREW's B_i */
        for (size_t i = 0; i + 1 < n; ++i)
            if ((st = rel_log(g, key_of(p, i), key_of(p, i + 1), p->coef + i * d, rel)))
                return st;
        return GA_OK;
    }
    if (p->scheme == GA_SCHEME_LIHAO3) {
        if (vel) {
            if (!allfinite(vel, n * d))
                return GA_ERR_NOTFINITE;
            memcpy(p->vel, vel, n * d * sizeof(double));
        } else {
            /* default rule (path.h): s_i = plog(A_i^-1 A_{i+1})/h_i, parked in D_i */
            for (size_t i = 0; i + 1 < n; ++i) {
                double *s = p->coef + (i * 3 + 2) * d;
                if ((st = rel_log(g, key_of(p, i), key_of(p, i + 1), s, rel)))
                    return st;
                lin(d, s, 1.0 / seg_len(p, i), s, 0.0, s);
            }
            for (size_t i = 0; i < n; ++i) {
                double *v = p->vel + i * d;
                const double *sl = i > 0 ? p->coef + ((i - 1) * 3 + 2) * d : NULL;
                const double *sr = i + 1 < n ? p->coef + (i * 3 + 2) * d : NULL;
                if (!sl)
                    memcpy(v, sr, d * sizeof(double));
                else if (!sr)
                    memcpy(v, sl, d * sizeof(double));
                else {
                    double hl = seg_len(p, i - 1), hr = seg_len(p, i);
                    lin(d, v, hr / (hl + hr), sl, hl / (hl + hr), sr);
                }
            }
        }
    } else { /* LIHAO2: the first key's velocity */
        if (vel) {
            if (!allfinite(vel, d))
                return GA_ERR_NOTFINITE;
            memcpy(p->vel, vel, d * sizeof(double));
        } else {
            if ((st = rel_log(g, key_of(p, 0), key_of(p, 1), p->vel, rel)))
                return st;
            lin(d, p->vel, 1.0 / seg_len(p, 0), p->vel, 0.0, p->vel);
        }
    }
    /* finite input, but a default velocity plog/h or B = h V can overflow (a
       subnormal segment): GA_ERR_DOMAIN, not the GA_ERR_NOTFINITE exp would give
       (fuzz/regress/path/lihao3-default-velocity-overflow-status) */
    if (!allfinite(p->vel, (p->scheme == GA_SCHEME_LIHAO3 ? n : 1) * d))
        return GA_ERR_DOMAIN;
    for (size_t i = 0; i + 1 < n; ++i)
        if ((st = lihao_segment(p, i)))
            return st;
    return GA_OK;
}

/* Key generators with the branch rule of path.h (W-L §3: the group's branch
 * rule, group.h). */
static int build_generators(ga_path *p)
{
    const ga_group *g = p->group;
    size_t d = g->dim;
    int st;
    for (size_t i = 0; i < p->n; ++i) {
        double *x = p->gen + i * d;
        if ((st = plog(g, key_of(p, i), x)))
            return st;
        if (g->branch && i > 0)
            g->branch(x - d, x);
    }
    return GA_OK;
}

/* Breakpoints of the SMOOTH spline: xi_0 = t_0, xi_k = (t_k + t_{k+1})/2 for
 * 1 <= k <= n-3, xi_{n-2} = t_{n-1}. */
static double brk(const ga_path *p, size_t k)
{
    if (k == 0)
        return p->t[0];
    if (k == p->n - 2)
        return p->t[p->n - 1];
    return 0.5 * (p->t[k] + p->t[k + 1]);
}

/* The slopes d_k = X'(xi_k) of the SMOOTH spline (path.h). X' is linear on
 * each piece [xi_k, xi_{k+1}], and for each segment j the integral of X' over
 * [t_j, t_{j+1}] (trapezoids on the at most two pieces it meets) must equal
 * X_{j+1} - X_j. Row j, divided by h_j/2 (alpha, beta, gamma, delta: where
 * t_j, t_{j+1} fall in their pieces, each in (0, 1)):
 *   j = 0:        (2 - g) d_0 + g d_1                         = 2 dX_0/h_0
 *   0 < j < n-2:  (1-a)/2 d_{j-1} + (3+a-b)/2 d_j + b/2 d_{j+1} = 2 dX_j/h_j
 *   j = n-2:      (1 - e) d_{n-3} + (1 + e) d_{n-2}           = 2 dX_j/h_j
 * Each row is strictly diagonally dominant, so the Thomas algorithm is stable. */
static void build_smooth(ga_path *p)
{
    size_t n = p->n, d = p->group->dim, m = n - 1;
    double *cp = p->slope + m * d; /* scratch: the modified upper diagonal */
    for (size_t j = 0; j < m; ++j) {
        double h = seg_len(p, j), lo, di, up;
        if (j == 0) {
            double gam = h / (brk(p, 1) - brk(p, 0));
            lo = 0.0;
            di = 2.0 - gam;
            up = gam;
        } else if (j == n - 2) {
            double del = (p->t[n - 2] - brk(p, n - 3)) / (brk(p, n - 2) - brk(p, n - 3));
            lo = 1.0 - del;
            di = 1.0 + del;
            up = 0.0;
        } else {
            double al = (p->t[j] - brk(p, j - 1)) / (brk(p, j) - brk(p, j - 1));
            double be = (p->t[j + 1] - brk(p, j)) / (brk(p, j + 1) - brk(p, j));
            lo = 0.5 * (1.0 - al);
            di = 0.5 * (3.0 + al - be);
            up = 0.5 * be;
        }
        double *r = p->slope + j * d;
        const double *x0 = p->gen + j * d, *x1 = x0 + d;
        for (size_t k = 0; k < d; ++k) r[k] = 2.0 * (x1[k] - x0[k]) / h;
        if (j > 0) {
            const double *rp = r - d; /* the previous row (an index k - d would wrap: k is unsigned) */
            di -= lo * cp[j - 1];
            for (size_t k = 0; k < d; ++k) r[k] -= lo * rp[k];
        }
        cp[j] = up / di;
        for (size_t k = 0; k < d; ++k) r[k] /= di;
    }
    for (size_t j = m - 1; j-- > 0;) {
        double *r = p->slope + j * d;
        for (size_t k = 0; k < d; ++k) r[k] -= cp[j] * r[k + d];
    }
}

/* C2 (path.h): on segment i, A_i exp(x(tau)), x(tau) = a tau + b tau^2 +
 * c tau^3 in coef (t units), the key velocities in vel solved by c2_solve
 * through the group (J_r by dexp, N by the 4x4 jet), then per key the
 * solver's scratch. theta_i = plog(A_i^-1 A_{i+1}) is parked in slot c. */
static const double *c2_theta(const ga_path *p, size_t i) { return p->coef + (3 * i + 2) * p->group->dim; }
static double *c2_rate(const ga_path *p, size_t i) { return p->vel + i * p->group->dim; }
static double *c2_scratch(const ga_path *p, size_t i)
{
    size_t d = p->group->dim;
    return p->vel + p->n * d + i * (d * d + d);
}
static int c2_jr(const ga_path *p, const double *th, int inv, double *m)
{
    const ga_group *g = p->group;
    size_t d = g->dim;
    double e[MAXD] = {0}, c[MAXD], J[MAXD * MAXD];
    for (size_t j = 0; j < d; ++j) {
        e[j] = 1.0;
        g->dexp(th, e, c);
        e[j] = 0.0;
        for (size_t i = 0; i < d; ++i) J[d * i + j] = c[i];
    }
    if (inv)
        return md_inv(d, J, m);
    memcpy(m, J, d * d * sizeof(double));
    return GA_OK;
}
static int exp_curve_deriv(const ga_group *g, const double *x, const double *xd, const double *xdd, double *v,
                           double *a);
/* N(theta, y) by the jet. The jet's squarings grow with log2 of theta's size,
 * and a translation near DBL_MAX would take a thousand per call (found by
 * fuzz/fuzz_path: a build of five keys took seconds). Scaling translations
 * by l is an automorphism of SE(3) (it commutes with exp, Ad and dexp), so
 * N(S x, S y) = S N(x, y) for S = diag(1, 1, 1, l, l, l): a translation of
 * theta beyond 2^20 is brought below 1 by a power of two l (exact, so the
 * scaling changes nothing but the jet's work). */
static int c2_nonlin(const ga_path *p, const double *th, const double *y, double *o)
{
    const double zero[MAXD] = {0};
    double big = fmax(fabs(th[3]), fmax(fabs(th[4]), fabs(th[5])));
    if (!(big > 0x1p20) || !isfinite(big))
        return exp_curve_deriv(p->group, th, y, zero, NULL, o);
    int e;
    frexp(big, &e);
    double x[6], ys[6];
    for (int k = 0; k < 6; ++k) {
        x[k] = k < 3 ? th[k] : ldexp(th[k], -e);
        ys[k] = k < 3 ? y[k] : ldexp(y[k], -e);
    }
    int st = exp_curve_deriv(p->group, x, ys, zero, NULL, o);
    for (int k = 3; k < 6; ++k) o[k] = ldexp(o[k], e);
    return st;
}

/* the ends: the screw velocities theta/h of the end segments (each a body
   velocity at both its ends); the interior, to start: lihao3's default (the
   parabola through the neighbouring screw velocities) */
static void c2_start(ga_path *p)
{
    size_t n = p->n, d = p->group->dim;
    for (size_t i = 0; i < n; ++i) {
        double *v = c2_rate(p, i);
        if (i == 0 || i + 1 == n) {
            size_t j = i ? i - 1 : 0;
            lin(d, v, 1.0 / seg_len(p, j), c2_theta(p, j), 0.0, v);
        } else {
            double hl = seg_len(p, i - 1), hr = seg_len(p, i);
            lin(d, v, hr / ((hl + hr) * hl), c2_theta(p, i - 1), hl / ((hl + hr) * hr), c2_theta(p, i));
        }
    }
}

static int build_c2(ga_path *p)
{
    const ga_group *g = p->group;
    size_t n = p->n, d = g->dim;
    double rel[MAXE], J[MAXD * MAXD], e[MAXD];
    int st;
    memset(p->coef, 0, scheme_doubles(p->scheme, n, d) * sizeof(double));
    for (size_t i = 0; i + 1 < n; ++i)
        if ((st = rel_log(g, key_of(p, i), key_of(p, i + 1), p->coef + (3 * i + 2) * d, rel)))
            return st;
    c2_start(p);
    if (!allfinite(p->vel, n * d))
        return GA_ERR_DOMAIN;
    if (n > 2) {
        c2_sys sys = {p, d, c2_theta, c2_rate, c2_scratch, c2_jr, c2_nonlin, c2_start};
        if ((st = c2_solve(&sys)))
            return st;
    }
    /* Hermite: a = w_i, x'(h) = J_r^-1(theta) w_{i+1},
       b = (3 theta - 2h a - h x'(h))/h^2, c = (-2 theta + h a + h x'(h))/h^3 */
    for (size_t i = 0; i + 1 < n; ++i) {
        double *A = p->coef + 3 * i * d, *B = A + d, *C = B + d, th[MAXD], h = seg_len(p, i);
        const double *w = c2_rate(p, i);
        memcpy(th, C, d * sizeof(double));
        if ((st = c2_jr(p, th, 1, J)))
            return st;
        md_vec(d, J, c2_rate(p, i + 1), e);
        for (size_t k = 0; k < d; ++k) {
            A[k] = w[k];
            B[k] = (3.0 * th[k] - 2.0 * h * w[k] - h * e[k]) / (h * h);
            C[k] = (-2.0 * th[k] + h * w[k] + h * e[k]) / (h * h * h);
        }
    }
    return GA_OK;
}

/* x(tau), x'(tau), x''(tau) of C2 segment seg at u (tau = u h, per unit t). */
static void c2_curve(const ga_path *p, size_t seg, double u, double *x, double *xd, double *xdd)
{
    size_t d = p->group->dim;
    const double *A = p->coef + 3 * seg * d, *B = A + d, *C = B + d;
    double tau = u * seg_len(p, seg);
    for (size_t k = 0; k < d; ++k) {
        x[k] = ((C[k] * tau + B[k]) * tau + A[k]) * tau;
        if (xd)
            xd[k] = (3.0 * C[k] * tau + 2.0 * B[k]) * tau + A[k];
        if (xdd)
            xdd[k] = 6.0 * C[k] * tau + 2.0 * B[k];
    }
}

static int build_scheme(ga_path *p, const double *vel)
{
    switch (p->scheme) {
    case GA_SCHEME_SCREW:
    case GA_SCHEME_BSPLINE:
    case GA_SCHEME_LIHAO2:
    case GA_SCHEME_LIHAO3: return build_lihao(p, vel);
    case GA_SCHEME_BIVECTOR: return build_generators(p);
    case GA_SCHEME_QUADRATIC:
    case GA_SCHEME_SMOOTH: {
        int st = build_generators(p);
        if (st == GA_OK)
            build_smooth(p);
        return st;
    }
    case GA_SCHEME_DECOUPLED:
    case GA_SCHEME_DECOUPLED_C2: return build_decoupled(p);
    case GA_SCHEME_C2: return build_c2(p);
    }
    return GA_ERR_ARG;
}

/* The scheme's coefficients, which follow the keys in the workspace, must be
 * finite (see finite_elem). The keys and velocities are checked first, so a
 * GA_ERR_NOTFINITE from inside (a log of a product of keys that overflowed) is
 * finite input overflowing: GA_ERR_DOMAIN (found by fuzz/fuzz_path:
 * fuzz/regress/path/cga-key-product-overflow). */
static int build(ga_path *p, const double *vel)
{
    const ga_group *g = p->group;
    size_t ed = g->elem_size / sizeof(double);
    for (size_t i = 0; i < p->n; ++i)
        if (!allfinite(key_of(p, i), ed))
            return GA_ERR_NOTFINITE;
    size_t nv = p->scheme == GA_SCHEME_LIHAO3 ? p->n : p->scheme == GA_SCHEME_LIHAO2 ? 1 : 0;
    if (vel && !allfinite(vel, nv * g->dim))
        return GA_ERR_NOTFINITE;
    /* the scheme's block, laid out for p->cap keys: defined everywhere (room
       for keys to come included), so that it can be checked whole */
    double *c = p->key + p->cap * p->key_stride;
    size_t nc = scheme_doubles(p->scheme, p->cap, g->dim);
    if (p->n == 1 || p->cap > p->n)
        memset(c, 0, nc * sizeof(double));
    if (p->n == 1) {                                /* the constant path: no segment, nothing to build */
        if (p->scheme == GA_SCHEME_LIHAO2 && vel) { /* kept for ga_path_append */
            memcpy(p->vel, vel, g->dim * sizeof(double));
            p->v0_given = 1;
        }
        return GA_OK;
    }
    int st = build_scheme(p, vel);
    if (st == GA_ERR_NOTFINITE)
        return GA_ERR_DOMAIN;
    if (st != GA_OK)
        return st;
    return allfinite(c, nc) ? GA_OK : GA_ERR_DOMAIN;
}

/* ga_path_init and ga_path_init_mat4: the keys are group elements, or 4x4
 * matrices read by g->from_mat4 (mat4 != 0). The path is built locally and
 * handed out only on success: on an error *out is untouched (the workspace
 * is not). */
static int init(const ga_group *g, ga_scheme s, size_t n, const double *times, const void *keys, int mat4,
                const double *velocities, void *work, size_t work_bytes, ga_path *out)
{
    ga_path p;
    if (!out)
        return GA_ERR_ARG;
    int st = layout(&p, g, s, n, times, keys, work, work_bytes);
    if (st != GA_OK)
        return st;
    for (size_t i = 0; i < n; ++i) {
        if (!mat4)
            copy_elem(g, key_of(&p, i), (const unsigned char *)keys + i * g->elem_size);
        else if ((st = g->from_mat4(((const ga_mat4 *)keys)[i], key_of(&p, i))))
            return st;
    }
    if ((st = build(&p, velocities)) == GA_OK)
        *out = p;
    return st;
}

ga_status ga_path_init(const ga_group *g, ga_scheme s, size_t n, const double *times, const void *keys,
                       const double *velocities, void *work, size_t work_bytes, ga_path *out)
{
    return init(g, s, n, times, keys, 0, velocities, work, work_bytes, out);
}

ga_status ga_path_init_mat4(const ga_group *g, ga_scheme s, size_t n, const double *times,
                            const ga_mat4 *keys, const double *velocities, void *work, size_t work_bytes,
                            ga_path *out)
{
    return init(g, s, n, times, keys, 1, velocities, work, work_bytes, out);
}

/* Key n goes into the room layout() left for it; segment n - 1 is built from
 * keys n - 1 and n (and LIHAO2: the velocity at key n - 1) by the same code
 * as ga_path_init, so the result is the path ga_path_init would build from
 * all n + 1 keys, bit for bit (tests/test_interp.c). Nothing is visible
 * before p->n grows, so an error leaves the path as it was. */
static int append(ga_path *p, double t, const void *key, int mat4)
{
    if (!p || !key || !p->group)
        return GA_ERR_ARG;
    if (!ga_scheme_can_append(p->scheme) || p->n >= p->cap)
        return GA_ERR_ARG;
    if (!isfinite(t))
        return GA_ERR_NOTFINITE;
    if (!(t > p->t[p->n - 1]))
        return GA_ERR_ARG;
    const ga_group *g = p->group;
    ga_path q = *p; /* the path with the new key, handed out on success */
    size_t i = q.n - 1, d = g->dim;
    double *k = key_of(&q, i + 1), rel[MAXE];
    int st = GA_OK;
    if (!mat4)
        copy_elem(g, k, key);
    else if ((st = g->from_mat4(*(const ga_mat4 *)key, k)))
        return st;
    if (!allfinite(k, g->elem_size / sizeof(double)))
        return GA_ERR_NOTFINITE;
    q.t[i + 1] = t;
    q.n = i + 2;
    /* BSPLINE: at least 4 keys before and after, evenly spaced (path.h) */
    if (q.scheme == GA_SCHEME_BSPLINE && (i + 1 < 4 || ga_times_uneven(i + 2, q.t)))
        return GA_ERR_ARG;
    switch (q.scheme) {
    case GA_SCHEME_BSPLINE: /* d_i of keys i, i + 1, as SCREW's B_i */
    case GA_SCHEME_SCREW:
        st = rel_log(g, key_of(&q, i), k, q.coef + i * d, rel);
        if (st == GA_OK && !allfinite(q.coef + i * d, d))
            st = GA_ERR_DOMAIN;
        break;
    case GA_SCHEME_LIHAO2:
        if (i == 0 && !q.v0_given) { /* the default first velocity (path.h) */
            if ((st = rel_log(g, key_of(&q, 0), k, q.vel, rel)))
                break;
            lin(d, q.vel, 1.0 / seg_len(&q, 0), q.vel, 0.0, q.vel);
        }
        if (!allfinite(q.vel + i * d, d))
            st = GA_ERR_DOMAIN;
        else if ((st = lihao_segment(&q, i)) == GA_OK &&
                 !(allfinite(q.coef + 2 * i * d, 2 * d) && allfinite(q.vel + (i + 1) * d, d)))
            st = GA_ERR_DOMAIN;
        break;
    case GA_SCHEME_BIVECTOR:
        if (i == 0 && (st = plog(g, key_of(&q, 0), q.gen))) /* one key: nothing was built */
            break;
        if ((st = plog(g, k, q.gen + (i + 1) * d)) == GA_OK && g->branch)
            g->branch(q.gen + i * d, q.gen + (i + 1) * d);
        if (st == GA_OK && !allfinite(q.gen + (i + 1) * d, d))
            st = GA_ERR_DOMAIN;
        break;
    case GA_SCHEME_DECOUPLED: {
        double *k0 = dkey(&q, i), saved[6];
        memcpy(saved, k0 + 7, sizeof saved); /* key i's rate and slope, restored on failure */
        if (i == 0)                          /* one key: nothing was built */
            g->to_qt(key_of(&q, 0), k0, k0 + 4);
        g->to_qt(k, dkey(&q, i + 1), dkey(&q, i + 1) + 4);
        dec_rel_rotation(&q, i);
        dec_linear(&q, i);
        if (!allfinite(dkey(&q, i), 2 * DK) || !allfinite(dseg(&q, i), DS)) {
            memcpy(k0 + 7, saved, sizeof saved);
            st = GA_ERR_DOMAIN;
        }
        break;
    }
    default: st = GA_ERR_ARG;
    }
    if (st == GA_ERR_NOTFINITE)
        st = GA_ERR_DOMAIN; /* finite input overflowing, as in build() */
    if (st == GA_OK)
        *p = q;
    return st;
}

ga_status ga_path_append(ga_path *p, double t, const void *key) { return append(p, t, key, 0); }

ga_status ga_path_append_mat4(ga_path *p, double t, ga_mat4 key) { return append(p, t, &key, 1); }

/* ---- evaluation ---------------------------------------------------------------- */

size_t ga_path_segments(const ga_path *p) { return p ? nseg(p) : 0; }

ga_status ga_path_range(const ga_path *p, double *t0, double *t1)
{
    if (!p || !t0 || !t1)
        return GA_ERR_ARG;
    *t0 = knot(p, 0);
    *t1 = knot(p, nseg(p));
    return GA_OK;
}

ga_status ga_path_segment_range(const ga_path *p, size_t seg, double *t0, double *t1)
{
    if (!p || !t0 || !t1 || seg >= nseg(p))
        return GA_ERR_ARG;
    *t0 = knot(p, seg);
    *t1 = knot(p, seg + 1);
    return GA_OK;
}

ga_status ga_path_locate(const ga_path *p, double t, size_t *seg, double *u)
{
    size_t m = nseg(p);
    if (!(t >= knot(p, 0) && t <= knot(p, m)))
        return GA_ERR_ARG; /* also NaN */
    if (m == 0) {          /* the constant path: its key, "segment 0" at u = 0 */
        *seg = 0;
        *u = 0.0;
        return GA_OK;
    }
    size_t lo = 0, hi = m - 1; /* largest i <= m-1 with knot i <= t */
    while (lo < hi) {
        size_t mid = (lo + hi + 1) / 2;
        if (knot(p, mid) <= t)
            lo = mid;
        else
            hi = mid - 1;
    }
    *seg = lo;
    *u = (t - knot(p, lo)) / seg_len(p, lo);
    return GA_OK;
}

/* X(t) and X'(t) (per unit t) of the generator-space schemes on segment j. */
static void gen_curve(const ga_path *p, size_t j, double u, double *x, double *xd)
{
    size_t d = p->group->dim, n = p->n;
    double h = seg_len(p, j);
    const double *x0 = p->gen + j * d, *x1 = x0 + d;
    if (p->scheme == GA_SCHEME_BIVECTOR) { /* W-L §3: linear in the generators */
        lin(d, x, 1.0 - u, x0, u, x1);
        lin(d, xd, 1.0 / h, x1, -1.0 / h, x0);
        return;
    }
    /* SMOOTH / QUADRATIC: from the nearer key a of the segment, inside one
     * piece k where X' is linear: X(t) = X_a + (t - t_a)(X'(t_a) + X'(t))/2. */
    int left = u <= 0.5;
    size_t k = j == 0 ? 0 : j == n - 2 ? n - 3 : left ? j - 1 : j;
    size_t a = left ? j : j + 1;
    double tau = left ? u * h : (u - 1.0) * h;
    double xk = brk(p, k), L = brk(p, k + 1) - xk;
    double fa = (p->t[a] - xk) / L, ft = (p->t[a] + tau - xk) / L;
    const double *dk = p->slope + k * d, *dk1 = dk + d, *xa = p->gen + a * d;
    for (size_t i = 0; i < d; ++i) {
        double sa = dk[i] + (dk1[i] - dk[i]) * fa, st = dk[i] + (dk1[i] - dk[i]) * ft;
        x[i] = xa[i] + tau * 0.5 * (sa + st);
        xd[i] = st;
    }
}

/* ---- SCREW on rotors: a sample as four fixed rotors --------------------------------
 * On the cga group a screw segment is A_i exp(u B), B = -(w I3 + v n)/2 the
 * generator of its twist X = (w, v) (group.c, cga_exp). With beta = -w/2,
 * c = -v/2 (as vectors, rotor.h), phi = |beta| and a = u phi, ga_rotor_exp's
 * closed form of exp(u B) is
 *   cos a + u sinc a (beta + c n) + u^2 sinc a (beta.c) I n + u^3 k(a) (beta.c) beta n,
 * sinc a = sin(a)/a, k(a) = (cos a - sinc a)/a^2, the bivector beta and the
 * vector c written into a rotor as rotor.c's rotor_make does: linear in four
 * rotors E_0 = 1, E_1, E_2, E_3 that are fixed on the segment, with
 * coefficients that depend on u alone. So A_i exp(u B) = sum_j f_j(u) (A_i E_j):
 * the three products A_i E_j once per segment (screw_prep), then per sample
 * the three functions of a, by ga_rotor_exp's series and branches, and 32
 * multiply-adds (screw_at), not an exp and a 48-multiplication product
 * through the group's function pointers. It is the same closed form rounded
 * in another order; tests/test_interp.c measures it against
 * ga_rotor_mul(A_i, ga_rotor_exp(u B)). */
static int screw_rotors(const ga_path *p)
{
    return p->group == &ga_group_cga && p->scheme == GA_SCHEME_SCREW && p->n > 1;
}

/* k01 = A_i E_0 | A_i E_1, k23 = A_i E_2 | A_i E_3 (8 doubles each), *phi2 = |beta|^2. */
static void screw_prep(const ga_path *p, size_t seg, double *k01, double *k23, double *phi2)
{
    const double *x = seg_coef(p, seg);
    double bx = -0.5 * x[0], by = -0.5 * x[1], bz = -0.5 * x[2];
    double cx = -0.5 * x[3], cy = -0.5 * x[4], cz = -0.5 * x[5];
    double bc = bx * cx + by * cy + bz * cz;
    ga_rotor a, e1 = {0, bz, -by, bx, cx, cy, cz, 0}, e2 = {0, 0, 0, 0, 0, 0, 0, bc},
                e3 = {0, 0, 0, 0, bc * bx, bc * by, bc * bz, 0};
    memcpy(&a, key_of(p, seg), sizeof a);
    ga_rotor r1 = ga_rotor_mul_inline(a, e1), r2 = ga_rotor_mul_inline(a, e2),
             r3 = ga_rotor_mul_inline(a, e3);
    memcpy(k01, &a, sizeof a);
    memcpy(k01 + 8, &r1, sizeof r1);
    memcpy(k23, &r2, sizeof r2);
    memcpy(k23 + 8, &r3, sizeof r3);
    *phi2 = bx * bx + by * by + bz * bz;
}

/* A_i exp(u B) from screw_prep's rotors; GA_ERR_DOMAIN where it is not finite
 * (an extrapolation far outside [0, 1]). */
static int screw_at(const double *k01, const double *k23, double phi2, double u, double *out)
{
    double a2 = (u * u) * phi2, cs, sinc, f3;
    if (a2 <= (GA_PI / 4) * (GA_PI / 4)) {
        double y2 = a2 * a2, y4 = y2 * y2, y8 = y4 * y4;
        cs = estrin9(cos_taylor, a2, y2, y4, y8);
        sinc = estrin9(sinc_taylor, a2, y2, y4, y8);
        f3 = u * (u * (u * estrin9(k_taylor, a2, y2, y4, y8)));
    } else {
        double a = sqrt(a2);
        if (a <= 3 * GA_PI / 4) { /* as ga_rotor_exp: r = pi/2 - a, sin a = cos r, cos a = r sinc r */
            double r = (PIO2_HI - a) + PIO2_LO, y = r * r, y2 = y * y, y4 = y2 * y2, y8 = y4 * y4;
            cs = r * estrin9(sinc_taylor, y, y2, y4, y8);
            sinc = estrin9(cos_taylor, y, y2, y4, y8) / a;
        } else {
            cs = cos(a);
            sinc = sin(a) / a;
        }
        f3 = u * ((cs - sinc) / phi2); /* u^3 k(a); phi2 > 0 here */
    }
    double f1 = u * sinc, f2 = u * f1, z = 0.0;
    for (int i = 0; i < 8; ++i) {
        out[i] = (cs * k01[i] + f1 * k01[8 + i]) + (f2 * k23[i] + f3 * k23[8 + i]);
        z += out[i] - out[i]; /* 0 for finite, NaN for Inf and NaN */
    }
    return z == 0.0 ? GA_OK : GA_ERR_DOMAIN;
}

ga_status ga_path_eval_segment(const ga_path *p, size_t seg, double u, void *out)
{
    if (!p || !out || seg >= nseg(p) || !isfinite(u))
        return GA_ERR_ARG;
    const ga_group *g = p->group;
    size_t d = g->dim, nf = nfac(p->scheme);
    int st;
    double x[MAXD], xd[MAXD];
    if (screw_rotors(p)) {
        double k01[16], k23[16], phi2;
        screw_prep(p, seg, k01, k23, &phi2);
        return screw_at(k01, k23, phi2, u, out);
    }
    if (is_decoupled(p->scheme))
        return dec_eval(p, seg, u, out, NULL, NULL);
    if (p->scheme == GA_SCHEME_C2) { /* A_i exp(x(tau)) */
        double e[MAXE];
        c2_curve(p, seg, u, x, NULL, NULL);
        if ((st = g->exp(x, e)))
            return st;
        g->compose(key_of(p, seg), e, out);
        return finite_elem(g, out);
    }
    if (nf == 0) { /* exp(X(t)) */
        gen_curve(p, seg, u, x, xd);
        return g->exp(x, out);
    }
    /* A_i exp(p_1(u) B) exp(p_2(u) C) exp(p_3(u) D) (Li-Hao eqs. 8, 14, 21;
     * BSPLINE: A_s and the d_j with the cumulative basis), the partial
     * products alternating between two buffers, the last one composed
     * straight into out */
    double acc[2][MAXE], e[MAXE];
    const double *left = key_of(p, seg), *X = seg_coef(p, seg);
    for (size_t j = 0; j < nf; ++j, X += d) {
        lin(d, x, poly_diff(fac_poly(p->scheme, j), 0, u, 0.0), X, 0.0, X);
        if ((st = g->exp(x, e)))
            return st;
        double *dst = j + 1 == nf ? out : acc[j & 1];
        g->compose(left, e, dst);
        left = dst;
    }
    /* a product of finite factors can still overflow: GA_ERR_DOMAIN, not Inf */
    return finite_elem(g, out);
}

/* DIRECT at (seg, u): at a key time the key itself, not its rounding (not
 * BSPLINE, whose knots are no keys; its one-key path is the key). */
static int eval_direct(const ga_path *p, size_t seg, double u, void *out)
{
    if ((u == 0.0 || u == 1.0) && (p->scheme != GA_SCHEME_BSPLINE || p->n == 1)) {
        copy_elem(p->group, out, key_of(p, seg + (u == 1.0)));
        return GA_OK;
    }
    return ga_path_eval_segment(p, seg, u, out);
}

ga_status ga_path_eval(const ga_path *p, double t, void *out)
{
    size_t seg;
    double u;
    if (!p || !out)
        return GA_ERR_ARG;
    int st = ga_path_locate(p, t, &seg, &u);
    return st ? st : eval_direct(p, seg, u, out);
}

/* Body velocity per unit u on segment seg. */
static int velocity_u(const ga_path *p, size_t seg, double u, double *v)
{
    const ga_group *g = p->group;
    size_t d = g->dim, nf = nfac(p->scheme);
    int st;
    double x[MAXD], xd[MAXD], w[MAXD];
    if (is_decoupled(p->scheme)) {
        if ((st = dec_eval(p, seg, u, NULL, w, NULL)))
            return st;
        lin(d, v, seg_len(p, seg), w, 0.0, w);
        return GA_OK;
    }
    if (nf == 0) { /* J_r(X) X' (group.h dexp), X' per unit t, times h */
        if (p->scheme == GA_SCHEME_C2)
            c2_curve(p, seg, u, x, xd, NULL);
        else
            gen_curve(p, seg, u, x, xd);
        g->dexp(x, xd, w);
        lin(d, v, seg_len(p, seg), w, 0.0, w);
        return GA_OK;
    }
    /* M = F_1 F_2 F_3, F_j = exp(p_j X_j): M^-1 M' = Ad_{F_3^-1}(Ad_{F_2^-1}(p_1' X_1)
     * + p_2' X_2) + p_3' X_3 (product rule; Li-Hao eqs. 15, 25, 34) */
    const double *X = seg_coef(p, seg);
    for (size_t j = 0; j < nf; ++j, X += d) {
        const double *cp = fac_poly(p->scheme, j);
        if (j > 0) {
            double fi[MAXE];
            lin(d, x, -poly_diff(cp, 0, u, 0.0), X, 0.0, X);
            if ((st = g->exp(x, fi)))
                return st;
            g->adjoint(fi, v, w);
        } else {
            for (size_t k = 0; k < d; ++k) w[k] = 0.0;
        }
        lin(d, v, 1.0, w, poly_deriv(cp, u), X);
    }
    return GA_OK;
}

ga_status ga_path_velocity_segment(const ga_path *p, size_t seg, double u, double *v)
{
    if (!p || !v || seg >= nseg(p) || !isfinite(u))
        return GA_ERR_ARG;
    size_t d = p->group->dim;
    double w[MAXD];
    int st = velocity_u(p, seg, u, w);
    if (st != GA_OK)
        return st;
    lin(d, w, 1.0 / seg_len(p, seg), w, 0.0, w);
    if (!allfinite(w, d))
        return GA_ERR_DOMAIN; /* see finite_elem */
    memcpy(v, w, d * sizeof(double));
    return GA_OK;
}

ga_status ga_path_velocity(const ga_path *p, double t, double *v)
{
    size_t seg;
    double u;
    if (!p || !v)
        return GA_ERR_ARG;
    int st = ga_path_locate(p, t, &seg, &u);
    if (st == GA_OK && p->n == 1) {
        memset(v, 0, p->group->dim * sizeof(double));
        return GA_OK;
    }
    return st ? st : ga_path_velocity_segment(p, seg, u, v);
}

/* ---- the growth rule (path.h) ------------------------------------------------------- */

/* The Euclidean norms of the parts of x: rotation and translation on the
 * rigid groups, the whole element on affine; returns the number of parts. */
static size_t part_norms(const ga_group *g, const double *x, double *nrm)
{
    size_t parts = g->rigid ? 2 : 1, w = g->dim / parts;
    for (size_t q = 0; q < parts; ++q) {
        double s = 0.0;
        for (size_t k = 0; k < w; ++k) s = hypot(s, x[q * w + k]);
        nrm[q] = s;
    }
    return parts;
}

ga_status ga_path_measure_growth(const ga_path *p, ga_path_growth *out)
{
    if (!p || !out)
        return GA_ERR_ARG;
    const ga_group *g = p->group;
    size_t n = p->n, parts = 1;
    ga_path_growth r = {0.0, 0, n};
    double chord[2] = {0.0, 0.0}, x[MAXD], rel[MAXE], nrm[2];
    int st;
    for (size_t j = 0; j + 1 < n; ++j) {
        if ((st = rel_log(g, key_of(p, j), key_of(p, j + 1), x, rel)))
            return st;
        parts = part_norms(g, x, nrm);
        for (size_t q = 0; q < parts; ++q) chord[q] = fmax(chord[q], nrm[q] / seg_len(p, j));
    }
    for (size_t i = 0; n > 1 && i < n; ++i) {
        if ((st = ga_path_velocity_segment(p, i + 1 < n ? i : n - 2, i + 1 < n ? 0.0 : 1.0, x)))
            return st;
        part_norms(g, x, nrm);
        double ratio = 0.0;
        for (size_t q = 0; q < parts; ++q)
            if (chord[q] > 0.0)
                ratio = fmax(ratio, nrm[q] / chord[q]);
        if (ratio > r.ratio) {
            r.ratio = ratio;
            r.key = i;
        }
        if (r.first == n && ratio > GA_PATH_GROWTH_MAX)
            r.first = i;
    }
    *out = r;
    return GA_OK;
}

/* ---- acceleration ------------------------------------------------------------------ */

/* x = vee(a) for a matrix a in the algebra up to rounding. vee is linear, but
 * the rigid groups' vee refuses a 3x3 block whose symmetric part exceeds 1e-9
 * of its largest entry, and a result that is small against the terms it was
 * formed from (a commutator of near-parallel twists, a body acceleration
 * near 0) carries a symmetric part of rounding about eps times those terms.
 * So vee is taken of a + hat(c), c = (S, ..., S) with S >= the terms'
 * scale, and c is subtracted again: exact up to a rounding of S. The last
 * row, zero in the algebra of every group here (homogeneous matrices), is
 * set to zero. */
static int vee_scaled(const ga_group *g, ga_mat4 a, double scale, double *x)
{
    double c[MAXD];
    size_t d = g->dim;
    for (size_t k = 0; k < d; ++k) c[k] = scale;
    ga_mat4 h = g->hat(c);
    for (int k = 0; k < 12; ++k) a.m[k] += h.m[k];
    for (int k = 12; k < 16; ++k) a.m[k] = 0.0;
    int st = g->vee(a, x);
    if (st != GA_OK)
        return GA_ERR_DOMAIN;
    for (size_t k = 0; k < d; ++k) x[k] -= scale;
    return GA_OK;
}

static double mat_maxabs(ga_mat4 a)
{
    double m = 0.0;
    for (int k = 0; k < 16; ++k) m = fmax(m, fabs(a.m[k]));
    return m;
}

/* out = [x, y] = vee(x^ y^ - y^ x^), the Lie bracket in the convention of
 * hat (body velocities: d/du Ad_{F^-1} w = Ad_{F^-1} w' + [Ad_{F^-1} w, p'X]
 * for F = exp(p X)). */
static int bracket(const ga_group *g, const double *x, const double *y, double *out)
{
    ga_mat4 a = g->hat(x), b = g->hat(y), ab = ga_mat4_mul(a, b), ba = ga_mat4_mul(b, a), c;
    for (int k = 0; k < 16; ++k) c.m[k] = ab.m[k] - ba.m[k];
    double s = 1.0 + mat_maxabs(ab) + mat_maxabs(ba);
    return vee_scaled(g, c, s, out);
}

/* The 4x4 jets a0 + e a1 + e^2 a2 (e^3 = 0): exp of a jet by scaling, Taylor
 * series and squaring (Higham 2005, as the affine dexp of group.c does to
 * first order). exp(X + e X' + e^2 X''/2) = G + e G' + e^2 G''/2 along a
 * curve X(t) at t. */
typedef struct {
    ga_mat4 c[3];
} jet;

static jet jet_mul(const jet *a, const jet *b)
{
    jet r;
    r.c[0] = ga_mat4_mul(a->c[0], b->c[0]);
    ga_mat4 p = ga_mat4_mul(a->c[0], b->c[1]), q = ga_mat4_mul(a->c[1], b->c[0]);
    for (int k = 0; k < 16; ++k) r.c[1].m[k] = p.m[k] + q.m[k];
    ga_mat4 u = ga_mat4_mul(a->c[0], b->c[2]), v = ga_mat4_mul(a->c[1], b->c[1]),
            w = ga_mat4_mul(a->c[2], b->c[0]);
    for (int k = 0; k < 16; ++k) r.c[2].m[k] = u.m[k] + v.m[k] + w.m[k];
    return r;
}

static jet jet_exp(jet z)
{
    /* scale by 2^-s so that ||z_0||_1 <= 1/2: nrm = f 2^e, f in [1/2, 1),
     * s = e + 1. An infinite or NaN norm (finite input that overflowed) is not
     * scaled: the result is then not finite, which the caller reports
     * (found by fuzz/fuzz_path under UBSan: (int) of an infinite log2;
     * fuzz/regress/path/jet-exp-infinite-norm) */
    double nrm = ga_mat4_norm1(z.c[0]);
    int s = 0;
    if (nrm > 0.5 && isfinite(nrm)) {
        frexp(nrm, &s);
        s += 1;
    }
    double sc = ldexp(1.0, -s);
    for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 16; ++k) z.c[i].m[k] *= sc;
    /* Horner: I + z (I + z/2 (I + z/3 (...))), 18 terms: 0.5^19/19! < 1e-22 */
    jet r;
    memset(&r, 0, sizeof r);
    r.c[0] = ga_mat4_identity();
    for (int m = 18; m >= 1; --m) {
        jet t = jet_mul(&z, &r);
        for (int i = 0; i < 3; ++i)
            for (int k = 0; k < 16; ++k) t.c[i].m[k] /= m;
        for (int k = 0; k < 16; ++k) t.c[0].m[k] += (k % 5 == 0);
        r = t;
    }
    for (int i = 0; i < s; ++i) r = jet_mul(&r, &r);
    return r;
}

/* X''(t) (per unit t^2) of the generator-space schemes on segment j at u:
 * 0 for BIVECTOR; the slope of X' on its piece for SMOOTH/QUADRATIC (the
 * piece gen_curve uses). */
static void gen_curve2(const ga_path *p, size_t j, double u, double *xdd)
{
    size_t d = p->group->dim, n = p->n;
    if (p->scheme == GA_SCHEME_BIVECTOR) {
        for (size_t i = 0; i < d; ++i) xdd[i] = 0.0;
        return;
    }
    int left = u <= 0.5;
    size_t k = j == 0 ? 0 : j == n - 2 ? n - 3 : left ? j - 1 : j;
    double L = brk(p, k + 1) - brk(p, k);
    const double *dk = p->slope + k * d, *dk1 = dk + d;
    for (size_t i = 0; i < d; ++i) xdd[i] = (dk1[i] - dk[i]) / L;
}

/* The body velocity v (may be NULL) and acceleration a of G = exp(X(t)) with
 * X = x, X' = xd, X'' = xdd (per unit t): v = J_r(X) X' (group.h dexp); the
 * jet exp(X + e X' + e^2 X''/2) gives G' and G''/2, and
 * a = d/dt(G^-1 G') = G^-1 G'' - (G^-1 G')^2. With X'' = 0, a is the term
 * N(X, X') = (d/dt J_r(X)) X' of the C2 system (c2_solve). */
static int exp_curve_deriv(const ga_group *g, const double *x, const double *xd, const double *xdd, double *v,
                           double *a)
{
    size_t d = g->dim;
    double half[MAXD], gi[MAXE], ge[MAXE];
    int st;
    for (size_t k = 0; k < d; ++k) half[k] = 0.5 * xdd[k];
    jet z = {{g->hat(x), g->hat(xd), g->hat(half)}};
    jet e = jet_exp(z);
    if ((st = g->exp(x, ge)) || (st = g->inverse(ge, gi)))
        return st;
    ga_mat4 G1 = g->to_mat4(gi), V = ga_mat4_mul(G1, e.c[1]), P = ga_mat4_mul(G1, e.c[2]),
            V2 = ga_mat4_mul(V, V), A;
    for (int k = 0; k < 16; ++k) A.m[k] = 2.0 * P.m[k] - V2.m[k];
    if (v)
        g->dexp(x, xd, v); /* the velocity as ga_path_velocity has it */
    return vee_scaled(g, A, 1.0 + 2.0 * mat_maxabs(P) + mat_maxabs(V2), a);
}

/* Body velocity and acceleration per unit u (u^2) on segment seg. */
static int accel_u(const ga_path *p, size_t seg, double u, double *v, double *a)
{
    const ga_group *g = p->group;
    size_t d = g->dim, nf = nfac(p->scheme);
    double h = seg_len(p, seg);
    int st;
    if (is_decoupled(p->scheme)) {
        if ((st = dec_eval(p, seg, u, NULL, v, a)))
            return st;
        lin(d, v, h, v, 0.0, v);
        lin(d, a, h * h, a, 0.0, a);
        return GA_OK;
    }
    if (nf == 0) {
        double x[MAXD], xd[MAXD], xdd[MAXD] = {0};
        if (p->scheme == GA_SCHEME_C2) {
            c2_curve(p, seg, u, x, xd, xdd);
        } else {
            gen_curve(p, seg, u, x, xd);
            gen_curve2(p, seg, u, xdd);
        }
        if ((st = exp_curve_deriv(g, x, xd, xdd, v, a)))
            return st;
        lin(d, v, h, v, 0.0, v);
        lin(d, a, h * h, a, 0.0, a);
        return GA_OK;
    }
    /* M = F_1 F_2 F_3, F_j = exp(p_j X_j): with w_1 = p_1' X_1, a_1 = p_1'' X_1,
     * w_{j+1} = Ad_{F^-1} w_j + p' X, a_{j+1} = Ad_{F^-1} a_j + [Ad_{F^-1} w_j, p' X]
     * + p'' X (F = F_{j+1}, X = X_{j+1}): the product rule of velocity_u
     * differentiated once more, the recursion of Sommer et al. 2020 (eqs. for
     * the cumulative B-spline's acceleration) */
    const double *X = seg_coef(p, seg);
    double w[MAXD], b[MAXD], c[MAXD], x[MAXD], fi[MAXE];
    for (size_t k = 0; k < d; ++k) v[k] = a[k] = 0.0;
    for (size_t j = 0; j < nf; ++j, X += d) {
        const double *cp = fac_poly(p->scheme, j);
        double d1 = poly_deriv(cp, u), d2 = poly_deriv2(cp, u);
        if (j > 0) {
            lin(d, x, -poly_diff(cp, 0, u, 0.0), X, 0.0, X);
            if ((st = g->exp(x, fi)))
                return st;
            g->adjoint(fi, v, w);
            g->adjoint(fi, a, b);
            lin(d, x, d1, X, 0.0, X);
            if ((st = bracket(g, w, x, c)))
                return st;
            lin(d, a, 1.0, b, 1.0, c);
            memcpy(v, w, d * sizeof(double));
        }
        lin(d, v, 1.0, v, d1, X);
        lin(d, a, 1.0, a, d2, X);
    }
    return GA_OK;
}

ga_status ga_path_acceleration_segment(const ga_path *p, size_t seg, double u, double *a)
{
    if (!p || !a || seg >= nseg(p) || !isfinite(u))
        return GA_ERR_ARG;
    size_t d = p->group->dim;
    double v[MAXD], w[MAXD], h = seg_len(p, seg);
    int st = accel_u(p, seg, u, v, w);
    if (st != GA_OK)
        return st;
    lin(d, w, 1.0 / (h * h), w, 0.0, w);
    if (!allfinite(w, d))
        return GA_ERR_DOMAIN;
    memcpy(a, w, d * sizeof(double));
    return GA_OK;
}

ga_status ga_path_acceleration(const ga_path *p, double t, double *a)
{
    return ga_path_differentiate(p, t, GA_FRAME_BODY, NULL, a);
}

ga_status ga_path_differentiate_segment(const ga_path *p, size_t seg, double u, ga_frame f, double *v,
                                        double *a)
{
    if (!p || seg >= nseg(p) || !isfinite(u) || (unsigned)f > GA_FRAME_SPATIAL)
        return GA_ERR_ARG;
    const ga_group *g = p->group;
    size_t d = g->dim;
    double vb[MAXD], ab[MAXD], h = seg_len(p, seg), m[MAXE];
    int st = accel_u(p, seg, u, vb, ab);
    if (st != GA_OK)
        return st;
    lin(d, vb, 1.0 / h, vb, 0.0, vb);
    lin(d, ab, 1.0 / (h * h), ab, 0.0, ab);
    if (f == GA_FRAME_SPATIAL) {
        /* spatial velocity Ad_M v_b; its derivative Ad_M (a_b + [v_b, v_b]) = Ad_M a_b */
        double vs[MAXD], as[MAXD];
        if ((st = ga_path_eval_segment(p, seg, u, m)))
            return st;
        g->adjoint(m, vb, vs);
        g->adjoint(m, ab, as);
        memcpy(vb, vs, sizeof vs);
        memcpy(ab, as, sizeof as);
    }
    if (!allfinite(vb, d) || !allfinite(ab, d))
        return GA_ERR_DOMAIN;
    if (v)
        memcpy(v, vb, d * sizeof(double));
    if (a)
        memcpy(a, ab, d * sizeof(double));
    return GA_OK;
}

ga_status ga_path_differentiate(const ga_path *p, double t, ga_frame f, double *v, double *a)
{
    size_t seg;
    double u;
    if (!p || (unsigned)f > GA_FRAME_SPATIAL)
        return GA_ERR_ARG;
    int st = ga_path_locate(p, t, &seg, &u);
    if (st != GA_OK)
        return st;
    if (p->n == 1) {
        if (v)
            memset(v, 0, p->group->dim * sizeof(double));
        if (a)
            memset(a, 0, p->group->dim * sizeof(double));
        return GA_OK;
    }
    return ga_path_differentiate_segment(p, seg, u, f, v, a);
}

/* ---- Euler (Li-Hao §5, group form) ---------------------------------------------- */

/* Smallest Euler step accepted: at most 1e9 steps per segment. */
#define EULER_MIN_STEP 1e-9

/* One Euler sample at (seg, u): continue the running state (*cur, *grid, A)
 * when it is on this segment at or below u, else restart at the key. */
static int euler_sample(const ga_path *p, double h, size_t *cur, size_t *grid, double *A, size_t seg,
                        double u, void *out)
{
    const ga_group *g = p->group;
    size_t d = g->dim;
    int st;
    double v[MAXD], e[MAXE], tmp[MAXE];
    if (p->n == 1) { /* the constant path: its key, on every scheme */
        copy_elem(g, out, key_of(p, 0));
        return GA_OK;
    }
    if (*cur != seg || (double)*grid * h > u) {
        if (p->scheme == GA_SCHEME_BSPLINE) { /* the knot's pose, no key */
            if ((st = ga_path_eval_segment(p, seg, 0.0, A)))
                return st;
        } else
            copy_elem(g, A, key_of(p, seg));
        *grid = 0;
        *cur = seg;
    }
    /* eq. 32 in group form: A(u + h) = A(u) exp(h V(u)) */
    while ((double)(*grid + 1) * h <= u) {
        if ((st = velocity_u(p, seg, (double)*grid * h, v)))
            return st;
        lin(d, v, h, v, 0.0, v);
        if ((st = g->exp(v, e)))
            return st;
        g->compose(A, e, tmp);
        copy_elem(g, A, tmp);
        ++*grid;
    }
    double r = u - (double)*grid * h;
    if (r > 0.0) {
        if ((st = velocity_u(p, seg, (double)*grid * h, v)))
            return st;
        lin(d, v, r, v, 0.0, v);
        if ((st = g->exp(v, e)))
            return st;
        g->compose(A, e, out);
    } else {
        copy_elem(g, out, A);
    }
    return finite_elem(g, out); /* a product of many steps can overflow */
}

/* ---- exact incremental stepping --------------------------------------------------- */

/* Slots of factor j start at j(j+3)/2: G_0 = exp(p(u) X), G_m = exp(D^m p(u) X)
 * for 0 < m < deg, then E = exp(D^deg p X), constant on a segment. Degrees 1,
 * 2, 3 use 2, 3, 4 slots. The key is folded into the first factor's G_0
 * (A_i exp(u B)), so SCREW costs one product per sample. */
static size_t slot_base(ga_scheme s, size_t j)
{
    size_t b = 0;
    for (size_t i = 0; i < j; ++i) b += fac_deg(s, i) + 1;
    return b; /* Li-Hao: j (j + 3)/2; BSPLINE: 4 j */
}

static int exact_anchor(ga_path_stepper *s, size_t seg, double u)
{
    const ga_path *p = s->path;
    const ga_group *g = p->group;
    size_t d = g->dim, nf = nfac(p->scheme);
    int st, newseg = seg != s->seg;
    double delta = s->dt / seg_len(p, seg), x[MAXD], e[MAXE];
    const double *X = seg_coef(p, seg);
    for (size_t j = 0; j < nf; ++j, X += d)
        for (size_t m = 0, deg = fac_deg(p->scheme, j); m <= deg; ++m) {
            if (m == deg && !newseg)
                break; /* E is kept for the segment */
            lin(d, x, poly_diff(fac_poly(p->scheme, j), m, u, delta), X, 0.0, X);
            if ((st = g->exp(x, m == 0 && j == 0 ? e : s->slot[slot_base(p->scheme, j) + m])))
                return st;
            if (m == 0 && j == 0)
                g->compose(key_of(p, seg), e, s->slot[0]);
        }
    return GA_OK;
}

/* G_m <- G_m G_{m+1}, m = 0 .. deg-1, in that order (each uses the old G_{m+1}):
 * exp(D^m p(u+d) X) = exp(D^m p(u) X) exp(D^{m+1} p(u) X). */
static void exact_advance(ga_path_stepper *s)
{
    const ga_group *g = s->path->group;
    size_t nf = nfac(s->path->scheme);
    double tmp[MAXE];
    for (size_t j = 0; j < nf; ++j)
        for (size_t m = 0, b = slot_base(s->path->scheme, j); m < fac_deg(s->path->scheme, j); ++m) {
            double *a = s->slot[b + m];
            g->compose(a, s->slot[b + m + 1], tmp);
            copy_elem(g, a, tmp);
        }
}

/* A_i F_1 F_2 F_3 with A_i F_1 in slot 0. */
static void exact_output(const ga_path_stepper *s, void *out)
{
    const ga_group *g = s->path->group;
    size_t nf = nfac(s->path->scheme);
    double acc[MAXE], tmp[MAXE];
    if (nf == 1) {
        copy_elem(g, out, s->slot[0]);
        return;
    }
    g->compose(s->slot[0], s->slot[slot_base(s->path->scheme, 1)], acc);
    if (nf == 3) {
        g->compose(acc, s->slot[slot_base(s->path->scheme, 2)], tmp);
        copy_elem(g, acc, tmp);
    }
    copy_elem(g, out, acc);
}

/* ---- samplers --------------------------------------------------------------------- */

ga_status ga_path_stepper_init(const ga_path *p, ga_eval ev, double step, size_t n, double t0, double t1,
                               ga_path_stepper *s)
{
    if (!s || !p || n < 1 || (unsigned)ev > GA_EVAL_EXACT)
        return GA_ERR_ARG;
    if (!isfinite(t0) || !isfinite(t1))
        return GA_ERR_NOTFINITE;
    if (!(t0 >= knot(p, 0) && t1 <= knot(p, nseg(p)) && t0 <= t1))
        return GA_ERR_ARG;
    if (ev == GA_EVAL_EULER && !(step >= EULER_MIN_STEP && step <= 1.0))
        return GA_ERR_ARG;
    s->path = p;
    s->eval = ev;
    s->step = step;
    s->n = n;
    s->k = 0;
    s->t0 = t0;
    s->t1 = t1;
    s->dt = n > 1 ? (t1 - t0) / (double)(n - 1) : 0.0;
    s->seg = SIZE_MAX;
    s->since = 0;
    s->grid = 0;
    return GA_OK;
}

/* DIRECT and EXACT samples of SCREW on rotors (screw_rotors), without the
 * group's function pointers: slot 0 is the running sample A_i exp(u B) and
 * slot 1 exp(dt/h B) (EXACT), slots 2 to 4 screw_prep's rotors of segment
 * s->seg, which are prepared whenever s->seg changes. */
static int screw_next(ga_path_stepper *s, size_t seg, double u, void *out)
{
    const ga_path *p = s->path;
    int st = GA_OK, newseg = seg != s->seg;
    if (newseg)
        screw_prep(p, seg, s->slot[2], s->slot[3], &s->slot[4][0]);
    s->seg = seg;
    if (s->eval == GA_EVAL_DIRECT) { /* as eval_direct: the key itself at a key time */
        if (u == 0.0 || u == 1.0) {
            memcpy(out, key_of(p, seg + (u == 1.0)), sizeof(ga_rotor));
            return GA_OK;
        }
        return screw_at(s->slot[2], s->slot[3], s->slot[4][0], u, out);
    }
    if (newseg || s->since >= GA_PATH_EXACT_REANCHOR) { /* as exact_anchor */
        st = screw_at(s->slot[2], s->slot[3], s->slot[4][0], u, s->slot[0]);
        if (st == GA_OK && newseg) {
            double x[6], delta = s->dt / seg_len(p, seg);
            lin(6, x, poly_diff(fac_poly(p->scheme, 0), 1, u, delta), seg_coef(p, seg), 0.0,
                seg_coef(p, seg));
            st = ga_group_cga.exp(x, s->slot[1]);
        }
        s->since = 0;
    } else { /* as exact_advance: G_0 <- G_0 exp(dt/h B) */
        ga_rotor a, e;
        memcpy(&a, s->slot[0], sizeof a);
        memcpy(&e, s->slot[1], sizeof e);
        a = ga_rotor_mul_inline(a, e);
        memcpy(s->slot[0], &a, sizeof a);
    }
    ++s->since;
    if (st == GA_OK) {
        memcpy(out, s->slot[0], sizeof(ga_rotor));
        double z = 0.0; /* as finite_elem */
        for (int i = 0; i < 8; ++i) z += s->slot[0][i] - s->slot[0][i];
        st = z == 0.0 ? GA_OK : GA_ERR_DOMAIN;
    }
    return st;
}

ga_status ga_path_stepper_next(ga_path_stepper *s, void *out)
{
    if (!s || !out || s->k >= s->n)
        return GA_ERR_ARG;
    const ga_path *p = s->path;
    double t = s->k + 1 == s->n ? s->t1 : s->t0 + (double)s->k * s->dt, u;
    size_t seg = s->seg;
    int st;
    if (seg != SIZE_MAX && knot(p, seg) <= t &&
        (t < knot(p, seg + 1) || (seg + 1 == nseg(p) && t == knot(p, seg + 1)))) {
        /* the running segment again (t is inside [t_0, t_{n-1}] by the init):
           what ga_path_locate would find, without its search */
        u = (t - knot(p, seg)) / seg_len(p, seg);
    } else if ((st = ga_path_locate(p, t, &seg, &u))) {
        return st;
    }
    if (s->eval == GA_EVAL_EULER) {
        st = euler_sample(p, s->step, &s->seg, &s->grid, s->slot[0], seg, u, out);
    } else if (screw_rotors(p)) {
        st = screw_next(s, seg, u, out);
    } else if (s->eval == GA_EVAL_DIRECT || nfac(p->scheme) == 0 || p->n == 1) {
        st = eval_direct(p, seg, u, out);
        s->seg = seg; /* DIRECT keeps no state: seg is only where to look first */
    } else {
        if (seg != s->seg || s->since >= GA_PATH_EXACT_REANCHOR) {
            st = exact_anchor(s, seg, u);
            s->seg = seg;
            s->since = 0;
        } else {
            exact_advance(s);
        }
        ++s->since;
        if (st == GA_OK) {
            exact_output(s, out);
            st = finite_elem(p->group, out);
        }
    }
    /* DIRECT and EULER checked their own results (finite_elem) */
    if (st == GA_OK)
        ++s->k;
    return st;
}

ga_status ga_path_sample_uniform(const ga_path *p, ga_eval ev, double step, size_t n, double t0, double t1,
                                 void *out)
{
    ga_path_stepper s;
    int st = ga_path_stepper_init(p, ev, step, n, t0, t1, &s);
    if (!out && st == GA_OK)
        st = GA_ERR_ARG;
    for (size_t k = 0; st == GA_OK && k < n; ++k)
        st = ga_path_stepper_next(&s, (unsigned char *)out + k * p->group->elem_size);
    return st;
}

ga_status ga_path_sample(const ga_path *p, ga_eval ev, double step, size_t n, const double *times, void *out)
{
    if (!p || !times || !out || (unsigned)ev > GA_EVAL_EXACT)
        return GA_ERR_ARG;
    if (ev == GA_EVAL_EULER && !(step >= EULER_MIN_STEP && step <= 1.0))
        return GA_ERR_ARG;
    size_t cur = SIZE_MAX, grid = 0;
    double A[MAXE];
    for (size_t k = 0; k < n; ++k) {
        void *o = (unsigned char *)out + k * p->group->elem_size;
        size_t seg;
        double u;
        int st = ga_path_locate(p, times[k], &seg, &u);
        if (st == GA_OK)
            st = ev == GA_EVAL_EULER ? euler_sample(p, step, &cur, &grid, A, seg, u, o)
                                     : eval_direct(p, seg, u, o); /* both checked */
        if (st)
            return st;
    }
    return GA_OK;
}
