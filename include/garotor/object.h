/* garotor/object.h: what a conformal object is, where two objects meet, and
 * the Euclidean questions about them (projection, distance, angle, the rigid
 * motion from one to another).
 *
 * Kinds (Dorst-Fontijne-Mann, "Geometric Algebra for Computer Science", 2007,
 * ch. 14-15): a direct blade X of grade 2, 3 or 4 is a round (point pair,
 * circle, sphere) when X ^ n != 0 and a flat (flat point, line, plane) when
 * X ^ n = 0; a vector is read as a dual sphere (X.n != 0) or a dual plane, as
 * in conformal.h. A round has a centre c and a signed squared radius r^2
 * (DFM §14.2): real (r^2 > 0), tangent (r^2 = 0: a double point, a point
 * circle, a point) or imaginary (r^2 < 0: the meet of two spheres that miss
 * each other is an imaginary circle, whose centre and r^2 are still read).
 * A flat with no finite point (the meet of parallel planes, of a line
 * parallel to a plane) is empty.
 *
 * Accuracy. GA_OK means the answer is right to the bound it states. The
 * input is taken as known to its own rounding: each coefficient to u = 2^-53
 * times the largest coefficient of its class (the blades of one grade with
 * as many factors e4 or e5), the error of its last rounding. ga_object_from_mv
 * reads the object of every multivector within that, and states in the
 * ga_object how far it can be off: err (the centre), r2_err, angle_err (the
 * direction), first-order bounds of the input's rounding and its own. They
 * are no promise about how the input was made: a chain of operations before
 * it carries its own errors, which no read-back can see.
 *   - Flats (planes, lines, flat points) keep their lengths to a few u L,
 *     L = max(1, |c| + |r|), anywhere up to 1e8 from the origin: conformal.h's
 *     constructors build about the first point and translate exactly, the meet
 *     of two flats is exact to its rounding, and a flat's e4 and e5 parts come
 *     out equal (its weight v.n, or X ^ n, exactly 0: that is what "flat" means
 *     to the read-back).
 *   - A round's weight (-X.n) is a difference of e4 and e5 coefficients of the
 *     size of its squared distance from the origin, so it is known only to u
 *     times that: a unit sphere built 1e4 from the origin has r^2 = 1 to about
 *     3 (and reads as tangent: at the scale of its distance it is a point);
 *     at 1e8 its weight 1 is stored but known only to about 1 (refused, below),
 *     and beyond about 1.3e8 (|c|^2 / 2 > 2^53) it rounds to 0 in storage: a
 *     plane as stored, and read as one.
 *   - Refused with GA_ERR_PRECISION: a weight within its uncertainty of 0 but
 *     not 0 (round and flat at once to the input's accuracy), or not known to
 *     a quarter of itself (for a circle or point pair, read about its own
 *     centre in units of its size: its weight or its carrier's; a small round
 *     far out, whose radius that leaves unknown).
 *   - Real, tangent and imaginary use the same bound: tangent when |r^2| is
 *     within max(GA_OBJECT_TANGENT_TOL L^2, r2_err).
 *   - A flat is empty (at infinity) where its weight (a plane's normal, a
 *     line's direction, a flat point's e45 part) is exactly 0 (the meets of
 *     parallel flats give it so: ga_mv_meet, ga_mv_meet_rel); refused with
 *     GA_ERR_PRECISION where the weight is within its uncertainty of 0 but
 *     not 0; otherwise a finite flat however far out, with its bounds (a
 *     line meeting a plane 3e9 from the origin, or 1e14 out at a grazing
 *     angle of 1e-14, is that flat point).
 *   - The functions below that state no bound of their own (ga_point_project,
 *     _reject, _distance, ga_object_angle, ga_rotor_between) promise
 *     GA_OBJECT_TOL: they refuse with GA_ERR_PRECISION an object whose err
 *     exceeds GA_OBJECT_TOL L or whose r2_err exceeds GA_OBJECT_TOL L^2.
 * docs/numerics.md ("Objects far from the origin") has the figures.
 *
 * Local origin and length scale. The answer is to carry an origin o and a
 * length lambda with the object: a scene held "about (o, lambda)" is the
 * scene seen from o in units of lambda, x -> (x - o) / lambda, built by the
 * constructors of conformal.h from the points (x - o) / lambda (rounded to u
 * of |x| / lambda; a power of two for lambda divides exactly). Both matter:
 * o removes the cancellation of the centre's distance (|c - o|^2 beside 1),
 * lambda that of the scene's size (a sphere of radius 1e6 centred 2e6 from
 * o has e4, e5 ~ 1e12 beside the weight 1/2 when lambda = 1, just as far out).
 * Everything holds about (o, lambda) as about (0, 1), with lengths relative
 * to L_o = lambda max(1, |c - o| / lambda + |r| / lambda):
 *   - build: any constructor, on (x - o) / lambda;
 *   - bring in an object given in world coordinates (a flat loses nothing on
 *     the way; a round only keeps what it had): ga_mv_localize;
 *   - meet: ga_mv_meet of two objects about the same (o, lambda);
 *   - move: ga_rotor_apply_about (the origin moves with the object, so that
 *     a rotation about a far point puts no large translation into it);
 *   - read back: ga_object_from_mv_about, in world coordinates;
 *   - project, distance: on (x - o) / lambda, giving lambda y + o and lambda d.
 * With o within a few sizes of the scene and lambda within a factor 4 or so of
 * its size, rounds anywhere up to 1e8 from the origin (and beyond) read back to
 * a few u L and are not refused (all kinds, tangent and imaginary included).
 */
