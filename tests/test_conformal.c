/* tests/test_conformal.c: the G(4,1) product table and the conformal model.
 *
 * Identities of the algebra (a wrong sign anywhere in the table breaks one) and
 * round trips of the conformal model (Wareham-Lasenby §1, §2.2): points, the
 * distance identity, and every object read back as the parameters it was built
 * from. Bad input must come back as a status. The seeded PRNG of testkit.h
 * makes every run the same. Exit status 0 when every check passes, 1
 * otherwise; every check prints its line (testkit.h): the case nearest its
 * tolerance, its error and its tolerance, as each case has a tolerance of its
 * own.
 *
 * Tolerances are rounding bounds of the computation being checked, in units of
 * u = 2^-53 (the unit roundoff). gamma(k) = k u / (1 - k u) bounds the relative
 * error of a sum of k - 1 products (Higham, Accuracy and Stability, §3.1). Each
 * check says where its bound comes from.
 */
#include "testkit.h"

/* the one stream the sections draw from, in order */
static tk_rng rng = {0x67a20f07c3b1d2e5ULL};

#define U 1.1102230246251565e-16 /* unit roundoff 2^-53 */
static double gamma_k(int k) { return k * U / (1.0 - k * U); }

/* ---- checks (testkit.h: named, a tolerance per case) --------------------------- */
static void check(const char *name, double err, double tol) { tk_add_tol(tk_get(name), err, tol); }
static void check_status(const char *name, int got, int want) { tk_add_status(tk_get(name), got, want); }

/* ---- random draws (testkit.h: splitmix64), one per statement ------------------- */
static ga_mv rand_mv(tk_rng *t)
{
    ga_mv a;
    for (int i = 0; i < 32; i++) a.c[i] = tk_range(t, -1, 1);
    return a;
}
static ga_vec3 rand_vec3(tk_rng *t, double s)
{
    ga_vec3 v;
    v.x = tk_range(t, -s, s);
    v.y = tk_range(t, -s, s);
    v.z = tk_range(t, -s, s);
    return v;
}

