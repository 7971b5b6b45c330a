/* tools/eval.h: `garotor eval` (docs/tool.md, "garotor eval"): two
 * trajectories associated by time, aligned (Horn's closed form of the
 * Umeyama problem, SE(3) or Sim(3)), and their absolute and relative pose
 * errors in evo's definitions. cmd_eval.c holds the command (options,
 * reading, report) and the TUM reader `garotor fit` shares; the numbers
 * are the library's (garotor/trajectory.h). Prefix ev_.
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

/** How a TUM file is read: --header, --normalize, --max-line (0: default),
 *  --time-unit ns, whether a stamp that looks like ms, us or ns is refused
 *  (no --time-unit given: stamps.h), --stamps FILE (NULL: none), --columns
 *  LIST (NULL: none; columns.h) and the command that reads it, for its
 *  messages ("eval" when NULL). */
typedef struct {
    int header, normalize;
    size_t max_line;
    int ns, guess_unit;
    const char *stamps, *columns, *cmd;
} ev_read_opts;

/** Read a TUM file (t x y z qx qy qz qw a line, or any layout with o->columns:
 *  columns.h; times strictly increasing,
 *  quaternions unit to 1e-9, or to 1e-3 with normalize, then normalised),
 *  or with o->stamps a file of KITTI poses when its first line has 12
 *  numbers (the 3x4 [R t], rigid to 1e-9, or projected onto SE(3) from
 *  1e-3 with normalize; its stamps from o->stamps: stamps.h). The times
 *  are taken relative to *t0, which is set to this file's first stamp when
 *  *have0 is 0; shift is added to each (exactly: timetext.h; in the file's
 *  unit); with o->ns they are whole nanoseconds, converted to seconds once
 *  relative. *kitti is set to 1 for a KITTI file. 0, or -1 after a message
 *  naming the file, the line and the columns. */
int ev_traj_read(const char *path, const ev_read_opts *o, tt_dec *t0, int *have0, const tt_dec *shift,
                 ev_traj *tr, int *kitti);
void ev_traj_free(ev_traj *tr);

/** The command: argv holds its arguments after the word `eval`; returns the
 *  exit status (0, or 2 after a message). */
int cmd_eval_main(int argc, char **argv);

/** `garotor fit` (cmd_fit.c), argv after the word `fit`: the exit status. */
int cmd_fit_main(int argc, char **argv);

#endif
