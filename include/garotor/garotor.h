/* garotor/garotor.h: the whole public interface of garotor, one include.
 *
 *   #include <garotor/garotor.h>   (compile with $(pkg-config --cflags --libs garotor))
 *
 * or one module, e.g. <garotor/rotor.h>. Modules, from the bottom up:
 *   version.h    GAROTOR_VERSION_MAJOR, _MINOR, _PATCH and _STRING
 *   export.h     GA_API and GA_NODISCARD, the markers on public declarations
 *   types.h      value types (ga_vec3, ga_mat4, ga_twist) and status codes
 *   numtext.h    doubles as the shortest decimal that reads back the same
 *   mv.h         the full 32-component multivector of G(4,1): the reference algebra,
 *                its inverse, regressive and commutator products, projections,
 *                and exp, log, split and powers of any bivector and rotor of G(4,1)
 *   conformal.h  the conformal model: n, nbar, points F(x), spheres, planes, lines
 *   object.h     kinds and read-back of every object, meet, projection, distance,
 *                angle, the rigid motion between two objects
 *   rotor.h      the compact rigid-motion rotor: exp, log, screws, the bridge to
 *                matrices, quaternions and dual quaternions
 *   rotor_inline.h  the hot path of rotor.h inline: ga_rotor_mul_inline, ...
 *   versor.h     versors (reflections, inversions, dilations, transversions)
 *                and their sandwich
 *   mat4.h       4x4 matrices: SE(3) exp and log (Eberly), general expm and logm
 *   group.h      the Lie-group interface the schemes are written against
 *   path.h       interpolation schemes through key poses, and their evaluators
 *   fit.h        least-squares spheres, circles, planes and lines through points
 *   jacobian.h   Lie-group Jacobians of rigid motions (manif, gtsam, Sophus)
 *   trajectory.h trajectories compared (evo's APE, RPE, alignment) and fitted (B-spline)
 */
#ifndef GAROTOR_H
#define GAROTOR_H

#include <garotor/version.h>
#include "types.h"
#include "numtext.h"
#include "mv.h"
#include "conformal.h"
#include "rotor.h"
#include "rotor_inline.h"
#include "versor.h"
#include "object.h"
#include "mat4.h"
#include "group.h"
#include "path.h"
#include "fit.h"
#include "jacobian.h"
#include "trajectory.h"

#endif
