/* tests/test_schemes.c: the properties every interpolation scheme claims,
 * checked the same way on every scheme x group (path.h, docs/schemes.md), in
 * the manner of Sophus's LieGroupTests: one generic property, every case.
 *
 * For each scheme and each group of ga_group_nth that the library builds it
 * on (ga_path_workspace_size nonzero; the decoupled schemes and c2 are
 * refused on affine): the keys are hit (bspline approximates and has none to
 * hit); the continuity the scheme claims holds at its interior keys (bspline:
 * knots), pose, velocity and acceleration from both sides of the key by
 * ga_path_*_segment; cga and matrix give the same poses from the same keys;
 * appending key by key builds the path ga_path_init builds from all keys, bit
 * for bit; shifting every time by a constant shifts the path; bad keys give
 * the statuses of path.h.
 *
 * Tolerances, from what is computed. A key set's unit is
 * U = eps K, its errors measured relative to S = max(1, largest key entry):
 * K = max th/sin th over the keys' rotations and the relative motions the
 * schemes take the log of (the log's condition; th <= 2.4 here, K <= 3.6),
 * on affine the largest ||A||_1 ||A^-1||_1 of a key (a product's rounding
 * grows with it). A pose is a product of at most 4 exps of logs of such
 * motions and keys, each backward stable to a few eps: 64 U. A velocity or an
 * acceleration carries its size and the adjoint through the translation
 * (|t| |w| in v): 64 U times S times its size. The c2 solvers (c2,
 * decoupled-c2) stop when no key rate moves by more than 4 eps of the
 * largest, or when the change, below 1e-12 of it, stops falling (path.c): a
 * rate off by 1e-12 relative moves the acceleration at its key by 1e-12 of
 * the rates' size over the spacing, which the acceleration's tolerance adds.
 */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "testkit.h"

static tk_rng rng = {0x736368656d6573ull}; /* "schemes" */

enum { NK = 6, SETS = 16, WORK = 1 << 14 };
static const double EPS = DBL_EPSILON;

typedef struct {
    size_t n;
    double t[NK];
    ga_mat4 m[NK];
    double S, K; /* the scale and the condition (above) */
} keyset;

static double work_a[WORK], work_b[WORK];

/* The scheme's continuity at its interior keys (path.h, docs/schemes.md):
   0 C0, 1 C1, 2 C2. quadratic is one exp of one quadratic: smooth. */
static int claimed_order(ga_scheme s)
{
    switch (s) {
    case GA_SCHEME_QUADRATIC:
    case GA_SCHEME_DECOUPLED_C2:
    case GA_SCHEME_BSPLINE:
    case GA_SCHEME_C2: return 2;
    case GA_SCHEME_SMOOTH:
    case GA_SCHEME_LIHAO2:
    case GA_SCHEME_LIHAO3: return 1;
    default: return 0;
    }
}

static double mdiff(ga_mat4 a, ga_mat4 b)
{
    double e = 0;
    for (int i = 0; i < 16; i++) e = tk_max(e, fabs(a.m[i] - b.m[i]));
    return e;
}
static double vmax(const double *v, size_t d)
{
    double e = 0;
    for (size_t i = 0; i < d; i++) e = tk_max(e, fabs(v[i]));
    return e;
}
static double vdiff(const double *a, const double *b, size_t d)
{
    double e = 0;
    for (size_t i = 0; i < d; i++) e = tk_max(e, fabs(a[i] - b[i]));
    return e;
}
/* th/sin th of a rotation angle th < pi (1 at 0) */
static double log_cond(double th) { return th > 1e-8 ? th / sin(th) : 1.0; }
static double angle_of(ga_mat4 m)
{
    ga_twist xi;
    return ga_se3_log(m, &xi) == GA_OK ? tk_norm(xi.w) : INFINITY;
}

/* Keys of group g: rigid, every rotation at most 1.2 rad (so a relative one
 * is at most 2.4 and every log is well conditioned), translations up to 3;
 * affine, expm of a 3x4 with entries up to 0.3 (translations up to 1).
 * Times dyadic (multiples of 1/64, spacings 0.5..2, or one spacing for
 * bspline), so that a shift by 1024 leaves every difference exact. */
