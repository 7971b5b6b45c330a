/* tests/test_object_between.c: the rotor between two objects of different
 * size (ga_versor_between) and the objects along it (ga_object_interp),
 * object.h.
 *
 *   between   random objects of every kind with a centre up to 1e2 from the
 *             origin and a size 1e-2 to 1e2, and a copy moved by a random
 *             similarity (a rotation, a dilation by 0.1 to 10, a
 *             translation), built from the moved points: V A V^-1
 *             (ga_versor_apply) read back is B to max(1e-12, 64 u L) of
 *             the scene, L of A and B (the centre, r^2 over L^2, the
 *             direction in radians, with its orientation), and V ~V = 1 to
 *             1e-14 |V|^2; the same with the copy of the same size, against
 *             ga_rotor_between's motion
 *   refusals  what has no such rotor: kinds that differ, a point (tangent
 *             round) and a real round, an imaginary round, an empty flat
 *   interp    ga_object_interp at t = 0 and 1 is A and B (a round far out
 *             and small refused as by ga_versor_between); a sphere's radius
 *             goes geometrically (r_A (r_B / r_A)^t), a translated copy's
 *             centre linearly; NaN t refused
 * GAROTOR_TEST_SEED=N draws other inputs (testkit.h; tests/seed_sweep.sh).
 */
#include "testkit.h"

