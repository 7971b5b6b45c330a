/* garotor/mv.h: the full multivector of G(4,1), the reference algebra.
 *
 * G(4,1) has basis vectors e1, e2, e3, e4 squaring to +1 and e5 squaring to -1
 * (Wareham-Lasenby §2.2: e4 = e, e5 = ebar). A multivector holds 32 doubles in
 * the canonical order of docs/conventions.md: grade first, then lexicographic,
 *
 *   1; e1 e2 e3 e4 e5; e12 e13 e14 e15 e23 e24 e25 e34 e35 e45;
 *   e123 e124 e125 e134 e135 e145 e234 e235 e245 e345;
 *   e1234 e1235 e1245 e1345 e2345; e12345
 *
 * The products here follow the definition blade by blade (a blade is a set of
 * basis vectors; the sign of a product is the parity of the swaps that sort
 * it, times -1 for e5*e5), written out term by term by gen/generate.py and
 * summed in the order of the blade loop. They are the reference that the
 * compact rotor (rotor.h) is checked against. Also here: exp, log and the
 * split of any bivector and rotor of G(4,1) (Dorst-Valkenburg 2011).
 *
 * Accuracies are stated in units of u = DBL_EPSILON = 2^-52, relative to the
 * size named (|B|: the largest coefficient of B).
 */
#ifndef GAROTOR_MV_H
#define GAROTOR_MV_H

#include "types.h"

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/** A multivector of G(4,1): c[i] is the coefficient of the i-th blade in canonical order. */
typedef struct {
    double c[32];
} ga_mv;

/** Index of each blade in ga_mv.c (canonical order). */
enum {
    /* clang-format off */
    GA_BLADE_SCALAR = 0,
    GA_BLADE_E1, GA_BLADE_E2, GA_BLADE_E3, GA_BLADE_E4, GA_BLADE_E5,
    GA_BLADE_E12, GA_BLADE_E13, GA_BLADE_E14, GA_BLADE_E15, GA_BLADE_E23,
    GA_BLADE_E24, GA_BLADE_E25, GA_BLADE_E34, GA_BLADE_E35, GA_BLADE_E45,
    GA_BLADE_E123, GA_BLADE_E124, GA_BLADE_E125, GA_BLADE_E134, GA_BLADE_E135,
    GA_BLADE_E145, GA_BLADE_E234, GA_BLADE_E235, GA_BLADE_E245, GA_BLADE_E345,
    GA_BLADE_E1234, GA_BLADE_E1235, GA_BLADE_E1245, GA_BLADE_E1345, GA_BLADE_E2345,
    GA_BLADE_E12345
    /* clang-format on */
};

/** The grade (0..5) of blade index i; -1 for i outside 0..31. */
GA_API int ga_blade_grade(int i);
/** The name of blade index i: "1", "e1", ..., "e12345"; "?" for i outside 0..31. */
GA_API const char *ga_blade_name(int i);
/** The basis vectors of blade index i as a bit mask (bit k-1 set for e_k); 0 for
 *  i outside 0..31. */
GA_API unsigned ga_blade_mask(int i);

/* ---- construction and linear operations ------------------------------
 * Exact where the operation is (construction), else one rounding per
 * coefficient (add, sub, scale); no status: NaN and Inf propagate. */
/** The multivector 0. */
GA_API ga_mv ga_mv_zero(void);
/** The scalar s (all other coefficients 0). */
GA_API ga_mv ga_mv_scalar(double s);
/** The basis blade with index i (coefficient 1); 0 for i outside 0..31. */
GA_API ga_mv ga_mv_blade(int i);
/** The vector x1 e1 + ... + x5 e5. */
GA_API ga_mv ga_mv_vector(double x1, double x2, double x3, double x4, double x5);
/** a + b, coefficient by coefficient. */
GA_API ga_mv ga_mv_add(ga_mv a, ga_mv b);
/** a - b, coefficient by coefficient. */
GA_API ga_mv ga_mv_sub(ga_mv a, ga_mv b);
/** s a, coefficient by coefficient. */
GA_API ga_mv ga_mv_scale(ga_mv a, double s);
/** 1 if every coefficient is finite, 0 otherwise. */
GA_API int ga_mv_isfinite(ga_mv a);
/** Largest absolute coefficient (the max norm, used for tolerances). */
GA_API double ga_mv_maxabs(ga_mv a);

