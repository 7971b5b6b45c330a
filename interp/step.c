/* interp/step.c: samples of a path at many times (path.h): the stepper
 * (ga_path_stepper_init/next) over evenly spaced times with the three
 * evaluators, DIRECT (eval.c), EULER (Li-Hao §5 in group form) and EXACT
 * (the product forms advanced by nested finite differences of their
 * exponents, re-anchored every GA_PATH_EXACT_REANCHOR samples), and the
 * batch calls ga_path_sample_uniform and ga_path_sample.
 */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include <garotor/path.h>

#include "internal/path.h"

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
    double v[GIP_MAXD], e[GIP_MAXE], tmp[GIP_MAXE];
    if (p->n == 1) { /* the constant path: its key, on every scheme */
        gip_copy_elem(g, out, gip_key_of(p, 0));
        return GA_OK;
    }
    if (*cur != seg || (double)*grid * h > u) {
        if (p->scheme == GA_SCHEME_BSPLINE) { /* the knot's pose, no key */
            if ((st = ga_path_eval_segment(p, seg, 0.0, A)))
                return st;
        } else
            gip_copy_elem(g, A, gip_key_of(p, seg));
        *grid = 0;
        *cur = seg;
    }
    /* eq. 32 in group form: A(u + h) = A(u) exp(h V(u)) */
    while ((double)(*grid + 1) * h <= u) {
        if ((st = gip_velocity_u(p, seg, (double)*grid * h, v)))
            return st;
        gip_lin(d, v, h, v, 0.0, v);
        if ((st = g->exp(v, e)))
            return st;
        g->compose(A, e, tmp);
        gip_copy_elem(g, A, tmp);
        ++*grid;
    }
    double r = u - (double)*grid * h;
    if (r > 0.0) {
        if ((st = gip_velocity_u(p, seg, (double)*grid * h, v)))
            return st;
        gip_lin(d, v, r, v, 0.0, v);
        if ((st = g->exp(v, e)))
            return st;
        g->compose(A, e, out);
    } else {
        gip_copy_elem(g, out, A);
    }
    return gip_finite_elem(g, out); /* a product of many steps can overflow */
}

/* ---- exact incremental stepping --------------------------------------------------- */

/* Slots of factor j start at j(j+3)/2: G_0 = exp(p(u) X), G_m = exp(D^m p(u) X)
 * for 0 < m < deg, then E = exp(D^deg p X), constant on a segment. Degrees 1,
 * 2, 3 use 2, 3, 4 slots. The key is folded into the first factor's G_0
 * (A_i exp(u B)), so SCREW costs one product per sample. */
static size_t slot_base(ga_scheme s, size_t j)
{
    size_t b = 0;
    for (size_t i = 0; i < j; ++i) b += gip_fac_deg(s, i) + 1;
    return b; /* Li-Hao: j (j + 3)/2; BSPLINE: 4 j */
}

static int exact_anchor(ga_path_stepper *s, size_t seg, double u)
{
    const ga_path *p = s->path;
    const ga_group *g = p->group;
    size_t d = g->dim, nf = gip_nfac(p->scheme);
    int st, newseg = seg != s->seg;
    double delta = s->dt / gip_seg_len(p, seg), x[GIP_MAXD], e[GIP_MAXE];
    const double *X = gip_seg_coef(p, seg);
    for (size_t j = 0; j < nf; ++j, X += d)
        for (size_t m = 0, deg = gip_fac_deg(p->scheme, j); m <= deg; ++m) {
            if (m == deg && !newseg)
                break; /* E is kept for the segment */
            gip_lin(d, x, gip_poly_diff(gip_fac_poly(p->scheme, j), m, u, delta), X, 0.0, X);
            if ((st = g->exp(x, m == 0 && j == 0 ? e : s->slot[slot_base(p->scheme, j) + m])))
                return st;
            if (m == 0 && j == 0)
                g->compose(gip_key_of(p, seg), e, s->slot[0]);
        }
    return GA_OK;
}

/* G_m <- G_m G_{m+1}, m = 0 .. deg-1, in that order (each uses the old G_{m+1}):
 * exp(D^m p(u+d) X) = exp(D^m p(u) X) exp(D^{m+1} p(u) X). */
static void exact_advance(ga_path_stepper *s)
{
    const ga_group *g = s->path->group;
    size_t nf = gip_nfac(s->path->scheme);
    double tmp[GIP_MAXE];
    for (size_t j = 0; j < nf; ++j)
        for (size_t m = 0, b = slot_base(s->path->scheme, j); m < gip_fac_deg(s->path->scheme, j); ++m) {
            double *a = s->slot[b + m];
            g->compose(a, s->slot[b + m + 1], tmp);
            gip_copy_elem(g, a, tmp);
        }
}

