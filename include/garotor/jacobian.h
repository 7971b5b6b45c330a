/* garotor/jacobian.h: Lie-group Jacobians of rigid motions, as estimation
 * code expects them from manif, gtsam and Sophus: the right and left
 * Jacobians of exp and their inverses, the small and the large adjoint, and
 * the Jacobians of compose, inverse, between, act (a point) and log, for
 * both representations of SE(3): rotors (ga_rotor) and 4x4 matrices
 * (ga_mat4). The two give the same matrices to rounding. The same set for
 * the affine group of 4x4 matrices (below, with its own conventions).
 *
 * Conventions (docs/conventions.md, "Jacobians"):
 *   - a tangent vector is a twist in garotor's order (wx, wy, wz, vx, vy, vz),
 *     angular part first (gtsam's order; manif and Sophus put v first);
 *   - X (+) tau = X exp(tau) (right, local perturbation, manif's and gtsam's
 *     default) or exp(tau) X (left, global); a Jacobian of f for a side is
 *     the matrix J with f(X (+) tau) = f(X) (+) J tau + O(|tau|^2), (+)
 *     taken on the same side for the output (plain addition for a vector:
 *     the point of act, the twist of log, the argument of exp);
 *   - a 6x6 matrix is row-major, m[6*row + col]; a 3x6 m[6*row + col]; a
 *     3x3 m[3*row + col];
 *   - between(A, B) = A^-1 B (gtsam's and manif's).
 * The closed forms (Barfoot and Furgale 2014, eqs. 100-102; Sola, Deray and
 * Atchuthan 2018, appendix D) are written out in docs/conventions.md; series
 * replace them for rotation angles below 1, so each keeps its relative
 * accuracy at 0.
 */
#ifndef GAROTOR_JACOBIAN_H
#define GAROTOR_JACOBIAN_H

#include "types.h"
#include "rotor.h"

