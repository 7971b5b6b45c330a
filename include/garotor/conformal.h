/* garotor/conformal.h: the conformal model of Euclidean 3-space in G(4,1).
 *
 * A point x of R^3 is the null vector (Wareham-Lasenby §1, the adapted Hestenes
 * mapping)
 *
 *   F(x) = (x^2 n + 2 lambda x - lambda^2 nbar) / (2 lambda^2),
 *   n = e4 + e5, nbar = e4 - e5   (n^2 = nbar^2 = 0, n.nbar = 2, §2.2),
 *
 * so F(x)^2 = 0, F(x).n = -1 and F(x).F(y) = -|x - y|^2 / (2 lambda^2). Lambda is
 * a length: the model is exact for every lambda, but a vector stored in the
 * e4/e5 basis keeps |x|^2/lambda^2 beside 1, so choose lambda near the size of
 * the scene (see GA_POINT_TOL). Everything here uses lambda = 1 unless a
 * function's name ends in _scaled.
 *
 * Objects are outer products of points ("direct" forms, grade 2 to 4), or the
 * vectors their duals are ("dual" forms, grade 1): x lies on a direct object O
 * when F(x) ^ O = 0, on a dual object o when F(x) . o = 0. Objects use lambda = 1:
 * their read-back is accurate to ~1e3 u for a scene within a factor 4 of the
 * unit length, and degrades like u s^2 beyond (s the scene size), as the e4 and
 * e5 parts of a point, (x^2 -+ 1)/2, are then stored side by side.
 *
 * Read-back functions return GA_OK, GA_ERR_NOTFINITE on NaN/Inf anywhere in the
 * input, or GA_ERR_NOTBLADE when the input is not that kind of object; on failure
 * the outputs are left untouched. Their tests are relative, to GA_POINT_TOL of
 * the input's largest coefficient, so any nonzero multiple of an object (the
 * representation is homogeneous) reads back the same.
 */
#ifndef GAROTOR_CONFORMAL_H
#define GAROTOR_CONFORMAL_H

#include "mv.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Relative tolerance of the tests in this module: a quantity that must vanish
 *  (a wrong grade, X.n of a point at infinity, the non-null part of a point...)
 *  counts as zero when it is at most GA_POINT_TOL times the largest coefficient
 *  of the input. It is far above rounding (a point computed in a few dozen
 *  operations is off by ~1e-15 of its size) and far below anything a real
 *  object of another kind shows. Consequence: a point farther than about
 *  sqrt(2 / GA_POINT_TOL) * lambda ~ 4.5e4 lambda from the origin has
 *  |X.n| below the tolerance and reads as the point at infinity; use a larger
 *  lambda for such scenes. */
#define GA_POINT_TOL 1e-9

/* ---- the basis of the model (Wareham-Lasenby §2.2) ------------------- */
/** n = e4 + e5: the point at infinity (n^2 = 0). */
GA_API ga_mv ga_mv_n(void);
/** nbar = e4 - e5: F(0) = -nbar/2, the origin up to scale (nbar^2 = 0, n.nbar = 2). */
GA_API ga_mv ga_mv_nbar(void);
/** e4 = e (squares to +1). */
GA_API ga_mv ga_mv_e4(void);
/** e5 = ebar (squares to -1). */
GA_API ga_mv ga_mv_e5(void);
/** I3 = e1 e2 e3, the Euclidean pseudoscalar (I3^2 = -1). */
GA_API ga_mv ga_mv_i3(void);
/** I5 = e1 e2 e3 e4 e5, the pseudoscalar of the dual (I5^2 = -1). */
GA_API ga_mv ga_mv_i5(void);
/** The Euclidean vector x1 e1 + x2 e2 + x3 e3 (not embedded). */
GA_API ga_mv ga_vec3_to_mv(ga_vec3 x);

/* ---- points: up and down ---------------------------------------------- */
/** F(x) with lambda = 1: x + (x^2/2) n - nbar/2 (Wareham-Lasenby §1). */
GA_API ga_mv ga_point_up(ga_vec3 x);
/** F(x) = (x^2 n + 2 lambda x - lambda^2 nbar) / (2 lambda^2) (Wareham-Lasenby §1).
 *  GA_ERR_NOTFINITE for NaN/Inf in x or lambda, GA_ERR_ARG for lambda <= 0,
 *  GA_ERR_DOMAIN when (|x|/lambda)^2 overflows. */
GA_API GA_NODISCARD ga_status ga_point_up_scaled(ga_vec3 x, double lambda, ga_mv *out);
/** The down-projection, lambda = 1: the x with X = w F(x) for some w != 0;
 *  ga_point_down_scaled(X, 1, out), with its statuses. */
GA_API GA_NODISCARD ga_status ga_point_down(ga_mv X, ga_vec3 *out);
/** The down-projection, the inverse of ga_point_up_scaled up to scale: X = w F(x)
 *  with the weight w = -X.n (w < 0 is allowed: -F(x) is the same point), and
 *  x = lambda <X>_E / w, where <X>_E is the e1 e2 e3 part.
 *  w is computed as (|<X>_E|^2 + (X.n)^2) / (2 X5), X5 the e5 coefficient,
 *  which equals -X.n exactly when X is null but keeps full relative accuracy
 *  far from the origin, where -X.n = X5 - X4 cancels.
 *  Status: GA_ERR_NOTFINITE on NaN/Inf in X or lambda, GA_ERR_ARG for lambda <= 0,
 *  GA_ERR_NOTPOINT when X is not a finite point, relative to s = max |coefficient|:
 *  a part of grade other than 1 above GA_POINT_TOL s, |X.n| <= GA_POINT_TOL s
 *  (the point at infinity, or X = 0), or X farther than GA_POINT_TOL s from
 *  w F(x) (X not null: X - w F(x) = 0 exactly when X.X = 0); GA_ERR_DOMAIN when
 *  x overflows (a lambda near DBL_MAX). */
