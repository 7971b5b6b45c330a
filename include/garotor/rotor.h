/* garotor/rotor.h: the compact rigid-motion rotor, its exp and log, screws,
 * and the bridge to matrices, twists, quaternions and dual quaternions.
 *
 * A rigid-motion rotor of G(4,1) (Wareham-Lasenby §2.2-2.5) has the form
 *
 *     R = q + P n,    n = e4 + e5,
 *
 * with q in the even subalgebra of G(3) (1, e12, e13, e23) and P odd in G(3)
 * (e1, e2, e3, e123). Since n commutes with even elements of G(3),
 * anticommutes with odd ones and n^2 = 0,
 *
 *     (q1 + P1 n)(q2 + P2 n) = q1 q2 + (q1 P2 + P1 q2) n,
 *
 * so the 8 coefficients of 1, e12, e13, e23, e1n, e2n, e3n, e123n are closed
 * under the product (e_i n = e_i4 + e_i5 and e123n = e1234 + e1235 in the full
 * multivector). q is the rotation; the translation is t = -2 <P ~q>_1, and
 * R = T_t q with T_a = 1 + n a/2 (W-L §2.2). R ~R = q ~q + (P ~q - q ~P) n, so
 * R is on the group iff |q| = 1 and <P ~q>_3 = 0; then R n ~R = n (Thm 8).
 *
 * Generators: B = beta I3 + c n with beta, c vectors of G(3) (I3 = e123), i.e.
 * the bivector span{e_ij, e_i n}. A twist xi = (w, v) has the generator
 * B(xi) = -(w I3 + v n)/2 (docs/conventions.md), so beta = -w/2, c = -v/2, and
 * exp(B(xi)) moves points as expm(xi^) does. With phi = |beta| (half the
 * rotation angle) and sinc(x) = sin(x)/x,
 *
 *     exp(B) = cos(phi) + sinc(phi) beta I3
 *            + [ cos(phi) c_par + sinc(phi) c_perp + sinc(phi) (beta.c) I3 ] n,
 *
 * (c_par, c_perp: the parts of c along and across beta), the closed form of
 * W-L Thm 3 (there written [cos + sin P][1 + t_perp n] + sinc t_par n, with
 * phi P = beta I3, t = 2c).
 *
 * Conventions: a rotor acts by X -> R X ~R; R2 R1 is R1 first. The quaternion
 * (w, x, y, z) of q = s + a12 e12 + a13 e13 + a23 e23 is (s, -a23, a13, -a12)
 * (a right-handed rotation by theta about u is (cos theta/2, sin theta/2 u)).
 */
#ifndef GAROTOR_ROTOR_H
#define GAROTOR_ROTOR_H

#include "types.h"
#include "mv.h"

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/** A rigid-motion rotor R = q + P n: q has the coefficients s, e12, e13, e23
 *  (a unit quaternion), P n the coefficients of e1n, e2n, e3n, e123n. */
typedef struct {
    double s, e12, e13, e23, e1n, e2n, e3n, e123n;
} ga_rotor;

/** A generator: a bivector B in span{e_ij, e_i n} (W-L §2.3: B = ab + c n). */
typedef struct {
    double e12, e13, e23, e1n, e2n, e3n;
} ga_generator;

/** Screw parameters of a rigid motion (Chasles; W-L §4.1, the helix).
 *  angle in [0, pi]; axis a unit vector; point the point of the axis closest to
 *  the origin; shift the translation along the axis; pitch = shift / angle.
 *  Pure translation: angle 0, axis its unit direction, point 0, shift its
 *  length, pitch INFINITY. Identity: everything 0, axis (0, 0, 1), pitch 0. */
typedef struct {
    double angle;
    ga_vec3 axis;
    ga_vec3 point;
    double shift;
    double pitch;
} ga_screw;

/** A quaternion w + x i + y j + z k (Hamilton's convention). */
typedef struct {
    double w, x, y, z;
} ga_quat;

