/* tests/test_meet_special.c: ga_mv_meet of objects in special position, and
 * of rounds in general position against the plain dual-wedge formula.
 *
 * Special position: the meet in the whole space is 0 in exact arithmetic,
 * and in floating point a residue of the objects' rounding, which must come
 * out as 0 (ga_object_from_mv: GA_ERR_SINGULAR, object.h), never as an
 * object read from the residue. The cases of issue 25 and their kin, each
 * built from random points at distances D = 1 .. 1e8 from the origin with a
 * size log-uniform between 1 and D: a sphere with itself, with 3 times
 * itself and with the same sphere built from other points on it; a circle
 * with the same circle through three other of its points; a line lying in a
 * plane; two lines through a common point; coincident planes (built from
 * other points, and a dual plane with a multiple of it). The other side of
 * the threshold: the same sphere moved by 2^13 u L, and a line and a plane
 * moved 2^10 u L off it, are in general position, and their meet answers.
 *
 * General position: rounds of radius around 20 at centres around 20 from the
 * origin (the size of clifford's random test objects): the meet of a sphere
 * with a line, a plane and a sphere against ((A I^-1) ^ (B I^-1)) I taken
 * in binary128 (rounded once), the largest coefficient difference over the
 * largest coefficient (the meet about the round's centre must not lose what
 * the direct formula keeps); and every such meet is a real or imaginary
 * object, never 0.
 *
 * Far and at infinity: spheres through the origin far out keep their
 * weight (ga_sphere_dual); a line meeting a plane at a grazing angle is
 * that flat point, never EMPTY above 32 u; a line parallel to a plane up to
 * its rounding meets it at infinity (EMPTY) by both meets.
 */
#include "testkit.h"

