/* interp/scheme_screw.c: SCREW (path.h; Li-Hao eqs. 8-10), A_i exp(u B_i)
 * with B_i = plog(A_i^-1 A_{i+1}), whose relative logs BSPLINE shares; and
 * the screw sampled by the group's own closed form where the group has one
 * (internal/group_fast.h): per segment a preparation, per sample no exp
 * and no product through the group's function pointers. Without it a screw
 * is one of the product forms (scheme_lihao.c, step.c).
 */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include <garotor/path.h>

#include "internal/group_fast.h"
#include "internal/path.h"

/* SCREW's B_i, and BSPLINE's d_i of path.h, the same relative logs. */
int gip_build_screw(ga_path *p)
{
    const ga_group *g = p->group;
    size_t n = p->n, d = g->dim;
    double rel[GIP_MAXE];
    int st;
    for (size_t i = 0; i + 1 < n; ++i)
        if ((st = gip_rel_log(g, gip_key_of(p, i), gip_key_of(p, i + 1), p->coef + i * d, rel)))
            return st;
    return GA_OK;
}

const gai_group_fast *gip_screw_fast(const ga_path *p)
{
    if (p->scheme != GA_SCHEME_SCREW || p->n < 2)
        return NULL;
    const gai_group_fast *f = gai_group_fast_of(p->group);
    return f && f->screw_prep && f->screw_at && f->screw_step ? f : NULL;
}

/* A_i exp(u B) on segment seg by the group's screw sampler. */
int gip_screw_eval(const ga_path *p, const gai_group_fast *f, size_t seg, double u, void *out)
{
    double prep[3][GIP_MAXE];
    f->screw_prep(gip_key_of(p, seg), gip_seg_coef(p, seg), prep[0], prep[1], prep[2]);
    return f->screw_at(prep[0], prep[1], prep[2], u, out);
}

/* DIRECT and EXACT samples of SCREW by the group's screw sampler: slot 0 is
 * the running sample A_i exp(u B) and slot 1 exp(dt/h B) (EXACT), slots 2
 * to 4 the sampler's preparation for segment s->seg, made whenever s->seg
 * changes. */
int gip_screw_next(ga_path_stepper *s, const gai_group_fast *f, size_t seg, double u, void *out)
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
