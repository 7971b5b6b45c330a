/* interp/scheme_generator.c: the generator-space schemes (path.h), A(t) =
 * exp(X(t)) with X through the key generators X_i = plog(A_i) taken on the
 * branch that continues the previous key's (group.h branch; W-L §3):
 * BIVECTOR, X piecewise linear (W-L §3.3); QUADRATIC and SMOOTH, X the
 * not-a-knot C1 quadratic spline (W-L §3.2 and Cendes-Wong). X, X' and X''
 * at u; their pose and derivatives are eval.c's.
 */
#include <math.h>
#include <string.h>

#include <garotor/path.h>

#include "internal/path.h"

/* Key generators with the branch rule of path.h (W-L §3: the group's branch
 * rule, group.h). */
int gip_build_generators(ga_path *p)
{
    const ga_group *g = p->group;
    size_t d = g->dim;
    int st;
    for (size_t i = 0; i < p->n; ++i) {
        double *x = p->gen + i * d;
        if ((st = gip_plog(g, gip_key_of(p, i), x)))
            return st;
        if (g->branch && i > 0)
            g->branch(x - d, x);
    }
    return GA_OK;
}

/* Breakpoints of the SMOOTH spline: xi_0 = t_0, xi_k = (t_k + t_{k+1})/2 for
 * 1 <= k <= n-3, xi_{n-2} = t_{n-1}. */
static double brk(const ga_path *p, size_t k)
{
    if (k == 0)
        return p->t[0];
    if (k == p->n - 2)
        return p->t[p->n - 1];
    return 0.5 * (p->t[k] + p->t[k + 1]);
}

/* The slopes d_k = X'(xi_k) of the SMOOTH spline (path.h). X' is linear on
 * each piece [xi_k, xi_{k+1}], and for each segment j the integral of X' over
 * [t_j, t_{j+1}] (trapezoids on the at most two pieces it meets) must equal
 * X_{j+1} - X_j. Row j, divided by h_j/2 (alpha, beta, gamma, delta: where
 * t_j, t_{j+1} fall in their pieces, each in (0, 1)):
 *   j = 0:        (2 - g) d_0 + g d_1                         = 2 dX_0/h_0
 *   0 < j < n-2:  (1-a)/2 d_{j-1} + (3+a-b)/2 d_j + b/2 d_{j+1} = 2 dX_j/h_j
 *   j = n-2:      (1 - e) d_{n-3} + (1 + e) d_{n-2}           = 2 dX_j/h_j
 * Each row is strictly diagonally dominant, so the Thomas algorithm is stable. */
void gip_build_smooth(ga_path *p)
{
    size_t n = p->n, d = p->group->dim, m = n - 1;
    double *cp = p->slope + m * d; /* scratch: the modified upper diagonal */
    for (size_t j = 0; j < m; ++j) {
        double h = gip_seg_len(p, j), lo, di, up;
        if (j == 0) {
            double gam = h / (brk(p, 1) - brk(p, 0));
            lo = 0.0;
            di = 2.0 - gam;
            up = gam;
        } else if (j == n - 2) {
            double del = (p->t[n - 2] - brk(p, n - 3)) / (brk(p, n - 2) - brk(p, n - 3));
            lo = 1.0 - del;
            di = 1.0 + del;
            up = 0.0;
        } else {
            double al = (p->t[j] - brk(p, j - 1)) / (brk(p, j) - brk(p, j - 1));
            double be = (p->t[j + 1] - brk(p, j)) / (brk(p, j + 1) - brk(p, j));
            lo = 0.5 * (1.0 - al);
            di = 0.5 * (3.0 + al - be);
            up = 0.5 * be;
        }
        double *r = p->slope + j * d;
        const double *x0 = p->gen + j * d, *x1 = x0 + d;
        for (size_t k = 0; k < d; ++k) r[k] = 2.0 * (x1[k] - x0[k]) / h;
        if (j > 0) {
            const double *rp = r - d; /* the previous row (an index k - d would wrap: k is unsigned) */
            di -= lo * cp[j - 1];
            for (size_t k = 0; k < d; ++k) r[k] -= lo * rp[k];
        }
        cp[j] = up / di;
        for (size_t k = 0; k < d; ++k) r[k] /= di;
    }
    for (size_t j = m - 1; j-- > 0;) {
        double *r = p->slope + j * d;
        for (size_t k = 0; k < d; ++k) r[k] -= cp[j] * r[k + d];
    }
}

/* X(t) and X'(t) (per unit t) of the generator-space schemes on segment j. */
void gip_gen_curve(const ga_path *p, size_t j, double u, double *x, double *xd)
{
    size_t d = p->group->dim, n = p->n;
    double h = gip_seg_len(p, j);
    const double *x0 = p->gen + j * d, *x1 = x0 + d;
    if (p->scheme == GA_SCHEME_BIVECTOR) { /* W-L §3: linear in the generators */
        gip_lin(d, x, 1.0 - u, x0, u, x1);
        gip_lin(d, xd, 1.0 / h, x1, -1.0 / h, x0);
        return;
    }
    /* SMOOTH / QUADRATIC: from the nearer key a of the segment, inside one
     * piece k where X' is linear: X(t) = X_a + (t - t_a)(X'(t_a) + X'(t))/2. */
    int left = u <= 0.5;
    size_t k = j == 0 ? 0 : j == n - 2 ? n - 3 : left ? j - 1 : j;
    size_t a = left ? j : j + 1;
    double tau = left ? u * h : (u - 1.0) * h;
    double xk = brk(p, k), L = brk(p, k + 1) - xk;
    double fa = (p->t[a] - xk) / L, ft = (p->t[a] + tau - xk) / L;
    const double *dk = p->slope + k * d, *dk1 = dk + d, *xa = p->gen + a * d;
    for (size_t i = 0; i < d; ++i) {
        double sa = dk[i] + (dk1[i] - dk[i]) * fa, st = dk[i] + (dk1[i] - dk[i]) * ft;
        x[i] = xa[i] + tau * 0.5 * (sa + st);
        xd[i] = st;
    }
}

/* X''(t) (per unit t^2) of the generator-space schemes on segment j at u:
 * 0 for BIVECTOR; the slope of X' on its piece for SMOOTH/QUADRATIC (the
 * piece gip_gen_curve uses). */
void gip_gen_curve2(const ga_path *p, size_t j, double u, double *xdd)
{
    size_t d = p->group->dim, n = p->n;
    if (p->scheme == GA_SCHEME_BIVECTOR) {
        for (size_t i = 0; i < d; ++i) xdd[i] = 0.0;
        return;
    }
    int left = u <= 0.5;
    size_t k = j == 0 ? 0 : j == n - 2 ? n - 3 : left ? j - 1 : j;
    double L = brk(p, k + 1) - brk(p, k);
    const double *dk = p->slope + k * d, *dk1 = dk + d;
    for (size_t i = 0; i < d; ++i) xdd[i] = (dk1[i] - dk[i]) / L;
}
