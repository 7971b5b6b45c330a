/* interp/c2_solve.c: the C2 system of key velocities (path.h, C2 and
 * DECOUPLED_C2), block-tridiagonal and nonlinear, by Newton sweeps of block
 * Thomas and, where they stall, continuation; and the d x d matrix helpers
 * it needs.
 */
#include <float.h>
#include <math.h>
#include <string.h>

#include <garotor/path.h>

#include "internal/path.h"

/* ---- d x d matrices (d <= GIP_MAXD, row-major) ------------------------------------ */

void gip_md_mul(size_t d, const double *a, const double *b, double *o)
{
    double t[GIP_MAXD * GIP_MAXD];
    for (size_t i = 0; i < d; ++i)
        for (size_t j = 0; j < d; ++j) {
            double s = 0.0;
            for (size_t k = 0; k < d; ++k) s += a[d * i + k] * b[d * k + j];
            t[d * i + j] = s;
        }
    memcpy(o, t, d * d * sizeof(double));
}
void gip_md_vec(size_t d, const double *a, const double *x, double *o)
{
    double t[GIP_MAXD];
    for (size_t i = 0; i < d; ++i) {
        double s = 0.0;
        for (size_t k = 0; k < d; ++k) s += a[d * i + k] * x[k];
        t[i] = s;
    }
    memcpy(o, t, d * sizeof(double));
}
/* o = a^-1 by Gauss-Jordan elimination with partial pivoting; GA_ERR_DOMAIN
 * for a matrix singular to working precision (or not finite) */
int gip_md_inv(size_t d, const double *a, double *o)
{
    double m[GIP_MAXD * GIP_MAXD], r[GIP_MAXD * GIP_MAXD];
    memcpy(m, a, d * d * sizeof(double));
    for (size_t i = 0; i < d * d; ++i) r[i] = (i % (d + 1) == 0);
    for (size_t c = 0; c < d; ++c) {
        size_t pv = c;
        for (size_t i = c + 1; i < d; ++i)
            if (fabs(m[d * i + c]) > fabs(m[d * pv + c]))
                pv = i;
        double piv = m[d * pv + c];
        if (!(fabs(piv) > 0) || !isfinite(piv))
            return GA_ERR_DOMAIN;
        for (size_t j = 0; j < d; ++j) {
            double x = m[d * c + j], y = r[d * c + j];
            m[d * c + j] = m[d * pv + j];
            r[d * c + j] = r[d * pv + j];
            m[d * pv + j] = x;
            r[d * pv + j] = y;
            m[d * c + j] /= piv;
            r[d * c + j] /= piv;
        }
        for (size_t i = 0; i < d; ++i) {
            double f = m[d * i + c];
            if (i == c || f == 0.0)
                continue;
            for (size_t j = 0; j < d; ++j) {
                m[d * i + j] -= f * m[d * c + j];
                r[d * i + j] -= f * r[d * c + j];
            }
        }
    }
    memcpy(o, r, d * d * sizeof(double));
    return GA_OK;
}

/* The C2 system of key velocities, shared by DECOUPLED_C2 (the rotation
 * vector, d = 3, SO(3)'s closed forms) and C2 (the twist, d = g->dim, through
 * the group's dexp and the 4x4 jet). On segment i the motion is
 * exp(x(tau)), x a cubic with x(0) = 0, x(h_i) = theta_i, x'(0) = w_i and
 * J_r(theta_i) x'(h_i) = w_{i+1}; its body acceleration is
 * J_r(x) x'' + N(x, x'), N = (d/dt J_r(x)) x'. Row k (interior key): the
 * accelerations of segments k-1 (at its end) and k (at its start) equal,
 *   2/h_{k-1} J_r(theta_{k-1}) w_{k-1} + (4/h_{k-1} + 4/h_k) w_k
 *     + 2/h_k J_r^-1(theta_k) w_{k+1}
 *   = 6 theta_{k-1}/h_{k-1}^2 + 6 theta_k/h_k^2 - N(theta_{k-1}, J_r^-1(theta_{k-1}) w_k)
 * (scipy's RotationSpline._solve_for_angular_rates for SO(3), which iterates
 * it as a fixed point, 10 sweeps at most). Each sweep here linearises N at
 * the current rates (Newton) and solves the block-tridiagonal system by block
 * Thomas (without N it is block diagonally dominant: |J_r| <= 1,
 * |J_r^-1| <= pi/2 on SO(3)); the full Newton step is taken (halving steps
 * that raise the largest residual failed more often: docs/schemes.md). At
 * most C2_SWEEPS; converged when no rate moves by more than 4 DBL_EPSILON of the
 * largest, or the change stops shrinking once it is below 1e-12 of it, or
 * (quadratic convergence) it is below 1e-10 of it and 1e-3 of the change
 * before. Each sweep is O(n), and the count of sweeps does not grow with n
 * (docs/numerics.md, "c2: the solver"). The Jacobians J_r(theta_i) are formed
 * once (jcache), their inverses by blocks each sweep (jinv). Where that
 * fails, continuation
 * (gip_c2_solve). */