#ifndef GAROTOR_OBJECT_H
#define GAROTOR_OBJECT_H

#include "rotor.h"

#ifdef __cplusplus
extern "C" {
#endif

/** The kind of a conformal object. */
enum {
    GA_OBJECT_EMPTY = 0, /**< no finite point: a flat at infinity (parallel planes' meet) */
    GA_OBJECT_FLATPOINT, /**< F(p) ^ n: a point with the point at infinity (a line meeting a plane) */
    GA_OBJECT_LINE,      /**< F(a) ^ F(b) ^ n */
    GA_OBJECT_PLANE,     /**< F(a) ^ F(b) ^ F(c) ^ n, or a dual plane (a vector) */
    GA_OBJECT_POINTPAIR, /**< F(a) ^ F(b) */
    GA_OBJECT_CIRCLE,    /**< F(a) ^ F(b) ^ F(c) */
    GA_OBJECT_SPHERE     /**< F(a) ^ F(b) ^ F(c) ^ F(d), or a dual sphere (a vector) */
};

/** Whether a round is real, tangent or imaginary (flats are real). */
enum {
    GA_REALITY_REAL = 0, /**< r^2 > 0, or a flat */
    GA_REALITY_TANGENT,  /**< |r^2| <= GA_OBJECT_TANGENT_TOL L^2: a double point, a point circle, a point */
    GA_REALITY_IMAGINARY /**< r^2 < 0 beyond that */
};

/** Relative tolerance for "r^2 = 0" (tangent): |r^2| <= GA_OBJECT_TANGENT_TOL L^2,
 *  L = max(1, |c|). Far above the rounding of r^2 (a few u L^2 after a meet), so
 *  objects tangent in exact arithmetic read as tangent; a round with a radius
 *  below 1e-6 L is therefore reported tangent, and its r^2 is still given. */
#define GA_OBJECT_TANGENT_TOL 1e-12

/** The accuracy promised, relative to L (above), by the functions that state
 *  no bound of their own: an object whose bounds exceed it is refused there
 *  with GA_ERR_PRECISION (ga_object_from_mv states the bounds instead). */
#define GA_OBJECT_TOL 1e-12

/** What an object is and where. For a flat point: centre is the point. Line:
 *  centre is its point closest to the origin, direction its unit direction.
 *  Plane: centre = d m (closest to the origin), direction the unit normal m
 *  (orientation as ga_plane_params). Point pair: centre the midpoint,
 *  direction from the first point to the second, r2 the squared half-distance.
 *  Circle: centre, r2, direction the unit normal of its plane. Sphere: centre,
 *  r2, direction 0. Empty: centre 0; for a flat point at infinity, direction is
 *  its direction (not normalised). */
typedef struct {
    int kind;    /**< GA_OBJECT_* */
    int reality; /**< GA_REALITY_* */
    ga_vec3 centre;
    ga_vec3 direction;
    double r2;        /**< signed squared radius of a round; 0 for a flat */
    double err;       /**< bound of the error of centre, in its length units (see "Accuracy") */
    double r2_err;    /**< bound of the error of r2 (0 for a flat) */
    double angle_err; /**< bound of the angle of direction from the exact one, radians (0 where none) */
} ga_object;

/** Classify X and read it back with its bounds ("Accuracy" above).
 *  GA_ERR_NOTFINITE on NaN/Inf, GA_ERR_SINGULAR for X = 0 (the meet of two
 *  objects in special position: coincident planes, a line in a plane),
 *  GA_ERR_NOTBLADE when X is not one of the objects above (mixed grades,
 *  grade 0 or 5, a non-blade), to GA_POINT_TOL relative (what is off the
 *  object's grade up to that is taken into its uncertainty),
 *  GA_ERR_PRECISION where round and flat cannot be told apart, GA_ERR_DOMAIN
 *  where a bound overflows. */
GA_API GA_NODISCARD ga_status ga_object_from_mv(ga_mv X, ga_object *out);

/** ga_object_from_mv of an object held about (o, lambda) (see "Local origin
 *  and length scale" above), in world coordinates: lambda c + o for the
 *  centre c of a round or flat point, the point closest to the world's origin
 *  for a plane (d m, d = lambda d_o + m.o) or a line, r^2 times lambda^2;
 *  kind, reality and direction as read about (o, lambda) (tangent relative to
 *  L_o). Codes of ga_object_from_mv on X; the bounds in world units (times lambda, and
 *  the rounding of the move). GA_ERR_NOTFINITE for NaN/Inf in o or lambda,
 *  GA_ERR_ARG for lambda <= 0, GA_ERR_DOMAIN on overflow. */
GA_API GA_NODISCARD ga_status ga_object_from_mv_about(ga_mv X, ga_vec3 origin, double lambda, ga_object *out);

/** The object X, given in world coordinates, held about (o, lambda): translated
 *  by -o (T_-o X ~T_-o), then every length divided by lambda (o -> lambda o,
 *  n -> n / lambda in the basis n, nbar; a positive multiple of the object of
 *  the points (x - o) / lambda). A flat built in world coordinates (a plane
 *  1e8 away) comes in as accurate as it was. A round keeps only what it had:
 *  where the move makes the rounding of its world form ("Accuracy" above)
 *  more than 16 times u of its local form's largest coefficient, its local
 *  read-back would claim digits the world form does not hold, and it is
 *  refused with GA_ERR_PRECISION (build such a round about the local origin
 *  instead). GA_ERR_NOTFINITE for NaN/Inf, GA_ERR_ARG for lambda <= 0,
 *  GA_ERR_DOMAIN on overflow. */
GA_API GA_NODISCARD ga_status ga_mv_localize(ga_mv X, ga_vec3 origin, double lambda, ga_mv *out);

/** The rigid motion R of an object X held about (o, lambda): R T_o X ~T_o ~R is
 *  T_o' X' ~T_o' with o' = R(o) (ga_rotor_apply) and X' = q X ~q, q the
 *  rotation of R = T_t q (lambda unchanged: a rotation about the local origin
 *  commutes with the scaling). Writes o' and X'. Exact up to the rounding of R(o)
 *  and of the rotation: no translation of the size of o enters X'.
 *  GA_ERR_NOTFINITE for NaN/Inf in R, o or X; GA_ERR_DOMAIN if o' overflows. */
GA_API GA_NODISCARD ga_status ga_rotor_apply_about(ga_rotor R, ga_vec3 origin, ga_mv X, ga_vec3 *new_origin,
                                                   ga_mv *out);

/** The meet of two objects, A* ^ B* undualised: ((A I^-1) ^ (B I^-1)) I (DFM §5.5,
 *  the meet in the whole space, as clifford's meet and ganja's dual wedge).
 *  Sphere/plane with sphere/plane: a circle or line (real, tangent, imaginary,
 *  or empty for parallel planes); sphere/plane with circle/line: a point pair or
 *  flat point. A vector argument is a dual sphere or plane (converted with
 *  ga_mv_dual). The duals are exact, and the outer product is carried in
 *  double-double and rounded once: the meet of A and B as given, to u of each
 *  coefficient, at any distance from the origin.
 *  Exactly 0 when the objects are in special position (not in general
 *  position: their grades sum to less than 5 after dualising, or they share
 *  a flat: a sphere and itself, a line in a plane, two lines through a
 *  point, coincident planes), decided to the accuracy of the inputs: every
 *  coefficient of the outer product within what the inputs' uncertainty
 *  (first order) and the product's rounding can make of it. An input is
 *  taken as known to 32 u (the roundings of a construction of a few dozen
 *  operations) of the largest coefficient of each class ("Accuracy" above)
 *  and, for a round with a centre c and radius r that ga_object_from_mv
 *  reads, of each class of it held about c in units of a power of two near
 *  max(1, r), moved back (the terms a constructor rounds, which a sphere
 *  through the origin sums to near 0); a point pair, circle or line
 *  further from a blade than that has it scaled to what its defect shows.
 *  So ga_object_from_mv of the meet says GA_ERR_SINGULAR there, never an
 *  object read from a rounding residue; ga_mv_meet_rel gives their meet.
 *  Two flats (A ^ n = B ^ n = 0 exactly) meet in a flat; where its weight
 *  (the coefficients on blades with e4 and e5) is within the same bound,
 *  they are parallel to the accuracy of the inputs and the weight is set to
 *  exactly 0: a flat at infinity, read as EMPTY. */
GA_API ga_mv ga_mv_meet(ga_mv A, ga_mv B);

/** The tolerance of ga_mv_join's and ga_mv_meet_rel's decisions (GA_POINT_TOL):
 *  a direction of B's subspace lies in A's when the sine of its principal
 *  angle with A's subspace is at most GA_OBJECT_JOIN_TOL, both objects held
 *  about the local origin o and length lambda of ga_mv_join and measured in
 *  the Euclidean metric of the coefficients (an orthonormal basis of each
 *  subspace: the right singular vectors of x -> x ^ X, one-sided Jacobi; the
 *  sines: the singular values of the part of B's basis orthogonal to A's,
 *  modified Gram-Schmidt twice). Where the rounding that the move to (o,
 *  lambda) adds is larger, that is the tolerance: 64 u |o| / lambda for two
 *  flats (at most 64 u 2^3 ~ 6e-14, as lambda >= 2^-2 |o| there), 64 u
 *  (|o| / lambda)^2 with a round or a point (above 1e-9 for rounds some 400
 *  of their sizes from the origin: hold such scenes about a local origin).
 *  An input is a blade when the k-th smallest singular value of x -> x ^ X
 *  (0 for a blade) is at most GA_OBJECT_JOIN_TOL times the largest (|X| for
 *  a blade). The sines are linear in the angle, so the decisions are too:
 *  objects in special position up to 1e-9 of lambda count as in special
 *  position; the rounding of objects built in a few dozen operations is
 *  far below it. */
#define GA_OBJECT_JOIN_TOL 1e-9

/** The join of two direct objects A and B: points (null vectors), point pairs
 *  and flat points, circles and lines, spheres and planes (grades 1 to 4;
 *  direct forms: a dual sphere or plane s is ga_mv_dual(s) here, as a vector
 *  is a point), the smallest blade whose subspace holds both:
 *    - A ^ B (ga_mv_op, bit for bit) when their subspaces share no direction
 *      (general position, DFM §5: two distinct points -> their pair, a line
 *      and a point off it -> their plane, two skew lines -> the whole space);
 *    - B when B's subspace holds A's, else A when A's holds B's (a point on a
 *      line -> the line, a circle on a sphere -> the sphere, an object and a
 *      multiple of itself -> the first);
 *    - otherwise A ^ c1 ^ ... ^ cr, the c the r directions of B's subspace
 *      orthogonal to A's (held about the local origin below, then moved
 *      back): two lines through a common point -> their plane, two circles on
 *      one sphere -> the sphere, coplanar circles -> the plane, two parallel
 *      lines -> their plane; up to scale and sign.
 *  The decisions are made about a local origin o (A's centre, or its point
 *  nearest the origin for a flat; B's if A has none) in units of a power of
 *  two lambda near the larger of the radii and the distance of the two
 *  centres, and at least 2^-10 |o| with a round, 2^-2 |o| for two flats (whose
 *  rounding, u |o| times the condition of their construction, must stay
 *  below the tolerance: a line and the same line through two other of its
 *  points, 1e-4 |o| apart, are one line) (ga_mv_localize), where the coefficients
 *  are of the scene's size; GA_OBJECT_JOIN_TOL has the tolerance. A join
 *  that holds n (a plane of two circles) is returned without A ^ nbar parts,
 *  as ga_mv_localize does for flats. Status: GA_ERR_NOTFINITE for NaN/Inf in A or B (first),
 *  GA_ERR_SINGULAR for a zero input, GA_ERR_NOTBLADE for mixed grades (a part
 *  of another grade above GA_POINT_TOL of the largest coefficient) or a
 *  grade-2 or -3 element that is no blade, GA_ERR_DOMAIN for a scalar or a
 *  pseudoscalar (grade 0 or 5: no object) and where the result overflows. No
 *  allocation. */
GA_API GA_NODISCARD ga_status ga_mv_join(ga_mv A, ga_mv B, ga_mv *out);

/** The meet of two direct objects relative to their join J (ga_mv_join), the
 *  subspace common to both, for objects in any position (DFM §5.6):
 *    - where J is the whole space, ga_mv_meet(A, B) bit for bit with A and B
 *      taken as direct (two planes -> their line, two spheres -> their
 *      circle, a circle crossing a sphere -> a point pair);
 *    - where one holds the other, the smaller one as given: a point on a line
 *      -> the point, a circle on a sphere -> the circle, identical objects ->
 *      B (meet = join = the object, up to scale);
 *    - otherwise (B _| J^-1) _| A, taken about the local origin of
 *      ga_mv_join in the Euclidean metric of the coefficients (there every
 *      blade J is invertible, so a null join, a tangent round, needs nothing
 *      special; the meet as a subspace does not depend on the metric, its
 *      scale and sign do): two intersecting lines -> their flat point, two
 *      parallel lines -> their direction at infinity (u ^ n, its weight
 *      exactly 0 where the sine of their angle is within the tolerance of
 *      the decisions, read as EMPTY),
 *      two coplanar or cospherical circles -> a point pair, real, tangent or
 *      imaginary; a scalar where the two share no point (a point off a line).
 *  Statuses of ga_mv_join. */
GA_API GA_NODISCARD ga_status ga_mv_meet_rel(ga_mv A, ga_mv B, ga_mv *out);

/** The point of O nearest x (a plane, line, sphere, circle, flat point, or the
 *  nearer point of a pair). GA_ERR_IMAGINARY for an imaginary round,
 *  GA_ERR_DOMAIN where the nearest point is not unique (x at the centre of a
 *  sphere or on the axis of a circle), GA_ERR_NOTBLADE for an empty object,
 *  and ga_object_from_mv's codes. */
GA_API GA_NODISCARD ga_status ga_point_project(ga_vec3 x, ga_mv O, ga_vec3 *out);
/** The rejection x - ga_point_project(x, O): the offset of x from O. Same codes. */
GA_API GA_NODISCARD ga_status ga_point_reject(ga_vec3 x, ga_mv O, ga_vec3 *out);
/** |x - ga_point_project(x, O)|, the distance from x to O. Same codes. */
GA_API GA_NODISCARD ga_status ga_point_distance(ga_vec3 x, ga_mv O, double *out);

/** The angle in [0, pi/2] between two flats or rounds through a common point:
 *  planes (between normals), lines (between directions), a line and a plane
 *  (pi/2 - the angle of direction and normal), and spheres or a sphere and a
 *  plane (the angle of their tangent planes where they cross: cos = |s1.s2| /
 *  sqrt(s1^2 s2^2) for the dual vectors, DFM §14.3). Taken as atan2(sine,
 *  cosine), the sine from the wedge, so that angles near 0 and near pi/2 keep
 *  their relative accuracy. GA_ERR_DOMAIN for rounds that do not cross,
 *  GA_ERR_NOTBLADE for other pairs, GA_ERR_IMAGINARY for an imaginary sphere. */
GA_API GA_NODISCARD ga_status ga_object_angle(ga_mv A, ga_mv B, double *out);

/** A rigid motion taking A to B, two objects of the same kind (planes, lines,
 *  spheres, circles, point pairs, flat points): T(cB) R T(-cA), cA and cB the
 *  centres of ga_object_from_mv and R the shortest rotation taking A's
 *  direction to B's (any half turn about a perpendicular axis when opposite).
 *  It takes A to a positive multiple of B (with orientation, where the kinds
 *  have one). GA_ERR_ARG for different kinds, GA_ERR_NOTRIGID for rounds of
 *  different radii (|r2A - r2B| > GA_POINT_TOL L^2, L = max(1, |c| + |r|) of
 *  either: a dilation would be needed),
 *  GA_ERR_IMAGINARY, GA_ERR_NOTBLADE for empty objects. */
GA_API GA_NODISCARD ga_status ga_rotor_between(ga_mv A, ga_mv B, ga_rotor *out);

/** A rotor of G(4,1) (an even versor, V ~V = 1) taking A to B, two objects
 *  of the same kind that may differ in size, where one exists (clifford's
 *  rotor_between_objects, Lasenby-Hadfield, makes such rotors too):
 *  V = T(cB) R D(s) T(-cA), cA and cB the centres of ga_object_from_mv, R the
 *  rotation of ga_rotor_between, and D(s) = exp(-ln(s)/2 e45) the dilation
 *  about the origin by s = sqrt(r2B / r2A) (s = 1 for flats, for two
 *  tangent rounds and where r2A and r2B agree to the sum of their r2_err:
 *  then V is ga_rotor_between's motion, bit for bit). V A V^-1 is a
 *  multiple of B, positive with the orientation where the kind has one (lines,
 *  planes, circles, point pairs): computed with ga_versor_apply, its centre
 *  and r^2 are B's to max(1e-12, 64 u L) of the scene (L = max(1, |c| + |r|)
 *  of A and B, L^2 for r^2) and its direction to as many radians, beyond the
 *  bounds err, r2_err and angle_err that ga_object_from_mv states for the
 *  two (what their coefficients know), for A up to 1e2 from the origin and
 *  of size 1e-2 to 1e2 and B a copy moved and dilated by 0.1 to 10: the
 *  sandwich by a V that moves A by ~L rounds terms ~L^2 times A's weight
 *  (further out that u L^2 grows on, as for every round held about the
 *  origin: object.h, "Accuracy"). V ~V = 1 to a few
 *  u |V|^2 (V is one product of a rigid rotor and D(s):
 *  T(cB - s R cA) R D(s)).
 *  A real round and a flat of the same grade (a sphere and a plane, a
 *  circle and a line, a point pair and a flat point), either way round:
 *  V = M V0 takes the round to the flat, V0 = N I T(-p) / (2r) the
 *  translation of p = c - r u (a point of the round, c and r its centre and
 *  radius, u B's normal for a sphere, a unit vector in the circle's plane,
 *  the point pair's direction) to the origin, the inversion I in the sphere
 *  of radius 2r about it and the reflection N in the plane of normal u
 *  through it, which leave the flat through -2r u; M a rigid motion taking
 *  that flat to B with the orientation of the image of A (for a point pair,
 *  the other point is sent to infinity where the flat point's weight has
 *  the wrong sign). A flat to a round is the reverse ~V of the round to the
 *  flat. V A V^-1 is a positive multiple of B to the rounding of the
 *  sandwich: points x of A moved by V (ga_point_up, ga_versor_apply,
 *  ga_point_down) lie on B to about u max(L, |y|) |V|^2 max(1, |x|)^2, |V|
 *  the largest coefficient of V, and more near the point sent to infinity,
 *  where the map magnifies the rounding of x. The image of a round is a flat
 *  only to that rounding: ga_object_from_mv may refuse it
 *  (GA_ERR_PRECISION, round and flat not told apart).
 *  Statuses of ga_rotor_between's read-back (GA_ERR_IMAGINARY,
 *  GA_ERR_NOTBLADE for empty objects, GA_ERR_PRECISION beyond
 *  GA_OBJECT_TOL, ...), GA_ERR_ARG for objects of different grades,
 *  GA_ERR_DOMAIN where no such rotor exists (a tangent round, radius 0, and
 *  a real one or a flat) or it overflows. */
GA_API GA_NODISCARD ga_status ga_versor_between(ga_mv A, ga_mv B, ga_mv *out);

/** The object at t along the rotor V = ga_versor_between(A, B):
 *  V^t A V^-t (ga_mv_pow, ga_versor_apply), A at t = 0 and B at t = 1 (to the
 *  accuracy of ga_mv_pow, 1e-13 of |V|). Between them a round's radius goes
 *  geometrically, rA (rB/rA)^t, and its centre and direction along the screw
 *  motion (with the dilation about the same fixed point) that V is the end of.
 *  Where V is rigid (s = 1 above) the power is the screw exp(t log V) of
 *  ga_rotor_log and ga_rotor_exp, applied with ga_rotor_apply_mv, so that a
 *  flat stays a flat to the bit; otherwise ga_mv_pow and ga_versor_apply.
 *  Statuses of ga_versor_between and ga_mv_pow (GA_ERR_ARG for different
 *  kinds, a round and a flat included); GA_ERR_NOTFINITE for a NaN
 *  or infinite t, GA_ERR_DOMAIN where the result overflows. */
GA_API GA_NODISCARD ga_status ga_object_interp(ga_mv A, ga_mv B, double t, ga_mv *out);

/** The weighted mean of n objects A[i] of one kind (spheres, planes, circles,
 *  lines, point pairs or flat points) with weights w[i] >= 0 (NULL: all equal;
 *  not all 0; only their ratios matter): the direct average of Hadfield and
 *  Lasenby ("Direct linear interpolation of geometric objects in conformal
 *  geometric algebra", 2019; clifford's average_objects). Each object is
 *  normalised to |<X ~X>_0| = 1 (a sphere or plane as its dual vector, the
 *  other kinds as the direct blade), the weighted sum C = sum_i w_i X_i taken
 *  and, for grades 2 and 3, projected back onto the blades: C = k X with k a
 *  scalar plus a 4-vector, k the square root of +-C ~C (Dorst and
 *  Valkenburg's), X = k^-1 C. The result is that X, normalised to
 *  |<X ~X>_0| = 1, in the form of the inputs (a sphere or plane as a 4-blade
 *  where every input is one, else as a vector). Orientation counts: an
 *  object and its reverse cancel.
 *  What it is, by kind (w_i normalised to sum 1):
 *    - spheres (F(c_i) - r_i^2/2 n over r_i): centre sum a_i c_i / sum a_i,
 *      a_i = w_i / r_i, and r^2 = (sum w_i r_i) / (sum a_i) - the a-weighted
 *      variance of the centres: about one centre the radius is
 *      sqrt(AM(r) HM(r)), the arithmetic and harmonic weighted means (for
 *      two radii with equal weights, their geometric mean); centres spread
 *      wider than the radii give an imaginary sphere (the pencil of spheres
 *      of two objects passes through their common circle). Circles and point
 *      pairs of one carrier about one centre, likewise;
 *    - planes (m_i + d_i n, |m_i| = 1): the normal along sum w_i m_i, at the
 *      distance sum w_i d_i / |sum w_i m_i|; parallel planes: the weighted
 *      mean of their distances. Parallel lines, flat points: the weighted
 *      mean of their positions;
 *    - n = 2 with weights (1 - t, t): ga_object_interp(A, B, t) where the
 *      two are parallel flats of one orientation, or concentric rounds (of
 *      one carrier) at t = 1/2; otherwise another object of the same pencil
 *      (two spheres of one radius apart average to a smaller sphere through
 *      their common circle, interp moves one rigidly to the other).
 *  Rounds are normalised about their own centres, and summed, projected and
 *  normalised about c0, the a-weighted mean of their centres, in units of a
 *  power of two near their a-weighted mean radius (moved there and back
 *  exactly, gao_translate's rounding once), so that a far scene keeps what
 *  its objects' coefficients hold ("Accuracy" above); flats about the
 *  origin.
 *  Accuracy: GA_OK means the object of out is, to first order, within the
 *  bounds ga_object_mean_read states of the mean of any inputs within their
 *  own rounding (object.h's model): those of out's read-back plus the
 *  change of the mean's centre, r^2 and direction with each coefficient of
 *  the sum times that coefficient's uncertainty (the inputs' and the
 *  computation's), doubled. These can be far above the bounds
 *  ga_object_from_mv states for out: where the weighted objects cancel
 *  (spheres of both orientations) or the projection magnifies the inputs'
 *  rounding (small rounds far out), the definition itself is ill-conditioned
 *  and out's coefficients do not show it. The mean of n copies of one object
 *  is that object, and the mean of V A_i V^-1 (V a rigid motion or a
 *  dilation) is V (mean) V^-1, each within those bounds and a few times the
 *  inputs' (docs/conformal.md has the figures). It does not depend on the
 *  order of the objects, bit for bit: every sum is exact (a fixed-point
 *  accumulator), rounded once.
 *  Statuses: GA_ERR_ARG for n = 0, a negative weight, weights all 0, objects
 *  of different kinds; GA_ERR_NOTFINITE for NaN/Inf in an object or weight;
 *  ga_object_from_mv's statuses for each object; GA_ERR_NOTBLADE for an empty
 *  object; GA_ERR_DOMAIN for a tangent round (a point: radius 0, no
 *  normalisation), for a sum that is no multiple of an object (no real root
 *  k) or whose object is of another kind (planes whose normals cancel: the
 *  plane at infinity; spheres of opposite orientation: a plane), and on
 *  overflow; GA_ERR_SINGULAR where the weighted objects cancel to within
 *  16 u of the largest term; GA_ERR_PRECISION where the mean's object is
 *  not known to first order (a small change of the sum changes its kind or
 *  leaves no blade). The result may be a tangent or imaginary round
 *  (ga_object_from_mv reads it so). Not iterative. */
GA_API GA_NODISCARD ga_status ga_object_mean(const ga_mv *A, const double *w, size_t n, ga_mv *out);

/** ga_object_mean, and in obj the read-back of out with the bounds the mean
 *  is known to (see ga_object_mean): ga_object_from_mv's of out plus the
 *  first-order effect of the inputs' uncertainty and of the computation;
 *  reality decided with that r2_err. The same statuses, and GA_ERR_ARG for a
 *  NULL obj; out and obj are written together, or neither. */
GA_API GA_NODISCARD ga_status ga_object_mean_read(const ga_mv *A, const double *w, size_t n, ga_mv *out,
                                                  ga_object *obj);

#ifdef __cplusplus
}
#endif
#endif
