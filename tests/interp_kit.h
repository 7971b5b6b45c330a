/* tests/interp_kit.h: what the tests of the interpolation schemes
 * (test_interp_*.c) share: random key sets, paths in a buffer, samples and
 * finite differences of paths, and the measures of their errors.
 *
 * Header-only (static functions), beside testkit.h.
 *
 * Tolerances: a pose error is max |a_ij - b_ij| over the 4x4 matrices divided
 * by the key set's scale max(1, largest key translation) (rotation entries are
 * O(1), translation entries O(scale)); where a path's formulas are measured
 * (not its keys) the scale also covers the algebra elements it exponentiates
 * (key generators or B_i, C_i, D_i), whose size the computation carries; on
 * affine keys, whose exp can amplify rounding by ||e^X|| ||e^-X||, tolerances
 * are multiplied by that condition number.
 *
 * The random inputs: the sections of the four programs draw from one stream
 * seeded INTERP_SEED, in one order: test_interp_paths' keys, c1, accel;
 * test_interp_c2's decoupled, c2; test_interp_paths' growth, cga_se3;
 * test_interp_forms; test_interp_stepping. A section that does not follow
 * its predecessor in that order starts the stream where the sections before
 * it leave it (tk_rng_after with the number of their draws), so that each
 * sees the inputs the figures of docs/schemes.md were measured on.
 */
#ifndef GAROTOR_INTERP_KIT_H
#define GAROTOR_INTERP_KIT_H

#include "testkit.h"

#define INTERP_SEED 20240607u

#define PI TK_PI
#define MAXK 8
#define WORK 2048

/* ---- random draws (testkit.h: splitmix64) -------------------------------- */

/* (Each draw is its own statement: the order of evaluation of arguments and
 * initializers is unspecified in C, and the sequence must not depend on the
 * compiler.) */
static inline ga_vec3 rvec(tk_rng *r, double s)
{
    ga_vec3 v;
    v.x = tk_range(r, -s, s);
    v.y = tk_range(r, -s, s);
    v.z = tk_range(r, -s, s);
    return v;
}
/* ---- matrices built independently of the library ------------------------- */

/* Rodrigues: R = I + sin th K + (1 - cos th) K^2, then translation. */
static inline ga_mat4 rigid(ga_vec3 u, double th, ga_vec3 t)
{
    double s = sin(th), c = 1.0 - cos(th);
    double K[9] = {0, -u.z, u.y, u.z, 0, -u.x, -u.y, u.x, 0};
    ga_mat4 m;
    memset(&m, 0, sizeof m);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            double k2 = 0;
            for (int l = 0; l < 3; ++l) k2 += K[3 * i + l] * K[3 * l + j];
            m.m[4 * i + j] = (i == j) + s * K[3 * i + j] + c * k2;
        }
    m.m[3] = t.x;
    m.m[7] = t.y;
    m.m[11] = t.z;
    m.m[15] = 1.0;
    return m;
}

/* An exact half turn: R = 2 u u^T - I. */
static inline ga_mat4 half_turn(ga_vec3 u, ga_vec3 t)
{
    double a[3] = {u.x, u.y, u.z};
    ga_mat4 m;
    memset(&m, 0, sizeof m);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) m.m[4 * i + j] = 2 * a[i] * a[j] - (i == j);
    m.m[3] = t.x;
    m.m[7] = t.y;
    m.m[11] = t.z;
    m.m[15] = 1.0;
    return m;
}

static inline ga_mat4 mmul(ga_mat4 a, ga_mat4 b) { return ga_mat4_mul(a, b); }

/* A random rigid motion: angle in [a0, a1] about a random axis, translation
 * in [-ts, ts]^3. */
static inline ga_mat4 rand_rigid(tk_rng *r, double a0, double a1, double ts)
{
    ga_vec3 u = tk_unit(r);
    double th = tk_range(r, a0, a1);
    ga_vec3 t = rvec(r, ts);
    return rigid(u, th, t);
}
static inline ga_twist rand_twist(tk_rng *r, double sw, double sv)
{
    ga_twist x;
    x.w = rvec(r, sw);
    x.v = rvec(r, sv);
    return x;
}

static inline double tnorm(ga_mat4 m) { return sqrt(m.m[3] * m.m[3] + m.m[7] * m.m[7] + m.m[11] * m.m[11]); }

/* Largest entry difference; NaN (a failed evaluation) counts as infinite. */
static inline double mdiff(ga_mat4 a, ga_mat4 b)
{
    double e = 0;
    for (int i = 0; i < 16; ++i) {
        double d = fabs(a.m[i] - b.m[i]);
        e = d > e || d != d ? (d != d ? INFINITY : d) : e;
    }
    return e;
}

