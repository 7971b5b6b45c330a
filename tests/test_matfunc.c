/* tests/test_matfunc.c: ga_mat4_expm and ga_mat4_logm against the test
 * matrices of scipy and Eigen, the peer matrices, near half turns and the
 * inputs fuzzing found, each with an 80-digit reference (tests/matfunc_refs.h,
 * written by tests/make_matfunc_refs.py, which says where every matrix comes
 * from).
 *
 * The error measure is scipy's own, as the table's scipy_err was measured:
 * max |entry error| / max |reference entry| over the n x n input (an input
 * of size n < 4 embedded in 4x4), with the embedding's entries (exactly 0
 * and 1 in the reference) counted in the numerator too.
 *
 * Checks, one line per source and function (testkit.h):
 *   - status: GA_OK for every input that has a real principal log (and for
 *     every expm input): no refusal;
 *   - error: at most scipy's error on the same double input, or 4u
 *     (u = 2^-53, 4u = 4.4e-16) where scipy's is below 4u. The floor: at
 *     unit-roundoff level the two round differently for reasons that are
 *     no condition of the problem (the 4x4 embedding, Q log(T) Q^T whose
 *     entries are sums of 16 products, exact zeros of a log such as
 *     diag log [2 3; 1 2] coming out as 1e-16); scipy's error is 0 on the
 *     zero matrix and 2e-17 on some. Measured (test_matfunc -v prints
 *     every matrix; errors against max(scipy's, 4u)): worst 0.96 (logm of
 *     a fuzz-found scaled scipy input, 3.9u against scipy's 0.3u, i.e.
 *     against the floor), 0.96 (expm of a scipy 4x4, 71.5u against
 *     74.5u), then 0.93 and 0.89 (logm of scipy's 4x4 inputs; the one with
 *     the pair -0.63 +- 1.23i, whose log doubles the Schur form's backward
 *     error, 6.1u against scipy's 6.9u); no slack factor. The regressions this guards
 *     against were 3 to 20 times (a squaring too few near theta_13 = 5.37,
 *     I + X for a contracting r_m, Schur vectors 10-30u from orthogonal)
 *     and 1000x and more before (9.4e-13 against scipy's 7.1e-16);
 *   - near half turns (rigid motions turning by pi - 1e-8 and pi - 1e-13):
 *     error at most 10 times ga_se3_log's (the closed form) on the same
 *     matrix, or 2u if the closed form's error is below u/5;
 *   - a sweep of turns pi - d, d = 10^-1 .. 10^-16, rigid and scaled by 2
 *     (the general path), d down to 10^-13 for the scaled ones: no
 *     GA_ERR_DOMAIN short of exactly pi, and GA_ERR_DOMAIN at exactly pi.
 */
#include "testkit.h"

#include "matfunc_refs.h"

#define U 0x1p-53

static double ref_err(const matfunc_ref *r, ga_mat4 got)
{
    double big = 0.0, e = 0.0;
    for (int i = 0; i < r->n; i++)
        for (int j = 0; j < r->n; j++) big = fmax(big, fabs(r->ref[4 * i + j]));
    for (int i = 0; i < 16; i++) {
        double d = fabs(got.m[i] - r->ref[i]);
        if (isnan(d))
            return NAN;
        e = fmax(e, d);
    }
    return big > 0.0 ? e / big : e;
}

static ga_mat4 mat(const double v[16])
{
    ga_mat4 a;
    memcpy(a.m, v, sizeof a.m);
    return a;
}

/* the rigid motion turning by th about the unit axis n, translated by t */
static ga_mat4 turn(double th, ga_vec3 n, ga_vec3 t, double scale)
{
    ga_twist xi = {{th * n.x, th * n.y, th * n.z}, {0, 0, 0}};
    ga_mat4 m = ga_se3_exp(xi);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) m.m[4 * i + j] *= scale;
    m.m[3] = t.x;
    m.m[7] = t.y;
    m.m[11] = t.z;
    return m;
}

static int verbose; /* -v: one line per matrix */

