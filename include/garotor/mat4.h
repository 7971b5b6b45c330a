/* garotor/mat4.h: 4x4 homogeneous matrices, the Lie group SE(3) in closed form
 * (Eberly), and the general matrix exponential and logarithm (Higham).
 *
 * A matrix is row-major, m[4*row + col], acting on column vectors (x, y, z, 1).
 * A twist xi = (w, v) stands for the Lie-algebra element
 *
 *       xi^ = [ [w]x  v ]      [w]x = [  0  -wz   wy ]
 *             [  0    0 ]             [  wz   0  -wx ]      ([w]x u = w x u)
 *                                     [ -wy  wx    0 ]
 *
 * and its motion is expm(xi^). In Eberly's notation S = [w]x, U = v and
 * theta = |w| (Eberly eqs. 8, 19).
 *
 * Two implementations of exp and log live here and agree with each other on
 * rigid motions: the SE(3) closed forms (fast, exactly rigid, full relative
 * accuracy as theta -> 0 and theta -> pi) and the general ones for any real
 * 4x4 matrix (Al-Mohy & Higham's scaling and squaring with Pade for exp,
 * their Schur-based inverse scaling and squaring for log), which the affine
 * group uses for scalings and shears. docs/matrices.md has both, with the
 * details of the general algorithms.
 */
#ifndef GAROTOR_MAT4_H
#define GAROTOR_MAT4_H

#include "rotor.h" /* GA_SE3_NORMALIZE_TOL, the tolerance of ga_se3_normalize */
#include "types.h"

