/* garotor/mv_algebra.c: the inverse of any invertible multivector of G(4,1),
 * and the projection and rejection of a blade onto a blade (the regressive
 * and commutator products: ga/mv_kernels.c).
 *
 * The general inverse is the closed form of Hitzer and Sangwine for algebras
 * of five dimensions ("Multivector and multivector matrix inverses in real
 * Clifford algebras", Appl. Math. Comput. 311, 2017): with m^ the grade
 * involution, ~m the reverse and m- the Clifford conjugate,
 *
 *     B = m m- m^ ~m     (grades 0, 1 and 4 only),
 *     C = B with its grades 1 and 4 negated,
 *     d = B C            (a scalar),
 *     m^-1 = m- m^ ~m C / d.
 *
 * Since m^ ~m is the grade involution of P = m m-, B = P P^ and the
 * numerator is m- P^ C: four products. tests/algebra_check.py checks the
 * identity in exact rational arithmetic.
 *
 * ga_mv_inverse takes ~m / (m ~m) where m ~m is a scalar to its rounding
 * (versors and blades, as before), this closed form where its d is well
 * above its rounding, Gaussian elimination otherwise (near a zero divisor),
 * and then Newton steps to a residual at the rounding of a; mv.h states the
 * criteria.
 */
#include <garotor/mv.h>

#include "internal/mv_kernels.h"
#include "internal/object.h"
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#define U DBL_EPSILON

/* Multiply the grade-k part by sign[k]. */
static ga_mv grade_signs(ga_mv a, const double sign[6])
{
    for (int i = 0; i < 32; i++) a.c[i] *= sign[ga_blade_grade(i)];
    return a;
}

/* a 2^k, coefficient by coefficient (exact unless it under- or overflows).
   Where 2^k is a normal double, the product a_i 2^k is the correctly rounded
   a_i 2^k, which is what ldexp gives: the same bits, without 32 calls. */
static ga_mv mv_ldexp(ga_mv a, int k)
{
    if (k >= -1022 && k <= 1023) {
        double p = ldexp(1.0, k);
        for (int i = 0; i < 32; i++) a.c[i] *= p;
        return a;
    }
    for (int i = 0; i < 32; i++) a.c[i] = ldexp(a.c[i], k);
    return a;
}

/* sum_k |a_k| |b_k| */
static double abs_dot(ga_mv a, ga_mv b)
{
    double s = 0.0;
    for (int i = 0; i < 32; i++) s += fabs(a.c[i]) * fabs(b.c[i]);
    return s;
}

/* The right inverse r, a r = 1, by Gaussian elimination with partial
   pivoting on the 32 x 32 matrix of x -> a x (column j: a e_j), for a near
   a zero divisor, where d of the closed form is lost to rounding (d is of
   degree 8 in a: it goes as the eighth power of the distance from the zero
   divisors, the matrix's smallest singular values only as the first).
   0 where a pivot is at most 32 u |a|_max: a is within that of a singular
   multivector. */
static int solve_lu(ga_mv a, ga_mv *out)
{
    double m[32][33];
    for (int j = 0; j < 32; j++) {
        ga_mv col = ga_mv_gp(a, ga_mv_blade(j));
        for (int i = 0; i < 32; i++) m[i][j] = col.c[i];
    }
    for (int i = 0; i < 32; i++) m[i][32] = i == 0;
    double tiny = 32 * U * ga_mv_maxabs(a);
    for (int k = 0; k < 32; k++) {
        int p = k;
        for (int i = k + 1; i < 32; i++)
            if (fabs(m[i][k]) > fabs(m[p][k]))
                p = i;
        if (!(fabs(m[p][k]) > tiny))
            return 0;
        if (p != k)
            for (int j = k; j < 33; j++) {
                double t = m[k][j];
                m[k][j] = m[p][j];
                m[p][j] = t;
            }
        for (int i = k + 1; i < 32; i++) {
            double f = m[i][k] / m[k][k];
            if (f == 0.0)
                continue;
            for (int j = k + 1; j < 33; j++) m[i][j] -= f * m[k][j];
        }
    }
    for (int k = 31; k >= 0; k--) {
        double t = m[k][32];
        for (int j = k + 1; j < 32; j++) t -= m[k][j] * out->c[j];
        out->c[k] = t / m[k][k];
    }
    return 1;
}

/* 1 - a r */
static ga_mv residual(ga_mv a, ga_mv r)
{
    ga_mv res = ga_mv_scale(ga_mv_gp(a, r), -1.0);
    res.c[GA_BLADE_SCALAR] += 1.0;
    return res;
}