static ga_vec3 add(ga_vec3 a, ga_vec3 b) { return (ga_vec3){a.x + b.x, a.y + b.y, a.z + b.z}; }
static ga_vec3 sub(ga_vec3 a, ga_vec3 b) { return (ga_vec3){a.x - b.x, a.y - b.y, a.z - b.z}; }
static ga_vec3 cross(ga_vec3 a, ga_vec3 b)
{
    return (ga_vec3){a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
static ga_vec3 unit(ga_vec3 a) { return tk_scale(a, 1.0 / tk_norm(a)); }

enum { K_SPHERE, K_CIRCLE, K_PAIR, K_PLANE, K_LINE, K_COUNT };
static const char *const kind_name[K_COUNT] = {"sphere", "circle", "point pair", "plane", "line"};

/* The object of kind k through the points p[] */
static ga_mv build(int k, const ga_vec3 *p)
{
    switch (k) {
    case K_SPHERE: return ga_sphere_from_points(p[0], p[1], p[2], p[3]);
    case K_CIRCLE: return ga_circle_from_points(p[0], p[1], p[2]);
    case K_PAIR: return ga_pointpair_from_points(p[0], p[1]);
    case K_PLANE: return ga_plane_from_points(p[0], p[1], p[2]);
    default: return ga_line_from_points(p[0], p[1]);
    }
}

/* Points of a random object of kind k: centre c, size r, on a sphere (four
   points), a circle (three in the plane of normal m), a pair (c -+ r m); a
   plane's and a line's near c. */
static void points(tk_rng *t, int k, ga_vec3 c, double r, ga_vec3 *p)
{
    ga_vec3 m = tk_unit(t), e1 = unit(cross(m, tk_unit(t))), e2 = cross(m, e1);
    for (int i = 0; i < 4; i++) {
        double a = 2.0 * TK_PI * (i + 0.3 * tk_uni(t)) / 4.0;
        ga_vec3 in = add(tk_scale(e1, cos(a)), tk_scale(e2, sin(a)));
        p[i] = k == K_SPHERE ? add(c, tk_scale(tk_unit(t), r))
             : k == K_PAIR   ? add(c, tk_scale(m, i ? r : -r))
                             : add(c, tk_scale(in, r));
    }
}

/* The angle between unit vectors a and b (orientation counts) */
static double angle(ga_vec3 a, ga_vec3 b)
{
    return atan2(tk_norm(cross(a, b)), a.x * b.x + a.y * b.y + a.z * b.z);
}

/* The scale of a scene: L = max(1, |c| + |r|) over its objects */
static double scene_L(const ga_object *o, int n)
{
    double L = 1.0;
    for (int i = 0; i < n; i++) L = fmax(L, tk_norm(o[i].centre) + sqrt(fabs(o[i].r2)));
    return L;
}

/* How far the object of X is from o beyond what their read-backs know: the
   largest of the centres' distance / L, the r^2 difference / L^2 and the
   directions' angle, each less the bounds (err, r2_err, angle_err) that
   ga_object_from_mv states for the two, L the scene's (scene_L of A, B and
   x). B is built from the moved points, rounded: a thin line or a small round
   far out is known only to its bound (a line through two points 0.01 apart at
   200 to ~u 200 / 0.01 rad), which no V can beat. For a plane and a line the
   centre is the point nearest the origin. */
static double object_err(ga_object x, ga_object o, double L)
{
    double e = tk_max(fmax(0.0, tk_norm(sub(x.centre, o.centre)) - x.err - o.err) / L,
                      fmax(0.0, fabs(x.r2 - o.r2) - x.r2_err - o.r2_err) / (L * L));
    if (o.kind != GA_OBJECT_SPHERE)
        e = tk_max(e, fmax(0.0, angle(x.direction, o.direction) - x.angle_err - o.angle_err));
    return x.kind == o.kind ? e : INFINITY;
}

/* What object.h promises for V A V^-1 computed with ga_versor_apply, relative
   to the scene (object_err): max(1e-12, 64 u L). The sandwich is two
   geometric products of up to 32 terms each (64 roundings of u on a path),
   and a V that moves A by ~L has coefficients ~L/2: its terms are ~L^2 times
   A's weight where the result is ~L times it, so the centre is known to
   ~64 u L^2, 64 u L of the scene. It is L of A and B together: a plane 54
   from the origin moved to 0.8 from it is not known to 1e-12 of 1 (its
   centre 3.2e-12 off: 1.4e4 u, 6e-14 of 54), nor, the sandwich's rounding
   growing like L^2, a line moved 630 from the origin to 1e-12 of 630 (1.9e-9
   off, 1.1e-12 of 630; 21 u L^2: within 64 u L of it). */
static double sandwich_tol(double L) { return fmax(1e-12, 64.0 * 0x1p-53 * L); }

/* V ~V - 1, largest coefficient, relative to |V|^2 (max coefficient) */
static double unit_err(ga_mv V)
{
    ga_mv W = ga_mv_gp(V, ga_mv_reverse(V));
    W.c[0] -= 1.0;
    return tk_mv_maxabs(W) / fmax(1.0, tk_mv_maxabs(V) * tk_mv_maxabs(V));
}

/* X reads back to GA_OBJECT_TOL of its scene (object.h): what
   ga_versor_between answers for; beyond it, it refuses */
static int known(ga_mv X)
{
    ga_object o;
    if (ga_object_from_mv(X, &o) != GA_OK)
        return 0;
    double L = fmax(1.0, tk_norm(o.centre) + sqrt(fabs(o.r2)));
    return o.err <= GA_OBJECT_TOL * L && o.r2_err <= GA_OBJECT_TOL * L * L;
}

static void section_between(void)
{
    tk_rng t = {tk_seed(2025)};
    tk_check sim[K_COUNT],
        rig = tk_begin("same size: V = ga_rotor_between's motion (max coefficient)", 1e-13),
        un = tk_begin("V ~V = 1 (max coefficient of V ~V - 1, over |V|^2)", 1e-14),
        st = tk_begin("GA_OK exactly where both read back to GA_OBJECT_TOL", 0);
    int refused = 0, resized = 0;
    for (int k = 0; k < K_COUNT; k++)
        sim[k] = tk_beginf(1e-12, "%s to a similar copy: V A V^-1 = B (max(1e-12, 64 u L))", kind_name[k]);
    static const double far[] = {1, 10, 100};
    for (int i = 0; i < 600; i++) {
        int k = i % K_COUNT;
        double D = far[(i / K_COUNT) % 3], r = tk_loguni(&t, 1e-2, 1e2), s = tk_loguni(&t, 0.1, 10);
        ga_vec3 cu = tk_unit(&t), c = tk_scale(cu, D * tk_uni(&t)), p[4], q[4], q1[4];
        points(&t, k, c, r, p);
        /* the similarity x -> s rot(x) + a, and the motion x -> rot(x) + a */
        ga_vec3 axis = tk_unit(&t);
        ga_rotor rot = ga_rotor_rotation(axis, tk_range(&t, -3, 3));
        ga_vec3 au = tk_unit(&t), a = tk_scale(au, D * tk_uni(&t));
        for (int j = 0; j < 4; j++) {
            ga_vec3 y = ga_rotor_apply(rot, p[j]);
            q[j] = add(tk_scale(y, s), a);
            q1[j] = add(y, a);
        }
        ga_mv A = build(k, p), B = build(k, q), B1 = build(k, q1), V, X, V1;
        ga_object ox = {0}, ob = {0};
        int s1 = ga_versor_between(A, B, &V), s2 = s1 == GA_OK ? ga_versor_apply(V, A, &X) : s1;
        int s3 = s2 == GA_OK ? ga_object_from_mv(X, &ox) : s2, s4 = ga_object_from_mv(B, &ob);
        int answer = known(A) && known(B);
        refused += !answer;
        tk_add(&st, (s1 == GA_OK) != answer || (answer && (s3 != GA_OK || s4 != GA_OK)));
        ga_object oab[3] = {ob, ox};
        if (answer && s3 == GA_OK && s4 == GA_OK && ga_object_from_mv(A, &oab[2]) == GA_OK) {
            double L = scene_L(oab, 3);
            tk_add_tol(&sim[k], object_err(ox, ob, L), sandwich_tol(L));
            tk_add(&un, unit_err(V));
        }
        /* B1 is built from the moved points, rounded: a small sphere through
           four nearly coplanar points comes out with an r^2 beyond the
           bounds its read-back states (5e-10 relative), a size that differs,
           and V1 dilates by it. The motion is promised only where the two
           r^2 agree to the sum of their r2_err (object.h). */
        ga_rotor R1;
        ga_object oa1, ob1;
        int t1 = ga_versor_between(A, B1, &V1), t2 = ga_rotor_between(A, B1, &R1);
        tk_add(&st, t1 != t2);
        if (t1 == GA_OK && t2 == GA_OK && ga_object_from_mv(A, &oa1) == GA_OK &&
            ga_object_from_mv(B1, &ob1) == GA_OK) {
            if (fabs(oa1.r2 - ob1.r2) <= oa1.r2_err + ob1.r2_err)
                tk_add(&rig, tk_mv_maxabs(ga_mv_sub(V1, ga_rotor_to_mv(R1))) / tk_mv_maxabs(V1));
            else
                resized++;
        }
    }
    tk_note(
        "(%d of 600 pairs refused: a round small against its distance, known to less than GA_OBJECT_TOL)\n",
        refused);
    tk_note("(%d of 600 same-size copies built with an r^2 beyond the read-backs' bounds: dilated)\n",
            resized);
    for (int k = 0; k < K_COUNT; k++) tk_end(&sim[k]);
    tk_end(&rig);
    tk_end(&un);
    tk_end(&st);
}

static void section_refusals(void)
{
    ga_vec3 o = {0, 0, 0}, ex = {1, 0, 0}, ez = {0, 0, 1};
    ga_mv V = ga_mv_zero(), W, S1 = ga_mv_dual(ga_sphere_dual(o, 1)), P = ga_mv_dual(ga_plane_dual(ez, 1));
    tk_expect_status("grades differ: sphere, line", ga_versor_between(S1, ga_line_from_points(o, ex), &V),
                     GA_ERR_ARG);
    tk_expect_status("a point (radius 0) and a sphere",
                     ga_versor_between(ga_mv_dual(ga_sphere_dual(ex, 0)), S1, &V), GA_ERR_DOMAIN);
    tk_expect_status("a sphere and a point", ga_versor_between(S1, ga_mv_dual(ga_sphere_dual(ex, 0)), &V),
                     GA_ERR_DOMAIN);
    tk_expect_status(
        "two points: a translation",
        ga_versor_between(ga_mv_dual(ga_sphere_dual(ex, 0)), ga_mv_dual(ga_sphere_dual(ez, 0)), &W), GA_OK);
    /* an imaginary circle: two spheres that miss each other */
    ga_mv Ci = ga_mv_meet(ga_sphere_dual(o, 1), ga_sphere_dual((ga_vec3){3, 0, 0}, 1));
    ga_mv Cr = ga_mv_meet(ga_sphere_dual(o, 1), ga_sphere_dual((ga_vec3){1, 0, 0}, 1));
    tk_expect_status("an imaginary circle", ga_versor_between(Ci, Cr, &V), GA_ERR_IMAGINARY);
    /* the meet of parallel planes: empty */
    ga_mv E = ga_mv_meet(ga_plane_dual(ez, 0), ga_plane_dual(ez, 1));
    tk_expect_status("an empty flat", ga_versor_between(E, E, &V), GA_ERR_NOTBLADE);
    tk_expect_status("nothing written on failure", tk_mv_maxabs(V) == 0.0 ? GA_OK : GA_ERR_ARG, GA_OK);
    tk_expect_status("interp: NaN t", ga_object_interp(S1, S1, NAN, &V), GA_ERR_NOTFINITE);
    tk_expect_status("interp: kinds differ", ga_object_interp(S1, P, 0.5, &V), GA_ERR_ARG);
}

static void section_interp(void)
{
    tk_rng t = {tk_seed(77)};
    tk_check ends = tk_begin("t = 0 gives A, t = 1 gives B (read back, rel)", 1e-12),
             geo = tk_begin("sphere at t: r^2 = (r_A (r_B/r_A)^t)^2 (over L^2, beyond r2_err)", 1e-12),
             lin = tk_begin("translated sphere at t: centre c_A + t a (over L, beyond err)", 1e-12),
             st = tk_begin("GA_OK exactly where both read back to GA_OBJECT_TOL", 0);
    for (int i = 0; i < 200; i++) {
        int k = i % K_COUNT;
        double r = tk_loguni(&t, 0.1, 10), s = tk_loguni(&t, 0.1, 10), tt = tk_range(&t, -0.5, 1.5);
        ga_vec3 cu = tk_unit(&t), c = tk_scale(cu, 10 * tk_uni(&t)), p[4], q[4];
        points(&t, k, c, r, p);
        ga_vec3 axis = tk_unit(&t);
        ga_rotor rot = ga_rotor_rotation(axis, tk_range(&t, -3, 3));
        ga_vec3 au = tk_unit(&t), a = tk_scale(au, 10 * tk_uni(&t));
        for (int j = 0; j < 4; j++) q[j] = add(tk_scale(ga_rotor_apply(rot, p[j]), s), a);
        ga_mv A = build(k, p), B = build(k, q), X0, X1;
        ga_object oa, ob, o0, o1;
        int s0 = ga_object_interp(A, B, 0.0, &X0), s1 = ga_object_interp(A, B, 1.0, &X1);
        int answer = known(A) && known(B);
        tk_add(&st, (s0 == GA_OK) != answer || (s1 == GA_OK) != answer);
        if (answer && s0 == GA_OK && s1 == GA_OK) {
            int r0 = ga_object_from_mv(X0, &o0), r1 = ga_object_from_mv(X1, &o1);
            int ra = ga_object_from_mv(A, &oa), rb = ga_object_from_mv(B, &ob);
            ga_object all[4] = {oa, ob, o0, o1};
            double L = scene_L(all, 4);
            tk_add(&ends,
                   r0 || r1 || ra || rb ? INFINITY : tk_max(object_err(o0, oa, L), object_err(o1, ob, L)));
        }
        /* spheres about one centre: the radius; a translated copy: the centre */
        ga_mv S = ga_mv_dual(ga_sphere_dual(c, r)), Ss = ga_mv_dual(ga_sphere_dual(c, s * r)),
              St = ga_mv_dual(ga_sphere_dual(add(c, a), r)), Y;
        ga_object oy;
        /* refused exactly where the two are not known to GA_OBJECT_TOL (a
           dual sphere of radius 99 has e4, e5 ~ r^2 / 2, so its weight only
           to ~u r^2 and r^2 to ~u r^4: beyond 1e-12 L^2 there) */
        int g = ga_object_interp(S, Ss, tt, &Y);
        tk_add(&st, (g == GA_OK) != (known(S) && known(Ss)));
        if (g == GA_OK && ga_object_from_mv(Y, &oy) == GA_OK) {
            /* r^2 and the centre beyond what Y's read-back knows of them
               (r2_err, err): a small sphere far out has r^2 only to ~u |c|^2,
               its radius to r2_err / 2r (2e-10 for a radius 0.007 at 9.4) */
            double want = r * pow(s, tt), L = fmax(1.0, tk_norm(c) + fmax(want, r));
            tk_add(&geo, tk_max(fmax(0.0, fabs(oy.r2 - want * want) - oy.r2_err) / (L * L),
                                fmax(0.0, tk_norm(sub(oy.centre, c)) - oy.err) / L));
        } else if (g == GA_OK)
            tk_add(&geo, INFINITY);
        g = ga_object_interp(S, St, tt, &Y);
        tk_add(&st, (g == GA_OK) != (known(S) && known(St)));
        if (g == GA_OK && ga_object_from_mv(Y, &oy) == GA_OK) {
            ga_vec3 want = add(c, tk_scale(a, tt));
            double L = fmax(1.0, fmax(tk_norm(c), tk_norm(add(c, a))) + r);
            tk_add(&lin, tk_max(fmax(0.0, tk_norm(sub(oy.centre, want)) - oy.err) / L,
                                fmax(0.0, fabs(oy.r2 - r * r) - oy.r2_err) / (L * L)));
        } else if (g == GA_OK)
            tk_add(&lin, INFINITY);
    }
    tk_end(&ends);
    tk_end(&geo);
    tk_end(&lin);
    tk_end(&st);
}

static const tk_section sections[] = {
    {"between", section_between, 0},
    {"refusals", section_refusals, 0},
    {"interp", section_interp, 0},
};

int main(int argc, char **argv)
{
    return tk_main(argc, argv, "test_object_between", sections, TK_COUNT(sections));
}