/* ---- small helpers --------------------------------------------------------- */
static double maxdiff(ga_mv a, ga_mv b) { return tk_mv_maxabs(ga_mv_sub(a, b)); }
static double sumabs(ga_mv a)
{
    double s = 0;
    for (int i = 0; i < 32; i++) s += fabs(a.c[i]);
    return s;
}
static ga_vec3 add3(ga_vec3 a, ga_vec3 b) { return (ga_vec3){a.x + b.x, a.y + b.y, a.z + b.z}; }
static ga_vec3 sub3(ga_vec3 a, ga_vec3 b) { return (ga_vec3){a.x - b.x, a.y - b.y, a.z - b.z}; }
static ga_vec3 mul3(ga_vec3 a, double s) { return (ga_vec3){a.x * s, a.y * s, a.z * s}; }
static double dot3(ga_vec3 a, ga_vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static double norm3(ga_vec3 a) { return sqrt(dot3(a, a)); }
static ga_vec3 cross3(ga_vec3 a, ga_vec3 b)
{
    return (ga_vec3){a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
static double dist3(ga_vec3 a, ga_vec3 b) { return norm3(sub3(a, b)); }
static double vmax3(ga_vec3 a) { return tk_max(fabs(a.x), tk_max(fabs(a.y), fabs(a.z))); }

static int popcount(unsigned m)
{
    int k = 0;
    for (; m; m >>= 1) k += m & 1;
    return k;
}

/* ---- the algebra ---------------------------------------------------------------- */
static void test_table(void)
{
    tk_note("the G(4,1) product table\n");
    /* signature: e1..e4 square to +1, e5 to -1 (exactly) */
    for (int i = 1; i <= 5; i++) {
        ga_mv e = ga_mv_blade(i);
        check("signature e_i^2", maxdiff(ga_mv_gp(e, e), ga_mv_scalar(i == 5 ? -1 : 1)), 0);
    }
    /* distinct basis vectors anticommute, and e_i e_j is the blade e_ij for i < j */
    for (int i = 1; i <= 5; i++)
        for (int j = 1; j <= 5; j++) {
            if (i == j)
                continue;
            ga_mv ij = ga_mv_gp(ga_mv_blade(i), ga_mv_blade(j)),
                  ji = ga_mv_gp(ga_mv_blade(j), ga_mv_blade(i));
            check("anticommute e_i e_j = -e_j e_i", tk_mv_maxabs(ga_mv_add(ij, ji)), 0);
        }
    /* every blade is the product of its vectors in increasing order: with
       associativity below, this pins every entry of the 32 x 32 table */
    for (int b = 0; b < 32; b++) {
        ga_mv p = ga_mv_scalar(1);
        for (int k = 0; k < 5; k++)
            if (ga_blade_mask(b) & (1u << k))
                p = ga_mv_gp(p, ga_mv_blade(1 + k));
        check("blade = ordered product of its vectors", maxdiff(p, ga_mv_blade(b)), 0);
        check("blade grade = popcount of mask", ga_blade_grade(b) == popcount(ga_blade_mask(b)) ? 0 : 1, 0);
    }
    tk_end_named();
}

static void test_products(void)
{
    tk_rng *t = &rng;
    tk_note("products, reverse, involutions, duals\n");
    /* Dense a, b, c with coefficients in [-1, 1]. A coefficient of ab is a sum of
       32 products of size <= 1, so |ab|_i <= 32 and its rounding error is at
       most gamma(33) * 32; (ab)c then errs by at most 2 gamma(33) 1024, and the
       difference of the two bracketings by twice that. */
    const double tol_assoc = 4 * gamma_k(33) * 1024;
    const double tol_dist = 2 * gamma_k(34) * 64; /* |b + c|_i <= 2: one sum more */
    const double tol_one = 2 * gamma_k(33) * 32;  /* two orders of the same 32-term sums */
    for (int trial = 0; trial < 2000; trial++) {
        ga_mv a = rand_mv(t), b = rand_mv(t), c = rand_mv(t);
        ga_mv ab = ga_mv_gp(a, b);
        check("associativity (ab)c = a(bc)", maxdiff(ga_mv_gp(ab, c), ga_mv_gp(a, ga_mv_gp(b, c))),
              tol_assoc);
        check("distributivity a(b+c) = ab+ac",
              maxdiff(ga_mv_gp(a, ga_mv_add(b, c)), ga_mv_add(ab, ga_mv_gp(a, c))), tol_dist);
        check("distributivity (b+c)a = ba+ca",
              maxdiff(ga_mv_gp(ga_mv_add(b, c), a), ga_mv_add(ga_mv_gp(b, a), ga_mv_gp(c, a))), tol_dist);
        check("reverse(ab) = reverse(b) reverse(a)",
              maxdiff(ga_mv_reverse(ab), ga_mv_gp(ga_mv_reverse(b), ga_mv_reverse(a))), tol_one);
        check("involute(ab) = involute(a) involute(b)",
              maxdiff(ga_mv_involute(ab), ga_mv_gp(ga_mv_involute(a), ga_mv_involute(b))), tol_one);
        check("conjugate(ab) = conjugate(b) conjugate(a)",
              maxdiff(ga_mv_conjugate(ab), ga_mv_gp(ga_mv_conjugate(b), ga_mv_conjugate(a))), tol_one);
        check("sp(a,b) = <ab>_0", fabs(ga_mv_sp(a, b) - ab.c[GA_BLADE_SCALAR]), tol_one);
        ga_mv sum = ga_mv_zero();
        for (int k = 0; k <= 5; k++) sum = ga_mv_add(sum, ga_mv_grade(a, k));
        check("sum of grade parts = a", maxdiff(sum, a), 0);
        /* outer product and left contraction of homogeneous parts are grade parts of
           the geometric product: A_r ^ B_s = <A_r B_s>_{r+s}, A_r _| B_s = <A_r B_s>_{s-r}
           (zero for s < r); r = 1 is a ^ B = <aB>_{k+1}, a _| B = <aB>_{k-1}. Both
           sides sum the same <= 32 terms of size <= 1. */
        ga_mv op = ga_mv_zero(), lc = ga_mv_zero();
        for (int r = 0; r <= 5; r++)
            for (int s = 0; s <= 5; s++) {
                ga_mv ar = ga_mv_grade(a, r), bs = ga_mv_grade(b, s), g = ga_mv_gp(ar, bs);
                ga_mv o = ga_mv_op(ar, bs), l = ga_mv_lc(ar, bs);
                check("A_r ^ B_s = <A_r B_s>_(r+s)", maxdiff(o, ga_mv_grade(g, r + s)), tol_one);
                check("A_r _| B_s = <A_r B_s>_(s-r)",
                      maxdiff(l, s >= r ? ga_mv_grade(g, s - r) : ga_mv_zero()), tol_one);
                op = ga_mv_add(op, o);
                lc = ga_mv_add(lc, l);
            }
        /* bilinearity over all 36 grade pairs: 36 more additions of terms <= 32 */
        check("a ^ b = sum of homogeneous parts", maxdiff(ga_mv_op(a, b), op), 2 * gamma_k(33 + 36) * 32);
        check("a _| b = sum of homogeneous parts", maxdiff(ga_mv_lc(a, b), lc), 2 * gamma_k(33 + 36) * 32);
        /* dual then undual: a product with one blade is exact (one term per coefficient) */
        check("undual(dual(a)) = a", maxdiff(ga_mv_undual(ga_mv_dual(a)), a), 0);
        check("dual(a) = a I^-1 = -a I", maxdiff(ga_mv_dual(a), ga_mv_scale(ga_mv_gp(a, ga_mv_i5()), -1)), 0);
    }
    tk_end_named();
}

/* A random vector that is far from null: |v.v| >= |v|^2 / 4 (Euclidean norm). */
static ga_mv rand_nonnull(tk_rng *t)
{
    for (;;) {
        ga_mv v = ga_mv_grade(rand_mv(t), 1);
        double e2 = 0;
        for (int i = 1; i <= 5; i++) e2 += v.c[i] * v.c[i];
        if (fabs(ga_mv_sp(v, v)) >= 0.25 * e2 && e2 > 0.01)
            return v;
    }
}

static void test_versors(void)
{
    tk_rng *t = &rng;
    tk_note("versors and inverses\n");
    /* V = v1 ... vk. Every coefficient of V V^-1 = V ~V / <V ~V>_0 is a sum of
       products of the 2k vector coefficients; its total size is at most
       prod |v_i|_1^2 (the 1-norms multiply under the product), and each step of
       the chain (k-1 products for V, one for V ~V, one for V V^-1) adds at most
       gamma(33) of it. Relative to <V ~V>_0 = prod v_i^2 the bound is
       (k + 1) gamma(33) prod (|v_i|_1^2 / |v_i^2|), times 2 for the two sides. */
    for (int trial = 0; trial < 2000; trial++) {
        int k = 1 + trial % 5;
        ga_mv V = ga_mv_scalar(1);
        double kappa = 1;
        for (int i = 0; i < k; i++) {
            ga_mv v = rand_nonnull(t);
            double n1 = sumabs(v);
            kappa *= n1 * n1 / fabs(ga_mv_sp(v, v));
            V = ga_mv_gp(V, v);
        }
        ga_mv Vi;
        int st = ga_mv_inverse(V, &Vi);
        check_status("versor inverse exists", st, GA_OK);
        if (st != GA_OK)
            continue;
        double tol = 2 * (k + 1) * gamma_k(33) * kappa;
        check("versor V V^-1 = 1", maxdiff(ga_mv_gp(V, Vi), ga_mv_scalar(1)), tol);
        check("versor V^-1 V = 1", maxdiff(ga_mv_gp(Vi, V), ga_mv_scalar(1)), tol);
    }
    /* what has no inverse: zero divisors (x y = 0 with y != 0 rules out x^-1) */
    ga_mv n = ga_mv_n(), one_e45 = ga_mv_add(ga_mv_scalar(1), ga_mv_blade(GA_BLADE_E45)),
          out = ga_mv_scalar(42);
    check("n n = 0 (n is a zero divisor)", tk_mv_maxabs(ga_mv_gp(n, n)), 0);
    check("(1+e45)(1-e45) = 0 (a zero divisor)",
          tk_mv_maxabs(ga_mv_gp(one_e45, ga_mv_sub(ga_mv_scalar(1), ga_mv_blade(GA_BLADE_E45)))), 0);
    check_status("inverse of n: singular", ga_mv_inverse(n, &out), GA_ERR_SINGULAR);
    check_status("inverse of nbar: singular", ga_mv_inverse(ga_mv_nbar(), &out), GA_ERR_SINGULAR);
    check_status("inverse of 1+e45: singular", ga_mv_inverse(one_e45, &out), GA_ERR_SINGULAR);
    check_status("inverse of F(x): singular", ga_mv_inverse(ga_point_up((ga_vec3){1, 2, 3}), &out),
                 GA_ERR_SINGULAR);
    check_status("inverse of 0: singular", ga_mv_inverse(ga_mv_zero(), &out), GA_ERR_SINGULAR);
    ga_mv bad = ga_mv_scalar(1);
    bad.c[GA_BLADE_E23] = NAN;
    check_status("inverse of NaN: not finite", ga_mv_inverse(bad, &out), GA_ERR_NOTFINITE);
    bad.c[GA_BLADE_E23] = INFINITY;
    check_status("inverse of Inf: not finite", ga_mv_inverse(bad, &out), GA_ERR_NOTFINITE);
    check("inverse leaves output untouched on failure", maxdiff(out, ga_mv_scalar(42)), 0);
    tk_end_named();
}

/* ---- the conformal model ---------------------------------------------------------- */
static void test_model(void)
{
    tk_rng *t = &rng;
    tk_note("the conformal model: points, distances, translations\n");
    ga_mv n = ga_mv_n(), nb = ga_mv_nbar();
    check("n^2 = 0", tk_mv_maxabs(ga_mv_gp(n, n)), 0);
    check("nbar^2 = 0", tk_mv_maxabs(ga_mv_gp(nb, nb)), 0);
    check("n.nbar = 2", fabs(ga_mv_sp(n, nb) - 2), 0);
    check("n nbar = 2 - 2 e45",
          maxdiff(ga_mv_gp(n, nb), ga_mv_sub(ga_mv_scalar(2), ga_mv_scale(ga_mv_blade(GA_BLADE_E45), 2))), 0);
    check("e4^2 = 1, e5^2 = -1",
          fabs(ga_mv_sp(ga_mv_e4(), ga_mv_e4()) - 1) + fabs(ga_mv_sp(ga_mv_e5(), ga_mv_e5()) + 1), 0);
    check("I3^2 = -1, I5^2 = -1",
          maxdiff(ga_mv_gp(ga_mv_i3(), ga_mv_i3()), ga_mv_scalar(-1)) +
              maxdiff(ga_mv_gp(ga_mv_i5(), ga_mv_i5()), ga_mv_scalar(-1)),
          0);
    check("I3 = e1 e2 e3",
          maxdiff(ga_mv_i3(), ga_mv_gp(ga_mv_gp(ga_mv_blade(GA_BLADE_E1), ga_mv_blade(GA_BLADE_E2)),
                                       ga_mv_blade(GA_BLADE_E3))),
          0);
    check("F(0) = -nbar/2", maxdiff(ga_point_up((ga_vec3){0, 0, 0}), ga_mv_scale(nb, -0.5)), 0);

    for (int trial = 0; trial < 20000; trial++) {
        /* lambda over six decades, |x| / lambda from 1e-3 to 1e4 */
        double lambda = trial % 2 ? 1.0 : pow(10, tk_range(t, -3, 3));
        ga_vec3 ux = tk_unit(t);
        ga_vec3 x = mul3(ux, lambda * pow(10, tk_range(t, -3, 4)));
        ga_vec3 uy = tk_unit(t);
        ga_vec3 y = add3(x, mul3(uy, lambda * pow(10, tk_range(t, -3, 4))));
        ga_mv X, Y;
        if (ga_point_up_scaled(x, lambda, &X) != GA_OK || ga_point_up_scaled(y, lambda, &Y) != GA_OK) {
            check_status("up_scaled of a finite point", GA_ERR_ARG, GA_OK);
            continue;
        }
        double e2 = 0, xy = 0;
        for (int i = 1; i <= 5; i++) {
            e2 += X.c[i] * X.c[i];
            xy += fabs(X.c[i] * Y.c[i]);
        }
        /* The coefficients of F carry a relative error <= gamma(4) (x^2 by 3
           products and 2 sums, then +-1 and /2); squares and sums of 5 products
           add gamma(6): each term of F.F or F(x).F(y) errs by <= 16 u of itself. */
        check("F(x)^2 = 0", maxdiff(ga_mv_gp(X, X), ga_mv_zero()), 16 * U * e2);
        check("F(x).n = -1", fabs(ga_mv_sp(X, n) + 1), 16 * U * fabs(X.c[GA_BLADE_E5]));
        ga_vec3 d = sub3(x, y);
        double want = -0.5 * dot3(d, d) / (lambda * lambda);
        check("F(x).F(y) = -|x-y|^2/(2 lambda^2)", fabs(ga_mv_sp(X, Y) - want), 16 * U * (xy + fabs(want)));
        /* Down: x = lambda <X>_E / w with w = (|<X>_E|^2 + (X.n)^2) / (2 X5), a
           quotient of sums of nonnegative terms: about 20 u relative in all
           (conformal.h), so 32 u |x|. The weight c (either sign) adds u. */
        ga_vec3 back = {NAN, NAN, NAN};
        int st = ga_point_down_scaled(X, lambda, &back);
        check_status("down(F(x)) status", st, GA_OK);
        check("down(F(x)) = x, lambda != 1 too", vmax3(sub3(back, x)), 32 * U * norm3(x));
        double c = (trial % 3 ? 1 : -1) * pow(10, tk_range(t, -6, 6));
        st = ga_point_down_scaled(ga_mv_scale(X, c), lambda, &back);
        check_status("down(c F(x)) status", st, GA_OK);
        check("down(c F(x)) = x, any weight c != 0", vmax3(sub3(back, x)), 34 * U * norm3(x));
    }

    /* Translation rotor T_a = 1 + n a / 2 moves F(x) to F(x + a) (Wareham-Lasenby
       §2.2). T F ~T is two products whose terms total at most
       |T|_1^2 |F|_1: each adds gamma(33) of it. */
    for (int trial = 0; trial < 2000; trial++) {
        ga_vec3 x = rand_vec3(t, 10), a = rand_vec3(t, 10);
        ga_mv T = ga_mv_add(ga_mv_scalar(1), ga_mv_scale(ga_mv_gp(ga_mv_n(), ga_vec3_to_mv(a)), 0.5));
        ga_mv moved = ga_mv_gp(ga_mv_gp(T, ga_point_up(x)), ga_mv_reverse(T));
        double tl = sumabs(T);
        check("T_a F(x) ~T_a = F(x + a)", maxdiff(moved, ga_point_up(add3(x, a))),
              2 * gamma_k(33) * tl * tl * sumabs(ga_point_up(x)) + 16 * U * sumabs(ga_point_up(add3(x, a))));
    }
    tk_end_named();
}

/* ---- objects, built from their parameters and read back ---------------------------- */

/* Unit vectors p, q completing m to a right-handed orthonormal frame. */
static void frame(ga_vec3 m, ga_vec3 *p, ga_vec3 *q)
{
    ga_vec3 h = fabs(m.x) < 0.6 ? (ga_vec3){1, 0, 0} : (ga_vec3){0, 1, 0};
    *p = cross3(m, h);
    *p = mul3(*p, 1 / norm3(*p));
    *q = cross3(m, *p);
}

static void test_objects(void)
{
    tk_rng *t = &rng;
    tk_note("objects built from their parameters and read back\n");
    /* The scene has size s = 4^U(-1, 1) (lambda = 1); centres and points lie in
       [-s, s]^3 and radii in [s/10, s]. The configurations are well conditioned by
       construction (points spread around circles and spheres, see each case), so
       the read-back must return the parameters to 1e-12 relative to the size of
       the configuration (its largest distance from the origin).
       Why s within a factor 4 of lambda: an object stores the e4 and e5 parts of
       its points, (x^2 -+ 1)/2, side by side, and what it says about x lives in
       their difference and in the e1..e3 parts. So its coefficients carry
       relative errors ~u max(s^2, 1/s^2) before any read-back starts (F(a)^F(b)
       has the e45 coefficient (a^2 - b^2)/2 as a difference of products of size
       s^4/4; the e_i4 and e_i5 coefficients differ by a_i - b_i against a size
       ~s^3), and a read-back multiplies that by a modest constant (a few hundred,
       measured: the radius of a round is the difference |c|^2 - (c^2 - r^2)).
       Within a factor 4 the worst case is ~1e3 u = 1e-13; at s = 10 it is ~5e3 u,
       at s = 30 ~5e4 u: choose lambda (ga_point_up_scaled) near the scene size. */
    const double tol = 1e-12;
    for (int trial = 0; trial < 5000; trial++) {
        double s = pow(4, tk_range(t, -1, 1));
        ga_vec3 c = rand_vec3(t, s), m = tk_unit(t), p, q;
        double r = s * pow(10, tk_range(t, -1, 0));
        frame(m, &p, &q);
        double size = norm3(c) + r;
        ga_vec3 oc, om, oa, ob;
        double orad, od;

        /* point pair: two random points, at least s/10 apart */
        ga_vec3 a = rand_vec3(t, s), ub = tk_unit(t), b = add3(a, mul3(ub, s * tk_range(t, 0.1, 1)));
        double psize = fmax(norm3(a), norm3(b));
        int st = ga_pointpair_points(ga_pointpair_from_points(a, b), &oa, &ob);
        check_status("point pair read back: status", st, GA_OK);
        check("point pair read back: a, b", tk_max(dist3(oa, a), dist3(ob, b)) / psize, tol);
        st = ga_pointpair_points(ga_pointpair_from_points(b, a), &oa, &ob);
        check("point pair F(b)^F(a) reads b, a", tk_max(dist3(oa, b), dist3(ob, a)) / psize, tol);

        /* line: through c with direction m, from two points on it (parameters
           s/10 to s apart); the closest point to the origin is c - (c.m) m */
        double t1 = tk_range(t, -s, s), t2 = t1 + tk_range(t, 0.1, 1) * s;
        ga_vec3 la = add3(c, mul3(m, t1)), lb = add3(c, mul3(m, t2));
        ga_vec3 closest = sub3(c, mul3(m, dot3(c, m)));
        st = ga_line_params(ga_line_from_points(la, lb), &om, &oc);
        check_status("line read back: status", st, GA_OK);
        check("line read back: direction", dist3(om, m), tol);
        check("line read back: closest point", dist3(oc, closest) / fmax(norm3(la), norm3(lb)), tol);

        st = ga_line_params(ga_mv_scale(ga_line_from_points(la, lb), -pow(10, tk_range(t, -6, 6))), &om, &oc);
        check("line -w L reads -direction, same point",
              st ? 1 : tk_max(dist3(om, mul3(m, -1)), dist3(oc, closest) / fmax(norm3(la), norm3(lb))), tol);
        /* the same line as F(p) ^ m ^ n: a point, a direction and infinity */
        st = ga_line_params(ga_mv_op(ga_mv_op(ga_point_up(c), ga_vec3_to_mv(m)), ga_mv_n()), &om, &oc);
        check("line F(c)^m^n reads m and the closest point",
              st ? 1 : tk_max(dist3(om, m), dist3(oc, closest) / size), tol);

        /* circle: centre c, radius r, normal m, three points at angles 2 pi k / 3
           + U(-0.5, 0.5) (no two closer than 1.1 rad), in the order that makes
           (b - a) x (c - a) point along m */
        ga_vec3 cp[4];
        double phase = tk_range(t, 0, 6.283185307179586);
        for (int k = 0; k < 3; k++) {
            double th = phase + 2.0943951023931957 * k + tk_range(t, -0.5, 0.5);
            cp[k] = add3(c, add3(mul3(p, r * cos(th)), mul3(q, r * sin(th))));
        }
        st = ga_circle_params(ga_circle_from_points(cp[0], cp[1], cp[2]), &oc, &orad, &om);
        check_status("circle read back: status", st, GA_OK);
        check("circle read back: centre", dist3(oc, c) / size, tol);
        check("circle read back: radius", fabs(orad - r) / size, tol);
        check("circle read back: normal", dist3(om, m), tol);

        /* plane: m.x = d, three points of the plane around its foot d m, spread
           as for the circle; distance relative to the size of the points */
        double d = tk_range(t, -s, s);
        ga_vec3 pp[3];
        for (int k = 0; k < 3; k++) {
            double th = phase + 2.0943951023931957 * k + tk_range(t, -0.5, 0.5);
            pp[k] = add3(mul3(m, d), add3(mul3(p, r * cos(th)), mul3(q, r * sin(th))));
        }
        st = ga_plane_params(ga_plane_from_points(pp[0], pp[1], pp[2]), &om, &od);
        check_status("plane (direct) read back: status", st, GA_OK);
        check("plane (direct) read back: normal", dist3(om, m), tol);
        check("plane (direct) read back: distance", fabs(od - d) / (fabs(d) + r), tol);
        /* dual plane w (m + d n): m = p_E / |p_E| and d = (p4 + p5) / (2 |p_E|) are
           a few roundings each (scaling by w: u; the norm: 2.5 u; the quotient: u)
           and the input m is unit only to 2 u: 8 u */
        double w = pow(10, tk_range(t, -6, 6));
        st = ga_plane_params(ga_mv_scale(ga_plane_dual(m, d), w), &om, &od);
        check_status("plane (dual) read back: status", st, GA_OK);
        check("plane (dual) read back: normal, distance", tk_max(dist3(om, m), fabs(od - d) / (fabs(d) + 1)),
              8 * U);
        st = ga_plane_params(ga_mv_scale(ga_plane_dual(m, d), -w), &om, &od);
        check("plane -(m + d n) reads -m, -d", tk_max(dist3(om, mul3(m, -1)), fabs(od + d) / (fabs(d) + 1)),
              8 * U);

        /* sphere: centre c, radius r, four points c + r v_k with v_k the vertices
           of a randomly turned regular tetrahedron, each moved by up to 0.3 */
        static const double tet[4][3] = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
        for (int k = 0; k < 4; k++) {
            ga_vec3 v = add3(add3(mul3(m, tet[k][0]), mul3(p, tet[k][1])), mul3(q, tet[k][2]));
            v = add3(mul3(v, 1 / sqrt(3.0)), mul3(tk_unit(t), 0.3));
            cp[k] = add3(c, mul3(v, r / norm3(v)));
        }
        w = (trial % 2 ? 1 : -1) * pow(10, tk_range(t, -6, 6)); /* any multiple is the same sphere */
        st = ga_sphere_params(ga_mv_scale(ga_sphere_from_points(cp[0], cp[1], cp[2], cp[3]), w), &oc, &orad);
        check_status("sphere (direct) read back: status", st, GA_OK);
        check("sphere (direct) read back: centre", dist3(oc, c) / size, tol);
        check("sphere (direct) read back: radius", fabs(orad - r) / size, tol);
        w = (trial % 2 ? 1 : -1) * pow(10, tk_range(t, -6, 6));
        st = ga_sphere_params(ga_mv_scale(ga_sphere_dual(c, r), w), &oc, &orad);
        check_status("sphere (dual) read back: status", st, GA_OK);
        check("sphere (dual) read back: centre, radius", tk_max(dist3(oc, c), fabs(orad - r)) / size, tol);
        /* a point is a sphere of radius 0: r^2 = |c|^2 - (s4 + s5) / w cancels terms
           of size |c|^2 and 1 known to ~u each (4 u (|c|^2 + 1) in all), and w =
           s5 - s4 = 1 only up to u (|c|^2 + 1), which multiplies |c|^2: so
           r^2 <= 2 u (|c|^2 + 1)(|c|^2 + 4). (r itself is known only to ~sqrt(u):
           the square root of a rounding error.) */
        st = ga_sphere_params(ga_point_up(c), &oc, &orad);
        check_status("sphere of radius 0 (a point): status", st, GA_OK);
        check("sphere of radius 0 (a point): centre", dist3(oc, c) / size, tol);
        check("sphere of radius 0 (a point): r^2", orad * orad, 2 * U * (dot3(c, c) + 1) * (dot3(c, c) + 4));
        /* the points of each object satisfy its equation: F(x).s = 0 on a dual sphere */
        check("F(x) . dual sphere = 0 on the sphere",
              fabs(ga_mv_sp(ga_point_up(cp[0]), ga_sphere_dual(c, r))) / (size * size), tol);
    }
    tk_end_named();
}

/* ---- bad input -------------------------------------------------------------------- */
static void test_bad_input(void)
{
    tk_note("bad input\n");
    const ga_vec3 sentinel = {7, 7, 7};
    ga_vec3 out = sentinel, o2 = sentinel;
    double r = 7;
    ga_vec3 x = {0.3, -1.2, 0.7};
    ga_mv X = ga_point_up(x);

    /* NaN or Inf in any coefficient, or in lambda */
    for (int i = 0; i < 32; i++) {
        ga_mv B = X;
        B.c[i] = (i % 2) ? NAN : -INFINITY;
        check_status("down of NaN/Inf: not finite", ga_point_down(B, &out), GA_ERR_NOTFINITE);
        check_status("sphere_params of NaN/Inf", ga_sphere_params(B, &out, &r), GA_ERR_NOTFINITE);
        check_status("plane_params of NaN/Inf", ga_plane_params(B, &out, &r), GA_ERR_NOTFINITE);
        check_status("line_params of NaN/Inf", ga_line_params(B, &out, &o2), GA_ERR_NOTFINITE);
        check_status("point_pair_points of NaN/Inf", ga_pointpair_points(B, &out, &o2), GA_ERR_NOTFINITE);
        check_status("circle_params of NaN/Inf", ga_circle_params(B, &out, &r, &o2), GA_ERR_NOTFINITE);
    }
    check_status("down with lambda NaN", ga_point_down_scaled(X, NAN, &out), GA_ERR_NOTFINITE);
    check_status("down with lambda Inf", ga_point_down_scaled(X, INFINITY, &out), GA_ERR_NOTFINITE);
    check_status("down with lambda 0", ga_point_down_scaled(X, 0, &out), GA_ERR_ARG);
    check_status("down with lambda < 0", ga_point_down_scaled(X, -1, &out), GA_ERR_ARG);
    ga_mv up = ga_mv_scalar(7), up0 = up;
    check_status("up with lambda 0", ga_point_up_scaled(x, 0, &up), GA_ERR_ARG);
    check_status("up with lambda -1", ga_point_up_scaled(x, -1, &up), GA_ERR_ARG);
    check_status("up with lambda NaN", ga_point_up_scaled(x, NAN, &up), GA_ERR_NOTFINITE);
    check_status("up with lambda Inf", ga_point_up_scaled(x, INFINITY, &up), GA_ERR_NOTFINITE);
    check_status("up of x with Inf", ga_point_up_scaled((ga_vec3){0, INFINITY, 0}, 1, &up), GA_ERR_NOTFINITE);
    check_status("up of |x|/lambda = 1e200 overflows", ga_point_up_scaled((ga_vec3){1e200, 0, 0}, 1, &up),
                 GA_ERR_DOMAIN);
    check_status("up of |x|/lambda = 1e100, lambda 1e-100 overflows",
                 ga_point_up_scaled((ga_vec3){1, 0, 0}, 1e-200, &up), GA_ERR_DOMAIN);
    check_status("failed up leaves its output untouched", memcmp(&up, &up0, sizeof up) == 0 ? GA_OK : -99,
                 GA_OK);
    check_status("point with x NaN is NaN", ga_point_down(ga_point_up((ga_vec3){NAN, 0, 0}), &out),
                 GA_ERR_NOTFINITE);

    /* not finite points */
    ga_mv e1 = ga_mv_blade(GA_BLADE_E1);
    check_status("down(n): at infinity", ga_point_down(ga_mv_n(), &out), GA_ERR_NOTPOINT);
    check_status("down(0)", ga_point_down(ga_mv_zero(), &out), GA_ERR_NOTPOINT);
    check_status("down(e1): not null, X.n = 0", ga_point_down(e1, &out), GA_ERR_NOTPOINT);
    check_status("down(e1 - nbar/2): not null",
                 ga_point_down(ga_mv_sub(e1, ga_mv_scale(ga_mv_nbar(), 0.5)), &out), GA_ERR_NOTPOINT);
    check_status("down(e4): not null", ga_point_down(ga_mv_e4(), &out), GA_ERR_NOTPOINT);
    check_status("down(e5): not null", ga_point_down(ga_mv_e5(), &out), GA_ERR_NOTPOINT);
    check_status("down(bivector e12)", ga_point_down(ga_mv_blade(GA_BLADE_E12), &out), GA_ERR_NOTPOINT);
    check_status("down(F(x) + e12): grade 2 present",
                 ga_point_down(ga_mv_add(X, ga_mv_blade(GA_BLADE_E12)), &out), GA_ERR_NOTPOINT);
    check_status("down(F(x) + 1): grade 0 present", ga_point_down(ga_mv_add(X, ga_mv_scalar(1)), &out),
                 GA_ERR_NOTPOINT);
    check_status("down(point pair)", ga_point_down(ga_pointpair_from_points(x, sentinel), &out),
                 GA_ERR_NOTPOINT);
    /* the tolerance GA_POINT_TOL: 1e-6 off null is rejected, 1e-12 (rounding) accepted */
    double s = ga_mv_maxabs(X);
    check_status("down(F(x) + 1e-6 s e1): not null",
                 ga_point_down(ga_mv_add(X, ga_mv_scale(e1, 1e-6 * s)), &out), GA_ERR_NOTPOINT);
    check_status("down(F(x) + 1e-12 s e1): accepted",
                 ga_point_down(ga_mv_add(X, ga_mv_scale(e1, 1e-12 * s)), &out), GA_OK);
    check_status("down(F(x) + 1e-6 s e45): grade 2",
                 ga_point_down(ga_mv_add(X, ga_mv_scale(ga_mv_blade(GA_BLADE_E45), 1e-6 * s)), &out),
                 GA_ERR_NOTPOINT);
    /* far points: |x| / lambda beyond sqrt(2 / GA_POINT_TOL) ~ 4.5e4 reads as infinity */
    ga_vec3 far = {1e5, 0, 0};
    check_status("down(F(1e5 e1)), lambda 1: at infinity", ga_point_down(ga_point_up(far), &out),
                 GA_ERR_NOTPOINT);
    check_status("down(F(1e5 e1)), lambda 10: a point",
                 ga_point_up_scaled(far, 10, &X) == GA_OK ? ga_point_down_scaled(X, 10, &out) : -99, GA_OK);
    check("down(F(1e5 e1)), lambda 10 = 1e5 e1", dist3(out, far), 32 * U * 1e5);
    ga_vec3 near_limit = {3e4, -1e4, 2e3};
    check_status("down(F(3e4, -1e4, 2e3)), lambda 1: a point", ga_point_down(ga_point_up(near_limit), &out),
                 GA_OK);
    check("down(F(3e4, -1e4, 2e3)) = x (full accuracy far out)", dist3(out, near_limit),
          32 * U * norm3(near_limit));

    /* wrong grade or wrong kind to each read-back; none may write its outputs */
    out = o2 = sentinel;
    r = 7;
    ga_vec3 a = {0.1, 0.2, 0.3}, b = {1.3, -0.4, 0.5}, c = {-0.7, 0.9, 1.1}, d = {0.4, -1.2, -0.6};
    ga_mv S = ga_sphere_from_points(a, b, c, d), P = ga_plane_from_points(a, b, c),
          L = ga_line_from_points(a, b), C = ga_circle_from_points(a, b, c);
    ga_mv PP = ga_pointpair_from_points(a, b);
    ga_mv wrong[] = {ga_mv_zero(), ga_mv_scalar(2), ga_mv_blade(GA_BLADE_E12345), ga_mv_add(X, PP),
                     ga_mv_add(S, C)};
    for (unsigned i = 0; i < sizeof wrong / sizeof wrong[0]; i++) {
        check_status("sphere_params: wrong grade", ga_sphere_params(wrong[i], &out, &r), GA_ERR_NOTBLADE);
        check_status("plane_params: wrong grade", ga_plane_params(wrong[i], &out, &r), GA_ERR_NOTBLADE);
        check_status("line_params: wrong grade", ga_line_params(wrong[i], &out, &o2), GA_ERR_NOTBLADE);
        check_status("point_pair_points: wrong grade", ga_pointpair_points(wrong[i], &out, &o2),
                     GA_ERR_NOTBLADE);
        check_status("circle_params: wrong grade", ga_circle_params(wrong[i], &out, &r, &o2),
                     GA_ERR_NOTBLADE);
    }
    check_status("sphere_params(bivector)", ga_sphere_params(PP, &out, &r), GA_ERR_NOTBLADE);
    check_status("sphere_params(trivector)", ga_sphere_params(C, &out, &r), GA_ERR_NOTBLADE);
    check_status("sphere_params(direct plane)", ga_sphere_params(P, &out, &r), GA_ERR_NOTBLADE);
    check_status("sphere_params(dual plane)", ga_sphere_params(ga_plane_dual(x, 1), &out, &r),
                 GA_ERR_NOTBLADE);
    check_status("sphere_params(n)", ga_sphere_params(ga_mv_n(), &out, &r), GA_ERR_NOTBLADE);
    ga_mv imag = ga_point_up(x); /* F(c) + (r^2/2) n: an imaginary sphere */
    imag.c[GA_BLADE_E4] += 2;
    imag.c[GA_BLADE_E5] += 2;
    check_status("sphere_params(imaginary sphere)", ga_sphere_params(imag, &out, &r), GA_ERR_IMAGINARY);
    check_status("plane_params(bivector)", ga_plane_params(PP, &out, &r), GA_ERR_NOTBLADE);
    check_status("plane_params(trivector)", ga_plane_params(L, &out, &r), GA_ERR_NOTBLADE);
    check_status("plane_params(direct sphere)", ga_plane_params(S, &out, &r), GA_ERR_NOTBLADE);
    check_status("plane_params(dual sphere)", ga_plane_params(ga_sphere_dual(x, 1), &out, &r),
                 GA_ERR_NOTBLADE);
    check_status("plane_params(n): plane at infinity", ga_plane_params(ga_mv_n(), &out, &r), GA_ERR_NOTBLADE);
    check_status("line_params(vector)", ga_line_params(X, &out, &o2), GA_ERR_NOTBLADE);
    check_status("line_params(bivector)", ga_line_params(PP, &out, &o2), GA_ERR_NOTBLADE);
    check_status("line_params(4-vector)", ga_line_params(P, &out, &o2), GA_ERR_NOTBLADE);
    check_status("line_params(circle)", ga_line_params(C, &out, &o2), GA_ERR_NOTBLADE);
    check_status("line_params(e123)", ga_line_params(ga_mv_i3(), &out, &o2), GA_ERR_NOTBLADE);
    check_status("line_params(e12 ^ n): no direction",
                 ga_line_params(ga_mv_op(ga_mv_blade(GA_BLADE_E12), ga_mv_n()), &out, &o2), GA_ERR_NOTBLADE);
    ga_mv nonblade = ga_mv_add(L, ga_line_from_points(c, d)); /* two skew lines: not a blade */
    check_status("line_params(sum of two skew lines)", ga_line_params(nonblade, &out, &o2), GA_ERR_NOTBLADE);
    check_status("point_pair_points(vector)", ga_pointpair_points(X, &out, &o2), GA_ERR_NOTBLADE);
    check_status("point_pair_points(trivector)", ga_pointpair_points(C, &out, &o2), GA_ERR_NOTBLADE);
    check_status("point_pair_points(flat point F(a)^n)",
                 ga_pointpair_points(ga_mv_op(X, ga_mv_n()), &out, &o2), GA_ERR_NOTBLADE);
    check_status("point_pair_points(e12 + e34): not a blade",
                 ga_pointpair_points(ga_mv_add(ga_mv_blade(GA_BLADE_E12), ga_mv_blade(GA_BLADE_E34)), &out,
                                     &o2),
                 GA_ERR_NOTBLADE);
    /* imaginary point pair: dual to an imaginary sphere meeting two planes through its centre */
    ga_mv ipp = ga_mv_undual(ga_mv_op(ga_mv_op(imag, ga_plane_dual((ga_vec3){1, 0, 0}, x.x)),
                                      ga_plane_dual((ga_vec3){0, 1, 0}, x.y)));
    check_status("point_pair_points(imaginary pair)", ga_pointpair_points(ipp, &out, &o2), GA_ERR_IMAGINARY);
    check_status("circle_params(vector)", ga_circle_params(X, &out, &r, &o2), GA_ERR_NOTBLADE);
    check_status("circle_params(bivector)", ga_circle_params(PP, &out, &r, &o2), GA_ERR_NOTBLADE);
    check_status("circle_params(4-vector)", ga_circle_params(S, &out, &r, &o2), GA_ERR_NOTBLADE);
    check_status("circle_params(line)", ga_circle_params(L, &out, &r, &o2), GA_ERR_NOTBLADE);
    /* (circles sharing two points add to a circle: F(b)^F(c)^(F(a) + F(d))) */
    check_status("circle_params(sum of two disjoint circles): not a blade",
                 ga_circle_params(ga_mv_add(C, ga_circle_from_points(d, add3(d, a), add3(d, b))), &out, &r,
                                  &o2),
                 GA_ERR_NOTBLADE);
    ga_mv icirc = ga_mv_undual(ga_mv_op(imag, ga_plane_dual((ga_vec3){0, 0, 1}, x.z)));
    check_status("circle_params(imaginary circle)", ga_circle_params(icirc, &out, &r, &o2), GA_ERR_IMAGINARY);
    /* collinear points make a line, not a circle; coplanar ones a plane */
    check_status("circle_params(circle through collinear points)",
                 ga_circle_params(ga_circle_from_points(a, b, add3(a, mul3(sub3(b, a), 2))), &out, &r, &o2),
                 GA_ERR_NOTBLADE);
    check_status("sphere_params(sphere through coplanar points)",
                 ga_sphere_params(ga_sphere_from_points(a, b, c, add3(a, add3(sub3(b, a), sub3(c, a)))), &out,
                                  &r),
                 GA_ERR_NOTBLADE);

    check("failed read-backs leave outputs untouched",
          dist3(out, sentinel) + dist3(o2, sentinel) + fabs(r - 7), 0);
}

static const tk_section sections[] = {
    {"table", test_table, 0},
    {"products", test_products, TK_STREAM},
    {"versors", test_versors, TK_STREAM},
    {"model", test_model, TK_STREAM},
    {"objects", test_objects, TK_STREAM},
    {"bad_input", test_bad_input, 0},
};

int main(int argc, char **argv)
{
    return tk_main(argc, argv, "test_conformal", sections, TK_COUNT(sections));
}
