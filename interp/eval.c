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
    if (p->scheme == GA_SCHEME_DECOUPLED) { /* slerp and the chord from the segment's constants */
        double c[GIP_DEC_CONST];
        gip_dec_prep(p, seg, c);
        return gip_dec_at(p, c, u, out);
    }
    if (gip_is_decoupled(p->scheme))
        return gip_dec_eval(p, seg, u, out, NULL, NULL, NULL, NULL);
    if (p->scheme == GA_SCHEME_C2) { /* A_i exp(x(tau)) */
        double e[GIP_MAXE];
        gip_c2_curve(p, seg, u, x, NULL, NULL, NULL);
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
        if ((st = gip_dec_eval(p, seg, u, NULL, w, NULL, NULL, NULL)))
            return st;
        gip_lin(d, v, gip_seg_len(p, seg), w, 0.0, w);
        return GA_OK;
    }
    if (nf == 0) { /* J_r(X) X' (group.h dexp), X' per unit t, times h */
        if (p->scheme == GA_SCHEME_C2)
            gip_c2_curve(p, seg, u, x, xd, NULL, NULL);
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

/* ---- the acceleration and the jerk ------------------------------------------------ */

/* Body velocity, acceleration and (m = 3) jerk per unit u (u^2, u^3) on
 * segment seg, m = 2 or 3; v (may be NULL: not needed), a, and j where m
 * reaches it; pw (decoupled only, may be NULL): the position's world
 * derivatives per unit t. *a_t: set where a is per unit t already (the
 * curves through exp and DECOUPLED's, whose derivatives are per unit t: no
 * round trip through h^2), else cleared. */
static int derivs_u(const ga_path *p, size_t seg, double u, int m, double *v, double *a, double *j,
                    double *pw, int *a_t)
{
    *a_t = 0;
    const ga_group *g = p->group;
    size_t d = g->dim, nf = gip_nfac(p->scheme);
    double h = gip_seg_len(p, seg), vv[GIP_MAXD];
    int st;
    if (nf > 0)
        return gip_prod_derivs(p, seg, u, m, v ? v : vv, a, j);
    if (gip_is_decoupled(p->scheme)) {
        if ((st = gip_dec_eval(p, seg, u, NULL, v, a, m >= 3 ? j : NULL, pw)))
            return st;
        *a_t = p->scheme == GA_SCHEME_DECOUPLED;
    } else if (nf == 0) {
        double x0[GIP_MAXD], x1[GIP_MAXD], x2[GIP_MAXD], x3[GIP_MAXD];
        const double *xs[4] = {x0, x1, x2, x3};
        if (p->scheme == GA_SCHEME_C2) {
            gip_c2_curve(p, seg, u, x0, x1, x2, x3);
        } else {
            gip_gen_curve(p, seg, u, x0, x1);
            gip_gen_curve2(p, seg, u, x2);
            if (m >= 3)
                memset(x3, 0, d * sizeof(double)); /* X''' = 0: at most quadratic */
        }
        if ((st = gip_exp_curve_jet(g, xs, m, v, a, m >= 3 ? j : NULL)))
            return st;
        *a_t = 1;
    }
    if (v)
        gip_lin(d, v, h, v, 0.0, v);
    if (!*a_t)
        gip_lin(d, a, h * h, a, 0.0, a);
    if (m >= 3)
        gip_lin(d, j, h * h * h, j, 0.0, j);
    return GA_OK;
}

ga_status ga_path_acceleration_segment(const ga_path *p, size_t seg, double u, double *a)
{
    if (!p || !a || seg >= gip_nseg(p) || !isfinite(u))
        return GA_ERR_ARG;
    size_t d = p->group->dim;
    double v[GIP_MAXD], w[GIP_MAXD], h = gip_seg_len(p, seg);
    int a_t, st = derivs_u(p, seg, u, 2, v, w, NULL, NULL, &a_t);
    if (st != GA_OK)
        return st;
    if (!a_t)
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

static void cross_add(double s, const double *a, const double *b, double *o)
{
    o[0] += s * (a[1] * b[2] - a[2] * b[1]);
    o[1] += s * (a[2] * b[0] - a[0] * b[2]);
    o[2] += s * (a[0] * b[1] - a[1] * b[0]);
}
static void rot3(const ga_mat4 *m, const double *x, double *o)
{
    for (int i = 0; i < 3; ++i) o[i] = m->m[4 * i] * x[0] + m->m[4 * i + 1] * x[1] + m->m[4 * i + 2] * x[2];
}

/* The world frame (rigid groups) from the body derivatives (v, a, j: the
 * twists (W, V), (W', A), (W'', J)) and the pose (R, p): angular rate R W,
 * R W', R (W'' + W x W'); the position's derivatives p' = R V,
 * p'' = R (A + W x V), p''' = R (J + W' x V + W x A + W x (A + W x V))
 * (from d/dt R y = R (y' + W x y)); pw, where the scheme has them directly
 * (decoupled), the position's. */
static void to_world(const ga_mat4 *M, int m, const double *pw, double *v, double *a, double *j)
{
    double W[3], Wd[3], Wdd[3], V[3], A[3], J[3], y[3];
    memcpy(W, v, sizeof W);
    memcpy(V, v + 3, sizeof V);
    rot3(M, W, v);
    if (pw)
        memcpy(v + 3, pw, 3 * sizeof(double));
    else
        rot3(M, V, v + 3);
    if (m < 2)
        return;
    memcpy(Wd, a, sizeof Wd);
    memcpy(A, a + 3, sizeof A);
    rot3(M, Wd, a);
    memcpy(y, A, sizeof y); /* u = A + W x V */
    cross_add(1.0, W, V, y);
    if (pw)
        memcpy(a + 3, pw + 3, 3 * sizeof(double));
    else
        rot3(M, y, a + 3);
    if (m < 3)
        return;
    memcpy(Wdd, j, sizeof Wdd);
    memcpy(J, j + 3, sizeof J);
    double z[3] = {Wdd[0], Wdd[1], Wdd[2]}, q[3] = {J[0], J[1], J[2]};
    cross_add(1.0, W, Wd, z);
    rot3(M, z, j);
    cross_add(1.0, Wd, V, q);
    cross_add(1.0, W, A, q);
    cross_add(1.0, W, y, q);
    if (pw)
        memcpy(j + 3, pw + 6, 3 * sizeof(double));
    else
        rot3(M, q, j + 3);
}

ga_status ga_path_derivatives_segment(const ga_path *p, size_t seg, double u, ga_frame f, double *v,
                                      double *a, double *j)
{
    if (!p || seg >= gip_nseg(p) || !isfinite(u) || (unsigned)f > GA_FRAME_WORLD ||
        (f == GA_FRAME_WORLD && !p->group->rigid))
        return GA_ERR_ARG;
    const ga_group *g = p->group;
    size_t d = g->dim;
    int m = j ? 3 : a ? 2 : 1, st, a_t = 0;
    double vb[GIP_MAXD], ab[GIP_MAXD], jb[GIP_MAXD], h = gip_seg_len(p, seg), e[GIP_MAXE], pw[9];
    int dec = gip_is_decoupled(p->scheme), need_v = v || f != GA_FRAME_BODY;
    if (m == 1)
        st = gip_velocity_u(p, seg, u, vb);
    else /* the velocity where it is asked for or a frame needs it */
        st = derivs_u(p, seg, u, m, need_v ? vb : NULL, ab, jb, dec && f == GA_FRAME_WORLD ? pw : NULL, &a_t);
    if (st != GA_OK)
        return st;
    if (need_v)
        gip_lin(d, vb, 1.0 / h, vb, 0.0, vb);
    if (m >= 2 && !a_t)
        gip_lin(d, ab, 1.0 / (h * h), ab, 0.0, ab);
    if (m >= 3)
        gip_lin(d, jb, 1.0 / (h * h * h), jb, 0.0, jb);
    if (f != GA_FRAME_BODY) {
        if ((st = ga_path_eval_segment(p, seg, u, e)))
            return st;
    }
    if (f == GA_FRAME_SPATIAL) {
        /* spatial velocity Ad_M v_b; its derivative Ad_M (a_b + [v_b, v_b]) = Ad_M a_b;
           the next, Ad_M (j_b + [v_b, a_b]) */
        double vs[GIP_MAXD], as[GIP_MAXD], js[GIP_MAXD], c[GIP_MAXD];
        if (m >= 3) {
            if ((st = gip_bracket(g, vb, ab, c)))
                return st;
            gip_lin(d, c, 1.0, jb, 1.0, c);
            g->adjoint(e, c, js);
            memcpy(jb, js, sizeof js);
        }
        g->adjoint(e, vb, vs);
        memcpy(vb, vs, sizeof vs);
        if (m >= 2) {
            g->adjoint(e, ab, as);
            memcpy(ab, as, sizeof as);
        }
    } else if (f == GA_FRAME_WORLD) {
        ga_mat4 M = g->to_mat4(e);
        if (dec && m == 1 && (st = gip_dec_eval(p, seg, u, NULL, NULL, NULL, NULL, pw)))
            return st;
        to_world(&M, m, dec ? pw : NULL, vb, ab, jb);
    }
    if ((need_v && !gip_allfinite(vb, d)) || (m >= 2 && !gip_allfinite(ab, d)) ||
        (m >= 3 && !gip_allfinite(jb, d)))
        return GA_ERR_DOMAIN;
    if (v)
        memcpy(v, vb, d * sizeof(double));
    if (a)
        memcpy(a, ab, d * sizeof(double));
    if (j)
        memcpy(j, jb, d * sizeof(double));
    return GA_OK;
}

ga_status ga_path_derivatives(const ga_path *p, double t, ga_frame f, double *v, double *a, double *j)
{
    size_t seg;
    double u;
    if (!p || (unsigned)f > GA_FRAME_WORLD || (f == GA_FRAME_WORLD && !p->group->rigid))
        return GA_ERR_ARG;
    int st = ga_path_locate(p, t, &seg, &u);
    if (st != GA_OK)
        return st;
    if (p->n == 1) {
        size_t d = p->group->dim;
        if (v)
            memset(v, 0, d * sizeof(double));
        if (a)
            memset(a, 0, d * sizeof(double));
        if (j)
            memset(j, 0, d * sizeof(double));
        return GA_OK;
    }
    return ga_path_derivatives_segment(p, seg, u, f, v, a, j);
}

ga_status ga_path_differentiate_segment(const ga_path *p, size_t seg, double u, ga_frame f, double *v,
                                        double *a)
{
    double w[GIP_MAXD];
    if (!p)
        return GA_ERR_ARG;
    /* the acceleration always, as before: a velocity alone is ga_path_velocity's */
    return ga_path_derivatives_segment(p, seg, u, f, v, a ? a : w, NULL);
}

ga_status ga_path_differentiate(const ga_path *p, double t, ga_frame f, double *v, double *a)
{
    double w[GIP_MAXD];
    if (!p)
        return GA_ERR_ARG;
    return ga_path_derivatives(p, t, f, v, a ? a : w, NULL);
}