/* The closed form of the top of this file for a, its largest coefficient in
   [1/2, 1), then Newton steps r + r (1 - a r) until the residual 1 - a r is
   at most u |a|_1 |r|_1 (three at most).

   Beside d, a first-order bound dd of its error: what the rounding of a
   (u |a_i| each) and of the products can make of it. A product x y of
   coefficients known to dx, dy is known to |x| dy + dx |y| + gamma_32 |x| |y|
   (gao_abs_gp of internal/object.h: the product with every sign +;
   gamma_32 < 33 u), so
       dP = 2 u |a||a| + 33 u |a||a|,
       dB = 2 |P| dP + 33 u |P||P|,
       dd = 2 sum_k |B_k| dB_k + 33 u sum_k B_k^2
   (C has B's coefficients up to sign). Taken with the computed |P| and |B|,
   it follows the cancellation in them: for a near a blade, P is near the
   scalar a ~a, not near |a|^2. */
static ga_status general_inverse(ga_mv a, ga_mv *out)
{
    static const double neg14[6] = {1, -1, 1, 1, -1, 1};
    ga_mv abar = ga_mv_conjugate(a);
    ga_mv P = ga_mv_gp(a, abar);
    ga_mv Ph = ga_mv_involute(P);
    ga_mv B = ga_mv_gp(P, Ph);
    ga_mv C = grade_signs(B, neg14);
    double d = ga_mv_sp(B, C);
    ga_mv Pa = gao_abs(P), dP = ga_mv_scale(gao_abs_gp(a, a), 35 * U);
    ga_mv dB = ga_mv_add(ga_mv_scale(gao_abs_gp(Pa, dP), 2.0), ga_mv_scale(gao_abs_gp(Pa, Pa), 33 * U));
    double dd = 2.0 * abs_dot(B, dB) + 33 * U * abs_dot(B, B);
    ga_mv r;
    if (fabs(d) > GA_MV_INVERSE_TOL * dd)
        r = ga_mv_scale(ga_mv_gp(abar, ga_mv_gp(Ph, C)), 1.0 / d);
    else if (!solve_lu(a, &r))
        return GA_ERR_SINGULAR;
    double na = 0.0;
    for (int i = 0; i < 32; i++) na += fabs(a.c[i]);
    ga_mv res = residual(a, r);
    for (int step = 0; step < 3; step++) {
        r = ga_mv_add(r, ga_mv_gp(r, res));
        res = residual(a, r);
        double nr = 0.0;
        for (int i = 0; i < 32; i++) nr += fabs(r.c[i]);
        if (ga_mv_maxabs(res) <= U * na * nr) {
            *out = r;
            return GA_OK;
        }
    }
    return GA_ERR_SINGULAR; /* the inverse is not found to the rounding of a */
}

/* ga_mv_inverse of a finite a of one parity (its grades within the mask g),
   its steps on arrays, fused: the same operations on each coefficient, in
   the same order (so the same bits), without copying 256-byte values from
   call to call. Where a ~a is not a scalar to its rounding, or 2^-e is not a
   normal double, ga_mv_inverse itself.
   Three shortcuts keep those bits:
   - sbar sums the squares of a's parity alone: the others are +0, and
     adding +0 leaves a sum of squares as it is;
   - of a ~a only the scalar and grade 4 are formed: a ~a is its own reverse,
     so its grades 2 and 3 are 0 but for rounding, and a ~a of one parity has
     no odd grade. That rounding is below the tolerance: each coefficient
     sums 16 products +-as_i as_j, j running over a permutation of i, so
     sum |as_i as_j| <= sbar (Cauchy-Schwarz) and the error is at most
     ~16 u sbar, against GA_MV_INVERSE_TOL U sbar = 128 u sbar: leaving grade 2
     out of the test never changes its outcome;
   - frexp of a normal amax and 2^-e are read and made from the bits. */
ga_status gak_inverse_one_parity(const ga_mv *a, unsigned g, ga_mv *out)
{
    double amax = gak_maxabs(a->c);
    int e = 0;
    if (amax >= DBL_MIN) {
        uint64_t bits;
        memcpy(&bits, &amax, sizeof bits);
        e = (int)(bits >> 52) - 1022; /* amax = m 2^e, m in [1/2, 1) */
    } else if (amax > 0.0) {
        frexp(amax, &e);
    }
    if (e < -1023 || e > 1022)
        return ga_mv_inverse(*a, out);
    uint64_t pbits = (uint64_t)(1023 - e) << 52; /* 2^-e, -e in [-1022, 1023]: normal */
    double p, sbar = 0.0;
    memcpy(&p, &pbits, sizeof p);
    /* ga_mv_reverse's sign of each blade: grades 0, 1 +, 2, 3 -, 4, 5 + */
    static const double rev_sign[32] = {1,  1,  1,  1,  1,  1,  -1, -1, -1, -1, -1, -1, -1, -1, -1, -1,
                                        -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, 1,  1,  1,  1,  1,  1};
    /* the blades of each parity, in the canonical order */
    static const unsigned char parity_blades[2][16] = {
        {0, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 26, 27, 28, 29, 30},
        {1, 2, 3, 4, 5, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 31}};
    int odd = (g & 0x2au) != 0;
    ga_mv as, rev;
    for (int i = 0; i < 32; i++) {
        as.c[i] = a->c[i] * p;
        rev.c[i] = as.c[i] * rev_sign[i];
    }
    for (int j = 0; j < 16; j++) {
        double x = as.c[parity_blades[odd][j]];
        sbar += x * x;
    }
    double aa[32];
    gak_gp_same_parity_g04(as.c, rev.c, odd, aa);
    double s = aa[GA_BLADE_SCALAR], a4 = 0.0;
    for (int i = 26; i < 31; i++) a4 = fabs(aa[i]) > a4 ? fabs(aa[i]) : a4;
    if (!(a4 <= GA_MV_INVERSE_TOL * U * sbar))
        return ga_mv_inverse(*a, out);
    if (!(fabs(s) > GA_MV_INVERSE_TOL * U * sbar))
        return GA_ERR_SINGULAR;
    double k = 1.0 / s;
    ga_mv r;
    for (int i = 0; i < 32; i++) r.c[i] = rev.c[i] * k * p;
    if (!gak_isfinite(r.c))
        return GA_ERR_SINGULAR;
    *out = r;
    return GA_OK;
}

