/* ex_meets.c: docs/exercises.md, exercise 8: real, tangent and imaginary
 * meets. Build from the repository: cc -std=c11 -Iinclude -Ibuild/include
 * docs/examples/ex_meets.c build/libgarotor.a -lm -o ex_meets */
#include <stdio.h>

#include <garotor/garotor.h>

static const char *kind[] = {"empty", "flat point", "line", "plane", "point pair", "circle", "sphere"};
static const char *reality[] = {"real", "tangent", "imaginary"};

static void show(const char *what, ga_mv M)
{
    ga_object o;
    double d;
    int st = ga_object_from_mv(M, &o);
    if (st != GA_OK) {
        printf("%-20s %s\n", what, ga_status_string(st));
        return;
    }
    printf("%-20s %s, %s: centre (%g, %g, %g), r^2 = %g", what, kind[o.kind], reality[o.reality],
           o.centre.x + 0.0, o.centre.y + 0.0, o.centre.z + 0.0, o.r2 + 0.0);
    /* a question about its points: how far is (3, 0, 0.5) from it? */
    st = ga_point_distance((ga_vec3){3, 0, 0.5}, M, &d);
    if (st == GA_OK)
        printf("; (3, 0, 0.5) at %g\n", d);
    else
        printf("; distance: %s\n", ga_status_string(st));
}

int main(void)
{
    ga_mv S = ga_sphere_dual((ga_vec3){0, 0, 0}, 1), ez = ga_plane_dual((ga_vec3){0, 0, 1}, 0);
    ga_vec3 up = {0, 0, 1};
    show("plane z = 0.5", ga_mv_meet(S, ga_plane_dual(up, 0.5)));
    show("plane z = 1", ga_mv_meet(S, ga_plane_dual(up, 1)));
    show("plane z = 2", ga_mv_meet(S, ga_plane_dual(up, 2)));
    show("line y = 0.6, z = 0",
         ga_mv_meet(ga_line_from_points((ga_vec3){0, 0.6, 0}, (ga_vec3){1, 0.6, 0}), S));
    show("line y = 1, z = 0", ga_mv_meet(ga_line_from_points((ga_vec3){0, 1, 0}, (ga_vec3){1, 1, 0}), S));
    show("line y = 2, z = 0", ga_mv_meet(ga_line_from_points((ga_vec3){0, 2, 0}, (ga_vec3){1, 2, 0}), S));
    show("z = 0 with itself", ga_mv_meet(ez, ez));
    return 0;
}
