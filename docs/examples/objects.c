/* objects.c: spheres, planes, lines, circles and point pairs, built and read
 * back (docs/conformal.md, "Objects"). Build from the repository: cc -std=c11
 * -Iinclude -Ibuild/include docs/examples/objects.c build/libgarotor.a -lm -o objects */
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
    printf("%s = %s\n", what, text);
}

/* x + 0.0 is x, but -0 becomes 0: printf writes "-0" for a negative zero */
static ga_vec3 z(ga_vec3 v) { return (ga_vec3){v.x + 0.0, v.y + 0.0, v.z + 0.0}; }

int main(void)
{
    ga_vec3 c, m, p, a, b;
    double r, d;
    /* a sphere through four points (direct form, a 4-vector) */
    ga_mv S = ga_sphere_from_points((ga_vec3){1, 0, 0}, (ga_vec3){-1, 0, 0}, (ga_vec3){0, 1, 0},
                                    (ga_vec3){0, 0, 1});
    show("S", S);
    check(ga_sphere_params(S, &c, &r), "ga_sphere_params");
    c = z(c);
    printf("sphere S: centre (%g, %g, %g), radius %g\n", c.x, c.y, c.z, r);
    printf("F((0,-1,0)) ^ S: max |coefficient| = %g\n",
           ga_mv_maxabs(ga_mv_op(ga_point_up((ga_vec3){0, -1, 0}), S)));
    printf("F((0,0,2)) ^ S: max |coefficient| = %g\n",
           ga_mv_maxabs(ga_mv_op(ga_point_up((ga_vec3){0, 0, 2}), S)));
    /* a sphere as one vector (dual form) */
    ga_mv s = ga_sphere_dual((ga_vec3){1, 1, 1}, 2);
    show("s", s);
    printf("F((1,1,3)).s = %g, F((1,1,1)).s = %g\n", ga_mv_sp(ga_point_up((ga_vec3){1, 1, 3}), s),
           ga_mv_sp(ga_point_up((ga_vec3){1, 1, 1}), s));
    /* the flats: a plane and a line through points */
    check(ga_plane_params(ga_plane_from_points((ga_vec3){0, 0, 1}, (ga_vec3){1, 0, 1}, (ga_vec3){0, 1, 1}),
                          &m, &d),
          "ga_plane_params");
    m = z(m);
    printf("plane: normal (%g, %g, %g), distance %g\n", m.x, m.y, m.z, d);
    check(ga_line_params(ga_line_from_points((ga_vec3){1, 1, 0}, (ga_vec3){1, 1, 5}), &m, &p),
          "ga_line_params");
    m = z(m), p = z(p);
    printf("line: direction (%g, %g, %g), closest point (%g, %g, %g)\n", m.x, m.y, m.z, p.x, p.y, p.z);
    /* the rounds of lower grade */
    check(ga_circle_params(ga_circle_from_points((ga_vec3){1, 0, 0}, (ga_vec3){0, 1, 0}, (ga_vec3){-1, 0, 0}),
                           &c, &r, &m),
          "ga_circle_params");
    c = z(c), m = z(m);
    printf("circle: centre (%g, %g, %g), radius %g, normal (%g, %g, %g)\n", c.x, c.y, c.z, r, m.x, m.y, m.z);
    check(ga_pointpair_points(ga_pointpair_from_points((ga_vec3){0, 0, 0}, (ga_vec3){2, 0, 0}), &a, &b),
          "ga_pointpair_points");
    a = z(a), b = z(b);
    printf("point pair: (%g, %g, %g), (%g, %g, %g)\n", a.x, a.y, a.z, b.x, b.y, b.z);
    return 0;
}
