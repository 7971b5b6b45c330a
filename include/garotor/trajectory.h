/* garotor/trajectory.h: trajectories of rigid motions compared and fitted,
 * as `garotor eval` and `garotor fit` do (docs/tool.md) and the Python
 * module's evaluate, ape, rpe, align and fit (docs/python.md).
 *
 * Evaluation, in evo's definitions (evo.core.sync, evo.core.metrics,
 * evo.core.geometry; Grupp, "evo: Python package for the evaluation of
 * odometry and SLAM", 2017):
 *   - association by time: each stamp of the trajectory with fewer poses
 *     (the estimate when both have as many) goes to the nearest stamp of the
 *     other, kept when they are at most max_diff apart;
 *   - alignment of the estimate onto the reference: Umeyama's least squares
 *     over the positions (1991), SE(3) or Sim(3), solved through Horn's unit
 *     quaternion (1987);
 *   - the absolute pose error APE_i = est_i^-1 ref_i and the relative pose
 *     error RPE = (Q_i^-1 Q_j)^-1 (P_i^-1 P_j), Q the reference, P the
 *     estimate, j = i + delta; each as its translation part |t| and its
 *     rotation angle;
 *   - the statistics evo prints (max, mean, median, min, rmse, sse, std) as
 *     numpy computes them.
 *
 * Fitting: the least-squares uniform cumulative cubic B-spline on SE(3)
 * (Lovegrove, Patron-Perez, Sibley 2013; Sommer et al. 2020), the spline of
 * path.h's GA_SCHEME_BSPLINE, through noisy poses at any stamps: control
 * poses X_j at the knots c_j = t_0 + (j - 1) h (t_0 the first key's time),
 * fitted by Levenberg-Marquardt to the residuals log(S(t_k)^-1 Z_k) (a twist:
 * radians and units of length weighted alike), with an optional smoothing
 * term sqrt(smooth) (log(X_j^-1 X_j+1) - log(X_j+1^-1 X_j+2)). The normal
 * equations are banded and solved by a banded Cholesky factorisation in the
 * caller's workspace.
 *
 * Poses are ga_mat4 rigid motions (a rotation block and a translation
 * column). Every function allocates nothing and writes its outputs (its last
 * pointers) only on success. Statuses: GA_ERR_ARG for a NULL pointer, a bad
 * count or option, times not strictly increasing; GA_ERR_NOTFINITE for NaN
 * or an infinity in a time or an input number; GA_ERR_DOMAIN where the
 * problem has no unique answer (said at each function).
 */
#ifndef GAROTOR_TRAJECTORY_H
#define GAROTOR_TRAJECTORY_H

#include "rotor.h" /* ga_quat, GA_SE3_NORMALIZE_TOL */
#include "types.h"

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/** The statistics evo prints for an array of errors. */
typedef struct {
    double max, mean, median, min, rmse, sse, std;
} ga_traj_stats;

/** The pose of a TUM row's last seven numbers x y z qx qy qz qw: the rotation
 *  of the quaternion, then the translation. Without normalize the quaternion
 *  must be unit to 1e-9 (else GA_ERR_NOTRIGID); with normalize, to
 *  GA_SE3_NORMALIZE_TOL, and it is normalised (ga_quat_normalize). */
GA_API GA_NODISCARD ga_status ga_traj_pose_from_tum(const double xyzq[7], int normalize, ga_mat4 *pose);

/** The TUM numbers x y z qx qy qz qw of a rigid motion, the quaternion's sign
 *  chosen so that its dot product with *prev is >= 0; *prev becomes that
 *  quaternion (start it at {1, 0, 0, 0}). A pose whose rotation block is not a
 *  rotation gives the identity quaternion. */
GA_API GA_NODISCARD ga_status ga_traj_pose_to_tum(ga_mat4 pose, ga_quat *prev, double xyzq[7]);

/** Associate two trajectories by their times t_ref[0..n_ref-1] and
 *  t_est[0..n_est-1] (each strictly increasing), as evo.core.sync does:
 *  each time of the shorter (the estimate when n_est <= n_ref) goes to the
 *  nearest time of the other (the lower index on a tie), and the pair is kept
 *  when |difference| <= max_diff (>= 0). Writes the pairs' indices, in
 *  increasing order, into ref_index and est_index (room for min(n_ref, n_est)
 *  each) and their count into *n (0 when none is kept: not an error). */
GA_API GA_NODISCARD ga_status ga_traj_associate(const double *t_ref, size_t n_ref, const double *t_est,
                                                size_t n_est, double max_diff, size_t *ref_index,
                                                size_t *est_index, size_t *n);

/** The alignment of est onto ref (n associated pairs) minimising
 *  sum |s R p_i + t - q_i|^2 over their positions p_i (est) and q_i (ref),
 *  with s = 1 unless with_scale (Umeyama 1991), through Horn's quaternion
 *  (1987): R is the top eigenvector of his symmetric 4x4 matrix (Jacobi's
 *  method) and s = tr(R^T C) / var(p), C the cross-covariance. Writes
 *  transform = [R, t; 0 1] and *scale (1 without with_scale).
 *  GA_ERR_DOMAIN when n < 3, when the rotation is not unique (the top
 *  eigenvalue is double to 1e-12 of the matrix's largest entry: positions on
 *  one line, or fewer than 3 distinct), or, with_scale, when the estimate's
 *  positions do not spread. */
GA_API GA_NODISCARD ga_status ga_traj_align(const ga_mat4 *ref, const ga_mat4 *est, size_t n, int with_scale,
                                            ga_mat4 *transform, double *scale);