static void draw_keys(const ga_group *g, ga_scheme s, size_t n, keyset *k)
{
    k->n = n;
    double h = 0.5 + floor(tk_uni(&rng) * 96) / 64;
    k->t[0] = floor(tk_range(&rng, -2, 2) * 64) / 64;
    for (size_t i = 1; i < n; i++)
        k->t[i] = k->t[i - 1] + (s == GA_SCHEME_BSPLINE ? h : 0.5 + floor(tk_uni(&rng) * 96) / 64);
    k->S = 1, k->K = 1;
    for (size_t i = 0; i < n; i++) {
        if (g->rigid) {
            ga_vec3 w = tk_scale(tk_unit(&rng), tk_range(&rng, 0, 1.2));
            ga_vec3 v = tk_scale(tk_unit(&rng), tk_range(&rng, 0, 3));
            k->m[i] = ga_se3_exp((ga_twist){w, v});
            k->K = fmax(k->K, log_cond(angle_of(k->m[i])));
            if (i > 0)
                k->K = fmax(k->K, log_cond(angle_of(ga_mat4_mul(ga_se3_inverse(k->m[i - 1]), k->m[i]))));
        } else {
            double x[12], e[16];
            for (int j = 0; j < 12; j++)
                x[j] = j % 4 == 3 ? tk_range(&rng, -1, 1) : tk_range(&rng, -0.3, 0.3);
            TK_OK(g->exp(x, e));
            k->m[i] = g->to_mat4(e);
            ga_mat4 inv;
            TK_OK(ga_mat4_inverse(k->m[i], &inv));
            k->K = fmax(k->K, ga_mat4_norm1(k->m[i]) * ga_mat4_norm1(inv));
        }
        for (int j = 0; j < 16; j++) k->S = fmax(k->S, fabs(k->m[i].m[j]));
    }
}

static size_t keys_for(ga_scheme s) { return s == GA_SCHEME_QUADRATIC ? 3 : NK; }

/* The largest ||E||_1 ||E^-1||_1 over the factors E = exp(X) a path
 * multiplies (path.h's coef: B_i[, C_i[, D_i]] or bspline's d_i; gen: the key
 * generators); 1 where it has none. */
static double factor_cond(const ga_path *p)
{
    const ga_group *g = p->group;
    size_t per = p->scheme == GA_SCHEME_LIHAO2 ? 2 : p->scheme == GA_SCHEME_LIHAO3 ? 3 : 1;
    size_t m = p->gen ? p->n : p->n - 1;
    const double *x = p->gen ? p->gen : p->coef;
    if (p->scheme == GA_SCHEME_C2 || p->scheme == GA_SCHEME_DECOUPLED ||
        p->scheme == GA_SCHEME_DECOUPLED_C2 || !x)
        return 1.0; /* no factors exp(X) of their own */
    double c = 1.0;
    for (size_t i = 0; i < m * per; i++) {
        double e[GA_GROUP_MAX_ELEM], ei[GA_GROUP_MAX_ELEM], nx[GA_GROUP_MAX_DIM];
        for (size_t j = 0; j < g->dim; j++) nx[j] = -x[i * g->dim + j];
        TK_OK(g->exp(x + i * g->dim, e));
        TK_OK(g->exp(nx, ei));
        c = fmax(c, ga_mat4_norm1(g->to_mat4(e)) * ga_mat4_norm1(g->to_mat4(ei)));
    }
    return c;
}

static long refused; /* lihao2 on affine: GA_ERR_DOMAIN (below) */

/* Build the path through k; on affine the factors' condition joins K. Li-Hao's
 * chained quadratic on affine keys may grow until a factor has no real log
 * (test_interp_paths' affine lihao2): GA_ERR_DOMAIN there is that limit, counted,
 * and the key set skipped (returns 0); any other failure fails check c. */
static int build_or_skip(const ga_group *g, ga_scheme s, keyset *k, double *work, ga_path *p, tk_check *c)
{
    ga_status st = ga_path_init_mat4(g, s, k->n, k->t, k->m, NULL, work, sizeof work_a, p);
    if (st == GA_ERR_DOMAIN && !g->rigid && s == GA_SCHEME_LIHAO2) {
        refused++;
        return 0;
    }
    if (st != GA_OK) {
        tk_note("     %s on %s: ga_path_init: %s\n", ga_scheme_name(s), g->name, ga_status_string(st));
        tk_add_tol(c, INFINITY, 0);
        return 0;
    }
    if (!g->rigid)
        k->K = fmax(k->K, factor_cond(p));
    return 1;
}
static ga_status build(const ga_group *g, ga_scheme s, const keyset *k, double *work, ga_path *p)
{
    return ga_path_init_mat4(g, s, k->n, k->t, k->m, NULL, work, sizeof work_a, p);
}

