/* tests/test_meet.c: object.h on random scenes, against Euclidean formulas.
 *
 * Scenes are placed at distances D = 1, 1e2, 1e4, 1e6, 1e8 from the origin,
 * with a size log-uniform between 1 and D. Every read-back (ga_object_from_mv)
 * of a constructed object and of a meet is compared with what Euclidean
 * geometry says: the centre or point (error / L, L = max(1, distance from the
 * origin + size)), the squared radius (error / L^2), the direction (absolute).
 * The promise checked is object.h's: every GA_OK answer within GA_OBJECT_TOL
 * (1e-12); a refusal must be GA_ERR_PRECISION, and none may happen at D = 1.
 * Each line prints the worst error for that kind at that distance. Tangent
 * and imaginary cases are built on purpose: spheres at the distance r1 + r2
 * (tangent) and beyond it (an imaginary circle with its signed r^2), a line
 * missing a sphere (an imaginary pair), parallel planes and a line parallel to
 * a plane (empty). Then projection, rejection, distance, angle and the rigid
 * motion between two objects, on the same scenes. The lines "about o" build,
 * meet, move and read the rounds (and flats) again about a local origin and
 * length (object.h, "Local origin and length scale"), where no refusal is
 * allowed at any distance.
 */
#include "testkit.h"

