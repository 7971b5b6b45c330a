/* ga/mv_kernels.c: the products of G(4,1) besides gp, op and lc (ga/mv.c),
 * and the sparse kernels of the geometric product, all written out term by
 * term by gen/generate.py (ga/mv_kernels.inc, section 13 of the script):
 *
 *   - ga_mv_sp, ga_mv_ip and the straight-line fat dot: every term summed in
 *     the order of the blade loop they replace (a's blade, then b's), so
 *     their numbers are the loop's (but the sign of a zero result: the sums
 *     start at their first term, not at +0.0); ga_mv_dot itself is the same
 *     sums in vectors (ga/mv.c);
 *   - ga_mv_regressive: the outer product of the duals, undualled, in the
 *     order of ga_mv_op's loop on the duals (the dual and the undual only
 *     move and negate coefficients): the numbers of undual(op(dual a,
 *     dual b)), but the sign of a zero;
 *   - ga_mv_commutator: the anticommuting blade pairs only, each once
 *     ((e_i e_j - e_j e_i) / 2 is e_i e_j or 0): half the terms of
 *     (a b - b a) / 2 and one rounding per term, so not the numbers of that
 *     difference (within its rounding; tests/test_products.c);
 *   - the sparse kernels: a of one parity (its even or its odd blades) times
 *     b of one grade or one parity, and a vector times a vector. A kernel
 *     leaves out the terms with a coefficient that is zero by its grades and
 *     sums the others in ga_mv_gp's order, so for finite inputs it gives
 *     ga_mv_gp's numbers, bit for bit, but the sign of a zero.
 */
#include <garotor/mv.h>

#include "internal/mv_kernels.h"

#include <string.h>

#include "mv_kernels.inc"

/* the grade of each blade index (canonical order) */
static const unsigned char grade_of[32] = {0, 1, 1, 1, 1, 1, 2, 2, 2, 2, 2, 2, 2, 2, 2, 2,
                                           3, 3, 3, 3, 3, 3, 3, 3, 3, 3, 4, 4, 4, 4, 4, 5};

#define EVEN_GRADES 0x15u /* grades 0, 2, 4 */
#define ODD_GRADES 0x2au  /* grades 1, 3, 5 */

typedef void (*kernel_fn)(const double *restrict, const double *restrict, double *restrict);

/* [parity of a][grade of b] and [parity of a][parity of b] */
static const kernel_fn gp_pg[2][6] = {
    {mv_gp_eg0, mv_gp_eg1, mv_gp_eg2, mv_gp_eg3, mv_gp_eg4, mv_gp_eg5},
    {mv_gp_og0, mv_gp_og1, mv_gp_og2, mv_gp_og3, mv_gp_og4, mv_gp_og5},
};
static const kernel_fn gp_pp[2][2] = {{mv_gp_ee, mv_gp_eo}, {mv_gp_oe, mv_gp_oo}};

/* the bits of x[i] but the sign: 0 exactly for +-0 (a NaN is not 0) */
static inline unsigned long long magnitude_bits(const double *x, int i)
{
    unsigned long long b;
    memcpy(&b, x + i, sizeof b);
    return b << 1;
}

unsigned gak_grades(const double *x)
{
    /* the blades of each grade are consecutive in the canonical order:
       0 | 1..5 | 6..15 | 16..25 | 26..30 | 31 */
    unsigned long long o1 = 0, o2 = 0, o3 = 0, o4 = 0;
    for (int i = 1; i < 6; i++) o1 |= magnitude_bits(x, i);
    for (int i = 6; i < 16; i++) o2 |= magnitude_bits(x, i);
    for (int i = 16; i < 26; i++) o3 |= magnitude_bits(x, i);
    for (int i = 26; i < 31; i++) o4 |= magnitude_bits(x, i);
    return (unsigned)(magnitude_bits(x, 0) != 0) | (unsigned)(o1 != 0) << 1 | (unsigned)(o2 != 0) << 2 |
           (unsigned)(o3 != 0) << 3 | (unsigned)(o4 != 0) << 4 | (unsigned)(magnitude_bits(x, 31) != 0) << 5;
}

