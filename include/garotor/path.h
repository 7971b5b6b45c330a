/* garotor/path.h: smooth paths through key poses, every scheme written once
 * against the group interface (group.h), and three ways to evaluate them.
 *
 * Keys A_0 .. A_{n-1} at strictly increasing times t_0 < ... < t_{n-1}.
 * Segment i is [t_i, t_{i+1}], h_i = t_{i+1} - t_i, u = (t - t_i)/h_i in [0, 1].
 * A velocity is a body velocity A(t)^-1 dA/dt (an algebra element: a twist
 * for cga/se3), per unit of t; on segment i the velocity per unit of u is
 * h_i times it. "plog" below is the group's principal log.
 *
 * Schemes (docs/schemes.md, `garotor interp --scheme`):
 *   SCREW      A(t) = A_i exp(u B_i), B_i = plog(A_i^-1 A_{i+1})  (Li-Hao eqs.
 *              8-10). By Ad-invariance, A exp(u log(A^-1 B)) A^-1 =
 *              exp(u Ad_A log(A^-1 B)) = exp(u log(B A^-1)), this is W-L §3.1's
 *              exp(u l(R_{i+1} ~R_i)) R_i and Eberly's geodesic (eq. 21).
 *   BIVECTOR   A(t) = exp(X(t)), X piecewise linear through the key
 *              generators X_i (W-L §3, §3.3, direct form).
 *   QUADRATIC  exactly 3 keys: A(t) = exp(X(t)), X the quadratic through
 *              (t_i, X_i) (W-L §3.2, whose lambda = -1, 0, 1 is the case of
 *              uniform times).
 *   SMOOTH     n >= 3 keys: A(t) = exp(X(t)), X a C1 quadratic spline through
 *              (t_i, X_i): one quadratic piece per key, the breakpoints at the
 *              midpoints (t_i + t_{i+1})/2 of the interior segments i = 1..n-3,
 *              none inside the first and last segments ("not-a-knot"). That
 *              gives n - 2 pieces and exactly n free coefficients per
 *              component, fixed by the n keys: no end condition to choose, and
 *              for n = 3 it is QUADRATIC. The slopes at the breakpoints solve
 *              a tridiagonal system, strictly diagonally dominant for any
 *              increasing times (docs/schemes.md, "smooth"). Our reading of
 *              the smoothed quadratics W-L §3.2 points to (Cendes-Wong): C1
 *              everywhere, each piece quadratic, nearly local, exact when X
 *              is a quadratic in t.
 *   LIHAO2     A(t) = A_i exp(u B_i) exp(u^2 C_i)  (Li-Hao eqs. 14-17):
 *              B_0 = h_0 V_0 from the given first-key velocity V_0 (default:
 *              V_0 = plog(A_0^-1 A_1)/h_0, Li-Hao Fig. 3c, i.e. the first
 *              segment is the screw); C_i = plog(exp(-B_i) A_i^-1 A_{i+1})
 *              (eq. 16); B_{i+1} = (h_{i+1}/h_i)(Ad_{(A_i^-1 A_{i+1})^-1} B_i
 *              + 2 C_i) (eq. 17 with time scaling): C1, velocity only at the
 *              first key is free.
 *   LIHAO3     A(t) = A_i exp(u B_i) exp(u^2 C_i) exp((u^3 - u^2) D_i)
 *              (Li-Hao eqs. 21-28) with a velocity V_i at every key:
 *              B_i = h_i V_i (eq. 26), C_i = plog(exp(-B_i) A_i^-1 A_{i+1})
 *              (eq. 27 corrected: the paper prints exp(+B_i), which contradicts
 *              eqs. 16 and 23 and misses the key),
 *              D_i = h_i V_{i+1} - Ad_{(A_i^-1 A_{i+1})^-1} B_i - 2 C_i (eq. 28).
 *              Default velocities (velocities == NULL): with the segment screw
 *              velocities s_i = plog(A_i^-1 A_{i+1})/h_i, each already a body
 *              velocity at both its ends (exp(uB) commutes with B),
 *                V_i = (h_i s_{i-1} + h_{i-1} s_i)/(h_{i-1} + h_i)  (interior),
 *                V_0 = s_0,  V_{n-1} = s_{n-2}  (one-sided at the ends):
 *              the derivative of the parabola through three samples (Bessel;
 *              Catmull-Rom's central difference for uniform times, second-order
 *              for any spacing), both s_{i-1} and s_i in A_i's body frame
 *              (docs/schemes.md, "lihao3", compares Li-Hao Fig. 3d's choice).
 *              A path whose keys lie on one screw motion is then reproduced
 *              exactly (every s_i equal, so C_i = D_i = 0).
 *
 *   DECOUPLED  rotation and translation apart (group.h to_qt/from_qt; rigid
 *              groups only, GA_ERR_ARG on affine): A(t) = (R(t), p(t)) with
 *              R(t) = R_i exp(u r_i), r_i = plog(R_i^-1 R_{i+1}) the principal
 *              rotation vector (slerp: the rotation part of SCREW; scipy's
 *              Slerp), and p(t) = p_i + (t - t_i)(p_{i+1} - p_i)/h_i.
 *   DECOUPLED_C2  p(t): the not-a-knot cubic spline through the key
 *              positions (de Boor, A Practical Guide to Splines, ch. IV;
 *              scipy's CubicSpline default: a line for 2 keys, the parabola
 *              for 3). R(t) = R_i exp(r(t - t_i)), r a cubic in the rotation
 *              vector with r(0) = 0, r(h_i) = r_i, r'(0) = w_i and
 *              J_r(r_i) r'(h_i) = w_{i+1}: the body angular rate is w_i at
 *              every key (C1), and the rates w_1..w_{n-2} solve the C2
 *              conditions, a block-tridiagonal system that is nonlinear
 *              through the term N(r, r') = d/dt(J_r(r)) r' of the angular
 *              acceleration J_r(r) r'' + N, solved by Newton sweeps over
 *              its block-tridiagonal linearisation (docs/schemes.md). End
 *              conditions: w_0 = r_0/h_0, w_{n-1} = r_{n-2}/h_{n-2} (scipy's
 *              RotationSpline, whose construction this is). Where the
 *              sweeps stall, continuation in N; GA_ERR_DOMAIN if that does
 *              not converge either (rare: docs/schemes.md, "Where Newton
 *              fails", counts how often).
 *              Body velocity (w, R^T p'), acceleration (w', R^T p'' - w x v).
 *   C2         rigid groups only (group.h rigid; GA_ERR_ARG on affine):
 *              A(t) = A_i exp(x(t - t_i)), x a cubic in the twist with
 *              x(0) = 0, x(h_i) = theta_i = plog(A_i^-1 A_{i+1}), x'(0) = V_i
 *              and J_r(theta_i) x'(h_i) = V_{i+1}: the body velocity is V_i at
 *              every key from both sides (C1), and the key velocities
 *              V_1..V_{n-2} solve the C2 conditions, the system of
 *              DECOUPLED_C2 with the twist for the rotation vector and the
 *              group's right Jacobian (dexp) for SO(3)'s: block-tridiagonal,
 *              nonlinear through N(x, x') = d/dt(J_r(x)) x' (the body
 *              acceleration is J_r(x) x'' + N, N taken from the 4x4 jet of
 *              the acceleration below), solved by the same Newton sweeps.
 *              End conditions: V_0 = theta_0/h_0, V_{n-1} = theta_{n-2}/h_{n-2},
 *              the screw velocities of the end segments. Keys on one screw
 *              motion exp(t xi) (every theta_i = h_i xi) give exactly that
 *              motion: V_i = xi solves the system with N = 0. Invariant under
 *              changes of world and body frame, like SCREW and LIHAO3.
 *              GA_ERR_DOMAIN if the sweeps and the continuation do not
 *              converge (rare: docs/numerics.md, "c2: where Newton fails", counts
 *              how often).
 *
 *   BSPLINE    the uniform cumulative cubic B-spline with the keys as control
 *              poses (approximating: the keys are not hit). Needs n >= 4 keys
 *              at evenly spaced times (ga_times_uneven); defined on
 *              [t_1, t_{n-2}] only (ga_path_range), in n - 3 segments: segment
 *              s is [t_{s+1}, t_{s+2}], u = (t - t_{s+1})/(t_{s+2} - t_{s+1}),
 *                A(t) = A_s exp(b_1(u) d_1) exp(b_2(u) d_2) exp(b_3(u) d_3),
 *              d_j = plog(A_{s+j-1}^-1 A_{s+j}), with the cumulative basis
 *              b_1 = (5 + 3u - 3u^2 + u^3)/6, b_2 = (1 + 3u + 3u^2 - 2u^3)/6,
 *              b_3 = u^3/6 (Sommer, Usenko, Schubert, Demmel, Cremers 2020,
 *              "Efficient derivative computation for cumulative B-splines on
 *              Lie groups", eqs. for k = 4; Kim, Kim, Shin 1995). C2: the
 *              pieces meet with equal pose, velocity and acceleration at the
 *              knots t_2 .. t_{n-3}. Velocity and acceleration by the
 *              recursion below (Sommer et al.'s, body frame). A motion whose
 *              keys lie on one screw motion A_i = A_0 exp(i X) is reproduced as
 *              that motion: A(t) = A_0 exp(((t - t_0)/h) X), as
 *              b_1 + b_2 + b_3 = 1 + u. Appending a key adds a segment and
 *              changes none before it (local support: 4 keys a segment).
 *
 * Branch rule (BIVECTOR, QUADRATIC, SMOOTH): X_0 is the principal log of A_0;
 * for i >= 1, X_i is the principal log of A_i passed through the group's
 * branch rule with X_{i-1} (group.h: on cga/se3, W-L's rule that consecutive
 * keys take the shortest motion, in twist coordinates; affine has none). Near
 * a rotation of 0 the other branch of a twist is ill-conditioned
 * (|k| ~ 2 pi/th): generators approach the full turn, an inherent limit of
 * generator-space interpolation. A key turning by less than
 * GA_GROUP_HALF_TURN_BAND keeps its principal log (group.h), as a pure
 * translation does.
 *
 * Half turns. Every log this module takes passes through the group's
 * half-turn rule (group.h), so that cga and se3 choose the same screw where
 * the principal log's axis sign is arbitrary.
 *
 * Evaluators:
 *   DIRECT  each sample in closed form.
 *   EULER   Li-Hao §5 (eqs. 32-42) in group form: from the segment start
 *           (its key; BSPLINE: the closed form at the knot, which is no key),
 *           A(u + h) = A(u) exp(h V_u(u)), V_u the analytic body velocity per
 *           unit u, step h in u units on the grid u = 0, h, 2h, ... of each
 *           segment; a sample between grid points takes one partial step from
 *           the grid point below it. Error O(h) (Li-Hao Prop. 1 / eq. 51).
 *           (Li-Hao's eqs. 36-41 step additively, M + h M', which leaves the
 *           group; the product with exp keeps every sample on it, and is exact
 *           for SCREW, whose body velocity is constant.)
 *   EXACT   exact incremental stepping of uniformly spaced samples: each
 *           factor exp(p(u) X) (p = u, u^2 or u^3 - u^2; BSPLINE: the
 *           three cubics b_j, 4 slots each) is advanced by
 *           exp(p(u+d) X) = exp(p(u) X) exp(Dp(u) X), the finite difference
 *           Dp itself advanced by products with exp(D^2 p X), and so on down
 *           to the constant exp(D^deg p X): deg products per factor and sample,
 *           no exp, no truncation error, only rounding. Every
 *           GA_PATH_EXACT_REANCHOR samples (and at each new segment) the
 *           factors are re-anchored by a direct evaluation, so rounding cannot
 *           build up (the cubic factor's rounding grows like the cube of the
 *           samples since the anchor). The generator-space and decoupled
 *           schemes are not products of fixed-X factors: for them EXACT is
 *           DIRECT. So is EXACT
 *           for samples at arbitrary times (ga_path_sample). Its sample
 *           times are the anchor's t_k = t0 + k dt (rounded to a double) plus
 *           whole steps of dt, not each t_k rounded as DIRECT takes them: the
 *           two grids are a few ulp(t) apart, so at large |t| the samples
 *           differ by that gap times the path's speed (docs/schemes.md).
 *
 * Body velocity (ga_path_velocity): Li-Hao forms, for M = F_1 F_2 F_3 with
 * F_j = exp(p_j(u) X_j): M^-1 M' = Ad_{F_3^-1}(Ad_{F_2^-1}(p_1' X_1) + p_2' X_2)
 * + p_3' X_3 (the product rule behind Li-Hao eqs. 15, 25, 34); generator
 * schemes: exp(X(t))^-1 d/dt exp(X(t)) = J_r(X) X', the right Jacobian
 * (group.h dexp: the closed form of SE(3) on cga/se3, a series on affine).
 *
 * Acceleration (ga_path_acceleration, ga_path_differentiate): the derivative
 * of the body velocity, analytic. Li-Hao forms: with w_1 = p_1' X_1,
 * a_1 = p_1'' X_1 and F = F_{j+1}, X = X_{j+1},
 *   w_{j+1} = Ad_{F^-1} w_j + p' X,
 *   a_{j+1} = Ad_{F^-1} a_j + [Ad_{F^-1} w_j, p' X] + p'' X,
 * the product rule above differentiated once more, with d/du Ad_{F^-1} w =
 * Ad_{F^-1} w' + [Ad_{F^-1} w, p' X] ([x, y] = vee(x^ y^ - y^ x^)); it is the
 * recursion of Sommer et al. 2020 for cumulative B-splines. Generator
 * schemes: G = exp(X(t)) through the 4x4 jet exp(X^ + e X'^ + e^2 X''^/2) =
 * G + e G' + e^2 G''/2 (scaling, Taylor series, squaring), then
 * a = vee(G^-1 G'' - (G^-1 G')^2). Spatial: Ad_A of both (d/dt Ad_A v_b =
 * Ad_A (a_b + [v_b, v_b])). On a segment the formula is smooth; at a key the
 * one-sided values of the two segments differ by the scheme's jump.
 *
 * One key (n = 1, any scheme): the constant path A(t_0) = A_0, defined at
 * t_0 only (ga_path_eval_segment has no segment to offer), velocity and
 * acceleration zero.
 *
 * Memory: nothing is allocated. ga_path_init copies the times and keys into a
 * caller's workspace of ga_path_workspace_size() bytes (aligned for double),
 * which must outlive the path. Functions returning a ga_status give GA_OK or a GA_ERR_*
 * code (types.h): GA_ERR_ARG for no key or too few (one key is always enough), times not strictly increasing,
 * a bad count, a t outside the path's range (ga_path_range), a small or misaligned workspace,
 * BSPLINE key times not evenly spaced (ga_times_uneven); GA_ERR_NOTFINITE for NaN/Inf
 * input; a failing log (GA_ERR_DOMAIN for an affine key with no real principal log) is passed on;
 * GA_ERR_DOMAIN when finite input overflows (a coefficient, sample or velocity would be Inf or NaN: keys near
 * DBL_MAX, a segment of subnormal length, spacings whose ratio overflows).
 * GA_OK always comes with finite output. On an error a velocity is left
 * untouched; a sampler may have written the samples before the failing one.
 */
