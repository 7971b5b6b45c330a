/* garotor/group.h: the small Lie-group interface the interpolation schemes are
 * written against, and its three implementations.
 *
 * A scheme (path.h) never looks inside a group element: it composes, inverts,
 * takes exp and log, and applies the adjoint action. Writing each scheme once
 * against this interface and running it on CGA rotors and on 4x4 matrices is
 * what makes the cross-check between the two representations mean something.
 *
 * Group elements are opaque blocks of `elem_size` bytes (a ga_rotor or a
 * ga_mat4). Algebra elements are arrays of `dim` doubles:
 *   - ga_group_cga and ga_group_se3: dim 6, a twist (wx, wy, wz, vx, vy, vz);
 *     the rotor side maps it to the generator B(xi) = -1/2 (w I3 + v n)
 *     (docs/conventions.md), the matrix side to xi^ = [[w]x, v; 0, 0];
 *   - ga_group_affine: dim 12, the top three rows of a 4x4 matrix whose last
 *     row is zero (row-major), i.e. any real 3x4 [A | b].
 * Vector-space operations on algebra elements (sums, scaling) are plain
 * arithmetic on those doubles.
 */
#ifndef GAROTOR_GROUP_H
#define GAROTOR_GROUP_H

#include <stddef.h>

#include "types.h"

