/* garotor/versor.h: the general algebra of G(4,1): versors (products of
 * vectors, even or odd) and their sandwich, the conformal transformations as
 * versors, and closed-form exp and log of any bivector and rotor.
 *
 * A versor V acts on any multivector X by V X^ V^-1, where X^ is X for even V
 * and the grade involution of X for odd V (Dorst-Fontijne-Mann, "Geometric
 * Algebra for Computer Science", 2007, §7.6): so a dual plane vector reflects
 * points in its plane, a dual sphere vector inverts them in its sphere.
 *
 * exp and log (docs/versors.md has the derivation): a bivector B of G(4,1)
 * is a sum B1 + B2 of two commuting 2-blades with B1^2 = l1, B2^2 = l2
 * scalars (Dorst-Valkenburg 2011, "Square root and logarithm of rotors in 3D
 * conformal geometric algebra using polar decomposition", §3), where l1, l2
 * are the roots of l^2 - s l + q.q/4 = 0 with s = <B^2>_0, q = <B^2>_4. A part
 * is elliptic (l < 0: a rotation), hyperbolic (l > 0: a boost, e.g. a
 * dilation) or parabolic (l = 0: a null 2-blade, a translation or a
 * transversion). exp(B) = exp(B1) exp(B2) is written as
 * alpha + beta B + gamma q + delta B q with coefficients that are symmetric
 * functions of l1, l2, evaluated without cancellation in every case
 * (repeated parts, null parts, near-degenerate ones).
 */
#ifndef GAROTOR_VERSOR_H
#define GAROTOR_VERSOR_H

#include "mv.h"
#include "types.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- exp, log and factorization ---------------------------------------------- */

/** exp(B) of the bivector part of B (other grades are ignored), in closed form.
 *  NaN or Inf in B propagates. Up to max |B| = 8 by the coefficients
 *  alpha..delta above. Beyond, where they lose u |B|^2 to cancellation
 *  (R ~R - 1 was 1.5e-8 at |B| ~ 1e4, and R unbounded beyond ~1e8) and
 *  overflow beyond ~1e77 (s^2 ~ |B|^4), B is scaled by a power of two, split
 *  into its parts (the two commuting 2-blades, or for near-equal parts the
 *  ideals of (1 +- J)/2, J the unit 4-vector of q), and each factor
 *  C(li) + S(li) Bi is formed with li = Bi^2 from the part itself and
 *  without overflow; a result off the group by more than rounding (a part
 *  below u |B|, rounding only, that is no 2-blade) takes Newton steps
 *  R (3 - ~R R)/2 onto it. So a bivector whose parts are all elliptic has a
 *  finite exp on the group at any finite size (tests/test_versor.c,
 *  section 6: to 1.8e308), and exactly cos t + sin t e12 for t e12. A
 *  hyperbolic part t (Bi^2 = t^2 > 0) beyond 710.475 overflows as exp
 *  does: a coefficient is +-Inf with the true coefficient's sign where that
 *  is beyond DBL_MAX, its value where it is in range (the factor's 2^e of
 *  e^t/2 is applied last), 0 where it is 0, never NaN for finite B; each
 *  is known to ~u t e^t/2 times the largest, so one below that may be Inf
 *  (section 6b). Both near null
 *  (|li| <= 2^-20 |B|^2) keep the coefficients. An angle of such B is known
 *  to u |B| radians, a part below u |B| only as rounding. */
GA_API ga_mv ga_mv_exp(ga_mv B);
/*  A null part larger than the rest (max |B| > 8, both squares li below
 *  |B|^2/64: a screw translating far, in any conformal frame) is taken in the
 *  frame where B is rigid (ga_rotor_exp there; docs/versors.md, "A null
 *  part"): within 4 u |B|^2 of the exact exp (tests/test_versor.c section 2c,
 *  null parts of 10 to 3000; the closed forms were 771 u |B|^2 off), which is
 *  what the rounding of B itself leaves. */

/** The principal logarithm of a rotor R (an even versor with R ~R = 1): a
 *  bivector B with exp(B) = R. Principal: log(exp(B)) = B whenever every
 *  elliptic part Bi of B (Bi^2 = -ti^2 < 0) has ti < pi/2; in general every
 *  elliptic part has ti in [0, pi], and a sign of R that no part can take
 *  within [0, pi/2) goes to the elliptic part with the largest angle (a
 *  part of angle pi in a plane that commutes with the rest when R has none).
 *  GA_ERR_NOTFINITE on NaN/Inf; GA_ERR_DOMAIN when R is not a rotor to a
 *  relative 1e-9 (odd parts, R ~R != 1, or exp(log R) != R to 1e-9), which is
 *  where R has no real logarithm.
 *  Accuracy (tests/test_versor.c, docs/versors.md): exp(log R) = R to 1e-13
 *  of |R| on the principal domain and beyond it, measured on 10^4 rotors of
 *  each family (`test_versor 10`, worst 8.9e-14, for -R of two rotations),
 *  including a rotation near a full turn beside a null part
 *  (-exp(delta E + N): -T for a translation T, delta from 1e-12 to 0.3, and
 *  0) and log(exp(B)) = B to 1e-13 where every elliptic half-angle is below
 *  pi/2. Where <R>_0 < 0 and the closed forms leave more than rounding, two
 *  other forms are tried and the one with the smallest |exp(B) - R| kept:
 *  log(-R) - pi E (E the unit plane of log(-R)'s part with the smaller
 *  angle, from ga_mv_split), and, beside a null part, the log in the frame
 *  where R is rigid (docs/versors.md, "A null part"). Beside a large null
 *  part (section 2c: 10 to 3000) exp(log R) = R and log(exp B) = B hold to
 *  32 and 16 u |B|^2 (measured 21 and 4.6 on 3000 rotors): exp of a log
 *  of that size is known to no better, so the 1e-9 check is widened to
 *  64 u s^2 (s = min(|R|, |B|) + 4) where that is larger, up to 1e-6
 *  (s ~ 2.6e5), beyond which GA_ERR_DOMAIN. */
