/* ga/internal/mat4.h (internal, not installed): what the 4x4 matrix files
 * (mat4.c, se3.c, expm.c, logm.c, schur.c) share: entry access, small
 * whole-matrix helpers, and the LU factorisation defined in mat4.c.
 * Prefix ga__mat4 (GA__M for the entry macro).
 */
#ifndef GA_INTERNAL_MAT4_H
#define GA_INTERNAL_MAT4_H

#include <garotor/types.h>
#include <math.h>
#include <string.h>

/* entry (i, j) of a ga_mat4 (row-major), an lvalue */
#define GA__M(a, i, j) ((a).m[4 * (i) + (j)])

/* No NaN or Inf in a. x - x is +0 for every finite x and NaN for NaN and
 * +-Inf, so the sum below is 0 exactly when all 16 entries are finite: one
 * test in place of sixteen, in four partial sums that can share vector lanes
 * (under -ffast-math this test, like isfinite() itself, cannot be relied on). */
static inline int ga__mat4_isfinite(const ga_mat4 *a)
{
    double z[4] = {0.0, 0.0, 0.0, 0.0};
    for (int i = 0; i < 16; i += 4)
        for (int j = 0; j < 4; j++) z[j] += a->m[i + j] - a->m[i + j];
    return (z[0] + z[1]) + (z[2] + z[3]) == 0.0;
}

static inline ga_mat4 ga__mat4_zero(void)
{
    ga_mat4 z;
    memset(&z, 0, sizeof z);
    return z;
}

/* y += c x */
static inline void ga__mat4_acc(ga_mat4 *y, double c, const ga_mat4 *x)
{
    for (int i = 0; i < 16; i++) y->m[i] += c * x->m[i];
}

/* a + c I */
static inline ga_mat4 ga__mat4_add_id(ga_mat4 a, double c)
{
    for (int i = 0; i < 4; i++) GA__M(a, i, i) += c;
    return a;
}

/* a *= 2^e. For |e| <= 1000 the power is a normal double and the product
 * rounds exactly as ldexp does, without a call per entry. */
static inline void ga__mat4_scale2(ga_mat4 *a, int e)
{
    if (e == 0)
        return;
    if (e >= -1000 && e <= 1000) {
        double f = ldexp(1.0, e);
        for (int i = 0; i < 16; i++) a->m[i] *= f;
    } else {
        for (int i = 0; i < 16; i++) a->m[i] = ldexp(a->m[i], e);
    }
}

/* LU with partial pivoting (mat4.c): P A^ = L U with A^ = Dr A Dc: L (unit
 * lower) below the diagonal of lu, U on and above it; piv[k] is the row
 * swapped with row k at step k; re, ce hold the exponents of the
 * power-of-2 (exact) scalings Dr, Dc. Used by the inverse, the Pade solve of
 * expm, and the roots and Pade solves of logm. */
typedef struct {
    ga_mat4 lu;
    int piv[4], re[4], ce[4];
} ga__mat4_lu;

/* The factors of A; GA_ERR_SINGULAR if A is numerically singular (a pivot
 * test, A as given and then equilibrated). A must be finite. */
int ga__mat4_lu_factor(ga_mat4 a, ga__mat4_lu *f);
/* A^{-1} b from the factors of A */
ga_mat4 ga__mat4_lu_solve(const ga__mat4_lu *f, ga_mat4 b);

#endif