#ifndef GAROTOR_PATH_H
#define GAROTOR_PATH_H

#include <stddef.h>

#include "group.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum {
    GA_SCHEME_SCREW,
    GA_SCHEME_BIVECTOR,
    GA_SCHEME_QUADRATIC,
    GA_SCHEME_SMOOTH,
    GA_SCHEME_LIHAO2,
    GA_SCHEME_LIHAO3,
    GA_SCHEME_DECOUPLED,
    GA_SCHEME_DECOUPLED_C2,
    GA_SCHEME_BSPLINE,
    GA_SCHEME_C2
} ga_scheme;

/** The number of schemes: GA_SCHEME_SCREW .. GA_SCHEME_COUNT - 1 are all of
 *  them (for loops over every scheme). */
#define GA_SCHEME_COUNT 10

typedef enum { GA_EVAL_DIRECT, GA_EVAL_EULER, GA_EVAL_EXACT } ga_eval;

/** The frame of a velocity and its derivatives: BODY, the twist of
 *  M^-1 dM/dt (and its derivatives); SPATIAL, the twist of dM/dt M^-1 =
 *  Ad_M of the body one (its derivative is Ad_M of the body acceleration, as
 *  [v_b, v_b] = 0; the next Ad_M (j_b + [v_b, a_b])); WORLD (rigid groups
 *  only), for M = (R, p): the angular rate in world axes R w_b and its
 *  derivatives, then the derivatives p', p'', p''' of the position, per
 *  unit t, t^2, t^3 (the SPATIAL linear part is p' - w x p, the velocity of
 *  the world point at the origin). */
