/* tools/cli.h: the options of the garotor tool and the commands that use them. */
#ifndef GAROTOR_TOOLS_CLI_H
#define GAROTOR_TOOLS_CLI_H

/** Every option any command takes; each command says which it accepts (an
 *  opt_bits of them: more than an int holds). */
typedef unsigned long long opt_bits;
#define OPT_IN (1ULL << 0)
#define OPT_OUT (1ULL << 1)
#define OPT_HEADER (1ULL << 2)
#define OPT_GROUP (1ULL << 3)
#define OPT_SCHEME (1ULL << 4)
#define OPT_SAMPLES (1ULL << 5)
#define OPT_AT (1ULL << 6)
#define OPT_FORMAT (1ULL << 7)
#define OPT_EVAL (1ULL << 8)
#define OPT_STEP (1ULL << 9)
#define OPT_V0 (1ULL << 10)
#define OPT_VELOCITIES (1ULL << 11)
#define OPT_SVG (1ULL << 12)
#define OPT_VIEW (1ULL << 13)
#define OPT_NORMALIZE (1ULL << 14)
#define OPT_WITH (1ULL << 15)
#define OPT_FRAME (1ULL << 16)
#define OPT_RATE (1ULL << 17)
#define OPT_TIMES (1ULL << 18)
#define OPT_EXTRAPOLATE (1ULL << 19)
#define OPT_HTML (1ULL << 20)
#define OPT_VERB (1ULL << 21) /* not an option: the command takes an operation word first */
#define OPT_TIME_UNIT (1ULL << 22)
#define OPT_MAX_LINE (1ULL << 23)
#define OPT_CLIP (1ULL << 24)
#define OPT_QUAT_ORDER (1ULL << 25)
#define OPT_OUTPUT_FORMAT (1ULL << 26)
#define OPT_TWIST_ORDER (1ULL << 27)
#define OPT_COLUMNS (1ULL << 28)
#define OPT_MIN_GAP (1ULL << 29)
#define OPT_DEDUP (1ULL << 30)
#define OPT_TEXT (1ULL << 31)
#define OPT_STAMPS (1ULL << 32)

#include <stddef.h>

typedef struct {
    opt_bits given; /* OPT_* bits of the options on the command line */
    const char *in, *out, *svg, *velocities, *at, *view, *html;
    const char *group, *scheme, *format, *eval, *with, *frame, *times, *extrapolate;
    const char *rate_text, *time_unit; /* --rate as written (read exactly), --time-unit */
    const char *verb;                  /* `versor exp`: the operation word */
    const char *quat_order, *output_format, *twist_order, *columns;
    const char *stamps; /* --stamps FILE: the times of KITTI poses */
    int clip, dedup;
    double min_gap; /* --min-gap, in the keys' time unit */
    double rate;
    int header, normalize, text; /* --text: multivectors with blade names */
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
int cmd_object(const cli_opts *o);

#endif