ga_status ga_mv_inverse(ga_mv a, ga_mv *out)
{
    if (!out)
        return GA_ERR_ARG;
    if (!ga_mv_isfinite(a))
        return GA_ERR_NOTFINITE;
    /* work on a 2^-e (exact), its largest coefficient in [1/2, 1): a ~a of a
       tiny or huge a underflowed or overflowed, and 1/s became Inf with GA_OK
       (found by fuzz/fuzz_numeric; fuzz/regress/numeric/mv-inverse-underflow
       replays it). (a 2^-e)^-1 = a^-1 2^e. */
    int e = 0;
    double amax = ga_mv_maxabs(a);
    if (amax > 0.0)
        frexp(amax, &e);
    a = mv_ldexp(a, -e);
    /* a versor or a blade: a ~a is a scalar s, and a^-1 = ~a / s. Every
       coefficient of a ~a sums 32 products whose sizes add up to at most
       sbar = sum a_i^2 (Cauchy-Schwarz), so its rounding, and what a few
       ulps of noise in a make of it, are a small multiple of u sbar. (sbar,
       a chain of 32 additions, first: it runs beside the product.) */
    double sbar = 0.0;
    for (int i = 0; i < 32; i++) sbar += a.c[i] * a.c[i];
    ga_mv rev = ga_mv_reverse(a);
    ga_mv aa; /* ga_mv_gp(a, rev), by the sparse kernels where a has one parity */
    gak_gp(a.c, rev.c, aa.c);
    double s = aa.c[GA_BLADE_SCALAR];
    aa.c[GA_BLADE_SCALAR] = 0.0;
    ga_mv r;
    ga_status st;
    if (ga_mv_maxabs(aa) <= GA_MV_INVERSE_TOL * U * sbar) {
        if (!(fabs(s) > GA_MV_INVERSE_TOL * U * sbar))
            return GA_ERR_SINGULAR;
        r = ga_mv_scale(rev, 1.0 / s);
    } else if ((st = general_inverse(a, &r)) != GA_OK) {
        return st;
    }
    r = mv_ldexp(r, -e);
    if (!ga_mv_isfinite(r))
        return GA_ERR_SINGULAR; /* the inverse overflows, as ga_mat4_inverse */
    *out = r;
    return GA_OK;
}

/* ---- projection and rejection ------------------------------------------------- */

/* The right contraction x |_ y = (~y _| ~x)~ */
static ga_mv rc(ga_mv x, ga_mv y) { return ga_mv_reverse(ga_mv_lc(ga_mv_reverse(y), ga_mv_reverse(x))); }

/* (A _| B) _| B^-1 (project) or (A ^ B) |_ B^-1 (reject) */
static ga_status project_reject(ga_mv A, ga_mv B, int reject, ga_mv *out)
{
    if (!out)
        return GA_ERR_ARG;
    if (!ga_mv_isfinite(A) || !ga_mv_isfinite(B))
        return GA_ERR_NOTFINITE;
    ga_mv Bi;
    ga_status st = ga_mv_inverse(B, &Bi);
    if (st != GA_OK)
        return st;
    ga_mv r = reject ? rc(ga_mv_op(A, B), Bi) : ga_mv_lc(ga_mv_lc(A, B), Bi);
    if (!ga_mv_isfinite(r))
        return GA_ERR_DOMAIN;
    *out = r;
    return GA_OK;
}

ga_status ga_mv_project(ga_mv A, ga_mv B, ga_mv *out) { return project_reject(A, B, 0, out); }

ga_status ga_mv_reject(ga_mv A, ga_mv B, ga_mv *out) { return project_reject(A, B, 1, out); }
