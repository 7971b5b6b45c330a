/* meet.c: meets, their kinds and read-back (docs/conformal.md, "Where objects
 * meet"). Build from the repository: cc -std=c11 -Iinclude -Ibuild/include
 * docs/examples/meet.c build/libgarotor.a -lm -o meet */
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

static const char *kind[] = {"empty", "flat point", "line", "plane", "point pair", "circle", "sphere"};
static const char *reality[] = {"real", "tangent", "imaginary"};

static void show(const char *what, ga_mv X)
{
    ga_object o;
    int st = ga_object_from_mv(X, &o);
    if (st != GA_OK) {
        printf("%-28s %s\n", what, ga_status_string(st));
        return;
    }
    printf("%-28s %s, %s: centre (%.6g, %.6g, %.6g)", what, kind[o.kind], reality[o.reality],
           o.centre.x + 0.0, o.centre.y + 0.0, o.centre.z + 0.0); /* + 0.0: no "-0" */
    if (o.kind >= GA_OBJECT_POINTPAIR)
        printf(", r^2 = %.6g", o.r2);
    if (o.kind != GA_OBJECT_SPHERE && o.kind != GA_OBJECT_FLATPOINT)
        printf(", direction (%.6g, %.6g, %.6g)", o.direction.x, o.direction.y, o.direction.z);
    printf("\n");
}

/* a round with the bounds its read-back states (object.h, "Accuracy") */
static void show_bounds(const char *what, ga_mv X)
{
    ga_object o;
    int st = ga_object_from_mv(X, &o);
    if (st != GA_OK) {
        printf("%-28s %s\n", what, ga_status_string(st));
        return;
    }
    printf("%-28s %s, %s: centre (%.6g, %.6g, %.6g) to %.2g, r^2 = %.6g to %.2g\n", what, kind[o.kind],
           reality[o.reality], o.centre.x + 0.0, o.centre.y + 0.0, o.centre.z + 0.0, o.err, o.r2, o.r2_err);
}

int main(void)
{
    ga_vec3 o = {0, 0, 0}, ex = {1, 0, 0}, ez = {0, 0, 1};
    ga_mv S1 = ga_sphere_dual(o, 1);
    show("sphere ^ sphere (d = 1.5)", ga_mv_meet(S1, ga_sphere_dual((ga_vec3){1.5, 0, 0}, 1)));
    show("sphere ^ sphere (d = 2)", ga_mv_meet(S1, ga_sphere_dual((ga_vec3){2, 0, 0}, 1)));
    show("sphere ^ sphere (d = 3)", ga_mv_meet(S1, ga_sphere_dual((ga_vec3){3, 0, 0}, 1)));
    ga_mv L = ga_line_from_points((ga_vec3){-5, 0.6, 0}, (ga_vec3){5, 0.6, 0});
    show("line y = 0.6 ^ sphere", ga_mv_meet(L, S1));
    show("line y = 0.6 ^ plane x = 2", ga_mv_meet(L, ga_plane_dual(ex, 2)));
    show("plane z = 0 ^ plane z = 1", ga_mv_meet(ga_plane_dual(ez, 0), ga_plane_dual(ez, 1)));
    show("plane z = 1e5 from points",
         ga_plane_from_points((ga_vec3){0, 0, 1e5}, (ga_vec3){1, 0, 1e5}, (ga_vec3){0, 1, 1e5}));
    show_bounds("sphere r = 50 at 100", ga_sphere_dual((ga_vec3){100, 0, 0}, 50));
    show_bounds("unit sphere at 1e4", ga_sphere_dual((ga_vec3){1e4, 0, 0}, 1));
    show_bounds("unit sphere at 1e8", ga_sphere_dual((ga_vec3){1e8, 0, 0}, 1));
    ga_vec3 p;
    double d;
    check(ga_point_project((ga_vec3){3, 4, 0}, S1, &p), "ga_point_project");
    check(ga_point_distance((ga_vec3){3, 4, 0}, S1, &d), "ga_point_distance");
    printf("(3, 4, 0) onto the unit sphere: (%.6g, %.6g, %.6g), distance %.6g\n", p.x, p.y, p.z, d);
    ga_rotor R;
    check(ga_rotor_between(ga_plane_dual(ez, 0), ga_plane_dual(ex, 2), &R), "ga_rotor_between");
    ga_vec3 q = ga_rotor_apply(R, (ga_vec3){0, 0, 0});
    printf("rotor from z = 0 to x = 2 takes the origin to (%.6g, %.6g, %.6g)\n", q.x, q.y, q.z);
    return 0;
}