typedef enum { GA_FRAME_BODY, GA_FRAME_SPATIAL, GA_FRAME_WORLD } ga_frame;

/** Samples between fresh direct evaluations in exact stepping (K). Between
 *  anchors the rounding of the nested differences grows like K, K^2, K^3 for
 *  the u, u^2, u^3 factors, and with the conditioning ||e^X|| ||e^-X|| of the
 *  factors; K = 16 keeps EXACT within 1e-12 relative of DIRECT, with a
 *  margin (docs/schemes.md, "Evaluation"), at the cost of 6 exps per 16
 *  samples (lihao3; 1 for screw). The compiled library fixes it: this
 *  constant states its value, it does not set it. */
enum { GA_PATH_EXACT_REANCHOR = 16 };

/** A path. Its fields are read-only after ga_path_init; the arrays live in the
 *  caller's workspace. */
typedef struct {
    const ga_group *group;
    ga_scheme scheme;
    size_t n;          /**< number of keys */
    size_t cap;        /**< keys the workspace holds (ga_path_append); n where the scheme cannot append */
    double *t;         /**< the n key times */
    double *key;       /**< the n keys, each group->elem_size bytes, padded to doubles */
    size_t key_stride; /**< doubles from one key to the next */
    double *coef;      /**< SCREW/LIHAO2/LIHAO3: per segment B_i[, C_i[, D_i]] (u units); C2: per segment the
                            cubic's a, b, c (x = a tau + b tau^2 + c tau^3, t units); BSPLINE: d_i =
                            plog(A_i^-1 A_{i+1}) between neighbouring keys */
    double *gen;       /**< BIVECTOR/QUADRATIC/SMOOTH: the n key generators X_i */
    double *slope;     /**< QUADRATIC/SMOOTH: X' at the n - 1 breakpoints */
    double *vel;       /**< LIHAO2/LIHAO3/C2: the body velocity at each key (per unit t); C2: then the
                            solver's scratch */
    double *dec;       /**< DECOUPLED/DECOUPLED_C2: per key q, p, angular rate, position slope (13
                            doubles), then per segment the rotation and position cubics (21) */
    int v0_given;      /**< LIHAO2 built from one key: its velocity was given (ga_path_append) */
} ga_path;