/** The normalisation tolerance (docs/conventions.md, "Keys near the group"):
 *  ga_quat_normalize and ga_se3_normalize (mat4.h) accept an input this far
 *  from the group and project it onto it; `garotor interp --normalize` uses
 *  it. */
#define GA_SE3_NORMALIZE_TOL 1e-3

/** q / |q| when ||q| - 1| <= tol: the rule of docs/conventions.md, "Keys
 *  near the group". Refuses: GA_ERR_NOTRIGID when q is farther,
 *  GA_ERR_NOTFINITE for NaN/Inf, GA_ERR_ARG for a tol that is negative, NaN
 *  or above GA_SE3_NORMALIZE_TOL. */
GA_API GA_NODISCARD ga_status ga_quat_normalize(ga_quat q, double tol, ga_quat *out);

/** A dual quaternion real + eps dual: for the motion "rotate by r, then translate
 *  by t", real = r and dual = t r / 2, with t the pure quaternion (0, t). */
typedef struct {
    ga_quat real, dual;
} ga_dualquat;

/** Largest distance from the group, max(| |q|^2 - 1 |, 2 |<P ~q>_3| / max(1, |P|)),
 *  that ga_rotor_log, ga_rotor_log_literal and ga_rotor_to_screw accept (and
 *  project away, as R (R ~R)^(-1/2)); farther is GA_ERR_NOTRIGID. */
#define GA_ROTOR_DRIFT_MAX 1e-6

/* ---- the group ---------------------------------------------------------- */

/** The identity rotor 1. */
GA_API ga_rotor ga_rotor_identity(void);

/** The product a b (b first, then a): (qa + Pa n)(qb + Pb n) = qa qb + (qa Pb + Pa qb) n,
 *  48 multiplications, written out term by term. */
GA_API ga_rotor ga_rotor_mul(ga_rotor a, ga_rotor b);

/** The reverse ~r = ~q - ~P n (the inverse of a unit rotor). */
GA_API ga_rotor ga_rotor_reverse(ga_rotor r);

/** The full 32-component multivector of r (e_i n = e_i4 + e_i5, e123 n = e1234 + e1235). */
GA_API ga_mv ga_rotor_to_mv(ga_rotor r);

/** The full 32-component multivector of the generator b, a bivector (e_i n = e_i4 + e_i5);
 *  exact: each coefficient is copied, none rounded. */
GA_API ga_mv ga_generator_to_mv(ga_generator b);

/** The compact rotor of a multivector m. GA_ERR_NOTFINITE on NaN/Inf; GA_ERR_NOTRIGID if a
 *  coefficient outside the 8-component form exceeds tol * max(1, max|m|), if
 *  e_i4 and e_i5 (or e1234 and e1235) differ by more than that, or if the
 *  rotor is farther than tol from the group (see ga_rotor_check). On success
 *  *out is projected onto the group (ga_rotor_normalize). */
GA_API GA_NODISCARD ga_status ga_rotor_from_mv(ga_mv m, double tol, ga_rotor *out);

/** r's distance from the group: max(| |q|^2 - 1 |, 2 |<P ~q>_3| / max(1, |P|)), i.e.
 *  the largest coefficient of R ~R - 1 (Thm 7), the second one relative to the
 *  size of the translation; R n ~R = n then follows (Thm 8). GA_OK if it is <= tol,
 *  GA_ERR_NOTRIGID if not, GA_ERR_NOTFINITE on NaN/Inf. */
GA_API GA_NODISCARD ga_status ga_rotor_check(ga_rotor r, double tol);

/** The rotor R (R ~R)^(-1/2) on the group: q /= |q|, P /= |q|, then the e123 part of
 *  P ~q is dropped (P = <P ~q>_1 q). GA_ERR_NOTFINITE on NaN/Inf, GA_ERR_NOTRIGID if
 *  q = 0 (no rotor is near), GA_ERR_DOMAIN if the result overflows (P near
 *  DBL_MAX). Works for any distance from the group. */
GA_API GA_NODISCARD ga_status ga_rotor_normalize(ga_rotor r, ga_rotor *out);

/* ---- action ---------------------------------------------------------------- */

