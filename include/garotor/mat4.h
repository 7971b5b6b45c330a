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
 * Two implementations of exp and log live here and are tested against each
 * other (tests/test_mat4.c): the SE(3) closed forms (fast, exactly rigid, full
 * relative accuracy as theta -> 0 and theta -> pi) and the general ones for any
 * real 4x4 matrix (scaling and squaring with Pade for exp, inverse scaling and
 * squaring for log), which the affine group uses for scalings and shears.
 */
#ifndef GAROTOR_MAT4_H
#define GAROTOR_MAT4_H

#include "types.h"

#ifdef __cplusplus
extern "C" {
#endif

/** The rigidity tolerance of docs/conventions.md: ga_se3_log and ga_se3_geodesic accept
 *  a matrix m when ga_se3_check(m, GA_SE3_TOL) is GA_OK. */
#define GA_SE3_TOL 1e-9
/** The normalisation tolerance (docs/conventions.md, "Keys near the group"):
 *  ga_se3_normalize and ga_quat_normalize accept an input this far from the
 *  group and project it onto it; `garotor interp --normalize` uses it. */
#define GA_SE3_NORMALIZE_TOL 1e-3

/* ---- plain 4x4 algebra ------------------------------------------------- */

/** The identity I. */
ga_mat4 ga_mat4_identity(void);

/** The product a*b (b acts first, then a). */
ga_mat4 ga_mat4_mul(ga_mat4 a, ga_mat4 b);

/** The inverse of a general 4x4, by Gaussian elimination with partial pivoting.
 *  GA_ERR_NOTFINITE if a holds NaN or Inf. GA_ERR_SINGULAR if a is numerically
 *  singular: a pivot is at most 4*DBL_EPSILON times the largest entry both for
 *  a as given and after exact power-of-2 row and column equilibration (so an
 *  affine [R, t; 0 1] with |t| = 1e16 or diag(1e-20, 1, 1, 1) is invertible
 *  and a rank-deficient matrix is not), or if the inverse overflows. */
int ga_mat4_inverse(ga_mat4 a, ga_mat4 *out);

/** The 1-norm, max_j sum_i |a_ij| (the largest column sum). */
double ga_mat4_norm1(ga_mat4 a);

/* ---- the Lie algebra se(3) ---------------------------------------------- */

/** xi^ = [[w]x, v; 0 0 0 0] (Eberly eqs. 8 and 19). */
ga_mat4 ga_twist_hat(ga_twist xi);

/** The inverse of hat: w from the skew part of the upper-left 3x3,
 *  w = ((a21 - a12)/2, (a02 - a20)/2, (a10 - a01)/2), and v = (a03, a13, a23).
 *  Reading the skew part makes vee(logm(M)) the nearest twist when the 3x3
 *  block is skew only to rounding. */
ga_twist ga_twist_vee(ga_mat4 a);

/* ---- the group SE(3) ---------------------------------------------------- */

/** Is m a rigid motion [[R, t]; [0 0 0 1]] (Eberly eq. 17)? GA_ERR_NOTFINITE if m
 *  holds NaN or Inf; GA_ERR_NOTRIGID unless max |R^T R - I|_ij <= tol, det R > 0
 *  and the last row is 0 0 0 1 to within tol (entrywise); else GA_OK. */
int ga_se3_check(ga_mat4 m, double tol);

/** The rigid motion nearest m: when ga_se3_check(m, tol) is GA_OK (rotation
 *  block with max |R^T R - I| <= tol and det R > 0, last row 0 0 0 1 to tol),
 *  out is m with its 3x3 block replaced by the nearest rotation (the
 *  orthogonal polar factor, Higham's Newton iteration R <- (R + R^-T)/2,
 *  quadratically convergent from such a start) and its last row set to
 *  0 0 0 1; the translation is kept. Otherwise the status of the check
 *  (GA_ERR_NOTRIGID, GA_ERR_NOTFINITE); tol > GA_SE3_NORMALIZE_TOL is
 *  GA_ERR_ARG. A matrix rigid to rounding comes back within 2 ulp. */
int ga_se3_normalize(ga_mat4 m, double tol, ga_mat4 *out);

/** The inverse of a rigid motion, [R^T, -R^T t; 0 1] (Eberly eq. 18). m is
 *  assumed rigid; its last row is ignored. */
ga_mat4 ga_se3_inverse(ga_mat4 m);

/** expm(xi^) in closed form (Eberly eqs. 9, 19, 20):
 *    R = I + (sin th/th) S + ((1 - cos th)/th^2) S^2,   t = V v,
 *    V = I + ((1 - cos th)/th^2) S + ((th - sin th)/th^3) S^2,   th = |w|.
 *  The three coefficients are summed from their Taylor series for th < 1, so
 *  a rotation of 1e-12 rad under a translation of 1e6 keeps full relative
 *  accuracy; any th is accepted (no reduction to [0, pi] is needed for exp).
 *  The result is exactly homogeneous (last row 0 0 0 1). NaN in, NaN out. */
ga_mat4 ga_se3_exp(ga_twist xi);

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
int ga_se3_log(ga_mat4 m, ga_twist *out);

/** The geodesic F(t) = exp(t log(h1 h0^{-1})) h0 (Eberly eq. 21): F(0) = h0,
 *  F(1) = h1, constant speed. Any finite t is accepted (extrapolation). When
 *  h1 h0^{-1} is a half turn the shortest path is not unique; the principal
 *  log's choice is taken. GA_ERR_NOTFINITE (NaN/Inf in h0, h1 or t),
 *  GA_ERR_NOTRIGID (h0 or h1 fails ga_se3_check(., GA_SE3_TOL)) or GA_ERR_DOMAIN
 *  (the result overflows: a far extrapolation, or translations near DBL_MAX). */
int ga_se3_geodesic(ga_mat4 h0, ga_mat4 h1, double t, ga_mat4 *out);

/** The adjoint action Ad_g xi = vee(g xi^ g^{-1}) of a rigid motion
 *  g = [R, t; 0 1]: w' = R w, v' = R v + t x (R w). */
ga_twist ga_se3_adjoint(ga_mat4 g, ga_twist xi);

/* ---- general real 4x4: exp and principal log ----------------------------- */

/** expm(a) for any real 4x4 by scaling and squaring (Higham, "The scaling and
 *  squaring method for the matrix exponential revisited", 2005, Alg. 2.3):
 *  the diagonal Pade approximant r_m of degree m in {3, 5, 7, 9, 13} chosen
 *  by ||a||_1 against Higham's theta_m (backward error <= 2^-53), applied to
 *  a/2^s and squared s times. The squaring is done on X = r - I as
 *  X <- 2X + X^2, which keeps relative accuracy for results near I (tiny
 *  rotations under large translations), until a diagonal entry of I + X falls
 *  below 3/4, after which plain squaring is the more accurate form.
 *  GA_ERR_NOTFINITE if a holds NaN/Inf; GA_ERR_DOMAIN if the result overflows (it
 *  is not representable in double). */
int ga_mat4_expm(ga_mat4 a, ga_mat4 *out);

/** The largest relative backward error ||expm(L) - a||_1 / ||a||_1 that
 *  ga_mat4_logm accepts for its result L. */
#define GA_LOGM_BACKWARD_TOL 1e-10

/** The principal log of a real 4x4 (the log whose eigenvalues have imaginary
 *  parts in (-pi, pi)), by inverse scaling and squaring (Higham, Functions of
 *  Matrices, 2008, ch. 11): square roots A_k = A^(1/2^k) by the scaled
 *  Denman-Beavers iteration, each polished by one Newton step (a 4x4
 *  Sylvester solve), until ||A_k - I||_1 <= 0.325; then
 *  log A = 2^k r_8(A_k - I), r_8 the [8/8] Pade approximant of log(1 + x) in
 *  partial fractions (8-point Gauss-Legendre; Higham 2001). A_k - I is carried
 *  along as (A_{k+1} + I)^{-1} (A_k - I) rather than formed by subtraction, so
 *  small parts under large ones keep relative accuracy (Al-Mohy & Higham
 *  2012). GA_ERR_NOTFINITE for NaN/Inf; GA_ERR_SINGULAR for a numerically singular
 *  a (as ga_mat4_inverse); GA_ERR_DOMAIN when there is no real principal log:
 *  an eigenvalue on the closed negative real axis (or within rounding of
 *  it), detected as a square-root iteration that meets a numerically
 *  singular matrix or does not converge. An exact half turn (eigenvalue -1)
 *  is therefore GA_ERR_DOMAIN here, while ga_se3_log handles it; near a half
 *  turn by th the error grows like eps th / sin th, the conditioning of the
 *  log of a general matrix there. Every result is verified: unless
 *  ||expm(L) - a||_1 <= GA_LOGM_BACKWARD_TOL ||a||_1 the answer is
 *  GA_ERR_DOMAIN, never a wrong log. In practice (tests/test_cross.c,
 *  tests/test_mat4.c) a rotation part within about 1e-11 rad of a half turn
 *  may be GA_ERR_DOMAIN here, and never one farther than 1e-10 rad; use
 *  ga_se3_log for rigid motions, which has no such limit. */
int ga_mat4_logm(ga_mat4 a, ga_mat4 *out);

#ifdef __cplusplus
}
#endif
#endif