/* ---- products ----------------------------------------------------------
 * Blade by blade from the definition (see the top of this header), each
 * coefficient summed in the order of the blade loop; no status: NaN and Inf
 * propagate. */
/** Geometric product a b. */
GA_API ga_mv ga_mv_gp(ga_mv a, ga_mv b);
/** Outer (wedge) product a ^ b. */
GA_API ga_mv ga_mv_op(ga_mv a, ga_mv b);
/** Left contraction a _| b: for blades, grade(b) - grade(a) part of a b when >= 0. */
GA_API ga_mv ga_mv_lc(ga_mv a, ga_mv b);
/** Scalar product <a b>_0. For vectors it is the inner product a.b. */
GA_API double ga_mv_sp(ga_mv a, ga_mv b);
/** The "fat dot" a . b = sum over grades r, s of <<a>_r <b>_s>_|r-s|, scalars
 *  included (2 . x = 2 x): the inner product of Dorst-Fontijne-Mann §B.1 and
 *  ganja.js's `|` (docs/conventions.md, "Inner products"). */
GA_API ga_mv ga_mv_dot(ga_mv a, ga_mv b);
/** Hestenes' inner product: the fat dot without the terms where r or s is 0
 *  (a scalar's inner product with anything is 0); clifford's (Python) `|`. */
GA_API ga_mv ga_mv_ip(ga_mv a, ga_mv b);

/* ---- sparse geometric products -------------------------------------------
 * The geometric product of the parts of a and b of the grades named (their
 * other coefficients are not read), computing only the terms those grades
 * have, each coefficient summed in ga_mv_gp's order: for finite inputs the
 * numbers of ga_mv_gp of those parts, bit for bit, but the sign of a zero
 * coefficient. No status (but the pointer form's, for its pointers). */
/** <a>_even <b>_1: a rotor (or any even multivector) times a vector (grades
 *  1, 3 and 5 of the result; the others are 0). */
GA_API ga_mv ga_mv_gp_even_vector(ga_mv a, ga_mv b);
/** The same product on the coefficients alone, no 32-component value passed
 *  or returned: even[16] are an even multivector's coefficients on the blades
 *  of even grade in the canonical order (indices 0, 6..15, 26..30 of a
 *  ga_mv), vec[5] a vector's (e1..e5), and odd[16] receives the product's
 *  coefficients on the blades of odd grade (indices 1..5, 16..25, 31): the
 *  numbers ga_mv_gp_even_vector gives there, bit for bit. odd may be the
 *  array even or vec (all read before any is written). GA_ERR_ARG where a
 *  pointer is NULL (nothing written); no other status: NaN and Inf
 *  propagate. */
GA_API GA_NODISCARD ga_status ga_mv_gp_even_vector_sparse(const double *even, const double *vec, double *odd);
/** <a>_1 <b>_1: a vector times a vector (grades 0 and 2). */
GA_API ga_mv ga_mv_gp_vector_vector(ga_mv a, ga_mv b);
/** <a>_even <b>_even: the product of two rotors of G(4,1) as full
 *  multivectors (grades 0, 2 and 4). */
GA_API ga_mv ga_mv_gp_even_even(ga_mv a, ga_mv b);