#ifdef __cplusplus
extern "C" {
#endif

/** The rigidity tolerance of docs/conventions.md: ga_se3_log and ga_se3_geodesic accept
 *  a matrix m when ga_se3_check(m, GA_SE3_TOL) is GA_OK. */
#define GA_SE3_TOL 1e-9

/* ---- plain 4x4 algebra ------------------------------------------------- */

/** The identity I. */
GA_API ga_mat4 ga_mat4_identity(void);
/** The points in[0], ..., in[n - 1] moved by the affine map of m (its last
 *  row is not read) into out[0..n - 1]: for x = in[i],
 *  out[i].x = ((m0 x.x + m1 x.y) + m2 x.z) + m3, and rows 1 and 2 alike, in
 *  that order. out may be in (the same array); other overlaps are not
 *  allowed. GA_ERR_ARG where in or out is NULL (nothing written); no other
 *  status: NaN and Inf propagate. */
GA_API GA_NODISCARD ga_status ga_mat4_apply_many(ga_mat4 m, const ga_vec3 *in, size_t n, ga_vec3 *out);

/** The product a*b (b acts first, then a). */
GA_API ga_mat4 ga_mat4_mul(ga_mat4 a, ga_mat4 b);

/** The inverse of a general 4x4, by Gaussian elimination with partial pivoting.
 *  GA_ERR_NOTFINITE if a holds NaN or Inf. GA_ERR_SINGULAR if a is numerically
 *  singular: a pivot is at most 4*DBL_EPSILON times the largest entry both for
 *  a as given and after exact power-of-2 row and column equilibration (so an
 *  affine [R, t; 0 1] with |t| = 1e16 or diag(1e-20, 1, 1, 1) is invertible
 *  and a rank-deficient matrix is not), or if the inverse overflows. */
GA_API GA_NODISCARD ga_status ga_mat4_inverse(ga_mat4 a, ga_mat4 *out);

/** The 1-norm, max_j sum_i |a_ij| (the largest column sum). */
GA_API double ga_mat4_norm1(ga_mat4 a);

/* ---- the Lie algebra se(3) ---------------------------------------------- */

/** xi^ = [[w]x, v; 0 0 0 0] (Eberly eqs. 8 and 19). */
GA_API ga_mat4 ga_twist_hat(ga_twist xi);

/** The inverse of hat: w from the skew part of the upper-left 3x3,
 *  w = ((a21 - a12)/2, (a02 - a20)/2, (a10 - a01)/2), and v = (a03, a13, a23).
 *  Reading the skew part makes vee(logm(M)) the nearest twist when the 3x3
 *  block is skew only to rounding. */
GA_API ga_twist ga_twist_vee(ga_mat4 a);

/* ---- the group SE(3) ---------------------------------------------------- */

/** Is m a rigid motion [[R, t]; [0 0 0 1]] (Eberly eq. 17)? GA_ERR_NOTFINITE if m
 *  holds NaN or Inf; GA_ERR_NOTRIGID unless max |R^T R - I|_ij <= tol, det R > 0
 *  and the last row is 0 0 0 1 to within tol (entrywise); else GA_OK. */
GA_API GA_NODISCARD ga_status ga_se3_check(ga_mat4 m, double tol);

/** The rigid motion nearest m: when ga_se3_check(m, tol) is GA_OK (rotation
 *  block with max |R^T R - I| <= tol and det R > 0, last row 0 0 0 1 to tol),
 *  out is m with its 3x3 block replaced by the nearest rotation (the
 *  orthogonal polar factor, Higham's Newton iteration R <- (R + R^-T)/2,
 *  quadratically convergent from such a start) and its last row set to
 *  0 0 0 1; the translation is kept. Otherwise the status of the check
 *  (GA_ERR_NOTRIGID, GA_ERR_NOTFINITE); tol > GA_SE3_NORMALIZE_TOL is
 *  GA_ERR_ARG. A matrix rigid to rounding comes back within 2 ulp. */
GA_API GA_NODISCARD ga_status ga_se3_normalize(ga_mat4 m, double tol, ga_mat4 *out);

/** The inverse of a rigid motion, [R^T, -R^T t; 0 1] (Eberly eq. 18). m is
 *  assumed rigid; its last row is ignored. */
GA_API ga_mat4 ga_se3_inverse(ga_mat4 m);

/** expm(xi^) in closed form (Eberly eqs. 9, 19, 20):
 *    R = I + (sin th/th) S + ((1 - cos th)/th^2) S^2,   t = V v,
 *    V = I + ((1 - cos th)/th^2) S + ((th - sin th)/th^3) S^2,   th = |w|.
 *  The three coefficients are summed from their Taylor series for th < 1, so
 *  a rotation of 1e-12 rad under a translation of 1e6 keeps full relative
 *  accuracy; any th is accepted (no reduction to [0, pi] is needed for exp),
 *  also beyond ~1e154, where th^2 overflows: there R and t from the half
 *  angle |w/2| and the unit axis (the rotation by the double angle, as
 *  ga_rotor_exp gives it).
 *  The result is exactly homogeneous (last row 0 0 0 1). NaN in, NaN out. */
GA_API ga_mat4 ga_se3_exp(ga_twist xi);

/** The principal log of a rigid motion: the twist xi with expm(xi^) = m and
 *  rotation angle |w| in [0, pi] (Eberly eqs. 11 and 20, and his theta = pi
 *  rule). First checks ga_se3_check(m, GA_SE3_TOL) and returns its status.
 *  The angle is atan2(|skew part|, (tr R - 1)/2), accurate at both ends; the
 *  axis comes from the skew part for th <= pi/2 (eq. 11) and from the largest
 *  column of the symmetric part (Eberly's R + I rule, used on all of
 *  (pi/2, pi]) otherwise, with the sign of the skew part. At th = pi exactly
 *  either sign is right. v = V^{-1} t with
 *    V^{-1} = I - S/2 + (1 - (th/2) cot(th/2))/th^2 S^2    (eq. 20),
 *  whose last coefficient comes from its series for th < 1/2. A matrix that is
 *  rigid only to GA_SE3_TOL is accepted as it is: the angle from atan2 and the
 *  normalised axis are those of a rotation within that tolerance of R.
 *  GA_ERR_DOMAIN if v overflows (a translation near DBL_MAX). */
GA_API GA_NODISCARD ga_status ga_se3_log(ga_mat4 m, ga_twist *out);

/** The geodesic F(t) = exp(t log(h1 h0^{-1})) h0 (Eberly eq. 21): F(0) = h0,
 *  F(1) = h1, constant speed. Any finite t is accepted (extrapolation). When
 *  h1 h0^{-1} is a half turn the shortest path is not unique; the principal
 *  log's choice is taken. GA_ERR_NOTFINITE (NaN/Inf in h0, h1 or t),
 *  GA_ERR_NOTRIGID (h0 or h1 fails ga_se3_check(., GA_SE3_TOL)) or GA_ERR_DOMAIN
 *  (the result overflows: a far extrapolation, or translations near DBL_MAX). */
GA_API GA_NODISCARD ga_status ga_se3_geodesic(ga_mat4 h0, ga_mat4 h1, double t, ga_mat4 *out);

/** The adjoint action Ad_g xi = vee(g xi^ g^{-1}) of a rigid motion
 *  g = [R, t; 0 1]: w' = R w, v' = R v + t x (R w). */
GA_API ga_twist ga_se3_adjoint(ga_mat4 g, ga_twist xi);

/* ---- general real 4x4: exp and principal log ----------------------------- */

/** expm(a) for any real 4x4, by scaling and squaring (Al-Mohy & Higham, "A
 *  new scaling and squaring algorithm for the matrix exponential", 2009,
 *  Alg. 5.1): a diagonal Pade approximant r_m, m in {3, 5, 7, 9, 13}, with m
 *  and the number s of squarings chosen from d_k = ||a^k||_1^(1/k) against
 *  Higham's theta_m (the backward error bound of that paper), so that a
 *  nonnormal a is not overscaled; r_m(a/2^s) is then squared s times.
 *  A homogeneous generator (last row 0) gives a result whose last row is
 *  0 0 0 1 exactly. An upper quasi-triangular a (a triangular matrix, an
 *  embedded 1x1 or 2x2) has its diagonal blocks, and the superdiagonal
 *  between two 1x1 blocks, recomputed in closed form after every squaring
 *  (Al-Mohy & Higham 2009, sec. 2), as scipy does for triangular input.
 *  docs/matrices.md, "The algorithms of expm and logm", has the details.
 *  Refuses: GA_ERR_NOTFINITE if a holds NaN/Inf; GA_ERR_DOMAIN if the result
 *  overflows (it is not representable in double). */
GA_API GA_NODISCARD ga_status ga_mat4_expm(ga_mat4 a, ga_mat4 *out);

/** ga_mat4_logm takes Eberly's closed form (as ga_se3_log) for a homogeneous
 *  matrix whose 3x3 block R has max |R^T R - I|_ij <= this, det R > 0 and a
 *  rotation angle above pi/2: 16 DBL_EPSILON, rounding. */
#define GA_MAT4_LOGM_RIGID_TOL 0x1p-48

/** ga_mat4_logm reports GA_ERR_DOMAIN for a complex pair of eigenvalues
 *  lambda with negative real part and |Im lambda| <= this times |lambda|:
 *  8 DBL_EPSILON, within the rounding of the Schur form of the negative real
 *  axis, where the sign of the imaginary part (and of the log) is noise. */
#define GA_MAT4_LOGM_AXIS_TOL 0x1p-49

/** The principal log of a real 4x4 (the log whose eigenvalues have imaginary
 *  parts in (-pi, pi)), by the Schur-based inverse scaling and squaring of
 *  Al-Mohy & Higham ("Improved inverse scaling and squaring algorithms for
 *  the matrix logarithm", 2012, Alg. 4.1), in real arithmetic: the real
 *  Schur form (of A - I, so that a matrix near I keeps relative accuracy, or
 *  of A when an eigenvalue has modulus below 1/2), square roots
 *  T_k = T^(1/2^k) until T_k - I is within theta_8 = 0.3667 (the paper's
 *  Table 2.1), then log T = 2^k r_8(T_k - I), r_8 the [8/8] Pade approximant,
 *  with the diagonal blocks recomputed in closed form. A homogeneous
 *  A = [B t; 0 1] gives a log whose last row is 0 exactly. A rigid motion
 *  (within GA_MAT4_LOGM_RIGID_TOL) turning by more than pi/2 takes Eberly's
 *  closed form instead (as ga_se3_log), exact to rounding up to the half
 *  turn. docs/matrices.md, "The algorithms of expm and logm", has the
 *  details.
 *  Refuses: GA_ERR_NOTFINITE on NaN/Inf; GA_ERR_DOMAIN for a real eigenvalue
 *  < 0 or a complex pair within GA_MAT4_LOGM_AXIS_TOL of the negative real
 *  axis (an exact half turn included), and for nothing else; GA_ERR_SINGULAR
 *  for an eigenvalue 0 or a numerically singular a (as ga_mat4_inverse)
 *  whose determinant is not negative (one with det < 0 has a negative real
 *  eigenvalue however ill-conditioned it is: GA_ERR_DOMAIN).
 *  Accuracy: there is no backward-error test: a conditioning-limited result
 *  (a general matrix near a half turn, error about eps / (pi - th)) is
 *  returned, not refused. */
GA_API GA_NODISCARD ga_status ga_mat4_logm(ga_mat4 a, ga_mat4 *out);

#ifdef __cplusplus
}
#endif
#endif
