/* tests/test_api_edges.c: the edges of the C API, where an argument is bad
 * rather than a number hard (docs/errors.md, "Hostile input").
 *
 *   null_pointers  every public function that returns a ga_status and takes
 *                  pointers, called with NULL for each pointer in turn (an
 *                  output, or an input such as a text, times, keys or a
 *                  path): GA_ERR_ARG, and nothing written through the other
 *                  outputs. The same call with every pointer given succeeds,
 *                  so the refusal is the NULL's.
 *   workspace      ga_path_workspace_size near SIZE_MAX: 0 where the bytes
 *                  do not fit in a size_t, else the exact size (never one
 *                  wrapped around); ga_path_init refuses such an n.
 *   locale         ga_mv_parse under a locale whose decimal point is ','
 *                  reads '.' as under "C", bit for bit; ga_mv_format writes
 *                  the same text. A German locale is used where one is
 *                  installed, else one built by localedef into the working
 *                  directory (LOCPATH, no change to the system); without
 *                  either the section prints why it is skipped.
 */
#define _POSIX_C_SOURCE 200809L

#include <locale.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#if defined(__unix__) || defined(__APPLE__)
#include <unistd.h>
#define API_EDGES_POSIX 1
#endif

#include "testkit.h"

/* ---- null_pointers ----------------------------------------------------------- */

/* The outputs: buffers filled with a pattern before each call, so that a write
 * through one is seen. Room for the largest output (a sampled path). */
enum { NBUF = 5, BUFBYTES = 4096 };
static union {
    unsigned char b[BUFBYTES];
    double d;
    max_align_t a;
} buf[NBUF];
static const unsigned char PATTERN = 0xA5;

/* The inputs the calls share, made valid by setup_inputs. */
static ga_vec3 va = {0.3, -0.2, 0.7}, vb = {1.1, 0.4, -0.5}, vc = {-0.6, 1.3, 0.2}, vd = {0.2, 0.5, 1.9};
static ga_rotor R;
static ga_mat4 M;
static ga_mv X, S, P, P2, L, PP, C, Rmv, B;
static const ga_group *G;
static double times[4] = {0.0, 0.5, 1.25, 2.0};
static double keys[4 * GA_GROUP_MAX_ELEM];
static ga_mat4 keys4[4];
static double work[8192], work_cap[8192];
static size_t work_bytes;
static ga_path path, path_cap;
static ga_path_stepper stepper;

/* argument k: the buffer k, or NULL when k is the argument under test */
static int which;
#define OUT(k) ((void *)(which == (k) ? NULL : buf[k].b))
#define IN(k, v) (which == (k) ? NULL : (v))

static int c_point_up_scaled(void) { return ga_point_up_scaled(va, 2.0, OUT(0)); }
static int c_point_down(void) { return ga_point_down(X, OUT(0)); }
static int c_point_down_scaled(void) { return ga_point_down_scaled(X, 1.0, OUT(0)); }
static int c_sphere_params(void) { return ga_sphere_params(S, OUT(0), OUT(1)); }
static int c_plane_params(void) { return ga_plane_params(P, OUT(0), OUT(1)); }
static int c_line_params(void) { return ga_line_params(L, OUT(0), OUT(1)); }
static int c_pointpair_points(void) { return ga_pointpair_points(PP, OUT(0), OUT(1)); }
static int c_circle_params(void) { return ga_circle_params(C, OUT(0), OUT(1), OUT(2)); }
static int c_mat4_inverse(void) { return ga_mat4_inverse(M, OUT(0)); }
static int c_se3_normalize(void) { return ga_se3_normalize(M, 1e-9, OUT(0)); }
static int c_se3_log(void) { return ga_se3_log(M, OUT(0)); }
static int c_se3_geodesic(void) { return ga_se3_geodesic(M, ga_mat4_identity(), 0.5, OUT(0)); }
static int c_mat4_expm(void)
{
    ga_twist xi = {{0.1, -0.2, 0.3}, {1.0, 2.0, -0.5}};
    return ga_mat4_expm(ga_twist_hat(xi), OUT(0));
}
static int c_mat4_logm(void) { return ga_mat4_logm(M, OUT(0)); }
static int c_mv_format(void) { return ga_mv_format(Rmv, OUT(0), BUFBYTES, OUT(1)); }
static int c_mv_parse(void) { return ga_mv_parse(IN(0, "1.5 + 2.25e12 - e3"), OUT(1)); }
static int c_mv_inverse(void) { return ga_mv_inverse(Rmv, OUT(0)); }
static int c_mv_log(void) { return ga_mv_log(Rmv, OUT(0)); }
static int c_mv_split(void) { return ga_mv_split(B, OUT(0), OUT(1)); }
static int c_mv_factor(void) { return ga_mv_factor(Rmv, OUT(0), OUT(1)); }
static int c_mv_pow(void) { return ga_mv_pow(Rmv, 0.3, OUT(0)); }
static int c_mv_sqrt(void) { return ga_mv_sqrt(Rmv, OUT(0)); }
static int c_mv_project(void) { return ga_mv_project(X, P, OUT(0)); }
static int c_mv_reject(void) { return ga_mv_reject(X, P, OUT(0)); }
static const ga_vec3 fit_pts[5] = {{1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, 0, 1}, {0.6, -0.8, 0}};
static int c_fit_sphere(void) { return ga_fit_sphere(IN(0, fit_pts), 5, OUT(1), OUT(2)); }
static int c_fit_plane(void) { return ga_fit_plane(IN(0, fit_pts), 5, OUT(1), OUT(2)); }
static int c_fit_circle(void) { return ga_fit_circle(IN(0, fit_pts), 5, OUT(1), OUT(2), OUT(3)); }
static int c_fit_line(void) { return ga_fit_line(IN(0, fit_pts), 5, OUT(1), OUT(2)); }
static int c_object_from_mv(void) { return ga_object_from_mv(S, OUT(0)); }
static int c_object_from_mv_about(void) { return ga_object_from_mv_about(S, vb, 1.0, OUT(0)); }
static int c_mv_localize(void) { return ga_mv_localize(S, vb, 1.0, OUT(0)); }
static int c_rotor_apply_about(void) { return ga_rotor_apply_about(R, vb, S, OUT(0), OUT(1)); }
static int c_mv_join(void) { return ga_mv_join(ga_point_up(va), ga_point_up(vb), OUT(0)); }
static int c_mv_meet_rel(void) { return ga_mv_meet_rel(P, P2, OUT(0)); }
static int c_point_project(void) { return ga_point_project(vd, P, OUT(0)); }
static int c_point_reject(void) { return ga_point_reject(vd, P, OUT(0)); }
static int c_point_distance(void) { return ga_point_distance(vd, P, OUT(0)); }
static int c_object_angle(void) { return ga_object_angle(P, P2, OUT(0)); }
static int c_rotor_between(void) { return ga_rotor_between(P, P2, OUT(0)); }
static int c_versor_between(void) { return ga_versor_between(S, S, OUT(0)); }
static int c_object_interp(void) { return ga_object_interp(C, C, 0.5, OUT(0)); }
static ga_mat4 tr_a[5], tr_b[5], fit_z[8];
static double tum_row[7] = {1, 2, 3, 0, 0.6, 0, 0.8}, tr_t[5] = {0, 1, 2, 3, 4},
              tr_t2[4] = {0.1, 1.1, 2.1, 3.1};