/* ---- involutions and grades ------------------------------------------- */
/** Reverse ~a: a grade-k part is multiplied by (-1)^(k(k-1)/2). */
GA_API ga_mv ga_mv_reverse(ga_mv a);
/** Grade involution: a grade-k part is multiplied by (-1)^k. */
GA_API ga_mv ga_mv_involute(ga_mv a);
/** Clifford conjugate: reverse of the grade involution. */
GA_API ga_mv ga_mv_conjugate(ga_mv a);
/** The grade-k part <a>_k (zero for k outside 0..5). */
GA_API ga_mv ga_mv_grade(ga_mv a, int k);

/* ---- dual ---------------------------------------------------------------- */
/** Dual a* = a I^-1 with I = e12345 (I^2 = -1, so I^-1 = -I). */
GA_API ga_mv ga_mv_dual(ga_mv a);
/** Undual a I, the inverse of ga_mv_dual. */
GA_API ga_mv ga_mv_undual(ga_mv a);

/* ---- text --------------------------------------------------------------- */
/** Bytes that ga_mv_format may need, with the terminating NUL: the longest
 *  text has 32 terms, each a number of 25 bytes (17 digits whose first is at
 *  the place 10^-7: "0.00000010000000000000001"), "-" before the first and
 *  " - " before the others, and the 31 names (111 bytes): 26 + 31 * 28 + 111 + 1. */
#define GA_MV_TEXT_MAX 1006
/** a as text, the nonzero terms in canonical order with the blade names of
 *  docs/conventions.md: "1 + 2e12 - 0.5e1234", "-e1 + 0.00001e2", "0" for
 *  zero. Coefficients are written as the shortest decimal that reads back as
 *  the same double (0.1, not 0.10000000000000001), in the tool's layout
 *  (docs/tool.md): positional when the leading digit is between the places
 *  10^20 and 10^-7, else d.ddde+XX with the exponent's sign and at least two
 *  digits (1e+21, 5e-324); +-1 on a blade as the name alone. Writes the text
 *  and its NUL into buf and its length (without the NUL) to *len; GA_ERR_ARG
 *  if cap is too small (GA_MV_TEXT_MAX always suffices) or buf is NULL,
 *  GA_ERR_NOTFINITE for NaN or Inf; nothing written then. No allocation and
 *  no locale. */
GA_API GA_NODISCARD ga_status ga_mv_format(ga_mv a, char *buf, size_t cap, size_t *len);
/** Reads what ga_mv_format writes, and a little more: terms separated by + or
 *  -, each a decimal number, a blade name (e1, ..., e12345, in canonical
 *  order only) or a number and a name, optionally with blanks or '*' between
 *  ("2e12", "2 e12", "2*e12"); a blade given twice adds up. A number's
 *  exponent is written with its sign ("1e+12", "2.5e-3") or with 'E'
 *  ("1E12"): 'e' followed by a digit begins a blade name, so "2e12" is 2 e12,
 *  as ganja.js prints it. A number is read as the tool's reader reads it
 *  (strtod, any length): beyond the double range ("1e+400", "1E400") it is
 *  GA_ERR_NOTFINITE, as the tool reports "number K is not finite", and so
 *  are terms of one blade that add up beyond it ("1e+308 + 1e+308"); below the
 *  smallest subnormal ("1e-400") it reads as 0, as there. "1e400" is 1 e400,
 *  an unknown name: GA_ERR_ARG. GA_ERR_ARG for anything else (an empty
 *  text, an unknown name, "e21", "nan", a mantissa of 400 characters or
 *  more glued to a blade name); *out untouched on any error. The decimal
 *  point is '.' whatever LC_NUMERIC (docs/conventions.md, "Multivectors as
 *  text"). */
GA_API GA_NODISCARD ga_status ga_mv_parse(const char *text, ga_mv *out);

