/* interp/path.c: the core of a path (path.h): names of the schemes and
 * evaluators, the workspace and its layout, ga_path_init (checks, then each
 * scheme's build) and ga_path_append, and where a time falls (range, locate).
 * The schemes are in scheme_*.c, the evaluators in eval.c and step.c, all
 * written once against the group interface (group.h); interp/internal/path.h
 * is what they share.
 */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#include <garotor/mat4.h>
#include <garotor/path.h>

#include "internal/path.h"

/* ---- names ---------------------------------------------------------------- */

static const char *const scheme_names[GA_SCHEME_COUNT] = {"screw",   "bivector", "quadratic", "smooth",
                                                          "lihao2",  "lihao3",   "decoupled", "decoupled-c2",
                                                          "bspline", "c2"};
static const char *const eval_names[] = {"direct", "euler", "exact"};

const char *ga_scheme_name(ga_scheme s) { return (unsigned)s < GA_SCHEME_COUNT ? scheme_names[s] : "?"; }

ga_status ga_scheme_by_name(const char *name, ga_scheme *out)
{
    if (!name || !out)
        return GA_ERR_ARG;
    for (unsigned i = 0; i < GA_SCHEME_COUNT; ++i)
        if (strcmp(name, scheme_names[i]) == 0) {
            *out = (ga_scheme)i;
            return GA_OK;
        }
    return GA_ERR_ARG;
}

const char *ga_eval_name(ga_eval e) { return (unsigned)e < 3 ? eval_names[e] : "?"; }

ga_status ga_eval_by_name(const char *name, ga_eval *out)
{
    if (!name || !out)
        return GA_ERR_ARG;
    for (unsigned i = 0; i < 3; ++i)
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

/* ---- logs, for every scheme ------------------------------------------------------- */

/* The principal log, made deterministic at half turns (group.h half_turn). */
int gip_plog(const ga_group *g, const void *a, double *x)
{
    int st = g->log(a, x);
    if (st == GA_OK && g->half_turn)
        g->half_turn(x);
    return st;
}

/* x = plog(a^-1 b) */
int gip_rel(const ga_group *g, const void *a, const void *b, void *rel)
{
    double ai[GIP_MAXE];
    if (memcmp(a, b, g->elem_size) == 0) { /* a constant segment: exactly no motion */
        g->identity(rel);
        return GA_OK;
    }
    int st = g->inverse(a, ai);
    if (st != GA_OK)
        return st;
    g->compose(ai, b, rel);
    return GA_OK;
}

int gip_rel_log(const ga_group *g, const void *a, const void *b, double *x, double *rel)
{
    int st = gip_rel(g, a, b, rel);
    if (st != GA_OK)
        return st;
    if (memcmp(a, b, g->elem_size) == 0) {
        memset(x, 0, g->dim * sizeof(double));
        return GA_OK;
    }
    return gip_plog(g, rel, x);
}

/* ---- workspace ---------------------------------------------------------------- */

/* Schemes defined on the rigid groups only (group.h rigid, to_qt/from_qt). */
static int rigid_only(const ga_group *g, ga_scheme s)
{
    return (gip_is_decoupled(s) && (!g->to_qt || !g->from_qt)) || (s == GA_SCHEME_C2 && !g->rigid);
}

size_t gip_scheme_doubles(ga_scheme s, size_t N, size_t D)
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
    case GA_SCHEME_DECOUPLED_C2: return gip_dec_doubles(N);
    case GA_SCHEME_C2: return 3 * S * D + N * D + N * (D * D + D) + S * D * D;
    }
    return 0;
}

