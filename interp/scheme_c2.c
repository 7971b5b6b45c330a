/* interp/scheme_c2.c: C2 (path.h), A_i exp(x(t - t_i)) with x a cubic in the
 * twist, C2 at the keys through the group's right Jacobian (dexp) and the
 * 4x4 jet of the acceleration (jet.c); the key velocities solve the system
 * of c2_solve.c.
 */
#include <math.h>
#include <string.h>

#include <garotor/path.h>

#include "internal/path.h"

/* C2 (path.h): on segment i, A_i exp(x(tau)), x(tau) = a tau + b tau^2 +
 * c tau^3 in coef (t units), the key velocities in vel solved by gip_c2_solve
 * through the group (J_r by dexp, N by the 4x4 jet), then per key the
 * solver's scratch. theta_i = plog(A_i^-1 A_{i+1}) is parked in slot c. */
static const double *c2_theta(const ga_path *p, size_t i) { return p->coef + (3 * i + 2) * p->group->dim; }
static double *c2_rate(const ga_path *p, size_t i) { return p->vel + i * p->group->dim; }
static double *c2_scratch(const ga_path *p, size_t i)
{
    size_t d = p->group->dim;
    return p->vel + p->n * d + i * (d * d + d);
}
static double *c2_jcache(const ga_path *p, size_t i)
{
    size_t d = p->group->dim;
    return p->vel + p->n * d + p->n * (d * d + d) + i * d * d;
}
/* The inverse of a twist group's J_r = [[A, 0], [Q, A]] (A = SO(3)'s J_r of
 * the rotation, row-major 6 x 6): [[A^-1, 0], [-A^-1 Q A^-1, A^-1]], A^-1 by
 * its adjugate; GA_ERR_DOMAIN where A is singular (a turn of 2 pi k). */
static int c2_jinv(size_t d, const double *J, double *o)
{
    double A[9], Q[9], Ai[9], T[9], B[9];
    (void)d;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            A[3 * i + j] = J[6 * i + j];
            Q[3 * i + j] = J[6 * (i + 3) + j];
        }
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) { /* the cofactor of A[j][i] */
            int r0 = (j + 1) % 3, r1 = (j + 2) % 3, c0 = (i + 1) % 3, c1 = (i + 2) % 3;
            Ai[3 * i + j] = A[3 * r0 + c0] * A[3 * r1 + c1] - A[3 * r0 + c1] * A[3 * r1 + c0];
        }
    double det = A[0] * Ai[0] + A[1] * Ai[3] + A[2] * Ai[6];
    if (!(fabs(det) > 0) || !isfinite(det))
        return GA_ERR_DOMAIN;
    for (int k = 0; k < 9; ++k) Ai[k] /= det;
    gip_md_mul(3, Q, Ai, T);
    gip_md_mul(3, Ai, T, B);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            o[6 * i + j] = Ai[3 * i + j];
            o[6 * i + j + 3] = 0.0;
            o[6 * (i + 3) + j] = -B[3 * i + j];
            o[6 * (i + 3) + j + 3] = Ai[3 * i + j];
        }
    return GA_OK;
}
static int c2_jr(const ga_path *p, const double *th, int inv, double *m)
{
    const ga_group *g = p->group;
    size_t d = g->dim;
    double e[GIP_MAXD] = {0}, c[GIP_MAXD], J[GIP_MAXD * GIP_MAXD];
    for (size_t j = 0; j < d; ++j) {
        e[j] = 1.0;
        g->dexp(th, e, c);
        e[j] = 0.0;
        for (size_t i = 0; i < d; ++i) J[d * i + j] = c[i];
    }
    if (inv)
        return c2_jinv(d, J, m);
    memcpy(m, J, d * d * sizeof(double));
    return GA_OK;
}
/* N(theta, y) = (d/dt J_r(x)) x' at x = theta, x' = y: the body
 * acceleration of exp(x(t)) with x'' = 0, in closed form (twist_deriv.c). */