/* ---- norm and inverse ------------------------------------------------- */
/** The signed squared norm <a ~a>_0 (negative for some blades of G(4,1)). */
GA_API double ga_mv_norm2(ga_mv a);
/** sqrt(|<a ~a>_0|). */
GA_API double ga_mv_norm(ga_mv a);
/** The multiple of u in ga_mv_inverse's tests of "to its rounding". */
#define GA_MV_INVERSE_TOL 64
/** The inverse of any invertible multivector a: a a^-1 = a^-1 a = 1 (one
 *  inverse serves both sides). Worked on a 2^-e (exact), e the exponent of
 *  a's largest coefficient, in one of two ways:
 *   - a versor or a blade, where a ~a is a scalar s to its rounding (every
 *     other coefficient of a ~a at most GA_MV_INVERSE_TOL u sbar, sbar =
 *     sum of a_i^2, which bounds the terms each coefficient sums): ~a / s.
 *     GA_ERR_SINGULAR where |s| <= GA_MV_INVERSE_TOL u sbar (a null blade
 *     or versor, to its rounding). a a^-1 = 1 to 2 GA_MV_INVERSE_TOL u
 *     sbar / |s|;
 *   - any other multivector: the closed form of Hitzer and Sangwine for
 *     five dimensions (2017): with P = a a- (a- the Clifford
 *     conjugate, ^ the grade involution), B = P P^ (grades 0, 1, 4) and C = B
 *     with grades 1 and 4 negated, d = <B C>_0 is a scalar and a^-1 =
 *     a- P^ C / d. Where |d| is at most GA_MV_INVERSE_TOL times a
 *     first-order bound of what the rounding of a (u per coefficient) and
 *     of the products can make of it (d goes as the eighth power of a's
 *     distance from the nearest zero divisor, and is lost to rounding long
 *     before a is singular), Gaussian elimination with partial pivoting on
 *     the 32 x 32 matrix of x -> a x instead. Then Newton steps r + r (1 - a r),
 *     at most three, until the residual 1 - a r, as computed, is at most
 *     u |a|_1 |r|_1 (|x|_1: the sum of the absolute coefficients).
 *     GA_ERR_SINGULAR where a pivot is at most 32 u |a|_max or no step
 *     reaches that residual: a is a zero divisor to its rounding (within a
 *     few u |a| of one), its inverse not determined in double. So a a^-1 = 1
 *     to u |a|_1 |a^-1|_1, a^-1 is within u |a|_1 |a^-1|_1^2 of the exact
 *     inverse, and a^-1 a = 1 to u (|a|_1 |a^-1|_1)^2.
 *  Also GA_ERR_SINGULAR where the inverse overflows, GA_ERR_NOTFINITE on
 *  NaN/Inf. */
GA_API GA_NODISCARD ga_status ga_mv_inverse(ga_mv a, ga_mv *out);

/* ---- exp and log of the whole algebra ------------------------------------
 * A bivector B of G(4,1) is a sum B1 + B2 of two commuting 2-blades with
 * B1^2 = l1, B2^2 = l2 scalars (Dorst-Valkenburg 2011, "Square root and
 * logarithm of rotors in 3D conformal geometric algebra using polar
 * decomposition", §3), where l1, l2 are the roots of l^2 - s l + q.q/4 = 0
 * with s = <B^2>_0, q = <B^2>_4. A part is elliptic (l < 0: a rotation),
 * hyperbolic (l > 0: a boost, e.g. a dilation) or parabolic (l = 0: a null
 * 2-blade, a translation or a transversion). docs/versors.md has the closed
 * forms, how they avoid cancellation, and the accuracy figures. */

/** exp(B) of the bivector part of B (other grades are ignored), in closed
 *  form: exp(B1) exp(B2) of the split above. No status: NaN or Inf in B
 *  propagates.
 *  Range: a bivector whose parts are all elliptic has a finite exp on the
 *  group at any finite size, and t e12 gives exactly cos t + sin t e12. A
 *  hyperbolic part t (Bi^2 = t^2 > 0) beyond 710.475 overflows as exp does:
 *  a coefficient is +-Inf with the true coefficient's sign where that is
 *  beyond DBL_MAX, its value where it is in range, 0 where it is 0, never
 *  NaN for finite B; each is known to ~u t e^t/2 times the largest, so one
 *  below that may be Inf.
 *  Accuracy: an angle of B is known to u |B| radians, a part below u |B|
 *  only as rounding; a result off the group by more than rounding is taken
 *  onto it by Newton steps R (3 - ~R R)/2. A null part larger than the rest
 *  (max |B| > 8, both squares li below |B|^2/64: a screw translating far, in
 *  any conformal frame) is taken in the frame where B is rigid
 *  (docs/numerics.md, "A null part"): within 4 u |B|^2 of the exact exp,
 *  which is what the rounding of B itself leaves. */