size_t ga_path_workspace_size(const ga_group *g, ga_scheme s, size_t n)
{
    if (!g || n < 1 || (unsigned)s >= GA_SCHEME_COUNT || rigid_only(g, s))
        return 0;
    size_t stride = (g->elem_size + sizeof(double) - 1) / sizeof(double), d = g->dim;
    /* The doubles are linear in n: base + (n - 1) per. Refuse (0) an n whose
       bytes do not fit in a size_t, rather than return them wrapped around;
       below that bound no term of the sum below can wrap either. */
    size_t base = 1 + stride + gip_scheme_doubles(s, 1, d);
    size_t per = 1 + stride + gip_scheme_doubles(s, 2, d) - gip_scheme_doubles(s, 1, d);
    size_t room = SIZE_MAX / sizeof(double);
    if (base > room || n - 1 > (room - base) / per)
        return 0;
    return sizeof(double) * (n + n * stride + gip_scheme_doubles(s, n, d));
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
    /* 0: the bytes of n keys do not fit in a size_t */
    size_t need = ga_path_workspace_size(g, s, n);
    if (need == 0 || bytes < need || (uintptr_t)work % _Alignof(double))
        return GA_ERR_ARG;
    if (!gip_allfinite(times, n))
        return GA_ERR_NOTFINITE;
    for (size_t i = 0; i + 1 < n; ++i)
        if (!(times[i] < times[i + 1]))
            return GA_ERR_ARG;
    if (s == GA_SCHEME_BSPLINE && ga_times_uneven(n, times))
        return GA_ERR_ARG;
    size_t d = g->dim, m = n;
    if (ga_scheme_can_append(s)) { /* every key the workspace has room for */
        size_t one = ga_path_workspace_size(g, s, 1), per = ga_path_workspace_size(g, s, 2) - one;
        m += (bytes - need) / per;
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

static int build_scheme(ga_path *p, const double *vel)
{
    switch (p->scheme) {
    case GA_SCHEME_SCREW:
    case GA_SCHEME_BSPLINE: return gip_build_screw(p);
    case GA_SCHEME_LIHAO2:
    case GA_SCHEME_LIHAO3: return gip_build_lihao(p, vel);
    case GA_SCHEME_BIVECTOR: return gip_build_generators(p);
    case GA_SCHEME_QUADRATIC:
    case GA_SCHEME_SMOOTH: {
        int st = gip_build_generators(p);
        if (st == GA_OK)
            gip_build_smooth(p);
        return st;
    }
    case GA_SCHEME_DECOUPLED:
    case GA_SCHEME_DECOUPLED_C2: return gip_build_decoupled(p);
    case GA_SCHEME_C2: return gip_build_c2(p);
    }
    return GA_ERR_ARG;
}

/* The scheme's coefficients, which follow the keys in the workspace, must be
 * finite (see gip_finite_elem). The keys and velocities are checked first, so a
 * GA_ERR_NOTFINITE from inside (a log of a product of keys that overflowed) is
 * finite input overflowing: GA_ERR_DOMAIN. */
static int build(ga_path *p, const double *vel)
{
    const ga_group *g = p->group;
    size_t ed = g->elem_size / sizeof(double);
    for (size_t i = 0; i < p->n; ++i)
        if (!gip_allfinite(gip_key_of(p, i), ed))
            return GA_ERR_NOTFINITE;
    size_t nv = p->scheme == GA_SCHEME_LIHAO3 ? p->n : p->scheme == GA_SCHEME_LIHAO2 ? 1 : 0;
    if (vel && !gip_allfinite(vel, nv * g->dim))
        return GA_ERR_NOTFINITE;
    /* the scheme's block, laid out for p->cap keys: defined everywhere (room
       for keys to come included), so that it can be checked whole */
    double *c = p->key + p->cap * p->key_stride;
    size_t nc = gip_scheme_doubles(p->scheme, p->cap, g->dim);
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
    return gip_allfinite(c, nc) ? GA_OK : GA_ERR_DOMAIN;
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
            gip_copy_elem(g, gip_key_of(&p, i), (const unsigned char *)keys + i * g->elem_size);
        else if ((st = g->from_mat4(((const ga_mat4 *)keys)[i], gip_key_of(&p, i))))
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
 * all n + 1 keys, bit for bit. Nothing is visible
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
    double *k = gip_key_of(&q, i + 1), rel[GIP_MAXE];
    int st = GA_OK;
    if (!mat4)
        gip_copy_elem(g, k, key);
    else if ((st = g->from_mat4(*(const ga_mat4 *)key, k)))
        return st;
    if (!gip_allfinite(k, g->elem_size / sizeof(double)))
        return GA_ERR_NOTFINITE;
    q.t[i + 1] = t;
    q.n = i + 2;
    /* BSPLINE: at least 4 keys before and after, evenly spaced (path.h) */
    if (q.scheme == GA_SCHEME_BSPLINE && (i + 1 < 4 || ga_times_uneven(i + 2, q.t)))
        return GA_ERR_ARG;
    switch (q.scheme) {
    case GA_SCHEME_BSPLINE: /* d_i of keys i, i + 1, as SCREW's B_i */
    case GA_SCHEME_SCREW:
        st = gip_rel_log(g, gip_key_of(&q, i), k, q.coef + i * d, rel);
        if (st == GA_OK && !gip_allfinite(q.coef + i * d, d))
            st = GA_ERR_DOMAIN;
        break;
    case GA_SCHEME_LIHAO2:
        if (i == 0 && !q.v0_given) { /* the default first velocity (path.h) */
            if ((st = gip_rel_log(g, gip_key_of(&q, 0), k, q.vel, rel)))
                break;
            gip_lin(d, q.vel, 1.0 / gip_seg_len(&q, 0), q.vel, 0.0, q.vel);
        }
        if (!gip_allfinite(q.vel + i * d, d))
            st = GA_ERR_DOMAIN;
        else if ((st = gip_lihao_segment(&q, i)) == GA_OK &&
                 !(gip_allfinite(q.coef + 2 * i * d, 2 * d) && gip_allfinite(q.vel + (i + 1) * d, d)))
            st = GA_ERR_DOMAIN;
        break;
    case GA_SCHEME_BIVECTOR:
        if (i == 0 && (st = gip_plog(g, gip_key_of(&q, 0), q.gen))) /* one key: nothing was built */
            break;
        if ((st = gip_plog(g, k, q.gen + (i + 1) * d)) == GA_OK && g->branch)
            g->branch(q.gen + i * d, q.gen + (i + 1) * d);
        if (st == GA_OK && !gip_allfinite(q.gen + (i + 1) * d, d))
            st = GA_ERR_DOMAIN;
        break;
    case GA_SCHEME_DECOUPLED: st = gip_dec_append(&q, i, k); break;
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

/* ---- segments and times --------------------------------------------------------- */

size_t ga_path_segments(const ga_path *p) { return p ? gip_nseg(p) : 0; }

ga_status ga_path_range(const ga_path *p, double *t0, double *t1)
{
    if (!p || !t0 || !t1)
        return GA_ERR_ARG;
    *t0 = gip_knot(p, 0);
    *t1 = gip_knot(p, gip_nseg(p));
    return GA_OK;
}

ga_status ga_path_segment_range(const ga_path *p, size_t seg, double *t0, double *t1)
{
    if (!p || !t0 || !t1 || seg >= gip_nseg(p))
        return GA_ERR_ARG;
    *t0 = gip_knot(p, seg);
    *t1 = gip_knot(p, seg + 1);
    return GA_OK;
}

ga_status ga_path_locate(const ga_path *p, double t, size_t *seg, double *u)
{
    if (!p || !seg || !u)
        return GA_ERR_ARG;
    size_t m = gip_nseg(p);
    if (!(t >= gip_knot(p, 0) && t <= gip_knot(p, m)))
        return GA_ERR_ARG; /* also NaN */
    if (m == 0) {          /* the constant path: its key, "segment 0" at u = 0 */
        *seg = 0;
        *u = 0.0;
        return GA_OK;
    }
    size_t lo = 0, hi = m - 1; /* largest i <= m-1 with knot i <= t */
    while (lo < hi) {
        size_t mid = (lo + hi + 1) / 2;
        if (gip_knot(p, mid) <= t)
            lo = mid;
        else
            hi = mid - 1;
    }
    *seg = lo;
    *u = (t - gip_knot(p, lo)) / gip_seg_len(p, lo);
    return GA_OK;
}