static ga_vec3 add(ga_vec3 a, ga_vec3 b) { return (ga_vec3){a.x + b.x, a.y + b.y, a.z + b.z}; }
static ga_vec3 sub(ga_vec3 a, ga_vec3 b) { return (ga_vec3){a.x - b.x, a.y - b.y, a.z - b.z}; }
static double dot(ga_vec3 a, ga_vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

/* the meet of A and B must be 0: read back, GA_ERR_SINGULAR */
static void zero_meet(const char *what, double D, ga_mv A, ga_mv B)
{
    ga_object ob = {0};
    char name[96];
    snprintf(name, sizeof name, "D=%-5g %s: meet 0 (GA_ERR_SINGULAR)", D, what);
    ga_mv M = ga_mv_meet(A, B);
    tk_add_status(tk_get(name), ga_object_from_mv(M, &ob), GA_ERR_SINGULAR);
}

/* the meet of A and B, in general position by a little more than their
   rounding, must answer: not 0, so not GA_ERR_SINGULAR */
static void real_meet(const char *what, double D, ga_mv A, ga_mv B)
{
    ga_object ob = {0};
    char name[96];
    snprintf(name, sizeof name, "D=%-5g %s: meet answers", D, what);
    ga_mv M = ga_mv_meet(A, B);
    tk_add_bool(tk_get(name), tk_mv_maxabs(M) > 0.0 && ga_object_from_mv(M, &ob) != GA_ERR_SINGULAR);
}

static const double dists[] = {1, 1e2, 1e4, 1e6, 1e8};

/* a vector of integers: exact at every distance here (below 2^53) */
static ga_vec3 iv(double x, double y, double z) { return (ga_vec3){x, y, z}; }
static double iround(tk_rng *t, double D) { return floor(tk_range(t, -D, D)); }

/* Objects in special position whose points are exact: integer coordinates,
   circles and spheres through Pythagorean points (3, 4, 5 and 5, 12, 13
   scaled by an integer k), so the special position holds for the points as
   stored and only the constructions round. */
static void scene_exact(tk_rng *t, double D)
{
    double k = D == 1.0 ? 1 : floor(tk_loguni(t, 1, D / 8)), X = iround(t, D), Y = iround(t, D),
           Z = iround(t, D);
    /* the circle of radius 5k about (X, Y, Z) in the plane z = Z, and the
       sphere of radius 13k about it */
    ga_vec3 q[6] = {iv(X + 3 * k, Y + 4 * k, Z), iv(X - 4 * k, Y + 3 * k, Z), iv(X + 5 * k, Y, Z),
                    iv(X, Y - 5 * k, Z),         iv(X - 3 * k, Y - 4 * k, Z), iv(X + 4 * k, Y - 3 * k, Z)};
    ga_vec3 p[8] = {iv(X + 12 * k, Y + 5 * k, Z), iv(X, Y - 12 * k, Z + 5 * k), iv(X - 5 * k, Y, Z - 12 * k),
                    iv(X + 13 * k, Y, Z),         iv(X - 12 * k, Y, Z + 5 * k), iv(X, Y + 5 * k, Z - 12 * k),
                    iv(X + 5 * k, Y + 12 * k, Z), iv(X, Y, Z + 13 * k)};
    ga_mv C1 = ga_circle_from_points(q[0], q[1], q[2]);
    zero_meet("exact: circle with itself from other points", D, C1, ga_circle_from_points(q[3], q[4], q[5]));
    ga_mv S1 = ga_sphere_from_points(p[0], p[1], p[2], p[3]),
          S2 = ga_sphere_from_points(p[4], p[5], p[6], p[7]);
    zero_meet("exact: sphere with itself from other points", D, S1, S2);
    zero_meet("exact: sphere (points) with the dual sphere", D, S1, ga_sphere_dual(iv(X, Y, Z), 13 * k));
    /* the plane z = Z from three of the circle's points and from three others */
    ga_mv P = ga_plane_from_points(q[0], q[1], q[2]);
    zero_meet("exact: coincident planes from other points", D, P, ga_plane_from_points(q[3], q[4], q[5]));
    zero_meet("exact: plane and the dual plane z = Z", D, P, ga_plane_dual(iv(0, 0, 1), Z));
    zero_meet("exact: line lying in a plane (other points)", D, ga_line_from_points(q[3], q[5]), P);
    zero_meet("exact: circle lying on its sphere", D, C1, ga_sphere_dual(iv(X, Y, Z), 5 * k));
    /* Both sides of the threshold: the same pairs moved apart by a little
       more than the inputs' rounding are in general position, and their
       meet answers (not 0: ga_object_from_mv does not say GA_ERR_SINGULAR).
       The sphere's centre moved by 2^13 u L (L = |c| + r, 9.1e-13 L), the
       plane by 2^10 u L off the line (1.1e-13 L): ga_mv_meet's threshold for
       these (meet.c) is some 500 u L and 130 u L, measured over the seeds. */
    double L = sqrt(X * X + Y * Y + Z * Z) + 13 * k, Lc = sqrt(X * X + Y * Y + Z * Z) + 5 * k;
    ga_vec3 dir = tk_unit(t);
    ga_vec3 moved = {X + 0x1p13 * DBL_EPSILON / 2 * L * dir.x, Y + 0x1p13 * DBL_EPSILON / 2 * L * dir.y,
                     Z + 0x1p13 * DBL_EPSILON / 2 * L * dir.z};
    real_meet("exact: sphere and itself moved 2^13 u L", D, S1, ga_sphere_dual(moved, 13 * k));
    real_meet("exact: line and the plane moved 2^10 u L off it", D, ga_line_from_points(q[3], q[5]),
              ga_plane_dual(iv(0, 0, 1), Z + 0x1p10 * DBL_EPSILON / 2 * Lc));
}

static void section_special(void)
{
    tk_rng t = {tk_seed(2525)}, te = {tk_seed(2552)};
    for (int k = 0; k < 5; k++) {
        double D = dists[k];
        for (int i = 0; i < 200; i++) {
            scene_exact(&te, D);
            double S = D == 1.0 ? tk_loguni(&t, 0.1, 1) : tk_loguni(&t, 1, D);
            ga_vec3 o = tk_scale(tk_unit(&t), D);
            /* a sphere of centre c and radius r, and points on it */
            ga_vec3 c = add(o, tk_scale(tk_unit(&t), S * tk_uni(&t)));
            double r = S * tk_range(&t, 0.2, 1);
            ga_vec3 p[4];
            for (int j = 0; j < 4; j++) p[j] = add(c, tk_scale(tk_unit(&t), r));
            ga_mv s = ga_sphere_dual(c, r);
            zero_meet("sphere with itself", D, s, s);
            zero_meet("sphere with 3 times itself", D, s, ga_mv_scale(s, 3.0));
            ga_mv S1 = ga_sphere_from_points(p[0], p[1], p[2], p[3]);
            zero_meet("sphere (points) with 3 times itself", D, S1, ga_mv_scale(S1, 3.0));
            zero_meet("circle with itself", D, ga_circle_from_points(p[0], p[1], p[2]),
                      ga_circle_from_points(p[0], p[1], p[2]));
            zero_meet("circle with -2 times itself", D, ga_circle_from_points(p[0], p[1], p[2]),
                      ga_mv_scale(ga_circle_from_points(p[0], p[1], p[2]), -2.0));
            /* a plane through a, b, c; a line through two of them; two lines
               through a common point; the same plane from the points in
               another order */
            ga_vec3 a = add(o, tk_scale(tk_unit(&t), S * tk_uni(&t)));
            /* a well-conditioned triangle: sides S at right angles */
            ga_vec3 e1 = tk_unit(&t), e2 = tk_unit(&t);
            double e12 = e1.x * e2.x + e1.y * e2.y + e1.z * e2.z;
            e2 = tk_scale(add(e2, tk_scale(e1, -e12)), 1 / sqrt(1 - e12 * e12));
            ga_vec3 b = add(a, tk_scale(e1, S)), d = add(a, tk_scale(e2, S));
            ga_vec3 x = add(a, tk_scale(tk_unit(&t), S));
            ga_mv P = ga_plane_from_points(a, b, d);
            zero_meet("plane with itself", D, P, P);
            zero_meet("line lying in a plane (its points)", D, ga_line_from_points(a, b), P);
            zero_meet("two lines through a common point", D, ga_line_from_points(a, b),
                      ga_line_from_points(a, x));
            /* the same plane built from its points in another order, about
               another point (built in double, each carried the rounding of
               the differences, some 10 u D / S of its size: 77 u at D / S = 8,
               beyond the meet's 32 u; in double-double, each is the plane
               of the points to its own rounding) */
            zero_meet("the plane and itself built from its points in another order", D, P,
                      ga_plane_from_points(d, a, b));
            zero_meet("a line of the plane through two others of its points", D, ga_line_from_points(b, d),
                      P);
            ga_vec3 mm = tk_unit(&t);
            double dd = mm.x * a.x + mm.y * a.y + mm.z * a.z;
            zero_meet("coincident dual planes (a multiple)", D, ga_plane_dual(mm, dd),
                      ga_mv_scale(ga_plane_dual(mm, dd), -3.0));
        }
        tk_end_named();
    }
}

/* The sign of the product of basis blades a and b (bit masks): the swaps
   that sort them, and e5 e5 = -1 (written here again, as the reference). */
static int blade_sign(unsigned a, unsigned b)
{
    int swaps = 0;
    for (unsigned x = a >> 1; x; x >>= 1)
        for (unsigned y = x & b; y; y &= y - 1) swaps++;
    if (a & b & 0x10u)
        swaps++;
    return swaps & 1 ? -1 : 1;
}

/* ((A I^-1) ^ (B I^-1)) I in binary128 (A and B direct, a vector taken as
   dual): every product of two doubles is exact there, and the sums of a
   wedge's few terms lose nothing a double can hold; rounded at the end */
static ga_mv dual_wedge_exact(ga_mv A, ga_mv B)
{
    if (tk_mv_maxabs(ga_mv_sub(A, ga_mv_grade(A, 1))) == 0.0)
        A = ga_mv_dual(A);
    if (tk_mv_maxabs(ga_mv_sub(B, ga_mv_grade(B, 1))) == 0.0)
        B = ga_mv_dual(B);
    ga_mv a = ga_mv_dual(A), b = ga_mv_dual(B); /* exact: a signed permutation */
    __float128 w[32] = {0};
    int index[32];
    for (int i = 0; i < 32; i++) index[ga_blade_mask(i)] = i;
    for (int i = 0; i < 32; i++)
        for (int j = 0; j < 32; j++) {
            unsigned mi = ga_blade_mask(i), mj = ga_blade_mask(j);
            if (a.c[i] == 0.0 || b.c[j] == 0.0 || (mi & mj))
                continue;
            w[index[mi | mj]] += (__float128)blade_sign(mi, mj) * (__float128)a.c[i] * (__float128)b.c[j];
        }
    ga_mv W;
    for (int i = 0; i < 32; i++) W.c[i] = (double)w[i];
    return ga_mv_undual(W); /* exact again */
}

static void general(tk_check *c, tk_check *nz, ga_mv A, ga_mv B)
{
    ga_mv M = ga_mv_meet(A, B), W = dual_wedge_exact(A, B);
    double s = tk_mv_maxabs(W);
    tk_add(c, tk_mv_maxabs(ga_mv_sub(M, W)) / s);
    ga_object ob;
    tk_add_status(nz, ga_object_from_mv(M, &ob), GA_OK);
}

static void section_general(void)
{
    tk_rng t = {tk_seed(2626)};
    tk_check cl = tk_begin("sphere ^ line against the exact dual wedge (max diff / max)", 1e-15),
             cp = tk_begin("sphere ^ plane against the exact dual wedge", 1e-15),
             cs = tk_begin("sphere ^ sphere against the exact dual wedge", 1e-15),
             nz = tk_begin("meets in general position read back with GA_OK", 0);
    for (int i = 0; i < 300; i++) {
        ga_vec3 c1 = tk_scale(tk_unit(&t), tk_range(&t, 0, 40)), c2 = add(c1, tk_scale(tk_unit(&t), 30));
        double r1 = tk_range(&t, 15, 25), r2 = tk_range(&t, 15, 25);
        ga_mv s1 = ga_sphere_dual(c1, r1), s2 = ga_sphere_dual(c2, r2);
        ga_vec3 a = tk_scale(tk_unit(&t), tk_range(&t, 0, 40)), b = add(a, tk_scale(tk_unit(&t), 20));
        ga_vec3 d = add(a, tk_scale(tk_unit(&t), 20));
        general(&cl, &nz, s1, ga_line_from_points(a, b));
        general(&cp, &nz, s1, ga_plane_from_points(a, b, d));
        general(&cs, &nz, s1, s2);
    }
    tk_end(&cl);
    tk_end(&cp);
    tk_end(&cs);
    tk_end(&nz);
}

/* ga_mv_meet_rel and ga_mv_join of a line and the same line through two
   other of its points (computed, so off it by their rounding, u D of their
   spacing S times D / S): the same line, not two lines meeting in a flat
   point; and ga_mv_localize of a round built in world coordinates far out:
   refused, as its local form would claim digits it does not hold. */
static void section_rel(void)
{
    tk_rng t = {tk_seed(2727)};
    for (int k = 0; k < 5; k++) {
        double D = dists[k];
        char name[96];
        snprintf(name, sizeof name, "D=%-5g line and itself from other points: meet_rel, join the line", D);
        tk_check *c = tk_get(name);
        for (int i = 0; i < 300; i++) {
            /* points S apart, S from D / 1e4 (a construction condition of 1e4) to D */
            double S = D == 1.0 ? 1.0 : tk_loguni(&t, D / 1e4, D);
            ga_vec3 a = tk_scale(tk_unit(&t), D), u = tk_scale(tk_unit(&t), S);
            double s1 = tk_range(&t, -3, 3), s2 = tk_range(&t, 4, 9);
            ga_mv L1 = ga_line_from_points(a, add(a, u));
            ga_mv L2 = ga_line_from_points(add(a, tk_scale(u, s1)), add(a, tk_scale(u, s2)));
            ga_mv M, J;
            ga_object om, oj;
            int ok = ga_mv_meet_rel(L1, L2, &M) == GA_OK && ga_mv_join(L1, L2, &J) == GA_OK &&
                     ga_object_from_mv(M, &om) == GA_OK && ga_object_from_mv(J, &oj) == GA_OK &&
                     om.kind == GA_OBJECT_LINE && oj.kind == GA_OBJECT_LINE;
            tk_add_bool(c, ok);
        }
    }
    ga_mv Y;
    tk_expect_status("localize a unit sphere built at 1e5 about its centre: refused",
                     ga_mv_localize(ga_sphere_dual((ga_vec3){1e5, 0, 0}, 1), (ga_vec3){1e5, 0, 0}, 1, &Y),
                     GA_ERR_PRECISION);
    tk_expect_status("localize a sphere of radius 1 at 1 about its centre: GA_OK",
                     ga_mv_localize(ga_sphere_dual((ga_vec3){1, 0, 0}, 1), (ga_vec3){1, 0, 0}, 1, &Y), GA_OK);
    tk_expect_status("localize a plane built at 1e8: GA_OK",
                     ga_mv_localize(ga_plane_dual((ga_vec3){0, 0, 1}, 1e8), (ga_vec3){0, 0, 1e8}, 1, &Y),
                     GA_OK);
}

/* F(x + a) = y + (|y|^2 / 2) n - nbar / 2, y = x + a, in binary128 (y
   exact, |y|^2 to 2^-113): the point the translation below is compared to
   (ga_point_up(x + a) is not: x + a rounded, then squared and summed) */
static void point_up_exact(ga_vec3 x, ga_vec3 a, __float128 f[5])
{
    __float128 y[3] = {(__float128)x.x + a.x, (__float128)x.y + a.y, (__float128)x.z + a.z};
    __float128 h = (y[0] * y[0] + y[1] * y[1] + y[2] * y[2]) / 2;
    f[0] = y[0], f[1] = y[1], f[2] = y[2], f[3] = h - (__float128)0.5, f[4] = h + (__float128)0.5;
}

/* T_a P ~T_a of the vector P (coefficients p of e1, e2, e3, e4, e5) in
   binary128 (products of doubles exact, each sum to 2^-113 of its terms,
   far below the u checked against):
   with P = v + alpha n + beta nbar (alpha = (p4 + p5) / 2, beta =
   (p4 - p5) / 2; n = e4 + e5, nbar = e4 - e5), T_a v ~T_a = v + (v.a) n,
   T_a n ~T_a = n, T_a nbar ~T_a = nbar - 2 a - |a|^2 n, so the result is
   v - 2 beta a + (alpha + v.a - beta |a|^2) n + beta nbar. */
static void translate_exact(const double p[5], ga_vec3 a, __float128 o[5])
{
    __float128 A[3] = {a.x, a.y, a.z}, al = ((__float128)p[3] + p[4]) / 2, be = ((__float128)p[3] - p[4]) / 2;
    __float128 va = 0, aa = 0;
    for (int k = 0; k < 3; k++) {
        va += (__float128)p[k] * A[k];
        aa += A[k] * A[k];
        o[k] = p[k] - 2 * be * A[k];
    }
    __float128 m = al + va - be * aa;
    o[3] = m + be, o[4] = m - be;
}

/* ga_rotor_apply_mv: a point moved far, against the point action; a rotor
   scaled by 2 scales R X ~R by 4 (the translation found over |q|^2); a
   rotation alone and a translation alone against their closed forms. */
static void section_apply(void)
{
    tk_rng t = {tk_seed(2929)};
    /* ga_rotor_apply is the same motion in another order of arithmetic, of
       a rotor on the group only to its rounding: rotor.h bounds such orders
       (ga_rotor_apply_many against it) per coordinate by 32 u (|x|_1 +
       |t|_inf), t the translation; the check is that bound (was 8 u of |y|,
       which 31 of 200 seeds broke, worst 24 u of |y|, against the 32 u
       (|x|_1 + |t|_inf) that ga_rotor_apply itself is bounded to) */
    tk_check far = tk_begin(
                 "apply_mv of a point, translations up to 1e6, against apply: 32 u (|x|_1 + |t|_inf)", 0),
             sc = tk_begin("apply_mv(2 R, X) = 4 apply_mv(R, X) (rel to max)", 8 * DBL_EPSILON),
             rot = tk_begin("apply_mv of a rotation: F(q x ~q) (rel to max)", 8 * DBL_EPSILON),
             tr = tk_begin("apply_mv of a translation: T_a P ~T_a rounded once, each coefficient", 0),
             tf = tk_begin("apply_mv of a translation: F(x + a), P's own rounding carried (derived)", 0);
    for (int i = 0; i < 300; i++) {
        ga_vec3 x = tk_scale(tk_unit(&t), tk_range(&t, 0, 3)),
                a = tk_scale(tk_unit(&t), tk_loguni(&t, 1, 1e6));
        ga_rotor q = ga_rotor_rotation(tk_unit(&t), tk_range(&t, -3, 3));
        ga_rotor R = ga_rotor_mul(ga_rotor_translation(a), q);
        ga_vec3 y, want = ga_rotor_apply(R, x);
        ga_vec3 tt = ga_rotor_to_translation(R);
        double tol = 32 * DBL_EPSILON *
                     (fabs(x.x) + fabs(x.y) + fabs(x.z) + fmax(fabs(tt.x), fmax(fabs(tt.y), fabs(tt.z))));
        if (ga_point_down(ga_rotor_apply_mv(R, ga_point_up(x)), &y) == GA_OK)
            tk_add_tol(&far, fmax(fabs(y.x - want.x), fmax(fabs(y.y - want.y), fabs(y.z - want.z))), tol);
        ga_mv X = ga_pointpair_from_points(x, add(x, tk_unit(&t)));
        ga_rotor R2 = {2 * R.s,   2 * R.e12, 2 * R.e13, 2 * R.e23,
                       2 * R.e1n, 2 * R.e2n, 2 * R.e3n, 2 * R.e123n};
        ga_mv A = ga_rotor_apply_mv(R, X), B = ga_rotor_apply_mv(R2, X);
        tk_add(&sc, tk_mv_maxabs(ga_mv_sub(B, ga_mv_scale(A, 4))) / tk_mv_maxabs(B));
        ga_mv P = ga_point_up(x), Pq = ga_rotor_apply_mv(q, P), Pw = ga_point_up(ga_rotor_apply(q, x));
        tk_add(&rot, tk_mv_maxabs(ga_mv_sub(Pq, Pw)) / tk_mv_maxabs(Pw));
        /* rotor.h: the translation carried exactly and rounded once, so
           each coefficient of Pt within u |c| of the exact c = T_a P ~T_a
           (P as rounded by ga_point_up), beside 2^-100 of the terms' sum S
           (the double-double sums of gao_translate), every other
           coefficient exactly 0 (err/tol reaches 1 on ties, which round
           by half an ulp exactly, u |c| at c = 2^e). Against F(x + a), P's own rounding comes
           on top, carried exactly by T_a: ga_point_up rounds |x|^2 (3
           roundings, gamma_3 |x|^2) and then e4 = (y2 - 1) / 2 and e5 =
           (y2 + 1) / 2 each once more, so |delta4|, |delta5| <= u (2 |x|^2
           + 1/2) + O(u^2) <= d = u (2 |x|^2 + 1) (the e_i are x_i exactly).
           delta = alpha n + beta nbar, |alpha|, |beta| <= d, goes to
           -2 beta a + (alpha - beta |a|^2) n + beta nbar: within 2 d |a_i|
           at e_i, d (|a|^2 + 2) at e4 and e5. The nbar part is what the
           check against F(x + a) alone at 16 u of max |F(x + a)| had not
           counted: it grows as |a|^2, and max |F(x + a)| is small where
           a nearly cancels x (16.1 u at seed 8, 18.0 u at seed 122, |x| =
           2.6, |a| = 2.6, max |F(x + a)| 1.1 and 0.84; the rounding of
           apply_mv itself was 0.47 u and 0.09 u of max there). */
        ga_mv Pt = ga_rotor_apply_mv(ga_rotor_translation(a), P);
        const int bl[5] = {GA_BLADE_E1, GA_BLADE_E2, GA_BLADE_E3, GA_BLADE_E4, GA_BLADE_E5};
        double p[5], u = DBL_EPSILON / 2, x2 = x.x * x.x + x.y * x.y + x.z * x.z,
                     aa = a.x * a.x + a.y * a.y + a.z * a.z;
        double ai[5] = {fabs(a.x), fabs(a.y), fabs(a.z), 0, 0};
        for (int k = 0; k < 5; k++) p[k] = P.c[bl[k]];
        __float128 o[5], f[5];
        translate_exact(p, a, o);
        point_up_exact(x, a, f);
        double S = fabs(p[0]) + fabs(p[1]) + fabs(p[2]) + fabs(p[3]) + fabs(p[4]) + fabs(p[0] * a.x) +
                   fabs(p[1] * a.y) + fabs(p[2] * a.z) + fabs(p[3] - p[4]) * (1 + aa + ai[0] + ai[1] + ai[2]);
        double d = u * (2 * x2 + 1);
        for (int k = 0; k < 5; k++) {
            double c = (double)o[k], tol1 = u * fabs(c) + 0x1p-100 * S;
            tk_add_tol(&tr, fabs((double)((__float128)Pt.c[bl[k]] - o[k])), tol1);
            tk_add_tol(&tf, fabs((double)((__float128)Pt.c[bl[k]] - f[k])),
                       tol1 + d * (k < 3 ? 2 * ai[k] : aa + 2));
        }
        tk_add_tol(&tr, tk_mv_maxabs(ga_mv_sub(Pt, ga_mv_grade(Pt, 1))), 0);
    }
    tk_end(&far);
    tk_end(&sc);
    tk_end(&rot);
    tk_end(&tr);
    tk_end(&tf);
}

/* Spheres through the origin far out, centre t 2^k for a Pythagorean t and
   radius |t| 2^k, all exact: |c|^2 - r^2 = 0, so e4 = -1/2 and e5 = 1/2
   exactly. Rounded term by term (|c|^2 / 2 first), their weight was lost
   beyond |c|^2 ~ 2^53 and they read back as planes. */
static void section_far_through_origin(void)
{
    static const double tr[][4] = {{3, 4, 0, 5}, {5, 12, 0, 13}, {2, 3, 6, 7}, {1, 4, 8, 9}};
    tk_check shape = tk_begin("far spheres through the origin: e4, e5 = -1/2, 1/2 exactly", 0);
    tk_check rd = tk_begin("far spheres through the origin: read back, within the stated bound", 0);
    for (int i = 0; i < 4; i++)
        for (int k = 20; k <= 34; k++) {
            double f = ldexp(1.0, k), r = tr[i][3] * f;
            ga_vec3 c = {tr[i][0] * f, tr[i][1] * f, tr[i][2] * f};
            ga_mv s = ga_sphere_dual(c, r);
            tk_add_bool(&shape, s.c[GA_BLADE_E4] == -0.5 && s.c[GA_BLADE_E5] == 0.5);
            ga_object ob;
            int st = ga_object_from_mv(s, &ob);
            tk_add_bool(&rd, st == GA_OK && ob.kind == GA_OBJECT_SPHERE &&
                                 tk_norm(sub(ob.centre, c)) <= ob.err && fabs(ob.r2 - r * r) <= ob.r2_err);
        }
    tk_end(&shape);
    tk_end(&rd);
}

/* Flats at and near infinity. A line and a plane meeting at a grazing angle
   theta meet in a finite flat point 1 / theta out, however far: GA_OK with
   that point within its stated bound, or GA_ERR_PRECISION, never EMPTY (an
   EMPTY band of 2048 u of the largest coefficient read them as empty below
   theta ~ 4.5e-13); below 32 u (GAO_MEET_KAPPA: the line's direction is
   known to that) they are parallel to the inputs' accuracy, and EMPTY is
   right too. A line parallel to a plane up to the rounding of its direction
   (the meet of the planes m.x = d and r.x = e, its direction m x r rounded:
   not quite orthogonal to m) meets the plane m.x = d + off at infinity to
   the inputs' accuracy: ga_mv_meet and ga_mv_meet_rel give the meet a
   weight of exactly 0, EMPTY on read-back, at every distance. */
static void section_infinity(void)
{
    tk_check graze =
        tk_begin("line ^ plane at a grazing angle: the flat point 1 / theta out, EMPTY only below 32 u", 0);
    for (int k = 6; k <= 16; k++) {
        double th = pow(10.0, -k), x = 1.0 / th;
        ga_mv L = ga_line_from_points((ga_vec3){0, 0, 0}, (ga_vec3){1, 0, th});
        ga_object ob;
        int st = ga_object_from_mv(ga_mv_meet(L, ga_plane_dual((ga_vec3){0, 0, 1}, 1)), &ob);
        /* the point (1 / th, 0, 1), 1 / th rounded once here */
        tk_add_bool(&graze, st == GA_ERR_PRECISION ||
                                (th < 32 * DBL_EPSILON / 2 && st == GA_OK && ob.kind == GA_OBJECT_EMPTY) ||
                                (st == GA_OK && ob.kind == GA_OBJECT_FLATPOINT &&
                                 tk_norm(sub(ob.centre, (ga_vec3){x, 0, 1})) <= ob.err + DBL_EPSILON * x));
    }
    tk_end(&graze);
    tk_rng t = {tk_seed(3131)};
    tk_check par = tk_begin("line parallel to a plane to its rounding: meet EMPTY", 0);
    tk_check parr = tk_begin("line parallel to a plane to its rounding: meet_rel EMPTY", 0);
    for (int k = 0; k < 5; k++)
        for (int i = 0; i < 200; i++) {
            double D = dists[k], S = D == 1.0 ? tk_loguni(&t, 0.1, 1) : tk_loguni(&t, 1, D);
            ga_vec3 m = tk_unit(&t), r = tk_unit(&t), q = tk_scale(tk_unit(&t), D);
            double off = S * tk_range(&t, 0.1, 1);
            /* the line of the planes m.x = m.q and r.x = r.q (its direction
               m x r rounded once), the plane m.x = m.q + off */
            ga_mv L = ga_mv_meet(ga_plane_dual(m, dot(m, q)), ga_plane_dual(r, dot(r, q)));
            ga_mv P = ga_plane_dual(m, dot(m, q) + off);
            ga_object ob;
            int st = ga_object_from_mv(ga_mv_meet(L, P), &ob);
            tk_add_bool(&par, st == GA_OK && ob.kind == GA_OBJECT_EMPTY);
            ga_mv M;
            st = ga_mv_meet_rel(L, ga_mv_dual(P), &M);
            if (st == GA_OK)
                st = ga_object_from_mv(M, &ob);
            tk_add_bool(&parr, st == GA_OK && ob.kind == GA_OBJECT_EMPTY);
        }
    tk_end(&par);
    tk_end(&parr);
}

static const tk_section sections[] = {
    {"apply", section_apply, 0},
    {"special", section_special, 0},
    {"rel", section_rel, 0},
    {"general", section_general, 0},
    {"far_through_origin", section_far_through_origin, 0},
    {"infinity", section_infinity, 0},
};

int main(int argc, char **argv)
{
    return tk_main(argc, argv, "test_meet_special", sections, TK_COUNT(sections));
}