#define C2_SWEEPS 200
#define C2_CONTINUATION_SWEEPS 1200 /* all the continuation's sweeps together */

/* Newton sweeps on the system with N scaled by lam (1: the system itself),
 * from the current rates, at most *budget of them (counted down). GA_OK
 * when converged: to the rule above when final, else to 1e-9 of the
 * largest rate (a start for the next lam). */
static int c2_newton(const gip_c2_sys *s, double lam, int final, int *budget)
{
    ga_path *p = s->p;
    size_t n = p->n, d = s->d, dd = d * d;
    double prev = INFINITY;
    int st;
    for (; *budget > 0; --*budget) {
        double big = 0.0, delta = 0.0;
        for (size_t k = 1; k + 1 < n; ++k) {
            const double *tl = s->theta(p, k - 1), *tr = s->theta(p, k);
            double hl = gip_seg_len(p, k - 1), hr = gip_seg_len(p, k);
            double L[GIP_MAXD * GIP_MAXD], U[GIP_MAXD * GIP_MAXD], D[GIP_MAXD * GIP_MAXD],
                Ji[GIP_MAXD * GIP_MAXD], Jn[GIP_MAXD * GIP_MAXD];
            double rhs[GIP_MAXD], rde[GIP_MAXD], nl[GIP_MAXD], t3[GIP_MAXD], jw[GIP_MAXD], sc = 0.0;
            double *C = s->scratch(p, k), *y = C + dd;
            const double *wk = s->rate(p, k);
            if (s->jcache) {
                memcpy(L, s->jcache(p, k - 1), dd * sizeof(double));
                if ((st = s->jinv(d, L, Ji)) || (st = s->jinv(d, s->jcache(p, k), U)))
                    return st;
            } else if ((st = s->jr(p, tl, 0, L)) || (st = s->jr(p, tr, 1, U)) || (st = s->jr(p, tl, 1, Ji)))
                return st;

            /* N(theta_{k-1}, J_r^-1(theta_{k-1}) w_k), linearised at the current
               w_k: N + Jn (w - w_k), Jn = dN/dr' J_r^-1, dN/dr' by polarisation
               (N is quadratic in r': dN/dr' e = (N(r' + s e) - N(r' - s e))/(2s),
               exact for any s; s = |r'| keeps the rounding relative) */
            gip_md_vec(d, Ji, wk, rde);
            if ((st = s->nonlin(p, tl, rde, nl)))
                return st;
            for (size_t j = 0; j < d; ++j) sc += rde[j] * rde[j];
            sc = sqrt(sc);
            if (!(sc > 0) || !isfinite(sc))
                sc = 1.0;
            for (size_t c = 0; c < d; ++c) {
                double xp[GIP_MAXD], xm[GIP_MAXD], np[GIP_MAXD], nm[GIP_MAXD];
                for (size_t j = 0; j < d; ++j) {
                    xp[j] = rde[j] + (j == c ? sc : 0.0);
                    xm[j] = rde[j] - (j == c ? sc : 0.0);
                }
                if ((st = s->nonlin(p, tl, xp, np)) || (st = s->nonlin(p, tl, xm, nm)))
                    return st;
                for (size_t j = 0; j < d; ++j) Jn[d * j + c] = (np[j] - nm[j]) / (2.0 * sc);
            }
            gip_md_mul(d, Jn, Ji, Jn);
            for (size_t j = 0; j < dd; ++j) Jn[j] *= lam;
            gip_md_vec(d, Jn, wk, jw);
            for (size_t j = 0; j < d; ++j)
                rhs[j] = 6.0 * tl[j] / (hl * hl) + 6.0 * tr[j] / (hr * hr) - lam * nl[j] + jw[j];
            for (size_t j = 0; j < dd; ++j) {
                L[j] *= 2.0 / hl;
                U[j] *= 2.0 / hr;
                D[j] = (j % (d + 1) == 0 ? 4.0 / hl + 4.0 / hr : 0.0) + Jn[j];
            }
            if (k == 1) {
                gip_md_vec(d, L, s->rate(p, 0), t3);
                for (size_t j = 0; j < d; ++j) rhs[j] -= t3[j];
            } else {
                double LC[GIP_MAXD * GIP_MAXD];
                const double *Cp = s->scratch(p, k - 1), *yp = Cp + dd;
                gip_md_mul(d, L, Cp, LC);
                for (size_t j = 0; j < dd; ++j) D[j] -= LC[j];
                gip_md_vec(d, L, yp, t3);
                for (size_t j = 0; j < d; ++j) rhs[j] -= t3[j];
            }
            if (k == n - 2) {
                gip_md_vec(d, U, s->rate(p, n - 1), t3);
                for (size_t j = 0; j < d; ++j) rhs[j] -= t3[j];
                for (size_t j = 0; j < dd; ++j) U[j] = 0.0;
            }
            double Di[GIP_MAXD * GIP_MAXD];
            if ((st = gip_md_inv(d, D, Di)))
                return st;
            gip_md_mul(d, Di, U, C);
            gip_md_vec(d, Di, rhs, y);
        }
        double nxt[GIP_MAXD] = {0};
        for (size_t k = n - 1; k-- > 1;) {
            double *C = s->scratch(p, k), *y = C + dd, *w = s->rate(p, k), nw[GIP_MAXD];
            gip_md_vec(d, C, nxt, nw);
            for (size_t j = 0; j < d; ++j) {
                nw[j] = y[j] - nw[j];
                delta = fmax(delta, fabs(nw[j] - w[j]));
                big = fmax(big, fabs(nw[j]));
            }
            memcpy(w, nw, d * sizeof(double));
            memcpy(nxt, nw, d * sizeof(double));
        }
        if (!isfinite(delta) || !isfinite(big))
            return GA_ERR_DOMAIN;
        if (delta <= 4 * DBL_EPSILON * big || (delta <= 1e-12 * big && delta >= prev))
            return GA_OK;
        /* quadratic convergence: a step of at most 1e-10 of the largest rate and
           1e-3 of the one before leaves an error of about its cube over the last
           one's square, 1e-16 of the largest rate: done, without the sweep that
           would only stir the rounding (whether that one lands under 4 eps was
           a matter of rounding, which made the count of sweeps grow with n) */
        if (final && delta <= 1e-10 * big && delta <= 1e-3 * prev)
            return GA_OK;
        if (!final && delta <= 1e-9 * big)
            return GA_OK;
        prev = delta;
    }
    return GA_ERR_DOMAIN;
}