/** "screw", "bivector", "quadratic", "smooth", "lihao2", "lihao3",
 *  "decoupled", "decoupled-c2", "bspline", "c2". */
GA_API const char *ga_scheme_name(ga_scheme s);
/** The scheme called name; GA_ERR_ARG if there is none. */
GA_API GA_NODISCARD ga_status ga_scheme_by_name(const char *name, ga_scheme *out);
/** "direct", "euler", "exact". */
GA_API const char *ga_eval_name(ga_eval e);
/** The evaluator called name; GA_ERR_ARG if there is none. */
GA_API GA_NODISCARD ga_status ga_eval_by_name(const char *name, ga_eval *out);
/** Fewest keys the scheme takes beyond the constant path of one key (2, or 3
 *  for QUADRATIC and SMOOTH, 4 for BSPLINE). QUADRATIC takes exactly 3 (or 1). */
GA_API size_t ga_scheme_min_keys(ga_scheme s);

/** 1 if paths of scheme s can grow by ga_path_append: SCREW, LIHAO2,
 *  BIVECTOR, DECOUPLED, whose segment i depends on keys 0..i+1 only, and
 *  BSPLINE (keys i..i+3; a path of at least 4 keys, the new key on the even
 *  grid of them all, as ga_times_uneven says, else GA_ERR_ARG). The
 *  others cannot: LIHAO3's default velocity at a key and the splines
 *  (QUADRATIC, SMOOTH, DECOUPLED_C2, C2) depend on every key, so a new key
 *  changes segments already built; rebuild them with ga_path_init. */
