/* versors.c: reflection, inversion, dilation and transversion as versors,
 * acting on points and on whole objects (docs/versors.md, "Versors"). Build
 * from the repository: cc -std=c11 -Iinclude -Ibuild/include
 * docs/examples/versors.c build/libgarotor.a -lm -o versors */
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

static void show_mv(const char *what, ga_mv x)
{
    char text[GA_MV_TEXT_MAX];
    size_t len;
    check(ga_mv_format(x, text, sizeof text, &len), "ga_mv_format");
    printf("%-34s %s\n", what, text);
}

/* V X^ V^-1, read back as an object; + 0.0 turns "-0" into "0" */
static void show(const char *what, ga_mv V, ga_mv X)
{
    ga_mv Y;
    ga_object o;
    int st = ga_versor_apply(V, X, &Y);
    if (st == GA_OK)
        st = ga_object_from_mv(Y, &o);
    if (st != GA_OK) {
        printf("%-34s %s\n", what, ga_status_string(st));
        return;
    }
    printf("%-34s %s: centre (%.6g, %.6g, %.6g)", what, kind[o.kind], o.centre.x + 0.0, o.centre.y + 0.0,
           o.centre.z + 0.0);
    if (o.kind >= GA_OBJECT_POINTPAIR)
        printf(", r^2 = %.6g", o.r2 + 0.0);
    if (o.kind != GA_OBJECT_SPHERE)
        printf(", direction (%.6g, %.6g, %.6g)", o.direction.x + 0.0, o.direction.y + 0.0,
               o.direction.z + 0.0);
    printf("\n");
}

/* V applied to the point x, read back with ga_point_down */
static void show_point(const char *what, ga_mv V, ga_vec3 x)
{
    ga_mv Y;
    ga_vec3 y;
    int st = ga_versor_apply(V, ga_point_up(x), &Y);
    if (st == GA_OK)
        st = ga_point_down(Y, &y);
    if (st != GA_OK)
        printf("%-34s %s\n", what, ga_status_string(st));
    else
        printf("%-34s (%.6g, %.6g, %.6g)\n", what, y.x + 0.0, y.y + 0.0, y.z + 0.0);
}

int main(void)
{
    ga_vec3 ex = {1, 0, 0}, ey = {0, 1, 0}, o = {0, 0, 0};
    /* a reflection is one vector: the dual plane x = 1 */
    ga_mv M = ga_versor_reflection(ex, 1);
    show_mv("reflection in x = 1", M);
    show_point("  (3, 2, 0)", M, (ga_vec3){3, 2, 0});
    show("  sphere centre (3, 2, 0), r = 1", M, ga_sphere_dual((ga_vec3){3, 2, 0}, 1));
    /* two reflections: in parallel planes a translation, in crossing planes a rotation */
    show_mv("x = 1 after x = 0", ga_mv_gp(M, ga_versor_reflection(ex, 0)));
    show_mv("translation by (2, 0, 0)", ga_versor_translation((ga_vec3){2, 0, 0}));
    ga_mv R = ga_mv_gp(ga_versor_reflection((ga_vec3){-0.70710678118654752, 0.70710678118654752, 0}, 0),
                       ga_versor_reflection(ey, 0));
    show_mv("x = y after y = 0", R);
    show_point("  (1, 0, 0)", R, ex);
    /* an inversion is one vector too: the dual sphere */
    ga_mv S = ga_versor_inversion(o, 1);
    show_mv("inversion in the unit sphere", S);
    show_point("  (2, 0, 0)", S, (ga_vec3){2, 0, 0});
    show_point("  (0, 0, 0)", S, o);
    show("  line x = 2, z = 0", S, ga_line_from_points((ga_vec3){2, 0, 0}, (ga_vec3){2, 1, 0}));
    show("  plane x = 2", S, ga_plane_dual(ex, 2));
    show("  sphere centre (3, 0, 0), r = 1", S, ga_sphere_dual((ga_vec3){3, 0, 0}, 1));
    /* a dilation and a transversion are rotors (even) */
    ga_mv D;
    check(ga_versor_dilation((ga_vec3){1, 1, 0}, 3, &D), "ga_versor_dilation");
    show_mv("dilation about (1, 1, 0) by 3", D);
    show("  sphere centre (2, 1, 0), r = 0.5", D, ga_sphere_dual((ga_vec3){2, 1, 0}, 0.5));
    ga_mv T = ga_versor_transversion((ga_vec3){0.5, 0, 0});
    show_mv("transversion b = (0.5, 0, 0)", T);
    show_point("  (1, 0, 0)", T, ex);
    show_point("  (2, 0, 0)", T, (ga_vec3){2, 0, 0});
    return 0;
}
