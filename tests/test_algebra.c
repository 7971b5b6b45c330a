/* tests/test_algebra.c: the algebra beside the products (mv.h, rotor.h,
 * fit.h): the general inverse, the regressive and commutator products,
 * projection and rejection, powers and square roots of rotors, the mean of
 * rigid motions and the fits of objects to points.
 *
 * Each check states where its bound comes from: a header's stated accuracy,
 * or a rounding bound of the check itself in units of u = 2^-52
 * (DBL_EPSILON, as the headers count). tests/algebra_check.py checks the same
 * functions against exact rational arithmetic, mpmath and scipy.
 */
#include "testkit.h"

#include <garotor/versor.h>

#define U DBL_EPSILON

static tk_rng rng = {0x5eed0a19eb7a11ULL};

static void check(const char *name, double err, double tol) { tk_add_tol(tk_get(name), err, tol); }
static void check_status(const char *name, int got, int want) { tk_add_status(tk_get(name), got, want); }
static void check_bool(const char *name, int cond) { tk_add_bool(tk_get(name), cond); }

static double maxdiff(ga_mv a, ga_mv b) { return tk_mv_maxabs(ga_mv_sub(a, b)); }
static double sumabs(ga_mv a)
{
    double s = 0;
    for (int i = 0; i < 32; i++) s += fabs(a.c[i]);
    return s;
}
static double sumsq(ga_mv a)
{
    double s = 0;
    for (int i = 0; i < 32; i++) s += a.c[i] * a.c[i];
    return s;
}
static double off_grade(ga_mv a, int k) { return tk_mv_maxabs(ga_mv_sub(a, ga_mv_grade(a, k))); }
static int same_bits(ga_mv a, ga_mv b) { return memcmp(&a, &b, sizeof a) == 0; }

static ga_mv rand_mv(tk_rng *t)
{
    ga_mv a;
    for (int i = 0; i < 32; i++) a.c[i] = tk_range(t, -1, 1);
    return a;
}
static ga_mv rand_vector(tk_rng *t)
{
    ga_mv v = ga_mv_zero();
    for (int i = 1; i <= 5; i++) v.c[i] = tk_range(t, -1, 1);
    return v;
}
/* a vector whose square is at least 0.1 in size: not near null */
static ga_mv rand_nonnull(tk_rng *t)
{
    for (;;) {
        ga_mv v = rand_vector(t);
        if (fabs(ga_mv_sp(v, v)) >= 0.1)
            return v;
    }
}
/* the blade of k random vectors, its square at least 1e-3 of its size */
static ga_mv rand_blade(tk_rng *t, int k)
{
    for (;;) {
        ga_mv B = ga_mv_scalar(1);
        for (int i = 0; i < k; i++) B = ga_mv_op(B, rand_vector(t));
        if (fabs(ga_mv_norm2(B)) >= 1e-3 * sumsq(B))
            return B;
    }
}
static ga_mv one_minus(ga_mv x) /* x - 1 */
{
    x.c[0] -= 1.0;
    return x;
}

/* ---- the inverse ------------------------------------------------------------------ */

/* What ga_mv_inverse decides, replayed: a ~a a scalar to its rounding, on a
   2^-e (exact), and then ~a / s as mv.h states it (and as 0.3.0 computed
   it), bit for bit */
static int versor_path(ga_mv a, ga_mv *inv, double *s_out, double *sbar_out)
{
    int e = 0;
    if (ga_mv_maxabs(a) > 0)
        frexp(ga_mv_maxabs(a), &e);
    for (int i = 0; i < 32; i++) a.c[i] = ldexp(a.c[i], -e);
    ga_mv rev = ga_mv_reverse(a), aa = ga_mv_gp(a, rev);
    double s = aa.c[0], sbar = sumsq(a);
    aa.c[0] = 0;
    *s_out = s;
    *sbar_out = sbar;
    if (ga_mv_maxabs(aa) > GA_MV_INVERSE_TOL * U * sbar)
        return 0;
    ga_mv r = ga_mv_scale(rev, 1.0 / s);
    for (int i = 0; i < 32; i++) r.c[i] = ldexp(r.c[i], -e);
    *inv = r;
    return 1;
}

/* one invertible multivector: left and right residuals within the bound of
   mv.h for the way it took */
static void inverse_case(const char *what, ga_mv a, int want_versor)
{
    ga_mv X, V;
    double s, sbar;
    int st = ga_mv_inverse(a, &X);
    char name[128];
    snprintf(name, sizeof name, "%s: GA_OK", what);
    check_status(name, st, GA_OK);
    if (st != GA_OK)
        return;
    int versor = versor_path(a, &V, &s, &sbar);
    if (want_versor >= 0) {
        snprintf(name, sizeof name, "%s: %s", what,
                 want_versor ? "a ~a scalar (the versor way)" : "the general way");
        check_bool(name, versor == want_versor);
    }
    /* mv.h: the versor way within 2 TOL u sbar / |s|, the general way within
       u |a|_1 |a^-1|_1 (the residual's own rounding is inside both: it sums
       32 products bounded by those sizes, and is measured at 0.13 and 0.05 of
       them) */
    double ax = sumabs(a) * sumabs(X);
    double tol = versor ? 2 * GA_MV_INVERSE_TOL * U * sbar / fabs(s) : U * ax;
    snprintf(name, sizeof name, "%s: a a^-1 = 1", what);
    check(name, tk_mv_maxabs(one_minus(ga_mv_gp(a, X))), tol);
    /* the other side: a^-1 a - 1 = a^-1 (a a^-1 - 1) a, so within the
       condition |a|_1 |a^-1|_1 times the first */
    snprintf(name, sizeof name, "%s: a^-1 a = 1", what);
    check(name, tk_mv_maxabs(one_minus(ga_mv_gp(X, a))), versor ? tol : tol * ax);
    if (versor) {
        snprintf(name, sizeof name, "%s: ~a / (a ~a) bit for bit", what);
        check_bool(name, same_bits(X, V));
    }
}

