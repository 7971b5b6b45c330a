/* tests/ganja_dump.c: random multivectors and what garotor computes from
 * them, one case a line, for tests/ganja_check.js to recompute with ganja.js.
 *
 *   ganja_dump N SEED
 *
 * Each line: an operation name, then its inputs and garotor's result, 32
 * numbers each in canonical order (which is ganja.js's basis order for
 * Algebra(4,1) too), written with %.17g so that they read back exactly:
 *   gp a b r, op a b r, lc a b r, dot a b r       (binary products)
 *   reverse a r, involute a r, conjugate a r,
 *   dual a r, undual a r                           (unary)
 *   vee a b r                                      (ga_mv_regressive)
 *   inverse a r                                    (ga_mv_inverse)
 *   sandwich V X r                                 (ga_versor_apply: V a
 *                                                   product of 1 to 4 random
 *                                                   vectors, even or odd)
 * Coefficients uniform in [-1, 1]; every 4th multivector keeps a random
 * subset of its blades, so sparse inputs are in too.
 */
#include "testkit.h"

#include <stdlib.h>

static ga_mv random_mv(tk_rng *r, int sparse)
{
    ga_mv X = ga_mv_zero();
    for (int i = 0; i < 32; i++)
        if (!sparse || tk_uni(r) < 0.3)
            X.c[i] = tk_range(r, -1, 1);
    return X;
}

static void put(const char *op, const ga_mv *const *m, int n)
{
    fputs(op, stdout);
    for (int k = 0; k < n; k++)
        for (int i = 0; i < 32; i++) printf(" %.17g", m[k]->c[i]);
    putchar('\n');
}

int main(int argc, char **argv)
{
    long n = argc > 1 ? atol(argv[1]) : 1000;
    tk_rng r = {argc > 2 ? (uint64_t)atoll(argv[2]) : 14};
    for (long k = 0; k < n; k++) {
        ga_mv a = random_mv(&r, k % 4 == 3), b = random_mv(&r, k % 4 == 2), x;
        x = ga_mv_gp(a, b);
        put("gp", (const ga_mv *[]){&a, &b, &x}, 3);
        x = ga_mv_op(a, b);
        put("op", (const ga_mv *[]){&a, &b, &x}, 3);
        x = ga_mv_lc(a, b);
        put("lc", (const ga_mv *[]){&a, &b, &x}, 3);
        x = ga_mv_dot(a, b);
        put("dot", (const ga_mv *[]){&a, &b, &x}, 3);
        x = ga_mv_reverse(a);
        put("reverse", (const ga_mv *[]){&a, &x}, 2);
        x = ga_mv_involute(a);
        put("involute", (const ga_mv *[]){&a, &x}, 2);
        x = ga_mv_conjugate(a);
        put("conjugate", (const ga_mv *[]){&a, &x}, 2);
        x = ga_mv_dual(a);
        put("dual", (const ga_mv *[]){&a, &x}, 2);
        x = ga_mv_undual(a);
        put("undual", (const ga_mv *[]){&a, &x}, 2);
        x = ga_mv_regressive(a, b);
        put("vee", (const ga_mv *[]){&a, &b, &x}, 3);
        /* the general inverse of a dense multivector (ganja.js inverts by
           the closed form of Hitzer and Sangwine too) */
        if (ga_mv_inverse(a, &x) != GA_OK) {
            fprintf(stderr, "ganja_dump: ga_mv_inverse refused a random multivector\n");
            return 1;
        }
        put("inverse", (const ga_mv *[]){&a, &x}, 2);
        /* a versor: the product of 1 to 4 random vectors, none near null
           (|v^2| >= 0.1, so that V has a well-conditioned inverse) */
        ga_mv V = ga_mv_scalar(1);
        int nv = 1 + (int)(tk_next(&r) % 4);
        for (int j = 0; j < nv; j++) {
            ga_mv v;
            do v = ga_mv_grade(random_mv(&r, 0), 1);
            while (fabs(ga_mv_sp(v, v)) < 0.1);
            V = ga_mv_gp(V, v);
        }
        if (ga_versor_apply(V, b, &x) != GA_OK) {
            fprintf(stderr, "ganja_dump: ga_versor_apply refused a product of %d vectors\n", nv);
            return 1;
        }
        put("sandwich", (const ga_mv *[]){&V, &b, &x}, 3);
    }
    return 0;
}