static inline double vdiff(const double *a, const double *b, int d)
{
    double e = 0;
    for (int i = 0; i < d; ++i) {
        double x = fabs(a[i] - b[i]);
        e = x > e || x != x ? (x != x ? INFINITY : x) : e;
    }
    return e;
}
static inline double vnorm(const double *a, int d)
{
    double e = 0;
    for (int i = 0; i < d; ++i) e = fmax(e, fabs(a[i]));
    return e;
}

/* ---- key sets ---------------------------------------------------------------- */

typedef struct {
    int n;
    double t[MAXK];
    ga_mat4 m[MAXK];
    double scale;
} keyset;

static inline void random_times(tk_rng *r, keyset *k)
{
    k->t[0] = tk_range(r, -2, 2);
    for (int i = 1; i < k->n; ++i) k->t[i] = k->t[i - 1] + tk_range(r, 0.2, 3.0);
}

/* The j-th of N + 1 evenly spaced times over the keys, the last exactly t_{n-1}. */
static inline double tgrid(const keyset *k, int j, int N)
{
    return j == N ? k->t[k->n - 1] : k->t[0] + (k->t[k->n - 1] - k->t[0]) * j / N;
}

static inline void set_scale(keyset *k)
{
    k->scale = 1.0;
    for (int i = 0; i < k->n; ++i) k->scale = fmax(k->scale, tnorm(k->m[i]));
}

/* n keys at random times on one screw motion exp(t xi) (rand_twist(r, 0.5,
   sv)); returns xi */
static inline ga_twist screw_keys(tk_rng *r, keyset *k, int n, double sv)
{
    k->n = n;
    random_times(r, k);
    ga_twist xi = rand_twist(r, 0.5, sv);
    for (int i = 0; i < n; ++i) {
        ga_twist x = {tk_scale(xi.w, k->t[i]), tk_scale(xi.v, k->t[i])};
        k->m[i] = ga_se3_exp(x);
    }
    set_scale(k);
    return xi;
}

/* kind 0: generic; 1: some exact half turns (absolute); 2: tiny rotations under
 * large translations; 3: relative half turns between neighbours; 4: a mixture. */
static inline void random_keys(tk_rng *r, keyset *k, int n, int kind)
{
    k->n = n;
    random_times(r, k);
    for (int i = 0; i < n; ++i) {
        int kd = kind == 4 ? (int)(tk_next(r) % 4) : kind;
        ga_vec3 u = tk_unit(r);
        if (kd == 1 && tk_next(r) % 2) {
            if (tk_next(r) % 3 == 0) {
                u.x = 0;
                u.y = 0;
                u.z = 1;
            } /* coordinate axis */
            k->m[i] = half_turn(u, rvec(r, 5));
        } else if (kd == 2) {
            double th = pow(10.0, tk_range(r, -9, -5));
            k->m[i] = rigid(u, th, rvec(r, 1e4));
        } else if (kd == 3 && i > 0 && tk_next(r) % 2) {
            ga_vec3 a = tk_unit(r);
            k->m[i] = mmul(k->m[i - 1], half_turn(a, rvec(r, 2)));
        } else {
            double th = tk_range(r, 0, PI);
            k->m[i] = rigid(u, th, rvec(r, 5));
        }
    }
    set_scale(k);
}

/* affine keys: exp of a random 3x4 (scalings, shears), det > 0 */
static inline void affine_keys(tk_rng *r, keyset *k, int n)
{
    k->n = n;
    random_times(r, k);
    for (int i = 0; i < n; ++i) {
        double x[12];
        for (int j = 0; j < 12; ++j) x[j] = tk_range(r, -0.4, 0.4) * (j % 4 == 3 ? 5 : 1);
        ga_group_affine.exp(x, &k->m[i]);
    }
    set_scale(k);
}

/* n keys for a group: affine_keys, else random_keys of the given kind. */
static inline void group_keys(tk_rng *r, int affine, keyset *k, int n, int kind)
{
    if (affine)
        affine_keys(r, k, n);
    else
        random_keys(r, k, n, kind);
}

/* ---- paths ---------------------------------------------------------------------- */

typedef struct {
    ga_path p;
    double work[WORK];
} pathbuf;

static inline int mkpath(pathbuf *b, const ga_group *g, ga_scheme s, const keyset *k, const double *vel)
{
    return ga_path_init_mat4(g, s, (size_t)k->n, k->t, k->m, vel, b->work, sizeof b->work, &b->p);
}