static double fit_t[8] = {0, 0.25, 0.5, 0.75, 1.0, 1.25, 1.5, 1.75}, tr_err[5] = {3, 1, 4, 1, 5};
static double fit_work[4096];
static int c_traj_pose_from_tum(void) { return ga_traj_pose_from_tum(IN(0, tum_row), 0, OUT(1)); }
static int c_traj_pose_to_tum(void) { return ga_traj_pose_to_tum(M, OUT(0), OUT(1)); }
static int c_traj_associate(void)
{
    return ga_traj_associate(IN(0, tr_t), 5, IN(1, tr_t2), 4, 0.5, OUT(2), OUT(3), OUT(4));
}
static int c_traj_align(void) { return ga_traj_align(IN(0, tr_a), IN(1, tr_b), 5, 1, OUT(2), OUT(3)); }
static int c_traj_transform(void) { return ga_traj_transform(M, 2.0, IN(0, tr_a), 5, OUT(1)); }
static int c_traj_ape(void) { return ga_traj_ape(IN(0, tr_a), IN(1, tr_b), 5, 1.0, OUT(2), OUT(3)); }
static int c_traj_rpe(void) { return ga_traj_rpe(IN(0, tr_a), IN(1, tr_b), 5, 2, 1, 1.0, OUT(2), OUT(3)); }
static int c_traj_statistics(void) { return ga_traj_statistics(IN(0, tr_err), 5, OUT(1)); }
static int c_traj_fit_count(void) { return ga_traj_fit_count(1.75, 0.5, OUT(0)); }
static int c_traj_fit_bspline(void)
{
    return ga_traj_fit_bspline(IN(0, fit_t), IN(1, fit_z), 8, 0.5, 0.1, IN(2, fit_work),
                               ga_traj_fit_workspace_size(7), OUT(3), 7);
}
static int c_traj_bspline_pose(void) { return ga_traj_bspline_pose(IN(0, tr_a), 5, 0.5, 0.3, OUT(1)); }
static int c_traj_fit_residuals(void)
{
    return ga_traj_fit_residuals(IN(0, fit_t), IN(1, fit_z), 8, IN(2, tr_a), 5, 0.5, OUT(3), OUT(4));
}
static int c_quat_normalize(void) { return ga_quat_normalize(ga_rotor_to_quat(R), 1e-9, OUT(0)); }
static int c_rotor_from_mv(void) { return ga_rotor_from_mv(Rmv, 1e-9, OUT(0)); }
static int c_rotor_normalize(void) { return ga_rotor_normalize(R, OUT(0)); }
static int c_rotor_log(void) { return ga_rotor_log(R, OUT(0)); }
static int c_rotor_log_literal(void) { return ga_rotor_log_literal(R, OUT(0)); }
static int c_rotor_to_screw(void) { return ga_rotor_to_screw(R, OUT(0)); }
static int c_rotor_from_mat4(void) { return ga_rotor_from_mat4(M, OUT(0)); }
static int c_twist_jr_inverse(void)
{
    return ga_twist_jr_inverse((ga_twist){{0.1, 0.2, 0.3}, {1, 2, 3}}, OUT(0));
}
static int c_twist_jl_inverse(void)
{
    return ga_twist_jl_inverse((ga_twist){{0.1, 0.2, 0.3}, {1, 2, 3}}, OUT(0));
}
static int c_rotor_jac_compose(void) { return ga_rotor_jac_compose(R, R, GA_JAC_RIGHT, OUT(0), OUT(1)); }
static int c_rotor_jac_inverse(void) { return ga_rotor_jac_inverse(R, GA_JAC_LEFT, OUT(0)); }
static int c_rotor_jac_between(void) { return ga_rotor_jac_between(R, R, GA_JAC_LEFT, OUT(0), OUT(1)); }
static int c_rotor_jac_act(void) { return ga_rotor_jac_act(R, va, GA_JAC_RIGHT, OUT(0), OUT(1)); }
static int c_rotor_jac_log(void) { return ga_rotor_jac_log(R, GA_JAC_RIGHT, OUT(0)); }
static int c_se3_jac_compose(void) { return ga_se3_jac_compose(M, M, GA_JAC_LEFT, OUT(0), OUT(1)); }
static int c_se3_jac_inverse(void) { return ga_se3_jac_inverse(M, GA_JAC_RIGHT, OUT(0)); }
static int c_se3_jac_between(void) { return ga_se3_jac_between(M, M, GA_JAC_RIGHT, OUT(0), OUT(1)); }
static int c_se3_jac_act(void) { return ga_se3_jac_act(M, va, GA_JAC_LEFT, OUT(0), OUT(1)); }
static int c_se3_jac_log(void) { return ga_se3_jac_log(M, GA_JAC_LEFT, OUT(0)); }
static ga_mat4 affine_x(void) { return ga_twist_hat((ga_twist){{0.1, 0.2, 0.3}, {1, 2, 3}}); }
static int c_affine_jr(void) { return ga_affine_jr(affine_x(), OUT(0)); }
static int c_affine_jl(void) { return ga_affine_jl(affine_x(), OUT(0)); }
static int c_affine_jr_inverse(void) { return ga_affine_jr_inverse(affine_x(), OUT(0)); }
static int c_affine_jl_inverse(void) { return ga_affine_jl_inverse(affine_x(), OUT(0)); }
static int c_affine_adjoint_matrix(void) { return ga_affine_adjoint_matrix(M, OUT(0)); }
static int c_affine_jac_compose(void) { return ga_affine_jac_compose(M, M, GA_JAC_RIGHT, OUT(0), OUT(1)); }
static int c_affine_jac_inverse(void) { return ga_affine_jac_inverse(M, GA_JAC_LEFT, OUT(0)); }
static int c_affine_jac_between(void) { return ga_affine_jac_between(M, M, GA_JAC_LEFT, OUT(0), OUT(1)); }
static int c_affine_jac_act(void) { return ga_affine_jac_act(M, va, GA_JAC_RIGHT, OUT(0), OUT(1)); }
static int c_affine_jac_log(void) { return ga_affine_jac_log(M, GA_JAC_RIGHT, OUT(0)); }
static int c_rotor_mean(void)
{
    static const double w[2] = {1.0, 0.5};
    ga_rotor two[2] = {R, ga_rotor_identity()};
    return ga_rotor_mean(IN(0, two), IN(1, w), 2, OUT(2));
}
/* w is optional (NULL: equal weights, test_object_mean): given here, the
   objects and the output are the pointers under test */
