/* interp/scheme_lihao.c: Li and Hao's product forms (path.h): building
 * LIHAO2 and LIHAO3 (Li-Hao eqs. 14-17, 21-28), and evaluating every
 * product A_i exp(p_1(u) X_1) exp(p_2(u) X_2) exp(p_3(u) X_3) (SCREW,
 * LIHAO2, LIHAO3, BSPLINE): the pose, the body velocity by the product rule
 * (eqs. 15, 25, 34) and the acceleration by the recursion of Sommer et al.
 * 2020.
 */
#include <math.h>
#include <string.h>

#include <garotor/path.h>

#include "internal/path.h"

/* LIHAO2 and LIHAO3 segment i from the velocity at key i (and LIHAO3: at key
 * i + 1); LIHAO2 writes the velocity at key i + 1. */
int gip_lihao_segment(ga_path *p, size_t i)
{
    const ga_group *g = p->group;
    size_t d = g->dim, nf = gip_nfac(p->scheme);
    double rel[GIP_MAXE], reli[GIP_MAXE], e[GIP_MAXE], m[GIP_MAXE], x[GIP_MAXD], ad[GIP_MAXD];
    int st;
    double h = gip_seg_len(p, i);
    double *B = p->coef + i * nf * d, *C = B + d, *D = C + d;
    const double *vi = p->vel + i * d;
    /* eq. 26: B_i = velocity at the key, per unit u */
    gip_lin(d, B, h, vi, 0.0, vi);
    if (!gip_allfinite(B, d))
        return GA_ERR_DOMAIN;
    /* eq. 16 (and 27 corrected): exp(B_i) exp(C_i) = A_i^-1 A_{i+1} */
    if ((st = gip_rel(g, gip_key_of(p, i), gip_key_of(p, i + 1), rel)))
        return st;
    gip_lin(d, x, -1.0, B, 0.0, B);
    if ((st = g->exp(x, e)))
        return st;
    g->compose(e, rel, m);
    if ((st = gip_plog(g, m, C)))
        return st;
    /* body velocity of exp(uB)exp(u^2 C) at u = 1: Ad_{rel^-1} B + 2 C (eqs. 15, 17) */
    if ((st = g->inverse(rel, reli)))
        return st;
    g->adjoint(reli, B, ad);
    const double *vn = p->vel + (i + 1) * d;
    if (p->scheme == GA_SCHEME_LIHAO2) /* eq. 17, per unit t: the next key's velocity */
        gip_lin(d, p->vel + (i + 1) * d, 1.0 / h, ad, 2.0 / h, C);
    else /* eq. 28: D_i = h V_{i+1} - Ad_{rel^-1} B_i - 2 C_i */
        for (size_t k = 0; k < d; ++k) D[k] = h * vn[k] - ad[k] - 2.0 * C[k];
    return GA_OK;
}

/* LIHAO2 (eqs. 14-17), LIHAO3 (eqs. 21-28), in u units on each segment:
 * B_i = h_i V_i where V_i is a velocity per unit t (SCREW, eq. 10, is
 * scheme_screw.c). */
int gip_build_lihao(ga_path *p, const double *vel)
{
    const ga_group *g = p->group;
    size_t n = p->n, d = g->dim;
    double rel[GIP_MAXE];
    int st;
    if (p->scheme == GA_SCHEME_LIHAO3) {
        if (vel) {
            if (!gip_allfinite(vel, n * d))
                return GA_ERR_NOTFINITE;
            memcpy(p->vel, vel, n * d * sizeof(double));
        } else {
            /* default rule (path.h): s_i = plog(A_i^-1 A_{i+1})/h_i, parked in D_i */
            for (size_t i = 0; i + 1 < n; ++i) {
                double *s = p->coef + (i * 3 + 2) * d;
                if ((st = gip_rel_log(g, gip_key_of(p, i), gip_key_of(p, i + 1), s, rel)))
                    return st;
                gip_lin(d, s, 1.0 / gip_seg_len(p, i), s, 0.0, s);
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
                    double hl = gip_seg_len(p, i - 1), hr = gip_seg_len(p, i);
                    gip_lin(d, v, hr / (hl + hr), sl, hl / (hl + hr), sr);
                }
            }
        }
    } else { /* LIHAO2: the first key's velocity */
        if (vel) {
            if (!gip_allfinite(vel, d))
                return GA_ERR_NOTFINITE;
            memcpy(p->vel, vel, d * sizeof(double));
        } else {
            if ((st = gip_rel_log(g, gip_key_of(p, 0), gip_key_of(p, 1), p->vel, rel)))
                return st;
            gip_lin(d, p->vel, 1.0 / gip_seg_len(p, 0), p->vel, 0.0, p->vel);
        }
    }
    /* finite input, but a default velocity plog/h or B = h V can overflow (a
       subnormal segment): GA_ERR_DOMAIN, not the GA_ERR_NOTFINITE exp would give */
    if (!gip_allfinite(p->vel, (p->scheme == GA_SCHEME_LIHAO3 ? n : 1) * d))
        return GA_ERR_DOMAIN;
    for (size_t i = 0; i + 1 < n; ++i)
        if ((st = gip_lihao_segment(p, i)))
            return st;
    return GA_OK;
}

/* ---- the product forms at u ---------------------------------------------------------
 * SCREW, LIHAO2, LIHAO3 and BSPLINE are products A_i F_1 F_2 F_3 of
 * factors F_j = exp(p_j(u) X_j) with fixed X_j on a segment (the factor
 * polynomials gip_fac_poly). */