GA_API ga_mv ga_mv_exp(ga_mv B);

/** The principal logarithm of a rotor R (an even versor with R ~R = 1): a
 *  bivector B with exp(B) = R. Principal: log(exp(B)) = B whenever every
 *  elliptic part Bi of B (Bi^2 = -ti^2 < 0) has ti < pi/2; in general every
 *  elliptic part has ti in [0, pi], and a sign of R that no part can take
 *  within [0, pi/2) goes to the elliptic part with the largest angle (a
 *  part of angle pi in a plane that commutes with the rest when R has none).
 *  Refuses: GA_ERR_NOTFINITE on NaN/Inf; GA_ERR_DOMAIN when R is not a rotor
 *  to a relative 1e-9 (odd parts, R ~R != 1, or exp(log R) != R to 1e-9),
 *  which is where R has no real logarithm. Beside a large null part that
 *  check is widened to 64 u s^2 (s = min(|R|, |B|) + 4) where that is
 *  larger, up to 1e-6 (reached at s of about 8.4e3), beyond which
 *  GA_ERR_DOMAIN.
 *  Accuracy: exp(log R) = R to 1e-13 of |R| on the principal domain and
 *  beyond it, a rotation near a full turn beside a null part included, and
 *  log(exp(B)) = B to 1e-13 where every elliptic half-angle is below pi/2.
 *  Beside a large null part (|B| of 10 to 3000) exp(log R) = R and
 *  log(exp B) = B hold to 32 and 16 u |B|^2: exp of a log of that size is
 *  known to no better. */
GA_API GA_NODISCARD ga_status ga_mv_log(ga_mv R, ga_mv *out);

/** B's bivector part as a sum B1 + B2 of two commuting 2-blades (B1 B2 =
 *  B2 B1, Bi^2 scalar; Dorst-Valkenburg 2011 §3), |B1^2| >= |B2^2| where the
 *  parts are separated; a 2-blade gives (B, 0). Two rotations (q = <B^2>_4
 *  spanning a Euclidean 4-space) are split through the ideals of
 *  (1 +- J)/2, J = q/sqrt(q.q): exact for any B, so also for isoclinic B
 *  (t1 = t2), where the split is not unique and any one is returned.
 *  Otherwise by B1 = (l1 B - Bq/2)/(l1 - l2), B2 = (Bq/2 - l2 B)/(l1 - l2),
 *  keeping the split with the smallest residual; a rotation t beside a null
 *  part N in the frame where it is rigid, which holds for any t down to 0
 *  (docs/numerics.md, "A null part").
 *  Refuses: GA_ERR_NOTFINITE on NaN/Inf in B's bivector part,
 *  GA_ERR_DOMAIN when a part overflows.
 *  Accuracy: through ga_mv_factor, the factors multiply to R, commute and
 *  are simple to 1e-13 of |R|, whatever the kinds of the parts (rotations,
 *  boosts, null parts, their pairs, isoclinic or nearly so, a small turn
 *  beside a null part; docs/versors.md has the measurements). */
GA_API GA_NODISCARD ga_status ga_mv_split(ga_mv B, ga_mv *B1, ga_mv *B2);

/** A rotor R as a product R1 R2 of commuting simple rotors Ri = exp(Bi)
 *  (Bi 2-blades: a rotation, a boost such as a dilation, or a null part such
 *  as a translation or transversion): the ga_mv_split of ga_mv_log(R).
 *  Refuses with the status of ga_mv_log (GA_ERR_DOMAIN where R has no real
 *  log) or of ga_mv_split. Accuracy as ga_mv_split. */