GA_API GA_NODISCARD ga_status ga_mv_log(ga_mv R, ga_mv *out);

/** B's bivector part as a sum B1 + B2 of two commuting 2-blades (B1 B2 =
 *  B2 B1, Bi^2 scalar; Dorst-Valkenburg 2011 §3), |B1^2| >= |B2^2| where the
 *  parts are separated. Two rotations (q = <B^2>_4 spanning a Euclidean
 *  4-space) are split through the ideals of (1 +- J)/2, J = q/sqrt(q.q):
 *  exact for any B, so also for isoclinic B (t1 = t2), where the split is
 *  not unique and any one is returned. Otherwise (a rotation and a boost, a
 *  null part) by B1 = (l1 B - Bq/2)/(l1 - l2), B2 = (Bq/2 - l2 B)/(l1 - l2)
 *  (l2 = 0 tried as well beside a null part), keeping the split with the
 *  smallest residual; a rotation t beside a null part N (a screw, or one
 *  seen in another conformal frame) in the frame where it is rigid, which
 *  needs no t^2 (known only to u |B|^2 from <B^2>_0) and holds for any t
 *  down to 0 (docs/versors.md, "A null part"). A 2-blade gives (B, 0).
 *  Accuracy (tests/test_versor.c section 7, 10^4 rotors per family with
 *  `test_versor 10`): the factors of ga_mv_factor multiply to R, commute
 *  and are simple to 5.3e-14 of |R| for every family (rotations, boosts,
 *  null parts, their pairs, isoclinic and near-isoclinic, a turn of 1e-12
 *  to 1e-4 beside a null part, dense random bivectors).
 *  GA_ERR_NOTFINITE on NaN/Inf in B's bivector part,
 *  GA_ERR_DOMAIN when a part overflows. */
GA_API GA_NODISCARD ga_status ga_mv_split(ga_mv B, ga_mv *B1, ga_mv *B2);

/** A rotor R as a product R1 R2 of commuting simple rotors Ri = exp(Bi)
 *  (Bi 2-blades: a rotation, a boost such as a dilation, or a null part such
 *  as a translation or transversion): the ga_mv_split of ga_mv_log(R).
 *  Status of ga_mv_log (GA_ERR_DOMAIN where R has no real log) or of
 *  ga_mv_split. */
GA_API GA_NODISCARD ga_status ga_mv_factor(ga_mv R, ga_mv *R1, ga_mv *R2);

/* ---- versors ------------------------------------------------------------------- */

/** V X^ V^-1 (X^ = X for even V, the grade involution of X for odd V).
 *  GA_ERR_NOTFINITE on NaN/Inf; GA_ERR_ARG when V has both even and odd parts;
 *  GA_ERR_SINGULAR when V has no inverse (ga_mv_inverse). */
GA_API GA_NODISCARD ga_status ga_versor_apply(ga_mv V, ga_mv X, ga_mv *out);

/** Reflection in the plane n.x = d (n need not be unit): the dual plane
 *  vector n + d e_inf (odd). */
GA_API ga_mv ga_versor_reflection(ga_vec3 normal, double distance);
/** Inversion in the sphere of centre c and radius r: the dual sphere
 *  F(c) - r^2/2 n (odd); it maps x to c + r^2 (x - c)/|x - c|^2. */
GA_API ga_mv ga_versor_inversion(ga_vec3 centre, double radius);
/** Dilation about c by the factor s > 0: T_c exp(-ln(s)/2 e45) T_c^-1, which
 *  maps x to c + s (x - c). GA_ERR_ARG unless s > 0, GA_ERR_NOTFINITE. */
GA_API GA_NODISCARD ga_status ga_versor_dilation(ga_vec3 centre, double s, ga_mv *out);
/** Transversion 1 + nbar b/2 (b a Euclidean vector): the translation by -b
 *  conjugated by the inversion in the unit sphere (e4 n e4 = nbar), so it
 *  maps x to (x - |x|^2 b) / (1 - 2 b.x + |b|^2 |x|^2). */
GA_API ga_mv ga_versor_transversion(ga_vec3 b);
/** Rotation by angle about the unit axis through the origin, as a full
 *  multivector (ga_rotor_to_mv of ga_rotor_rotation). */
GA_API ga_mv ga_versor_rotation(ga_vec3 axis, double angle);
/** Translation by a, as a full multivector (ga_rotor_to_mv of
 *  ga_rotor_translation): 1 + n a/2. */
GA_API ga_mv ga_versor_translation(ga_vec3 a);

#ifdef __cplusplus
}
#endif
#endif