/* 0 even (or zero), 1 odd, -1 both */
static int parity(unsigned g)
{
    if (!(g & ODD_GRADES))
        return 0;
    return (g & EVEN_GRADES) ? -1 : 1;
}

/* r's blades of parity p from t0, the others from t1 */
static void merge(const double *t0, const double *t1, int p, double *r)
{
    for (int i = 0; i < 32; i++) r[i] = (grade_of[i] & 1u) == (unsigned)p ? t0[i] : t1[i];
}

void gak_gp(const double *a, const double *b, double *r) { gak_gp_g(a, gak_grades(a), b, gak_grades(b), r); }

void gak_gp_g(const double *a, unsigned ga, const double *b, unsigned gb, double *r)
{
    int pa = parity(ga), pb = parity(gb);
    double t0[32], t1[32];
    if (pa >= 0) {
        /* b of one small grade (0, 1, 4, 5: at most 80 terms): its kernel;
           else the half of ga_mv_gp's vectors that a's parity has */
        if ((gb == 1u || gb == 2u || gb == 16u || gb == 32u))
            gp_pg[pa][__builtin_ctz(gb)](a, b, r);
        else if (pa == 0)
            gak_gp_even(a, b, r);
        else
            gak_gp_odd(a, b, r);
    } else if (pb >= 0) {
        /* a's even blades give the blades of b's parity, its odd ones the others */
        gp_pp[0][pb](a, b, t0);
        gp_pp[1][pb](a, b, t1);
        merge(t0, t1, pb, r);
    } else {
        ga_mv x, y, z;
        for (int i = 0; i < 32; i++) x.c[i] = a[i], y.c[i] = b[i];
        z = ga_mv_gp(x, y);
        for (int i = 0; i < 32; i++) r[i] = z.c[i];
    }
}

/* ---- the public products ------------------------------------------------ */

double ga_mv_sp(ga_mv a, ga_mv b) { return mv_sp_dense(a.c, b.c); }

#define PRODUCT(name, kernel)                                                                                \
    ga_mv name(ga_mv a, ga_mv b)                                                                             \
    {                                                                                                        \
        ga_mv r;                                                                                             \
        kernel(a.c, b.c, r.c);                                                                               \
        return r;                                                                                            \
    }

PRODUCT(ga_mv_ip, mv_ip_dense)
PRODUCT(ga_mv_regressive, mv_regressive_dense)
PRODUCT(ga_mv_commutator, mv_commutator_dense)
PRODUCT(ga_mv_gp_even_vector, mv_gp_eg1)
PRODUCT(ga_mv_gp_vector_vector, mv_gp_g1g1)
PRODUCT(ga_mv_gp_even_even, mv_gp_ee)

ga_status ga_mv_gp_even_vector_sparse(const double *even, const double *vec, double *odd)
{
    if (!even || !vec || !odd)
        return GA_ERR_ARG;
    double o[16]; /* odd may overlap even or vec: read both before writing */
    mv_gp_eg1_sparse(even, vec, o);
    memcpy(odd, o, sizeof o);
    return GA_OK;
}

void gak_gp_same_parity_g04(const double *a, const double *b, int odd, double *r)
{
    if (odd)
        mv_gp_oo_g04(a, b, r);
    else
        mv_gp_ee_g04(a, b, r);
}

void gak_dot_p(const ga_mv *a, const ga_mv *b, ga_mv *r) { gak_dot_blocks(a->c, b->c, r->c); }
void gak_dot_dense(const double *a, const double *b, double *r) { mv_dot_dense(a, b, r); }
void gak_gp_even_vector_p(const ga_mv *a, const ga_mv *b, ga_mv *r) { mv_gp_eg1(a->c, b->c, r->c); }
