/* tests/soak_c2_spacing.c: how often the C2 Newton sweeps (path.h
 * DECOUPLED_C2 and C2) fail to converge, by the ratio of neighbouring key
 * spacings, the figures of docs/schemes.md ("decoupled-c2", "c2").
 *
 * For each spacing ratio rho and largest angle: 2000 random key sets (3 to
 * 42 keys; each key a random rotation about a random axis up to the angle,
 * and a translation in [-1, 1]^3; spacings log-uniform in [1/rho, rho]),
 * seeded; prints the failures (GA_ERR_DOMAIN) of decoupled-c2 ("dc2") and c2
 * on the matrix group, a row per rho, for angles up to 1 rad and up to pi.
 * Exit status 0 always: a measurement, not a check; doc-figures (docs suite)
 * checks the table of docs/schemes.md against what it prints. */
#include <stdio.h>
#include <stdlib.h>

#include "testkit.h"

#define MAXN 42

int main(int argc, char **argv)
{
    int sets = argc > 1 ? atoi(argv[1]) : 2000;
    const double rhos[4] = {1, 3, 10, 1000}, angs[2] = {1.0, TK_PI};
    const ga_scheme sc[2] = {GA_SCHEME_DECOUPLED_C2, GA_SCHEME_C2};
    static double work[200000];
    printf("%-6s  %-8s  %-8s  %-8s  %s\n", "rho", "dc2 1", "c2 1", "dc2 pi", "c2 pi");
    for (int ri = 0; ri < 4; ++ri) {
        int fail[2][2] = {{0, 0}, {0, 0}};
        for (int ai = 0; ai < 2; ++ai) {
            tk_rng r = {20260 + 10 * (uint64_t)ri + (uint64_t)ai};
            for (int s = 0; s < sets; ++s) {
                int n = 3 + (int)(tk_next(&r) % 40);
                double t[MAXN];
                ga_mat4 k[MAXN];
                t[0] = 0.0;
                for (int i = 0; i < n; ++i) {
                    if (i)
                        t[i] = t[i - 1] + tk_loguni(&r, 1.0 / rhos[ri], rhos[ri] * (1 + 1e-12));
                    ga_vec3 u = tk_unit(&r);
                    double th = tk_range(&r, 0, angs[ai]);
                    ga_twist x = {tk_scale(u, th), {0, 0, 0}};
                    k[i] = ga_se3_exp(x);
                    k[i].m[3] = tk_range(&r, -1, 1);
                    k[i].m[7] = tk_range(&r, -1, 1);
                    k[i].m[11] = tk_range(&r, -1, 1);
                }
                for (int q = 0; q < 2; ++q) {
                    ga_path p;
                    int st = ga_path_init_mat4(&ga_group_se3, sc[q], (size_t)n, t, k, NULL, work, sizeof work,
                                               &p);
                    fail[ai][q] += st != GA_OK;
                }
            }
        }
        printf("%-6g  %-8d  %-8d  %-8d  %d\n", rhos[ri], fail[0][0], fail[0][1], fail[1][0], fail[1][1]);
    }
    return 0;
}
