/* ga/internal/mv_kernels.h (internal, not installed): the geometric product
 * by the sparse kernels of ga/mv_kernels.c (generated into ga/mv_kernels.inc),
 * for mv_algebra.c's inverse and versor.c's sandwich. Prefix gak_.
 */
#ifndef GA_INTERNAL_MV_KERNELS_H
#define GA_INTERNAL_MV_KERNELS_H

#include <garotor/mv.h>
#include <math.h>

/* ga_mv_isfinite and ga_mv_maxabs of the 32 coefficients x[0..31], inline
   (ga/mv.c's exported ones call these): x - x is +0 for every finite x and
   NaN for NaN and +-Inf, so the sum is 0 exactly when all 32 are finite (one
   test, in partial sums that share vector lanes, as ga__mat4_isfinite). */
static inline int gak_isfinite(const double *x)
{
    double z[4] = {0.0, 0.0, 0.0, 0.0};
    for (int i = 0; i < 32; i += 4)
        for (int j = 0; j < 4; j++) z[j] += x[i + j] - x[i + j];
    return (z[0] + z[1]) + (z[2] + z[3]) == 0.0;
}
static inline double gak_maxabs(const double *x)
{
    /* v > m ? v : m is fmax(m, v) for m never NaN: a NaN v is passed over;
       four running maxima (in vectors, no chain of 32), then theirs */
    double m[4] = {0.0, 0.0, 0.0, 0.0};
    for (int i = 0; i < 32; i += 4)
        for (int j = 0; j < 4; j++) {
            double v = fabs(x[i + j]);
            m[j] = v > m[j] ? v : m[j];
        }
    double p = m[0] > m[1] ? m[0] : m[1], q = m[2] > m[3] ? m[2] : m[3];
    return p > q ? p : q;
}

/* The grades of x that have a coefficient other than 0 (a NaN counts): bit k
   for grade k. */
unsigned gak_grades(const double *x);

/* r = a b (32 coefficients each; r may not be a or b), with the kernels of
   the grades a and b have: a of one parity times b of one grade or one
   parity, or the converse; the dense product where both have both
   parities. The terms a kernel leaves out are products with a zero
   coefficient, and each component sums the others in ga_mv_gp's order, so
   for finite a and b the result is ga_mv_gp's, bit for bit, but the sign of
   a zero. */
void gak_gp(const double *a, const double *b, double *r);
/* The same with the grades of a and b given (ga, gb as gak_grades gives
   them, or any masks with more grades: a kernel is picked for those). */
void gak_gp_g(const double *a, unsigned ga, const double *b, unsigned gb, double *r);

/* r[0] and r[26..30]: the scalar and grade-4 coefficients of a b, a and b
   both even (odd = 0) or both odd (odd = 1), their other blades not read;
   ga_mv_gp's numbers for them (but the sign of a zero). r's other
   coefficients are not written. */
void gak_gp_same_parity_g04(const double *a, const double *b, int odd, double *r);

/* ga_mv_inverse(*a, out) for a finite a whose grades are within g, and of
   one parity (ga/mv_algebra.c): the same statuses and bits, faster. */
ga_status gak_inverse_one_parity(const ga_mv *a, unsigned g, ga_mv *out);

typedef void (*gak_kernel_fn)(const double *, const double *, double *);

/* In vectors where gcc has them (ga/mv.c, the width picked at load time as
   ga_mv_gp's): the fat dot (ga_mv_dot), and the geometric product for a of
   one parity (its other blades not read: they must be 0), the terms of a's
   even (odd) blades in ga_mv_gp's order. r not a or b. Elsewhere the
   straight-line dot and the dense product. */
void gak_dot_blocks(const double *a, const double *b, double *r);
void gak_gp_even(const double *a, const double *b, double *r);
void gak_gp_odd(const double *a, const double *b, double *r);
/* the straight-line fat dot (ga/mv_kernels.c) */
void gak_dot_dense(const double *a, const double *b, double *r);

/* The products by pointer, r = a b (r not a or b): ga_mv_gp, ga_mv_op,
   ga_mv_lc (ga/mv.c), ga_mv_dot and ga_mv_gp_even_vector (ga/mv_kernels.c),
   the same numbers.
   Not exported: garotor-bench links them to time the by-value ABI against
   pointers (docs/benchmarks.md, "By value or by pointer"). */
void gak_gp_p(const ga_mv *a, const ga_mv *b, ga_mv *r);
void gak_op_p(const ga_mv *a, const ga_mv *b, ga_mv *r);
void gak_lc_p(const ga_mv *a, const ga_mv *b, ga_mv *r);
void gak_dot_p(const ga_mv *a, const ga_mv *b, ga_mv *r);
void gak_gp_even_vector_p(const ga_mv *a, const ga_mv *b, ga_mv *r);

#endif
