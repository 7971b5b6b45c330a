/* garotor/path.c: the schemes and evaluators of path.h, written once against
 * the group interface (group.h). See path.h for the mathematics and the
 * paper equations; each function below cites the ones it implements.
 */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include <garotor/mat4.h>
#include <garotor/path.h>
#define MAXD GA_GROUP_MAX_DIM
#define MAXE GA_GROUP_MAX_ELEM

/* ---- names ---------------------------------------------------------------- */

static const char *const scheme_names[] = {"screw", "bivector", "quadratic", "smooth", "lihao2", "lihao3"};
static const char *const eval_names[] = {"direct", "euler", "exact"};

const char *ga_scheme_name(ga_scheme s) { return (unsigned)s < 6 ? scheme_names[s] : "?"; }

int ga_scheme_by_name(const char *name, ga_scheme *out)
{
    for (unsigned i = 0; name && i < 6; ++i)
        if (strcmp(name, scheme_names[i]) == 0) {
            *out = (ga_scheme)i;
            return GA_OK;
        }
    return GA_ERR_ARG;
}

const char *ga_eval_name(ga_eval e) { return (unsigned)e < 3 ? eval_names[e] : "?"; }

int ga_eval_by_name(const char *name, ga_eval *out)
{
    for (unsigned i = 0; name && i < 3; ++i)
        if (strcmp(name, eval_names[i]) == 0) {
            *out = (ga_eval)i;
            return GA_OK;
        }
    return GA_ERR_ARG;
}

size_t ga_scheme_min_keys(ga_scheme s) { return (s == GA_SCHEME_QUADRATIC || s == GA_SCHEME_SMOOTH) ? 3 : 2; }

/* ---- small helpers ---------------------------------------------------------- */

/* The exponent polynomials p_j(u) = a u + b u^2 + c u^3 of the Li-Hao factors
 * exp(p_j(u) X_j): u (eq. 9), u^2 (eq. 14), u^3 - u^2 (eq. 21). Factor j has
 * degree j + 1. */
static const double fac_poly[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, -1, 1}};

static size_t nfac(ga_scheme s)
{
    return s == GA_SCHEME_SCREW ? 1 : s == GA_SCHEME_LIHAO2 ? 2 : s == GA_SCHEME_LIHAO3 ? 3 : 0;
}

/* The order-m forward difference of p with step d at u (m = 0: p(u) itself),
 * expanded so that no difference of nearby values is formed. */
static double poly_diff(const double *c, size_t m, double u, double d)
{
    switch (m) {
    case 0: return u * (c[0] + u * (c[1] + u * c[2]));
    case 1: return c[0] * d + c[1] * d * (2 * u + d) + c[2] * d * (3 * u * u + 3 * u * d + d * d);
    case 2: return c[1] * 2 * d * d + c[2] * 6 * d * d * (u + d);
    default: return c[2] * 6 * d * d * d;
    }
}

static double poly_deriv(const double *c, double u) { return c[0] + u * (2 * c[1] + 3 * u * c[2]); }

static double *key_of(const ga_path *p, size_t i) { return p->key + i * p->key_stride; }
static double seg_len(const ga_path *p, size_t i) { return p->t[i + 1] - p->t[i]; }

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

/* ---- workspace ---------------------------------------------------------------- */

static size_t scheme_doubles(ga_scheme s, size_t N, size_t D)
{
    size_t S = N - 1;
    switch (s) {
    case GA_SCHEME_SCREW: return S * D;
    case GA_SCHEME_LIHAO2: return 2 * S * D + N * D;
    case GA_SCHEME_LIHAO3: return 3 * S * D + N * D;
    case GA_SCHEME_BIVECTOR: return N * D;
    case GA_SCHEME_QUADRATIC:
    case GA_SCHEME_SMOOTH: return N * D + S * D + S;
    }
    return 0;
}

size_t ga_path_workspace_size(const ga_group *g, ga_scheme s, size_t n)
{
    if (!g || n < 1 || (unsigned)s > GA_SCHEME_LIHAO3)
        return 0;
    size_t stride = (g->elem_size + sizeof(double) - 1) / sizeof(double);
    return sizeof(double) * (n + n * stride + scheme_doubles(s, n, g->dim));
}