/* A_i F_1 F_2 F_3 with A_i F_1 in slot 0. */
static void exact_output(const ga_path_stepper *s, void *out)
{
    const ga_group *g = s->path->group;
    size_t nf = gip_nfac(s->path->scheme);
    double acc[GIP_MAXE], tmp[GIP_MAXE];
    if (nf == 1) {
        gip_copy_elem(g, out, s->slot[0]);
        return;
    }
    g->compose(s->slot[0], s->slot[slot_base(s->path->scheme, 1)], acc);
    if (nf == 3) {
        g->compose(acc, s->slot[slot_base(s->path->scheme, 2)], tmp);
        gip_copy_elem(g, acc, tmp);
    }
    gip_copy_elem(g, out, acc);
}

/* ---- samplers --------------------------------------------------------------------- */

ga_status ga_path_stepper_init(const ga_path *p, ga_eval ev, double step, size_t n, double t0, double t1,
                               ga_path_stepper *s)
{
    if (!s || !p || n < 1 || (unsigned)ev > GA_EVAL_EXACT)
        return GA_ERR_ARG;
    if (!isfinite(t0) || !isfinite(t1))
        return GA_ERR_NOTFINITE;
    if (!(t0 >= gip_knot(p, 0) && t1 <= gip_knot(p, gip_nseg(p)) && t0 <= t1))
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

/* DIRECT and EXACT samples of SCREW by the group's screw sampler: slot 0 is
 * the running sample A_i exp(u B) and slot 1 exp(dt/h B) (EXACT), slots 2
 * to 4 the sampler's preparation for segment s->seg, made whenever s->seg
 * changes. */
static int screw_next(ga_path_stepper *s, const gai_group_fast *f, size_t seg, double u, void *out)
{
    const ga_path *p = s->path;
    const ga_group *g = p->group;
    int newseg = seg != s->seg;
    if (newseg)
        f->screw_prep(gip_key_of(p, seg), gip_seg_coef(p, seg), s->slot[2], s->slot[3], s->slot[4]);
    s->seg = seg;
    if (s->eval == GA_EVAL_DIRECT) { /* as gip_eval_direct: the key itself at a key time */
        if (u == 0.0 || u == 1.0) {
            gip_copy_elem(g, out, gip_key_of(p, seg + (u == 1.0)));
            return GA_OK;
        }
        return f->screw_at(s->slot[2], s->slot[3], s->slot[4], u, out);
    }
    if (!newseg && s->since < GA_PATH_EXACT_REANCHOR) { /* as step.c's exact_advance */
        ++s->since;
        return f->screw_step(s->slot[0], s->slot[1], out); /* G_0 <- G_0 exp(dt/h B) */
    }
    /* as step.c's exact_anchor */
    int st = f->screw_at(s->slot[2], s->slot[3], s->slot[4], u, s->slot[0]);
    if (st == GA_OK && newseg) {
        double x[GIP_MAXD], delta = s->dt / gip_seg_len(p, seg);
        gip_lin(g->dim, x, gip_poly_diff(gip_fac_poly(p->scheme, 0), 1, u, delta), gip_seg_coef(p, seg), 0.0,
                gip_seg_coef(p, seg));
        st = g->exp(x, s->slot[1]);
    }
    s->since = 1;
    if (st == GA_OK) {
        gip_copy_elem(g, out, s->slot[0]);
        st = gip_finite_elem(g, s->slot[0]);
    }
    return st;
}

/* DIRECT and EXACT samples of DECOUPLED (no product form: EXACT is DIRECT):
 * slot 0 holds the constants of segment s->seg (gip_dec_prep), made whenever
 * s->seg changes; at a key time the key itself, as gip_eval_direct. */
_Static_assert(GIP_DEC_CONST <= GA_GROUP_MAX_ELEM, "a decoupled segment's constants fill one slot");
static int dec_next(ga_path_stepper *s, size_t seg, double u, void *out)
{
    const ga_path *p = s->path;
    if (seg != s->seg)
        gip_dec_prep(p, seg, s->slot[0]);
    s->seg = seg;
    if (u == 0.0 || u == 1.0) {
        gip_copy_elem(p->group, out, gip_key_of(p, seg + (u == 1.0)));
        return GA_OK;
    }
    return gip_dec_at(p, s->slot[0], u, out);
}

ga_status ga_path_stepper_next(ga_path_stepper *s, void *out)
{
    if (!s || !out || s->k >= s->n)
        return GA_ERR_ARG;
    const ga_path *p = s->path;
    double t = s->k + 1 == s->n ? s->t1 : s->t0 + (double)s->k * s->dt, u;
    size_t seg = s->seg;
    const gai_group_fast *f;
    int st;
    if (seg != SIZE_MAX && gip_knot(p, seg) <= t &&
        (t < gip_knot(p, seg + 1) || (seg + 1 == gip_nseg(p) && t == gip_knot(p, seg + 1)))) {
        /* the running segment again (t is inside [t_0, t_{n-1}] by the init):
           what ga_path_locate would find, without its search */
        u = (t - gip_knot(p, seg)) / gip_seg_len(p, seg);
    } else if ((st = ga_path_locate(p, t, &seg, &u))) {
        return st;
    }
    if (s->eval == GA_EVAL_EULER) {
        st = euler_sample(p, s->step, &s->seg, &s->grid, s->slot[0], seg, u, out);
    } else if ((f = gip_screw_fast(p))) {
        st = screw_next(s, f, seg, u, out);
    } else if (p->scheme == GA_SCHEME_DECOUPLED && p->n > 1) {
        st = dec_next(s, seg, u, out);
    } else if (s->eval == GA_EVAL_DIRECT || gip_nfac(p->scheme) == 0 || p->n == 1) {
        st = gip_eval_direct(p, seg, u, out);
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
            st = gip_finite_elem(p->group, out);
        }
    }
    /* DIRECT and EULER checked their own results (gip_finite_elem) */
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

/* ---- samples at given times ------------------------------------------------------ */

/* ga_path_sample takes its times in blocks: each block is located first, then
 * evaluated with the data of a later sample prefetched. A time in the segment
 * of the time before it (sorted times) needs no search; the others are
 * searched in lockstep, a level of every search at a time, without branches
 * on the knots: at random times the loads of the searches overlap and no
 * branch is mispredicted, where one search at a time waits for each level's
 * load in turn. The segments and u are ga_path_locate's exactly (the same
 * segment, u by the same expression), so the samples are ga_path_eval's bit
 * for bit in any order. */
#define SAMPLE_BLOCK 64
#define SAMPLE_AHEAD 8

#if defined(__GNUC__) || defined(__clang__)
#define STEP_PREFETCH(x) __builtin_prefetch(x)
#else
#define STEP_PREFETCH(x) ((void)(x))
#endif

/* In ga_path_range: NaN is not. */
static int in_range(const ga_path *p, double t)
{
    return t >= gip_knot(p, 0) && t <= gip_knot(p, gip_nseg(p));
}

/* 1 if t is in segment seg (< m, else 0) as ga_path_locate finds it: the
 * segment's start up to its end excluded, the last segment's included; the
 * comparisons combined without branches (at random times each is a toss) */
static int in_segment(const ga_path *p, size_t seg, double t)
{
    size_t m = gip_nseg(p);
    if (seg >= m)
        return 0;
    int last = seg + 1 == m;
    return (gip_knot(p, seg) <= t) & ((t < gip_knot(p, seg + 1)) | (last & (t == gip_knot(p, m))));
}

/* Segments and u of times[0..n) (n <= SAMPLE_BLOCK, all in range), as
 * ga_path_locate gives them; *hint is a segment found before (SIZE_MAX for
 * none), and becomes the last one's. */
static void locate_block(const ga_path *p, size_t n, const double *times, size_t *hint, size_t *seg,
                         double *u)
{
    size_t m = gip_nseg(p), h = *hint, todo[SAMPLE_BLOCK], nt = 0;
    if (m == 0) { /* the constant path: "segment 0" at u = 0 */
        for (size_t k = 0; k < n; ++k) seg[k] = 0, u[k] = 0.0;
        return;
    }
    for (size_t k = 0; k < n; ++k) { /* the last segment found, or the one after it */
        if (in_segment(p, h, times[k]))
            seg[k] = h;
        else if (h < m && in_segment(p, h + 1, times[k]))
            seg[k] = ++h;
        else
            todo[nt++] = k;
    }
    /* the largest i <= m - 1 with knot i <= t, as ga_path_locate's search,
       for all of todo at once, the next level's candidates asked for ahead */
    size_t lo[SAMPLE_BLOCK] = {0};
    double tt[SAMPLE_BLOCK];
    const double *knot = p->t + gip_knot_off(p);
    for (size_t j = 0; j < nt; ++j) tt[j] = times[todo[j]];
    for (size_t w = m; w > 1;) {
        size_t half = w / 2, next = (w - half) / 2;
        for (size_t j = 0; j < nt; ++j) {
            lo[j] += (size_t)(knot[lo[j] + half] <= tt[j]) * half;
            STEP_PREFETCH(knot + lo[j] + next);
        }
        w -= half;
    }
    for (size_t j = 0; j < nt; ++j) seg[todo[j]] = lo[j];
    for (size_t k = 0; k < n; ++k) u[k] = (times[k] - gip_knot(p, seg[k])) / gip_seg_len(p, seg[k]);
    *hint = seg[n - 1];
}

/* Ask for the lines of what evaluating on segment seg reads first: its
 * key, its coefficients (SCREW, Li-Hao: B_i[, C_i[, D_i]]), from the first
 * byte to the last. A macro: gcc 12 deletes the prefetches of a function
 * that does nothing else before it is inlined. */
#define PREFETCH_BYTES(a, n)                                                                                 \
    do {                                                                                                     \
        const char *a_ = (const char *)(a), *z_ = a_ + (n)-1;                                                \
        STEP_PREFETCH(a_);                                                                                   \
        if (((uintptr_t)a_ ^ (uintptr_t)z_) >= 64)                                                           \
            STEP_PREFETCH(z_);                                                                               \
    } while (0)
#define PREFETCH_SEGMENT(p, seg)                                                                             \
    do {                                                                                                     \
        PREFETCH_BYTES(gip_key_of(p, seg), (p)->group->elem_size);                                           \
        if (gip_nfac((p)->scheme) > 0 && (p)->scheme != GA_SCHEME_BSPLINE)                                   \
            PREFETCH_BYTES(gip_seg_coef(p, seg), gip_nfac((p)->scheme) * (p)->group->dim * sizeof(double));  \
    } while (0)

ga_status ga_path_sample(const ga_path *p, ga_eval ev, double step, size_t n, const double *times, void *out)
{
    if (!p || !times || !out || (unsigned)ev > GA_EVAL_EXACT)
        return GA_ERR_ARG;
    if (ev == GA_EVAL_EULER && !(step >= EULER_MIN_STEP && step <= 1.0))
        return GA_ERR_ARG;
    /* times [0, end) are located, into the ring seg, u (two blocks: the one
       evaluated and the next, whose data is asked for ahead); at end, where
       stop, a time outside the range */
    size_t cur = SIZE_MAX, grid = 0, hint = SIZE_MAX, end = 0, seg[2 * SAMPLE_BLOCK];
    double A[GIP_MAXE], u[2 * SAMPLE_BLOCK];
    int stop = 0;
    for (size_t k = 0; k < n; ++k) {
        /* the blocks of k and the next (end is a whole number of blocks) */
        while (!stop && end < n && end < k - k % SAMPLE_BLOCK + 2 * SAMPLE_BLOCK) {
            size_t nb = n - end < SAMPLE_BLOCK ? n - end : SAMPLE_BLOCK, good = 0,
                   r = end % (2 * SAMPLE_BLOCK);
            while (good < nb && in_range(p, times[end + good])) ++good;
            if (good > 0)
                locate_block(p, good, times + end, &hint, seg + r, u + r);
            if (end == 0 && gip_nseg(p) > 0)
                for (size_t j = 0; j < good && j < SAMPLE_AHEAD; ++j) PREFETCH_SEGMENT(p, seg[j]);
            stop = good < nb;
            end += good;
        }
        void *o = (unsigned char *)out + k * p->group->elem_size;
        size_t s;
        double uk;
        int st;
        if (k < end) {
            if (k + SAMPLE_AHEAD < end && gip_nseg(p) > 0)
                PREFETCH_SEGMENT(p, seg[(k + SAMPLE_AHEAD) % (2 * SAMPLE_BLOCK)]);
            s = seg[k % (2 * SAMPLE_BLOCK)];
            uk = u[k % (2 * SAMPLE_BLOCK)];
            st = GA_OK;
        } else /* outside the range or NaN: ga_path_locate's status */
            st = ga_path_locate(p, times[k], &s, &uk);
        if (st == GA_OK)
            st = ev == GA_EVAL_EULER ? euler_sample(p, step, &cur, &grid, A, s, uk, o)
                                     : gip_eval_direct(p, s, uk, o); /* both checked */
        if (st)
            return st;
    }
    return GA_OK;
}
