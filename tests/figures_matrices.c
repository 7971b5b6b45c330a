/* tests/figures_matrices.c: the "exp then log" table of docs/matrices.md.
 * For xi = (theta u, v), u = (0.48, -0.6, 0.64), v = (1000, -200, 300), and
 * each theta of the table: the largest entry of log(exp(xi)) - xi relative to
 * max |xi| on each group (cga, matrix; affine in its 12 coordinates, the top
 * 3x4 of hat(xi)), and the largest entry of exp on cga minus exp on matrix as
 * 4x4 matrices. Deterministic; tests/doc_figures_check.py runs it and checks
 * the table against what it prints (one row per theta). */
#include <math.h>
#include <stdio.h>

#include <garotor/garotor.h>

static double maxabs(const double *x, size_t n)
{
    double m = 0;
    for (size_t i = 0; i < n; ++i) m = fmax(m, fabs(x[i]));
    return m;
}

/* max |log(exp x) - x| / max |x| on g (x in g's coordinates); -1 if refused */
static double round_trip(const ga_group *g, const double *x, double scale)
{
    double elem[32], y[12], d[12];
    if (g->exp(x, elem) != GA_OK || g->log(elem, y) != GA_OK)
        return -1;
    for (size_t i = 0; i < g->dim; ++i) d[i] = y[i] - x[i];
    return maxabs(d, g->dim) / scale;
}

int main(void)
{
    const double pi = 3.14159265358979323846;
    const struct {
        const char *name;
        double theta;
    } row[] = {{"0", 0}, {"1e-12", 1e-12}, {"1e-9", 1e-9},         {"1e-6", 1e-6},        {"1e-3", 1e-3},
               {"1", 1}, {"2", 2},         {"pi-1e-6", pi - 1e-6}, {"pi-1e-9", pi - 1e-9}};
    printf("%-9s  %-9s  %-9s  %-9s  %s\n", "theta", "cga", "matrix", "affine", "cga-matrix");
    for (size_t r = 0; r < sizeof row / sizeof row[0]; ++r) {
        const double th = row[r].theta;
        double xi[6] = {0.48 * th, -0.6 * th, 0.64 * th, 1000, -200, 300}, xa[12];
        const double scale = maxabs(xi, 6);
        if (ga_group_affine.vee(ga_group_se3.hat(xi), xa) != GA_OK) {
            printf("%s: no affine coordinates\n", row[r].name);
            return 1;
        }
        ga_rotor rc;
        ga_mat4 mm;
        double dm = -1;
        if (ga_group_cga.exp(xi, &rc) == GA_OK && ga_group_se3.exp(xi, &mm) == GA_OK) {
            ga_mat4 mc = ga_group_cga.to_mat4(&rc);
            dm = 0;
            for (int i = 0; i < 16; ++i) dm = fmax(dm, fabs(mc.m[i] - mm.m[i]));
        }
        printf("%-9s  %-9.2g  %-9.2g  %-9.2g  %.2g\n", row[r].name, round_trip(&ga_group_cga, xi, scale),
               round_trip(&ga_group_se3, xi, scale), round_trip(&ga_group_affine, xa, scale), dm);
    }
    return 0;
}