static int c_object_mean(void)
{
    static const double w[2] = {1.0, 0.5};
    ga_mv two[2] = {S, ga_sphere_dual(va, 2.0)};
    return ga_object_mean(IN(0, two), w, 2, OUT(1));
}
static int c_object_mean_read(void)
{
    static const double w[2] = {1.0, 0.5};
    ga_mv two[2] = {S, ga_sphere_dual(va, 2.0)};
    return ga_object_mean_read(IN(0, two), w, 2, OUT(1), OUT(2));
}
static int c_versor_apply(void) { return ga_versor_apply(ga_versor_translation(va), X, OUT(0)); }
static ga_vec3 pts_in[2] = {{0.3, -0.2, 0.7}, {1.1, 0.4, -0.5}};
static ga_mv mvs_in[2];
static const double even_in[16] = {0.9, 0.1, -0.2, 0.3}, vec_in[5] = {1.0, 2.0, 3.0, 0.5, -0.5};
static int c_mv_gp_even_vector_sparse(void)
{
    return ga_mv_gp_even_vector_sparse(IN(0, even_in), IN(1, vec_in), OUT(2));
}
static int c_rotor_apply_many(void) { return ga_rotor_apply_many(R, IN(0, pts_in), 2, OUT(1)); }
static int c_mat4_apply_many(void) { return ga_mat4_apply_many(M, IN(0, pts_in), 2, OUT(1)); }
static int c_versor_apply_many(void)
{
    return ga_versor_apply_many(ga_versor_translation(va), IN(0, mvs_in), 2, OUT(1));
}
static int c_versor_dilation(void) { return ga_versor_dilation(va, 2.0, OUT(0)); }
static int c_scheme_by_name(void) { return ga_scheme_by_name(IN(0, "lihao2"), OUT(1)); }
static int c_eval_by_name(void) { return ga_eval_by_name(IN(0, "euler"), OUT(1)); }
static int c_path_init(void)
{
    return ga_path_init(IN(0, G), GA_SCHEME_SCREW, 4, IN(1, times), IN(2, keys), NULL, IN(3, work),
                        work_bytes, OUT(4));
}
static int c_path_init_mat4(void)
{
    return ga_path_init_mat4(IN(0, G), GA_SCHEME_LIHAO2, 4, IN(1, times), IN(2, keys4), NULL, IN(3, work),
                             work_bytes, OUT(4));
}
static int c_path_append(void)
{
    ga_path q = path_cap;
    return ga_path_append(IN(0, &q), 3.0, IN(1, keys));
}
static int c_path_append_mat4(void)
{
    ga_path q = path_cap;
    return ga_path_append_mat4(IN(0, &q), 3.0, M);
}
static int c_path_range(void) { return ga_path_range(IN(0, &path), OUT(1), OUT(2)); }
static int c_path_segment_range(void) { return ga_path_segment_range(IN(0, &path), 1, OUT(1), OUT(2)); }
static int c_path_locate(void) { return ga_path_locate(IN(0, &path), 0.7, OUT(1), OUT(2)); }
static int c_path_eval(void) { return ga_path_eval(IN(0, &path), 0.7, OUT(1)); }
static int c_path_eval_segment(void) { return ga_path_eval_segment(IN(0, &path), 1, 0.5, OUT(1)); }
static int c_path_velocity(void) { return ga_path_velocity(IN(0, &path), 0.7, OUT(1)); }
static int c_path_velocity_segment(void) { return ga_path_velocity_segment(IN(0, &path), 1, 0.5, OUT(1)); }
static int c_path_acceleration(void) { return ga_path_acceleration(IN(0, &path), 0.7, OUT(1)); }
static int c_path_acceleration_segment(void)
{
    return ga_path_acceleration_segment(IN(0, &path), 1, 0.5, OUT(1));
}
/* v and a of the two below may be NULL (path.h): only the path is required */
static int c_path_differentiate(void)
{
    return ga_path_differentiate(IN(0, &path), 0.7, GA_FRAME_BODY, &buf[1].d, &buf[2].d);
}
static int c_path_differentiate_segment(void)
{
    return ga_path_differentiate_segment(IN(0, &path), 1, 0.5, GA_FRAME_SPATIAL, &buf[1].d, &buf[2].d);
}
/* v, a and j of the two below may be NULL (path.h) */
static int c_path_derivatives(void)
{
    return ga_path_derivatives(IN(0, &path), 0.7, GA_FRAME_WORLD, &buf[1].d, &buf[2].d, &buf[3].d);
}
static int c_path_derivatives_segment(void)
{
    return ga_path_derivatives_segment(IN(0, &path), 1, 0.5, GA_FRAME_SPATIAL, &buf[1].d, &buf[2].d,
                                       &buf[3].d);
}
static int c_path_measure_growth(void) { return ga_path_measure_growth(IN(0, &path), OUT(1)); }
static const ga_path_growth growth_past = {4.25, 1, 1}; /* a growth past the rule, for its words */
static int c_path_growth_describe(void)
{
    return ga_path_growth_describe(IN(0, &path), IN(1, &growth_past), OUT(2));
}
static ga_path_extrap xpath; /* path, extrapolated at constant velocity (setup_inputs) */
static int c_extrap_by_name(void) { return ga_extrap_by_name(IN(0, "constant-velocity"), OUT(1)); }
static int c_path_extrap_init(void) { return ga_path_extrap_init(IN(0, &path), GA_EXTRAP_EXTEND, OUT(1)); }
static int c_path_extrap_eval(void) { return ga_path_extrap_eval(IN(0, &xpath), 2.5, OUT(1)); }
/* v, a and j may be NULL (path.h, as ga_path_derivatives) */
static int c_path_extrap_derivatives(void)
{
    return ga_path_extrap_derivatives(IN(0, &xpath), 2.5, GA_FRAME_WORLD, &buf[1].d, &buf[2].d, &buf[3].d);
}
static int c_path_stepper_init(void)
{
    return ga_path_stepper_init(IN(0, &path), GA_EVAL_EULER, 0.1, 5, 0.25, 1.75, OUT(1));
}
static int c_path_stepper_next(void)
{
    ga_path_stepper s = stepper;
    return ga_path_stepper_next(IN(0, &s), OUT(1));
}
static int c_path_sample_uniform(void)
{
    return ga_path_sample_uniform(IN(0, &path), GA_EVAL_EXACT, 0.1, 5, 0.25, 1.75, OUT(1));
}
static int c_path_sample(void)
{
    return ga_path_sample(IN(0, &path), GA_EVAL_EULER, 0.1, 3, IN(1, times), OUT(2));
}