/* Check the arguments and lay the arrays out in the workspace. */
static int layout(ga_path *p, const ga_group *g, ga_scheme s, size_t n, const double *times, const void *keys,
                  void *work, size_t bytes)
{
    if (!p || !g || !times || !keys || !work || (unsigned)s > GA_SCHEME_LIHAO3)
        return GA_ERR_ARG;
    if (n != 1 && (n < ga_scheme_min_keys(s) || (s == GA_SCHEME_QUADRATIC && n != 3)))
        return GA_ERR_ARG; /* one key: the constant path, on every scheme */
    if (bytes < ga_path_workspace_size(g, s, n) || (uintptr_t)work % _Alignof(double))
        return GA_ERR_ARG;
    if (!allfinite(times, n))
        return GA_ERR_NOTFINITE;
    for (size_t i = 0; i + 1 < n; ++i)
        if (!(times[i] < times[i + 1]))
            return GA_ERR_ARG;
    size_t d = g->dim;
    double *w = work;
    memset(p, 0, sizeof *p);
    p->group = g;
    p->scheme = s;
    p->n = n;
    p->key_stride = (g->elem_size + sizeof(double) - 1) / sizeof(double);
    p->t = w;
    w += n;
    p->key = w;
    w += n * p->key_stride;
    memcpy(p->t, times, n * sizeof(double));
    switch (s) {
    case GA_SCHEME_SCREW: p->coef = w; break;
    case GA_SCHEME_LIHAO2:
        p->coef = w;
        p->vel = w + 2 * (n - 1) * d;
        break;
    case GA_SCHEME_LIHAO3:
        p->coef = w;
        p->vel = w + 3 * (n - 1) * d;
        break;
    case GA_SCHEME_BIVECTOR: p->gen = w; break;
    case GA_SCHEME_QUADRATIC:
    case GA_SCHEME_SMOOTH:
        p->gen = w;
        p->slope = w + n * d;
        break;
    }
    return GA_OK;
}

/* ---- building the schemes ------------------------------------------------------ */

/* SCREW (Li-Hao eq. 10), LIHAO2 (eqs. 14-17), LIHAO3 (eqs. 21-28), all in u
 * units on each segment: B_i = h_i V_i where V_i is a velocity per unit t. */
static int build_lihao(ga_path *p, const double *vel)
{
    const ga_group *g = p->group;
    size_t n = p->n, d = g->dim, nf = nfac(p->scheme);
    double rel[MAXE], reli[MAXE], e[MAXE], m[MAXE], x[MAXD], ad[MAXD];
    int st;
    if (p->scheme == GA_SCHEME_SCREW) {
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
    for (size_t i = 0; i + 1 < n; ++i) {
        double h = seg_len(p, i);
        double *B = p->coef + i * nf * d, *C = B + d, *D = C + d;
        const double *vi = p->vel + i * d;
        /* eq. 26: B_i = velocity at the key, per unit u */
        lin(d, B, h, vi, 0.0, vi);
        if (!allfinite(B, d))
            return GA_ERR_DOMAIN;
        /* eq. 16 (and 27 corrected): exp(B_i) exp(C_i) = A_i^-1 A_{i+1} */
        double ai[MAXE];
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
        if (p->scheme == GA_SCHEME_LIHAO2) {
            /* eq. 17, per unit t: the next key's velocity */
            double *vn = p->vel + (i + 1) * d;
            lin(d, vn, 1.0 / h, ad, 2.0 / h, C);
        } else {
            /* eq. 28: D_i = h V_{i+1} - Ad_{rel^-1} B_i - 2 C_i */
            const double *vn = p->vel + (i + 1) * d;
            for (size_t k = 0; k < d; ++k) D[k] = h * vn[k] - ad[k] - 2.0 * C[k];
        }
    }
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
            di -= lo * cp[j - 1];
            for (size_t k = 0; k < d; ++k) r[k] -= lo * r[k - d];
        }
        cp[j] = up / di;
        for (size_t k = 0; k < d; ++k) r[k] /= di;
    }
    for (size_t j = m - 1; j-- > 0;) {
        double *r = p->slope + j * d;
        for (size_t k = 0; k < d; ++k) r[k] -= cp[j] * r[k + d];
    }
}