static void section_inverse(void)
{
    for (int t = 0; t < 20000; t++) {
        ga_mv a = rand_mv(&rng);
        int k = (int)(tk_next(&rng) % 1200) - 600; /* any scale: 2^-600 .. 2^600 */
        inverse_case("dense", t % 4 ? a : ga_mv_scale(a, ldexp(1.0, k)), 0);
    }
    /* sparse: some are versors, most are not */
    for (int t = 0; t < 5000; t++) {
        ga_mv a = ga_mv_zero();
        for (int i = 0; i < 32; i++)
            if (tk_uni(&rng) < 0.2)
                a.c[i] = tk_range(&rng, -1, 1);
        if (ga_mv_maxabs(a) > 0)
            inverse_case("sparse", a, -1);
    }
    for (int t = 0; t < 10000; t++) {
        int k = 1 + t % 5;
        ga_mv V = ga_mv_scalar(1);
        for (int i = 0; i < k; i++) V = ga_mv_gp(V, rand_nonnull(&rng));
        inverse_case("versors of 1 to 5 vectors", V, 1);
        inverse_case("blades of grade 1 to 5", rand_blade(&rng, k), 1);
        ga_twist xi = tk_twist(&rng, t % TK_TWIST_FAMILIES);
        inverse_case("rigid rotors, every twist family",
                     ga_rotor_to_mv(ga_rotor_exp(ga_twist_to_generator(xi))), 1);
    }
    /* a blade with a few ulps of noise on each coefficient is a blade to its
       rounding: the versor way, not a refusal (0.3.0's fixed 1e-12 and
       64 u |a|^2 refused such blades where a ~a cancels) */
    for (int t = 0; t < 10000; t++) {
        ga_mv B = rand_blade(&rng, 1 + t % 4);
        for (int i = 0; i < 32; i++) B.c[i] *= 1 + (double)((int)(tk_next(&rng) % 17) - 8) * U;
        inverse_case("blades, 8 ulps of noise", B, 1);
        /* far carriers: the plane of a circle 1e2..1e6 from the origin
           (F = C ^ n, as a round's read-back inverts it) */
        ga_vec3 c = tk_scale(tk_unit(&rng), tk_loguni(&rng, 1e2, 1e6));
        ga_vec3 p[3];
        for (int i = 0; i < 3; i++) {
            ga_vec3 u = tk_unit(&rng);
            p[i] = (ga_vec3){c.x + u.x, c.y + u.y, c.z + u.z};
        }
        inverse_case("carrier C ^ n of a circle 1e2..1e6 out",
                     ga_mv_op(ga_circle_from_points(p[0], p[1], p[2]), ga_mv_n()), -1);
    }
    tk_end_named();
}

static void section_inverse_singular(void)
{
    ga_mv one_e45 = ga_mv_add(ga_mv_scalar(1), ga_mv_blade(GA_BLADE_E45));
    ga_mv one_e1 = ga_mv_add(ga_mv_scalar(1), ga_mv_blade(GA_BLADE_E1));
    ga_mv o = ga_point_up((ga_vec3){0, 0, 0});
    /* zero divisors: x y = 0 for some y != 0 rules an inverse out */
    const struct {
        const char *what;
        ga_mv a;
    } null[] = {
        {"0", ga_mv_zero()},
        {"n", ga_mv_n()},
        {"nbar", ga_mv_nbar()},
        {"F(1, 2, 3)", ga_point_up((ga_vec3){1, 2, 3})},
        {"1 + e45", one_e45},
        {"1 + e1", one_e1},
        {"n ^ e1", ga_mv_op(ga_mv_n(), ga_mv_blade(GA_BLADE_E1))},
        {"F(0) ^ e1 (a tangent vector)", ga_mv_op(o, ga_mv_blade(GA_BLADE_E1))},
        {"(1 + e45)(1 + e1) (mixed)", ga_mv_gp(one_e45, one_e1)},
    };
    for (size_t i = 0; i < TK_COUNT(null); i++) {
        ga_mv out = ga_mv_scalar(42);
        int st = ga_mv_inverse(null[i].a, &out);
        if (st != GA_ERR_SINGULAR)
            tk_note("  inverse of %s: %s\n", null[i].what, ga_status_string(st));
        check_status("zero divisors of the list: GA_ERR_SINGULAR", st, GA_ERR_SINGULAR);
        check_bool("zero divisors of the list: output untouched", maxdiff(out, ga_mv_scalar(42)) == 0);
    }
    /* (1 + e45) X and (1 + e1) X are zero divisors for every X: exactly, with
       small-integer coefficients; to their rounding, with random ones */
    for (int t = 0; t < 5000; t++) {
        ga_mv X = ga_mv_zero(), Y = rand_mv(&rng);
        for (int i = 0; i < 32; i++) X.c[i] = (double)((int)(tk_next(&rng) % 9) - 4);
        ga_mv out;
        ga_mv z = t % 2 ? one_e45 : one_e1;
        check_status("(1 + e45) X, (1 + e1) X, X of small integers: GA_ERR_SINGULAR",
                     ga_mv_inverse(ga_mv_gp(z, X), &out), GA_ERR_SINGULAR);
        check_status("(1 + e45) X, (1 + e1) X, X random: GA_ERR_SINGULAR",
                     ga_mv_inverse(ga_mv_gp(z, Y), &out), GA_ERR_SINGULAR);
        /* a step away from them: invertible, ill-conditioned */
        ga_mv near = ga_mv_add(ga_mv_gp(z, Y), ga_mv_scale(rand_mv(&rng), 1e-6));
        inverse_case("1e-6 from a zero divisor", near, -1);
    }
    /* the way from a zero divisor z Y to its rounding: eps W added, eps from
       1e-3 to 1e-12 of |z Y| (~1) is invertible (condition up to ~1e12),
       eps = 2^-53, half an ulp of the coefficients near 1, is a zero
       divisor to its rounding */
    for (int k = 3; k <= 12; k++)
        for (int t = 0; t < 100; t++) {
            ga_mv Y = rand_mv(&rng), W = rand_mv(&rng);
            inverse_case("1e-3..1e-12 from a zero divisor",
                         ga_mv_add(ga_mv_gp(one_e45, Y), ga_mv_scale(W, pow(10, -k))), -1);
        }
    for (int t = 0; t < 1000; t++) {
        ga_mv Y = rand_mv(&rng), W = rand_mv(&rng), out;
        check_status("u/2 from a zero divisor: GA_ERR_SINGULAR",
                     ga_mv_inverse(ga_mv_add(ga_mv_gp(one_e45, Y), ga_mv_scale(W, 0x1p-53)), &out),
                     GA_ERR_SINGULAR);
    }
    ga_mv out = ga_mv_scalar(42), bad = ga_mv_scalar(1);
    /* an inverse beyond DBL_MAX */
    check_status("1e-310 (its inverse overflows): GA_ERR_SINGULAR", ga_mv_inverse(ga_mv_scalar(1e-310), &out),
                 GA_ERR_SINGULAR);
    inverse_case("1e-300 + 1e-300 e1 + 2e-300 e23 (tiny, invertible)",
                 ga_mv_add(ga_mv_scalar(1e-300), ga_mv_add(ga_mv_scale(ga_mv_blade(GA_BLADE_E1), 1e-300),
                                                           ga_mv_scale(ga_mv_blade(GA_BLADE_E23), 2e-300))),
                 -1);
    bad.c[GA_BLADE_E23] = NAN;
    check_status("NaN, Inf: GA_ERR_NOTFINITE", ga_mv_inverse(bad, &out), GA_ERR_NOTFINITE);
    bad.c[GA_BLADE_E23] = INFINITY;
    check_status("NaN, Inf: GA_ERR_NOTFINITE", ga_mv_inverse(bad, &out), GA_ERR_NOTFINITE);
    check_bool("NaN, Inf: output untouched", maxdiff(out, ga_mv_scalar(42)) == 0);
    tk_end_named();
}

