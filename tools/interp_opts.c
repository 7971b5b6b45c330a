/* tools/interp_opts.c: the options of `garotor interp` (docs/tool.md), parsed
 * and checked into an ic_opts before any file is read. The checks run in a
 * fixed order, so a command line with several mistakes is told the first. */
#include "html.h"
#include "interp_cmd.h"
#include "stamps.h"

#include <stdio.h>
#include <string.h>

/* --group, --scheme, --eval, --step and --format: the path and its keys. */
static int path_options(const cli_opts *o, ic_opts *io)
{
    io->g = cli_group("interp", o);
    if (!io->g)
        return -1;
    io->scheme = GA_SCHEME_SCREW;
    if (o->scheme && ga_scheme_by_name(o->scheme, &io->scheme) != GA_OK) {
        fprintf(stderr,
                "garotor interp: --scheme must be screw, bivector, quadratic, smooth, "
                "lihao2, lihao3, decoupled, decoupled-c2, bspline or c2, not '%s'\n",
                o->scheme);
        return -1;
    }
    io->ev = GA_EVAL_DIRECT;
    if (o->eval && ga_eval_by_name(o->eval, &io->ev) != GA_OK) {
        fprintf(stderr, "garotor interp: --eval must be direct, euler or exact, not '%s'\n", o->eval);
        return -1;
    }
    if (io->ev == GA_EVAL_EULER && !(o->given & OPT_STEP)) {
        fprintf(stderr, "garotor interp: --eval euler needs --step H (in u units, 1e-9 <= H <= 1)\n");
        return -1;
    }
    if ((o->given & OPT_STEP) && io->ev != GA_EVAL_EULER) {
        fprintf(stderr, "garotor interp: --step applies only to --eval euler\n");
        return -1;
    }
    io->pose = io->kitti = 0;
    if (o->format && strcmp(o->format, "pose") == 0)
        io->pose = 1;
    else if (o->format && strcmp(o->format, "kitti") == 0)
        io->kitti = 1;
    else if (o->format && strcmp(o->format, "mat") != 0) {
        fprintf(stderr, "garotor interp: --format must be mat, pose or kitti, not '%s'\n", o->format);
        return -1;
    }
    if (o->columns && o->format && !io->pose) {
        fprintf(stderr, "garotor interp: --columns reads poses: drop --format %s\n", o->format);
        return -1;
    }
    if (o->columns)
        io->pose = 1;
    if (o->columns && o->quat_order) {
        fprintf(stderr, "garotor interp: --columns names the quaternion's columns: drop --quat-order\n");
        return -1;
    }
    if (io->pose && !io->g->rigid) {
        fprintf(stderr, "garotor interp: --group %s takes keys as matrices (--format mat)\n", io->g->name);
        return -1;
    }
    return 0;
}

/* The sample times (one of --samples, --at, --rate, --times), --extrapolate,
 * the velocities (--v0, --velocities) and --normalize. */
static int sample_options(const cli_opts *o, ic_opts *io)
{
    int nwhen = !!(o->given & OPT_SAMPLES) + !!(o->given & OPT_AT) + !!(o->given & OPT_RATE) +
                !!(o->given & OPT_TIMES);
    if (nwhen != 1) {
        fprintf(stderr, "garotor interp: give one of --samples N, --at t1,t2,..., --rate HZ, --times FILE\n");
        return -1;
    }
    ga_extrap x = GA_EXTRAP_ERROR; /* the names of ga_extrap_by_name, as garotor.Path's */
    if (o->extrapolate && ga_extrap_by_name(o->extrapolate, &x) != GA_OK) {
        fprintf(stderr,
                "garotor interp: --extrapolate must be error, hold, extend or constant-velocity, not '%s'\n",
                o->extrapolate);
        return -1;
    }
    io->extrap = (int)x;
    io->clip = o->clip;
    if (o->clip && o->extrapolate) {
        fprintf(stderr, "garotor interp: --clip drops the times --extrapolate %s would sample: give one\n",
                o->extrapolate);
        return -1;
    }
    if ((o->given & OPT_V0) && io->scheme != GA_SCHEME_LIHAO2) {
        fprintf(stderr, "garotor interp: --v0 applies only to --scheme lihao2\n");
        return -1;
    }
    if ((o->given & OPT_VELOCITIES) && io->scheme != GA_SCHEME_LIHAO3) {
        fprintf(stderr, "garotor interp: --velocities applies only to --scheme lihao3\n");
        return -1;
    }
    if (o->dedup && !io->g->rigid) {
        fprintf(stderr, "garotor interp: --dedup applies to --group cga or matrix\n");
        return -1;
    }
    if (o->normalize && !io->g->rigid) {
        fprintf(stderr, "garotor interp: --normalize applies to --group cga or matrix\n");
        return -1;
    }
    return 0;
}

/* --with: a comma-separated list of velocity, acceleration and jerk, each at
 * most once (the columns come in that order whatever the list's). */
static int with_list(const char *s, ic_opts *io)
{
    static const char *const name[3] = {"velocity", "acceleration", "jerk"};
    int *flag[3] = {&io->with_v, &io->with_a, &io->with_j};
    while (*s) {
        size_t len = strcspn(s, ",");
        int k = 0;
        while (k < 3 && !(strlen(name[k]) == len && strncmp(s, name[k], len) == 0)) k++;
        if (k == 3 || *flag[k])
            return -1;
        *flag[k] = 1;
        s += len;
        if (*s == ',' && *++s == '\0')
            return -1;
    }
    return io->with_v + io->with_a + io->with_j ? 0 : -1;
}