static ga_mat4 pose_seg(const ga_path *p, size_t seg, double u)
{
    double e[GA_GROUP_MAX_ELEM];
    if (ga_path_eval_segment(p, seg, u, e) != GA_OK) {
        ga_mat4 z;
        for (int i = 0; i < 16; i++) z.m[i] = NAN;
        return z;
    }
    return p->group->to_mat4(e);
}
static ga_mat4 pose_at(const ga_path *p, double t)
{
    double e[GA_GROUP_MAX_ELEM];
    if (ga_path_eval(p, t, e) != GA_OK) {
        ga_mat4 z;
        for (int i = 0; i < 16; i++) z.m[i] = NAN;
        return z;
    }
    return p->group->to_mat4(e);
}

/* Calls f(g, s) for every scheme x group the library builds. */
static void each_case(void (*f)(const ga_group *g, ga_scheme s))
{
    const ga_group *g;
    for (size_t gi = 0; (g = ga_group_nth(gi)); gi++)
        for (int s = 0; s < GA_SCHEME_COUNT; s++)
            if (ga_path_workspace_size(g, (ga_scheme)s, NK) != 0)
                f(g, (ga_scheme)s);
    tk_end_named();
    if (refused)
        tk_note("     (%ld affine lihao2 key sets skipped: GA_ERR_DOMAIN, a factor with no real log)\n",
                refused);
    refused = 0;
}

static tk_check *named(const ga_group *g, ga_scheme s, const char *what)
{
    char name[128];
    snprintf(name, sizeof name, "%s on %s: %s", ga_scheme_name(s), g->name, what);
    return tk_get(name);
}

/* ---- the keys are hit: eval at t_i, and each side's formula at the key ---- */
static void keys_case(const ga_group *g, ga_scheme s)
{
    if (s == GA_SCHEME_BSPLINE) /* approximating: no key to hit */
        return;
    tk_check *c = named(g, s, "A(t_i) = A_i, and each side's formula, / S (64 U)");
    for (int set = 0; set < SETS; set++) {
        keyset k;
        ga_path p;
        draw_keys(g, s, keys_for(s), &k);
        if (!build_or_skip(g, s, &k, work_a, &p, c))
            continue;
        double tol = 64 * EPS * k.K;
        for (size_t i = 0; i < k.n; i++) {
            tk_add_tol(c, mdiff(pose_at(&p, k.t[i]), k.m[i]) / k.S, tol);
            if (i > 0)
                tk_add_tol(c, mdiff(pose_seg(&p, i - 1, 1.0), k.m[i]) / k.S, tol);
            if (i + 1 < k.n)
                tk_add_tol(c, mdiff(pose_seg(&p, i, 0.0), k.m[i]) / k.S, tol);
        }
    }
}
static void keys(void) { each_case(keys_case); }