GA_API int ga_scheme_can_append(ga_scheme s);

/** Relative tolerance of even spacing (BSPLINE): key i may be off the even
 *  grid t_0 + i h, h = (t_{n-1} - t_0)/(n - 1), by GA_PATH_SPACING_TOL h plus
 *  4 DBL_EPSILON max(|t_0|, |t_{n-1}|) (the rounding of the times themselves:
 *  at t ~ 1.3e9 a double is 2.4e-7 apart from the next). */
#define GA_PATH_SPACING_TOL 1e-9
/** The first key (1 .. n-2) whose time is off the even grid by more than the
 *  tolerance above, or 0 when the n times are evenly spaced (n <= 2: always;
 *  NaN counts as off). */
GA_API size_t ga_times_uneven(size_t n, const double *times);

/** Bytes of workspace a path of n keys needs (0 if g is NULL or n < 1, if
 *  the size does not fit in a size_t, or if the scheme is not defined on g:
 *  DECOUPLED and DECOUPLED_C2 on a group without to_qt/from_qt, C2 on a
 *  group that is not rigid: affine). A
 *  workspace of this size for m > n keys, given to ga_path_init with n keys,
 *  leaves room for ga_path_append to add m - n (schemes that can append). */
GA_API size_t ga_path_workspace_size(const ga_group *g, ga_scheme s, size_t n);

/** Build into *out a path through n keys (n group elements, each
 *  g->elem_size bytes, in a contiguous array) at the given times.
 *  velocities: LIHAO2: NULL or the first key's velocity (g->dim doubles);
 *  LIHAO3: NULL or one velocity per key (n * g->dim doubles); other schemes
 *  ignore it. */
GA_API GA_NODISCARD ga_status ga_path_init(const ga_group *g, ga_scheme s, size_t n, const double *times,
                                           const void *keys, const double *velocities, void *work,
                                           size_t work_bytes, ga_path *out);

/** The same from 4x4 matrices, each read by g->from_mat4 (its status is
 *  returned: GA_ERR_NOTRIGID for a non-rigid matrix on cga/se3, ...). */
GA_API GA_NODISCARD ga_status ga_path_init_mat4(const ga_group *g, ga_scheme s, size_t n, const double *times,
                                                const ga_mat4 *keys, const double *velocities, void *work,
                                                size_t work_bytes, ga_path *out);

/** Add a key at time t > the last key's to a path of a scheme that can append
 *  (ga_scheme_can_append), building its one new segment: the result is the
 *  path ga_path_init builds from all the keys, bit for bit, at the cost of
 *  one segment. Room: a path built in a workspace of
 *  ga_path_workspace_size(g, s, m) bytes holds up to m keys (p->cap).
 *  LIHAO2: the new segment continues the velocity recurrence; a path of one
 *  key takes the velocity given to ga_path_init, else the default rule.
 *  GA_ERR_ARG: no room, a scheme that cannot append, t not after the last
 *  key; GA_ERR_NOTFINITE: t or the key; GA_ERR_DOMAIN: the segment
 *  overflows. On an error *p is unchanged. */
GA_API GA_NODISCARD ga_status ga_path_append(ga_path *p, double t, const void *key);
/** The same with the key a 4x4 matrix, read by g->from_mat4 (its status is
 *  returned). */
GA_API GA_NODISCARD ga_status ga_path_append_mat4(ga_path *p, double t, ga_mat4 key);

/** The number of segments: n - 1, BSPLINE n - 3 (0 for the one-key path). */
GA_API size_t ga_path_segments(const ga_path *p);
/** The times [*t0, *t1] the path is defined on: [t_0, t_{n-1}], BSPLINE
 *  [t_1, t_{n-2}] (one key: [t_0, t_0]). */
GA_API GA_NODISCARD ga_status ga_path_range(const ga_path *p, double *t0, double *t1);
/** The times [*t0, *t1] of segment seg (u = 0 and u = 1): [t_seg, t_{seg+1}],
 *  BSPLINE [t_{seg+1}, t_{seg+2}]. GA_ERR_ARG for seg >= ga_path_segments. */
GA_API GA_NODISCARD ga_status ga_path_segment_range(const ga_path *p, size_t seg, double *t0, double *t1);

/** The segment and u of time t (t in ga_path_range; t at the start of a
 *  segment gives that segment, u = 0, except the range's end: the last
 *  segment, u = 1). GA_ERR_ARG outside, and for a NaN t (a time that is in
 *  no range: so from every function that takes a sample time t). */
GA_API GA_NODISCARD ga_status ga_path_locate(const ga_path *p, double t, size_t *seg, double *u);

