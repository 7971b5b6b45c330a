/* interp/eval.c: the closed-form evaluators of path.h: the pose
 * (ga_path_eval), the body velocity and the acceleration (ga_path_velocity,
 * ga_path_acceleration, ga_path_differentiate), each dispatching to the
 * scheme's curve: the product forms (scheme_lihao.c), the generator-space
 * and C2 curves through exp, dexp and the 4x4 jet (jet.c), the decoupled
 * pair.
 */
#include <math.h>
#include <string.h>

#include <garotor/path.h>

#include "internal/path.h"

/* ---- the pose --------------------------------------------------------------------- */

ga_status ga_path_eval_segment(const ga_path *p, size_t seg, double u, void *out)
{
    if (!p || !out || seg >= gip_nseg(p) || !isfinite(u))
        return GA_ERR_ARG;
    const ga_group *g = p->group;
    size_t nf = gip_nfac(p->scheme);
    int st;
    double x[GIP_MAXD], xd[GIP_MAXD];
    const gai_group_fast *f = gip_screw_fast(p);
    if (f) /* the group's own screw sampler */
        return gip_screw_eval(p, f, seg, u, out);
    if (gip_is_decoupled(p->scheme))
        return gip_dec_eval(p, seg, u, out, NULL, NULL);
    if (p->scheme == GA_SCHEME_C2) { /* A_i exp(x(tau)) */
        double e[GIP_MAXE];
        gip_c2_curve(p, seg, u, x, NULL, NULL);
        if ((st = g->exp(x, e)))
            return st;
        g->compose(gip_key_of(p, seg), e, out);
        return gip_finite_elem(g, out);
    }
    if (nf == 0) { /* exp(X(t)) */
        gip_gen_curve(p, seg, u, x, xd);
        return g->exp(x, out);
    }
    return gip_prod_eval(p, seg, u, out);
}

/* DIRECT at (seg, u): at a key time the key itself, not its rounding (not
 * BSPLINE, whose knots are no keys; its one-key path is the key). */