/* ---- continuity at the interior keys (bspline: knots), as claimed --------- */
static void continuity_case(const ga_group *g, ga_scheme s)
{
    static const char *what[3] = {"C0 at the keys, pose / S (64 U)",
                                  "C1 at the keys, velocity / (S |v|) (64 U)",
                                  "C2 at the keys, acceleration / (S |a|) (64 U, solver 1e-12)"};
    int order = claimed_order(s);
    tk_check *c[3];
    for (int o = 0; o <= order; o++) c[o] = named(g, s, what[o]);
    size_t d = g->dim;
    for (int set = 0; set < SETS; set++) {
        keyset k;
        ga_path p;
        draw_keys(g, s, keys_for(s), &k);
        if (!build_or_skip(g, s, &k, work_a, &p, c[0]))
            continue;
        double tol = 64 * EPS * k.K, hmin = INFINITY;
        for (size_t i = 0; i + 1 < k.n; i++) hmin = fmin(hmin, k.t[i + 1] - k.t[i]);
        for (size_t seg = 1; seg < ga_path_segments(&p); seg++) {
            tk_add_tol(c[0], mdiff(pose_seg(&p, seg - 1, 1.0), pose_seg(&p, seg, 0.0)) / k.S, tol);
            if (order < 1)
                continue;
            double vl[GA_GROUP_MAX_DIM], vr[GA_GROUP_MAX_DIM], al[GA_GROUP_MAX_DIM], ar[GA_GROUP_MAX_DIM];
            TK_OK(ga_path_velocity_segment(&p, seg - 1, 1.0, vl));
            TK_OK(ga_path_velocity_segment(&p, seg, 0.0, vr));
            double vs = fmax(1, fmax(vmax(vl, d), vmax(vr, d)));
            tk_add_tol(c[1], vdiff(vl, vr, d) / (k.S * vs), tol);
            if (order < 2)
                continue;
            TK_OK(ga_path_acceleration_segment(&p, seg - 1, 1.0, al));
            TK_OK(ga_path_acceleration_segment(&p, seg, 0.0, ar));
            double as = fmax(vs * vs, fmax(vmax(al, d), vmax(ar, d)));
            /* the solved key rates: 1e-12 of their size, over the spacing */
            int solved = s == GA_SCHEME_C2 || s == GA_SCHEME_DECOUPLED_C2;
            tk_add_tol(c[2], vdiff(al, ar, d) / (k.S * as), tol + (solved ? 1e-12 * vs / hmin / as : 0));
        }
    }
}
static void continuity(void) { each_case(continuity_case); }

/* ---- cga = matrix: the same keys give the same poses ---------------------- */
static void cga_matrix(void)
{
    for (int s = 0; s < GA_SCHEME_COUNT; s++) {
        tk_check *c = named(&ga_group_cga, (ga_scheme)s, "= matrix, poses / S (2 x 64 U)");
        for (int set = 0; set < SETS; set++) {
            keyset k;
            ga_path pc, pm;
            draw_keys(&ga_group_se3, (ga_scheme)s, keys_for((ga_scheme)s), &k);
            if (build(&ga_group_cga, (ga_scheme)s, &k, work_a, &pc) != GA_OK ||
                build(&ga_group_se3, (ga_scheme)s, &k, work_b, &pm) != GA_OK) {
                tk_add_tol(c, INFINITY, 0);
                continue;
            }
            for (size_t seg = 0; seg < ga_path_segments(&pc); seg++)
                for (int j = 0; j <= 8; j++) {
                    double u = j / 8.0;
                    tk_add_tol(c, mdiff(pose_seg(&pc, seg, u), pose_seg(&pm, seg, u)) / k.S, 128 * EPS * k.K);
                }
        }
    }
    tk_end_named();
}

/* ---- append = rebuild, bit for bit ----------------------------------------- */
static int same_bits(const ga_path *a, const ga_path *b)
{
    double t0, t1;
    TK_OK(ga_path_range(a, &t0, &t1));
    for (int j = 0; j <= 64; j++)
        if (!tk_path_same_at(a, b, j == 64 ? t1 : t0 + (t1 - t0) * j / 64))
            return 0;
    return 1;
}
static void append_case(const ga_group *g, ga_scheme s)
{
    if (!ga_scheme_can_append(s))
        return;
    tk_check *c = named(g, s, "appended key by key = ga_path_init, bit for bit");
    size_t start = ga_scheme_min_keys(s);
    for (int set = 0; set < SETS; set++) {
        keyset k;
        ga_path all, grown;
        draw_keys(g, s, NK, &k);
        ga_status sa = build(g, s, &k, work_a, &all);
        keyset first = k;
        first.n = start;
        ga_status st = build(g, s, &first, work_b, &grown);
        for (size_t i = start; i < NK && st == GA_OK; i++) st = ga_path_append_mat4(&grown, k.t[i], k.m[i]);
        /* affine lihao2's GA_ERR_DOMAIN (build_or_skip): growing fails alike */
        if (sa == GA_ERR_DOMAIN && !g->rigid && s == GA_SCHEME_LIHAO2)
            tk_add_bool(c, st == sa);
        else
            tk_add_bool(c, sa == GA_OK && st == GA_OK && grown.n == NK && same_bits(&all, &grown));
    }
}
static void append(void) { each_case(append_case); }