static int build_scheme(ga_path *p, const double *vel)
{
    switch (p->scheme) {
    case GA_SCHEME_SCREW:
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
    if (p->n == 1) { /* the constant path: no segment, nothing to build */
        memset(p->key + p->key_stride, 0, scheme_doubles(p->scheme, 1, g->dim) * sizeof(double));
        return GA_OK;
    }
    int st = build_scheme(p, vel);
    if (st == GA_ERR_NOTFINITE)
        return GA_ERR_DOMAIN;
    if (st != GA_OK)
        return st;
    const double *c = p->key + p->n * p->key_stride;
    return allfinite(c, scheme_doubles(p->scheme, p->n, p->group->dim)) ? GA_OK : GA_ERR_DOMAIN;
}

/* Both build into a local path and hand it out only on success: on an error
 * *out is untouched (the workspace is not). */
int ga_path_init(const ga_group *g, ga_scheme s, size_t n, const double *times, const void *keys,
                 const double *velocities, void *work, size_t work_bytes, ga_path *out)
{
    ga_path p;
    if (!out)
        return GA_ERR_ARG;
    int st = layout(&p, g, s, n, times, keys, work, work_bytes);
    if (st != GA_OK)
        return st;
    for (size_t i = 0; i < n; ++i)
        copy_elem(g, key_of(&p, i), (const unsigned char *)keys + i * g->elem_size);
    if ((st = build(&p, velocities)) == GA_OK)
        *out = p;
    return st;
}

int ga_path_init_mat4(const ga_group *g, ga_scheme s, size_t n, const double *times, const ga_mat4 *keys,
                      const double *velocities, void *work, size_t work_bytes, ga_path *out)
{
    ga_path p;
    if (!out)
        return GA_ERR_ARG;
    int st = layout(&p, g, s, n, times, keys, work, work_bytes);
    if (st != GA_OK)
        return st;
    for (size_t i = 0; i < n; ++i)
        if ((st = g->from_mat4(keys[i], key_of(&p, i))))
            return st;
    if ((st = build(&p, velocities)) == GA_OK)
        *out = p;
    return st;
}

/* ---- evaluation ---------------------------------------------------------------- */

int ga_path_locate(const ga_path *p, double t, size_t *seg, double *u)
{
    size_t n = p->n;
    if (!(t >= p->t[0] && t <= p->t[n - 1]))
        return GA_ERR_ARG; /* also NaN */
    if (n == 1) {          /* the constant path: its key, "segment 0" at u = 0 */
        *seg = 0;
        *u = 0.0;
        return GA_OK;
    }
    size_t lo = 0, hi = n - 2; /* largest i <= n-2 with t_i <= t */
    while (lo < hi) {
        size_t mid = (lo + hi + 1) / 2;
        if (p->t[mid] <= t)
            lo = mid;
        else
            hi = mid - 1;
    }
    *seg = lo;
    *u = (t - p->t[lo]) / seg_len(p, lo);
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

int ga_path_eval_segment(const ga_path *p, size_t seg, double u, void *out)
{
    if (!p || !out || seg + 2 > p->n || !isfinite(u))
        return GA_ERR_ARG;
    const ga_group *g = p->group;
    size_t d = g->dim, nf = nfac(p->scheme);
    int st;
    double x[MAXD], xd[MAXD];
    if (nf == 0) { /* exp(X(t)) */
        gen_curve(p, seg, u, x, xd);
        return g->exp(x, out);
    }
    /* A_i exp(p_1(u) B) exp(p_2(u) C) exp(p_3(u) D) (Li-Hao eqs. 8, 14, 21),
     * the partial products alternating between two buffers, the last one
     * composed straight into out */
    double acc[2][MAXE], e[MAXE];
    const double *left = key_of(p, seg), *X = p->coef + seg * nf * d;
    for (size_t j = 0; j < nf; ++j, X += d) {
        lin(d, x, poly_diff(fac_poly[j], 0, u, 0.0), X, 0.0, X);
        if ((st = g->exp(x, e)))
            return st;
        double *dst = j + 1 == nf ? out : acc[j & 1];
        g->compose(left, e, dst);
        left = dst;
    }
    /* a product of finite factors can still overflow: GA_ERR_DOMAIN, not Inf */
    return finite_elem(g, out);
}

/* DIRECT at (seg, u): at a key time the key itself, not its rounding. */
static int eval_direct(const ga_path *p, size_t seg, double u, void *out)
{
    if (u == 0.0 || u == 1.0) {
        copy_elem(p->group, out, key_of(p, seg + (u == 1.0)));
        return GA_OK;
    }
    return ga_path_eval_segment(p, seg, u, out);
}

int ga_path_eval(const ga_path *p, double t, void *out)
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
    if (nf == 0) { /* J_r(X) X' (group.h dexp), X' per unit t, times h */
        gen_curve(p, seg, u, x, xd);
        g->dexp(x, xd, w);
        lin(d, v, seg_len(p, seg), w, 0.0, w);
        return GA_OK;
    }
    /* M = F_1 F_2 F_3, F_j = exp(p_j X_j): M^-1 M' = Ad_{F_3^-1}(Ad_{F_2^-1}(p_1' X_1)
     * + p_2' X_2) + p_3' X_3 (product rule; Li-Hao eqs. 15, 25, 34) */
    const double *X = p->coef + seg * nf * d;
    for (size_t j = 0; j < nf; ++j, X += d) {
        if (j > 0) {
            double fi[MAXE];
            lin(d, x, -poly_diff(fac_poly[j], 0, u, 0.0), X, 0.0, X);
            if ((st = g->exp(x, fi)))
                return st;
            g->adjoint(fi, v, w);
        } else {
            for (size_t k = 0; k < d; ++k) w[k] = 0.0;
        }
        lin(d, v, 1.0, w, poly_deriv(fac_poly[j], u), X);
    }
    return GA_OK;
}

int ga_path_velocity_segment(const ga_path *p, size_t seg, double u, double *v)
{
    if (!p || !v || seg + 2 > p->n || !isfinite(u))
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

int ga_path_velocity(const ga_path *p, double t, double *v)
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
    double nrm = ga_mat4_norm1(z.c[0]);
    int s = 0;
    if (nrm > 0.5)
        s = (int)ceil(log2(nrm / 0.5));
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

/* Body velocity and acceleration per unit u (u^2) on segment seg. */
static int accel_u(const ga_path *p, size_t seg, double u, double *v, double *a)
{
    const ga_group *g = p->group;
    size_t d = g->dim, nf = nfac(p->scheme);
    double h = seg_len(p, seg);
    int st;
    if (nf == 0) {
        /* G = exp(X(t)): the jet exp(X + e X' + e^2 X''/2) gives G' and G''/2;
         * body velocity G^-1 G', acceleration d/dt(G^-1 G') = G^-1 G'' - (G^-1 G')^2 */
        double x[MAXD], xd[MAXD], xdd[MAXD], gi[MAXE], ge[MAXE];
        gen_curve(p, seg, u, x, xd);
        gen_curve2(p, seg, u, xdd);
        for (size_t k = 0; k < d; ++k) xdd[k] *= 0.5;
        jet z = {{g->hat(x), g->hat(xd), g->hat(xdd)}};
        jet e = jet_exp(z);
        if ((st = g->exp(x, ge)) || (st = g->inverse(ge, gi)))
            return st;
        ga_mat4 G1 = g->to_mat4(gi), V = ga_mat4_mul(G1, e.c[1]), P = ga_mat4_mul(G1, e.c[2]),
                V2 = ga_mat4_mul(V, V), A;
        for (int k = 0; k < 16; ++k) A.m[k] = 2.0 * P.m[k] - V2.m[k];
        g->dexp(x, xd, v); /* the velocity as ga_path_velocity has it */
        if ((st = vee_scaled(g, A, 1.0 + 2.0 * mat_maxabs(P) + mat_maxabs(V2), a)))
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
    const double *X = p->coef + seg * nf * d;
    double w[MAXD], b[MAXD], c[MAXD], x[MAXD], fi[MAXE];
    for (size_t k = 0; k < d; ++k) v[k] = a[k] = 0.0;
    for (size_t j = 0; j < nf; ++j, X += d) {
        const double *cp = fac_poly[j];
        double d1 = poly_deriv(cp, u), d2 = 2 * cp[1] + 6 * cp[2] * u;
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

int ga_path_acceleration_segment(const ga_path *p, size_t seg, double u, double *a)
{
    if (!p || !a || seg + 2 > p->n || !isfinite(u))
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

int ga_path_acceleration(const ga_path *p, double t, double *a)
{
    return ga_path_differentiate(p, t, GA_FRAME_BODY, NULL, a);
}

int ga_path_differentiate_segment(const ga_path *p, size_t seg, double u, ga_frame f, double *v, double *a)
{
    if (!p || seg + 2 > p->n || !isfinite(u) || (unsigned)f > GA_FRAME_SPATIAL)
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

int ga_path_differentiate(const ga_path *p, double t, ga_frame f, double *v, double *a)
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
    if (*cur != seg || (double)*grid * h > u) {
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
static size_t slot_base(size_t j) { return j * (j + 3) / 2; }

static int exact_anchor(ga_path_stepper *s, size_t seg, double u)
{
    const ga_path *p = s->path;
    const ga_group *g = p->group;
    size_t d = g->dim, nf = nfac(p->scheme);
    int st, newseg = seg != s->seg;
    double delta = s->dt / seg_len(p, seg), x[MAXD], e[MAXE];
    const double *X = p->coef + seg * nf * d;
    for (size_t j = 0; j < nf; ++j, X += d)
        for (size_t m = 0; m <= j + 1; ++m) {
            if (m == j + 1 && !newseg)
                break; /* E is kept for the segment */
            lin(d, x, poly_diff(fac_poly[j], m, u, delta), X, 0.0, X);
            if ((st = g->exp(x, m == 0 && j == 0 ? e : s->slot[slot_base(j) + m])))
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
        for (size_t m = 0; m <= j; ++m) {
            double *a = s->slot[slot_base(j) + m];
            g->compose(a, s->slot[slot_base(j) + m + 1], tmp);
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
    g->compose(s->slot[0], s->slot[slot_base(1)], acc);
    if (nf == 3) {
        g->compose(acc, s->slot[slot_base(2)], tmp);
        copy_elem(g, acc, tmp);
    }
    copy_elem(g, out, acc);
}

/* ---- samplers --------------------------------------------------------------------- */

int ga_path_stepper_init(const ga_path *p, ga_eval ev, double step, size_t n, double t0, double t1,
                         ga_path_stepper *s)
{
    if (!s || !p || n < 1 || (unsigned)ev > GA_EVAL_EXACT)
        return GA_ERR_ARG;
    if (!isfinite(t0) || !isfinite(t1))
        return GA_ERR_NOTFINITE;
    if (!(t0 >= p->t[0] && t1 <= p->t[p->n - 1] && t0 <= t1))
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

int ga_path_stepper_next(ga_path_stepper *s, void *out)
{
    if (!s || !out || s->k >= s->n)
        return GA_ERR_ARG;
    const ga_path *p = s->path;
    double t = s->k + 1 == s->n ? s->t1 : s->t0 + (double)s->k * s->dt, u;
    size_t seg = s->seg;
    int st;
    if (seg != SIZE_MAX && p->t[seg] <= t && (t < p->t[seg + 1] || (seg == p->n - 2 && t == p->t[seg + 1]))) {
        /* the running segment again (t is inside [t_0, t_{n-1}] by the init):
           what ga_path_locate would find, without its search */
        u = (t - p->t[seg]) / seg_len(p, seg);
    } else if ((st = ga_path_locate(p, t, &seg, &u))) {
        return st;
    }
    if (s->eval == GA_EVAL_EULER) {
        st = euler_sample(p, s->step, &s->seg, &s->grid, s->slot[0], seg, u, out);
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

int ga_path_sample_uniform(const ga_path *p, ga_eval ev, double step, size_t n, double t0, double t1,
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

int ga_path_sample(const ga_path *p, ga_eval ev, double step, size_t n, const double *times, void *out)
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