/** A(t) in closed form (DIRECT). At a key time t_i it is the key A_i itself
 *  (the formulas give it up to rounding, which ga_path_eval_segment shows);
 *  so are the DIRECT samples of the batch calls. */
GA_API GA_NODISCARD ga_status ga_path_eval(const ga_path *p, double t, void *out);
/** The formula of segment seg (0 .. ga_path_segments(p) - 1) at any finite
 *  u (outside [0, 1] it extrapolates); no special case at the keys. */
GA_API GA_NODISCARD ga_status ga_path_eval_segment(const ga_path *p, size_t seg, double u, void *out);

/** The body velocity A(t)^-1 dA/dt at t (g->dim doubles, per unit t); at a key
 *  time the velocity of the segment starting there (the last key: ending). */
GA_API GA_NODISCARD ga_status ga_path_velocity(const ga_path *p, double t, double *v);
/** The body velocity per unit t on segment seg at u. */
GA_API GA_NODISCARD ga_status ga_path_velocity_segment(const ga_path *p, size_t seg, double u, double *v);

/** The body acceleration d/dt (A(t)^-1 dA/dt) at t (g->dim doubles, per unit
 *  t^2), analytic: Li-Hao forms by the product rule differentiated once more
 *  (see "Acceleration" above), generator schemes through the 4x4 jet
 *  exp(X + e X' + e^2 X''/2). At a key time the segment starting there. */
GA_API GA_NODISCARD ga_status ga_path_acceleration(const ga_path *p, double t, double *a);
/** The body acceleration per unit t^2 on segment seg at u. */
GA_API GA_NODISCARD ga_status ga_path_acceleration_segment(const ga_path *p, size_t seg, double u, double *a);
/** Velocity (per unit t) and acceleration (per unit t^2) at t in frame f;
 *  either output may be NULL (the acceleration is computed all the same:
 *  ga_path_derivatives computes only what it is asked). The constant path of
 *  one key: zeros. GA_ERR_ARG for GA_FRAME_WORLD on a group that is not
 *  rigid. */
GA_API GA_NODISCARD ga_status ga_path_differentiate(const ga_path *p, double t, ga_frame f, double *v,
                                                    double *a);
/** The same on segment seg at any finite u (outside [0, 1]: the segment's
 *  formula continued, as ga_path_eval_segment). */
GA_API GA_NODISCARD ga_status ga_path_differentiate_segment(const ga_path *p, size_t seg, double u,
                                                            ga_frame f, double *v, double *a);
/** Velocity (per unit t), acceleration (per unit t^2) and jerk (per unit
 *  t^3, the derivative of the acceleration) at t in frame f (g->dim doubles
 *  each); any output may be NULL, and only what is asked is computed: the
 *  velocity alone is ga_path_velocity's (BODY: bit for bit), the jerk costs
 *  what the acceleration does and a little more. Each from the segment's
 *  own closed form: the product forms by the recursion under
 *  "Acceleration" taken once more, j' = Ad_{F^-1} j + 2 [Ad_{F^-1} a, p' X] +
 *  [[Ad_{F^-1} w, p' X], p' X] + [Ad_{F^-1} w, p'' X] + p''' X; exp(X(t))
 *  (generator schemes, C2, the decoupled rotation) on the rigid groups by
 *  SE(3)'s exp in closed form, on affine by the 4x4 jet of order 3. At a key
 *  time the segment starting there. GA_ERR_ARG as ga_path_differentiate. */
GA_API GA_NODISCARD ga_status ga_path_derivatives(const ga_path *p, double t, ga_frame f, double *v,
                                                  double *a, double *j);
/** The same on segment seg at any finite u (the segment's formula
 *  continued outside [0, 1]). */
GA_API GA_NODISCARD ga_status ga_path_derivatives_segment(const ga_path *p, size_t seg, double u, ga_frame f,
                                                          double *v, double *a, double *j);

/** Where a time outside the path's range (ga_path_range) goes
 *  (`garotor interp --extrapolate`, garotor.Path's extrapolate=): ERROR, as
 *  the path's own functions (GA_ERR_ARG); HOLD, the pose at the range's end
 *  (the end key; BSPLINE the range's end pose), velocity, acceleration and
 *  jerk zero; EXTEND, the end segment's formula continued
 *  (ga_path_eval_segment at its u outside [0, 1], with its derivatives; one
 *  key: HOLD); CONSTANT_VELOCITY, the end pose E moved on by its body
 *  velocity V there for the time d past the end, E exp(d V), in closed form:
 *  the body velocity stays V, the acceleration and jerk are zero in the
 *  body and spatial frames, and in the world frame the angular rate is R w
 *  and the position's are R v, R (w x v), R (w x (w x v)) (R the rotation
 *  of the pose E exp(d V) at t, V = (w, v)). */
typedef enum { GA_EXTRAP_ERROR, GA_EXTRAP_HOLD, GA_EXTRAP_EXTEND, GA_EXTRAP_CONSTANT_VELOCITY } ga_extrap;

/** "error", "hold", "extend", "constant-velocity". */
GA_API const char *ga_extrap_name(ga_extrap x);
/** The extrapolation called name; GA_ERR_ARG if there is none. */
GA_API GA_NODISCARD ga_status ga_extrap_by_name(const char *name, ga_extrap *out);

