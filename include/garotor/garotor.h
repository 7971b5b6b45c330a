/* garotor/garotor.h: the whole public interface of garotor, one include.
 *
 *   #include <garotor/garotor.h>   (compile with $(pkg-config --cflags --libs garotor))
 *
 * or one module, e.g. <garotor/rotor.h>. Modules, from the bottom up:
 *   version.h    GAROTOR_VERSION_MAJOR, _MINOR, _PATCH and _STRING
 *   types.h      value types (ga_vec3, ga_mat4, ga_twist) and status codes
 *   mv.h         the full 32-component multivector of G(4,1): the reference algebra
 *   conformal.h  the conformal model: n, nbar, points F(x), spheres, planes, lines
 *   rotor.h      the compact rigid-motion rotor: exp, log, screws, the bridge to
 *                matrices, quaternions and dual quaternions
 *   versor.h     the general algebra: versors (reflections, inversions, dilations,
 *                transversions) and their sandwich, exp, log and split of any
 *                bivector and rotor of G(4,1)
 *   mat4.h       4x4 matrices: SE(3) exp and log (Eberly), general expm and logm
 *   group.h      the Lie-group interface the schemes are written against
 *   path.h       interpolation schemes through key poses, and their evaluators
 */
#ifndef GAROTOR_H
#define GAROTOR_H

#include <garotor/version.h>
#include "types.h"
#include "mv.h"
#include "conformal.h"
#include "rotor.h"
#include "versor.h"
#include "mat4.h"
#include "group.h"
#include "path.h"

#endif
