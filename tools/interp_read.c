/* tools/interp_read.c: the inputs of `garotor interp`, read and checked
 * before anything is written (docs/tool.md): the keys (t, then a pose: 16
 * numbers with --format mat, 7 with --format pose), the given times (--at
 * t1,t2,... or --times FILE) and the velocities (--v0, --velocities FILE). */
#include "columns.h"
#include "interp_cmd.h"
#include "stamps.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* A unit quaternion (qx qy qz qw, or qw qx qy qz with --quat-order wxyz) and
 * a position to a 4x4 matrix; -1 after a message when q is not unit to 1e-9,
 * or with --normalize to GA_SE3_NORMALIZE_TOL (then q is divided by its norm:
 * ga_quat_normalize). A norm far from 1 (beyond what --normalize accepts)
 * where the first four numbers have norm 1 is named as a quaternion written
 * before the position. */
static int pose_to_mat4(const ic_opts *io, const tio_items *in, size_t i, const double *v, ga_mat4 *out)
{
    int normalize = io->o->normalize;
    ga_quat q = io->wxyz ? (ga_quat){v[3], v[4], v[5], v[6]} : (ga_quat){v[6], v[3], v[4], v[5]};
    double norm = sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
    double first = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2] + v[3] * v[3]);
    const char *hint = !io->o->columns && fabs(norm - 1.0) > GA_SE3_NORMALIZE_TOL &&
                               fabs(first - 1.0) <= (normalize ? GA_SE3_NORMALIZE_TOL : 1e-9)
                         ? "; the four numbers after t have norm 1: is the quaternion written before the "
                           "position? the tool reads t x y z, then the quaternion"
                         : "";
    if (normalize && ga_quat_normalize(q, GA_SE3_NORMALIZE_TOL, &q) != GA_OK)
        return tio_error(in, i,
                         "not a rigid motion: the quaternion has norm %.17g, farther from 1 "
                         "than --normalize accepts (1e-3)%s",
                         norm, hint);
    if (!normalize && fabs(norm - 1.0) > 1e-9)
        return tio_error(in, i,
                         "not a rigid motion: the quaternion has norm %.17g, not 1 "
                         "(to 1e-9; --normalize accepts up to 1e-3)%s",
                         norm, hint);
    *out = ga_rotor_to_mat4(ga_rotor_from_quat(q, (ga_vec3){v[0], v[1], v[2]}));
    return 0;
}

/* A key read as a matrix, on a rigid group with --normalize: projected onto
 * the group (ga_se3_normalize) when within GA_SE3_NORMALIZE_TOL; without it,
 * a matrix off by more than 1e-9 but within that is refused with a message
 * naming --normalize. 1 when this handled it (0: ok, -1: error after a
 * message), 0 to leave the key to cli_check_motion. */
static int normalize_key(const ga_group *g, int normalize, const tio_items *in, size_t i, ga_mat4 *m, int *rc)
{
    ga_mat4 r;
    if (!g->rigid || ga_se3_normalize(*m, GA_SE3_NORMALIZE_TOL, &r) != GA_OK)
        return 0; /* cli_check_motion says what is wrong */
    if (normalize) {
        *m = r;
        *rc = 0;
        return 1;
    }
    if (ga_se3_check(*m, 1e-9) == GA_OK)
        return 0;
    double off = 0.0;
    for (int k = 0; k < 16; k++) off = fmax(off, fabs(m->m[k] - r.m[k]));
    *rc = tio_error(in, i,
                    "not a rigid motion to 1e-9 (it is %.3g from the nearest one); "
                    "--normalize accepts up to 1e-3",
                    off);
    return 1;
}