/* Newton from the start; where it does not converge, continuation: from
 * the start again, the systems with N scaled by 1/m, 2/m, ..., 1, each
 * solved from the last one's rates, for m = 4, 16 and 64 in turn (the
 * system without N is linear and block diagonally dominant, and a small
 * change of lam moves the solution little); C2_SWEEPS at most for each,
 * C2_CONTINUATION_SWEEPS for all, which bounds the time a key set that
 * has no solution within reach takes to fail; uncapped steps and steps
 * capped at 30 sweeps failed more often (docs/schemes.md). */
int gip_c2_solve(const gip_c2_sys *s)
{
    int st;
    for (size_t i = 0; s->jcache && i + 1 < s->p->n; ++i) { /* the Jacobians, once */
        if ((st = s->jr(s->p, s->theta(s->p, i), 0, s->jcache(s->p, i))))
            return st;
    }
    int budget = C2_SWEEPS;
    st = c2_newton(s, 1.0, 1, &budget);
    budget = C2_CONTINUATION_SWEEPS;
    for (int m = 4; st == GA_ERR_DOMAIN && m <= 64 && budget > 0; m *= 4) {
        s->start(s->p);
        st = GA_OK;
        for (int j = 1; j <= m && st == GA_OK; ++j) {
            int step = budget < C2_SWEEPS ? budget : C2_SWEEPS, left = step;
            st = c2_newton(s, (double)j / m, j == m, &left);
            budget -= step - left;
        }
    }
    return st;
}
