/* ex_maps.c: docs/exercises.md, exercise 9: a reflection and a dilation on
 * whole objects. Build from the repository: cc -std=c11 -Iinclude
 * -Ibuild/include docs/examples/ex_maps.c build/libgarotor.a -lm -o ex_maps */
#include <stdio.h>

#include <garotor/garotor.h>

static const char *kind[] = {"empty", "flat point", "line", "plane", "point pair", "circle", "sphere"};

/* V X^ V^-1, read back; + 0.0 turns "-0" into "0" */
static void show(const char *what, ga_mv V, ga_mv X)
{
    ga_mv Y;
    ga_object o;
    if (ga_versor_apply(V, X, &Y) != GA_OK || ga_object_from_mv(Y, &o) != GA_OK) {
        printf("%-31s no image\n", what);
        return;
    }
    printf("%-31s %s: centre (%.6g, %.6g, %.6g)", what, kind[o.kind], o.centre.x + 0.0, o.centre.y + 0.0,
           o.centre.z + 0.0);
    if (o.kind == GA_OBJECT_SPHERE)
        printf(", r^2 = %.6g\n", o.r2);
    else
        printf(", direction (%.6g, %.6g, %.6g)\n", o.direction.x + 0.0, o.direction.y + 0.0,
               o.direction.z + 0.0);
}

int main(void)
{
    /* the mirror x + y = 2 (the normal need not be a unit vector) */
    ga_mv M = ga_versor_reflection((ga_vec3){1, 1, 0}, 2);
    show("mirror: sphere (3, 2, 0), 1", M, ga_sphere_dual((ga_vec3){3, 2, 0}, 1));
    show("mirror: line x = 2, z = 0", M, ga_line_from_points((ga_vec3){2, 0, 0}, (ga_vec3){2, 1, 0}));
    /* the dilation about c = (1, 1, 0) by 1/2 */
    ga_vec3 c = {1, 1, 0};
    ga_mv D;
    if (ga_versor_dilation(c, 0.5, &D) != GA_OK)
        return 1;
    printf("%-31s %.12g\n", "dilation: D ~D", ga_mv_sp(D, ga_mv_reverse(D)));
    show("dilation: sphere (3, 1, 0), 1", D, ga_sphere_dual((ga_vec3){3, 1, 0}, 1));
    show("dilation: plane x = 3", D, ga_plane_dual((ga_vec3){1, 0, 0}, 3));
    show("dilation: line y = 1, z = 0", D, ga_line_from_points((ga_vec3){0, 1, 0}, (ga_vec3){1, 1, 0}));
    return 0;
}