/** The point x moved by r, as down(R F(x) ~R), computed as q x ~q + t (R = T_t q,
 *  t = -2 <P ~q>_1) in one quaternion sandwich (rotor_inline.h). r must be
 *  on the group (ga_rotor_check): off it, the rotated part is scaled by
 *  |q|^2. */
GA_API ga_vec3 ga_rotor_apply(ga_rotor r, ga_vec3 x);

/** The points in[0], ..., in[n - 1] moved by r into out[0..n - 1]: r's
 *  matrix once, then the 3 x 4 product per point, so out is, bit for bit,
 *  what ga_mat4_apply_many(ga_rotor_to_mat4(r), in, n, out) writes. Against
 *  ga_rotor_apply (another order of the same arithmetic), for r on the group
 *  (ga_rotor_check) each coordinate of out[i] is within
 *  32 u (|x|_1 + |t|_inf) of ga_rotor_apply(r, in[i]), u = DBL_EPSILON,
 *  x = in[i], t = ga_rotor_to_translation(r). out may be in (the same
 *  array); other overlaps are not allowed. GA_ERR_ARG where in or out is
 *  NULL (nothing written); no other status: NaN and Inf propagate. */
GA_API GA_NODISCARD ga_status ga_rotor_apply_many(ga_rotor r, const ga_vec3 *in, size_t n, ga_vec3 *out);

/** R X ~R for any conformal object X: the rotation q X ~q of R = T_t q
 *  through the geometric product, then the translation by t carried exactly
 *  and rounded once (no cancellation of t^2 terms however far R reaches).
 *  For a translation R = T_t (q = 1, t read from R exactly) each coefficient
 *  c of the exact T_t X ~T_t comes within DBL_EPSILON |c| / 2 (one rounding;
 *  beside ~2^-100 of the sum of its terms). X's own rounding is carried
 *  along exactly and grows with t: a point off by d in its nbar part moves
 *  d |t|^2 in its n part, so ga_point_up(x) moved by T_t is F(x + t) only to
 *  within DBL_EPSILON (2 |x|^2 + 1) |t_i| at e_i and DBL_EPSILON
 *  (|x|^2 + 1/2) (|t|^2 + 2) at e4 and e5 beyond that rounding, not to a few
 *  DBL_EPSILON of max |F(x + t)|. */
GA_API ga_mv ga_rotor_apply_mv(ga_rotor r, ga_mv X);

/* ---- constructors ------------------------------------------------------- */

/** The rotation by angle (radians) right-handed about axis (normalised here; a zero
 *  axis gives the identity): R = exp(-angle/2 u I3) = cos(angle/2) - sin(angle/2) u I3
 *  (W-L §2.1; u I3 = ux e23 - uy e13 + uz e12). */
GA_API ga_rotor ga_rotor_rotation(ga_vec3 axis, double angle);

/** The translation by a: T_a = 1 + n a / 2 (W-L §2.2). */
GA_API ga_rotor ga_rotor_translation(ga_vec3 a);

/** The twist of W-L Definition 4, tau(psi, P, a) = [cos(psi/2) + sin(psi/2) P][1 + n a/2]:
 *  translate by a, then rotate by exp(psi P / 2). P is the e_ij part of plane,
 *  normalised here to P^2 = -1 (a zero plane gives T_a); the n part of plane
 *  is ignored. exp(psi P/2) is the right-handed rotation by psi about u = P I3
 *  (so P = e12 turns e2 towards e1). The paper asks for a . P = 0 (a along the
 *  axis); any a is accepted and the formula applied as written. */
GA_API ga_rotor ga_rotor_twist(double psi, ga_generator plane, ga_vec3 a);

/** The generator B(xi) = -(w I3 + v n)/2 of a twist (docs/conventions.md). */
GA_API ga_generator ga_twist_to_generator(ga_twist xi);

/** The twist of a generator: the inverse of ga_twist_to_generator. */
GA_API ga_twist ga_generator_to_twist(ga_generator b);

/* ---- exp and log ------------------------------------------------------- */