/** out[k] = transform [R_k, scale t_k; 0 1] for in[k] = [R_k, t_k; 0 1],
 *  k < n: the estimate as evo aligns it (the translation scaled, then moved).
 *  out may be in. */
GA_API GA_NODISCARD ga_status ga_traj_transform(ga_mat4 transform, double scale, const ga_mat4 *in, size_t n,
                                                ga_mat4 *out);

/** The rotation angle of m's 3x3 block in [0, pi]:
 *  atan2(|vee(R - R^T)| / 2, (tr R - 1) / 2). */
GA_API double ga_traj_angle(ga_mat4 m);

/** The absolute pose errors of n associated (and aligned) pairs:
 *  trans_err[i] = |t(est_i) - t(ref_i)| and rot_err[i] = angle_unit times the
 *  rotation angle of est_i^-1 ref_i (angle_unit 1 for radians, 180 / pi for
 *  degrees; > 0). n >= 1. */
GA_API GA_NODISCARD ga_status ga_traj_ape(const ga_mat4 *ref, const ga_mat4 *est, size_t n, double angle_unit,
                                          double *trans_err, double *rot_err);

/** How many relative pose errors ga_traj_rpe writes for n poses: the pairs
 *  (i, i + delta), i = 0, delta, 2 delta, ... (consecutive), or every i with
 *  all_pairs; 0 when delta is 0 or none fits. */
GA_API size_t ga_traj_rpe_count(size_t n, size_t delta, int all_pairs);

/** The relative pose errors of n associated (and aligned) pairs, for the
 *  pairs ga_traj_rpe_count counts (which must be >= 1, else GA_ERR_ARG):
 *  E = (Q_i^-1 Q_j)^-1 (P_i^-1 P_j), Q = ref, P = est; trans_err the length
 *  of E's translation, rot_err angle_unit times its rotation angle. */
GA_API GA_NODISCARD ga_status ga_traj_rpe(const ga_mat4 *ref, const ga_mat4 *est, size_t n, size_t delta,
                                          int all_pairs, double angle_unit, double *trans_err,
                                          double *rot_err);

/** The statistics of err[0..n-1], n >= 1, as numpy computes them: the mean
 *  and sse summed in index order, the median the mean of the two middle
 *  values for even n, std the population deviation. err is sorted in place
 *  (increasing). */
GA_API GA_NODISCARD ga_status ga_traj_statistics(double *err, size_t n, ga_traj_stats *stats);

/** The most knot intervals a fitted spline may have. */
#define GA_TRAJ_FIT_MAX_SEGMENTS 1000000

/** The number of control poses of the spline with knots spacing apart
 *  (> 0) over keys spanning duration (>= 0) from the first key:
 *  max(1, ceil(duration / spacing)) + 3. GA_ERR_DOMAIN when that is over
 *  GA_TRAJ_FIT_MAX_SEGMENTS intervals. */
GA_API GA_NODISCARD ga_status ga_traj_fit_count(double duration, double spacing, size_t *n_controls);

/** Bytes of workspace ga_traj_fit_bspline needs for n_controls control poses
 *  (aligned for double); 0 if n_controls < 4 or the size overflows. */
GA_API size_t ga_traj_fit_workspace_size(size_t n_controls);

/** Fit the spline's control poses controls[0..n_controls-1] (n_controls from
 *  ga_traj_fit_count on duration t[n-1] - t[0]) to the n >= 4 keys poses
 *  at times t (strictly increasing), knot spacing `spacing` (> 0), smoothing
 *  weight `smooth` (>= 0), in work of work_size bytes
 *  (ga_traj_fit_workspace_size). The start is the key nearest each knot;
 *  Levenberg-Marquardt runs until no step lowers the cost, a step is below
 *  1e-12 or the cost falls by less than 1e-14 of itself (at most 100
 *  iterations). GA_ERR_ARG for a small or misaligned workspace or a bad
 *  count; GA_ERR_DOMAIN when the cost is not finite (a control pose with no
 *  key near it and no smoothing). */
GA_API GA_NODISCARD ga_status ga_traj_fit_bspline(const double *t, const ga_mat4 *poses, size_t n,
                                                  double spacing, double smooth, void *work, size_t work_size,
                                                  ga_mat4 *controls, size_t n_controls);

/** The spline's pose at time t_rel after the first key (t - t_0) for the
 *  control poses controls[0..n_controls-1] (n_controls >= 4) with knots
 *  spacing apart: the cumulative cubic B-spline of the segment
 *  floor(t_rel / spacing), clamped to the first and last. */
GA_API GA_NODISCARD ga_status ga_traj_bspline_pose(const ga_mat4 *controls, size_t n_controls, double spacing,
                                                   double t_rel, ga_mat4 *pose);

/** The fitted spline at the n keys' times t (t[0] is t_0, as for
 *  ga_traj_fit_bspline): fitted[k] its pose at t[k] (ga_traj_bspline_pose of
 *  t[k] - t[0]), and the residual of key k, residuals[2k] the length of the
 *  translation of fitted[k]^-1 poses[k] and residuals[2k+1] its rotation angle
 *  (radians). */
GA_API GA_NODISCARD ga_status ga_traj_fit_residuals(const double *t, const ga_mat4 *poses, size_t n,
                                                    const ga_mat4 *controls, size_t n_controls,
                                                    double spacing, ga_mat4 *fitted, double *residuals);

#ifdef __cplusplus
}
#endif
#endif