int gip_eval_direct(const ga_path *p, size_t seg, double u, void *out)
{
    if ((u == 0.0 || u == 1.0) && (p->scheme != GA_SCHEME_BSPLINE || p->n == 1)) {
        gip_copy_elem(p->group, out, gip_key_of(p, seg + (u == 1.0)));
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
    return st ? st : gip_eval_direct(p, seg, u, out);
}

/* ---- the body velocity ------------------------------------------------------------ */

/* Body velocity per unit u on segment seg. */
int gip_velocity_u(const ga_path *p, size_t seg, double u, double *v)
{
    const ga_group *g = p->group;
    size_t d = g->dim, nf = gip_nfac(p->scheme);
    int st;
    double x[GIP_MAXD], xd[GIP_MAXD], w[GIP_MAXD];
    if (gip_is_decoupled(p->scheme)) {
        if ((st = gip_dec_eval(p, seg, u, NULL, w, NULL)))
            return st;
        gip_lin(d, v, gip_seg_len(p, seg), w, 0.0, w);
        return GA_OK;
    }
    if (nf == 0) { /* J_r(X) X' (group.h dexp), X' per unit t, times h */
        if (p->scheme == GA_SCHEME_C2)
            gip_c2_curve(p, seg, u, x, xd, NULL);
        else
            gip_gen_curve(p, seg, u, x, xd);
        g->dexp(x, xd, w);
        gip_lin(d, v, gip_seg_len(p, seg), w, 0.0, w);
        return GA_OK;
    }
    return gip_prod_velocity(p, seg, u, v);
}

ga_status ga_path_velocity_segment(const ga_path *p, size_t seg, double u, double *v)
{
    if (!p || !v || seg >= gip_nseg(p) || !isfinite(u))
        return GA_ERR_ARG;
    size_t d = p->group->dim;
    double w[GIP_MAXD];
    int st = gip_velocity_u(p, seg, u, w);
    if (st != GA_OK)
        return st;
    gip_lin(d, w, 1.0 / gip_seg_len(p, seg), w, 0.0, w);
    if (!gip_allfinite(w, d))
        return GA_ERR_DOMAIN; /* see gip_finite_elem */
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

/* ---- the acceleration ------------------------------------------------------------- */

/* Body velocity and acceleration per unit u (u^2) on segment seg. */
static int accel_u(const ga_path *p, size_t seg, double u, double *v, double *a)
{
    const ga_group *g = p->group;
    size_t d = g->dim, nf = gip_nfac(p->scheme);
    double h = gip_seg_len(p, seg);
    int st;
    if (gip_is_decoupled(p->scheme)) {
        if ((st = gip_dec_eval(p, seg, u, NULL, v, a)))
            return st;
        gip_lin(d, v, h, v, 0.0, v);
        gip_lin(d, a, h * h, a, 0.0, a);
        return GA_OK;
    }
    if (nf == 0) {
        double x[GIP_MAXD], xd[GIP_MAXD], xdd[GIP_MAXD] = {0};
        if (p->scheme == GA_SCHEME_C2) {
            gip_c2_curve(p, seg, u, x, xd, xdd);
        } else {
            gip_gen_curve(p, seg, u, x, xd);
            gip_gen_curve2(p, seg, u, xdd);
        }
        if ((st = gip_exp_curve_deriv(g, x, xd, xdd, v, a)))
            return st;
        gip_lin(d, v, h, v, 0.0, v);
        gip_lin(d, a, h * h, a, 0.0, a);
        return GA_OK;
    }
    return gip_prod_accel(p, seg, u, v, a);
}

ga_status ga_path_acceleration_segment(const ga_path *p, size_t seg, double u, double *a)
{
    if (!p || !a || seg >= gip_nseg(p) || !isfinite(u))
        return GA_ERR_ARG;
    size_t d = p->group->dim;
    double v[GIP_MAXD], w[GIP_MAXD], h = gip_seg_len(p, seg);
    int st = accel_u(p, seg, u, v, w);
    if (st != GA_OK)
        return st;
    gip_lin(d, w, 1.0 / (h * h), w, 0.0, w);
    if (!gip_allfinite(w, d))
        return GA_ERR_DOMAIN;
    memcpy(a, w, d * sizeof(double));
    return GA_OK;
}

ga_status ga_path_acceleration(const ga_path *p, double t, double *a)
{
    return a ? ga_path_differentiate(p, t, GA_FRAME_BODY, NULL, a) : GA_ERR_ARG;
}

ga_status ga_path_differentiate_segment(const ga_path *p, size_t seg, double u, ga_frame f, double *v,
                                        double *a)
{
    if (!p || seg >= gip_nseg(p) || !isfinite(u) || (unsigned)f > GA_FRAME_SPATIAL)
        return GA_ERR_ARG;
    const ga_group *g = p->group;
    size_t d = g->dim;
    double vb[GIP_MAXD], ab[GIP_MAXD], h = gip_seg_len(p, seg), m[GIP_MAXE];
    int st = accel_u(p, seg, u, vb, ab);
    if (st != GA_OK)
        return st;
    gip_lin(d, vb, 1.0 / h, vb, 0.0, vb);
    gip_lin(d, ab, 1.0 / (h * h), ab, 0.0, ab);
    if (f == GA_FRAME_SPATIAL) {
        /* spatial velocity Ad_M v_b; its derivative Ad_M (a_b + [v_b, v_b]) = Ad_M a_b */
        double vs[GIP_MAXD], as[GIP_MAXD];
        if ((st = ga_path_eval_segment(p, seg, u, m)))
            return st;
        g->adjoint(m, vb, vs);
        g->adjoint(m, ab, as);
        memcpy(vb, vs, sizeof vs);
        memcpy(ab, as, sizeof as);
    }
    if (!gip_allfinite(vb, d) || !gip_allfinite(ab, d))
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
