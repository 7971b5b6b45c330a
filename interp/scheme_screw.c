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

/* A_i exp(u B) on segment seg by the group's screw sampler. */
int gip_screw_eval(const ga_path *p, const gai_group_fast *f, size_t seg, double u, void *out)
{
    double prep[3][GIP_MAXE];
    f->screw_prep(gip_key_of(p, seg), gip_seg_coef(p, seg), prep[0], prep[1], prep[2]);
    return f->screw_at(prep[0], prep[1], prep[2], u, out);
}