static inline ga_mat4 at(const ga_path *p, double t)
{
    double e[16];
    int st = ga_path_eval(p, t, e);
    if (st) {
        ga_mat4 z;
        for (int i = 0; i < 16; ++i) z.m[i] = NAN;
        return z;
    }
    return p->group->to_mat4(e);
}
static inline ga_mat4 at_seg(const ga_path *p, int seg, double u)
{
    double e[16];
    int st = ga_path_eval_segment(p, (size_t)seg, u, e);
    if (st) {
        ga_mat4 z;
        for (int i = 0; i < 16; ++i) z.m[i] = NAN;
        return z;
    }
    return p->group->to_mat4(e);
}

/* The velocity at t; NaN if the call fails (so that a check sees it). */
static inline void vel_at(const ga_path *p, double t, double *v)
{
    if (ga_path_velocity(p, t, v) != GA_OK)
        for (size_t i = 0; i < p->group->dim; ++i) v[i] = NAN;
}

/* y = log(a^-1 b) through the group (the body displacement from a to b). */
static inline void body_log(const ga_group *g, const void *a, const void *b, double *y)
{
    double ai[16], r[16];
    g->inverse(a, ai);
    g->compose(ai, b, r);
    if (g->log(r, y) != GA_OK)
        for (size_t i = 0; i < g->dim; ++i) y[i] = NAN;
}

/* Central difference body velocity at (seg, u). */
static inline void fd_central(const ga_path *p, int seg, double u, double eps, double *v)
{
    const ga_group *g = p->group;
    double a[16], b1[16], b2[16], y1[12], y2[12];
    double h = p->t[seg + 1] - p->t[seg];
    TK_OK(ga_path_eval_segment(p, (size_t)seg, u, a));
    TK_OK(ga_path_eval_segment(p, (size_t)seg, u + eps / h, b1));
    TK_OK(ga_path_eval_segment(p, (size_t)seg, u - eps / h, b2));
    body_log(g, a, b1, y1);
    body_log(g, a, b2, y2);
    for (size_t i = 0; i < g->dim; ++i) v[i] = (y1[i] - y2[i]) / (2 * eps);
}

/* Central difference of the analytic velocity in frame f at (seg, u), step e in t. */
static inline void fd_accel(const ga_path *p, int seg, double u, ga_frame f, double e, double *a)
{
    double vp[12], vm[12], h = p->t[seg + 1] - p->t[seg];
    TK_OK(ga_path_differentiate_segment(p, (size_t)seg, u + e / h, f, vp, NULL));
    TK_OK(ga_path_differentiate_segment(p, (size_t)seg, u - e / h, f, vm, NULL));
    for (size_t i = 0; i < p->group->dim; ++i) a[i] = (vp[i] - vm[i]) / (2 * e);
}

/* The scale a path's computation carries: keys' translations and the algebra
 * elements it exponentiates (key generators, or B_i, C_i, D_i). */
static inline double path_scale(const ga_path *p, const keyset *k)
{
    double s = k->scale;
    size_t m = p->gen ? p->n
                      : (p->n - 1) * (p->scheme == GA_SCHEME_SCREW    ? 1
                                      : p->scheme == GA_SCHEME_LIHAO2 ? 2
                                                                      : 3);
    const double *x = p->gen ? p->gen : p->coef;
    for (size_t i = 0; i < m * p->group->dim; ++i) s = fmax(s, fabs(x[i]));
    return s;
}

/* The conditioning of a path's formulas: the largest ||E||_1 ||E^-1||_1 over the
 * factors E = exp(X) it multiplies (B_i, C_i, D_i or the key generators). The
 * rounding of a product grows with it, so affine tolerances scale with it. */
static inline double path_cond(const ga_path *p)
{
    const ga_group *g = p->group;
    int d = (int)g->dim, m = (int)(p->coef ? (p->n - 1) * (p->scheme == GA_SCHEME_SCREW    ? 1
                                                           : p->scheme == GA_SCHEME_LIHAO2 ? 2
                                                                                           : 3)
                                           : p->n);
    const double *x = p->coef ? p->coef : p->gen;
    double c = 1.0;
    for (int i = 0; i < m; ++i) {
        double e[16], ei[16], nx[12];
        for (int k = 0; k < d; ++k) nx[k] = -x[i * d + k];
        g->exp(x + i * d, e);
        g->exp(nx, ei);
        c = fmax(c, ga_mat4_norm1(g->to_mat4(e)) * ga_mat4_norm1(g->to_mat4(ei)));
    }
    return c;
}

#endif