typedef struct {
    const char *name;
    int (*call)(void);
    int nptr;     /* pointer arguments, numbered 0 .. nptr - 1 as above */
    unsigned out; /* which of them are outputs (bit k: buffer k) */
} api_case;

#define CASE(f, n, out)                                                                                      \
    {                                                                                                        \
#f, c_##f, n, out                                                                                    \
    }
static const api_case cases[] = {
    CASE(point_up_scaled, 1, 1),
    CASE(point_down, 1, 1),
    CASE(point_down_scaled, 1, 1),
    CASE(sphere_params, 2, 3),
    CASE(plane_params, 2, 3),
    CASE(line_params, 2, 3),
    CASE(pointpair_points, 2, 3),
    CASE(circle_params, 3, 7),
    CASE(mat4_inverse, 1, 1),
    CASE(se3_normalize, 1, 1),
    CASE(se3_log, 1, 1),
    CASE(se3_geodesic, 1, 1),
    CASE(mat4_expm, 1, 1),
    CASE(mat4_logm, 1, 1),
    CASE(mv_format, 2, 3),
    CASE(mv_parse, 2, 2),
    CASE(mv_inverse, 1, 1),
    CASE(mv_log, 1, 1),
    CASE(mv_split, 2, 3),
    CASE(mv_factor, 2, 3),
    CASE(mv_pow, 1, 1),
    CASE(mv_sqrt, 1, 1),
    CASE(mv_project, 1, 1),
    CASE(mv_reject, 1, 1),
    CASE(fit_sphere, 3, 6),
    CASE(fit_plane, 3, 6),
    CASE(fit_circle, 4, 14),
    CASE(fit_line, 3, 6),
    CASE(object_from_mv, 1, 1),
    CASE(object_from_mv_about, 1, 1),
    CASE(mv_localize, 1, 1),
    CASE(rotor_apply_about, 2, 3),
    CASE(mv_join, 1, 1),
    CASE(mv_meet_rel, 1, 1),
    CASE(point_project, 1, 1),
    CASE(point_reject, 1, 1),
    CASE(point_distance, 1, 1),
    CASE(object_angle, 1, 1),
    CASE(rotor_between, 1, 1),
    CASE(versor_between, 1, 1),
    CASE(object_interp, 1, 1),
    CASE(quat_normalize, 1, 1),
    CASE(rotor_from_mv, 1, 1),
    CASE(rotor_normalize, 1, 1),
    CASE(rotor_log, 1, 1),
    CASE(rotor_log_literal, 1, 1),
    CASE(rotor_to_screw, 1, 1),
    CASE(rotor_from_mat4, 1, 1),
    CASE(rotor_mean, 3, 4),
    CASE(object_mean, 2, 2),
    CASE(object_mean_read, 3, 6),
    CASE(twist_jr_inverse, 1, 1),
    CASE(twist_jl_inverse, 1, 1),
    CASE(rotor_jac_compose, 2, 3),
    CASE(rotor_jac_inverse, 1, 1),
    CASE(rotor_jac_between, 2, 3),
    CASE(rotor_jac_act, 2, 3),
    CASE(rotor_jac_log, 1, 1),
    CASE(se3_jac_compose, 2, 3),
    CASE(se3_jac_inverse, 1, 1),
    CASE(se3_jac_between, 2, 3),
    CASE(se3_jac_act, 2, 3),
    CASE(se3_jac_log, 1, 1),
    CASE(affine_jr, 1, 1),
    CASE(affine_jl, 1, 1),
    CASE(affine_jr_inverse, 1, 1),
    CASE(affine_jl_inverse, 1, 1),
    CASE(affine_adjoint_matrix, 1, 1),
    CASE(affine_jac_compose, 2, 3),
    CASE(affine_jac_inverse, 1, 1),
    CASE(affine_jac_between, 2, 3),
    CASE(affine_jac_act, 2, 3),
    CASE(affine_jac_log, 1, 1),
    CASE(versor_apply, 1, 1),
    CASE(versor_apply_many, 2, 2),
    CASE(mv_gp_even_vector_sparse, 3, 4),
    CASE(rotor_apply_many, 2, 2),
    CASE(mat4_apply_many, 2, 2),
    CASE(versor_dilation, 1, 1),
    CASE(scheme_by_name, 2, 2),
    CASE(eval_by_name, 2, 2),
    CASE(path_init, 5, 16),
    CASE(path_init_mat4, 5, 16),
    CASE(path_append, 2, 0),
    CASE(path_append_mat4, 1, 0),
    CASE(path_range, 3, 6),
    CASE(path_segment_range, 3, 6),
    CASE(path_locate, 3, 6),
    CASE(path_eval, 2, 2),
    CASE(path_eval_segment, 2, 2),
    CASE(path_velocity, 2, 2),
    CASE(path_velocity_segment, 2, 2),
    CASE(path_acceleration, 2, 2),
    CASE(path_acceleration_segment, 2, 2),
    CASE(path_differentiate, 1, 6),
    CASE(path_differentiate_segment, 1, 6),
    CASE(path_derivatives, 1, 14),
    CASE(path_derivatives_segment, 1, 14),
    CASE(path_measure_growth, 2, 2),
    CASE(path_growth_describe, 3, 4),
    CASE(extrap_by_name, 2, 2),
    CASE(path_extrap_init, 2, 2),
    CASE(path_extrap_eval, 2, 2),
    CASE(path_extrap_derivatives, 1, 14),
    CASE(path_stepper_init, 2, 2),
    CASE(path_stepper_next, 2, 2),
    CASE(path_sample_uniform, 2, 2),
    CASE(path_sample, 3, 4),
    CASE(traj_pose_from_tum, 2, 2),
    CASE(traj_pose_to_tum, 2, 3),
    CASE(traj_associate, 5, 28),
    CASE(traj_align, 4, 12),
    CASE(traj_transform, 2, 2),
    CASE(traj_ape, 4, 12),
    CASE(traj_rpe, 4, 12),
    CASE(traj_statistics, 2, 2),
    CASE(traj_fit_count, 1, 1),
    CASE(traj_fit_bspline, 4, 8),
    CASE(traj_bspline_pose, 2, 2),
    CASE(traj_fit_residuals, 5, 24),
};