/* ---- shift invariance: times + 16 give the path shifted ------------------- */
/* With dyadic times every spacing and every t - t_i is the same double after
   the shift. A formula that rebuilds t from (t_i, u) rounds it at the shifted
   size instead: by eps (16 + |t|) at most, which moves the pose by at most
   |A V^| of that, 4 S |V| (V the body velocity there). */
static void shift_case(const ga_group *g, ga_scheme s)
{
    tk_check *c = named(g, s, "times + 16: A(t + 16) = A(t), / S (4 eps (16+|t|) |V|)");
    for (int set = 0; set < SETS; set++) {
        keyset k, ks;
        ga_path p, ps;
        draw_keys(g, s, keys_for(s), &k);
        ks = k;
        for (size_t i = 0; i < k.n; i++) ks.t[i] = k.t[i] + 16;
        if (!build_or_skip(g, s, &k, work_a, &p, c) || !build_or_skip(g, s, &ks, work_b, &ps, c))
            continue;
        double t0, t1;
        TK_OK(ga_path_range(&p, &t0, &t1));
        for (int j = 0; j <= 32; j++) {
            double t = t0 + (t1 - t0) * j / 32, v[GA_GROUP_MAX_DIM]; /* a multiple of 2^-11 */
            TK_OK(ga_path_velocity(&p, t, v));
            tk_add_tol(c, mdiff(pose_at(&p, t), pose_at(&ps, t + 16)) / k.S,
                       4 * EPS * (16 + fabs(t)) * vmax(v, g->dim));
        }
    }
}
static void shift(void) { each_case(shift_case); }

/* ---- statuses on bad keys --------------------------------------------------- */
static void statuses_case(const ga_group *g, ga_scheme s)
{
    keyset k;
    draw_keys(g, s, keys_for(s), &k);
    double keys[NK][GA_GROUP_MAX_ELEM];
    ga_path p;
    for (size_t i = 0; i < k.n; i++) TK_OK(g->from_mat4(k.m[i], keys[i]));
    size_t n = k.n, stride = g->elem_size;
    unsigned char raw[NK * sizeof(double) * GA_GROUP_MAX_ELEM];
    for (size_t i = 0; i < n; i++) memcpy(raw + i * stride, keys[i], stride);
    tk_check *c = named(g, s, "bad keys: NaN, times, too few, non-rigid: the statuses");
    tk_add_status(c, ga_path_init(g, s, n, k.t, raw, NULL, work_a, sizeof work_a, &p), GA_OK); /* good */
    double nan = NAN;
    memcpy(raw + 2 * stride, &nan, sizeof nan); /* a NaN in key 2 */
    tk_add_status(c, ga_path_init(g, s, n, k.t, raw, NULL, work_a, sizeof work_a, &p), GA_ERR_NOTFINITE);
    memcpy(raw + 2 * stride, keys[2], stride);
    keyset bad = k;
    bad.t[2] = bad.t[1]; /* times not increasing */
    tk_add_status(c, build(g, s, &bad, work_a, &p), GA_ERR_ARG);
    bad.t[2] = bad.t[1] - 0.5;
    tk_add_status(c, build(g, s, &bad, work_a, &p), GA_ERR_ARG);
    size_t few = ga_scheme_min_keys(s) - 1; /* too few (one key is a path: then none) */
    tk_add_status(c, ga_path_init(g, s, few > 1 ? few : 0, k.t, raw, NULL, work_a, sizeof work_a, &p),
                  GA_ERR_ARG);
    if (g->rigid) { /* a scaled rotation block is no rigid motion */
        bad = k;
        for (int r = 0; r < 3; r++)
            for (int col = 0; col < 3; col++) bad.m[1].m[4 * r + col] *= 1.01;
        tk_add_status(c, build(g, s, &bad, work_a, &p), GA_ERR_NOTRIGID);
    }
}
static void statuses(void) { each_case(statuses_case); }

static const tk_section sections[] = {
    {"keys", keys, TK_STREAM},
    {"continuity", continuity, TK_STREAM},
    {"cga_matrix", cga_matrix, TK_STREAM},
    {"append", append, TK_STREAM},
    {"shift", shift, TK_STREAM},
    {"statuses", statuses, TK_STREAM},
};

int main(int argc, char **argv) { return tk_main(argc, argv, "test_schemes", sections, TK_COUNT(sections)); }