/** exp(B) of a generator, in closed form (W-L Thm 3 / eq. 2): the formula
 *  at the top of this header, exact for every B (pure translations and small
 *  angles included: cos phi, sinc phi and (cos phi - sinc phi)/phi^2 keep
 *  their relative accuracy as phi -> 0; docs/numerics.md, "The rotor exponential").
 *  Any finite angle is accepted, also beyond ~1e154 where phi^2 overflows
 *  (the scaled norm there): the rotation by the double angle, as ga_se3_exp
 *  gives it. No status: NaN in, NaN out.
 *  Accuracy: each component within 32 u (u = DBL_EPSILON) of the exact exp,
 *  relative to max(1, |translation|); on the group to 16 u. */
GA_API ga_rotor ga_rotor_exp(ga_generator b);

/** The principal logarithm l(R) (W-L Thm 9, made robust): the generator of the
 *  shortest motion, rotation angle in [0, pi] (R is replaced by -R when its
 *  scalar part is negative; at exactly pi either axis sign is returned). The
 *  half angle is atan2(|<q>_2|, <q>_0) (in the common case without a libm
 *  call: a Taylor series after reduction to the nearest multiple of pi/8),
 *  the parallel translation
 *  c.u = cos(phi)(p.u) + sin(phi) p123 and the perpendicular one
 *  p_perp / sinc(phi), so no branch or series is needed: exact at 0, near and
 *  at pi, and for pure translations. A rotor that has drifted from the group
 *  by at most GA_ROTOR_DRIFT_MAX is projected first; farther is GA_ERR_NOTRIGID;
 *  NaN/Inf is GA_ERR_NOTFINITE; a generator that overflows (a translation near
 *  DBL_MAX) is GA_ERR_DOMAIN.
 *  Accuracy: exp(l(R)) = +-R, and l(exp(B)) = B for B of angle in [0, pi),
 *  to 8 u relative to max(1, |B|), at every angle and size (u =
 *  DBL_EPSILON); a tiny rotation keeps its full relative accuracy under any
 *  translation. */
GA_API GA_NODISCARD ga_status ga_rotor_log(ga_rotor r, ga_generator *out);

/** The literal logarithm: exp(l(R)) = R exactly, no sign flip, rotation angle in
 *  [0, 2 pi]. At exactly q = -1 (a turn of 2 pi) the axis is taken along the
 *  translation (or e3 if there is none); near 2 pi the perpendicular
 *  translation is ill-conditioned (divided by sinc(phi) -> 0; GA_ERR_DOMAIN when that
 *  overflows), and its rounding along the axis, which exp would not damp, is
 *  taken out again. Statuses as ga_rotor_log. */
GA_API GA_NODISCARD ga_status ga_rotor_log_literal(ga_rotor r, ga_generator *out);

/* ---- screws (Chasles; W-L §4.1) ------------------------------------------- */

/** The screw of r (through its principal log; see ga_screw). GA_ERR_NOTFINITE,
 *  GA_ERR_NOTRIGID as ga_rotor_log; GA_ERR_DOMAIN if the axis point overflows (a
 *  rotation of ~1e-300 rad under a finite translation). */
GA_API GA_NODISCARD ga_status ga_rotor_to_screw(ga_rotor r, ga_screw *out);

/** The rotor of a screw: rotate by angle about the axis through point, translating
 *  by shift along it (pitch is not used; shift is). The axis is normalised; for
 *  angle 0 it is the translation by shift * axis. */
GA_API ga_rotor ga_rotor_from_screw(ga_screw s);

/* ---- the bridge ----------------------------------------------------------- */

/** The 4x4 homogeneous matrix of r (row-major, column vectors): [Rot(q), t; 0 0 0 1]. */
GA_API ga_mat4 ga_rotor_to_mat4(ga_rotor r);

/** The rotor of a rigid-motion matrix (Shepperd's method: the quaternion from the
 *  largest of trace, m00, m11, m22, robust at half turns), with the sign chosen
 *  so that the scalar part is >= 0. GA_ERR_NOTFINITE on NaN/Inf; GA_ERR_NOTRIGID if the
 *  3x3 block is not orthonormal to 1e-9 (max |M^T M - 1|), has det <= 0, or the
 *  last row is not 0 0 0 1 to 1e-9; GA_ERR_DOMAIN if the rotor overflows (a
 *  translation near DBL_MAX). */
