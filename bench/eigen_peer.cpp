// bench/eigen_peer.cpp: the Eigen peer of garotor-bench (see eigen_peer.h).
//
// Each function is one call of what a user would write with Eigen 3: no
// caching, no precomputation across calls, the same inputs garotor gets.
#include "eigen_peer.h"

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <unsupported/Eigen/MatrixFunctions>

namespace {
typedef Eigen::Matrix<double, 4, 4, Eigen::RowMajor> Mat4RowMajor;
}

extern "C" void garotor_eigen_expm(const double a[16], double out[16])
{
    Eigen::Map<const Mat4RowMajor> in(a);
    Eigen::Matrix4d m = in;
    Eigen::Map<Mat4RowMajor> res(out);
    res = m.exp();
}

extern "C" void garotor_eigen_logm(const double a[16], double out[16])
{
    Eigen::Map<const Mat4RowMajor> in(a);
    Eigen::Matrix4d m = in;
    Eigen::Map<Mat4RowMajor> res(out);
    res = m.log();
}

extern "C" void garotor_eigen_slerp_lerp(const double k0[7], const double k1[7], double u, double out[7])
{
    // Quaterniond(w, x, y, z); the pose stores x y z qx qy qz qw
    const Eigen::Quaterniond q0(k0[6], k0[3], k0[4], k0[5]);
    const Eigen::Quaterniond q1(k1[6], k1[3], k1[4], k1[5]);
    const Eigen::Vector3d t0(k0[0], k0[1], k0[2]), t1(k1[0], k1[1], k1[2]);
    const Eigen::Quaterniond q = q0.slerp(u, q1);
    const Eigen::Vector3d t = (1.0 - u) * t0 + u * t1;
    out[0] = t.x();
    out[1] = t.y();
    out[2] = t.z();
    out[3] = q.x();
    out[4] = q.y();
    out[5] = q.z();
    out[6] = q.w();
}

#define GAROTOR_STR2(x) #x
#define GAROTOR_STR(x) GAROTOR_STR2(x)

extern "C" const char *garotor_eigen_version(void)
{
    return GAROTOR_STR(EIGEN_WORLD_VERSION) "." GAROTOR_STR(EIGEN_MAJOR_VERSION) "." GAROTOR_STR(
        EIGEN_MINOR_VERSION);
}
