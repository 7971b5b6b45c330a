/* tools/cmd_fit.c: `garotor fit` (docs/tool.md, "garotor fit"): the
 * least-squares uniform cumulative cubic B-spline on SE(3) through noisy
 * poses at any stamps (Lovegrove, Patron-Perez, Sibley 2013; Sommer et al.
 * 2020): control poses X_j at the knots c_j = t_0 + (j - 1) h, the spline
 * of `interp --scheme bspline` (path.h, BSPLINE), fitted by Levenberg-
 * Marquardt to the residuals r_k = log(S(t_k)^-1 Z_k) (a twist: radians and
 * units of length weighted alike), with an optional smoothing term
 * sqrt(lambda) (log(X_j^-1 X_j+1) - log(X_j+1^-1 X_j+2)). The fit is the
 * library's (garotor/trajectory.h, ga_traj_fit_bspline); this file reads,
 * checks and writes.
 */
#include "eval.h"
#include "stamps.h"

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
    "  --time-unit s|ns    t in seconds or whole nanoseconds (--spacing stays in\n"
    "                      seconds); without it, whole numbers of 12 digits or more\n"
    "                      are an error (ms, us, ns?)\n"
    "  --in FILE, --out FILE   input and output (default standard input and output)\n"
    "  --header            skip the first line of the input (a CSV header)\n";

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
    double v[9];
    if (ga_traj_pose_to_tum(m, prev, v) != GA_OK)
        return; /* not reached: no pointer is NULL */
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
    static const char *const names[] = {"--in",       "--out",       "--spacing",   "--smooth",
                                        "--controls", "--time-unit", "--normalize", "--header"};
    enum { NVALUED = 6, NNAMES = 8 };
    const char *val[NVALUED] = {NULL, NULL, NULL, NULL, NULL, NULL};
    int flag[2] = {0, 0};
    unsigned seen = 0;
    for (int i = 0; i < argc; i++) {
        const char *a = argv[i], *eq = strchr(a, '=');
        size_t len = eq ? (size_t)(eq - a) : strlen(a);
        int k = 0;
        while (k < NNAMES && !(strlen(names[k]) == len && strncmp(a, names[k], len) == 0)) k++;
        if (k == NNAMES)
            return usage("unknown option", a);
        if (seen >> k & 1)
            return usage("option given twice", names[k]);
        seen |= 1u << k;
        if (k >= NVALUED) {
            if (eq)
                return usage("takes no value:", a);
            flag[k - NVALUED] = 1;
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
    int ns;
    if (st_time_unit("fit", val[5], &ns))
        return 2;
    ev_read_opts ro = {flag[1], flag[0], 0, ns, !val[5], NULL, NULL, "fit"};
    static tt_dec t0, zero;
    int have0 = 0;
    tt_parse("0", &zero);
    ev_traj z;
    memset(&z, 0, sizeof z);
    int rc = 2;
    ga_mat4 *X = NULL, *F = NULL;
    double *res = NULL;
    void *work = NULL;
    tio_out out = TIO_OUT_NONE, cout = TIO_OUT_NONE;
    if (ev_traj_read(val[0], &ro, &t0, &have0, &zero, &z, NULL))
        goto done;
    size_t n;
    if (ga_traj_fit_count(z.t[z.n - 1], h, &n) != GA_OK) {
        fprintf(stderr, "garotor fit: --spacing %s makes %.0f segments (at most 1e6)\n", val[2],
                ceil(z.t[z.n - 1] / h));
        goto done;
    }
    if (z.n < 4) {
        fprintf(stderr, "garotor fit: %s: %zu poses; a fit needs at least 4\n", z.in.name, z.n);
        goto done;
    }
    size_t wsize = ga_traj_fit_workspace_size(n);
    X = malloc(n * sizeof *X);
    F = malloc(z.n * sizeof *F);
    res = malloc(2 * z.n * sizeof *res);
    work = wsize ? malloc(wsize) : NULL;
    if (!X || !F || !res || !work) {
        fprintf(stderr, "garotor fit: out of memory\n");
        goto done;
    }
    if (ga_traj_fit_bspline(z.t, z.m, z.n, h, lambda, work, wsize, X, n) != GA_OK) {
        fprintf(stderr, "garotor fit: the least-squares problem has no finite solution (out of memory, or a "
                        "control pose with no key near it: try a larger --spacing or --smooth)\n");
        goto done;
    }
    if (tio_out_open(&out, val[1]))
        goto done;
    if (ga_traj_fit_residuals(z.t, z.m, z.n, X, n, h, F, res) != GA_OK)
        goto done; /* not reached: the fit checked its inputs */
    ga_quat prev = {1, 0, 0, 0};
    for (size_t k = 0; k < z.n; k++) put_pose(&out, z.in.first[k], F[k], &prev, res + 2 * k, 2);
    if (val[4]) {
        if (tio_out_open(&cout, val[4]))
            goto done;
        /* the knots c_j = t_0 + (j - 1) H as exact decimals: t_0 - H, then
           H added once a knot (the text of --spacing, read exactly) */
        static tt_dec hd, tj, tn;
        char stamp[TT_DIG + 32];
        tt_parse(val[2], &hd);
        if (ns && hd.n) /* --spacing is in seconds: in nanoseconds, exactly */
            hd.exp += 9;
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
    free(F);
    free(res);
    free(work);
    ev_traj_free(&z);
    return rc;
}
