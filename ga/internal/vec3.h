/* ga/internal/vec3.h (internal, not installed): small helpers on ga_vec3,
 * the one place for them in the library (prefix ga__v3). Each is the plain
 * formula, in this order of operations, so that callers keep their rounding
 * (the build passes -ffp-contract=off: no product is fused into a sum).
 */
#ifndef GA_INTERNAL_VEC3_H
#define GA_INTERNAL_VEC3_H

#include <garotor/mv.h>
#include <garotor/types.h>
#include <math.h>

static inline ga_vec3 ga__v3(double x, double y, double z)
{
    ga_vec3 r = {x, y, z};
    return r;
}
/* the e1, e2, e3 part of a multivector */
static inline ga_vec3 ga__v3_of_mv(ga_mv X)
{
    return ga__v3(X.c[GA_BLADE_E1], X.c[GA_BLADE_E2], X.c[GA_BLADE_E3]);
}
static inline ga_vec3 ga__v3_add(ga_vec3 a, ga_vec3 b) { return ga__v3(a.x + b.x, a.y + b.y, a.z + b.z); }
static inline ga_vec3 ga__v3_sub(ga_vec3 a, ga_vec3 b) { return ga__v3(a.x - b.x, a.y - b.y, a.z - b.z); }
/* k a */
static inline ga_vec3 ga__v3_scale(ga_vec3 a, double k) { return ga__v3(k * a.x, k * a.y, k * a.z); }
/* a / k, divided: 1/k overflows for a subnormal k, and a / k rounds once */
static inline ga_vec3 ga__v3_div(ga_vec3 a, double k) { return ga__v3(a.x / k, a.y / k, a.z / k); }
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
/* |a| the same way, scaled by the largest component m first (the rotor's
 * norm; its bits differ from ga__v3_norm's). Divided by m, not multiplied by
 * 1/m, which overflows to Inf for a subnormal m. */
static inline double ga__v3_norm_scaled(ga_vec3 a)
{
    double m = fmax(fabs(a.x), fmax(fabs(a.y), fabs(a.z)));
    if (m == 0.0 || !isfinite(m))
        return m;
    a = ga__v3_div(a, m);
    return m * sqrt(ga__v3_dot(a, a));
}

#endif
