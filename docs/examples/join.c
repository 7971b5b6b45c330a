/* join.c: joins, and meets of objects in special position (docs/conformal.md,
 * "Join, and meets of objects in special position"). Build from the
 * repository: cc -std=c11 -Iinclude -Ibuild/include docs/examples/join.c
 * build/libgarotor.a -lm -o join */
#include <math.h>
#include <stdio.h>

#include <garotor/garotor.h>

static const char *kind[] = {"empty", "flat point", "line", "plane", "point pair", "circle", "sphere"};
static const char *reality[] = {"real", "tangent", "imaginary"};

/* a number as %.6g, with what is rounding below 1e-12 (and -0) shown as 0 */
static double clean(double v) { return fabs(v) < 1e-12 ? 0.0 : v; }

static void show(const char *what, int st, ga_mv X)
{
    ga_object o;
    ga_vec3 x;
    if (st == GA_OK && ga_mv_maxabs(ga_mv_sub(X, ga_mv_grade(X, 0))) == 0.0) {
        printf("%-28s a scalar (no common point)\n", what);
        return;
    }
    if (st == GA_OK && ga_mv_maxabs(ga_mv_sub(X, ga_mv_grade(X, 5))) == 0.0) {
        printf("%-28s a pseudoscalar (the whole space)\n", what);
        return;
    }
    if (st == GA_OK && ga_point_down(X, &x) == GA_OK) { /* a vector: a point */
        printf("%-28s point (%.6g, %.6g, %.6g)\n", what, clean(x.x), clean(x.y), clean(x.z));
        return;
    }
    if (st == GA_OK)
        st = ga_object_from_mv(X, &o);
    if (st != GA_OK) {
        printf("%-28s %s\n", what, ga_status_string(st));
        return;
    }
    printf("%-28s %s", what, kind[o.kind]);
    if (o.kind >= GA_OBJECT_POINTPAIR)
        printf(" (%s)", reality[o.reality]);
    printf(": centre (%.6g, %.6g, %.6g)", clean(o.centre.x), clean(o.centre.y), clean(o.centre.z));
    if (o.kind >= GA_OBJECT_POINTPAIR)
        printf(", r^2 = %.6g", clean(o.r2));
    if (o.kind != GA_OBJECT_SPHERE && o.kind != GA_OBJECT_FLATPOINT && o.kind != GA_OBJECT_EMPTY)
        printf(", direction (%.6g, %.6g, %.6g)", clean(o.direction.x), clean(o.direction.y),
               clean(o.direction.z));
    printf("\n");
}

/* the join and the meet of A and B, one line each */
static void both(const char *what, ga_mv A, ga_mv B)
{
    char line[64];
    ga_mv J, M;
    int st = ga_mv_join(A, B, &J);
    snprintf(line, sizeof line, "join %s", what);
    show(line, st, J);
    st = ga_mv_meet_rel(A, B, &M);
    snprintf(line, sizeof line, "meet %s", what);
    show(line, st, M);
}

int main(void)
{
    ga_vec3 p = {1, 2, 3};
    ga_mv L1 = ga_line_from_points(p, (ga_vec3){2, 2, 3}); /* along x through p */
    ga_mv L2 = ga_line_from_points(p, (ga_vec3){1, 3, 4}); /* along (0, 1, 1) through p */
    both("two lines", L1, L2);
    both("point on L1, L1", ga_point_up((ga_vec3){4, 2, 3}), L1);
    both("point off L1, L1", ga_point_up((ga_vec3){4, 2, 5}), L1);
    /* circles in the plane z = 0: the unit circle, and circles of radius 1
       about (1, 0, 0), (2, 0, 0) and (3, 0, 0) */
    ga_mv C = ga_circle_from_points((ga_vec3){1, 0, 0}, (ga_vec3){0, 1, 0}, (ga_vec3){-1, 0, 0});
    for (int k = 1; k <= 3; k++) {
        char what[32];
        double c = k;
        snprintf(what, sizeof what, "C, circle at (%d, 0, 0)", k);
        both(what, C,
             ga_circle_from_points((ga_vec3){c + 1, 0, 0}, (ga_vec3){c, 1, 0}, (ga_vec3){c - 1, 0, 0}));
    }
    ga_mv S = ga_mv_dual(ga_sphere_dual((ga_vec3){0, 0, 0}, 1)); /* the unit sphere, direct */
    both("C, circle x = 0 on S", C,
         ga_circle_from_points((ga_vec3){0, 0, 1}, (ga_vec3){0, 1, 0}, (ga_vec3){0, 0, -1}));
    both("C, S", C, S);
    ga_mv P = ga_mv_dual(ga_plane_dual((ga_vec3){0, 0, 1}, 0)); /* z = 0, direct */
    both("z = 0, itself", P, P);
    both("z = 0, x = 2", P, ga_mv_dual(ga_plane_dual((ga_vec3){1, 0, 0}, 2)));
    ga_mv out;
    printf("%-28s %s\n", "join L1, a scalar", ga_status_string(ga_mv_join(L1, ga_mv_scalar(1), &out)));
    return 0;
}
