/* tools/cli.h: the options of the garotor tool and the commands that use them. */
#ifndef GAROTOR_TOOLS_CLI_H
#define GAROTOR_TOOLS_CLI_H

/** Every option any command takes; each command says which it accepts. */
enum {
    OPT_IN = 1 << 0,
    OPT_OUT = 1 << 1,
    OPT_HEADER = 1 << 2,
    OPT_GROUP = 1 << 3,
    OPT_SCHEME = 1 << 4,
    OPT_SAMPLES = 1 << 5,
    OPT_AT = 1 << 6,
    OPT_FORMAT = 1 << 7,
    OPT_EVAL = 1 << 8,
    OPT_STEP = 1 << 9,
    OPT_V0 = 1 << 10,
    OPT_VELOCITIES = 1 << 11,
    OPT_SVG = 1 << 12,
    OPT_VIEW = 1 << 13,
    OPT_NORMALIZE = 1 << 14,
    OPT_WITH = 1 << 15,
    OPT_FRAME = 1 << 16,
    OPT_RATE = 1 << 17,
    OPT_TIMES = 1 << 18,
    OPT_EXTRAPOLATE = 1 << 19,
    OPT_HTML = 1 << 20,
    OPT_VERB = 1 << 21, /* not an option: the command takes an operation word first */
    OPT_TIME_UNIT = 1 << 22,
    OPT_MAX_LINE = 1 << 23,
    OPT_CLIP = 1 << 24,
    OPT_QUAT_ORDER = 1 << 25,
    OPT_OUTPUT_FORMAT = 1 << 26,
    OPT_TWIST_ORDER = 1 << 27,
    OPT_COLUMNS = 1 << 28,
    OPT_MIN_GAP = 1 << 29,
    OPT_DEDUP = 1 << 30
};

#include <stddef.h>

typedef struct {
    unsigned given; /* OPT_* bits of the options on the command line */
    const char *in, *out, *svg, *velocities, *at, *view, *html;
    const char *group, *scheme, *format, *eval, *with, *frame, *times, *extrapolate;
    const char *rate_text, *time_unit; /* --rate as written (read exactly), --time-unit */
    const char *verb;                  /* `versor exp`: the operation word */
    const char *quat_order, *output_format, *twist_order, *columns;
    int clip, dedup;
    double min_gap; /* --min-gap, in the keys' time unit */
    double rate;
    int header, normalize;
    long samples;
    size_t max_line; /* --max-line, 0 when not given (textio.h: TIO_MAX_LINE) */
    double step;
    double v0[6];
} cli_opts;

#include <garotor/garotor.h>
#include "textio.h"

/** How the command's input (--in) is read: --header, --max-line. */
static inline tio_read_opts cli_input(const cli_opts *o)
{
    tio_read_opts r = {o->header, 1, o->max_line};
    return r;
}
/** How another file it reads (--times, --velocities) is read: --max-line. */
static inline tio_read_opts cli_other_input(const cli_opts *o)
{
    tio_read_opts r = {0, 0, o->max_line};
    return r;
}

/** The group named by --group (default cga), or NULL after a message. */
const ga_group *cli_group(const char *cmd, const cli_opts *o);
/** Check that a matrix read from item i is an element of g (rigid to 1e-9 for
 *  cga and matrix, homogeneous with positive determinant for affine); prints
 *  the reason naming the line and returns -1 if not, 0 if it is. */
int cli_check_motion(const ga_group *g, ga_mat4 m, const tio_items *in, size_t i);

/** Commands: each returns the process exit status (0 ok, 2 bad input or usage). */
int cmd_demo(const cli_opts *o);
int cmd_exp(const cli_opts *o);
int cmd_log(const cli_opts *o);
int cmd_interp(const cli_opts *o);
int cmd_versor(const cli_opts *o);

#endif