static ga_vec3 add(ga_vec3 a, ga_vec3 b) { return (ga_vec3){a.x + b.x, a.y + b.y, a.z + b.z}; }
static ga_vec3 sub(ga_vec3 a, ga_vec3 b) { return (ga_vec3){a.x - b.x, a.y - b.y, a.z - b.z}; }
static double dot(ga_vec3 a, ga_vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static ga_vec3 cross(ga_vec3 a, ga_vec3 b)
{
    return (ga_vec3){a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
static ga_vec3 unit(ga_vec3 a) { return tk_scale(a, 1.0 / tk_norm(a)); }
/* distance between directions up to sign (a line's, a normal's) */
static double dir_err(ga_vec3 a, ga_vec3 b)
{
    double p = tk_norm(sub(a, b)), m = tk_norm(add(a, b));
    return p < m ? p : m;
}

typedef struct {
    const char *kind;
    double worst;
    long n, refused;
} acc;
static acc kinds[64];
static int nkinds;
static acc *kind_acc(const char *k)
{
    for (int i = 0; i < nkinds; i++)
        if (!strcmp(kinds[i].kind, k))
            return &kinds[i];
    kinds[nkinds] = (acc){k, 0, 0, 0};
    return &kinds[nkinds++];
}

/* the check that counts measure()'s statuses (scene_join has its own) */
static const char *status_check = "statuses: GA_OK, or a refusal for rounds far out";

/* one measured read-back: status must be GA_OK (or GA_ERR_PRECISION where allowed), error <= 1e-12 */
static void measure(const char *kind, int st, double err, int may_refuse)
{
    acc *a = kind_acc(kind);
    /* a round far out may also be refused as GA_ERR_NOTBLADE when rounding
       breaks its grade before its weight is read (a gap: GA_ERR_PRECISION
       would say more); never at D = 1, which flush() checks */
    if ((st == GA_ERR_PRECISION || st == GA_ERR_NOTBLADE || st == GA_ERR_SINGULAR) && may_refuse) {
        a->refused++;
        return;
    }
    tk_add_status(tk_get(status_check), st, GA_OK);
    if (st != GA_OK)
        return;
    a->n++;
    a->worst = tk_max(a->worst, err);
}

static void flush(double D)
{
    for (int i = 0; i < nkinds; i++) {
        char name[96];
        snprintf(name, sizeof name, "D=%g %-26s (%ld refused)", D, kinds[i].kind, kinds[i].refused);
        tk_check c = tk_begin(name, GA_OBJECT_TOL);
        if (kinds[i].n)
            tk_add(&c, kinds[i].worst);
        c.n = kinds[i].n;
        tk_end(&c);
        if (D == 1.0)
            tk_expect(kinds[i].refused == 0, "no refusal at D = 1");
    }
    nkinds = 0;
}

/* The error of an object read back against (kind, centre, r2, direction):
   each part over its allowance, the larger of GA_OBJECT_TOL L^k (k = 1 for
   lengths, 2 for r^2, 0 for the direction) and the bound the object states
   (err, r2_err, angle_err) plus 16 u L^k for the reference's own rounding,
   times GA_OBJECT_TOL: at most GA_OBJECT_TOL when the promise holds. */
static double obj_err(ga_object o, int kind, ga_vec3 c, double r2, ga_vec3 dir, double L)
{
    if (o.kind != kind)
        return INFINITY;
    const double T = GA_OBJECT_TOL, s = 16 * DBL_EPSILON / 2;
    double e = tk_norm(sub(o.centre, c)) / tk_max(T * L, o.err + s * L);
    e = tk_max(e, fabs(o.r2 - r2) / tk_max(T * L * L, o.r2_err + s * L * L));
    if (tk_norm(dir) > 0)
        e = tk_max(e, dir_err(o.direction, dir) / tk_max(T, o.angle_err + s));
    return T * e;
}

static void scene(tk_rng *t, double D)
{
    ga_vec3 zero = {0, 0, 0};
    double S = D == 1.0 ? tk_loguni(t, 0.1, 1) : tk_loguni(t, 1, D); /* the size */
    ga_vec3 o = tk_scale(tk_unit(t), D);                             /* where */
    ga_vec3 a = add(o, tk_scale(tk_unit(t), S * tk_uni(t)));
    ga_vec3 b = add(o, tk_scale(tk_unit(t), S * tk_uni(t)));
    ga_vec3 c = add(o, tk_scale(tk_unit(t), S * tk_uni(t)));
    double L = D + 2 * S;
    ga_object ob;
    int st;

    /* plane through a, b, c: normal (b - a) x (c - a), d = m.a */
    ga_vec3 m = unit(cross(sub(b, a), sub(c, a)));
    ga_mv P = ga_plane_from_points(a, b, c);
    st = ga_object_from_mv(P, &ob);
    measure("plane", st, obj_err(ob, GA_OBJECT_PLANE, tk_scale(m, dot(m, a)), 0, m, L), 0);
    /* line through a, b */
    ga_vec3 u = unit(sub(b, a));
    ga_mv Ln = ga_line_from_points(a, b);
    st = ga_object_from_mv(Ln, &ob);
    measure("line", st, obj_err(ob, GA_OBJECT_LINE, sub(a, tk_scale(u, dot(u, a))), 0, u, L), 0);

    /* plane ^ plane: a line; check its point lies on both and is closest to the origin */
    ga_vec3 m2 = tk_unit(t);
    double d2 = dot(m2, c);
    ga_mv P2 = ga_mv_dual(ga_plane_dual(m2, d2));
    st = ga_object_from_mv(ga_mv_meet(P, P2), &ob);
    {
        double e = ob.kind == GA_OBJECT_LINE ? 0 : INFINITY;
        e = tk_max(e, fabs(dot(m, ob.centre) - dot(m, a)) / L);
        e = tk_max(e, fabs(dot(m2, ob.centre) - d2) / L);
        e = tk_max(e, fabs(dot(ob.direction, ob.centre)) / L);
        e = tk_max(e, dir_err(ob.direction, unit(cross(m, m2))) * tk_norm(cross(m, m2)));
        measure("meet plane^plane: line", st, e, 0);
    }
    /* line ^ plane: a flat point a + t u, t = (d2 - m2.a) / (m2.u) */
    st = ga_object_from_mv(ga_mv_meet(Ln, P2), &ob);
    {
        double tt = (d2 - dot(m2, a)) / dot(m2, u), cond = fabs(dot(m2, u));
        ga_vec3 x = add(a, tk_scale(u, tt));
        measure("meet line^plane: flat point", st,
                obj_err(ob, GA_OBJECT_FLATPOINT, x, 0, zero, tk_max(L, tk_norm(x))) * cond, 0);
    }
    /* parallel: empty */
    st = ga_object_from_mv(ga_mv_meet(ga_plane_dual(m, dot(m, a)), ga_plane_dual(m, dot(m, a) + S)), &ob);
    tk_add_bool(tk_get("parallel planes meet in nothing (EMPTY)"), st == GA_OK && ob.kind == GA_OBJECT_EMPTY);

    /* spheres: centre c1 = a, r1; c2 = a + dist e, r2; circle at a + h e, r^2 = r1^2 - h^2 */
    double r1 = S * tk_range(t, 0.2, 1), r2 = S * tk_range(t, 0.2, 1);
    ga_vec3 e = tk_unit(t);
    /* A dual sphere whose weight is below the spacing of its e4/e5
       coefficients (|c|^2 - r^2 beyond ~2^54: ga_sphere_dual beyond ~1.3e8)
       is a plane as stored; no read-back can see a sphere in it: counted, not
       measured (object.h). */
    ga_object s1;
    int flat_spheres = 0;
    ga_vec3 cc = add(a, tk_scale(e, r1));
    ga_vec3 w1 = unit(cross(e, tk_unit(t))), w2 = cross(e, w1);
    ga_vec3 p1 = add(cc, tk_scale(w1, r1)), p2 = add(cc, tk_scale(w2, r1)), p3 = sub(cc, tk_scale(w1, r1));
    ga_vec3 ctrs[] = {a, c, cc};
    for (int i = 0; i < 3; i++)
        if (ga_object_from_mv(ga_sphere_dual(ctrs[i], i == 1 ? 2 * S : r1), &s1) == GA_OK &&
            s1.kind != GA_OBJECT_SPHERE)
            flat_spheres = 1;
    if (ga_object_from_mv(ga_sphere_from_points(p1, p2, p3, add(cc, tk_scale(e, r1))), &s1) == GA_OK &&
        s1.kind != GA_OBJECT_SPHERE)
        flat_spheres = 1;
    if (flat_spheres)
        kind_acc("(spheres stored as flats)")->refused++;
    for (int cs = 0; cs < 3 * !flat_spheres; cs++) { /* crossing, tangent, imaginary */
        double dist = cs == 0 ? tk_range(t, fabs(r1 - r2), r1 + r2)
                    : cs == 1 ? r1 + r2
                              : (r1 + r2) * tk_range(t, 1.1, 3);
        ga_vec3 c2 = add(a, tk_scale(e, dist));
        double h = (dist * dist + r1 * r1 - r2 * r2) / (2 * dist);
        ga_mv M = ga_mv_meet(ga_sphere_dual(a, r1), ga_sphere_dual(c2, r2));
        st = ga_object_from_mv(M, &ob);
        double err = obj_err(ob, GA_OBJECT_CIRCLE, add(a, tk_scale(e, h)), (r1 - h) * (r1 + h), e, L);
        static const char *nm[] = {"meet sphere^sphere: circle", "  ... tangent", "  ... imaginary"};
        static const int want[] = {GA_REALITY_REAL, GA_REALITY_TANGENT, GA_REALITY_IMAGINARY};
        measure(nm[cs], st, err, 1);
        if (st == GA_OK && cs > 0)
            tk_add_bool(tk_get("tangent and imaginary circles classified so"), ob.reality == want[cs]);
    }
    /* line ^ sphere (centre c, radius r1): the pair q -+ h u, q the foot of c on the line */
    if (!flat_spheres) {
        ga_vec3 q = add(a, tk_scale(u, dot(u, sub(c, a))));
        double off = tk_norm(sub(q, c));
        double R = fmin(off * tk_range(t, 0.5, 2), 2 * S);
        /* the sphere met here is checked as those above: at 1e8 a radius
           near 1e8 can leave it a plane as stored (e4 == e5) */
        if (ga_object_from_mv(ga_sphere_dual(c, R), &s1) == GA_OK && s1.kind != GA_OBJECT_SPHERE) {
            kind_acc("(spheres stored as flats)")->refused++;
        } else {
            st = ga_object_from_mv(ga_mv_meet(Ln, ga_sphere_dual(c, R)), &ob);
            measure("meet line^sphere: pair", st,
                    obj_err(ob, GA_OBJECT_POINTPAIR, q, (R - off) * (R + off), u, L), 1);
            if (st == GA_OK)
                tk_add_bool(tk_get("line missing a sphere: an imaginary pair"),
                            (R < off) == (ob.reality == GA_REALITY_IMAGINARY) ||
                                ob.reality == GA_REALITY_TANGENT);
            /* plane ^ sphere: circle at c - (m.c - d) m, r^2 = R^2 - (m.c - d)^2 */
            double s = dot(m, c) - dot(m, a);
            st = ga_object_from_mv(ga_mv_meet(P, ga_sphere_dual(c, R)), &ob);
            measure("meet plane^sphere: circle", st,
                    obj_err(ob, GA_OBJECT_CIRCLE, sub(c, tk_scale(m, s)), (R - s) * (R + s), m, L), 1);
        }
    }
    /* rounds built from points */
    if (!flat_spheres) {
        st = ga_object_from_mv(ga_sphere_dual(cc, r1), &ob);
        measure("sphere (dual)", st, obj_err(ob, GA_OBJECT_SPHERE, cc, r1 * r1, zero, L), 1);
        st = ga_object_from_mv(ga_circle_from_points(p1, p2, p3), &ob);
        measure("circle (from points)", st, obj_err(ob, GA_OBJECT_CIRCLE, cc, r1 * r1, e, L), 1);
        st = ga_object_from_mv(ga_sphere_from_points(p1, p2, p3, add(cc, tk_scale(e, r1))), &ob);
        measure("sphere (from points)", st, obj_err(ob, GA_OBJECT_SPHERE, cc, r1 * r1, zero, L), 1);
        st = ga_object_from_mv(ga_pointpair_from_points(p1, p3), &ob);
        measure("pair (from points)", st, obj_err(ob, GA_OBJECT_POINTPAIR, cc, r1 * r1, w1, L), 1);

        /* projection onto the sphere and the plane, against c + r (x - c)/|x - c|, x - (m.x - d) m */
    }
    {
        ga_vec3 x = add(o, tk_scale(tk_unit(t), S)), pr, rj;
        ga_vec3 wantS = add(cc, tk_scale(unit(sub(x, cc)), r1));
        st = ga_point_project(x, ga_sphere_dual(cc, r1), &pr);
        if (!flat_spheres)
            measure("project onto sphere", st, tk_norm(sub(pr, wantS)) / L, 1);
        st = ga_point_reject(x, P, &rj);
        measure("reject from plane", st, tk_norm(sub(rj, tk_scale(m, dot(m, x) - dot(m, a)))) / L, 0);
        double dd;
        st = ga_point_distance(x, Ln, &dd);
        measure("distance to line", st, fabs(dd - tk_norm(cross(sub(x, a), u))) / L, 0);
        /* the rigid motion from an object to a moved copy (built from the moved
           points) takes a point of it onto the copy and its direction onto the copy's */
        ga_rotor Rm = ga_rotor_twist(tk_range(t, 0, 3), (ga_generator){0.6, 0, 0.8, 0, 0, 0},
                                     tk_scale(tk_unit(t), S));
        ga_vec3 q1 = ga_rotor_apply(Rm, p1), q2 = ga_rotor_apply(Rm, p2), q3 = ga_rotor_apply(Rm, p3);
        ga_rotor B;
        ga_object o3;
        st = flat_spheres
               ? GA_ERR_PRECISION
               : ga_rotor_between(ga_circle_from_points(p1, p2, p3), ga_circle_from_points(q1, q2, q3), &B);
        if (st == GA_OK)
            st = ga_object_from_mv(ga_circle_from_points(q1, q2, q3), &o3);
        if (st == GA_OK) {
            ga_vec3 bc = ga_rotor_apply(B, cc),
                    bn = tk_scale(sub(ga_rotor_apply(B, add(cc, tk_scale(e, L))), bc), 1 / L);
            measure("rotor between circles", st,
                    tk_max(tk_norm(sub(bc, o3.centre)) / L, tk_norm(sub(bn, o3.direction))), 1);
        } else
            measure("rotor between circles", st, 0, 1);
        st = ga_rotor_between(ga_plane_from_points(p1, p2, p3), ga_plane_from_points(q1, q2, q3), &B);
        ga_vec3 m3 = unit(cross(sub(q2, q1), sub(q3, q1))), mp = unit(cross(sub(p2, p1), sub(p3, p1)));
        if (st == GA_OK) {
            ga_vec3 ba = ga_rotor_apply(B, p1),
                    bn = tk_scale(sub(ga_rotor_apply(B, add(p1, tk_scale(mp, L))), ba), 1 / L);
            measure("rotor between planes", st, tk_max(fabs(dot(m3, sub(ba, q1))) / L, tk_norm(sub(bn, m3))),
                    0);
        } else
            measure("rotor between planes", st, 0, 0);
        double ang;
        st = ga_object_angle(P, P2, &ang);
        measure("angle plane, plane", st, fabs(ang - atan2(tk_norm(cross(m, m2)), fabs(dot(m, m2)))), 0);
    }
}

/* The same rounds held about a local origin og and length lam, a power of two
   near the size (object.h, "Local origin and length scale"): built from the
   points (x - og) / lam, a plane built in world coordinates brought in by
   ga_mv_localize, met, moved by a screw motion about an axis through the
   world's origin (ga_rotor_apply_about) and read back with
   ga_object_from_mv_about, against the same Euclidean formulas in world
   coordinates. No refusal is allowed at any distance. */
static void scene_about(tk_rng *t, double D)
{
    ga_vec3 zero = {0, 0, 0};
    double S = D == 1.0 ? tk_loguni(t, 0.1, 1) : tk_loguni(t, 1, D);
    ga_vec3 og = tk_scale(tk_unit(t), D); /* the local origin, near the scene */
    ga_vec3 a = add(og, tk_scale(tk_unit(t), S * tk_uni(t)));
    ga_vec3 b = add(og, tk_scale(tk_unit(t), S * tk_uni(t)));
    ga_vec3 c = add(og, tk_scale(tk_unit(t), S * tk_uni(t)));
    double L = D + 2 * S;
    double lam = ldexp(1.0, ilogb(S));
    ga_object ob;
    int st;
#define LOC(x) tk_scale(sub((x), og), 1 / lam)
    /* a plane built in world coordinates (exact as a flat), brought to og */
    ga_vec3 m = unit(cross(sub(b, a), sub(c, a)));
    ga_mv P;
    st = ga_mv_localize(ga_plane_from_points(a, b, c), og, lam, &P);
    tk_add_status(tk_get("about o: ga_mv_localize of a world plane"), st, GA_OK);
    st = ga_object_from_mv_about(P, og, lam, &ob);
    measure("about o: world plane", st, obj_err(ob, GA_OBJECT_PLANE, tk_scale(m, dot(m, a)), 0, m, L), 0);
    ga_vec3 u = unit(sub(b, a));
    ga_mv Ln = ga_line_from_points(LOC(a), LOC(b)), Lw;
    st = ga_object_from_mv_about(Ln, og, lam, &ob);
    measure("about o: line", st, obj_err(ob, GA_OBJECT_LINE, sub(a, tk_scale(u, dot(u, a))), 0, u, L), 0);
    /* a line and a dual plane given in world coordinates, brought in */
    st = ga_mv_localize(ga_line_from_points(a, b), og, lam, &Lw);
    if (st == GA_OK)
        st = ga_object_from_mv_about(Lw, og, lam, &ob);
    measure("about o: world line", st, obj_err(ob, GA_OBJECT_LINE, sub(a, tk_scale(u, dot(u, a))), 0, u, L),
            0);
    ga_vec3 m2 = tk_unit(t);
    double d2w = dot(m2, c);
    st = ga_mv_localize(ga_plane_dual(m2, d2w), og, lam, &Lw);
    if (st == GA_OK)
        st = ga_object_from_mv_about(Lw, og, lam, &ob);
    measure("about o: world dual plane", st, obj_err(ob, GA_OBJECT_PLANE, tk_scale(m2, d2w), 0, m2, L), 0);

    double r1 = S * tk_range(t, 0.2, 1), r2 = S * tk_range(t, 0.2, 1);
    ga_vec3 e = tk_unit(t);
    static const char *nm[] = {"about o: sphere^sphere circle", "about o:   ... tangent",
                               "about o:   ... imaginary"};
    static const int want[] = {GA_REALITY_REAL, GA_REALITY_TANGENT, GA_REALITY_IMAGINARY};
    for (int cs = 0; cs < 3; cs++) {
        double dist = cs == 0 ? tk_range(t, fabs(r1 - r2), r1 + r2)
                    : cs == 1 ? r1 + r2
                              : (r1 + r2) * tk_range(t, 1.1, 3);
        /* the truth from the centres as rounded (c2 - a is exact where they
           are close: Sterbenz), which at 1e8 are u D off the line a + e dist;
           tangent: r2 is the rounded distance less r1 */
        ga_vec3 c2 = add(a, tk_scale(e, dist)), ea = sub(c2, a);
        double da = tk_norm(ea), s2 = cs == 1 ? da - r1 : r2;
        ea = tk_scale(ea, 1 / da);
        double h = (da * da + r1 * r1 - s2 * s2) / (2 * da);
        ga_mv M = ga_mv_meet(ga_sphere_dual(LOC(a), r1 / lam), ga_sphere_dual(LOC(c2), s2 / lam));
        st = ga_object_from_mv_about(M, og, lam, &ob);
        measure(nm[cs], st,
                obj_err(ob, GA_OBJECT_CIRCLE, add(a, tk_scale(ea, h)), (r1 - h) * (r1 + h), ea, L), 0);
        tk_add_bool(tk_get("about o: tangent and imaginary circles classified so"),
                    st == GA_OK && ob.reality == want[cs]);
    }
    ga_vec3 q = add(a, tk_scale(u, dot(u, sub(c, a))));
    double off = tk_norm(sub(q, c));
    double R = fmin(off * tk_range(t, 0.5, 2), 2 * S);
    st = ga_object_from_mv_about(ga_mv_meet(Ln, ga_sphere_dual(LOC(c), R / lam)), og, lam, &ob);
    measure("about o: line^sphere pair", st, obj_err(ob, GA_OBJECT_POINTPAIR, q, (R - off) * (R + off), u, L),
            0);
    double sd = dot(m, c) - dot(m, a);
    st = ga_object_from_mv_about(ga_mv_meet(P, ga_sphere_dual(LOC(c), R / lam)), og, lam, &ob);
    measure("about o: plane^sphere circle", st,
            obj_err(ob, GA_OBJECT_CIRCLE, sub(c, tk_scale(m, sd)), (R - sd) * (R + sd), m, L), 0);

    ga_vec3 cc = add(a, tk_scale(e, r1));
    ga_vec3 w1 = unit(cross(e, tk_unit(t))), w2 = cross(e, w1);
    ga_vec3 p1 = add(cc, tk_scale(w1, r1)), p2 = add(cc, tk_scale(w2, r1)), p3 = sub(cc, tk_scale(w1, r1));
    st = ga_object_from_mv_about(ga_sphere_dual(LOC(cc), r1 / lam), og, lam, &ob);
    measure("about o: sphere (dual)", st, obj_err(ob, GA_OBJECT_SPHERE, cc, r1 * r1, zero, L), 0);
    /* the circle and pair through the points as rounded (u D off cc + r1 w at
       1e8, which tilts a small circle by u D / r1): centre, r^2 and normal
       from their differences (exact where close), the circumcentre of the
       triangle 0, d2, d3 at (|d2|^2 d3 - |d3|^2 d2) x (d2 x d3) / (2 |d2 x d3|^2)
       (rounded to a few u of its size, added to p1) */
    ga_vec3 d2 = sub(p2, p1), d3 = sub(p3, p1), nc = cross(d2, d3);
    ga_vec3 kc = tk_scale(cross(sub(tk_scale(d3, dot(d2, d2)), tk_scale(d2, dot(d3, d3))), nc),
                          0.5 / dot(nc, nc));
    ga_vec3 ccp = add(p1, kc);
    ga_mv C = ga_circle_from_points(LOC(p1), LOC(p2), LOC(p3));
    st = ga_object_from_mv_about(C, og, lam, &ob);
    measure("about o: circle (from points)", st, obj_err(ob, GA_OBJECT_CIRCLE, ccp, dot(kc, kc), unit(nc), L),
            0);
    ga_vec3 p4 = add(cc, tk_scale(e, r1)), d4 = sub(p4, p1);
    {
        /* the sphere through p1..p4: centre p1 + k with 2 k.di = |di|^2, i = 2, 3, 4 */
        double b2 = 0.5 * dot(d2, d2), b3 = 0.5 * dot(d3, d3), b4 = 0.5 * dot(d4, d4);
        ga_vec3 k = tk_scale(add(add(tk_scale(cross(d3, d4), b2), tk_scale(cross(d4, d2), b3)),
                                 tk_scale(cross(d2, d3), b4)),
                             1 / dot(d2, cross(d3, d4)));
        st = ga_object_from_mv_about(ga_sphere_from_points(LOC(p1), LOC(p2), LOC(p3), LOC(p4)), og, lam, &ob);
        measure("about o: sphere (from points)", st,
                obj_err(ob, GA_OBJECT_SPHERE, add(p1, k), dot(k, k), zero, L), 0);
    }
    st = ga_object_from_mv_about(ga_pointpair_from_points(LOC(p1), LOC(p3)), og, lam, &ob);
    measure("about o: pair (from points)", st,
            obj_err(ob, GA_OBJECT_POINTPAIR, add(p1, tk_scale(d3, 0.5)), 0.25 * dot(d3, d3), unit(d3), L), 0);

    /* moved by a screw motion about an axis through the world's origin (a
       turn of up to 3 rad moves the circle by up to ~2 D): the centre moved
       by Rm, the normal turned by Rm's rotation */
    ga_rotor Rm = ga_rotor_twist(tk_range(t, 0, 3), (ga_generator){0.6, 0, 0.8, 0, 0, 0},
                                 tk_scale(tk_unit(t), S));
    ga_rotor Rq = ga_rotor_from_quat(ga_rotor_to_quat(Rm), zero);
    ga_vec3 og2;
    ga_mv C2;
    st = ga_rotor_apply_about(Rm, og, C, &og2, &C2);
    if (st == GA_OK)
        st = ga_object_from_mv_about(C2, og2, lam, &ob);
    measure("about o: circle moved", st,
            obj_err(ob, GA_OBJECT_CIRCLE, ga_rotor_apply(Rm, ccp), dot(kc, kc), ga_rotor_apply(Rq, unit(nc)),
                    L),
            0);
    /* projection onto the sphere about og */
    ga_vec3 x = add(og, tk_scale(tk_unit(t), S)), pr;
    st = ga_point_project(LOC(x), ga_sphere_dual(LOC(cc), r1 / lam), &pr);
    measure("about o: project onto sphere", st,
            tk_norm(sub(add(tk_scale(pr, lam), og), add(cc, tk_scale(unit(sub(x, cc)), r1)))) / L, 0);
#undef LOC
}

/* ga_mv_join and ga_mv_meet_rel on random scenes in special position, against
   Euclid (a stream of their own, so that the lines above print as before).
   Flats at every distance D: two lines through a common point x (join: their
   plane; meet: the flat point x), two parallel lines (their plane; the
   direction at infinity), a line in a plane, a line and itself. Points and
   rounds at D = 1 (beyond, they are held about a local origin: object.h):
   a point on a line and off it, coplanar circles (crossing, tangent,
   imaginary: a point pair), circles on a common sphere (their pair), a circle
   on a sphere and across one, two point pairs sharing a point. Errors as in
   scene() (weighted by the sine of the angle that conditions them where one
   does); the results that must be an input as given (the join of a point
   and a line through it is the line) are checked bit for bit. */
static int same_mv(ga_mv a, ga_mv b) { return !memcmp(&a, &b, sizeof a); }

/* The error of a plane read back that should hold x with normal m: the
   distance of x from it / L, and the tilt of its normal over the scene's size
   S / L (the displacement it makes at S from x, as the other errors: at D the
   objects themselves are rounded to u D, which tilts the plane through two
   lines S apart by u D / S). */
static double plane_err(ga_object ob, ga_vec3 x, ga_vec3 m, double S, double L)
{
    if (ob.kind != GA_OBJECT_PLANE)
        return INFINITY;
    return tk_max(fabs(dot(ob.direction, sub(x, ob.centre))) / L, dir_err(ob.direction, m) * S / L);
}

static void scene_join(tk_rng *t, double D)
{
    double S = D == 1.0 ? tk_loguni(t, 0.1, 1) : tk_loguni(t, 1, D);
    ga_vec3 o = tk_scale(tk_unit(t), D), zero = {0, 0, 0};
    ga_vec3 x = add(o, tk_scale(tk_unit(t), S * tk_uni(t)));
    double L = D + 2 * S;
    ga_vec3 u1 = tk_unit(t), u2 = tk_unit(t);
    double sn = tk_norm(cross(u1, u2));
    ga_vec3 m = unit(cross(u1, u2));
    double al = tk_range(t, 0.2, 1), be = tk_range(t, 0.2, 1), ga = tk_range(t, 0.2, 1),
           de = tk_range(t, 0.2, 1);
    ga_mv L1 = ga_line_from_points(sub(x, tk_scale(u1, al * S)), add(x, tk_scale(u1, be * S)));
    ga_mv L2 = ga_line_from_points(add(x, tk_scale(u2, ga * S)), sub(x, tk_scale(u2, de * S)));
    ga_mv J, M;
    ga_object ob;
    int st;
    tk_check *stc = tk_get("join, meet_rel: GA_OK on valid objects");
#define JM(A, B)                                                                                             \
    do {                                                                                                     \
        tk_add_status(stc, ga_mv_join((A), (B), &J), GA_OK);                                                 \
        tk_add_status(stc, ga_mv_meet_rel((A), (B), &M), GA_OK);                                             \
    } while (0)
    JM(L1, L2);
    st = ga_object_from_mv(J, &ob);
    measure("join line,line (crossing): plane", st, plane_err(ob, x, m, S, L) * sn, 0);
    st = ga_object_from_mv(M, &ob);
    measure("meet_rel line,line: flat point", st, obj_err(ob, GA_OBJECT_FLATPOINT, x, 0, zero, L) * sn, 0);
    /* parallel lines, each the meet of two dual planes of normals n1, n2
       (so that their directions are the same doubles; lines built from points
       at D are parallel only to u D / S): at n1.y = d1 + e1, n2.y = d2 + e2
       for e = 0 and e = (S, S) times U(-1, 1); the points p = a n1 + b n2
       with [1 k; k 1] (a, b) = (d1, d2) + e; their plane of normal u x (p' - p) */
    ga_vec3 n1 = tk_unit(t), n2 = tk_unit(t), w;
    double k12 = dot(n1, n2), det = (1 - k12) * (1 + k12);
    double d1 = dot(n1, x), d2 = dot(n2, x), e1 = S * tk_range(t, -1, 1), e2 = S * tk_range(t, -1, 1);
    ga_mv L4 = ga_mv_meet(ga_plane_dual(n1, d1), ga_plane_dual(n2, d2));
    ga_mv L5 = ga_mv_meet(ga_plane_dual(n1, d1 + e1), ga_plane_dual(n2, d2 + e2));
    ga_vec3 up = unit(cross(n1, n2));
    w = add(tk_scale(n1, (e1 - k12 * e2) / det), tk_scale(n2, (e2 - k12 * e1) / det)); /* p' - p */
    ga_vec3 mw = unit(cross(up, w));
    JM(L4, L5);
    st = ga_object_from_mv(J, &ob);
    measure("join line,line (parallel): plane", st, plane_err(ob, x, mw, S, L) * det, 0);
    st = ga_object_from_mv(M, &ob);
    measure("meet_rel parallel lines: at infinity", st,
            ob.kind == GA_OBJECT_EMPTY ? dir_err(unit(ob.direction), up) * S / L : INFINITY, 0);
    double off = S * tk_range(t, 0.1, 1);
    w = unit(cross(u1, tk_unit(t)));
    mw = unit(cross(u1, w));
    /* a line in a plane, a line and a multiple of itself, a line and another
       pair of its points: the inputs as given */
    ga_mv P = ga_plane_from_points(sub(x, tk_scale(u1, al * S)), add(x, tk_scale(u1, be * S)),
                                   add(x, tk_scale(u2, ga * S)));
    tk_check *same = tk_get("join, meet_rel: a line in a plane: the plane, the line");
    JM(L1, P);
    tk_add_bool(same, same_mv(J, P) && same_mv(M, L1));
    JM(P, L1);
    tk_add_bool(same, same_mv(J, P) && same_mv(M, L1));
    same = tk_get("join, meet_rel: a line and -2.5 times it: the line, -2.5 L");
    ga_mv L1s = ga_mv_scale(L1, -2.5);
    JM(L1, L1s);
    tk_add_bool(same, same_mv(J, L1) && same_mv(M, L1s));
    /* the same line through two other points (up to D = 1e2: beyond, points
       S apart at D, rounded to u D, give lines whose directions differ by
       u D / S, which the decisions see at some D / S as two lines) */
    if (D <= 1e2) {
        same = tk_get("join, meet_rel: a line and the same through other points (D <= 1e2)");
        ga_mv L1b = ga_line_from_points(add(x, tk_scale(u1, ga * S)), sub(x, tk_scale(u1, de * S)));
        JM(L1, L1b);
        tk_add_bool(same, same_mv(J, L1) && same_mv(M, L1b));
    }
    /* two planes: in general position, ga_mv_meet bit for bit; their join the whole space */
    ga_mv P2 = ga_mv_dual(ga_plane_dual(u1, dot(u1, x) + S * tk_uni(t)));
    JM(P, P2);
    tk_add_bool(tk_get("meet_rel in general position: ga_mv_meet bit for bit"),
                same_mv(M, ga_mv_meet(P, P2)));
    tk_add_bool(tk_get("join of two planes: a pseudoscalar"),
                ga_mv_maxabs(ga_mv_grade(J, 5)) > 0 && ga_mv_maxabs(ga_mv_sub(J, ga_mv_grade(J, 5))) == 0);
    if (D != 1.0)
        return;

    /* a point on L1 and off it (by up to S along w): the line; the plane through both */
    ga_vec3 xo = add(x, tk_scale(u1, S * tk_range(t, -1, 1)));
    ga_mv X = ga_point_up(xo);
    same = tk_get("join, meet_rel: a point on a line: the line, the point");
    JM(X, L1);
    tk_add_bool(same, same_mv(J, L1) && same_mv(M, X));
    ga_vec3 xf = add(xo, tk_scale(w, off));
    JM(ga_point_up(xf), L1);
    st = ga_object_from_mv(J, &ob);
    measure("join point off a line: plane", st, plane_err(ob, x, mw, S, L), 0);
    tk_add_bool(tk_get("meet_rel of a point off a line: a scalar"),
                ga_mv_maxabs(ga_mv_sub(M, ga_mv_grade(M, 0))) == 0 && M.c[0] != 0);

    /* coplanar circles about c1 = x and c2 = x + d e (e in the plane of
       normal m), radii r1, r2, each through three points: the pair at
       x + h e, r^2 = r1^2 - h^2, along m x e; their join the plane */
    ga_vec3 a1 = unit(cross(m, tk_unit(t))), a2 = cross(m, a1);
    double r1 = S * tk_range(t, 0.2, 1), r2 = S * tk_range(t, 0.2, 1), ph = tk_range(t, 0, 2 * TK_PI);
    ga_vec3 e = add(tk_scale(a1, cos(ph)), tk_scale(a2, sin(ph)));
    ga_vec3 cp[3][2];
    double f1 = tk_range(t, 0, 2 * TK_PI), f2 = tk_range(t, 0, 2 * TK_PI);
    for (int i = 0; i < 3; i++) { /* three points about 120 degrees apart on each */
        double p1 = f1 + i * 2 * TK_PI / 3 + tk_range(t, -0.5, 0.5),
               p2 = f2 + i * 2 * TK_PI / 3 + tk_range(t, -0.5, 0.5);
        cp[i][0] = add(tk_scale(a1, cos(p1)), tk_scale(a2, sin(p1)));
        cp[i][1] = add(tk_scale(a1, cos(p2)), tk_scale(a2, sin(p2)));
    }
    ga_mv C1 = ga_circle_from_points(add(x, tk_scale(cp[0][0], r1)), add(x, tk_scale(cp[1][0], r1)),
                                     add(x, tk_scale(cp[2][0], r1)));
    static const char *nm[] = {"meet_rel coplanar circles: pair", "  ... tangent", "  ... imaginary"};
    static const int want[] = {GA_REALITY_REAL, GA_REALITY_TANGENT, GA_REALITY_IMAGINARY};
    for (int cs = 0; cs < 3; cs++) {
        double d = cs == 0 ? tk_range(t, fabs(r1 - r2), r1 + r2)
                 : cs == 1 ? r1 + r2
                           : (r1 + r2) * tk_range(t, 1.1, 3);
        ga_vec3 c2 = add(x, tk_scale(e, d));
        ga_mv C2 = ga_circle_from_points(add(c2, tk_scale(cp[0][1], r2)), add(c2, tk_scale(cp[1][1], r2)),
                                         add(c2, tk_scale(cp[2][1], r2)));
        double h = (d * d + r1 * r1 - r2 * r2) / (2 * d);
        JM(C1, C2);
        st = ga_object_from_mv(J, &ob);
        measure("join coplanar circles: plane", st, plane_err(ob, x, m, S, L), 0);
        st = ga_object_from_mv(M, &ob);
        measure(nm[cs], st,
                obj_err(ob, GA_OBJECT_POINTPAIR, add(x, tk_scale(e, h)), (r1 - h) * (r1 + h), cross(m, e), L),
                0);
        tk_add_bool(tk_get("coplanar circles: real, tangent and imaginary pairs classified so"),
                    st == GA_OK && ob.reality == want[cs]);
    }

    /* circles on the sphere (c = x, R): in the planes n_i.(y - c) = s_i; their
       pair on the line of the two planes, at q = c + al n1 + be n2 with
       q - c along n1, n2 at s1, s2: r^2 = R^2 - |q - c|^2, along n1 x n2 */
    double R = S * tk_range(t, 0.5, 1);
    ga_vec3 n[2], ci[2];
    double s[2];
    ga_mv C[2];
    for (int i = 0; i < 2; i++) {
        n[i] = tk_unit(t);
        s[i] = R * tk_range(t, -0.9, 0.9);
        ci[i] = add(x, tk_scale(n[i], s[i]));
        double rho = sqrt((R - s[i]) * (R + s[i]));
        ga_vec3 b1 = unit(cross(n[i], tk_unit(t))), b2 = cross(n[i], b1), q3[3];
        double f = tk_range(t, 0, 2 * TK_PI);
        for (int k = 0; k < 3; k++) {
            double p = f + k * 2 * TK_PI / 3 + tk_range(t, -0.5, 0.5);
            q3[k] = add(ci[i], tk_scale(add(tk_scale(b1, cos(p)), tk_scale(b2, sin(p))), rho));
        }
        C[i] = ga_circle_from_points(q3[0], q3[1], q3[2]);
    }
    double kn = dot(n[0], n[1]), sq = tk_norm(cross(n[0], n[1]));
    ga_vec3 qc = add(tk_scale(n[0], (s[0] - kn * s[1]) / (sq * sq)),
                     tk_scale(n[1], (s[1] - kn * s[0]) / (sq * sq)));
    JM(C[0], C[1]);
    st = ga_object_from_mv(J, &ob);
    measure("join circles on a sphere: sphere", st, obj_err(ob, GA_OBJECT_SPHERE, x, R * R, zero, L), 0);
    st = ga_object_from_mv(M, &ob);
    measure("meet_rel circles on a sphere: pair", st,
            obj_err(ob, GA_OBJECT_POINTPAIR, add(x, qc), R * R - dot(qc, qc), unit(cross(n[0], n[1])), L) *
                sq * sq,
            0);
    /* a circle on the sphere: the sphere, the circle; across a sphere about
       another centre: ga_mv_meet bit for bit */
    ga_mv Sd = ga_mv_dual(ga_sphere_dual(x, R));
    same = tk_get("join, meet_rel: a circle on a sphere: the sphere, the circle");
    JM(C[0], Sd);
    tk_add_bool(same, same_mv(J, Sd) && same_mv(M, C[0]));
    ga_mv S2 = ga_mv_dual(ga_sphere_dual(add(ci[0], tk_scale(tk_unit(t), R * tk_uni(t))), R));
    JM(C[0], S2);
    tk_add_bool(tk_get("meet_rel in general position: ga_mv_meet bit for bit"),
                same_mv(M, ga_mv_meet(C[0], S2)));
    /* two point pairs sharing the point x: the point (a vector, read as a
       sphere of radius 0 about it); their join the circle through the three */
    ga_vec3 pb = add(x, tk_scale(tk_unit(t), S)), pc = add(x, tk_scale(tk_unit(t), S));
    JM(ga_pointpair_from_points(x, pb), ga_pointpair_from_points(pc, x));
    st = ga_object_from_mv(M, &ob);
    measure("meet_rel pairs sharing a point: it", st, obj_err(ob, GA_OBJECT_SPHERE, x, 0, zero, L), 0);
    st = ga_object_from_mv(J, &ob);
    {
        /* the circle through x, pb, pc: centre x + k (circumcentre, as in scene_about) */
        ga_vec3 d2 = sub(pb, x), d3 = sub(pc, x), nc = cross(d2, d3);
        ga_vec3 kc = tk_scale(cross(sub(tk_scale(d3, dot(d2, d2)), tk_scale(d2, dot(d3, d3))), nc),
                              0.5 / dot(nc, nc));
        measure("join pairs sharing a point: circle", st,
                obj_err(ob, GA_OBJECT_CIRCLE, add(x, kc), dot(kc, kc), unit(nc), L) * tk_norm(nc) / (S * S),
                0);
    }
#undef JM
}

/* the distances from the origin the scenes are placed at */
static const double dists[] = {1, 1e2, 1e4, 1e6, 1e8};

/* the scenes, per distance D from the origin */
static void section_scenes(void)
{
    tk_rng t = {tk_seed(14)}, ta = {tk_seed(1414)};
    tk_note("worst error per kind, per distance D from the origin (lengths / L, r^2 / L^2; read-backs: over\n"
            "the larger of that and their stated bound, times 1e-12)\n");
    for (int k = 0; k < 5; k++) {
        for (int i = 0; i < 300; i++) scene(&t, dists[k]);
        for (int i = 0; i < 300; i++) scene_about(&ta, dists[k]);
        flush(dists[k]);
    }
}

/* join and meet_rel of the scenes, per distance D */
static void section_join(void)
{
    tk_rng tj = {tk_seed(2222)};
    status_check = "join, meet_rel: results read back with GA_OK";
    tk_note("join and meet_rel, worst error per kind, per distance D\n");
    for (int k = 0; k < 5; k++) {
        for (int i = 0; i < 300; i++) scene_join(&tj, dists[k]);
        flush(dists[k]);
    }
}

/* statuses */
static void section_statuses(void)
{
    ga_object ob;
    ga_vec3 z = {0, 0, 0}, ex = {1, 0, 0};
    tk_expect_status("imaginary sphere: GA_ERR_IMAGINARY from ga_sphere_params",
                     ga_sphere_params(ga_sphere_dual(z, -1.0) /* r^2 = 1 */, &z, &(double){0}), GA_OK);
    ga_mv im = ga_sphere_dual(z, 0);
    im.c[GA_BLADE_E4] += 0.5; /* + (1/2) n: r^2 = -1 */
    im.c[GA_BLADE_E5] += 0.5;
    tk_expect_status("imaginary sphere: GA_ERR_IMAGINARY, not GA_ERR_NOTBLADE",
                     ga_sphere_params(im, &z, &(double){0}), GA_ERR_IMAGINARY);
    tk_expect_status("object of an imaginary sphere reads", ga_object_from_mv(im, &ob), GA_OK);
    tk_expect(ob.kind == GA_OBJECT_SPHERE && ob.reality == GA_REALITY_IMAGINARY && ob.r2 == -1.0,
              "imaginary sphere: kind, reality, r^2 = -1");
    tk_expect_status("projection onto an imaginary sphere", ga_point_project(ex, im, &z), GA_ERR_IMAGINARY);
    tk_expect_status("wrong kind: a line is no sphere",
                     ga_sphere_params(ga_line_from_points(z, ex), &z, &(double){0}), GA_ERR_NOTBLADE);
    tk_expect_status("zero: GA_ERR_SINGULAR", ga_object_from_mv(ga_mv_zero(), &ob), GA_ERR_SINGULAR);
    tk_expect_status("mixed grades: GA_ERR_NOTBLADE",
                     ga_object_from_mv(ga_mv_add(ga_mv_scalar(1), ga_mv_n()), &ob), GA_ERR_NOTBLADE);
    tk_expect_status("centre of a sphere: no nearest point", ga_point_project(z, ga_sphere_dual(z, 1), &ex),
                     GA_ERR_DOMAIN);
    tk_expect_status("rotor between spheres of different radii",
                     ga_rotor_between(ga_sphere_dual(z, 1), ga_sphere_dual(z, 2), &(ga_rotor){0}),
                     GA_ERR_NOTRIGID);
    tk_expect_status("rotor between a sphere and a plane",
                     ga_rotor_between(ga_sphere_dual(z, 1), ga_plane_dual(ex, 0), &(ga_rotor){0}),
                     GA_ERR_ARG);
    /* the other branches of ga_object_angle and ga_rotor_between, by hand:
       unit spheres sqrt(2) apart cross at right angles (r1^2 + r2^2 = d^2);
       a sphere and a plane through its centre too; the line x = y (z = 0)
       and the plane z = 0 at 0; the plane x = 1 and the line along z at 0 */
    double ang, s2 = sqrt(2.0);
    ga_vec3 ez = {0, 0, 1};
    tk_add_status(tk_get("angles: statuses"),
                  ga_object_angle(ga_sphere_dual(z, 1), ga_sphere_dual((ga_vec3){s2, 0, 0}, 1), &ang), GA_OK);
    tk_add_tol(tk_get("angle of spheres sqrt(2) apart: pi/2"), fabs(ang - TK_PI / 2), 4 * DBL_EPSILON);
    tk_add_status(tk_get("angles: statuses"),
                  ga_object_angle(ga_sphere_dual(z, 1), ga_plane_dual(ez, 0), &ang), GA_OK);
    tk_add_tol(tk_get("angle of a sphere and a plane through its centre: pi/2"), fabs(ang - TK_PI / 2),
               4 * DBL_EPSILON);
    tk_add_status(tk_get("angles: statuses"),
                  ga_object_angle(ga_plane_dual(ez, 0), ga_line_from_points(z, (ga_vec3){1, 1, 0}), &ang),
                  GA_OK);
    tk_add_tol(tk_get("angle of a line in a plane's direction: 0"), fabs(ang), 4 * DBL_EPSILON);
    tk_add_status(tk_get("angles: statuses"),
                  ga_object_angle(ga_sphere_dual(z, 1), ga_sphere_dual((ga_vec3){3, 0, 0}, 1), &ang),
                  GA_ERR_DOMAIN);
    tk_add_status(tk_get("angles: statuses"),
                  ga_object_angle(ga_sphere_dual(z, 1), ga_line_from_points(z, ez), &ang), GA_ERR_NOTBLADE);
    /* accuracy of the angle near 0 and near pi/2, against constructions whose
       angle is known in closed form from their (exact) doubles; each case
       builds angles e and pi/2 - e, e = 1e-8. The sine comes from a wedge
       and the cosine from an inner product, so the relative error is a few
       roundings: of the constructor and read-back (a unit vector, a centre,
       r^2, each within 2 u relative), of the sine and cosine (a few u), of
       atan2 (1 u). 16 u covers them; acos of the cosine alone is off by
       about sqrt(u) ~ 1.5e-8 absolute, which is 100% relative at 1e-8. */
    const double e = 1e-8, rtol = 16 * DBL_EPSILON;
    tk_check *acc_ang = tk_get("angle near 0 and pi/2: relative error <= 16 u");
    for (int k = 0; k < 2; k++) {
        /* k = 0: the angle near 0; k = 1: near pi/2 */
        double want;
        /* planes: normals ez and (e, 0, 1) meet at atan(e); ez and (1, 0, e) at atan2(1, e) */
        ga_vec3 n2 = k ? (ga_vec3){1, 0, e} : (ga_vec3){e, 0, 1};
        want = k ? atan2(1.0, e) : atan(e);
        tk_add_status(tk_get("angles: statuses"),
                      ga_object_angle(ga_plane_dual(ez, 0), ga_plane_dual(n2, 3), &ang), GA_OK);
        tk_add_tol(acc_ang, fabs(ang - want) / want, rtol);
        /* lines: directions ex and (1, e, 0), or (e, 1, 0) */
        ga_vec3 d2 = k ? (ga_vec3){e, 1, 0} : (ga_vec3){1, e, 0};
        tk_add_status(tk_get("angles: statuses"),
                      ga_object_angle(ga_line_from_points(z, ex), ga_line_from_points(ez, add(ez, d2)), &ang),
                      GA_OK);
        tk_add_tol(acc_ang, fabs(ang - want) / want, rtol);
        /* a line and the plane z = 0: direction (1, 0, e) is atan(e) out of it,
           (e, 0, 1) is atan2(1, e) */
        tk_add_status(
            tk_get("angles: statuses"),
            ga_object_angle(ga_line_from_points(ex, add(ex, k ? (ga_vec3){e, 0, 1} : (ga_vec3){1, 0, e})),
                            ga_plane_dual(ez, 0), &ang),
            GA_OK);
        tk_add_tol(acc_ang, fabs(ang - want) / want, rtol);
        /* a sphere of radius 3 centred at (0, 0, h) and the plane z = 0 cross
           at acos(h / 3) = atan2(sqrt((3 - h)(3 + h)), h): h the double below 3
           gives about 1.7e-8 (h / 3 is no double: acos of it rounded is off by
           13%), h = 3e-8 about pi/2 - 1e-8 */
        double h = k ? 3 * e : nextafter(3.0, 0.0);
        want = atan2(sqrt((3 - h) * (3 + h)), h);
        tk_add_status(tk_get("angles: statuses"),
                      ga_object_angle(ga_sphere_dual((ga_vec3){0, 0, h}, 3), ga_plane_dual(ez, 0), &ang),
                      GA_OK);
        tk_add_tol(acc_ang, fabs(ang - want) / want, rtol);
        /* unit spheres d apart: the triangle of radii 1, 1 and d has the angle
           2 asin(d / 2) between the normals where they cross; d = e, or the d
           of the angle pi/2 - e (the angle taken for the double d) */
        double d = k ? 2 * sin(TK_PI / 4 - e / 2) : e;
        want = 2 * asin(d / 2);
        tk_add_status(tk_get("angles: statuses"),
                      ga_object_angle(ga_sphere_dual(z, 1), ga_sphere_dual((ga_vec3){0, 0, d}, 1), &ang),
                      GA_OK);
        tk_add_tol(acc_ang, fabs(ang - want) / want, rtol);
    }
    /* the local-origin functions' statuses */
    ga_vec3 nanv = {NAN, 0, 0};
    ga_mv lm;
    tk_expect_status("about: NaN origin", ga_object_from_mv_about(ga_sphere_dual(z, 1), nanv, 1, &ob),
                     GA_ERR_NOTFINITE);
    tk_expect_status("about: lambda 0", ga_object_from_mv_about(ga_sphere_dual(z, 1), z, 0, &ob), GA_ERR_ARG);
    tk_expect_status("about: a line is still no object of grade 0",
                     ga_object_from_mv_about(ga_mv_scalar(1), z, 1, &ob), GA_ERR_NOTBLADE);
    tk_expect_status("localize: lambda -1", ga_mv_localize(ga_sphere_dual(z, 1), z, -1, &lm), GA_ERR_ARG);
    tk_expect_status("localize: NaN", ga_mv_localize(ga_sphere_dual(nanv, 1), z, 1, &lm), GA_ERR_NOTFINITE);
    tk_expect_status("localize: overflow",
                     ga_mv_localize(ga_sphere_dual((ga_vec3){4, 0, 0}, 1), z, 1e-308, &lm), GA_ERR_DOMAIN);
    tk_expect_status("apply_about: NaN", ga_rotor_apply_about(ga_rotor_identity(), nanv, im, &ex, &lm),
                     GA_ERR_NOTFINITE);
    /* about (o, 1) with o = 1e8 ex, the unit sphere at 1e8 + (1, 0, 0) reads back
       exactly (its local form is exact) */
    ga_vec3 far = {1e8, 0, 0};
    tk_expect_status("about: unit sphere at 1e8", ga_object_from_mv_about(ga_sphere_dual(ex, 1), far, 1, &ob),
                     GA_OK);
    tk_expect(ob.kind == GA_OBJECT_SPHERE && ob.centre.x == 1e8 + 1 && ob.r2 == 1,
              "about: unit sphere at 1e8 + 1: centre and r^2 exact");
    /* about (0, 1), a unit sphere at 1e4 is read with what its storage keeps:
       its weight to u 1e8, so r^2 = 1 to about 3 (tangent: not known to be
       positive), the centre to about 1e-4; at 1e8 it is a plane as stored */
    tk_expect_status("world: unit sphere at 1e4 read with its bounds",
                     ga_object_from_mv(ga_sphere_dual((ga_vec3){1e4, 0, 0}, 1), &ob), GA_OK);
    tk_expect(ob.kind == GA_OBJECT_SPHERE && fabs(ob.r2 - 1) <= ob.r2_err && ob.r2_err > 1 &&
                  ob.r2_err < 10 && fabs(ob.centre.x - 1e4) <= ob.err && ob.reality == GA_REALITY_TANGENT,
              "world: unit sphere at 1e4: r^2 within r2_err (1 < r2_err < 10), tangent");
    /* ga_mv_join and ga_mv_meet_rel: statuses, and nothing written on failure */
    {
        ga_mv Lz = ga_line_from_points(z, ez), nanL = Lz, keep = ga_mv_scalar(7), out = keep;
        nanL.c[GA_BLADE_E145] = NAN;
        ga_mv big = ga_mv_scale(Lz, 1e300),
              big2 = ga_mv_scale(ga_line_from_points(ex, (ga_vec3){1, 1, 0}), 1e300);
        ga_mv e12e34 = ga_mv_add(ga_mv_blade(GA_BLADE_E12), ga_mv_blade(GA_BLADE_E34));
        ga_mv e123e345 = ga_mv_add(ga_mv_blade(GA_BLADE_E123), ga_mv_blade(GA_BLADE_E345));
        struct {
            const char *what;
            ga_mv a, b;
            int want;
        } cs[] = {
            {"join, meet_rel: NaN", nanL, Lz, GA_ERR_NOTFINITE},
            {"join, meet_rel: NaN after a scalar (NaN first)", ga_mv_scalar(1), nanL, GA_ERR_NOTFINITE},
            {"join, meet_rel: Inf", Lz, ga_mv_scale(Lz, INFINITY), GA_ERR_NOTFINITE},
            {"join, meet_rel: zero", ga_mv_zero(), Lz, GA_ERR_SINGULAR},
            {"join, meet_rel: a scalar (grade 0)", Lz, ga_mv_scalar(2), GA_ERR_DOMAIN},
            {"join, meet_rel: a pseudoscalar (grade 5)", ga_mv_blade(GA_BLADE_E12345), Lz, GA_ERR_DOMAIN},
            {"join, meet_rel: mixed grades", ga_mv_add(Lz, ga_mv_n()), Lz, GA_ERR_NOTBLADE},
            {"join, meet_rel: e12 + e34, no blade", e12e34, Lz, GA_ERR_NOTBLADE},
            {"join, meet_rel: e123 + e345, no blade", Lz, e123e345, GA_ERR_NOTBLADE},
            {"join, meet_rel: overflow of A ^ B", big, big2, GA_ERR_DOMAIN},
        };
        for (size_t i = 0; i < sizeof cs / sizeof cs[0]; i++) {
            tk_expect_status(cs[i].what, ga_mv_join(cs[i].a, cs[i].b, &out), cs[i].want);
            tk_expect_status(cs[i].what, ga_mv_meet_rel(cs[i].a, cs[i].b, &out), cs[i].want);
            tk_add_bool(tk_get("join, meet_rel: the output untouched on failure"), same_mv(out, keep));
        }
        /* by hand: the lines x = 0 and y = 0 of the plane z = 0 meet in the
           flat point of the origin, their join is that plane; the point (2, 0, 0)
           on the second: the line, the point */
        ga_mv Lx = ga_line_from_points(z, ex), Ly = ga_line_from_points(z, (ga_vec3){0, 1, 0}), J, M;
        tk_expect_status("join of the x and y axes", ga_mv_join(Lx, Ly, &J), GA_OK);
        tk_expect_status("meet_rel of the x and y axes", ga_mv_meet_rel(Lx, Ly, &M), GA_OK);
        ga_object oj, om;
        tk_expect(ga_object_from_mv(J, &oj) == GA_OK && oj.kind == GA_OBJECT_PLANE &&
                      fabs(fabs(oj.direction.z) - 1) == 0 && tk_norm(oj.centre) == 0,
                  "join of the x and y axes: the plane z = 0");
        tk_expect(ga_object_from_mv(M, &om) == GA_OK && om.kind == GA_OBJECT_FLATPOINT &&
                      tk_norm(om.centre) <= 1e-16,
                  "meet_rel of the x and y axes: the origin");
        ga_mv X2 = ga_point_up((ga_vec3){2, 0, 0});
        tk_expect(ga_mv_join(X2, Lx, &J) == GA_OK && same_mv(J, Lx) && ga_mv_meet_rel(Lx, X2, &M) == GA_OK &&
                      same_mv(M, X2),
                  "(2, 0, 0) and the x axis: join the axis, meet the point");
    }
    /* antiparallel planes: a half turn about a perpendicular axis */
    ga_rotor H;
    ga_vec3 mz = {0, 0, -1};
    tk_add_status(tk_get("rotor between opposite planes"),
                  ga_rotor_between(ga_plane_dual(ez, 0), ga_plane_dual(mz, 1), &H), GA_OK);
    ga_vec3 hz = ga_rotor_apply(H, ez), h0 = ga_rotor_apply(H, z);
    tk_add_tol(tk_get("rotor between opposite planes: normal reversed, origin to z = -1"),
               tk_max(tk_norm(sub(sub(hz, h0), mz)), tk_norm(sub(h0, mz))), 8 * DBL_EPSILON);
    tk_end_named();
}

static const tk_section sections[] = {
    {"scenes", section_scenes, 0},
    {"join", section_join, 0},
    {"statuses", section_statuses, 0},
};

int main(int argc, char **argv) { return tk_main(argc, argv, "test_meet", sections, TK_COUNT(sections)); }
