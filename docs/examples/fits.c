/* fits.c: least-squares spheres, circles, planes and lines through points
 * (docs/conformal.md, "More algebra"). Build from the repository:
 * cc -std=c11 -Iinclude -Ibuild/include docs/examples/fits.c
 * build/libgarotor.a -lm -o fits */
#include <math.h>
#include <stdio.h>

#include <garotor/garotor.h>

static double clean(double v) { return fabs(v) < 1e-12 ? 0.0 : v; }

int main(void)
{
    /* the 8 corners of a cube of side 2 about (1, 2, 3), at sqrt(3) =
       1.73205 from its centre, moved along their diagonals, 4 of them out by
       0.01 and 4 in (a corner and its 3 neighbours never both out): the
       geometric fit is the sphere of radius sqrt(3) about (1, 2, 3) */
    ga_vec3 p[8];
    for (int i = 0; i < 8; i++) {
        int out = ((i & 1) ^ (i >> 1 & 1) ^ (i >> 2 & 1)) != 0;
        double s = 1 + (out ? 0.01 : -0.01) / sqrt(3);
        p[i] = (ga_vec3){1 + s * (i & 1 ? 1 : -1), 2 + s * (i & 2 ? 1 : -1), 3 + s * (i & 4 ? 1 : -1)};
    }
    ga_vec3 c, n, u, q;
    double r, d;
    if (ga_fit_sphere(p, 8, &c, &r) == GA_OK)
        printf("sphere: centre (%.6g, %.6g, %.6g), radius %.6g\n", c.x, c.y, c.z, r);
    /* 6 points of the circle of radius 5 about (10, 0, 0) in the plane
       x + y + z = 10 (normal (1, 1, 1)/sqrt(3)) */
    ga_vec3 e1 = {1 / sqrt(2), -1 / sqrt(2), 0}, e2 = {1 / sqrt(6), 1 / sqrt(6), -2 / sqrt(6)}, ring[6];
    for (int i = 0; i < 6; i++) {
        double a = i * 3.14159265358979323846 / 3;
        ring[i] = (ga_vec3){10 + 5 * (cos(a) * e1.x + sin(a) * e2.x), 5 * (cos(a) * e1.y + sin(a) * e2.y),
                            5 * (cos(a) * e1.z + sin(a) * e2.z)};
    }
    if (ga_fit_circle(ring, 6, &c, &r, &n) == GA_OK)
        printf("circle: centre (%.6g, %.6g, %.6g), radius %.6g, normal (%.6g, %.6g, %.6g)\n", clean(c.x),
               clean(c.y), clean(c.z), r, n.x, n.y, n.z);
    if (ga_fit_plane(ring, 6, &n, &d) == GA_OK)
        printf("plane:  normal (%.6g, %.6g, %.6g), distance %.6g\n", n.x, n.y, n.z, d);
    /* points near the line through (0, 1, 0) along (1, 0, 0), off it by
       +-0.1 in y and z */
    ga_vec3 line[4] = {{0, 1.1, 0}, {1, 0.9, 0}, {2, 1, 0.1}, {3, 1, -0.1}};
    if (ga_fit_line(line, 4, &u, &q) == GA_OK)
        printf("line:   direction (%.6g, %.6g, %.6g), nearest the origin (%.6g, %.6g, %.6g)\n", u.x,
               clean(u.y), clean(u.z), clean(q.x), q.y, clean(q.z));
    /* four points in a plane fit no sphere */
    ga_vec3 flat[4] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
    printf("sphere through 4 coplanar points: %s\n", ga_status_string(ga_fit_sphere(flat, 4, &c, &r)));
    return 0;
}