/* What a row holds besides the pose (--with, --frame) and --time-unit. */
static int row_options(const cli_opts *o, ic_opts *io)
{
    io->with_v = io->with_a = io->with_j = 0;
    io->frame = GA_FRAME_BODY;
    if (o->with && with_list(o->with, io)) {
        fprintf(stderr,
                "garotor interp: --with must list velocity, acceleration or jerk (each once, joined by "
                "commas), not '%s'\n",
                o->with);
        return -1;
    }
    if (o->frame && strcmp(o->frame, "spatial") == 0)
        io->frame = GA_FRAME_SPATIAL;
    else if (o->frame && strcmp(o->frame, "world") == 0)
        io->frame = GA_FRAME_WORLD;
    else if (o->frame && strcmp(o->frame, "body") != 0) {
        fprintf(stderr, "garotor interp: --frame must be body, spatial or world, not '%s'\n", o->frame);
        return -1;
    }
    if (o->frame && !o->with) {
        fprintf(stderr, "garotor interp: --frame applies only with --with velocity,acceleration,jerk\n");
        return -1;
    }
    if (io->frame == GA_FRAME_WORLD && !io->g->rigid) {
        fprintf(stderr, "garotor interp: --frame world needs a rigid group (--group cga or matrix)\n");
        return -1;
    }
    if (o->stamps && !io->kitti) {
        fprintf(stderr, "garotor interp: --stamps gives KITTI poses their times: it needs --format kitti\n");
        return -1;
    }
    if (o->time_unit && io->kitti && !o->stamps) {
        fprintf(stderr, "garotor interp: --format kitti has no times (key k is at t = k): drop --time-unit, "
                        "or give the times with --stamps FILE\n");
        return -1;
    }
    io->unit_given = o->time_unit != NULL;
    return st_time_unit("interp", o->time_unit, &io->ns);
}

/* The layout of a row written (--output-format, --quat-order,
 * --twist-order). */
static int layout_options(const cli_opts *o, ic_opts *io)
{
    static const char *const fmt[] = {"mat", "pose", "tum", "kitti", "csv"};
    io->out_fmt = io->pose ? IC_OUT_POSE : io->kitti ? IC_OUT_KITTI : IC_OUT_MAT;
    if (o->output_format) {
        io->out_fmt = 0;
        while (io->out_fmt < 5 && strcmp(o->output_format, fmt[io->out_fmt]) != 0) io->out_fmt++;
        if (io->out_fmt == 5) {
            fprintf(stderr,
                    "garotor interp: --output-format must be mat, pose, tum, kitti or csv, not '%s'\n",
                    o->output_format);
            return -1;
        }
    }
    int quat_out = io->out_fmt == IC_OUT_POSE || io->out_fmt == IC_OUT_TUM || io->out_fmt == IC_OUT_CSV;
    if (quat_out && !io->g->rigid) {
        fprintf(stderr, "garotor interp: --group %s writes matrices (--output-format mat or kitti)\n",
                io->g->name);
        return -1;
    }
    if ((io->with_v || io->with_a || io->with_j) &&
        (io->out_fmt == IC_OUT_TUM || io->out_fmt == IC_OUT_KITTI)) {
        fprintf(stderr, "garotor interp: --output-format %s has no room for --with: use pose, mat or csv\n",
                fmt[io->out_fmt]);
        return -1;
    }
    io->wxyz = 0;
    if (o->quat_order && strcmp(o->quat_order, "wxyz") == 0)
        io->wxyz = 1;
    else if (o->quat_order && strcmp(o->quat_order, "xyzw") != 0) {
        fprintf(stderr, "garotor interp: --quat-order must be xyzw or wxyz, not '%s'\n", o->quat_order);
        return -1;
    }
    if (o->quat_order && !io->pose && !(quat_out && io->out_fmt != IC_OUT_TUM)) {
        fprintf(stderr,
                "garotor interp: --quat-order applies to --format pose, --output-format pose or csv\n");
        return -1;
    }
    io->vw = 0;
    if (o->twist_order && strcmp(o->twist_order, "vw") == 0)
        io->vw = 1;
    else if (o->twist_order && strcmp(o->twist_order, "wv") != 0) {
        fprintf(stderr, "garotor interp: --twist-order must be wv or vw, not '%s'\n", o->twist_order);
        return -1;
    }
    if (o->twist_order && !io->g->rigid) {
        fprintf(stderr, "garotor interp: --twist-order applies to --group cga or matrix\n");
        return -1;
    }
    return 0;
}

/* --out, --svg (and --view), --html: each a different file. */
static int file_options(const cli_opts *o, ic_opts *io)
{
    if (svg_options("interp", o->svg, o->view, &io->view) || html_options("interp", o->html))
        return -1;
    /* one file for two outputs: the second would silently replace the first */
    const char *files[3] = {o->out, o->svg, o->html}, *opt[3] = {"--out", "--svg", "--html"};
    for (int i = 0; i < 3; i++)
        for (int j = i + 1; j < 3; j++)
            if (files[i] && files[j] && strcmp(files[i], files[j]) == 0) {
                fprintf(stderr, "garotor interp: %s and %s name the same file: %s\n", opt[i], opt[j],
                        files[i]);
                return -1;
            }
    return 0;
}

int ic_options(const cli_opts *o, ic_opts *io)
{
    io->o = o;
    if (path_options(o, io) || sample_options(o, io) || row_options(o, io) || layout_options(o, io) ||
        file_options(o, io))
        return -1;
    return 0;
}
