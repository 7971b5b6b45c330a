/* tools/cmd_fit.c: `garotor fit` (docs/tool.md, "garotor fit"): the
 * least-squares uniform cumulative cubic B-spline on SE(3) through noisy
 * poses at any stamps (Lovegrove, Patron-Perez, Sibley 2013; Sommer et al.
 * 2020): control poses X_j at the knots c_j = t_0 + (j - 1) h, the spline
 * of `interp --scheme bspline` (path.h, BSPLINE), fitted by Levenberg-
 * Marquardt to the residuals r_k = log(S(t_k)^-1 Z_k) (a twist: radians and
 * units of length weighted alike), with an optional smoothing term
 * sqrt(lambda) (log(X_j^-1 X_j+1) - log(X_j+1^-1 X_j+2)). The Jacobians are
 * central differences on right perturbations X_j exp(d); the normal
 * equations are banded (a residual touches 4 consecutive control poses) and
 * solved by a banded Cholesky factorisation.
 */
#include "eval.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char fit_help[] =
    "usage: garotor fit --in FILE --spacing H [OPTIONS]\n"
    "Fit a uniform cumulative cubic B-spline on SE(3), knots H apart, to noisy\n"
    "poses by least squares. Input: one pose a line, t x y z qx qy qz qw (TUM),\n"
    "t increasing, at any spacing. Output: one line a key, its time, the fitted\n"
    "pose x y z qx qy qz qw, and the residual: the distance and the angle (rad)\n"
    "from the fitted pose to the key.\n"
    "  --spacing H         the knot spacing, in units of t (> 0)\n"
    "  --smooth L          weight of the smoothing term (default 0)\n"
    "  --controls FILE     also write the control poses (c_j x y z qx qy qz qw):\n"
    "                      `garotor interp --scheme bspline --format pose` reads them\n"
    "                      (velocity, acceleration: --with velocity,acceleration)\n"
    "  --normalize         accept quaternions up to 1e-3 from unit norm, normalised\n"
    "  --in FILE, --out FILE   input and output (default standard input and output)\n"
    "  --header            skip the first line of the input (a CSV header)\n";

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

/* S(t) on segment seg from controls c[0..3] */
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

/* the Jacobian of resid (over m controls starting at c) by central differences */
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

/* solve the band SPD system (H + mu diag) x = -g in place of a copy; -1 if not SPD */
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

static double cost_of(const ev_traj *z, const spline *s, double w)
{
    double c = 0, r[6];
    for (size_t k = 0; k < z->n; k++) {
        double u;
        size_t seg = segment(s, z->t[k], &u);
        res_key(s->X + seg, u, z->m[k], r);
        for (int i = 0; i < 6; i++) c += r[i] * r[i];
    }
    for (size_t j = 0; w > 0 && j + 2 < s->n; j++) {
        res_smooth(s->X + j, w, r);
        for (int i = 0; i < 6; i++) c += r[i] * r[i];
    }
    return c;
}

