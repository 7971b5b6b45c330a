/* interp/traj_fit.c: the least-squares uniform cumulative cubic B-spline on
 * SE(3) through noisy poses at any stamps (trajectory.h; `garotor fit`, the
 * Python module's fit). Levenberg-Marquardt on the control poses; the
 * Jacobians are central differences on right perturbations X_j exp(d); the
 * normal equations are banded (a residual touches 4 consecutive control
 * poses) and solved by a banded Cholesky factorisation in the caller's
 * workspace.
 */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include <garotor/mat4.h>
#include <garotor/trajectory.h>

typedef struct {
    const ga_mat4 *X; /* control poses */
    size_t n;         /* how many */
    double h;         /* knot spacing */
} spline;

/* the segment of t (relative to t_0) and its u in [0, 1] */
static size_t segment(const spline *s, double t, double *u)
{
    double x = t / s->h;
    double f = floor(x);
    if (f < 0)
        f = 0;
    if (f > (double)(s->n - 4))
        f = (double)(s->n - 4);
    *u = x - f;
    return (size_t)f;
}

static ga_twist rel_log(ga_mat4 a, ga_mat4 b)
{
    ga_twist x = {{0, 0, 0}, {0, 0, 0}};
    if (ga_se3_log(ga_mat4_mul(ga_se3_inverse(a), b), &x) != GA_OK)
        x.w.x = NAN;
    return x;
}

static ga_twist tw_scale(ga_twist x, double k)
{
    return (ga_twist){{k * x.w.x, k * x.w.y, k * x.w.z}, {k * x.v.x, k * x.v.y, k * x.v.z}};
}

/* S(t) on a segment from its controls c[0..3] */
static ga_mat4 eval4(const ga_mat4 *c, double u)
{
    double b[3] = {(5 + 3 * u - 3 * u * u + u * u * u) / 6, (1 + 3 * u + 3 * u * u - 2 * u * u * u) / 6,
                   u * u * u / 6};
    ga_mat4 a = c[0];
    for (int j = 0; j < 3; j++) a = ga_mat4_mul(a, ga_se3_exp(tw_scale(rel_log(c[j], c[j + 1]), b[j])));
    return a;
}

static void res_key(const ga_mat4 *c, double u, ga_mat4 z, double *r)
{
    ga_twist x = rel_log(eval4(c, u), z);
    r[0] = x.w.x, r[1] = x.w.y, r[2] = x.w.z, r[3] = x.v.x, r[4] = x.v.y, r[5] = x.v.z;
}

static void res_smooth(const ga_mat4 *c, double w, double *r)
{
    ga_twist a = rel_log(c[0], c[1]), b = rel_log(c[1], c[2]);
    double x[6] = {a.w.x - b.w.x, a.w.y - b.w.y, a.w.z - b.w.z, a.v.x - b.v.x, a.v.y - b.v.y, a.v.z - b.v.z};
    for (int i = 0; i < 6; i++) r[i] = w * x[i];
}

static ga_mat4 perturb(ga_mat4 m, int k, double d)
{
    double x[6] = {0};
    x[k] = d;
    return ga_mat4_mul(m, ga_se3_exp((ga_twist){{x[0], x[1], x[2]}, {x[3], x[4], x[5]}}));
}

enum { BW = 24 }; /* half bandwidth + 1 of the normal equations */

/* add the residual r (6) with Jacobian J (6 x 6m, columns of controls
 * first.. first+m-1) into H (band) and g */
static void accumulate(double *H, double *g, size_t first, int m, const double *J, const double *r)
{
    int cols = 6 * m;
    for (int a = 0; a < cols; a++) {
        size_t ia = 6 * first + (size_t)a;
        double ga = 0;
        for (int i = 0; i < 6; i++) ga += J[i * cols + a] * r[i];
        g[ia] += ga;
        for (int b = a; b < cols; b++) {
            double s = 0;
            for (int i = 0; i < 6; i++) s += J[i * cols + a] * J[i * cols + b];
            H[ia * BW + (size_t)(b - a)] += s;
        }
    }
}

/* the Jacobian of a residual (over m controls starting at c) by central differences */
static void jacobian(ga_mat4 *c, int m, double u, ga_mat4 z, double w, int key, double *J)
{
    const double hd = 1e-6;
    int cols = 6 * m;
    for (int p = 0; p < cols; p++) {
        ga_mat4 keep = c[p / 6];
        double rp[6], rm[6];
        c[p / 6] = perturb(keep, p % 6, hd);
        if (key)
            res_key(c, u, z, rp);
        else
            res_smooth(c, w, rp);
        c[p / 6] = perturb(keep, p % 6, -hd);
        if (key)
            res_key(c, u, z, rm);
        else
            res_smooth(c, w, rm);
        c[p / 6] = keep;
        for (int i = 0; i < 6; i++) J[i * cols + p] = (rp[i] - rm[i]) / (2 * hd);
    }
}

