/* tools/interp_cmd.h: the parts of `garotor interp` (cmd_interp.c), shared by
 * its files; internal to the tool, every name prefixed ic_.
 *
 *   interp_opts.c    the options, parsed and checked into an ic_opts
 *   interp_read.c    the inputs: keys (mat or pose, or any layout through
 *                    --columns: columns.h), --at, --times, --v0,
 *                    --velocities, read and checked into an ic_input
 *   interp_times.c   times relative to the first key, exactly; the sample
 *                    times of each kind (ic_sampler) and their stamps
 *   interp_write.c   the samples (poses, velocities, accelerations) made and
 *                    written a chunk at a time, and the picture (--svg, --html)
 *   cmd_interp.c     the command: the steps above in order, and the path
 *
 * Every step returns 0, or -1 after a message (the command then exits 2). */
#ifndef GAROTOR_TOOLS_INTERP_CMD_H
#define GAROTOR_TOOLS_INTERP_CMD_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "cli.h"
#include "svg.h"
#include "timetext.h"

/* The options of `garotor interp`, read and checked. */
typedef struct {
    const cli_opts *o; /* as given */
    const ga_group *g;
    ga_scheme scheme;
    ga_eval ev;
    svg_view view;
    int pose;   /* --format pose */
    int kitti;  /* --format kitti: 12 numbers a key, no t */
    int extrap; /* --extrapolate: a ga_extrap (0 error, 1 hold, 2 extend, 3 constant-velocity) */
    int clip;   /* --clip: given times outside the range dropped */
    int with_v, with_a, with_j; /* --with velocity,acceleration,jerk (any of them) */
    ga_frame frame;             /* --frame */
    int ns;                     /* --time-unit ns */
    int unit_given;             /* --time-unit given (no guess from the stamps then) */
    int wxyz;                   /* --quat-order wxyz */
    int vw;                     /* --twist-order vw: twists written (and read) v first */
    int out_fmt;                /* --output-format: an IC_OUT_* */
} ic_opts;
/* What a row of samples is (--output-format; default: as the keys were read). */
enum { IC_OUT_MAT, IC_OUT_POSE, IC_OUT_TUM, IC_OUT_KITTI, IC_OUT_CSV };
/* Parse and check every option, in the order their messages come. */
int ic_options(const cli_opts *o, ic_opts *io);

/* Times (docs/tool.md, "Times"): each read exactly from its text
 * (timetext.h) and taken relative to the first key's, exactly, before it is
 * rounded to a double: so the path sees the same doubles whatever constant
 * every time is shifted by. With --time-unit ns the relative times are
 * converted to seconds (exactly, rounded once). */
typedef struct {
    tt_dec ref; /* the first key's time, exactly */
    int ns;     /* --time-unit ns */
} ic_timebase;
/* The time of text relative to the reference, in seconds, as a double. */
double ic_rel_time(const ic_timebase *tb, const char *text);
/* 1 if text is a whole number. */
int ic_whole(const char *text);

/* What was read, all of it held until the command ends (ic_input_free). */
typedef struct {
    tio_items in;     /* the keys' file */
    tio_items tin;    /* --times FILE */
    tio_items vin;    /* --velocities FILE */
    size_t n;         /* keys */
    double *times;    /* the keys' relative times */
    ga_mat4 *keys;    /* the keys, as matrices */
    size_t i0, i1;    /* the path's range (ga_path_range): from key i0 to key i1 */
    char *at_buf;     /* --at: a copy of its text */
    char **at_arg;    /* --at: each time's text, in at_buf */
    size_t nat;       /* given times (--at, --times) */
    char **at_text;   /* given times as written, NULL for none */
    char **clip_text; /* --clip: those kept (the texts are at_arg's or tin's) */
    double *at;       /* given times, relative */
    double *vel;      /* --v0 (one) or --velocities (one a key), NULL for none */
} ic_input;
/* --at t1,t2,...: the texts of the times, checked to be finite numbers. */
int ic_parse_at(const char *s, ic_input *in);
/* The keys' file: keys in --format, times increasing, enough for --scheme
 * (with no --time-unit, whole-number stamps of 12 digits or more refused). */
int ic_read_keys(const ic_opts *io, ic_timebase *tb, ic_input *in);
/* The given times (--times FILE or --at), relative to the first key's. */
int ic_read_times(const ic_opts *io, const ic_timebase *tb, ic_input *in);
/* --v0 or --velocities FILE, as elements of the group's algebra. */
int ic_read_velocities(const ic_opts *io, ic_input *in);
void ic_input_free(ic_input *in);

/* The samples: where their times come from, and what each row holds. */
typedef enum { IC_UNIFORM, IC_GIVEN, IC_RATE, IC_NS_SAMPLES } ic_when;
typedef struct {
    const cli_opts *o;
    const ga_group *g;
    const ga_path *path;
    const tio_items *in;
    const ic_timebase *tb;
    ga_eval ev;
    double step;
    int extrap, pose, with_v, with_a, with_j;
    ga_frame frame;
    int out_fmt, wxyz, vw; /* --output-format, --quat-order wxyz, --twist-order vw */
    int pw, dw, width;     /* pose, algebra element and row widths */
    const double *times;   /* the keys' relative times */
    size_t n;              /* keys */
    size_t i0, i1;         /* the path's range: from key i0 to key i1 (bspline: 1 and n - 2) */
    ic_when kind;
    size_t ns;            /* samples (IC_RATE: the most there can be) */
    const double *at;     /* IC_GIVEN: the times, relative */
    char *const *at_text; /* IC_GIVEN: as written */
    uint64_t rp;          /* IC_RATE: HZ = rp 10^rq when rexact */
    int rq, rexact;
    size_t k0;         /* IC_RATE: the first k in the range */
    double s0, sp;     /* IC_NS_SAMPLES: the range's start and span in nanoseconds */
    ga_path_extrap xp; /* the path with --extrapolate's mode (ic_write sets it) */
} ic_sampler;
/* The sample times of --samples, --rate, --at or --times (path and widths
 * are set once the path is built). */
int ic_plan(const ic_opts *io, const ic_timebase *tb, const ic_input *in, ic_sampler *smp);
/* The time of sample k relative to the first key, and with --time-unit ns
 * its whole nanoseconds *off; 0 when there is no sample k. */
int ic_sample_time(const ic_sampler *s, size_t k, double *t, double *off);
/* The stamp of sample k, taken at t, as the tool writes it (buf: TT_DIG + 32
 * bytes, used for a computed one). */
const char *ic_stamp(const ic_sampler *s, size_t k, double t, double off, char *buf);

/* Every sample written to --out, and the picture to --svg, --html. */
int ic_write(const ic_opts *io, const ic_input *in, ic_sampler *smp);

/* The message of a failed allocation; -1. */
static inline int ic_oom(void)
{
    fprintf(stderr, "garotor interp: out of memory\n");
    return -1;
}

#endif