/* ---- the regressive and commutator products ------------------------------------------ */

static double dual_sign_free_diff(ga_mv a, ga_mv b) { return maxdiff(a, b); }

static void section_products(void)
{
    ga_mv I = ga_mv_blade(GA_BLADE_E12345);
    for (int t = 0; t < 5000; t++) {
        ga_mv a = rand_mv(&rng), b = rand_mv(&rng), c = rand_mv(&rng);
        /* (a & b)* = a* ^ b*: the dual and the undual only move and negate
           coefficients, so exactly */
        check("(a & b)* = a* ^ b*, exactly",
              dual_sign_free_diff(ga_mv_dual(ga_mv_regressive(a, b)), ga_mv_op(ga_mv_dual(a), ga_mv_dual(b))),
              0);
        check("a & I = I & a = a, exactly", maxdiff(ga_mv_regressive(a, I), a), 0);
        check("a & I = I & a = a, exactly", maxdiff(ga_mv_regressive(I, a), a), 0);
        /* associative as the outer product is: each side sums at most 32 x 32
           products of coefficients in [-1, 1], in two orders */
        check("(a & b) & c = a & (b & c)",
              maxdiff(ga_mv_regressive(ga_mv_regressive(a, b), c),
                      ga_mv_regressive(a, ga_mv_regressive(b, c))),
              2 * 64 * U * 32 * 32);
        /* the commutator: antisymmetric exactly (the same two products, the
           difference negated), zero with a scalar exactly, Jacobi's identity
           to the rounding of three nested products (each term's sums are at
           most 32^2 of coefficients in [-1, 1]) */
        check("a x b = -(b x a), exactly",
              maxdiff(ga_mv_commutator(a, b), ga_mv_scale(ga_mv_commutator(b, a), -1)), 0);
        check("2 x a = 0, exactly", tk_mv_maxabs(ga_mv_commutator(ga_mv_scalar(2), a)), 0);
        ga_mv jac = ga_mv_add(ga_mv_commutator(a, ga_mv_commutator(b, c)),
                              ga_mv_add(ga_mv_commutator(b, ga_mv_commutator(c, a)),
                                        ga_mv_commutator(c, ga_mv_commutator(a, b))));
        check("Jacobi: a x (b x c) + b x (c x a) + c x (a x b) = 0", tk_mv_maxabs(jac), 6 * 66 * U * 32 * 32);
        /* bivectors close under it (the Lie algebra of the rotors), and a
           bivector's commutator with a vector is -x _| B = B |_ x */
        ga_mv A2 = ga_mv_grade(a, 2), B2 = ga_mv_grade(b, 2), x = ga_mv_grade(c, 1);
        ga_mv AB = ga_mv_commutator(A2, B2);
        check("bivector x bivector is a bivector", off_grade(AB, 2), 2 * 33 * U * 10);
        check("B x x = -(x _| B) for a bivector B, a vector x",
              maxdiff(ga_mv_commutator(B2, x), ga_mv_scale(ga_mv_lc(x, B2), -1)), 2 * 33 * U * 10);
    }
    /* blades: A & B holds their common subspace. A = a1 a2 a3 a4 and B = a1 a2
       b3 b4 (outer products) span the whole space together, so A & B is a
       trivector holding a1 and a2, and (A & B) ^ a1 = 0 */
    for (int t = 0; t < 5000; t++) {
        ga_mv a1 = rand_vector(&rng), a2 = rand_vector(&rng), a3 = rand_vector(&rng), a4 = rand_vector(&rng);
        ga_mv b3 = rand_vector(&rng), b4 = rand_vector(&rng);
        ga_mv A = ga_mv_op(ga_mv_op(a1, a2), ga_mv_op(a3, a4)),
              B = ga_mv_op(ga_mv_op(a1, a2), ga_mv_op(b3, b4));
        ga_mv M = ga_mv_regressive(A, B);
        double scale = sumabs(A) * sumabs(B) * (sumabs(a1) + sumabs(a2));
        check("blades: A & B of grade 4 + 4 - 5 = 3", off_grade(M, 3), 64 * U * sumabs(A) * sumabs(B));
        check("blades: a1 ^ (A & B) = a2 ^ (A & B) = 0", tk_mv_maxabs(ga_mv_op(a1, M)), 256 * U * scale);
        check("blades: a1 ^ (A & B) = a2 ^ (A & B) = 0", tk_mv_maxabs(ga_mv_op(a2, M)), 256 * U * scale);
        /* grades 4 and 4: B & A = (-1)^((5-4)(5-4)) A & B */
        check("blades: B & A = -(A & B), exactly", maxdiff(ga_mv_regressive(B, A), ga_mv_scale(M, -1)), 0);
    }
    /* the meet of two planes is their regressive product */
    for (int t = 0; t < 2000; t++) {
        ga_vec3 p[4];
        for (int i = 0; i < 4; i++) p[i] = tk_scale(tk_unit(&rng), tk_range(&rng, 0, 3));
        ga_mv P1 = ga_plane_from_points(p[0], p[1], p[2]), P2 = ga_plane_from_points(p[0], p[1], p[3]);
        ga_mv R = ga_mv_regressive(P1, P2), M = ga_mv_meet(P1, P2);
        check("planes: P1 & P2 = ga_mv_meet(P1, P2)", maxdiff(R, M), 64 * U * sumabs(P1) * sumabs(P2));
    }
    tk_end_named();
}