#ifdef __cplusplus
extern "C" {
#endif

/** A 6x6 matrix, row-major: m[6*row + col]. */
typedef struct {
    double m[36];
} ga_mat6;

/** A 3x6 matrix, row-major: m[6*row + col]. */
typedef struct {
    double m[18];
} ga_mat36;

/** A 3x3 matrix, row-major: m[3*row + col]. */
typedef struct {
    double m[9];
} ga_mat3;

/** The side of a perturbation: X exp(tau) (right, local, the default of
 *  manif and gtsam) or exp(tau) X (left, global). */
typedef enum { GA_JAC_RIGHT, GA_JAC_LEFT } ga_jac_side;

/* ---- the Lie algebra: the same for rotors and matrices ------------------ */

/** The small adjoint ad(xi), the matrix of eta -> [xi, eta]:
 *  [[w]x, 0; [v]x, [w]x]. */
GA_API ga_mat6 ga_twist_ad(ga_twist xi);

/** The right Jacobian of exp, J_r(xi) = sum_k (-ad xi)^k / (k+1)!:
 *  exp(xi + d) = exp(xi) exp(J_r(xi) d) + O(|d|^2) (gtsam's
 *  Pose3::ExpmapDerivative, manif's rjac). Any finite xi; NaN in, NaN out. */
GA_API ga_mat6 ga_twist_jr(ga_twist xi);

/** The left Jacobian of exp, J_l(xi) = J_r(-xi) = Ad(exp xi) J_r(xi):
 *  exp(xi + d) = exp(J_l(xi) d) exp(xi) + O(|d|^2) (Sophus's leftJacobian,
 *  manif's ljac). Any finite xi; NaN in, NaN out. */
GA_API ga_mat6 ga_twist_jl(ga_twist xi);

/** The inverse of J_r(xi) in closed form. Its rotation coefficient
 *  (1 - (th/2) cot(th/2))/th^2 has poles at th = |w| = 2 pi k: the function
 *  is defined for th < 2 pi (the principal log has th <= pi). Refuses:
 *  GA_ERR_NOTFINITE for NaN/Inf, GA_ERR_DOMAIN for th >= 2 pi or a result
 *  that overflows. */
GA_API GA_NODISCARD ga_status ga_twist_jr_inverse(ga_twist xi, ga_mat6 *out);

/** The inverse of J_l(xi) (= that of J_r(-xi)); as ga_twist_jr_inverse. */
GA_API GA_NODISCARD ga_status ga_twist_jl_inverse(ga_twist xi, ga_mat6 *out);

/* ---- the group: rotors and 4x4 matrices --------------------------------- */

/** The adjoint matrix Ad(X) of a rigid motion X = [R, t; 0 1]:
 *  [R, 0; [t]x R, R], so that Ad(X) xi = ga_se3_adjoint(X, xi). m is
 *  assumed rigid (its last row is ignored). */
GA_API ga_mat6 ga_se3_adjoint_matrix(ga_mat4 m);

/** Ad(X) of a rotor, as ga_se3_adjoint_matrix of its matrix. r is assumed
 *  on the group. */
GA_API ga_mat6 ga_rotor_adjoint_matrix(ga_rotor r);

/* Every function below checks its pointers (GA_ERR_ARG for a NULL or a side
 * that is neither GA_JAC_RIGHT nor GA_JAC_LEFT), then its elements: a rotor
 * within GA_ROTOR_DRIFT_MAX of the group (ga_rotor_check) and projected onto
 * it, a matrix within GA_SE3_TOL (ga_se3_check): GA_ERR_NOTRIGID farther,
 * GA_ERR_NOTFINITE for NaN/Inf. The formulas, right / left:
 *   compose   C = A B        J_A = Ad(B^-1) / I,          J_B = I / Ad(A)
 *   inverse   A^-1           J   = -Ad(A) / -Ad(A^-1)
 *   between   A^-1 B         J_A = -Ad(B^-1 A) / -Ad(A^-1), J_B = I / Ad(A^-1)
 *   act       y = R p + t    J_A = [-R [p]x, R] / [-[y]x, I],  J_p = R
 *   log       xi = log A     J   = J_r^-1(xi) / J_l^-1(xi)  (principal log)
 */

/** The Jacobians of A B with respect to A and B. */
GA_API GA_NODISCARD ga_status ga_rotor_jac_compose(ga_rotor a, ga_rotor b, ga_jac_side side, ga_mat6 *ja,
                                                   ga_mat6 *jb);
/** The Jacobian of A^-1. */
GA_API GA_NODISCARD ga_status ga_rotor_jac_inverse(ga_rotor a, ga_jac_side side, ga_mat6 *j);
/** The Jacobians of A^-1 B with respect to A and B. */
GA_API GA_NODISCARD ga_status ga_rotor_jac_between(ga_rotor a, ga_rotor b, ga_jac_side side, ga_mat6 *ja,
                                                   ga_mat6 *jb);
/** The Jacobians of the point A p with respect to A (3x6) and p (3x3). */
GA_API GA_NODISCARD ga_status ga_rotor_jac_act(ga_rotor a, ga_vec3 p, ga_jac_side side, ga_mat36 *ja,
                                               ga_mat3 *jp);
/** The Jacobian of the principal log (ga_rotor_log's twist). At a half
 *  turn, where the principal log jumps, it is that of the branch taken. */
GA_API GA_NODISCARD ga_status ga_rotor_jac_log(ga_rotor a, ga_jac_side side, ga_mat6 *j);

/** ga_rotor_jac_compose for 4x4 rigid motions. */
GA_API GA_NODISCARD ga_status ga_se3_jac_compose(ga_mat4 a, ga_mat4 b, ga_jac_side side, ga_mat6 *ja,
                                                 ga_mat6 *jb);
/** ga_rotor_jac_inverse for 4x4 rigid motions. */
GA_API GA_NODISCARD ga_status ga_se3_jac_inverse(ga_mat4 a, ga_jac_side side, ga_mat6 *j);
/** ga_rotor_jac_between for 4x4 rigid motions. */
GA_API GA_NODISCARD ga_status ga_se3_jac_between(ga_mat4 a, ga_mat4 b, ga_jac_side side, ga_mat6 *ja,
                                                 ga_mat6 *jb);
/** ga_rotor_jac_act for 4x4 rigid motions. */
GA_API GA_NODISCARD ga_status ga_se3_jac_act(ga_mat4 a, ga_vec3 p, ga_jac_side side, ga_mat36 *ja,
                                             ga_mat3 *jp);
/** ga_rotor_jac_log for 4x4 rigid motions (ga_se3_log's twist). */
GA_API GA_NODISCARD ga_status ga_se3_jac_log(ga_mat4 a, ga_jac_side side, ga_mat6 *j);

/* ---- the affine group: homogeneous 4x4 matrices with det > 0 ------------ */

/* Its algebra element is a 4x4 X whose last row is zero (the last row of an
 * argument is ignored); its coordinates are the 12 entries of rows 0..2,
 * x[4*i + j] = X[i][j] (the group ga_group_affine's vee). A 12x12 matrix is
 * row-major, m[12*row + col]; a 3x12 m[12*row + col]. The conventions of the
 * rigid functions above hold: X (+) tau = X exp(tau) (right) or
 * exp(tau) X (left). There is no closed form: J_r(X) = phi(-ad X) and
 * J_l(X) = phi(ad X), phi(z) = (e^z - 1)/z, are summed on 12x12 matrices
 * by scaling, Taylor series and doubling (phi(2z) = phi(z)(e^z + 1)/2), the
 * inverses by Gaussian elimination with partial pivoting. For X in se(3)
 * they are the rigid ones, in these coordinates. */

/** A 12x12 matrix, row-major: m[12*row + col]. */
typedef struct {
    double m[144];
} ga_mat12;

/** A 3x12 matrix, row-major: m[12*row + col]. */
typedef struct {
    double m[36];
} ga_mat3x12;

/** The small adjoint ad(X), the matrix of Y -> X Y - Y X on the algebra. */
GA_API ga_mat12 ga_affine_ad(ga_mat4 x);

/** The right Jacobian of exp, J_r(X) = sum_k (-ad X)^k / (k+1)!:
 *  expm(X + E) = expm(X) expm(J_r(X) E) + O(|E|^2), i.e. J_r(X) E =
 *  expm(-X) L(X, E), L the Frechet derivative of expm. GA_ERR_NOTFINITE for
 *  NaN/Inf, GA_ERR_DOMAIN for a result that overflows. */
GA_API GA_NODISCARD ga_status ga_affine_jr(ga_mat4 x, ga_mat12 *out);

/** The left Jacobian of exp, J_l(X) = J_r(-X): expm(X + E) =
 *  expm(J_l(X) E) expm(X) + O(|E|^2). As ga_affine_jr. */
GA_API GA_NODISCARD ga_status ga_affine_jl(ga_mat4 x, ga_mat12 *out);

/** The inverse of J_r(X). J_r(X) is singular where two eigenvalues of X
 *  differ by 2 pi i k, k != 0: GA_ERR_SINGULAR there (a pivot of the
 *  elimination below 1e-14 of the matrix's largest entry); otherwise as
 *  ga_affine_jr. */
GA_API GA_NODISCARD ga_status ga_affine_jr_inverse(ga_mat4 x, ga_mat12 *out);

/** The inverse of J_l(X) (= that of J_r(-X)); as ga_affine_jr_inverse. */
GA_API GA_NODISCARD ga_status ga_affine_jl_inverse(ga_mat4 x, ga_mat12 *out);

/* The group's functions check their pointers (GA_ERR_ARG for a NULL or a
 * side that is neither GA_JAC_RIGHT nor GA_JAC_LEFT), then each element A:
 * GA_ERR_NOTFINITE for NaN/Inf, GA_ERR_DOMAIN for a last row farther than
 * 1e-12 from 0 0 0 1 or det < 0, GA_ERR_SINGULAR for a singular A (as
 * ga_mat4_inverse). The last row is then taken as 0 0 0 1 exactly. The
 * formulas are the rigid ones (above) with the affine Ad and, for act,
 * right J_A[i][4k+l] = M[i][k] p~[l], left J_A[i][4k+l] = delta_ik y~[l]
 * (M the linear part of A, p~ = (p, 1), y~ = (A p, 1)), J_p = M. */

/** The adjoint matrix Ad(A), the matrix of Y -> A Y A^-1 on the algebra. */
GA_API GA_NODISCARD ga_status ga_affine_adjoint_matrix(ga_mat4 a, ga_mat12 *out);
/** The Jacobians of A B with respect to A and B. */
GA_API GA_NODISCARD ga_status ga_affine_jac_compose(ga_mat4 a, ga_mat4 b, ga_jac_side side, ga_mat12 *ja,
                                                    ga_mat12 *jb);
/** The Jacobian of A^-1. */
GA_API GA_NODISCARD ga_status ga_affine_jac_inverse(ga_mat4 a, ga_jac_side side, ga_mat12 *j);
/** The Jacobians of A^-1 B with respect to A and B. */
GA_API GA_NODISCARD ga_status ga_affine_jac_between(ga_mat4 a, ga_mat4 b, ga_jac_side side, ga_mat12 *ja,
                                                    ga_mat12 *jb);
/** The Jacobians of the point A p with respect to A (3x12) and p (3x3). */
GA_API GA_NODISCARD ga_status ga_affine_jac_act(ga_mat4 a, ga_vec3 p, ga_jac_side side, ga_mat3x12 *ja,
                                                ga_mat3 *jp);
/** The Jacobian of the principal log (ga_mat4_logm): J_r(X)^-1 / J_l(X)^-1
 *  at X = logm(A); ga_mat4_logm's refusals (an eigenvalue on the negative
 *  real axis) and ga_affine_jr_inverse's. */
GA_API GA_NODISCARD ga_status ga_affine_jac_log(ga_mat4 a, ga_jac_side side, ga_mat12 *j);

#ifdef __cplusplus
}
#endif
#endif