GA_API GA_NODISCARD ga_status ga_mv_factor(ga_mv R, ga_mv *R1, ga_mv *R2);

/** R^t = exp(t log R) for a rotor R of G(4,1) and any real t, with the
 *  principal log of ga_mv_log and the exp of ga_mv_exp: every power is a
 *  function of the one bivector log R, so R^s R^t = R^(s+t), R^1 = R and
 *  R^-1 = ~R hold to the accuracy of exp and log (above). Refuses with the
 *  statuses of ga_mv_log (GA_ERR_DOMAIN where R has no real log), with
 *  GA_ERR_NOTFINITE for a NaN or infinite t, and with GA_ERR_DOMAIN where
 *  the power overflows (a boost raised to a large t). */
GA_API GA_NODISCARD ga_status ga_mv_pow(ga_mv R, double t, ga_mv *out);
/** The principal square root of a rotor R: ga_mv_pow(R, 1/2), the root
 *  whose elliptic angles are half those of log R (in [0, pi/2]), so
 *  sqrt(R)^2 = R to the accuracy of exp(log R) = R. Statuses of ga_mv_log. */
GA_API GA_NODISCARD ga_status ga_mv_sqrt(ga_mv R, ga_mv *out);

/* ---- more products ----------------------------------------------------- */
/** The regressive product a & b = (a* ^ b*) I, a* = a I^-1 (ga_mv_dual),
 *  so that (a & b)* = a* ^ b*: the meet of blades whose subspaces together
 *  span the whole space (for blades of grades r and s, grade r + s - 5), x & I
 *  = I & x = x. Of the dual and the undual, which only move and negate
 *  coefficients, it has the outer product's rounding. ganja.js's `&` (Vee);
 *  docs/conventions.md states the convention. No status. */
GA_API ga_mv ga_mv_regressive(ga_mv a, ga_mv b);
/** The commutator product a x b = (a b - b a) / 2 (for bivectors
 *  the Lie bracket of the rotors' algebra, a bivector again), summed over
 *  the pairs of blades that anticommute (the others cancel exactly), each
 *  term once: one rounding per term, not the numbers of the difference
 *  (a b - b a) / 2 computed as written. No status. */
GA_API ga_mv ga_mv_commutator(ga_mv a, ga_mv b);
/** The projection of a blade A onto an invertible blade B, (A _| B) _| B^-1
 *  (DFM §3.6; for blades equal to (A _| B) B^-1): the part of A in B's
 *  subspace, of A's grade. B^-1 as ga_mv_inverse (for a blade: ~B / (B ~B)).
 *  A and B are taken as given: for other multivectors the formula is
 *  computed as written. GA_ERR_SINGULAR where B has no inverse: a null blade
 *  (a point F(x), n, a tangent round, any blade with B ~B = 0 to its
 *  rounding) spans a subspace on which the metric is degenerate, and there no
 *  orthogonal projection exists (ga_point_project projects points onto such
 *  objects in the Euclidean sense). GA_ERR_NOTFINITE on NaN/Inf,
 *  GA_ERR_DOMAIN where the result overflows. */
GA_API GA_NODISCARD ga_status ga_mv_project(ga_mv A, ga_mv B, ga_mv *out);
/** The rejection of A from an invertible blade B, (A ^ B) |_ B^-1 (|_ the
 *  right contraction; for blades equal to (A ^ B) B^-1): for a vector a,
 *  a - ga_mv_project(a, B), the part of a orthogonal to B; for a blade A of
 *  higher grade, the part of A orthogonal to B (zero where A and B share a
 *  direction). Statuses of ga_mv_project. */
GA_API GA_NODISCARD ga_status ga_mv_reject(ga_mv A, ga_mv B, ga_mv *out);

#ifdef __cplusplus
}
#endif
#endif