int gip_prod_eval(const ga_path *p, size_t seg, double u, void *out)
{
    const ga_group *g = p->group;
    size_t d = g->dim, nf = gip_nfac(p->scheme);
    int st;
    double x[GIP_MAXD];
    /* A_i exp(p_1(u) B) exp(p_2(u) C) exp(p_3(u) D) (Li-Hao eqs. 8, 14, 21;
     * BSPLINE: A_s and the d_j with the cumulative basis), the partial
     * products alternating between two buffers, the last one composed
     * straight into out */
    double acc[2][GIP_MAXE], e[GIP_MAXE];
    const double *left = gip_key_of(p, seg), *X = gip_seg_coef(p, seg);
    for (size_t j = 0; j < nf; ++j, X += d) {
        gip_lin(d, x, gip_poly_diff(gip_fac_poly(p->scheme, j), 0, u, 0.0), X, 0.0, X);
        if ((st = g->exp(x, e)))
            return st;
        double *dst = j + 1 == nf ? out : acc[j & 1];
        g->compose(left, e, dst);
        left = dst;
    }
    /* a product of finite factors can still overflow: GA_ERR_DOMAIN, not Inf */
    return gip_finite_elem(g, out);
}

/* Body velocity per unit u. */
int gip_prod_velocity(const ga_path *p, size_t seg, double u, double *v)
{
    const ga_group *g = p->group;
    size_t d = g->dim, nf = gip_nfac(p->scheme);
    int st;
    double x[GIP_MAXD], w[GIP_MAXD];
    /* M = F_1 F_2 F_3, F_j = exp(p_j X_j): M^-1 M' = Ad_{F_3^-1}(Ad_{F_2^-1}(p_1' X_1)
     * + p_2' X_2) + p_3' X_3 (product rule; Li-Hao eqs. 15, 25, 34) */
    const double *X = gip_seg_coef(p, seg);
    for (size_t j = 0; j < nf; ++j, X += d) {
        const double *cp = gip_fac_poly(p->scheme, j);
        if (j > 0) {
            double fi[GIP_MAXE];
            gip_lin(d, x, -gip_poly_diff(cp, 0, u, 0.0), X, 0.0, X);
            if ((st = g->exp(x, fi)))
                return st;
            g->adjoint(fi, v, w);
        } else {
            for (size_t k = 0; k < d; ++k) w[k] = 0.0;
        }
        gip_lin(d, v, 1.0, w, gip_poly_deriv(cp, u), X);
    }
    return GA_OK;
}

/* Body velocity, acceleration and (m = 3) jerk per unit u (u^2, u^3); a and j
 * may be NULL where m does not reach them. */
int gip_prod_derivs(const ga_path *p, size_t seg, double u, int m, double *v, double *a, double *j)
{
    const ga_group *g = p->group;
    size_t d = g->dim, nf = gip_nfac(p->scheme);
    int st;
    /* M = F_1 F_2 F_3, F_j = exp(p_j X_j): with w_1 = p_1' X_1, a_1 = p_1'' X_1,
     * w_{j+1} = Ad_{F^-1} w_j + p' X, a_{j+1} = Ad_{F^-1} a_j + [Ad_{F^-1} w_j, p' X]
     * + p'' X (F = F_{j+1}, X = X_{j+1}): the product rule of gip_prod_velocity
     * differentiated once more, the recursion of Sommer et al. 2020 (eqs. for
     * the cumulative B-spline's acceleration); once more for the jerk, with
     * W = Ad_{F^-1} w_j, A = Ad_{F^-1} a_j and P_k = p^(k) X:
     * j_{j+1} = Ad_{F^-1} j_j + 2 [A, P_1] + [[W, P_1], P_1] + [W, P_2] + P_3 */
    const double *X = gip_seg_coef(p, seg);
    double w[GIP_MAXD], b[GIP_MAXD], c[GIP_MAXD], x[GIP_MAXD], fi[GIP_MAXE], aa[GIP_MAXD], jj[GIP_MAXD],
        jb[GIP_MAXD], t1[GIP_MAXD], t2[GIP_MAXD], x2[GIP_MAXD];
    if (!a)
        a = aa;
    if (!j)
        j = jj;
    for (size_t k = 0; k < d; ++k) v[k] = a[k] = j[k] = 0.0;
    for (size_t f = 0; f < nf; ++f, X += d) {
        const double *cp = gip_fac_poly(p->scheme, f);
        double d1 = gip_poly_deriv(cp, u), d2 = gip_poly_deriv2(cp, u), d3 = 6.0 * cp[3];
        if (f > 0) {
            gip_lin(d, x, -gip_poly_diff(cp, 0, u, 0.0), X, 0.0, X);
            if ((st = g->exp(x, fi)))
                return st;
            g->adjoint(fi, v, w);
            g->adjoint(fi, a, b);
            gip_lin(d, x, d1, X, 0.0, X);
            if ((st = gip_bracket(g, w, x, c)))
                return st;
            if (m >= 3) {
                /* j <- Ad j + 2 [A, P_1] + [[W, P_1], P_1] + [W, P_2] */
                gip_lin(d, x2, d2, X, 0.0, X);
                g->adjoint(fi, j, jb);
                if ((st = gip_bracket(g, b, x, t1)))
                    return st;
                gip_lin(d, jb, 1.0, jb, 2.0, t1);
                if ((st = gip_bracket(g, c, x, t1)) || (st = gip_bracket(g, w, x2, t2)))
                    return st;
                gip_lin(d, jb, 1.0, jb, 1.0, t1);
                gip_lin(d, j, 1.0, jb, 1.0, t2);
            }
            gip_lin(d, a, 1.0, b, 1.0, c);
            memcpy(v, w, d * sizeof(double));
        }
        gip_lin(d, v, 1.0, v, d1, X);
        gip_lin(d, a, 1.0, a, d2, X);
        if (m >= 3)
            gip_lin(d, j, 1.0, j, d3, X);
    }
    return GA_OK;
}