static void setup_inputs(void)
{
    ga_vec3 axis = {0.36, 0.48, 0.8};
    R = ga_rotor_mul(ga_rotor_translation(vb), ga_rotor_rotation(axis, 0.9));
    M = ga_rotor_to_mat4(R);
    Rmv = ga_rotor_to_mv(R);
    X = ga_point_up(va);
    mvs_in[0] = X;
    mvs_in[1] = ga_point_up(vb);
    S = ga_sphere_from_points(va, vb, vc, vd);
    P = ga_plane_from_points(va, vb, vc);
    P2 = ga_plane_from_points(va, vb, vd);
    L = ga_line_from_points(va, vb);
    PP = ga_pointpair_from_points(va, vb);
    C = ga_circle_from_points(va, vb, vc);
    B = ga_mv_add(ga_mv_scale(ga_mv_blade(GA_BLADE_E12), 0.7), ga_mv_scale(ga_mv_blade(GA_BLADE_E34), 0.2));
    G = &ga_group_cga;
    size_t ed = G->elem_size / sizeof(double);
    for (int i = 0; i < 4; i++) {
        keys4[i] = ga_rotor_to_mat4(ga_rotor_mul(ga_rotor_translation((ga_vec3){0.5 * i, 0.1, -0.2 * i}),
                                                 ga_rotor_rotation(axis, 0.3 * i)));
        tk_expect_status("setup: a key", G->from_mat4(keys4[i], keys + i * ed), GA_OK);
    }
    for (int i = 0; i < 5; i++) { /* two trajectories, positions not on one line */
        tr_a[i] = ga_se3_exp((ga_twist){{0.1 * i, -0.2, 0.3 * i}, {0.4 * i, 0.2 * i * i, 1.0 - 0.3 * i}});
        tr_b[i] = ga_mat4_mul(M, ga_se3_exp((ga_twist){{0.02, 0.01 * i, 0}, {0.01 * i, 0, 0.03}}));
        tr_b[i] = ga_mat4_mul(tr_b[i], tr_a[i]);
    }
    for (int i = 0; i < 8; i++)
        fit_z[i] = ga_se3_exp((ga_twist){{0.2 * fit_t[i], 0, 0.1}, {fit_t[i], 0.5 * fit_t[i] * fit_t[i], 0}});
    tk_expect(ga_traj_fit_workspace_size(7) <= sizeof fit_work, "setup: the fit's workspace fits");
    work_bytes = ga_path_workspace_size(G, GA_SCHEME_LIHAO2, 4);
    size_t cap_bytes = ga_path_workspace_size(G, GA_SCHEME_SCREW, 6);
    tk_expect(work_bytes <= sizeof work && cap_bytes <= sizeof work_cap &&
                  ga_path_workspace_size(G, GA_SCHEME_SCREW, 4) <= work_bytes,
              "setup: the workspaces fit");
    tk_expect_status("setup: the path",
                     ga_path_init(G, GA_SCHEME_SCREW, 4, times, keys, NULL, work_cap, cap_bytes, &path_cap),
                     GA_OK);
    static double work_path[8192];
    tk_expect_status("setup: the path",
                     ga_path_init(G, GA_SCHEME_SCREW, 4, times, keys, NULL, work_path, work_bytes, &path),
                     GA_OK);
    tk_expect_status("setup: the stepper",
                     ga_path_stepper_init(&path, GA_EVAL_EULER, 0.1, 5, 0.25, 1.75, &stepper), GA_OK);
    tk_expect_status("setup: the path extrapolated",
                     ga_path_extrap_init(&path, GA_EXTRAP_CONSTANT_VELOCITY, &xpath), GA_OK);
}