int ic_parse_at(const char *s, ic_input *in)
{
    size_t cap = 1;
    for (const char *c = s; *c; c++) cap += *c == ',';
    char *b = malloc(strlen(s) + 1);
    char **t = malloc(cap * sizeof *t);
    if (!b || !t) {
        free(b);
        free(t);
        return ic_oom();
    }
    strcpy(b, s);
    size_t k = 0;
    char *c = b;
    for (;;) {
        char *end;
        double x = strtod(c, &end);
        if (end == c || !isfinite(x) || (*end != ',' && *end != '\0')) {
            fprintf(stderr, "garotor interp: --at needs finite times separated by commas: '%s'\n", s);
            free(b);
            free(t);
            return -1;
        }
        while (*c == ' ' || *c == '\t' || *c == '\n' || *c == '\r' || *c == '\f' || *c == '\v') c++;
        t[k++] = c;
        int last = *end == '\0';
        *end = '\0';
        if (last)
            break;
        c = end + 1;
    }
    in->at_buf = b;
    in->at_arg = t;
    in->nat = k;
    return 0;
}

/* A KITTI key: 12 numbers, the 3x4 [R t] row by row. Without --stamps it
 * is at time i (its text made "i", so that samples there are stamped so). */
static int read_kitti(const ic_opts *io, ic_timebase *tb, ic_input *in, size_t i)
{
    tio_items *f = &in->in;
    int m = f->item[i].count;
    if (m != 12)
        return tio_error(f, i, "expected 12 numbers (a KITTI pose: the 3x4 [R t] row by row), found %d%s", m,
                         m == 8               ? ": is this a pose file? pass --format pose"
                         : m == 17 || m == 16 ? ": is this a file of 4x4 matrices? drop --format kitti"
                                              : "");
    if (!io->o->stamps) {
        char b[32], *t;
        int len = snprintf(b, sizeof b, "%zu", i);
        if (!(t = malloc((size_t)len + 1)))
            return ic_oom();
        memcpy(t, b, (size_t)len + 1);
        free(f->first[i]);
        f->first[i] = t;
        if (i == 0)
            tt_parse(t, &tb->ref);
        in->times[i] = (double)i;
    }
    ga_mat4 *k = &in->keys[i];
    memcpy(k->m, f->value + f->item[i].first, 12 * sizeof *k->m);
    k->m[12] = k->m[13] = k->m[14] = 0.0;
    k->m[15] = 1.0;
    int krc;
    return normalize_key(io->g, io->o->normalize, f, i, k, &krc) ? krc : cli_check_motion(io->g, *k, f, i);
}

/* Key i: its number of numbers, its time (the first key's is the
 * reference; with no --time-unit, a whole number of 12 digits or more is
 * refused: st_guess_unit), after the one before, and its pose an element of
 * the group. A KITTI key's time is its --stamps line's (st_kitti_stamps
 * made it the key's text), or i. */
static int read_key(const ic_opts *io, ic_timebase *tb, ic_input *in, size_t i)
{
    const tio_items *f = &in->in;
    int want = io->pose ? 8 : 17;
    if (io->kitti && !io->o->stamps)
        return read_kitti(io, tb, in, i);
    if (io->kitti && read_kitti(io, tb, in, i))
        return -1;
    /* a line of separators only is an item of no numbers, and with no
       number in the whole input value is NULL: no pointer arithmetic on
       it (undefined; found by fuzz/fuzz_tool under UBSan:
       fuzz/regress/tool/interp-comma-line-no-numbers) */
    const double *v = f->item[i].count ? f->value + f->item[i].first : NULL;
    if (!io->kitti && f->item[i].count != want) {
        /* the count says what the line probably is: a pose (t and 7) read as
           a matrix, a matrix (t and 16) read as a pose, a key without its t */
        int m = f->item[i].count;
        const char *hint = !io->pose && io->g->rigid && m == 8 ? ": is this a pose file? pass --format pose"
                         : io->pose && m == 17     ? ": is this a file of 4x4 matrices? drop --format pose"
                         : m == want - 1           ? ": is t missing? a key is its time, then the pose"
                         : m == 12 && io->g->rigid ? ": is this a KITTI file (3x4, no t)? pass --format kitti"
                                                   : "";
        return tio_error(f, i, "expected %d numbers (t, then %s), found %d%s", want,
                         io->pose ? "x y z qx qy qz qw" : "a 4x4 matrix", m, hint);
    }
    if (i == 0 && !io->unit_given && st_guess_unit(f, 0))
        return -1;
    if (tb->ns && st_whole_ns(f, i))
        return -1;
    if (i == 0)
        tt_parse(f->first[0], &tb->ref);
    in->times[i] = ic_rel_time(tb, f->first[i]);
    if (i > 0 && !(in->times[i] > in->times[i - 1]))
        return tio_error(f, i, "key times must increase strictly: %s after %s", f->first[i], f->first[i - 1]);
    if (io->kitti)
        return 0;
    if (io->pose)
        return pose_to_mat4(io, f, i, v + 1, &in->keys[i]);
    int krc;
    memcpy(in->keys[i].m, v + 1, sizeof in->keys[i].m);
    return normalize_key(io->g, io->o->normalize, f, i, &in->keys[i], &krc)
             ? krc
             : cli_check_motion(io->g, in->keys[i], f, i);
}