/* ---- projection and rejection ------------------------------------------------------- */

static void section_projection(void)
{
    for (int t = 0; t < 10000; t++) {
        int k = 1 + t % 4;
        ga_mv B = rand_blade(&rng, k), a = rand_vector(&rng), P, R, PP, Bi;
        check_status("vector onto a blade: GA_OK", ga_mv_project(a, B, &P), GA_OK);
        check_status("vector onto a blade: GA_OK", ga_mv_reject(a, B, &R), GA_OK);
        TK_OK(ga_mv_inverse(B, &Bi));
        /* the products (a _| B) _| B^-1 and (a ^ B) |_ B^-1 each sum terms
           bounded by |a|_1 |B|_1 |B^-1|_1 */
        double scale = sumabs(a) * sumabs(B) * sumabs(Bi), tol = 4 * 33 * U * scale;
        check("a = P_B(a) + R_B(a)", maxdiff(ga_mv_add(P, R), a), 2 * tol);
        check("P_B(a) is a vector", off_grade(P, 1), tol);
        check("P_B(a) lies in B: P ^ B = 0", tk_mv_maxabs(ga_mv_op(P, B)), 2 * tol * sumabs(B));
        check("R_B(a) is orthogonal to B: R _| B = 0", tk_mv_maxabs(ga_mv_lc(R, B)), 2 * tol * sumabs(B));
        TK_OK(ga_mv_project(P, B, &PP));
        check("P_B(P_B(a)) = P_B(a)", maxdiff(PP, P), 2 * tol * sumabs(B) * sumabs(Bi));
        /* a blade inside B projects onto itself */
        if (k >= 2) {
            ga_mv A, in = ga_mv_op(ga_mv_lc(rand_vector(&rng), B), ga_mv_zero());
            in = ga_mv_lc(rand_vector(&rng), B); /* a (k-1)-blade in B */
            TK_OK(ga_mv_project(in, B, &A));
            check("a blade in B projects onto itself", maxdiff(A, in), 4 * tol * sumabs(B) * sumabs(Bi));
        }
    }
    /* Euclidean: e1 + 2 e2 + 3 e3 onto e12, exactly */
    ga_mv x = ga_mv_vector(1, 2, 3, 0, 0), P, R;
    TK_OK(ga_mv_project(x, ga_mv_blade(GA_BLADE_E12), &P));
    TK_OK(ga_mv_reject(x, ga_mv_blade(GA_BLADE_E12), &R));
    check("e1 + 2e2 + 3e3 onto e12: e1 + 2e2, exactly", maxdiff(P, ga_mv_vector(1, 2, 0, 0, 0)), 0);
    check("e1 + 2e2 + 3e3 from e12: 3e3, exactly", maxdiff(R, ga_mv_vector(0, 0, 3, 0, 0)), 0);
    /* null blades: no inverse, no projection */
    ga_mv null[] = {ga_mv_n(), ga_point_up((ga_vec3){1, 2, 3}), ga_mv_op(ga_mv_n(), ga_mv_blade(GA_BLADE_E1)),
                    ga_mv_op(ga_point_up((ga_vec3){0, 0, 0}), ga_mv_blade(GA_BLADE_E2))};
    for (size_t i = 0; i < TK_COUNT(null); i++) {
        ga_mv out = ga_mv_scalar(42);
        check_status("onto a null blade (n, F(x), n ^ e1, tangent): GA_ERR_SINGULAR",
                     ga_mv_project(x, null[i], &out), GA_ERR_SINGULAR);
        check_status("onto a null blade (n, F(x), n ^ e1, tangent): GA_ERR_SINGULAR",
                     ga_mv_reject(x, null[i], &out), GA_ERR_SINGULAR);
        check_bool("onto a null blade: output untouched", maxdiff(out, ga_mv_scalar(42)) == 0);
    }
    ga_mv bad = x;
    bad.c[1] = NAN;
    check_status("NaN: GA_ERR_NOTFINITE", ga_mv_project(bad, ga_mv_blade(GA_BLADE_E12), &P),
                 GA_ERR_NOTFINITE);
    check_status("NaN: GA_ERR_NOTFINITE", ga_mv_reject(x, bad, &P), GA_ERR_NOTFINITE);
    tk_end_named();
}

/* ---- powers and square roots of rotors ------------------------------------------------ */

/* A bivector of kind f from commuting blades, elliptic half-angles below
   amax, moved into general position by a conformal rotor (rotation,
   translation, dilation, transversion: every coefficient in play). */
