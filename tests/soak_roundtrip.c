/* tests/soak_roundtrip.c: exp/l round trips by the ten million, per family.
 *
 *   soak_roundtrip FAMILY N [SEED]
 *
 * N random twists of one twist family of testkit.h (FAMILY is its index,
 * 0..TK_TWIST_FAMILIES-1), each taken through both round trips:
 *   exp(l(R)) = +-R, R = exp(B(xi)), error / max(1, |t|) (t: R's translation);
 *   l(exp(B)) = B, error / max(1, |v|), B the generator of the twist, for
 *   angles below pi (at pi either axis sign is right: the other generator of
 *   the same half turn is accepted too). Beyond a half turn (pi..3pi) B is not
 *   the principal log: there l(R) is checked to be principal, its angle |w|
 *   at most pi (to 4 EPS, the rounding of |w| itself).
 * The soak suite (meson.build) runs every twist family with N = 7.7e6, 1.0e8
 * round trips of each kind in all, one test per family so they run in
 * parallel. The tolerance is that of tests/test_rotor.c, derived there: exp
 * and l each take O(10) roundings of quantities of size 1 or |t|, 8 EPS.
 * Prints the worst error of each kind; exits nonzero if one is above the
 * tolerance or a log fails. */
#include <float.h>
#include <stdio.h>
#include <stdlib.h>

#include "testkit.h"

#define EPS DBL_EPSILON

static double gen_dist(ga_generator a, ga_generator b)
{
    const double *x = &a.e12, *y = &b.e12;
    double d = 0.0;
    for (int i = 0; i < 6; i++) d = tk_max(d, fabs(x[i] - y[i]));
    return d;
}

/* max |a - s b| over the 8 coefficients, s = +-1 the nearer sign */
static double rotor_dist_pm(ga_rotor a, ga_rotor b)
{
    const double *x = &a.s, *y = &b.s;
    double dp = 0.0, dm = 0.0;
    for (int i = 0; i < 8; i++) {
        dp = tk_max(dp, fabs(x[i] - y[i]));
        dm = tk_max(dm, fabs(x[i] + y[i]));
    }
    return fmin(dp, dm);
}

/* The other twist of a half turn: axis -u, v_par kept, v_perp negated. */
static ga_twist half_turn_other(ga_twist xi)
{
    double th = tk_norm(xi.w);
    ga_vec3 u = tk_scale(xi.w, 1.0 / th);
    double vp = u.x * xi.v.x + u.y * xi.v.y + u.z * xi.v.z;
    ga_vec3 par = tk_scale(u, vp);
    ga_vec3 perp = {xi.v.x - par.x, xi.v.y - par.y, xi.v.z - par.z};
    return (ga_twist){tk_scale(xi.w, -1), {par.x - perp.x, par.y - perp.y, par.z - perp.z}};
}

int main(int argc, char **argv)
{
    if (argc < 3) {
        fprintf(stderr, "usage: soak_roundtrip FAMILY N [SEED]\n");
        return 2;
    }
    int f = atoi(argv[1]);
    long n = atol(argv[2]);
    if (f < 0 || f >= TK_TWIST_FAMILIES || n < 1) {
        fprintf(stderr, "soak_roundtrip: FAMILY 0..%d, N >= 1\n", TK_TWIST_FAMILIES - 1);
        return 2;
    }
    tk_rng rng = {argc > 3 ? strtoull(argv[3], NULL, 0) : 0x5EED0000u + (uint64_t)f};
    tk_check el = tk_begin("exp(l(R)) = +-R, / max(1,|t|)", 8 * EPS);
    tk_check le = f == TK_BEYOND_PI ? tk_begin("l(exp(B)) principal: |w| - pi", 4 * EPS)
                                    : tk_begin("l(exp(B)) = B, / max(1,|v|)", 8 * EPS);
    long failed_logs = 0;
    for (long i = 0; i < n; i++) {
        ga_twist xi = tk_twist(&rng, f);
        ga_generator B = ga_twist_to_generator(xi), L;
        ga_rotor R = ga_rotor_exp(B);
        if (ga_rotor_log(R, &L) != GA_OK) {
            failed_logs++;
            tk_add(&el, INFINITY);
            continue;
        }
        ga_vec3 t = ga_rotor_to_translation(R);
        tk_add(&el, rotor_dist_pm(ga_rotor_exp(L), R) / fmax(1.0, tk_norm(t)));
        if (f == TK_BEYOND_PI) {
            tk_add(&le, tk_norm(ga_generator_to_twist(L).w) - TK_PI);
            continue;
        }
        double d = gen_dist(L, B);
        if (f == TK_ROT_PI)
            d = fmin(d, gen_dist(L, ga_twist_to_generator(half_turn_other(xi))));
        tk_add(&le, d / fmax(1.0, tk_norm(xi.v)));
    }
    printf("family %d: %s, %ld round trips\n", f, tk_family_name[f], n);
    tk_end(&el);
    tk_end(&le);
    tk_expect(failed_logs == 0, "every l(R) succeeded");
    printf("worst in EPS: exp(l(R)) %.2f, %s %.2f\n", el.worst / EPS,
           f == TK_BEYOND_PI ? "principal |w| - pi" : "l(exp(B))", le.worst / EPS);
    return tk_finish("soak_roundtrip");
}