/* solve the band SPD system (H + mu diag) x = -g; -1 if not SPD */
static int band_solve(const double *H, const double *g, size_t n, double mu, double *L, double *x)
{
    for (size_t i = 0; i < n; i++)
        for (int d = 0; d < BW; d++) L[i * BW + d] = 0;
    /* L[i*BW + (i - j)] = L(i, j) */
    for (size_t j = 0; j < n; j++) {
        double s = H[j * BW] * (1 + mu) + 1e-12;
        for (size_t k = j >= BW - 1 ? j - (BW - 1) : 0; k < j; k++)
            s -= L[j * BW + (j - k)] * L[j * BW + (j - k)];
        if (!(s > 0))
            return -1;
        double ljj = sqrt(s);
        L[j * BW] = ljj;
        for (size_t i = j + 1; i < n && i < j + BW; i++) {
            double t = H[j * BW + (i - j)];
            for (size_t k = i >= BW - 1 ? i - (BW - 1) : 0; k < j; k++)
                t -= L[i * BW + (i - k)] * L[j * BW + (j - k)];
            L[i * BW + (i - j)] = t / ljj;
        }
    }
    for (size_t i = 0; i < n; i++) { /* L y = -g */
        double s = -g[i];
        for (size_t k = i >= BW - 1 ? i - (BW - 1) : 0; k < i; k++) s -= L[i * BW + (i - k)] * x[k];
        x[i] = s / L[i * BW];
    }
    for (size_t i = n; i-- > 0;) { /* L^T x = y */
        double s = x[i];
        for (size_t k = i + 1; k < n && k < i + BW; k++) s -= L[k * BW + (k - i)] * x[k];
        x[i] = s / L[i * BW];
    }
    return 0;
}

/* the keys: times relative to the first, poses */
typedef struct {
    const double *t;
    const ga_mat4 *m;
    size_t n;
} keys;

static double cost_of(const keys *z, const spline *s, double w)
{
    double c = 0, r[6];
    for (size_t k = 0; k < z->n; k++) {
        double u;
        size_t seg = segment(s, z->t[k] - z->t[0], &u);
        res_key(s->X + seg, u, z->m[k], r);
        for (int i = 0; i < 6; i++) c += r[i] * r[i];
    }
    for (size_t j = 0; w > 0 && j + 2 < s->n; j++) {
        res_smooth(s->X + j, w, r);
        for (int i = 0; i < 6; i++) c += r[i] * r[i];
    }
    return c;
}

/* the workspace: H and L (6n x BW each), g and dx (6n each), X and Y (n poses each) */
#define PER_CONTROL (sizeof(double) * 6 * (2 * BW + 2) + 2 * sizeof(ga_mat4))

size_t ga_traj_fit_workspace_size(size_t n_controls)
{
    if (n_controls < 4 || n_controls > SIZE_MAX / PER_CONTROL)
        return 0;
    return n_controls * PER_CONTROL;
}

ga_status ga_traj_fit_count(double duration, double spacing, size_t *n_controls)
{
    if (!n_controls || isnan(duration) || isnan(spacing) || !(spacing > 0) || duration < 0)
        return GA_ERR_ARG;
    if (!isfinite(duration) || !isfinite(spacing))
        return GA_ERR_NOTFINITE;
    double segs = ceil(duration / spacing);
    if (segs < 1)
        segs = 1;
    if (segs > GA_TRAJ_FIT_MAX_SEGMENTS)
        return GA_ERR_DOMAIN;
    *n_controls = (size_t)segs + 3;
    return GA_OK;
}

/* Levenberg-Marquardt on the control poses X[0..n-1]; the final cost */
static double lm(const keys *z, ga_mat4 *X, size_t n, double h, double lambda, double *H, double *L,
                 double *g, double *dx, ga_mat4 *Y)
{
    size_t dim = 6 * n;
    double w = sqrt(lambda), mu = 1e-6;
    spline s = {X, n, h};
    double cost = cost_of(z, &s, w);
    for (int it = 0; it < 100; it++) {
        memset(H, 0, dim * BW * sizeof *H);
        memset(g, 0, dim * sizeof *g);
        double J[6 * 24], r[6];
        for (size_t k = 0; k < z->n; k++) {
            double u;
            size_t seg = segment(&s, z->t[k] - z->t[0], &u);
            res_key(X + seg, u, z->m[k], r);
            jacobian(X + seg, 4, u, z->m[k], 0, 1, J);
            accumulate(H, g, seg, 4, J, r);
        }
        for (size_t j = 0; w > 0 && j + 2 < n; j++) {
            res_smooth(X + j, w, r);
            jacobian(X + j, 3, 0, X[0], w, 0, J);
            accumulate(H, g, j, 3, J, r);
        }
        int accepted = 0;
        double step = 0, newcost = cost;
        for (int tries = 0; tries < 20 && !accepted; tries++) {
            if (band_solve(H, g, dim, mu, L, dx) == 0) {
                step = 0;
                for (size_t j = 0; j < n; j++) {
                    const double *d = dx + 6 * j;
                    Y[j] = ga_mat4_mul(X[j], ga_se3_exp((ga_twist){{d[0], d[1], d[2]}, {d[3], d[4], d[5]}}));
                    for (int i = 0; i < 6; i++) step = fmax(step, fabs(d[i]));
                }
                spline sy = {Y, n, h};
                newcost = cost_of(z, &sy, w);
                if (newcost <= cost) {
                    accepted = 1;
                    break;
                }
            }
            mu *= 10;
        }
        if (!accepted)
            break; /* no step lowers the cost: a minimum to rounding */
        memcpy(X, Y, n * sizeof *X);
        mu = fmax(mu / 10, 1e-12);
        double drop = cost - newcost;
        cost = newcost;
        if (step < 1e-12 || drop <= 1e-14 * cost)
            break;
    }
    return cost;
}