enum { NKIND = 7 };
static const char *const kind_name[NKIND] = {
    "rotation",        "boost", "null (translation)", "two rotations", "rotation x boost",
    "rotation x null", "dense",
};
static ga_mv kind_bivector(tk_rng *r, int f, double amax)
{
    double t1 = tk_range(r, 0.01, amax), t2 = tk_range(r, 0.01, amax), h = tk_range(r, -2, 2);
    double c = tk_range(r, -3, 3);
    ga_mv B = ga_mv_zero();
    ga_mv e12 = ga_mv_blade(GA_BLADE_E12), e34 = ga_mv_blade(GA_BLADE_E34), e23 = ga_mv_blade(GA_BLADE_E23);
    ga_mv e45 = ga_mv_blade(GA_BLADE_E45), e1n = ga_mv_op(ga_mv_blade(GA_BLADE_E1), ga_mv_n());
    switch (f) {
    case 0: B = ga_mv_scale(e12, t1); break;
    case 1: B = ga_mv_scale(e45, h); break;
    case 2: B = ga_mv_scale(e1n, c); break;
    case 3: B = ga_mv_add(ga_mv_scale(e12, t1), ga_mv_scale(e34, t2)); break;
    case 4: B = ga_mv_add(ga_mv_scale(e23, t1), ga_mv_scale(e45, h)); break;
    case 5: B = ga_mv_add(ga_mv_scale(e23, t1), ga_mv_scale(e1n, c)); break;
    default:
        for (int i = GA_BLADE_E12; i <= GA_BLADE_E45; i++) B.c[i] = tk_range(r, -0.5, 0.5);
        return B; /* every half-angle below pi/2: at most 0.5 sqrt(10) < 1.6 */
    }
    double ang = tk_range(r, 0, TK_PI), ka = tk_range(r, 0, 1.5), kb = tk_range(r, 0, 0.3);
    ga_vec3 axis = tk_unit(r), a = tk_scale(tk_unit(r), ka), b = tk_scale(tk_unit(r), kb);
    double s = tk_loguni(r, 0.5, 2.0);
    ga_mv D = ga_mv_scalar(1);
    TK_OK(ga_versor_dilation(tk_scale(tk_unit(r), 0.5), s, &D));
    ga_mv V = ga_mv_gp(ga_mv_gp(ga_versor_rotation(axis, ang), ga_versor_translation(a)),
                       ga_mv_gp(D, ga_versor_transversion(b)));
    ga_mv Vi = ga_mv_scalar(1);
    TK_OK(ga_mv_inverse(V, &Vi));
    return ga_mv_grade(ga_mv_gp(ga_mv_gp(V, B), Vi), 2);
}
static double rel(ga_mv a, ga_mv b) { return tk_mv_maxabs(ga_mv_sub(a, b)) / tk_mv_maxabs(b); }

static void section_powers(void)
{
    /* mv.h: exp(log R) = R and log(exp B) = B to 1e-13 of |R|, |B| on the
       principal domain; a power is one exp of t log R, so its identities
       hold to a few of those (the products add the rounding of 32 x 32
       terms, below them) */
    const double tol = 4e-13;
    for (int f = 0; f < NKIND; f++) {
        char n1[96], n2[96], n3[96], n4[96], n5[96];
        snprintf(n1, sizeof n1, "sqrt(R)^2 = R: %s", kind_name[f]);
        snprintf(n2, sizeof n2, "R^1 = R, R^0 = 1: %s", kind_name[f]);
        snprintf(n3, sizeof n3, "R^a R^b = R^(a+b): %s", kind_name[f]);
        snprintf(n4, sizeof n4, "R^-1 R = 1: %s", kind_name[f]);
        snprintf(n5, sizeof n5, "sqrt(exp B) = exp(B/2): %s", kind_name[f]);
        for (int t = 0; t < 1000; t++) {
            ga_mv B = kind_bivector(&rng, f, TK_PI / 2 - 1e-3), R = ga_mv_exp(B), S, P1, P0, Pa, Pb, Pab, Pm;
            double x = tk_range(&rng, -2, 2), y = tk_range(&rng, -2, 2);
            if (ga_mv_sqrt(R, &S) != GA_OK || ga_mv_pow(R, 1, &P1) != GA_OK ||
                ga_mv_pow(R, 0, &P0) != GA_OK || ga_mv_pow(R, x, &Pa) != GA_OK ||
                ga_mv_pow(R, y, &Pb) != GA_OK || ga_mv_pow(R, x + y, &Pab) != GA_OK ||
                ga_mv_pow(R, -1, &Pm) != GA_OK) {
                check_status(n1, GA_ERR_DOMAIN, GA_OK);
                continue;
            }
            check(n1, rel(ga_mv_gp(S, S), R), tol);
            check(n2, rel(P1, R), tol);
            check(n2, maxdiff(P0, ga_mv_scalar(1)), 0);
            check(n3, rel(ga_mv_gp(Pa, Pb), Pab), 4 * tol);
            check(n4, tk_mv_maxabs(one_minus(ga_mv_gp(Pm, R))) / (tk_mv_maxabs(Pm) * tk_mv_maxabs(R)), tol);
            check(n5, rel(S, ga_mv_exp(ga_mv_scale(B, 0.5))), tol);
        }
    }
    /* statuses: not a rotor, NaN, a power that overflows */
    ga_mv out = ga_mv_scalar(42), odd = ga_mv_vector(1, 0, 0, 0, 0), two = ga_mv_scalar(2),
          bad = ga_mv_scalar(1);
    bad.c[GA_BLADE_E12] = NAN;
    check_status("sqrt, pow of a vector (no rotor): GA_ERR_DOMAIN", ga_mv_sqrt(odd, &out), GA_ERR_DOMAIN);
    check_status("sqrt, pow of 2 (R ~R != 1): GA_ERR_DOMAIN", ga_mv_pow(two, 0.3, &out), GA_ERR_DOMAIN);
    check_status("sqrt, pow of NaN: GA_ERR_NOTFINITE", ga_mv_sqrt(bad, &out), GA_ERR_NOTFINITE);
    check_status("pow(R, NaN), pow(R, Inf): GA_ERR_NOTFINITE", ga_mv_pow(ga_mv_scalar(1), NAN, &out),
                 GA_ERR_NOTFINITE);
    check_status("pow(R, NaN), pow(R, Inf): GA_ERR_NOTFINITE", ga_mv_pow(ga_mv_scalar(1), INFINITY, &out),
                 GA_ERR_NOTFINITE);
    ga_mv boost = ga_mv_exp(ga_mv_scale(ga_mv_blade(GA_BLADE_E45), 2.0));
    check_status("exp(2 e45)^1000 (overflows): GA_ERR_DOMAIN", ga_mv_pow(boost, 1000, &out), GA_ERR_DOMAIN);
    check_bool("refused: output untouched", maxdiff(out, ga_mv_scalar(42)) == 0);
    /* -1 has a real log (a half turn), so a square root: a quarter turn */
    ga_mv S;
    TK_OK(ga_mv_sqrt(ga_mv_scalar(-1), &S));
    check("sqrt(-1)^2 = -1", maxdiff(ga_mv_gp(S, S), ga_mv_scalar(-1)), 4 * U);
    tk_end_named();
}

/* ---- the mean of rigid motions -------------------------------------------------------- */

/* distance of two rigid rotors as motions: the larger of the rotation part
   (up to sign) and of the translation relative to max(1, |t|) */