static int untouched(unsigned out, int skip)
{
    for (int k = 0; k < NBUF; k++)
        if ((out >> k & 1) && k != skip)
            for (size_t i = 0; i < BUFBYTES; i++)
                if (buf[k].b[i] != PATTERN)
                    return 0;
    return 1;
}

static void section_null_pointers(void)
{
    setup_inputs();
    tk_check ok = tk_begin("every pointer given: GA_OK (the inputs are valid)", 0);
    tk_check arg = tk_begin("one pointer NULL: GA_ERR_ARG", 0);
    tk_check none = tk_begin("one pointer NULL: nothing written through the others", 0);
    size_t calls = 0;
    for (size_t c = 0; c < TK_COUNT(cases); c++) {
        which = -1;
        int st = cases[c].call();
        if (st != GA_OK)
            tk_note("  ga_%s: %s with every pointer given\n", cases[c].name, ga_status_string(st));
        tk_add_status(&ok, st, GA_OK);
        for (which = 0; which < cases[c].nptr; which++) {
            memset(buf, PATTERN, sizeof buf);
            st = cases[c].call();
            if (st != GA_ERR_ARG)
                tk_note("  ga_%s, pointer %d NULL: %s\n", cases[c].name, which, ga_status_string(st));
            tk_add_status(&arg, st, GA_ERR_ARG);
            tk_add_bool(&none, untouched(cases[c].out, which));
            calls++;
        }
    }
    tk_note("  %zu functions, %zu calls with a NULL\n", TK_COUNT(cases), calls);
    tk_end(&ok);
    tk_end(&arg);
    tk_end(&none);
    /* the optional outputs stay optional */
    tk_expect_status("ga_path_differentiate: v and a NULL allowed",
                     ga_path_differentiate(&path, 0.7, GA_FRAME_BODY, NULL, &buf[0].d), GA_OK);
    tk_expect_status(
        "ga_path_init: velocities NULL allowed",
        ga_path_init(G, GA_SCHEME_LIHAO2, 4, times, keys, NULL, work, work_bytes, (void *)buf[0].b), GA_OK);
}