/* Levenberg-Marquardt on the control poses X[0..n-1] */
static int fit(const ev_traj *z, ga_mat4 *X, size_t n, double h, double lambda)
{
    size_t dim = 6 * n;
    double *H = malloc(dim * BW * sizeof *H), *g = malloc(dim * sizeof *g), *L = malloc(dim * BW * sizeof *L),
           *dx = malloc(dim * sizeof *dx);
    ga_mat4 *Y = malloc(n * sizeof *Y);
    int rc = -1;
    if (!H || !g || !L || !dx || !Y)
        goto done;
    double w = sqrt(lambda), mu = 1e-6;
    spline s = {X, n, h};
    double cost = cost_of(z, &s, w);
    for (int it = 0; it < 100; it++) {
        memset(H, 0, dim * BW * sizeof *H);
        memset(g, 0, dim * sizeof *g);
        double J[6 * 24], r[6];
        for (size_t k = 0; k < z->n; k++) {
            double u;
            size_t seg = segment(&s, z->t[k], &u);
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
    rc = isfinite(cost) ? 0 : -1;
done:
    free(H);
    free(g);
    free(L);
    free(dx);
    free(Y);
    return rc;
}

/* ---- the command ---------------------------------------------------------- */

static int usage(const char *what, const char *arg)
{
    fprintf(stderr, "garotor fit: %s%s%s%s\n(garotor fit --help shows the options)\n", what, arg ? " '" : "",
            arg ? arg : "", arg ? "'" : "");
    return 2;
}

/* a pose line: the quaternion's sign kept continuous through *prev */
static void put_pose(tio_out *o, const char *stamp, ga_mat4 m, ga_quat *prev, const double *extra, int nextra)
{
    ga_rotor r;
    if (ga_rotor_from_mat4(m, &r) != GA_OK)
        r = ga_rotor_identity();
    ga_quat q = ga_rotor_to_quat(r);
    if (q.w * prev->w + q.x * prev->x + q.y * prev->y + q.z * prev->z < 0)
        q = (ga_quat){-q.w, -q.x, -q.y, -q.z};
    *prev = q;
    double v[9] = {m.m[3], m.m[7], m.m[11], q.x, q.y, q.z, q.w};
    for (int i = 0; i < nextra; i++) v[7 + i] = extra[i];
    tio_out_stamped(o, stamp, v, 7 + nextra);
}

int cmd_fit_main(int argc, char **argv)
{
    for (int i = 0; i < argc; i++)
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) {
            fputs(fit_help, stdout);
            return 0;
        }
    static const char *const names[] = {"--in",       "--out",       "--spacing", "--smooth",
                                        "--controls", "--normalize", "--header"};
    const char *val[5] = {NULL, NULL, NULL, NULL, NULL};
    int flag[2] = {0, 0};
    unsigned seen = 0;
    for (int i = 0; i < argc; i++) {
        const char *a = argv[i], *eq = strchr(a, '=');
        size_t len = eq ? (size_t)(eq - a) : strlen(a);
        int k = 0;
        while (k < 7 && !(strlen(names[k]) == len && strncmp(a, names[k], len) == 0)) k++;
        if (k == 7)
            return usage("unknown option", a);
        if (seen >> k & 1)
            return usage("option given twice", names[k]);
        seen |= 1u << k;
        if (k >= 5) {
            if (eq)
                return usage("takes no value:", a);
            flag[k - 5] = 1;
        } else if (eq)
            val[k] = eq + 1;
        else if (i + 1 < argc)
            val[k] = argv[++i];
        else
            return usage("missing value for", a);
    }
    char *end;
    if (!val[2])
        return usage("--spacing H is required (the knot spacing)", NULL);
    double h = strtod(val[2], &end);
    if (end == val[2] || *end || !(h > 0) || !isfinite(h))
        return usage("--spacing needs a number > 0, not", val[2]);
    double lambda = 0;
    if (val[3]) {
        lambda = strtod(val[3], &end);
        if (end == val[3] || *end || !(lambda >= 0) || !isfinite(lambda))
            return usage("--smooth needs a number >= 0, not", val[3]);
    }
    ev_read_opts ro = {flag[1], flag[0], 0};
    static tt_dec t0, zero;
    int have0 = 0;
    tt_parse("0", &zero);
    ev_traj z;
    memset(&z, 0, sizeof z);
    int rc = 2;
    ga_mat4 *X = NULL;
    tio_out out = TIO_OUT_NONE, cout = TIO_OUT_NONE;
    if (ev_traj_read(val[0], &ro, &t0, &have0, &zero, &z))
        goto done;
    double span = z.t[z.n - 1];
    double segs = ceil(span / h);
    if (segs < 1)
        segs = 1;
    if (segs > 1e6) {
        fprintf(stderr, "garotor fit: --spacing %s makes %.0f segments (at most 1e6)\n", val[2], segs);
        goto done;
    }
    size_t n = (size_t)segs + 3;
    if (z.n < 4) {
        fprintf(stderr, "garotor fit: %s: %zu poses; a fit needs at least 4\n", z.in.name, z.n);
        goto done;
    }
    X = malloc(n * sizeof *X);
    if (!X) {
        fprintf(stderr, "garotor fit: out of memory\n");
        goto done;
    }
    for (size_t j = 0, k = 0; j < n; j++) { /* start: the key nearest each knot */
        double c = ((double)j - 1) * h;
        while (k + 1 < z.n && fabs(z.t[k + 1] - c) <= fabs(z.t[k] - c)) k++;
        X[j] = z.m[k];
    }
    if (fit(&z, X, n, h, lambda)) {
        fprintf(stderr, "garotor fit: the least-squares problem has no finite solution (out of memory, or a "
                        "control pose with no key near it: try a larger --spacing or --smooth)\n");
        goto done;
    }
    if (tio_out_open(&out, val[1]))
        goto done;
    spline s = {X, n, h};
    ga_quat prev = {1, 0, 0, 0};
    for (size_t k = 0; k < z.n; k++) {
        double u;
        size_t seg = segment(&s, z.t[k], &u);
        ga_mat4 f = eval4(X + seg, u), e = ga_mat4_mul(ga_se3_inverse(f), z.m[k]);
        double res[2] = {sqrt(e.m[3] * e.m[3] + e.m[7] * e.m[7] + e.m[11] * e.m[11]), ev_angle(&e)};
        put_pose(&out, z.in.first[k], f, &prev, res, 2);
    }
    if (val[4]) {
        if (tio_out_open(&cout, val[4]))
            goto done;
        /* the knots c_j = t_0 + (j - 1) H as exact decimals: t_0 - H, then
           H added once a knot (the text of --spacing, read exactly) */
        static tt_dec hd, tj, tn;
        char stamp[TT_DIG + 32];
        tt_parse(val[2], &hd);
        tt_add(&t0, &hd, 1, &tj);
        prev = (ga_quat){1, 0, 0, 0};
        for (size_t j = 0; j < n; j++) {
            tt_format(&tj, stamp);
            put_pose(&cout, stamp, X[j], &prev, NULL, 0);
            tt_add(&tj, &hd, 0, &tn);
            tj = tn;
        }
        if (tio_out_finish(&cout))
            goto done;
    }
    if (tio_out_finish(&out) || tio_out_commit(&out) || tio_out_commit(&cout))
        goto done;
    rc = 0;
done:
    if (rc) {
        tio_out_discard(&out);
        tio_out_discard(&cout);
    }
    free(X);
    ev_traj_free(&z);
    return rc;
}
