/* ex_inversion.c: docs/exercises.md, exercise 6: the image of a line under an
 * inversion. Build from the repository: cc -std=c11 -Iinclude -Ibuild/include
 * docs/examples/ex_inversion.c build/libgarotor.a -lm -o ex_inversion */
#include <stdio.h>

#include <garotor/garotor.h>

static const char *kind[] = {"empty", "flat point", "line", "plane", "point pair", "circle", "sphere"};

int main(void)
{
    ga_mv V = ga_versor_inversion((ga_vec3){0, 0, 0}, 2); /* centre 0, radius 2 */
    ga_vec3 a = {1, 0, 0}, b = {1, 1, 0};
    ga_mv L = ga_line_from_points(a, b), C; /* the line x = 1, z = 0 */
    ga_object o;
    if (ga_versor_apply(V, L, &C) != GA_OK || ga_object_from_mv(C, &o) != GA_OK)
        return 1;
    printf("image of the line: %s, centre (%g, %g, %g), r^2 = %g, normal (%g, %g, %g)\n", kind[o.kind],
           o.centre.x + 0.0, o.centre.y + 0.0, o.centre.z + 0.0, o.r2, o.direction.x + 0.0,
           o.direction.y + 0.0, o.direction.z);
    /* the images of a and b, point by point, and their distance from the circle */
    const ga_vec3 *p[] = {&a, &b};
    for (int i = 0; i < 2; i++) {
        ga_mv Y;
        ga_vec3 y;
        double d;
        if (ga_versor_apply(V, ga_point_up(*p[i]), &Y) != GA_OK || ga_point_down(Y, &y) != GA_OK ||
            ga_point_distance(y, C, &d) != GA_OK)
            return 1;
        printf("(%g, %g, %g) goes to (%g, %g, %g), at distance %g from the image\n", p[i]->x, p[i]->y,
               p[i]->z, y.x, y.y, y.z + 0.0, d);
    }
    return 0;
}