/* Keys i0..i1 (closer than --min-gap) merged into key i0: the mean of their
 * times and poses (ga_path_merge_keys, as garotor.Path's dedup=), the mean
 * time stamped as the tool stamps a computed time. 0, or -1 after a
 * message. */
static int merge_keys(const ic_timebase *tb, ic_input *in, size_t i0, size_t i1)
{
    tio_items *f = &in->in;
    size_t m = i1 - i0 + 1;
    double t;
    ga_mat4 mean;
    if (m > GA_PATH_MERGE_MAX)
        return tio_error(f, i0, "more than %d keys closer than --min-gap in a row: is --min-gap too large?",
                         GA_PATH_MERGE_MAX);
    int st = ga_path_merge_keys(m, in->times + i0, in->keys + i0, tb->ns, &t, &mean);
    if (st != GA_OK)
        return tio_error(f, i0, "cannot merge the keys of lines %ld to %ld: %s", f->item[i0].line,
                         f->item[i1].line, ga_status_string(st));
    /* the mean time's text: the shortest decimal of it (whole ns with
       --time-unit ns) added to the first key's, exactly */
    static tt_dec o;
    char *text = malloc(TT_DIG + 32);
    if (!text)
        return ic_oom();
    if (tb->ns) {
        char b[400];
        snprintf(b, sizeof b, "%.0f", t);
        tt_parse(b, &o);
    } else
        tt_shortest(t, &o);
    if (tt_add(&tb->ref, &o, 0, &o)) { /* cannot happen (timetext.h) */
        free(text);
        return ic_oom();
    }
    tt_format(&o, text);
    free(f->first[i0]);
    f->first[i0] = text;
    in->times[i0] = ic_rel_time(tb, text);
    in->keys[i0] = mean;
    return 0;
}

/* Keys closer than --min-gap (default: 1% of the median spacing,
 * ga_times_min_gap): an error naming the pair, or with --dedup merged (the
 * keys, their times, texts and lines compacted). 0, or -1 after a message. */
static int near_duplicates(const ic_opts *io, const ic_timebase *tb, ic_input *in)
{
    const cli_opts *o = io->o;
    tio_items *f = &in->in;
    size_t n = in->n;
    double unit = tb->ns ? 1e-9 : 1.0, gap = o->min_gap * unit, median = 0.0;
    const char *u = tb->ns ? "ns" : "s";
    if (n < 2 || ((o->given & OPT_MIN_GAP) && o->min_gap == 0.0))
        return 0;
    if (!(o->given & OPT_MIN_GAP)) {
        double *g = malloc((n - 1) * sizeof *g);
        if (!g)
            return ic_oom();
        int st = ga_times_min_gap(n, in->times, g, &median, &gap);
        free(g);
        if (st != GA_OK) /* cannot happen: the times are finite and increasing */
            return ic_oom();
    }
    size_t out = 0;
    for (size_t i = 0; i < n;) {
        size_t j = ga_times_gap_run(n, in->times, gap, i);
        if (j > i && !o->dedup) {
            char dflt[96] = "";
            if (!(o->given & OPT_MIN_GAP))
                snprintf(dflt, sizeof dflt, " (1%% of the median spacing, %.6g %s)", median / unit, u);
            return tio_error(
                f, i + 1,
                "key at t = %s is %.3g %s after the key at t = %s (line %ld), closer than --min-gap "
                "%.6g %s%s: pass --dedup to merge such keys, or --min-gap 0 to keep them",
                f->first[i + 1], (in->times[i + 1] - in->times[i]) / unit, u, f->first[i], f->item[i].line,
                gap / unit, u, dflt);
        }
        if (j > i && merge_keys(tb, in, i, j))
            return -1;
        if (out != i) {
            in->times[out] = in->times[i];
            in->keys[out] = in->keys[i];
            char *keep = f->first[i];
            f->first[i] = f->first[out];
            f->first[out] = keep;
            f->item[out] = f->item[i];
        }
        out++;
        i = j + 1;
    }
    in->n = out;
    return 0;
}