/* ---- workspace ---------------------------------------------------------------- */

static void section_workspace(void)
{
    tk_check exact = tk_begin("workspace size: exact where it fits, 0 where it does not", 0);
    tk_check near = tk_begin("workspace size: the largest n that fits is accepted, n + 1 refused", 0);
    for (size_t gi = 0; ga_group_nth(gi); gi++) {
        const ga_group *g = ga_group_nth(gi);
        for (int s = 0; s < GA_SCHEME_COUNT; s++) {
            size_t one = ga_path_workspace_size(g, (ga_scheme)s, 1);
            if (one == 0)
                continue; /* not defined on g */
            size_t per = ga_path_workspace_size(g, (ga_scheme)s, 2) - one;
            /* the sizes are linear in n: one + (n - 1) per, which fits for
               n - 1 <= (SIZE_MAX - one) / per */
            size_t last = (SIZE_MAX - one) / per + 1;
            size_t ns[] = {
                1000,         SIZE_MAX / 64, SIZE_MAX / 8 + 1, ((size_t)1 << (sizeof(size_t) * 8 - 3)) + 100,
                SIZE_MAX / 2, SIZE_MAX - 1,  SIZE_MAX,         last - 1,
                last,         last + 1};
            for (size_t i = 0; i < TK_COUNT(ns); i++) {
                size_t n = ns[i], got = ga_path_workspace_size(g, (ga_scheme)s, n);
                size_t want = n - 1 <= (SIZE_MAX - one) / per ? one + (n - 1) * per : 0;
                if (got != want)
                    tk_note("  %s %s n=%zu: %zu, not %zu\n", g->name, ga_scheme_name((ga_scheme)s), n, got,
                            want);
                tk_add_bool(&exact, got == want);
            }
            tk_add_bool(&near, ga_path_workspace_size(g, (ga_scheme)s, last) != 0 &&
                                   ga_path_workspace_size(g, (ga_scheme)s, last + 1) == 0);
        }
    }
    tk_end(&exact);
    tk_end(&near);
    /* ga_path_init with such an n refuses before it reads a time or a key */
    static double w[1024];
    double t[4] = {0, 1, 2, 3};
    ga_path p;
    size_t n = ((size_t)1 << (sizeof(size_t) * 8 - 3)) + 100;
    ga_mat4 k4[4] = {ga_mat4_identity(), ga_mat4_identity(), ga_mat4_identity(), ga_mat4_identity()};
    double k[4 * GA_GROUP_MAX_ELEM] = {0};
    tk_expect_status("ga_path_init: 2^61 + 100 keys refused",
                     ga_path_init(&ga_group_cga, GA_SCHEME_SCREW, n, t, k, NULL, w, sizeof w, &p),
                     GA_ERR_ARG);
    tk_expect_status("ga_path_init_mat4: 2^61 + 100 keys refused",
                     ga_path_init_mat4(&ga_group_se3, GA_SCHEME_BIVECTOR, n, t, k4, NULL, w, sizeof w, &p),
                     GA_ERR_ARG);
    tk_expect_status("ga_path_init: SIZE_MAX keys refused",
                     ga_path_init(&ga_group_affine, GA_SCHEME_LIHAO3, SIZE_MAX, t, k, NULL, w, sizeof w, &p),
                     GA_ERR_ARG);
}