/** A path with its extrapolation: what ga_path_extrap_init reads once (the
 *  range, and for CONSTANT_VELOCITY the pose and body velocity at both of
 *  its ends). It holds a pointer to the path and is valid while the path is
 *  unchanged (after ga_path_append, init it again). */
typedef struct {
    const ga_path *path;
    ga_extrap mode;
    double r0, r1;                     /**< ga_path_range */
    double pose[2][GA_GROUP_MAX_ELEM]; /**< CONSTANT_VELOCITY: the pose at r0 [0] and r1 [1] */
    double vel[2][GA_GROUP_MAX_DIM];   /**< CONSTANT_VELOCITY: the body velocity there */
} ga_path_extrap;

/** Prepare p's samples with extrapolation mode into *out. GA_ERR_ARG for a
 *  bad mode; CONSTANT_VELOCITY: a failing pose or velocity at an end is
 *  passed on. */
GA_API GA_NODISCARD ga_status ga_path_extrap_init(const ga_path *p, ga_extrap mode, ga_path_extrap *out);
/** The pose at t: inside the range ga_path_eval's (the same bits), outside
 *  as x's mode says (ERROR: GA_ERR_ARG). A NaN t is GA_ERR_ARG; a time so
 *  far out that the pose overflows, GA_ERR_DOMAIN or GA_ERR_NOTFINITE. */
GA_API GA_NODISCARD ga_status ga_path_extrap_eval(const ga_path_extrap *x, double t, void *out);
/** Velocity, acceleration and jerk at t in frame f (any of them NULL, as
 *  ga_path_derivatives): inside the range ga_path_derivatives' (the same
 *  bits), outside as x's mode says (ERROR: GA_ERR_ARG). GA_ERR_ARG for
 *  GA_FRAME_WORLD on a group that is not rigid. */
GA_API GA_NODISCARD ga_status ga_path_extrap_derivatives(const ga_path_extrap *x, double t, ga_frame f,
                                                         double *v, double *a, double *j);

/** The growth rule (docs/schemes.md, "lihao2: growth"): a path whose
 *  velocity at some key exceeds GA_PATH_GROWTH_MAX times the fastest chord of
 *  the path. The chord speed from key j is the screw velocity
 *  s_j = plog(A_j^-1 A_e)/(t_e - t_j) to the first key e > j at least 1/16
 *  of the mean key spacing (t_{n-1} - t_0)/(n - 1) later (or the last key):
 *  e = j + 1 unless that segment is that short, so that a near-duplicate key,
 *  whose chord over its tiny gap is the noise of the keys, does not set the
 *  bound (its key velocities are measured against the others' chords, and
 *  flagged). On the rigid groups the rotation (first
 *  three) and translation (last three) parts of a twist are measured apart
 *  (Euclidean norms), on affine the whole algebra element. Key i's ratio is
 *  the largest over the parts of |part of V_i| / max_j |part of s_j|, V_i
 *  the body velocity at t_i (the segment starting there; the last key: the
 *  one ending there); a part whose chords are all zero is not measured.
 *  Schemes whose key velocities are averages of chords (screw, lihao3 by
 *  default) have ratios of at most 1 where no segment is that short; lihao2's recurrence
 *  V_{i+1} = (Ad B_i + 2 C_i)/h_i can grow along the keys without bound. */
#define GA_PATH_GROWTH_MAX 3.0

/** What ga_path_measure_growth found. */
typedef struct {
    double ratio; /**< the largest ratio over the keys (0 for one key) */
    size_t key;   /**< the key where it is largest */
    size_t first; /**< the first key whose ratio exceeds GA_PATH_GROWTH_MAX; n if none: the velocity that
                       the segment first - 1 (from t_{first-1} to t_first) carried to it, or for key 0 the
                       velocity given there (lihao2's v0), is the first past the rule */
} ga_path_growth;

/** Measure the growth rule on p (any scheme; BSPLINE at its keys 1 .. n-2,
 *  those in its range, keys 0 and n-1 taking ratio 0); GA_ERR_ARG for NULL;
 *  a failing log or velocity is passed on. */
GA_API GA_NODISCARD ga_status ga_path_measure_growth(const ga_path *p, ga_path_growth *out);

/** The words of the growth rule's warning (`garotor interp`, garotor.Path),
 *  where ga_path_measure_growth found a key past the rule. */
typedef struct {
    size_t a, b;        /**< the keys of the segment that carried the velocity past the bound: first - 1
                             and first (key 0: 0 and 1) */
    char ratio[32];     /**< the largest ratio in 3 significant digits, or as many as show it past
                             GA_PATH_GROWTH_MAX (3.0004, not 3), as C's "%.*g" writes it in the C locale */
    const char *advice; /**< what to do: for LIHAO2 another scheme, for the others near-duplicate keys */
} ga_path_growth_words;

/** The words of gr, measured on p (ga_path_measure_growth), for its warning
 *  (an infinite ratio, of chords that underflow, as "inf"). GA_ERR_ARG for
 *  NULL, where gr found no key past the rule (gr->first >= p->n), or for a
 *  NaN ratio (which ga_path_measure_growth never gives). */
