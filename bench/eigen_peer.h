/* bench/eigen_peer.h: the Eigen peer of garotor-bench, callable from C.
 *
 * What a user without garotor would write with Eigen 3: the general matrix
 * exponential and logarithm of unsupported/Eigen/MatrixFunctions, and the
 * decoupled pose interpolation most code uses (Quaterniond::slerp for the
 * rotation, linear interpolation for the translation). Built only where
 * Eigen 3 is found (bench/meson.build defines GAROTOR_BENCH_EIGEN then).
 *
 * Matrices are 16 doubles, row-major (docs/conventions.md). A pose is 7 doubles,
 * x y z qx qy qz qw (the pose text order of docs/conventions.md).
 */
#ifndef GAROTOR_BENCH_EIGEN_PEER_H
#define GAROTOR_BENCH_EIGEN_PEER_H

#ifdef __cplusplus
extern "C" {
#endif

/** out = (Matrix4d a).exp(), MatrixFunctions' scaling and squaring with Pade. */
void garotor_eigen_expm(const double a[16], double out[16]);

/** out = (Matrix4d a).log(), MatrixFunctions' Schur-Parlett logarithm. */
void garotor_eigen_logm(const double a[16], double out[16]);

/** The pose between k0 (u = 0) and k1 (u = 1): rotation q0.slerp(u, q1),
 *  translation (1 - u) t0 + u t1. */
void garotor_eigen_slerp_lerp(const double k0[7], const double k1[7], double u, double out[7]);

/** "3.4.0": the Eigen version the peer was compiled against. */
const char *garotor_eigen_version(void);

#ifdef __cplusplus
}
#endif
#endif