/* ---- locale ------------------------------------------------------------------- */

static const char *const texts[] = {
    "1.5 + 2.25e12",     "0.1",   "-3.14159265358979323846e1 + 1.5E3e2", ".5e3 - 1.e4",
    "2.5e-3 + 7.25 e45", "1e+21", "0.00000010000000000000001e12345",     "12345.678 * e1235",
};

/* A locale whose decimal point is ',': an installed one, else one localedef
 * builds into the working directory (found through LOCPATH). NULL and why. */
static const char *comma_locale(const char **why)
{
    static const char *const names[] = {"de_DE.UTF-8", "de_DE", "fr_FR.UTF-8", "fr_FR"};
    for (size_t i = 0; i < TK_COUNT(names); i++)
        if (setlocale(LC_NUMERIC, names[i]))
            return names[i];
#ifdef API_EDGES_POSIX
    char dir[4096];
    if (!getcwd(dir, sizeof dir - 32)) {
        *why = "no de_DE or fr_FR locale installed, and no working directory to build one in";
        return NULL;
    }
    strcat(dir, "/test_api_edges.locale");
    char cmd[4400];
    /* built before the first setlocale that looks in LOCPATH: glibc remembers
       a locale it did not find there */
    snprintf(cmd, sizeof cmd, "%s/de_DE.UTF-8/LC_NUMERIC", dir);
    if (access(cmd, R_OK) != 0) {
        snprintf(cmd, sizeof cmd,
                 "mkdir -p '%s' && localedef -i de_DE -f UTF-8 '%s/de_DE.UTF-8' >/dev/null 2>&1", dir, dir);
        if (!system(NULL) || system(cmd) != 0) {
            *why = "no de_DE or fr_FR locale installed, and localedef could not build de_DE.UTF-8";
            return NULL;
        }
    }
    setenv("LOCPATH", dir, 1);
    if (setlocale(LC_NUMERIC, "de_DE.UTF-8"))
        return "de_DE.UTF-8 (built by localedef)";
    unsetenv("LOCPATH");
    *why = "no de_DE or fr_FR locale installed, and localedef could not build de_DE.UTF-8";
#else
    *why = "no de_DE or fr_FR locale installed";
#endif
    return NULL;
}

static void section_locale(void)
{
    ga_mv in_c[TK_COUNT(texts)];
    char text_c[TK_COUNT(texts)][GA_MV_TEXT_MAX];
    size_t len;
    for (size_t i = 0; i < TK_COUNT(texts); i++) {
        tk_expect_status(texts[i], ga_mv_parse(texts[i], &in_c[i]), GA_OK);
        tk_expect_status("format", ga_mv_format(in_c[i], text_c[i], sizeof text_c[i], &len), GA_OK);
    }
    const char *why = NULL, *name = comma_locale(&why);
    if (name && strcmp(localeconv()->decimal_point, ",") != 0) {
        why = "the locale's decimal point is not ','";
        name = NULL;
    }
    if (!name) {
        printf("SKIP locale: %s\n", why);
        setlocale(LC_NUMERIC, "C");
        return;
    }
    tk_note("  LC_NUMERIC %s, decimal point '%s'\n", name, localeconv()->decimal_point);
    ga_mv m;
    int st = ga_mv_parse("1.5 + 2.25e12", &m);
    tk_expect(st == GA_OK && m.c[0] == 1.5 && m.c[GA_BLADE_E12] == 2.25 && ga_mv_maxabs(m) == 2.25,
              "'1.5 + 2.25e12' under a ',' locale: 1.5 and 2.25 e12, exactly");
    tk_check same = tk_begin("every text read as under \"C\", bit for bit", 0);
    tk_check fmt = tk_begin("ga_mv_format writes what it writes under \"C\"", 0);
    for (size_t i = 0; i < TK_COUNT(texts); i++) {
        char t[GA_MV_TEXT_MAX];
        st = ga_mv_parse(texts[i], &m);
        tk_add_bool(&same, st == GA_OK && memcmp(&m, &in_c[i], sizeof m) == 0);
        st = ga_mv_format(in_c[i], t, sizeof t, &len);
        tk_add_bool(&fmt, st == GA_OK && strcmp(t, text_c[i]) == 0);
    }
    tk_end(&same);
    tk_end(&fmt);
    /* a ',' is no decimal point to ga_mv_parse, whatever the locale */
    tk_expect_status("'1,5' refused under a ',' locale", ga_mv_parse("1,5", &m), GA_ERR_ARG);
    setlocale(LC_NUMERIC, "C");
}

static const tk_section sections[] = {
    {"null_pointers", section_null_pointers, 0},
    {"workspace", section_workspace, 0},
    {"locale", section_locale, 0},
};

int main(int argc, char **argv)
{
    return tk_main(argc, argv, "test_api_edges", sections, TK_COUNT(sections));
}
