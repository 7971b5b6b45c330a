/* tools/demo.c: `garotor` with no arguments, a short tour of what garotor does. */
#include "cli.h"

#include <math.h>
#include <stdio.h>

static void show_vec(const char *label, ga_vec3 x)
{
    printf("  %-34s (%.6g, %.6g, %.6g)\n", label, x.x, x.y, x.z);
}

int cmd_demo(const cli_opts *o)
{
    (void)o;
    printf("garotor %s: rigid motions in conformal geometric algebra G(4,1)\n\n", GAROTOR_VERSION);

    /* 1. the conformal model: a point is a null vector, distances are inner products */
    ga_vec3 x = {1, 2, 3}, y = {4, 6, 3};
    ga_mv X = ga_point(x), Y = ga_point(y);
    printf("The conformal model (Wareham-Lasenby §1): F(x) = (x^2 n + 2x - nbar)/2\n");
    show_vec("x", x);
    printf("  %-34s %.3g\n", "F(x).F(x) (a null vector)", ga_sp(X, X));
    show_vec("y", y);
    printf("  %-34s %.6g  (|x - y|^2 = 25)\n", "-2 F(x).F(y)", -2.0 * ga_sp(X, Y));

    /* 2. a translation rotor T_a = 1 + n a/2 moves F(x) to F(x + a) */
    ga_vec3 a = {0.5, -1, 2};
    ga_mv T = ga_add(ga_mv_scalar(1.0), ga_scale(ga_gp(ga_n(), ga_vec3_mv(a)), 0.5));
    ga_mv TX = ga_gp(ga_gp(T, X), ga_reverse(T));
    ga_vec3 moved;
    int st = ga_down(TX, &moved);
    printf("\nA translation rotor T = 1 + n a/2 and the sandwich T F(x) ~T:\n");
    show_vec("a", a);
    if (st != GA_OK) {
        fprintf(stderr, "garotor: demo: down-projection failed: %s\n", ga_strerror(st));
        return 1;
    }
    show_vec("down(T F(x) ~T)", moved);
    ga_vec3 want = {x.x + a.x, x.y + a.y, x.z + a.z};
    double err = fmax(fmax(fabs(moved.x - want.x), fabs(moved.y - want.y)), fabs(moved.z - want.z));
    show_vec("x + a", want);
    printf("  %-34s %.3g\n", "largest difference", err);
    return 0;
}