#ifdef __cplusplus
extern "C" {
#endif

/** The largest algebra dimension of any group here (affine: 12). */
#define GA_GROUP_MAX_DIM 12
/** The largest element size of any group here, in doubles (a 4x4 matrix). */
#define GA_GROUP_MAX_ELEM 16
/** Half-turn band (rad) of the twist groups' half-turn and branch rules
 *  (ga_group.half_turn, ga_group.branch); the branch rule also keeps the
 *  principal log of a rotation smaller than it. */
#define GA_GROUP_HALF_TURN_BAND 1e-9

typedef struct ga_group ga_group;

/** A Lie group as the schemes see it. Every function is pure (no state). The
 *  tables below are the only place that knows what a group element is: the
 *  schemes (path.h) and the tool ask these operations, never which group
 *  they run on. */
struct ga_group {
    const char *name; /**< "cga", "matrix" (SE(3)) or "affine" */
    size_t elem_size; /**< bytes of one group element */
    size_t dim;       /**< doubles in one algebra element */
    /** 1 when every element is a rigid motion and an algebra element is a
     *  twist (wx, wy, wz, vx, vy, vz) (cga, se3); 0 when elements may scale
     *  and shear and an algebra element is only meaningful as its hat, a 4x4
     *  (affine). The tool reads and writes algebra elements accordingly. */
    int rigid;
    /** out = identity */
    void (*identity)(void *out);
    /** out = a b (b first, then a, as matrices act on column vectors) */
    void (*compose)(const void *a, const void *b, void *out);
    /** out = a^-1 (for affine: GA_ERR_SINGULAR if not invertible) */
    ga_status (*inverse)(const void *a, void *out);
    /** out = exp(x); GA_ERR_NOTFINITE for NaN/Inf in x, GA_ERR_DOMAIN when the
     *  result is not representable (overflows: docs/errors.md) */
    ga_status (*exp)(const double *x, void *out);
    /** x = the principal log of g: rotation angle in [0, pi] for cga/se3;
     *  GA_ERR_DOMAIN where the group element has no principal log (affine) or
     *  the log overflows */
    ga_status (*log)(const void *g, double *x);
    /** out = Ad_g x = g x g^-1, in algebra coordinates (exp(Ad_g x) = g exp(x) g^-1) */
    void (*adjoint)(const void *g, const double *x, double *out);
    /** out = J_r(x) y, the right Jacobian (dexp) of exp at x applied to y:
     *  the body velocity g^-1 dg/ds of g(s) = exp(x + s y) at s = 0, i.e.
     *  sum_k (-ad_x)^k y / (k+1)!. The generator-space schemes of path.h need
     *  it for the velocity of exp(X(t)): g^-1 g' = J_r(X) X'. cga and se3:
     *  the closed form of the SE(3) right Jacobian; affine: the series by
     *  scaling and doubling. */
    void (*dexp)(const double *x, const double *y, double *out);
    /** Read a 4x4 homogeneous matrix into a group element, checking it
     *  (GA_ERR_NOTRIGID for cga/se3 if not a rigid motion to 1e-9; for affine
     *  the last row must be 0 0 0 1 and the determinant positive). */
    ga_status (*from_mat4)(ga_mat4 m, void *out);
    /** The 4x4 homogeneous matrix of a group element. */
    ga_mat4 (*to_mat4)(const void *g);
    /** The algebra element x as a 4x4 matrix (last row zero): the matrix whose
     *  expm is to_mat4(exp(x)). cga/se3: xi^ = [[w]x, v; 0 0 0 0]. */
    ga_mat4 (*hat)(const double *x);
    /** The inverse of hat. GA_ERR_ARG when a is not in the algebra: a last row
     *  other than 0 0 0 0 (any group), or for cga/se3 a 3x3 block that is not
     *  skew to 1e-9 relative to its largest entry (the skew part is read). */
    ga_status (*vee)(ga_mat4 a, double *x);
    /** The half-turn rule, or NULL where the principal log is unique. At a
     *  rotation of exactly pi the principal log's axis sign is arbitrary, so
     *  two representations may pick opposite screws; the schemes apply this
     *  to every log they take, making it deterministic: for cga/se3, when the
     *  angle th >= pi - GA_GROUP_HALF_TURN_BAND, x is replaced by its other
     *  branch (below) if the first component of w/th (x, y, z order) larger
     *  than 0.3 in magnitude is negative (one always is, as 3 * 0.3^2 < 1).
     *  Inside the band a motion may thus go the long way round by at most
     *  2 GA_GROUP_HALF_TURN_BAND rad. */
    void (*half_turn)(double *x);
    /** The branch rule of generator-space interpolation, or NULL where the log
     *  has one branch to offer (affine: the principal logm). x holds a log of
     *  a key; it is replaced, where the group has another log of the same
     *  element, by the one that continues prev, the previous key's
     *  generator. cga/se3: the other branch of a twist (w, v) of angle
     *  th = |w| > 0 is the angle th - 2 pi about the same axis,
     *  w' = k w, v' = k v_perp + v_par, k = (th - 2 pi)/th (v_par the part of
     *  v along w; exp(w', v') = exp(w, v) because V(w')^-1 V(w) = k across w
     *  and 1 along it, Eberly eq. 20); it is taken when the rotation
     *  quaternions q(x) = (cos(|w|/2), sin(|w|/2) w/|w|) of prev and x have a
     *  dot product below -GA_GROUP_HALF_TURN_BAND/2: W-L's rotor rule
     *  <R_i ~R_{i-1}>_0 >= 0 (consecutive keys take the shortest motion) in
     *  twist coordinates, so that cga and se3 choose alike. x is kept within
     *  the band (keys a half turn apart, where rounding would decide), for a
     *  rotation th < GA_GROUP_HALF_TURN_BAND (its other branch, a full turn
     *  less th, is |k| ~ 2 pi/th times its w and v_perp, and its axis rests on
     *  the key's rounding) and for a pure translation (th = 0, no other
     *  branch). */
    void (*branch)(const double *prev, double *x);
    /** The rotation and translation of a rigid element: q = (w, x, y, z) a
     *  unit quaternion (Hamilton's convention, either sign) and p such that
     *  the element is "rotate by q, then translate by p" (its 4x4 matrix is
     *  [Rot(q), p; 0 0 0 1]). NULL where an element is not a rotation and a
     *  translation (affine): the decoupled schemes (path.h), which
     *  interpolate the two separately, are refused there with GA_ERR_ARG. */
    void (*to_qt)(const void *g, double q[4], double p[3]);
    /** The element "rotate by q, then translate by p" (q used as given: unit
     *  to rounding); NULL where to_qt is. */
    void (*from_qt)(const double q[4], const double p[3], void *out);
};

/** CGA rotors (ga_rotor, rotor.h): the closed forms of Wareham-Lasenby. */
GA_API extern const ga_group ga_group_cga;
/** SE(3) as 4x4 matrices (ga_mat4, mat4.h): Eberly's closed forms. */
GA_API extern const ga_group ga_group_se3;
/** Invertible homogeneous 4x4 matrices with positive determinant (ga_mat4):
 *  the general matrix exp and log (Higham's scaling and squaring, inverse
 *  scaling and squaring). */
GA_API extern const ga_group ga_group_affine;

/** The group called `name` ("cga", "matrix", "affine"), or NULL. */
GA_API const ga_group *ga_group_by_name(const char *name);

/** The i-th group of the library (0, 1, 2, ...: cga, matrix, affine), NULL
 *  past the last: for tests and tools that run over every group. */
GA_API const ga_group *ga_group_nth(size_t i);

#ifdef __cplusplus
}
#endif
#endif
