/* tests/test_object_kinds.c: the rotor between a round and a flat of one
 * grade (ga_versor_between, object.h: sphere <-> plane, circle <-> line,
 * point pair <-> flat point).
 *
 *   kinds     seeded random real rounds (radius 0.1 to 10, centre up to 1,
 *             10 or 100 from the origin) and flats (through a point as far
 *             out, random direction), built from points, each pair both
 *             ways: V ~V = 1 to the rounding of V's coefficients; A moved
 *             by V is a positive multiple of B (coefficient dot product);
 *             and, independent of any read-back, sample points x of A moved
 *             by V (ga_point_up, ga_versor_apply, ga_point_down) lie on B to
 *             1e-12 max(L, |y|) |V|^2 max(1, |x|)^2 (the sandwich's
 *             rounding, |V| the largest coefficient; images beyond 4 L,
 *             points next to the one sent to infinity, are skipped); GA_OK
 *             exactly where A and B read back to GA_OBJECT_TOL (the status
 *             of ga_rotor_between of each with itself otherwise)
 *   refusals  grades that differ (GA_ERR_ARG), a tangent round (radius 0)
 *             and a flat (GA_ERR_DOMAIN), an imaginary round
 */
#include "testkit.h"

static ga_vec3 add(ga_vec3 a, ga_vec3 b) { return (ga_vec3){a.x + b.x, a.y + b.y, a.z + b.z}; }
static ga_vec3 sub(ga_vec3 a, ga_vec3 b) { return (ga_vec3){a.x - b.x, a.y - b.y, a.z - b.z}; }
static ga_vec3 cross(ga_vec3 a, ga_vec3 b)
{
    return (ga_vec3){a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
static double dot(ga_vec3 a, ga_vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static ga_vec3 unit(ga_vec3 a) { return tk_scale(a, 1.0 / tk_norm(a)); }

/* grade g: 0 sphere / plane, 1 circle / line, 2 point pair / flat point;
   centre c, unit w (circle normal, line direction, pair axis, plane normal),
   e1, e2 unit and perpendicular to w, radius r */
typedef struct {
    int g;
    ga_vec3 c, w, e1, e2;
    double r;
} obj;

static ga_vec3 on_round(const obj *o, double a, double b)
{
    if (o->g == 0)
        return add(o->c, tk_scale((ga_vec3){cos(a) * cos(b), sin(a) * cos(b), sin(b)}, o->r));
    if (o->g == 1)
        return add(o->c, add(tk_scale(o->e1, o->r * cos(a)), tk_scale(o->e2, o->r * sin(a))));
    return add(o->c, tk_scale(o->w, a > 0 ? o->r : -o->r));
}
static ga_vec3 on_flat(const obj *o, double a, double b)
{
    if (o->g == 0)
        return add(o->c, add(tk_scale(o->e1, a), tk_scale(o->e2, b)));
    if (o->g == 1)
        return add(o->c, tk_scale(o->w, a));
    return o->c;
}
/* the distance from x to the round or flat o */
static double dist(const obj *o, int round, ga_vec3 x)
{
    ga_vec3 d = sub(x, o->c);
    if (round) {
        if (o->g == 0)
            return fabs(tk_norm(d) - o->r);
        if (o->g == 1) {
            double h = dot(d, o->w);
            return hypot(tk_norm(sub(d, tk_scale(o->w, h))) - o->r, h);
        }
        return fmin(tk_norm(sub(d, tk_scale(o->w, o->r))), tk_norm(add(d, tk_scale(o->w, o->r))));
    }
    if (o->g == 0)
        return fabs(dot(d, o->w));
    if (o->g == 1)
        return tk_norm(cross(d, o->w));
    return tk_norm(d);
}
static ga_mv build(const obj *o, int round)
{
    if (round) {
        if (o->g == 0)
            return ga_sphere_from_points(on_round(o, 0.3, 0.2), on_round(o, 2.1, -0.5), on_round(o, 4.0, 0.9),
                                         on_round(o, 5.0, -1.2));
        if (o->g == 1)
            return ga_circle_from_points(on_round(o, 0.3, 0), on_round(o, 2.5, 0), on_round(o, 4.4, 0));
        return ga_pointpair_from_points(on_round(o, -1, 0), on_round(o, 1, 0));
    }
    if (o->g == 0)
        return ga_plane_from_points(o->c, add(o->c, o->e1), add(o->c, o->e2));
    if (o->g == 1)
        return ga_line_from_points(o->c, add(o->c, o->w));
    return ga_mv_op(ga_point_up(o->c), ga_mv_n());
}
static obj random_obj(tk_rng *t, int g, double D)
{
    obj o;
    o.g = g;
    ga_vec3 u = tk_unit(t); /* then the distance: one draw per statement */
    o.c = tk_scale(u, tk_range(t, 0, D));
    o.w = tk_unit(t);
    o.e1 = unit(cross(o.w, tk_unit(t)));
    o.e2 = cross(o.w, o.e1);
    o.r = tk_loguni(t, 0.1, 10);
    return o;
}

static const char *const names[3] = {"sphere <-> plane", "circle <-> line", "point pair <-> flat point"};

static void section_kinds(void)
{
    static const double D[3] = {1, 10, 100};
    for (int g = 0; g < 3; g++) {
        tk_rng t = tk_rng_after(tk_seed(0x6b696e64), (uint64_t)g);
        tk_check vv = tk_beginf(1e-13, "%s: V ~V = 1 (over |V|^2)", names[g]);
        tk_check pts = tk_beginf(1e-12, "%s: sample points of A moved onto B (over the sandwich's rounding)",
                                 names[g]);
        tk_check sign = tk_beginf(0, "%s: V A V^-1 a positive multiple of B", names[g]);
        tk_check st = tk_beginf(0, "%s: GA_OK exactly where A and B read back", names[g]);
        int nok = 0;
        for (int i = 0; i < 3 * 60; i++) {
            double Dm = D[i % 3];
            obj R = random_obj(&t, g, Dm), F = random_obj(&t, g, Dm);
            for (int dir = 0; dir < 2; dir++) {
                ga_mv A = dir ? build(&F, 0) : build(&R, 1), B = dir ? build(&R, 1) : build(&F, 0), V, X;
                ga_rotor Q;
                int want = ga_rotor_between(A, A, &Q);
                if (want == GA_OK)
                    want = ga_rotor_between(B, B, &Q);
                int got = ga_versor_between(A, B, &V);
                tk_add_status(&st, got, want);
                if (got != GA_OK)
                    continue;
                nok++;
                double vm = tk_mv_maxabs(V);
                ga_mv W = ga_mv_gp(V, ga_mv_reverse(V));
                W.c[0] -= 1.0;
                tk_add(&vv, tk_mv_maxabs(W) / (vm * vm));
                TK_OK(ga_versor_apply(V, A, &X));
                double k = 0.0;
                for (int j = 0; j < 32; j++) k += X.c[j] * B.c[j];
                tk_add_bool(&sign, k > 0.0);
                double L = fmax(1.0, fmax(tk_norm(R.c) + R.r, tk_norm(F.c)));
                for (int s = 0; s < 6; s++) {
                    double a = tk_range(&t, -3, 3), b = tk_range(&t, -1.5, 1.5);
                    ga_vec3 x = dir ? on_flat(&F, a * R.r, b * R.r) : on_round(&R, a, b), y;
                    ga_mv Y;
                    TK_OK(ga_versor_apply(V, ga_point_up(x), &Y));
                    if (ga_point_down(Y, &y) != GA_OK || tk_norm(y) > 4.0 * L)
                        continue; /* next to the point sent to infinity */
                    double xs = fmax(1.0, tk_norm(x));
                    tk_add(&pts, dist(dir ? &R : &F, dir, y) / (fmax(L, tk_norm(y)) * vm * vm * xs * xs));
                }
            }
        }
        tk_end(&vv);
        tk_end(&pts);
        tk_end(&sign);
        tk_end(&st);
        tk_note("%s: %d of %d pairs answered GA_OK\n", names[g], nok, 2 * 3 * 60);
    }
}

static void section_refusals(void)
{
    ga_vec3 o = {0, 0, 0}, ex = {1, 0, 0}, ez = {0, 0, 1};
    ga_mv V = ga_mv_zero(), S = ga_mv_dual(ga_sphere_dual(o, 1)), P = ga_mv_dual(ga_plane_dual(ez, 1));
    ga_mv Ln = ga_line_from_points(o, ex),
          C = ga_circle_from_points(ex, (ga_vec3){0, 1, 0}, (ga_vec3){-1, 0, 0});
    tk_expect_status("a sphere and a line", ga_versor_between(S, Ln, &V), GA_ERR_ARG);
    tk_expect_status("a circle and a plane", ga_versor_between(C, P, &V), GA_ERR_ARG);
    tk_expect_status("a plane and a line", ga_versor_between(P, Ln, &V), GA_ERR_ARG);
    tk_expect_status("a sphere and a circle", ga_versor_between(S, C, &V), GA_ERR_ARG);
    tk_expect_status("a point (radius 0) and a plane",
                     ga_versor_between(ga_mv_dual(ga_sphere_dual(ex, 0)), P, &V), GA_ERR_DOMAIN);
    tk_expect_status("a plane and a point", ga_versor_between(P, ga_mv_dual(ga_sphere_dual(ex, 0)), &V),
                     GA_ERR_DOMAIN);
    ga_mv Ci = ga_mv_meet(ga_sphere_dual(o, 1), ga_sphere_dual((ga_vec3){3, 0, 0}, 1));
    tk_expect_status("an imaginary circle and a line", ga_versor_between(Ci, Ln, &V), GA_ERR_IMAGINARY);
    tk_expect_status("nothing written on failure", tk_mv_maxabs(V) == 0.0 ? GA_OK : GA_ERR_ARG, GA_OK);
    tk_expect_status("the unit sphere and the plane z = 1", ga_versor_between(S, P, &V), GA_OK);
    tk_expect_status("interp: kinds differ", ga_object_interp(S, P, 0.5, &V), GA_ERR_ARG);
}

static const tk_section sections[] = {
    {"kinds", section_kinds, 0},
    {"refusals", section_refusals, 0},
};

int main(int argc, char **argv)
{
    return tk_main(argc, argv, "test_object_kinds", sections, TK_COUNT(sections));
}
