/* garotor/fit.h: least-squares spheres, planes, circles and lines through n
 * points, by the linear method of the conformal model (Dorst, "Total least
 * squares fitting of k-spheres in n-D Euclidean space using an (n+2)-D
 * isometric representation", J. Math. Imaging Vis. 50, 2014; Hildenbrand,
 * "Foundations of Geometric Algebra Computing", 2013).
 *
 * A dual sphere or plane s gives every point x the algebraic distance
 * F(x).s, zero on the object: (r^2 - |x - c|^2) / 2 for the dual sphere
 * F(c) - (r^2/2) n, m.x - d for the dual plane m + d n. The fit minimises
 * sum_i (F(x_i).s)^2 over s with s^2 = 1 (r^2 = 1 times the weight squared:
 * Pratt's normalisation): a 5x5 generalised eigenproblem, the matrix
 * sum_i F(x_i) F(x_i)^T against the metric of G(4,1), whose best solutions
 * are the fitted objects; a circle is the meet of the best two (the
 * pencil of spheres through it), a plane and a line the same problem among
 * flats. ga/fit.c solves it from a QR factor of the points, without forming
 * the matrix, about the points' centroid in units of their spread, so that
 * the result does not depend on where the points are: a fit of points 1e6
 * from the origin is as good as one about it, to the rounding of the
 * points themselves.
 *
 * What it minimises, and its bias:
 *   - planes and lines: F(x).s = m.x - d is the distance of x from the plane,
 *     so the fit is total least squares (orthogonal distances): the plane
 *     through the centroid normal to the direction of least spread, the line
 *     through it along the direction of largest spread. It is the geometric
 *     fit, unbiased;
 *   - spheres and circles: (r^2 - |x - c|^2) / (2r) = (r - |x - c|)(r + |x -
 *     c|) / (2r) weighs a point outside more than one as far inside, so the
 *     radius comes out too large: with independent noise of standard
 *     deviation sigma in every coordinate of points spread over the whole
 *     sphere or circle, the fitted r exceeds the true one by 2.5 sigma^2 / r
 *     to leading order, where the geometric fit (orthogonal distances,
 *     iterative) exceeds it by sigma^2 / r for a sphere and sigma^2 / (2r)
 *     for a circle: the linear fit's radius is larger than the geometric
 *     fit's by 1.5 sigma^2 / r (sphere) and 2 sigma^2 / r (circle). Centres
 *     agree with the geometric fit's to first order. On exact points the fit
 *     is exact, to the rounding of the points.
 *
 * Each function takes n points (const ga_vec3 *pts, not modified), writes
 * the object's parameters through its last pointers (left untouched on
 * failure) and allocates nothing. Statuses: GA_ERR_ARG for NULL pointers or
 * fewer points than the object needs, GA_ERR_NOTFINITE for NaN/Inf in a
 * point, GA_ERR_DOMAIN where the answer is not unique to the rounding of the
 * points (points that all coincide; coplanar points for a sphere, whose
 * best fit is a plane; points on a circle for a sphere, where every sphere
 * through the circle fits; collinear points for a plane or a circle; no
 * direction of largest spread for a line) or overflows.
 */
#ifndef GAROTOR_FIT_H
#define GAROTOR_FIT_H

#include "types.h"

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/** The least-squares sphere through n >= 4 points: its centre and radius.
 *  GA_ERR_DOMAIN where the best fit is a plane to the rounding of the points
 *  (coplanar points) or every sphere through a circle fits (cocircular
 *  points). */
GA_API GA_NODISCARD ga_status ga_fit_sphere(const ga_vec3 *pts, size_t n, ga_vec3 *centre, double *radius);
/** The least-squares plane through n >= 3 points: the unit normal m and the
 *  distance d of the plane m.x = d (as ga_plane_params), m's largest
 *  component positive. GA_ERR_DOMAIN for collinear points. */
GA_API GA_NODISCARD ga_status ga_fit_plane(const ga_vec3 *pts, size_t n, ga_vec3 *normal, double *distance);
/** The least-squares circle through n >= 3 points: its centre, radius and
 *  the unit normal of its plane (largest component positive).
 *  GA_ERR_DOMAIN for collinear points (the best fit is a line), and where the
 *  best two spheres meet in no real circle. */
GA_API GA_NODISCARD ga_status ga_fit_circle(const ga_vec3 *pts, size_t n, ga_vec3 *centre, double *radius,
                                            ga_vec3 *normal);
/** The least-squares line through n >= 2 points: its unit direction (largest
 *  component positive) and its point closest to the origin (as
 *  ga_line_params). GA_ERR_DOMAIN where the points coincide or have no
 *  single direction of largest spread. */
GA_API GA_NODISCARD ga_status ga_fit_line(const ga_vec3 *pts, size_t n, ga_vec3 *direction, ga_vec3 *point);

#ifdef __cplusplus
}
#endif
#endif