ga_status ga_traj_fit_bspline(const double *t, const ga_mat4 *poses, size_t n, double spacing, double smooth,
                              void *work, size_t work_size, ga_mat4 *controls, size_t n_controls)
{
    if (!t || !poses || !work || !controls || n < 4 || n_controls < 4 || isnan(spacing) || !(spacing > 0) ||
        isnan(smooth) || smooth < 0 || ga_traj_fit_workspace_size(n_controls) == 0 ||
        work_size < ga_traj_fit_workspace_size(n_controls) || (uintptr_t)work % sizeof(double) != 0)
        return GA_ERR_ARG;
    if (!isfinite(spacing) || !isfinite(smooth))
        return GA_ERR_NOTFINITE;
    for (size_t k = 0; k < n; k++) {
        if (!isfinite(t[k]))
            return GA_ERR_NOTFINITE;
        if (k > 0 && !(t[k] > t[k - 1]))
            return GA_ERR_ARG;
        for (int i = 0; i < 16; i++)
            if (!isfinite(poses[k].m[i]))
                return GA_ERR_NOTFINITE;
    }
    size_t dim = 6 * n_controls;
    double *H = work, *L = H + dim * BW, *g = L + dim * BW, *dx = g + dim;
    ga_mat4 *X = (ga_mat4 *)(void *)(dx + dim), *Y = X + n_controls;
    keys z = {t, poses, n};
    for (size_t j = 0, k = 0; j < n_controls; j++) { /* start: the key nearest each knot */
        double c = ((double)j - 1) * spacing;
        while (k + 1 < n && fabs(t[k + 1] - t[0] - c) <= fabs(t[k] - t[0] - c)) k++;
        X[j] = poses[k];
    }
    if (!isfinite(lm(&z, X, n_controls, spacing, smooth, H, L, g, dx, Y)))
        return GA_ERR_DOMAIN;
    memcpy(controls, X, n_controls * sizeof *X);
    return GA_OK;
}

ga_status ga_traj_bspline_pose(const ga_mat4 *controls, size_t n_controls, double spacing, double t_rel,
                               ga_mat4 *pose)
{
    if (!controls || !pose || n_controls < 4 || isnan(spacing) || !(spacing > 0))
        return GA_ERR_ARG;
    if (!isfinite(spacing) || !isfinite(t_rel))
        return GA_ERR_NOTFINITE;
    spline s = {controls, n_controls, spacing};
    double u;
    size_t seg = segment(&s, t_rel, &u);
    *pose = eval4(controls + seg, u);
    return GA_OK;
}

ga_status ga_traj_fit_residuals(const double *t, const ga_mat4 *poses, size_t n, const ga_mat4 *controls,
                                size_t n_controls, double spacing, ga_mat4 *fitted, double *residuals)
{
    if (!t || !poses || !controls || !fitted || !residuals || n == 0 || n_controls < 4 || isnan(spacing) ||
        !(spacing > 0))
        return GA_ERR_ARG;
    if (!isfinite(spacing))
        return GA_ERR_NOTFINITE;
    for (size_t k = 0; k < n; k++) {
        if (!isfinite(t[k]))
            return GA_ERR_NOTFINITE;
        for (int i = 0; i < 16; i++)
            if (!isfinite(poses[k].m[i]))
                return GA_ERR_NOTFINITE;
    }
    spline s = {controls, n_controls, spacing};
    for (size_t k = 0; k < n; k++) {
        double u;
        size_t seg = segment(&s, t[k] - t[0], &u);
        ga_mat4 f = eval4(controls + seg, u), e = ga_mat4_mul(ga_se3_inverse(f), poses[k]);
        fitted[k] = f;
        residuals[2 * k] = sqrt(e.m[3] * e.m[3] + e.m[7] * e.m[7] + e.m[11] * e.m[11]);
        residuals[2 * k + 1] = ga_traj_angle(e);
    }
    return GA_OK;
}