int ic_read_keys(const ic_opts *io, ic_timebase *tb, ic_input *in)
{
    ga_scheme scheme = io->scheme;
    tio_read_opts ro = cli_input(io->o);
    if (io->o->columns ? col_read_poses("interp", io->o->in, io->o->columns, &ro, &in->in, NULL)
                       : tio_read_first(io->o->in, &ro, &in->in))
        return -1;
    if (io->o->stamps && st_kitti_stamps(io->o->stamps, io->o->max_line, io->ns, !io->unit_given, &in->in))
        return -1;
    size_t n = in->n = in->in.n;
    in->times = malloc((n ? n : 1) * sizeof *in->times);
    in->keys = malloc((n ? n : 1) * sizeof *in->keys);
    if (!in->times || !in->keys)
        return ic_oom();
    for (size_t i = 0; i < n; i++)
        if (read_key(io, tb, in, i))
            return -1;
    if (near_duplicates(io, tb, in))
        return -1;
    n = in->n;
    size_t min = ga_scheme_min_keys(scheme);
    if (n != 1 && (n < min || (scheme == GA_SCHEME_QUADRATIC && n != 3))) {
        fprintf(stderr, "garotor interp: %s: --scheme %s needs one key or %s %zu, found %zu\n", in->in.name,
                ga_scheme_name(scheme), scheme == GA_SCHEME_QUADRATIC ? "exactly" : "at least", min, n);
        return -1;
    }
    size_t bad = scheme == GA_SCHEME_BSPLINE ? ga_times_uneven(n, in->times) : 0;
    if (bad) {
        const double *times = in->times;
        double grid = times[0] + (times[n - 1] - times[0]) * (double)bad / (double)(n - 1);
        return tio_error(&in->in, bad,
                         "--scheme bspline needs evenly spaced key times (to 1e-9 of the spacing): %s is "
                         "%.3g s off the even grid of the first and last key (spacing %.17g s)",
                         in->in.first[bad], (times[bad] - grid) * (tb->ns ? 1e9 : 1.0),
                         (times[n - 1] - times[0]) / (double)(n - 1));
    }
    /* the path's range (ga_path_range): from key i0 to key i1, the first
       and last key, but for bspline the second and the last but one */
    in->i0 = scheme == GA_SCHEME_BSPLINE && n > 1;
    in->i1 = n - 1 - in->i0;
    return 0;
}

