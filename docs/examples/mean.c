/* mean.c: the weighted mean of objects of one kind (docs/conformal.md,
 * "More algebra"). Build from the repository:
 * cc -std=c11 -Iinclude -Ibuild/include docs/examples/mean.c
 * build/libgarotor.a -lm -o mean */
#include <math.h>
#include <stdio.h>

#include <garotor/garotor.h>

/* a number as %.6g, with what is rounding below 1e-12 (and -0) shown as 0 */
static double clean(double v) { return fabs(v) < 1e-12 ? 0.0 : v; }

static void object(const char *what, int st, ga_mv X)
{
    static const char *const kind[] = {"empty",      "flat point", "line",  "plane",
                                       "point pair", "circle",     "sphere"};
    ga_object o;
    if (st == GA_OK)
        st = ga_object_from_mv(X, &o);
    if (st != GA_OK) {
        printf("%-24s %s\n", what, ga_status_string(st));
        return;
    }
    printf("%-24s %s: centre (%.6g, %.6g, %.6g)", what, kind[o.kind], clean(o.centre.x), clean(o.centre.y),
           clean(o.centre.z));
    if (o.kind >= GA_OBJECT_POINTPAIR)
        printf(", r^2 %.6g", clean(o.r2));
    if (o.kind != GA_OBJECT_SPHERE)
        printf(", direction (%.6g, %.6g, %.6g)", clean(o.direction.x), clean(o.direction.y),
               clean(o.direction.z));
    printf("\n");
}

int main(void)
{
    ga_vec3 o = {0, 0, 0}, ez = {0, 0, 1};
    ga_mv X;
    /* spheres of radii 1 and 4 about one centre: r^2 = AM HM = 2.5 * 1.6 = 4,
       the geometric mean 2 of the radii, as ga_object_interp at t = 1/2 */
    ga_mv S[2] = {ga_sphere_dual(o, 1), ga_sphere_dual(o, 4)};
    object("radii 1, 4", ga_object_mean(S, NULL, 2, &X), X);
    object("interp at 1/2", ga_object_interp(S[0], S[1], 0.5, &X), X);
    /* spheres of radius 1 centred 1 apart: a smaller sphere through the
       circle they share, r^2 = 1 - 1/4 */
    ga_mv T[2] = {ga_sphere_dual(o, 1), ga_sphere_dual((ga_vec3){1, 0, 0}, 1)};
    object("radius 1, 1 apart", ga_object_mean(T, NULL, 2, &X), X);
    /* weights 3 : 1 */
    object("the same, 3 : 1", ga_object_mean(T, (double[]){3, 1}, 2, &X), X);
    /* the planes z = 0 and x = 0: the bisecting plane */
    ga_mv P[2] = {ga_plane_dual(ez, 0), ga_plane_dual((ga_vec3){1, 0, 0}, 0)};
    object("planes z = 0, x = 0", ga_object_mean(P, NULL, 2, &X), X);
    /* three noisy estimates of the line through (0, 0, 1) along x */
    ga_mv L[3] = {ga_line_from_points((ga_vec3){0, 0, 1}, (ga_vec3){1, 0.01, 1}),
                  ga_line_from_points((ga_vec3){0, 0.02, 1.01}, (ga_vec3){1, 0, 0.99}),
                  ga_line_from_points((ga_vec3){0, -0.02, 0.99}, (ga_vec3){1, -0.01, 1.01})};
    object("three lines", ga_object_mean(L, NULL, 3, &X), X);
    /* what has no mean */
    ga_mv Q[2] = {ga_plane_dual(ez, 1), ga_plane_dual((ga_vec3){0, 0, -1}, 1)};
    object("opposite planes", ga_object_mean(Q, NULL, 2, &X), X);
    ga_mv M[2] = {S[0], P[0]};
    object("a sphere and a plane", ga_object_mean(M, NULL, 2, &X), X);
    return 0;
}
