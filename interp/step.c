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

ga_status ga_path_sample(const ga_path *p, ga_eval ev, double step, size_t n, const double *times, void *out)
{
    if (!p || !times || !out || (unsigned)ev > GA_EVAL_EXACT)
        return GA_ERR_ARG;
    if (ev == GA_EVAL_EULER && !(step >= EULER_MIN_STEP && step <= 1.0))
        return GA_ERR_ARG;
    size_t cur = SIZE_MAX, grid = 0;
    double A[GIP_MAXE];
    for (size_t k = 0; k < n; ++k) {
        void *o = (unsigned char *)out + k * p->group->elem_size;
        size_t seg;
        double u;
        int st = ga_path_locate(p, times[k], &seg, &u);
        if (st == GA_OK)
            st = ev == GA_EVAL_EULER ? euler_sample(p, step, &cur, &grid, A, seg, u, o)
                                     : gip_eval_direct(p, seg, u, o); /* both checked */
        if (st)
            return st;
    }
    return GA_OK;
}