static double motion_dist(ga_rotor a, ga_rotor b)
{
    double sp = a.s * b.s + a.e12 * b.e12 + a.e13 * b.e13 + a.e23 * b.e23;
    ga_rotor c = sp < 0 ? (ga_rotor){-b.s, -b.e12, -b.e13, -b.e23, -b.e1n, -b.e2n, -b.e3n, -b.e123n} : b;
    double dq = fmax(fmax(fabs(a.s - c.s), fabs(a.e12 - c.e12)),
                     fmax(fabs(a.e13 - c.e13), fabs(a.e23 - c.e23)));
    ga_vec3 ta = ga_rotor_to_translation(a), tb = ga_rotor_to_translation(b);
    double dt = tk_norm((ga_vec3){ta.x - tb.x, ta.y - tb.y, ta.z - tb.z}) / fmax(1, tk_norm(ta));
    return fmax(dq, dt);
}
static ga_rotor rand_motion(tk_rng *r, double angle, double shift)
{
    ga_twist xi = {tk_scale(tk_unit(r), tk_range(r, 0, angle)), tk_scale(tk_unit(r), tk_range(r, 0, shift))};
    return ga_rotor_exp(ga_twist_to_generator(xi));
}

static void section_mean(void)
{
    enum { NMAX = 8 };
    ga_rotor R[NMAX], L[NMAX], Q[NMAX], M, ML, MQ;
    double w[NMAX];
    /* the stopping rule leaves a step of GA_ROTOR_MEAN_TOL u of the logs'
       sizes; the mean moves by that and by the rounding of a few rotor
       products: 4 GA_ROTOR_MEAN_TOL u relative to max(1, |t|) */
    const double tol = 4 * GA_ROTOR_MEAN_TOL * U;
    for (int t = 0; t < 3000; t++) {
        double spread = t % 3 == 0 ? 0.3 : t % 3 == 1 ? 1.2 : 2.5, shift = tk_loguni(&rng, 1e-3, 1e3);
        ga_rotor C = rand_motion(&rng, TK_PI, shift);
        /* one rotor; a rotor twice */
        TK_OK(ga_rotor_mean(&C, (double[]){0.7}, 1, &M));
        check("mean of one rotor: itself", motion_dist(M, C), tol);
        ga_rotor two[2] = {C, C};
        TK_OK(ga_rotor_mean(two, (double[]){0.2, 3.0}, 2, &M));
        check("mean of R and R: R", motion_dist(M, C), tol);
        /* pairs symmetric about C: C exp(+-B_k), equal weights within a
           pair, rotations within 1.5 of C (where the mean is unique) */
        int np = 1 + (int)(tk_next(&rng) % 3);
        for (int k = 0; k < np; k++) {
            ga_twist xi = {tk_scale(tk_unit(&rng), tk_range(&rng, 0, fmin(spread, 1.5))),
                           tk_scale(tk_unit(&rng), tk_range(&rng, 0, shift))};
            ga_twist mxi = {tk_scale(xi.w, -1), tk_scale(xi.v, -1)};
            R[2 * k] = ga_rotor_mul(C, ga_rotor_exp(ga_twist_to_generator(xi)));
            R[2 * k + 1] = ga_rotor_mul(C, ga_rotor_exp(ga_twist_to_generator(mxi)));
            w[2 * k] = w[2 * k + 1] = tk_range(&rng, 0.1, 1);
        }
        int st = ga_rotor_mean(R, w, (size_t)(2 * np), &M);
        check_status("symmetric pairs about M: GA_OK", st, GA_OK);
        if (st == GA_OK)
            check("symmetric pairs about M: M", motion_dist(M, C), tol * fmax(1, shift));
        /* random rotors about C: invariant under L R_i and R_i L, and the
           fixed-point equation holds at the mean */
        int n = 2 + (int)(tk_next(&rng) % 6);
        ga_rotor Lm = rand_motion(&rng, TK_PI, shift), Rm = rand_motion(&rng, TK_PI, shift);
        for (int i = 0; i < n; i++) {
            R[i] = ga_rotor_mul(C, rand_motion(&rng, spread, shift));
            w[i] = tk_range(&rng, 0.1, 1);
            L[i] = ga_rotor_mul(Lm, R[i]);
            Q[i] = ga_rotor_mul(R[i], Rm);
        }
        st = ga_rotor_mean(R, w, (size_t)n, &M);
        check_status("random rotors: GA_OK", st, GA_OK);
        if (st != GA_OK)
            continue;
        TK_OK(ga_rotor_mean(L, w, (size_t)n, &ML));
        TK_OK(ga_rotor_mean(Q, w, (size_t)n, &MQ));
        /* the invariance holds to the conditioning of the mean: the rotors
           are spread by up to 2.5 rad, and the products L R_i round at u of
           their translations (|t| up to 3 shift) */
        double scale = fmax(1, shift);
        check("mean(L R_i) = L mean(R_i)", motion_dist(ML, ga_rotor_mul(Lm, M)), 4 * tol * scale);
        check("mean(R_i L) = mean(R_i) L", motion_dist(MQ, ga_rotor_mul(M, Rm)), 4 * tol * scale);
        double sum[6] = {0}, wsum = 0, big = 1;
        for (int i = 0; i < n; i++) wsum += w[i];
        for (int i = 0; i < n; i++) {
            ga_generator b;
            TK_OK(ga_rotor_log(ga_rotor_mul(ga_rotor_reverse(M), R[i]), &b));
            const double *c = &b.e12;
            for (int k = 0; k < 6; k++) sum[k] += w[i] / wsum * c[k], big = fmax(big, fabs(c[k]));
        }
        double res = 0;
        for (int k = 0; k < 6; k++) res = fmax(res, fabs(sum[k]));
        check("at the mean: |sum w_i log(M^-1 R_i)|", res / big, 2 * tol);
    }
    /* pure translations: the weighted mean of the translations; rotations
       about one axis within pi/2: the weighted mean of the angles */
    for (int t = 0; t < 1000; t++) {
        int n = 2 + t % 5;
        ga_vec3 tm = {0, 0, 0};
        double am = 0, wsum = 0;
        ga_vec3 axis = tk_unit(&rng);
        for (int i = 0; i < n; i++) {
            ga_vec3 v = tk_scale(tk_unit(&rng), tk_range(&rng, 0, 10));
            double ang = tk_range(&rng, -TK_PI / 4, TK_PI / 4);
            w[i] = tk_range(&rng, 0.1, 1);
            wsum += w[i];
            tm = (ga_vec3){tm.x + w[i] * v.x, tm.y + w[i] * v.y, tm.z + w[i] * v.z};
            am += w[i] * ang;
            R[i] = ga_rotor_translation(v);
            L[i] = ga_rotor_rotation(axis, ang);
        }
        tm = tk_scale(tm, 1 / wsum);
        TK_OK(ga_rotor_mean(R, w, (size_t)n, &M));
        check("translations: the weighted mean translation", motion_dist(M, ga_rotor_translation(tm)), tol);
        TK_OK(ga_rotor_mean(L, w, (size_t)n, &M));
        check("rotations about one axis: the weighted mean angle",
              motion_dist(M, ga_rotor_rotation(axis, am / wsum)), tol);
    }
    /* statuses */
    ga_rotor out = ga_rotor_identity(),
             two[2] = {ga_rotor_identity(), ga_rotor_rotation((ga_vec3){0, 0, 1}, 1)};
    check_status("n = 0: GA_ERR_ARG", ga_rotor_mean(two, (double[]){1, 1}, 0, &out), GA_ERR_ARG);
    check_status("a negative weight: GA_ERR_ARG", ga_rotor_mean(two, (double[]){1, -1}, 2, &out), GA_ERR_ARG);
    check_status("weights all 0: GA_ERR_ARG", ga_rotor_mean(two, (double[]){0, 0}, 2, &out), GA_ERR_ARG);
    check_status("weights overflowing: GA_ERR_ARG", ga_rotor_mean(two, (double[]){DBL_MAX, DBL_MAX}, 2, &out),
                 GA_ERR_ARG);
    check_status("a NaN weight: GA_ERR_NOTFINITE", ga_rotor_mean(two, (double[]){1, NAN}, 2, &out),
                 GA_ERR_NOTFINITE);
    two[1].e12 = NAN;
    check_status("a NaN rotor: GA_ERR_NOTFINITE", ga_rotor_mean(two, (double[]){1, 1}, 2, &out),
                 GA_ERR_NOTFINITE);
    two[1] = ga_rotor_identity();
    two[1].s = 1.1; /* 0.21 off the group */
    check_status("a rotor off the group: GA_ERR_NOTRIGID", ga_rotor_mean(two, (double[]){1, 1}, 2, &out),
                 GA_ERR_NOTRIGID);
    check_bool("refused: output untouched", motion_dist(out, ga_rotor_identity()) == 0);
    /* a zero weight leaves its rotor out, even one off the group */
    TK_OK(ga_rotor_mean(two, (double[]){1, 0}, 2, &out));
    check("a zero weight leaves its rotor out", motion_dist(out, ga_rotor_identity()), 0);
    tk_end_named();
}

