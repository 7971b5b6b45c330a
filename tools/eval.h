/* tools/eval.h: `garotor eval` (docs/tool.md, "garotor eval"): two
 * trajectories associated by time, aligned (Horn's closed form of the
 * Umeyama problem, SE(3) or Sim(3)), and their absolute and relative pose
 * errors in evo's definitions. cmd_eval.c holds the command (options,
 * reading, association, report) and the TUM reader `garotor fit` shares,
 * eval_metrics.c the numbers. Prefix ev_.
 */
#ifndef GAROTOR_TOOLS_EVAL_H
#define GAROTOR_TOOLS_EVAL_H

#include <stddef.h>

#include <garotor/garotor.h>

#include "textio.h"
#include "timetext.h"

/** A TUM trajectory as read (ev_traj_read). */
typedef struct {
    tio_items in;
    double *t; /* times relative to the first stamp given (t0), plus a shift */
    ga_mat4 *m;
    size_t n;
} ev_traj;

/** How a TUM file is read: --header, --normalize, --max-line (0: default). */
typedef struct {
    int header, normalize;
    size_t max_line;
} ev_read_opts;

/** Read a TUM file (t x y z qx qy qz qw a line, times strictly increasing,
 *  quaternions unit to 1e-9, or to 1e-3 with normalize, then normalised).
 *  The times are taken relative to *t0, which is set to this file's first
 *  stamp when *have0 is 0; shift is added to each (exactly: timetext.h).
 *  0, or -1 after a message naming the file, the line and the columns. */
int ev_traj_read(const char *path, const ev_read_opts *o, tt_dec *t0, int *have0, const tt_dec *shift,
                 ev_traj *tr);
void ev_traj_free(ev_traj *tr);

/** The command: argv holds its arguments after the word `eval`; returns the
 *  exit status (0, or 2 after a message). */
int cmd_eval_main(int argc, char **argv);

/** `garotor fit` (cmd_fit.c), argv after the word `fit`: the exit status. */
int cmd_fit_main(int argc, char **argv);

/** The statistics evo prints for an error array. */
typedef struct {
    double max, mean, median, min, rmse, sse, std;
} ev_stats;

/** The statistics of err[0..n-1], n >= 1, as numpy computes them (median:
 *  the mean of the two middle values for even n; std: the population
 *  deviation). err is sorted in place. */
void ev_statistics(double *err, size_t n, ev_stats *out);

/** The alignment of est to ref minimising sum |s R est_i + t - ref_i|^2 over
 *  the positions (Umeyama 1991; s = 1 unless with_scale), through Horn's
 *  unit quaternion (1987): R is the eigenvector of the largest eigenvalue of
 *  his 4x4 matrix N, found by Jacobi's method, and s = tr(R^T C) / var(est)
 *  with C the cross-covariance (Umeyama's tr(D S)). Writes T = [R, t; 0 1]
 *  and s. -1 when the rotation is not unique (the largest eigenvalue of N is
 *  double: the positions are collinear or fewer than 3 distinct), or the
 *  estimate's positions do not spread (var 0) for the scale. */
int ev_align(const ga_mat4 *ref, const ga_mat4 *est, size_t n, int with_scale, ga_mat4 *T, double *s);

/** The rotation angle of the 3x3 block of m, in [0, pi]:
 *  atan2(|vee(R - R^T)| / 2, (tr R - 1) / 2). */
double ev_angle(const ga_mat4 *m);

#endif