GA_API GA_NODISCARD ga_status ga_point_down_scaled(ga_mv X, double lambda, ga_vec3 *out);

/* ---- objects built from points (direct forms) -------------------------- */
/** Point pair F(a) ^ F(b) (a bivector). */
GA_API ga_mv ga_pointpair_from_points(ga_vec3 a, ga_vec3 b);
/** Circle through a, b, c: F(a) ^ F(b) ^ F(c) (a trivector). */
GA_API ga_mv ga_circle_from_points(ga_vec3 a, ga_vec3 b, ga_vec3 c);
/** Line through a and b: F(a) ^ F(b) ^ n (a trivector; the circle through infinity). */
GA_API ga_mv ga_line_from_points(ga_vec3 a, ga_vec3 b);
/** Sphere through a, b, c, d: F(a) ^ F(b) ^ F(c) ^ F(d) (a 4-vector). */
GA_API ga_mv ga_sphere_from_points(ga_vec3 a, ga_vec3 b, ga_vec3 c, ga_vec3 d);
/** Plane through a, b, c: F(a) ^ F(b) ^ F(c) ^ n (a 4-vector; the sphere through infinity). */
GA_API ga_mv ga_plane_from_points(ga_vec3 a, ga_vec3 b, ga_vec3 c);

/* ---- dual forms (vectors) --------------------------------------------- */
/** Dual sphere s = F(c) - (r^2/2) n: F(x).s = (r^2 - |x - c|^2) / 2, zero on the sphere.
 *  Its e4 and e5 coefficients, (|c|^2 - r^2 -+ 1) / 2, come from |c|^2 - r^2
 *  carried exactly: e5 rounded once and e4 = e5 - 1 exactly where |e5| < 2^53
 *  (the weight e5 - e4 exactly 1), each rounded once beyond; so a sphere
 *  through the origin far out keeps its weight. Where |c|^2 - r^2 passes
 *  about 2^54 (a unit sphere 1.3e8 out, or one of radius 1.3e8 about the
 *  origin) the weight is below the spacing of e4 and e5 and may round to 0:
 *  what is stored is then a plane (the plane at infinity for a centre near
 *  the origin), and read back as one (object.h, "Accuracy"); hold such
 *  spheres about a local origin (ga_point_up_scaled, object.h). */
GA_API ga_mv ga_sphere_dual(ga_vec3 centre, double radius);
/** Dual plane p = m + d n, m a unit normal: F(x).p = m.x - d, zero on the plane
 *  m.x = d (d is the signed distance from the origin along m). */
GA_API ga_mv ga_plane_dual(ga_vec3 normal, double distance);

/* ---- read-back ----------------------------------------------------------- */
/** Centre and radius of a sphere, given either form, told apart by grade: a
 *  vector is a dual sphere (w F(c) - (w r^2/2) n), a 4-vector a direct one (its
 *  dual is read). Radius 0 (a point) is accepted. GA_ERR_NOTBLADE for any other
 *  grade, for a plane (|S.n| <= GA_POINT_TOL s after dualising) or an imaginary
 *  sphere (r^2 < 0). */
GA_API GA_NODISCARD ga_status ga_sphere_params(ga_mv S, ga_vec3 *centre, double *radius);
/** Unit normal m and distance d (the plane m.x = d) of a plane, given either
 *  form, told apart by grade: a vector is a dual plane w (m + d n), a 4-vector
 *  a direct one. Orientation: ga_plane_from_points(a, b, c) reads back m along
 *  (b - a) x (c - a); a dual plane w (m + d n) reads back m for w > 0.
 *  GA_ERR_NOTBLADE for any other grade, a sphere (X.n != 0) or the plane at
 *  infinity (no normal). */
GA_API GA_NODISCARD ga_status ga_plane_params(ga_mv P, ga_vec3 *normal, double *distance);
/** Unit direction u and the point p of a line closest to the origin.
 *  A line is L = w (u e45 + (p ^ u) ^ n), |u| = 1; ga_line_from_points(a, b) reads back u
 *  along b - a. GA_ERR_NOTBLADE if L is not a trivector of that form (a circle, a
 *  trivector not a blade, u = 0). */
GA_API GA_NODISCARD ga_status ga_line_params(ga_mv L, ga_vec3 *direction, ga_vec3 *closest);
/** The two points of a point pair: ga_pointpair_from_points(a, b) reads back a, b in that
 *  order (a negative multiple swaps them). Read as the midpoint and half-distance
 *  of the carrier sphere and the direction of the line PP ^ n.
 *  GA_ERR_NOTBLADE for any other grade, an imaginary or degenerate pair (PP^2 <= 0),
 *  or a flat point F(a) ^ n. */
GA_API GA_NODISCARD ga_status ga_pointpair_points(ga_mv PP, ga_vec3 *a, ga_vec3 *b);
/** Centre, radius and unit normal of a circle (a trivector). The normal is that
 *  of the plane C ^ n: for ga_circle_from_points(a, b, c), along (b - a) x (c - a).
 *  GA_ERR_NOTBLADE for any other grade, a line, or an imaginary circle. */
GA_API GA_NODISCARD ga_status ga_circle_params(ga_mv C, ga_vec3 *centre, double *radius, ga_vec3 *normal);

#ifdef __cplusplus
}
#endif
#endif