static int c2_nonlin(const ga_path *p, const double *th, const double *y, double *o)
{
    const double zero[GIP_MAXD] = {0};
    const double *xs[4] = {th, y, zero, zero};
    (void)p;
    gip_twist_exp_derivs(xs, 2, NULL, o, NULL);
    return GA_OK;
}

/* the ends: the screw velocities theta/h of the end segments (each a body
   velocity at both its ends); the interior, to start: lihao3's default (the
   parabola through the neighbouring screw velocities) */
static void c2_start(ga_path *p)
{
    size_t n = p->n, d = p->group->dim;
    for (size_t i = 0; i < n; ++i) {
        double *v = c2_rate(p, i);
        if (i == 0 || i + 1 == n) {
            size_t j = i ? i - 1 : 0;
            gip_lin(d, v, 1.0 / gip_seg_len(p, j), c2_theta(p, j), 0.0, v);
        } else {
            double hl = gip_seg_len(p, i - 1), hr = gip_seg_len(p, i);
            gip_lin(d, v, hr / ((hl + hr) * hl), c2_theta(p, i - 1), hl / ((hl + hr) * hr), c2_theta(p, i));
        }
    }
}

int gip_build_c2(ga_path *p)
{
    const ga_group *g = p->group;
    size_t n = p->n, d = g->dim;
    double rel[GIP_MAXE], J[GIP_MAXD * GIP_MAXD], e[GIP_MAXD];
    int st;
    memset(p->coef, 0, gip_scheme_doubles(p->scheme, n, d) * sizeof(double));
    for (size_t i = 0; i + 1 < n; ++i)
        if ((st = gip_rel_log(g, gip_key_of(p, i), gip_key_of(p, i + 1), p->coef + (3 * i + 2) * d, rel)))
            return st;
    c2_start(p);
    if (!gip_allfinite(p->vel, n * d))
        return GA_ERR_DOMAIN;
    if (n > 2) {
        gip_c2_sys sys = {p,     d,         c2_theta, c2_rate,   c2_scratch,
                          c2_jr, c2_nonlin, c2_start, c2_jcache, c2_jinv};
        if ((st = gip_c2_solve(&sys)))
            return st;
    }
    /* Hermite: a = w_i, x'(h) = J_r^-1(theta) w_{i+1},
       b = (3 theta - 2h a - h x'(h))/h^2, c = (-2 theta + h a + h x'(h))/h^3 */
    for (size_t i = 0; i + 1 < n; ++i) {
        double *A = p->coef + 3 * i * d, *B = A + d, *C = B + d, th[GIP_MAXD], h = gip_seg_len(p, i);
        const double *w = c2_rate(p, i);
        memcpy(th, C, d * sizeof(double));
        if ((st = n > 2 ? c2_jinv(d, c2_jcache(p, i), J) : c2_jr(p, th, 1, J)))
            return st;
        gip_md_vec(d, J, c2_rate(p, i + 1), e);
        for (size_t k = 0; k < d; ++k) {
            A[k] = w[k];
            B[k] = (3.0 * th[k] - 2.0 * h * w[k] - h * e[k]) / (h * h);
            C[k] = (-2.0 * th[k] + h * w[k] + h * e[k]) / (h * h * h);
        }
    }
    return GA_OK;
}

/* x(tau), x'(tau), x''(tau), x'''(tau) of C2 segment seg at u (tau = u h,
 * per unit t); xd, xdd, xddd may be NULL. */
void gip_c2_curve(const ga_path *p, size_t seg, double u, double *x, double *xd, double *xdd, double *xddd)
{
    size_t d = p->group->dim;
    const double *A = p->coef + 3 * seg * d, *B = A + d, *C = B + d;
    double tau = u * gip_seg_len(p, seg);
    for (size_t k = 0; k < d; ++k) {
        x[k] = ((C[k] * tau + B[k]) * tau + A[k]) * tau;
        if (xd)
            xd[k] = (3.0 * C[k] * tau + 2.0 * B[k]) * tau + A[k];
        if (xdd)
            xdd[k] = 6.0 * C[k] * tau + 2.0 * B[k];
        if (xddd)
            xddd[k] = 6.0 * C[k];
    }
}
