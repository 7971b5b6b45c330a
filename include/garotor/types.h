/* garotor/types.h: the small value types and status codes every module shares.
 *
 * Conventions (docs/conventions.md):
 *   - a 4x4 matrix is homogeneous, row-major, acting on column vectors (x,y,z,1);
 *   - a twist xi = (w, v) = (wx, wy, wz, vx, vy, vz) names the motion expm(xi^),
 *     xi^ = [[w]x, v; 0, 0];
 *   - a function that can fail returns a ga_status (GA_OK or a negative
 *     GA_E* code) and writes its result through its last pointer argument;
 *     on failure that result is left untouched;
 *   - such a function given NULL for a pointer argument, an output or an
 *     input (a text, times, keys, a path), returns GA_ERR_ARG before
 *     anything else and writes nothing; only the pointers its comment calls
 *     optional may be NULL (ga_path_init's velocities, the v and a of
 *     ga_path_differentiate).
 */
#ifndef GAROTOR_TYPES_H
#define GAROTOR_TYPES_H

#include "export.h"

#ifdef __cplusplus
extern "C" {
#endif

/** A point or direction of Euclidean 3-space. */
typedef struct {
    double x, y, z;
} ga_vec3;

/** A 4x4 matrix, row-major: m[4*row + col]. */
typedef struct {
    double m[16];
} ga_mat4;

/** A twist: angular part w, linear part v (the motion is expm of [[w]x, v; 0, 0]). */
typedef struct {
    ga_vec3 w, v;
} ga_twist;

/** A status: GA_OK (0) or one of the negative GA_ERR_* codes below. Every
 *  function that can fail returns one, marked GA_NODISCARD. */
typedef int ga_status;

/** Status codes. GA_OK is 0; every error is negative. */
enum {
    GA_OK = 0,
    GA_ERR_NOTFINITE = -1, /**< an input holds NaN or an infinity */
    GA_ERR_SINGULAR = -2,  /**< no inverse: a zero or non-invertible input */
    GA_ERR_NOTPOINT = -3,  /**< not a finite conformal point (X.n = 0 or X not null) */
    GA_ERR_NOTRIGID = -4,  /**< not a rigid motion (rotor or matrix) within tolerance */
    GA_ERR_DOMAIN = -5,    /**< outside the function's domain (e.g. log of a matrix
                             with an eigenvalue on the closed negative real axis) */
    GA_ERR_ARG = -6,       /**< an invalid argument (bad count, times not increasing, ...) */
    GA_ERR_NOTBLADE = -7,  /**< not an object of the expected kind (sphere, plane, line...) */
    GA_ERR_IMAGINARY = -8, /**< the right kind of round, but imaginary (r^2 < 0): no real points */
    GA_ERR_PRECISION = -9  /**< the result would not have the accuracy promised (object.h):
                             refused rather than returned with digits lost */
};

/** A short English description of a status code ("ok", "not a rigid motion", ...). */
GA_API const char *ga_status_string(ga_status status);

#ifdef __cplusplus
}
#endif
#endif