int ic_read_times(const ic_opts *io, const ic_timebase *tb, ic_input *in)
{
    const cli_opts *o = io->o;
    if (o->times) { /* --times FILE: one time a line */
        const tio_items *f = &in->tin;
        tio_read_opts ro = cli_other_input(o);
        if (tio_read_first(o->times, &ro, &in->tin))
            return -1;
        in->nat = f->n;
        for (size_t k = 0; k < in->nat; k++)
            if (f->item[k].count != 1)
                return tio_error(f, k, "expected 1 number (a time), found %d", f->item[k].count);
            else if (tb->ns && st_whole_ns(f, k))
                return -1;
        if (in->nat == 0) {
            fprintf(stderr, "garotor interp: %s: no times\n", f->name);
            return -1;
        }
        in->at_text = f->first;
    }
    if (o->at) {
        for (size_t k = 0; k < in->nat; k++)
            if (tb->ns && !ic_whole(in->at_arg[k])) {
                fprintf(stderr, "garotor interp: --at: --time-unit ns takes whole nanoseconds, not '%s'\n",
                        in->at_arg[k]);
                return -1;
            }
        in->at_text = in->at_arg;
    }
    if (in->at_text) { /* given times, relative to the first key's */
        in->at = malloc(in->nat * sizeof *in->at);
        if (!in->at)
            return ic_oom();
        for (size_t k = 0; k < in->nat; k++) in->at[k] = ic_rel_time(tb, in->at_text[k]);
    }
    if (in->at_text && io->clip) { /* --clip: those outside the range dropped */
        if (!(in->clip_text = malloc(in->nat * sizeof *in->clip_text)))
            return ic_oom();
        size_t m = 0;
        for (size_t k = 0; k < in->nat; k++)
            if (in->at[k] >= in->times[in->i0] && in->at[k] <= in->times[in->i1]) {
                in->at[m] = in->at[k];
                in->clip_text[m++] = in->at_text[k];
            }
        in->nat = m;
        in->at_text = in->clip_text;
    }
    return 0;
}

/* A velocity as the tool reads it: 6 numbers, a twist (on every group: its
 * hat read by the group's vee), or on a group that is not rigid 16, a 4x4
 * with last row zero. Writes g->dim doubles. */
static int read_velocity(const ga_group *g, int vw, const double *v, int count, double *x)
{
    ga_mat4 a;
    if (count == 6 && vw) /* --twist-order vw: v first */
        a = ga_twist_hat((ga_twist){{v[3], v[4], v[5]}, {v[0], v[1], v[2]}});
    else if (count == 6)
        a = ga_twist_hat((ga_twist){{v[0], v[1], v[2]}, {v[3], v[4], v[5]}});
    else if (count == 16 && !g->rigid)
        memcpy(a.m, v, sizeof a.m);
    else
        return -1;
    return g->vee(a, x) == GA_OK ? 0 : -1;
}

int ic_read_velocities(const ic_opts *io, ic_input *in)
{
    const cli_opts *o = io->o;
    const ga_group *g = io->g;
    size_t n = in->n;
    const tio_items *f = &in->vin;
    /* --v0 for lihao2, --velocities FILE (one a key) for lihao3 */
    if (o->given & OPT_V0) {
        in->vel = malloc(GA_GROUP_MAX_DIM * sizeof *in->vel);
        if (!in->vel)
            return ic_oom();
        read_velocity(g, io->vw, o->v0, 6, in->vel);
    }
    if (!o->velocities)
        return 0;
    tio_read_opts ro = cli_other_input(o);
    if (tio_read(o->velocities, &ro, &in->vin))
        return -1;
    if (f->n != n) {
        if (f->n > n)
            return tio_error(f, n, "one velocity per key: %zu keys, but %zu velocities", n, f->n);
        fprintf(stderr, "garotor interp: %s: one velocity per key: %zu keys, but %zu velocities\n", f->name,
                n, f->n);
        return -1;
    }
    in->vel = malloc(n * (size_t)g->dim * sizeof *in->vel);
    if (!in->vel)
        return ic_oom();
    for (size_t i = 0; i < n; i++)
        if (read_velocity(g, io->vw, f->item[i].count ? f->value + f->item[i].first : NULL, f->item[i].count,
                          in->vel + i * (size_t)g->dim))
            return tio_error(f, i,
                             "expected 6 numbers (a body velocity %s)%s, "
                             "found %d",
                             io->vw ? "v1 v2 v3 w1 w2 w3" : "w1 w2 w3 v1 v2 v3",
                             g->rigid ? "" : " or 16 (a 4x4, last row zero)", f->item[i].count);
    return 0;
}

void ic_input_free(ic_input *in)
{
    free(in->times);
    free(in->keys);
    free(in->at);
    free(in->at_buf);
    free(in->at_arg);
    free(in->clip_text);
    free(in->vel);
    tio_free(&in->in);
    tio_free(&in->vin);
    tio_free(&in->tin);
}
