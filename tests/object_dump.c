/* tests/object_dump.c: objects of every kind, at distances 1 to 1e8 from
 * the origin, with what ga_object_from_mv reads of them, for
 * tests/object_exact.py, which reads the same coefficients again in exact
 * arithmetic and checks each GA_OK answer against its stated bounds.
 *
 * One line per object: a name, the 32 coefficients (%a, exactly), the status,
 * then kind, reality, centre, direction, r2, err, r2_err, angle_err (%a).
 * Scenes: constructed spheres (dual and from points), circles and point
 * pairs from points, planes, lines; meets of spheres (crossing, tangent,
 * missing), of a line and a sphere, a plane and a sphere, a line and a
 * plane; each at D = 1, 1e2, 1e4, 1e6, 1e8 with sizes log-uniform in 1..D.
 */
#include "testkit.h"

static ga_vec3 add(ga_vec3 a, ga_vec3 b) { return (ga_vec3){a.x + b.x, a.y + b.y, a.z + b.z}; }

static void dump(const char *name, double D, ga_mv X)
{
    ga_object o = {0};
    int st = ga_object_from_mv(X, &o);
    printf("%s %g", name, D);
    for (int i = 0; i < 32; i++) printf(" %a", X.c[i]);
    printf(" %d %d %d %a %a %a %a %a %a %a %a %a %a\n", st, o.kind, o.reality, o.centre.x, o.centre.y,
           o.centre.z, o.direction.x, o.direction.y, o.direction.z, o.r2, o.err, o.r2_err, o.angle_err);
}

int main(void)
{
    static const double dists[] = {1, 1e2, 1e4, 1e6, 1e8};
    tk_rng t = {tk_seed(2828)};
    for (int k = 0; k < 5; k++) {
        double D = dists[k];
        for (int i = 0; i < 60; i++) {
            double S = D == 1.0 ? tk_loguni(&t, 0.1, 1) : tk_loguni(&t, 1, D);
            ga_vec3 o = tk_scale(tk_unit(&t), D), c = add(o, tk_scale(tk_unit(&t), S * tk_uni(&t)));
            double r = S * tk_range(&t, 0.2, 1);
            ga_vec3 p[4];
            for (int j = 0; j < 4; j++) p[j] = add(c, tk_scale(tk_unit(&t), r));
            ga_vec3 e = tk_unit(&t);
            dump("sphere-dual", D, ga_sphere_dual(c, r));
            dump("sphere-points", D, ga_sphere_from_points(p[0], p[1], p[2], p[3]));
            dump("circle-points", D, ga_circle_from_points(p[0], p[1], p[2]));
            dump("pair-points", D, ga_pointpair_from_points(p[0], p[1]));
            dump("plane-points", D, ga_plane_from_points(p[0], p[1], p[2]));
            dump("line-points", D, ga_line_from_points(p[0], p[1]));
            double r2 = S * tk_range(&t, 0.2, 1);
            double dist[3] = {tk_range(&t, fabs(r - r2), r + r2), r + r2, (r + r2) * tk_range(&t, 1.1, 3)};
            for (int j = 0; j < 3; j++)
                dump("meet-spheres", D,
                     ga_mv_meet(ga_sphere_dual(c, r), ga_sphere_dual(add(c, tk_scale(e, dist[j])), r2)));
            ga_mv L = ga_line_from_points(add(c, tk_scale(e, 0.5 * r)),
                                          add(c, tk_scale(tk_unit(&t), 0.8 * r)));
            dump("meet-line-sphere", D, ga_mv_meet(L, ga_sphere_dual(c, r)));
            dump("meet-plane-sphere", D,
                 ga_mv_meet(ga_plane_from_points(p[0], p[1], p[3]), ga_sphere_dual(c, r)));
            dump("meet-line-plane", D, ga_mv_meet(L, ga_plane_from_points(p[0], p[1], p[2])));
        }
    }
    return 0;
}
