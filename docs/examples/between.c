/* between.c: the rotor between two objects of different size, and the
 * objects along it (docs/conformal.md, "More algebra"). Build from the
 * repository:
 * cc -std=c11 -Iinclude -Ibuild/include docs/examples/between.c
 * build/libgarotor.a -lm -o between */
#include <math.h>
#include <stdio.h>

#include <garotor/garotor.h>

/* a number as %.6g, with what is rounding below 1e-12 (and -0) shown as 0 */
static double clean(double v) { return fabs(v) < 1e-12 ? 0.0 : v; }

static void show(const char *what, ga_mv X)
{
    char text[GA_MV_TEXT_MAX];
    size_t len;
    for (int i = 0; i < 32; i++) X.c[i] = clean(X.c[i]);
    if (ga_mv_format(X, text, sizeof text, &len) == GA_OK)
        printf("%-22s %s\n", what, text);
}

static void object(const char *what, ga_mv X)
{
    static const char *const kind[] = {"empty",      "flat point", "line",  "plane",
                                       "point pair", "circle",     "sphere"};
    ga_object o;
    int st = ga_object_from_mv(X, &o);
    if (st != GA_OK) {
        printf("%-22s %s\n", what, ga_status_string(st));
        return;
    }
    printf("%-22s %s: centre (%.6g, %.6g, %.6g), radius %.6g", what, kind[o.kind], clean(o.centre.x),
           clean(o.centre.y), clean(o.centre.z), sqrt(o.r2));
    if (o.kind != GA_OBJECT_SPHERE)
        printf(", direction (%.6g, %.6g, %.6g)", clean(o.direction.x), clean(o.direction.y),
               clean(o.direction.z));
    printf("\n");
}

int main(void)
{
    /* A: the unit circle of the plane z = 0; B: a circle of radius 2 about
       (3, 2, 3) in the plane x = 3 */
    ga_mv A = ga_circle_from_points((ga_vec3){1, 0, 0}, (ga_vec3){0, 1, 0}, (ga_vec3){-1, 0, 0});
    ga_mv B = ga_circle_from_points((ga_vec3){3, 2, 1}, (ga_vec3){3, 4, 3}, (ga_vec3){3, 2, 5});
    object("A", A);
    object("B", B);
    ga_mv V, X;
    if (ga_versor_between(A, B, &V) != GA_OK)
        return 1;
    show("V", V);
    show("V ~V", ga_mv_gp(V, ga_mv_reverse(V)));
    if (ga_versor_apply(V, A, &X) == GA_OK)
        object("V A V^-1", X);
    for (int k = 1; k <= 3; k++) {
        char what[32];
        snprintf(what, sizeof what, "at t = %.2g", k / 4.0);
        if (ga_object_interp(A, B, k / 4.0, &X) == GA_OK)
            object(what, X);
    }
    /* spheres of radii 1 and 3: a dilation by 3 about their common point */
    ga_mv S1 = ga_mv_dual(ga_sphere_dual((ga_vec3){0, 0, 0}, 1)),
          S3 = ga_mv_dual(ga_sphere_dual((ga_vec3){2, 0, 0}, 3));
    if (ga_versor_between(S1, S3, &V) == GA_OK &&
        ga_versor_apply(V, ga_point_up((ga_vec3){-1, 0, 0}), &X) == GA_OK) {
        ga_vec3 p;
        if (ga_point_down(X, &p) == GA_OK)
            printf("%-22s (%.6g, %.6g, %.6g)\n", "(-1, 0, 0) moved to", clean(p.x), clean(p.y), clean(p.z));
    }
    ga_mv P = ga_mv_dual(ga_sphere_dual((ga_vec3){5, 0, 0}, 0));
    printf("%-22s %s\n", "sphere to a point", ga_status_string(ga_versor_between(S1, P, &V)));
    printf("%-22s %s\n", "sphere to a line",
           ga_status_string(ga_versor_between(S1, ga_line_from_points((ga_vec3){0, 0, 0}, (ga_vec3){1, 0, 0}),
                                              &V)));
    return 0;
}
