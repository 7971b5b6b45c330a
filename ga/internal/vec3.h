/* ga/internal/vec3.h (internal, not installed): small helpers on ga_vec3,
 * the one place for them in ga/ (prefix ga__v3). Each is the plain formula,
 * in this order of operations, so that callers keep their rounding.
 */
#ifndef GA_INTERNAL_VEC3_H
#define GA_INTERNAL_VEC3_H

#include <garotor/types.h>
#include <math.h>

static inline ga_vec3 ga__v3(double x, double y, double z)
{
    ga_vec3 r = {x, y, z};
    return r;
}
static inline double ga__v3_dot(ga_vec3 a, ga_vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static inline ga_vec3 ga__v3_cross(ga_vec3 a, ga_vec3 b)
{
    return ga__v3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
/* s x + y */
static inline ga_vec3 ga__v3_axpy(double s, ga_vec3 x, ga_vec3 y)
{
    return ga__v3(s * x.x + y.x, s * x.y + y.y, s * x.z + y.z);
}
/* |a| without overflow or underflow of the squares */
static inline double ga__v3_norm(ga_vec3 a) { return hypot(hypot(a.x, a.y), a.z); }

#endif