GA_API GA_NODISCARD ga_status ga_path_growth_describe(const ga_path *p, const ga_path_growth *gr,
                                                      ga_path_growth_words *out);

/** Near-duplicate keys (`garotor interp --min-gap, --dedup`, garotor.Path's
 *  min_gap=, dedup=): keys closer in time than a minimum gap, by default
 *  GA_PATH_MIN_GAP_FRACTION of the median spacing of the keys, make a steep,
 *  meaningless path (the velocity between them is their difference over a
 *  tiny time). A run of them can be merged into one key at their mean time
 *  with their mean pose (ga_rotor_mean), at most GA_PATH_MERGE_MAX keys. */
#define GA_PATH_MIN_GAP_FRACTION 0.01
#define GA_PATH_MERGE_MAX 64

/** The default minimum gap of n increasing times: *median their median
 *  spacing (of an even count of spacings, the mean of the two middle ones),
 *  *gap GA_PATH_MIN_GAP_FRACTION of it; both 0 for n < 2. scratch: room for
 *  n - 1 doubles (overwritten). GA_ERR_NOTFINITE for a spacing that is not
 *  finite; GA_ERR_DOMAIN where the median overflows (finite spacings near
 *  DBL_MAX). */
GA_API GA_NODISCARD ga_status ga_times_min_gap(size_t n, const double *times, double *scratch, double *median,
                                               double *gap);
/** The last key j >= i such that each spacing times[k + 1] - times[k],
 *  i <= k < j, is below gap: the run of near-duplicates that starts at key i
 *  ends at j (j = i: none). i itself for i >= n or times NULL. */
GA_API size_t ga_times_gap_run(size_t n, const double *times, double gap, size_t i);
/** The m keys (rigid 4x4 matrices at the given times, 1 <= m <=
 *  GA_PATH_MERGE_MAX) merged into one: *t the mean of the times (each divided
 *  by m, added in order), with ns the whole number nearest to it times 1e9
 *  (a time in nanoseconds, for times in seconds relative to a stamp of whole
 *  nanoseconds); *key the mean of the poses (ga_rotor_mean, equal weights).
 *  GA_ERR_ARG for m out of range; GA_ERR_NOTFINITE for a time that is not
 *  finite; GA_ERR_DOMAIN where *t would overflow (ns: the mean times 1e9);
 *  a key that is no rigid motion, or a mean that does not converge, passes
 *  its status on. */
GA_API GA_NODISCARD ga_status ga_path_merge_keys(size_t m, const double *times, const ga_mat4 *keys, int ns,
                                                 double *t, ga_mat4 *key);

/** Stepping state for N evenly spaced samples; caller-owned, no allocation. */
#define GA_PATH_STEP_SLOTS 12
typedef struct {
    const ga_path *path;
    ga_eval eval;
    double step; /**< Euler step in u units */
    size_t n, k; /**< samples in all, index of the next one */
    double t0, t1, dt;
    size_t seg;   /**< segment of the running state, SIZE_MAX for none */
    size_t since; /**< EXACT: samples since the last anchor */
    size_t grid;  /**< EULER: grid index of the running state */
    double slot[GA_PATH_STEP_SLOTS][GA_GROUP_MAX_ELEM];
} ga_path_stepper;

/** Prepare n >= 1 samples at t_k = t0 + k (t1 - t0)/(n - 1), the last exactly
 *  t1, [t0, t1] inside ga_path_range (n = 1: t0 alone), each rounded to a double
 *  (EXACT: only at its anchors, whole steps from there; see EXACT above).
 *  step: the Euler step in u units, in [1e-9, 1] (else GA_ERR_ARG), ignored by
 *  the other evaluators. */
GA_API GA_NODISCARD ga_status ga_path_stepper_init(const ga_path *p, ga_eval ev, double step, size_t n,
                                                   double t0, double t1, ga_path_stepper *out);
/** Write the next sample to out, advancing s. GA_ERR_ARG after the last. */
GA_API GA_NODISCARD ga_status ga_path_stepper_next(ga_path_stepper *s, void *out);

/** n evenly spaced samples t0..t1 (both included) into out (n elements of
 *  g->elem_size bytes, contiguous). */
GA_API GA_NODISCARD ga_status ga_path_sample_uniform(const ga_path *p, ga_eval ev, double step, size_t n,
                                                     double t0, double t1, void *out);
/** Samples at n given times, in any order (repeats allowed): DIRECT gives
 *  at each time what ga_path_eval gives there, bit for bit, whatever the
 *  order. Increasing times cost least (a time in the segment of the one
 *  before, or the next segment, needs no search; EULER continues from the
 *  previous sample within a segment). EXACT needs even spacing, so here it
 *  is DIRECT. A time outside ga_path_range (or NaN): GA_ERR_ARG, the samples
 *  before it written. */
GA_API GA_NODISCARD ga_status ga_path_sample(const ga_path *p, ga_eval ev, double step, size_t n,
                                             const double *times, void *out);

#ifdef __cplusplus
}
#endif
#endif
