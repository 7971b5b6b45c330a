/* ex_inversions.c: docs/exercises.md, exercise 7: two inversions in
 * concentric spheres make a dilation. Build from the repository: cc -std=c11
 * -Iinclude -Ibuild/include docs/examples/ex_inversions.c build/libgarotor.a -lm
 * -o ex_inversions */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include <garotor/garotor.h>

/* a status other than GA_OK ends the program, naming the call */
static void check(ga_status status, const char *call)
{
    if (status != GA_OK) {
        fprintf(stderr, "%s: %s\n", call, ga_status_string(status));
        exit(1);
    }
}

static void show(const char *what, ga_mv x)
{
    char text[GA_MV_TEXT_MAX];
    size_t len;
    check(ga_mv_format(x, text, sizeof text, &len), "ga_mv_format");
    printf("%-20s %s\n", what, text);
}

int main(void)
{
    ga_vec3 o = {0, 0, 0};
    ga_mv S1 = ga_versor_inversion(o, 1), S2 = ga_versor_inversion(o, 2);
    show("S1 (radius 1)", S1);
    show("S2 (radius 2)", S2);
    ga_mv V = ga_mv_gp(S2, S1); /* S1 first, then S2 */
    show("S2 S1", V);
    double w = ga_mv_sp(V, ga_mv_reverse(V)); /* V ~V: a positive scalar */
    show("S2 S1 / sqrt(V ~V)", ga_mv_scale(V, 1 / sqrt(w)));
    ga_mv D;
    check(ga_versor_dilation(o, 4, &D), "ga_versor_dilation");
    show("dilation by 4", D);
    ga_mv Y;
    ga_vec3 y;
    if (ga_versor_apply(V, ga_point_up((ga_vec3){1, 2, 3}), &Y) != GA_OK || ga_point_down(Y, &y) != GA_OK)
        return 1;
    printf("%-20s (%g, %g, %g)\n", "(1, 2, 3) goes to", y.x, y.y, y.z);
    return 0;
}