/* ---- fits ---------------------------------------------------------------------------------- */

static ga_vec3 add3(ga_vec3 a, ga_vec3 b) { return (ga_vec3){a.x + b.x, a.y + b.y, a.z + b.z}; }
static ga_vec3 sub3(ga_vec3 a, ga_vec3 b) { return (ga_vec3){a.x - b.x, a.y - b.y, a.z - b.z}; }
static double dist3(ga_vec3 a, ga_vec3 b) { return tk_norm(sub3(a, b)); }
static ga_vec3 cross3(ga_vec3 a, ga_vec3 b)
{
    return (ga_vec3){a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
/* a unit vector orthogonal to the unit vector u */
static ga_vec3 ortho(ga_vec3 u)
{
    ga_vec3 a = fabs(u.x) < 0.6 ? (ga_vec3){1, 0, 0} : (ga_vec3){0, 1, 0};
    ga_vec3 c = cross3(u, a);
    return tk_scale(c, 1 / tk_norm(c));
}
/* u up to sign: the distance of the two directions */
static double dir_dist(ga_vec3 u, ga_vec3 v) { return fmin(dist3(u, v), tk_norm(add3(u, v))); }

static void section_fits(void)
{
    enum { NP = 64 };
    ga_vec3 p[NP];
    /* exact data: points on the object, rounded to doubles. Each point is
       known to u |x| only, and the fit is taken about the centroid in units
       of the points' spread r, so the object is recovered to a few times
       u |x| / r of r: centres and points to 64 u (D + r), radii and
       directions to 64 u (D + r) (/ r), D the distance from the origin */
    const double scales[] = {1, 1e3, 1e6};
    for (int t = 0; t < 3000; t++) {
        double D = scales[t % 3] * tk_range(&rng, 0.5, 1), r = tk_loguni(&rng, 1e-2, 1e2);
        ga_vec3 c = tk_scale(tk_unit(&rng), D), nrm = tk_unit(&rng), e1 = ortho(nrm), e2 = cross3(nrm, e1);
        int n = 4 + (int)(tk_next(&rng) % (NP - 4));
        double tol = 64 * U * (D + r);
        ga_vec3 oc, on;
        double orr, od;
        /* a sphere */
        for (int i = 0; i < n; i++) p[i] = add3(c, tk_scale(tk_unit(&rng), r));
        int st = ga_fit_sphere(p, (size_t)n, &oc, &orr);
        check_status("exact sphere: GA_OK", st, GA_OK);
        if (st == GA_OK) {
            check("exact sphere: centre, radius (to 64 u (D + r))", dist3(oc, c), tol);
            check("exact sphere: centre, radius (to 64 u (D + r))", fabs(orr - r), tol);
        }
        /* a circle */
        for (int i = 0; i < n; i++) {
            double a = tk_range(&rng, 0, 2 * TK_PI);
            p[i] = add3(c, add3(tk_scale(e1, r * cos(a)), tk_scale(e2, r * sin(a))));
        }
        st = ga_fit_circle(p, (size_t)n, &oc, &orr, &on);
        check_status("exact circle: GA_OK", st, GA_OK);
        if (st == GA_OK) {
            check("exact circle: centre, radius", dist3(oc, c), tol);
            check("exact circle: centre, radius", fabs(orr - r), tol);
            check("exact circle: normal (to 64 u (D + r) / r)", dir_dist(on, nrm), tol / r);
        }
        /* a plane through c with normal nrm, and a line through c along nrm */
        for (int i = 0; i < n; i++) {
            double a = tk_range(&rng, -r, r), b = tk_range(&rng, -r, r);
            p[i] = add3(c, add3(tk_scale(e1, a), tk_scale(e2, b)));
        }
        st = ga_fit_plane(p, (size_t)n, &on, &od);
        check_status("exact plane: GA_OK", st, GA_OK);
        if (st == GA_OK) {
            double dc = on.x * c.x + on.y * c.y + on.z * c.z;
            check("exact plane: normal (to 64 u (D + r) / r)", dir_dist(on, nrm), tol / r);
            check("exact plane: distance", fabs(od - dc), tol);
        }
        for (int i = 0; i < n; i++) p[i] = add3(c, tk_scale(nrm, tk_range(&rng, -r, r)));
        st = ga_fit_line(p, (size_t)n, &on, &oc);
        check_status("exact line: GA_OK", st, GA_OK);
        if (st == GA_OK) {
            ga_vec3 want = sub3(c, tk_scale(nrm, c.x * nrm.x + c.y * nrm.y + c.z * nrm.z));
            check("exact line: direction (to 64 u (D + r) / r)", dir_dist(on, nrm), tol / r);
            check("exact line: point nearest the origin", dist3(oc, want), tol * fmax(1, D / r));
        }
    }
    /* signs: the normals' and directions' largest component positive */
    ga_vec3 sq[4] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}}, nn, pt;
    double dd;
    TK_OK(ga_fit_plane(sq, 4, &nn, &dd));
    check("the square z = 0: normal (0, 0, 1), distance 0, exactly",
          fmax(dist3(nn, (ga_vec3){0, 0, 1}), fabs(dd)), 0);
    ga_vec3 ln[3] = {{5, 1, 2}, {3, 1, 2}, {4, 1, 2}};
    TK_OK(ga_fit_line(ln, 3, &nn, &pt));
    check("x = 3, 4, 5 at (y, z) = (1, 2): direction (1, 0, 0), point (0, 1, 2)",
          fmax(dist3(nn, (ga_vec3){1, 0, 0}), dist3(pt, (ga_vec3){0, 1, 2})), 4 * U);
    /* statuses: too few points, NaN, and where the answer is not unique */
    ga_vec3 o3 = {0, 0, 0}, oc = {7, 7, 7};
    double orr = 7;
    ga_vec3 cop[5] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {3, 2, 0}};       /* coplanar */
    ga_vec3 coc[5] = {{1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}, {0.6, 0.8, 0}}; /* cocircular */
    ga_vec3 col[4] = {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {-3, -3, -3}};               /* collinear */
    ga_vec3 same[4] = {{1, 2, 3}, {1, 2, 3}, {1, 2, 3}, {1, 2, 3}};
    ga_vec3 tet[4] = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}}; /* no direction of largest spread */
    ga_vec3 nan4[4] = {{0, 0, 0}, {1, 0, 0}, {0, NAN, 0}, {0, 0, 1}};
    check_status("too few points: GA_ERR_ARG", ga_fit_sphere(tet, 3, &oc, &orr), GA_ERR_ARG);
    check_status("too few points: GA_ERR_ARG", ga_fit_circle(tet, 2, &oc, &orr, &nn), GA_ERR_ARG);
    check_status("too few points: GA_ERR_ARG", ga_fit_plane(tet, 2, &nn, &orr), GA_ERR_ARG);
    check_status("too few points: GA_ERR_ARG", ga_fit_line(tet, 1, &nn, &oc), GA_ERR_ARG);
    check_status("NaN: GA_ERR_NOTFINITE", ga_fit_sphere(nan4, 4, &oc, &orr), GA_ERR_NOTFINITE);
    check_status("NaN: GA_ERR_NOTFINITE", ga_fit_line(nan4, 4, &nn, &oc), GA_ERR_NOTFINITE);
    check_status("sphere of coplanar points: GA_ERR_DOMAIN", ga_fit_sphere(cop, 5, &oc, &orr), GA_ERR_DOMAIN);
    check_status("sphere of cocircular points: GA_ERR_DOMAIN", ga_fit_sphere(coc, 5, &oc, &orr),
                 GA_ERR_DOMAIN);
    check_status("plane, circle, sphere of collinear points: GA_ERR_DOMAIN", ga_fit_plane(col, 4, &nn, &orr),
                 GA_ERR_DOMAIN);
    check_status("plane, circle, sphere of collinear points: GA_ERR_DOMAIN",
                 ga_fit_circle(col, 4, &oc, &orr, &nn), GA_ERR_DOMAIN);
    check_status("plane, circle, sphere of collinear points: GA_ERR_DOMAIN", ga_fit_sphere(col, 4, &oc, &orr),
                 GA_ERR_DOMAIN);
    check_status("coincident points: GA_ERR_DOMAIN", ga_fit_line(same, 4, &nn, &oc), GA_ERR_DOMAIN);
    check_status("coincident points: GA_ERR_DOMAIN", ga_fit_sphere(same, 4, &oc, &orr), GA_ERR_DOMAIN);
    check_status("line of a regular tetrahedron's corners: GA_ERR_DOMAIN", ga_fit_line(tet, 4, &nn, &oc),
                 GA_ERR_DOMAIN);
    check_bool("refused: outputs untouched", oc.x == 7 && orr == 7 && o3.x == 0);
    /* a circle of cocircular points, a sphere through a tetrahedron: exact */
    TK_OK(ga_fit_circle(coc, 5, &oc, &orr, &nn));
    check("the unit circle z = 0 from 5 of its points",
          fmax(fmax(dist3(oc, o3), fabs(orr - 1)), dist3(nn, (ga_vec3){0, 0, 1})), 8 * U);
    TK_OK(ga_fit_sphere(tet, 4, &oc, &orr));
    check("the sphere through a regular tetrahedron's corners", fmax(dist3(oc, o3), fabs(orr - sqrt(3))),
          8 * U);
    tk_end_named();
}

/* ---- the sections ---------------------------------------------------------------------- */

static const tk_section sections[] = {
    {"inverse", section_inverse, 0},   {"inverse_singular", section_inverse_singular, 0},
    {"products", section_products, 0}, {"projection", section_projection, 0},
    {"powers", section_powers, 0},     {"mean", section_mean, 0},
    {"fits", section_fits, 0},
};

int main(int argc, char **argv) { return tk_main(argc, argv, "test_algebra", sections, TK_COUNT(sections)); }