/* the reference matrices: expm and logm against scipy's */
static void section_refs(void)
{
    char name[128];
    for (size_t k = 0; k < N_MATFUNC_REFS; k++) {
        const matfunc_ref *r = &matfunc_refs[k];
        const char *fn = r->logm ? "logm" : "expm";
        ga_mat4 a = mat(r->a), out;
        int st = r->logm ? ga_mat4_logm(a, &out) : ga_mat4_expm(a, &out);
        if (!r->has_log) { /* no real principal log: any status, but never a non-finite GA_OK */
            snprintf(name, sizeof name, "%s %s: no real log, GA_OK only finite", fn, r->src);
            tk_add_bool(tk_get(name), st != GA_OK || isfinite(ga_mat4_norm1(out)));
            continue;
        }
        snprintf(name, sizeof name, "%s %s: no refusal", fn, r->src);
        tk_add_status(tk_get(name), st, GA_OK);
        if (st != GA_OK) {
            if (verbose)
                tk_note("  row %zu %s %s n=%d: refused %d\n", k, fn, r->src, r->n, st);
            continue;
        }
        double e = ref_err(r, out);
        if (strncmp(r->src, "halfturn", 8) == 0) {
            ga_twist xi;
            int cst = ga_se3_log(a, &xi);
            double ce = cst == GA_OK ? ref_err(r, ga_twist_hat(xi)) : INFINITY;
            snprintf(name, sizeof name, "logm %s: error <= 10x the closed form's", r->src);
            tk_add_tol(tk_get(name), e, ce >= U / 5 ? 10.0 * ce : 2.0 * U);
            if (verbose)
                tk_note("  row %zu %s %s: err %.3e closed form %.3e\n", k, fn, r->src, e, ce);
            continue;
        }
        snprintf(name, sizeof name, "%s %s: error <= scipy's (floor 4u)", fn, r->src);
        tk_add_tol(tk_get(name), e, fmax(r->scipy_err, 4.0 * U));
        if (verbose)
            tk_note("  row %zu %s %s n=%d: err %.3e scipy %.3e\n", k, fn, r->src, r->n, e, r->scipy_err);
    }
    tk_end_named();
}

/* the sweep toward the half turn */
static void section_half_turn(void)
{
    static const double ax[4][3] = {{1, 2, 3}, {0, 0, 1}, {-3, 1, 1}, {1, 1, 0}};
    tk_check rigid = tk_begin("logm rigid turn pi - 10^-k, k = 1..16: GA_OK", 0),
             scaled = tk_begin("logm 2 x turn pi - 10^-k, k = 1..13: GA_OK", 0),
             exact = tk_begin("logm turn by exactly pi: GA_ERR_DOMAIN", 0);
    for (int i = 0; i < 4; i++) {
        double l = sqrt(ax[i][0] * ax[i][0] + ax[i][1] * ax[i][1] + ax[i][2] * ax[i][2]);
        ga_vec3 n = {ax[i][0] / l, ax[i][1] / l, ax[i][2] / l}, t = {0.5, -1.0, 2.0};
        ga_mat4 out;
        for (int kk = 1; kk <= 16; kk++) {
            double th = TK_PI - pow(10.0, -kk);
            tk_add_status(&rigid, ga_mat4_logm(turn(th, n, t, 1.0), &out), GA_OK);
            if (kk <= 13)
                tk_add_status(&scaled, ga_mat4_logm(turn(th, n, t, 2.0), &out), GA_OK);
        }
        /* exactly pi: the symmetric rotation 2 n n^T - I */
        ga_mat4 m = ga_mat4_identity();
        double nn[3] = {n.x, n.y, n.z};
        for (int p = 0; p < 3; p++) /* symmetric as computed: (2 n_p) n_q = (2 n_q) n_p */
            for (int q = 0; q < 3; q++) m.m[4 * p + q] = 2.0 * nn[p] * nn[q] - (p == q);
        tk_add_status(&exact, ga_mat4_logm(m, &out), GA_ERR_DOMAIN);
    }
    tk_end(&rigid);
    tk_end(&scaled);
    tk_end(&exact);
}

static const tk_section sections[] = {
    {"refs", section_refs, 0},
    {"half_turn", section_half_turn, 0},
};

static void setup(const char *arg) { verbose = arg && strcmp(arg, "-v") == 0; }

int main(int argc, char **argv)
{
    return tk_main_arg(argc, argv, "test_matfunc", sections, TK_COUNT(sections), setup);
}