GA_API GA_NODISCARD ga_status ga_rotor_from_mat4(ga_mat4 m, ga_rotor *out);

/** The rotation of r as a quaternion: q = s + a12 e12 + a13 e13 + a23 e23 is
 *  (s, -a23, a13, -a12). With ga_rotor_to_translation, r = T_t q. */
GA_API ga_quat ga_rotor_to_quat(ga_rotor r);

/** The translation t = -2 <P ~q>_1 of r (r = T_t q: rotate by q, then translate by t). */
GA_API ga_vec3 ga_rotor_to_translation(ga_rotor r);

/** The rotor "rotate by the unit quaternion q, then translate by t": T_t q.
 *  q is used as given (normalise it first if it may not be unit). */
GA_API ga_rotor ga_rotor_from_quat(ga_quat q, ga_vec3 t);

/** The unit dual quaternion of r (real = r, dual = t r / 2). The map is an algebra
 *  isomorphism: real <-> q, dual <-> P with P = -(dual.x, dual.y, dual.z) - dual.w e123. */
GA_API ga_dualquat ga_rotor_to_dualquat(ga_rotor r);

/** The rotor of a unit dual quaternion (the inverse of ga_rotor_to_dualquat). */
GA_API ga_rotor ga_rotor_from_dualquat(ga_dualquat d);

/* ---- the mean of rigid motions ------------------------------------------------ */

/** The most iterations ga_rotor_mean takes. */
#define GA_ROTOR_MEAN_ITER 100
/** ga_rotor_mean's stopping rule, in units of u. */
#define GA_ROTOR_MEAN_TOL 64

/** The weighted mean of n rigid motions R[i] with weights w[i] >= 0 (not all
 *  0; they are normalised to sum 1): the exponential barycentre M,
 *  sum_i w_i log(M^-1 R_i) = 0 (Pennec and Arsigny, "Exponential
 *  barycenters of the canonical Cartan connection and invariant means on
 *  Lie groups", 2013), with the principal log of ga_rotor_log. For
 *  rotations alone it is the Karcher (Frechet) mean of the rotation angle;
 *  for pure translations the weighted mean of the translations; it is
 *  invariant under L R_i and R_i L (the mean of those is L M, M L) and under
 *  the order of the rotors. Found by the fixed-point iteration
 *  M <- M exp(sum_i w_i log(M^-1 R_i)) from the rotor of largest weight
 *  (projected onto the group), which stops when the rotation part of the
 *  step is at most GA_ROTOR_MEAN_TOL u max(1, the logs' rotation parts) and
 *  its translation part at most GA_ROTOR_MEAN_TOL u max(1, the logs'
 *  translation parts, the n parts of the rotors and of M): the rounding of
 *  the sum of the logs and of the products M^-1 R_i. The mean is
 *  unique where the rotations lie in a ball of radius pi/2 (Pennec and
 *  Arsigny), and the iteration converges linearly, the faster the closer
 *  the rotors (docs/conformal.md, "More algebra", has the rates); where the mean is not unique
 *  (rotations spread over more than a half turn) it returns one of them.
 *  GA_ERR_DOMAIN where it has not converged after GA_ROTOR_MEAN_ITER
 *  iterations. Refuses:
 *  GA_ERR_ARG for n = 0, a negative weight or weights summing to 0 or
 *  overflowing; GA_ERR_NOTFINITE for NaN/Inf in a rotor or a weight;
 *  GA_ERR_NOTRIGID where a rotor is farther than GA_ROTOR_DRIFT_MAX from
 *  the group (ga_rotor_log's status). */
GA_API GA_NODISCARD ga_status ga_rotor_mean(const ga_rotor *R, const double *w, size_t n, ga_rotor *out);

#ifdef __cplusplus
}
#endif
#endif
