/* tools/interp_write.c: the output of `garotor interp`: each sample's stamp
 * and pose as --output-format says (a 4x4, a pose from the group's own
 * rotation and translation, KITTI's 3x4, CSV), with --with its velocity and
 * acceleration, at times outside the path's range as --extrapolate says; and
 * the picture of the path (--svg, --html: svg.h, html.h).
 *
 * Nothing but the keys (and given times) is held: each chunk of CHUNK sample
 * times is made, sampled, turned into rows and written before the next, each
 * sample once, so memory does not grow with the number of samples and the
 * first line comes out at once. A sample that cannot be computed stops the
 * run: a regular --out file and the picture are removed; on standard output
 * the samples before it stay written. */
#include "html.h"
#include "interp_cmd.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { CHUNK = 512 };

/* The pose of a rigid element straight from the group (to_qt: a rotor's own
 * quaternion and translation, no 4x4 in between): x y z then the quaternion
 * (qx qy qz qw, or qw qx qy qz with wxyz), its sign following *prev (the
 * previous sample's) so that the output is continuous. */
static void element_pose(const ga_group *g, const void *e, int wxyz, double prev[4], double *v)
{
    double q[4], p[3]; /* q = (w, x, y, z) */
    g->to_qt(e, q, p);
    if (q[0] * prev[0] + q[1] * prev[1] + q[2] * prev[2] + q[3] * prev[3] < 0.0)
        for (int i = 0; i < 4; i++) q[i] = -q[i];
    memcpy(prev, q, sizeof q);
    double pose[7] = {p[0], p[1], p[2], q[1], q[2], q[3], q[0]};
    if (wxyz) {
        pose[3] = q[0];
        memcpy(pose + 4, q + 1, 3 * sizeof *q);
    }
    memcpy(v, pose, sizeof pose);
}

/* An algebra element as written: 6 numbers on a rigid group (w v, or v w
 * with vw), else the 16 of its hat. */
static void put_algebra(const ga_group *g, int vw, const double *x, double *row)
{
    if (g->rigid) {
        memcpy(row, x + 3 * vw, 3 * sizeof *row);
        memcpy(row + 3, x + 3 * !vw, 3 * sizeof *row);
        return;
    }
    ga_mat4 h = g->hat(x);
    memcpy(row, h.m, sizeof h.m);
}

/* The pose at t: inside the path's range by the evaluator of --eval, outside
 * as --extrapolate says (ga_path_extrap_eval, as garotor.Path's
 * extrapolate=). */
static int sample_at(const ic_sampler *s, double t, void *o)
{
    double r0, r1;
    if (s->ev != GA_EVAL_DIRECT && ga_path_range(s->path, &r0, &r1) == GA_OK && t >= r0 && t <= r1)
        return ga_path_sample(s->path, s->ev, s->step, 1, &t, o);
    return ga_path_extrap_eval(&s->xp, t, o);
}

/* Velocity, acceleration and jerk at t (those not NULL: only they are
 * computed), extrapolated as the samples are (ga_path_extrap_derivatives). */
static int differentiate(const ic_sampler *s, double t, double *v, double *a, double *j)
{
    return ga_path_extrap_derivatives(&s->xp, t, s->frame, v, a, j);
}

/* The path with --extrapolate's mode, once (constant-velocity: the pose and
 * body velocity at both ends of the range). 0, or -1 after a message. */
static int extrap_ends(ic_sampler *s)
{
    int st = ga_path_extrap_init(s->path, (ga_extrap)s->extrap, &s->xp);
    if (st != GA_OK) {
        fprintf(stderr, "garotor interp: %s: no velocity at the end of the path: %s\n", s->in->name,
                ga_status_string(st));
        return -1;
    }
    return 0;
}

/* The samples a picture keeps: every stride-th from the first, and the last;
 * at most PICTURE_MAX + 1 matrices (128 bytes each) however many samples
 * are written: an 800-pixel picture shows no more. */
enum { PICTURE_MAX = 8192 };
typedef struct {
    ga_mat4 *m;
    size_t stride, n;
} picture_keep;

/* The row of sample k (the element e at t): its pose as --output-format
 * says, then with --with its velocity, acceleration and jerk (those asked); written to out (NULL:
 * not written). 0, or -1 after a message naming the sample and its time. */
static int put_row(const ic_sampler *s, tio_out *out, size_t k, double t, double off, const void *e,
                   double prev[4])
{
    const ga_group *g = s->g;
    double row[17 + 3 * 16];
    static char stamp[TT_DIG + 32];
    int pw = s->pw - 1; /* the pose's numbers, without t */
    if (s->out_fmt == IC_OUT_MAT || s->out_fmt == IC_OUT_KITTI) {
        ga_mat4 mat = g->to_mat4(e);
        memcpy(row + 1, mat.m, (size_t)pw * sizeof *row);
    } else
        element_pose(g, e, s->wxyz && s->out_fmt != IC_OUT_TUM, prev, row + 1);
    if (s->with_v || s->with_a || s->with_j) {
        double dv[GA_GROUP_MAX_DIM], da[GA_GROUP_MAX_DIM], dj[GA_GROUP_MAX_DIM];
        int st = differentiate(s, t, s->with_v ? dv : NULL, s->with_a ? da : NULL, s->with_j ? dj : NULL);
        if (st != GA_OK) {
            fprintf(stderr, "garotor interp: %s: sample %zu at t = %s: no velocity: %s\n", s->in->name, k + 1,
                    ic_stamp(s, k, t, off, stamp), ga_status_string(st));
            return -1;
        }
        double *col = row + s->pw;
        if (s->with_v)
            put_algebra(g, s->vw, dv, col), col += s->dw;
        if (s->with_a)
            put_algebra(g, s->vw, da, col), col += s->dw;
        if (s->with_j)
            put_algebra(g, s->vw, dj, col);
    }
    if (!out)
        return 0;
    if (s->out_fmt == IC_OUT_KITTI)
        tio_out_line(out, row + 1, s->width - 1);
    else
        tio_out_stamped(out, ic_stamp(s, k, t, off, stamp), row + 1, s->width - 1);
    return 0;
}

/* Every sample, made once: checked, written to out (NULL: not written) as it
 * is made and kept as a matrix in keep (NULL: not kept); *count is the
 * number of samples. A sample that cannot be computed stops the run with a
 * message naming it and its time. 0, or -1 after a message. */
static int run(const ic_sampler *s, tio_out *out, picture_keep *keep, size_t *count)
{
    const ga_group *g = s->g;
    const char *name = s->in->name;
    double t[CHUNK], off[CHUNK], prev[4] = {1, 0, 0, 0};
    static char stamp[TT_DIG + 32];
    unsigned char *buf = malloc(CHUNK * g->elem_size);
    ga_path_stepper stepper;
    size_t k = 0;
    int st = GA_OK, rc = -1;
    if (!buf)
        return ic_oom();
    if (s->kind == IC_UNIFORM)
        st = ga_path_stepper_init(s->path, s->ev, s->step, s->ns, s->times[s->i0], s->times[s->i1], &stepper);
    if (st != GA_OK) { /* cannot happen for a built path */
        fprintf(stderr, "garotor interp: %s: sampling failed: %s\n", name, ga_status_string(st));
        goto done;
    }
    /* an output that fails (a full disk; a pipe whose reader left, SIGPIPE
       ignored) stops the samples: tio_out_finish then says so */
    for (int more = 1; more && !(out && ferror(out->fp));) {
        size_t m = 0, good;
        while (m < CHUNK && (more = ic_sample_time(s, k + m, &t[m], &off[m]))) m++;
        if (m == 0)
            break;
        /* the chunk's poses; good: how many were made before one failed */
        if (s->kind == IC_UNIFORM) {
            for (good = 0; good < m; good++)
                if ((st = ga_path_stepper_next(&stepper, buf + good * g->elem_size)) != GA_OK)
                    break;
        } else if (!s->extrap && (st = ga_path_sample(s->path, s->ev, s->step, m, t, buf)) == GA_OK)
            good = m;
        else
            for (good = 0; good < m; good++)
                if ((st = sample_at(s, t[good], buf + good * g->elem_size)) != GA_OK)
                    break;
        for (size_t j = 0; j < good; j++, k++) {
            const void *e = buf + j * g->elem_size;
            if (keep && k % keep->stride == 0)
                keep->m[keep->n++] = g->to_mat4(e);
            else if (keep) /* the last sample so far, in the slot after the kept ones */
                keep->m[keep->n] = g->to_mat4(e);
            if (put_row(s, out, k, t[j], off[j], e, prev))
                goto done;
        }
        if (good < m) {
            fprintf(stderr, "garotor interp: %s: sample %zu at t = %s: sampling failed: %s\n", name, k + 1,
                    ic_stamp(s, k, t[good], off[good], stamp), ga_status_string(st));
            goto done;
        }
    }
    rc = 0;
    if (keep && k && (k - 1) % keep->stride != 0)
        keep->n++; /* the last sample, off the stride */
done:
    free(buf);
    *count = k;
    return rc;
}

/* The picture of the path: the keys (labelled with their times key_t), the
 * nm samples kept in m (of ns made, in the order sampled) and, for the
 * screw scheme on keys that follow one screw motion, its axis: to svg and
 * html, finished but not renamed (svg.h). */
static int draw(const ic_opts *io, const ic_input *in, const double *key_t, const ga_mat4 *m, size_t nm,
                size_t ns, tio_out *svg, tio_out *html)
{
    const cli_opts *o = io->o;
    size_t n = in->n;
    char title[256], step[64] = "";
    if (io->ev == GA_EVAL_EULER)
        snprintf(step, sizeof step, ", step %g", o->step);
    snprintf(title, sizeof title, "%s: %zu keys, %zu samples (group %s, eval %s%s)",
             ga_scheme_name(io->scheme), n, ns, io->g->name, ga_eval_name(io->ev), step);
    int frames = 4 * (int)(n - 1) < 12 ? 12 : 4 * (int)(n - 1) > 48 ? 48 : 4 * (int)(n - 1);
    svg_path path = {ga_scheme_name(io->scheme), "#333333", m, nm, frames};
    svg_picture pic = {title, io->view, in->keys, key_t, n, &path, 1, 0, {0, 0, 0}, {0, 0, 0}};
    pic.has_axis = io->scheme == GA_SCHEME_SCREW &&
                   svg_screw_axis(in->keys, n, &pic.axis_point, &pic.axis_dir);
    int st = o->svg ? svg_write(svg, o->svg, &pic) : 0;
    if (st == 0 && o->html && (st = html_write(html, o->html, &pic)) != 0)
        tio_out_discard(svg);
    return st;
}

/* The header line of --output-format csv: the names of the columns. */
static void csv_header(const ic_sampler *s, tio_out *out)
{
    static const char *const pose[2][7] = {{"x", "y", "z", "qx", "qy", "qz", "qw"},
                                           {"x", "y", "z", "qw", "qx", "qy", "qz"}};
    static const char *const tw[2][6] = {{"wx", "wy", "wz", "vx", "vy", "vz"},
                                         {"vx", "vy", "vz", "wx", "wy", "wz"}};
    fputs("t", out->fp);
    for (int i = 0; i < 7; i++) fprintf(out->fp, ",%s", pose[s->wxyz][i]);
    static const char *const prefix[3] = {"", "d", "dd"}; /* velocity, acceleration, jerk */
    const int with[3] = {s->with_v, s->with_a, s->with_j};
    for (int d = 0; d < 3; d++)
        for (int i = 0; i < 6 && with[d]; i++) fprintf(out->fp, ",%s%s", prefix[d], tw[s->vw][i]);
    fputc('\n', out->fp);
}

/* The samples are made once, each written as it is made: a regular --out
 * file is written beside its name and renamed onto it only when every sample
 * was written; to standard output, a FIFO or a device the samples before a
 * failure stay written. The picture (--svg, --html) keeps the samples'
 * matrices (at most PICTURE_MAX + 1 of them) as they are written, and is drawn
 * to its temporary file after the last sample and renamed after the samples'
 * file, so a run cut off while it writes (a write error, `| head` and its
 * SIGPIPE, any other signal) leaves no picture of samples it did not write. */
int ic_write(const ic_opts *io, const ic_input *in, ic_sampler *smp)
{
    const cli_opts *o = io->o;
    size_t n = in->n;
    int drawn = o->svg || o->html, rc = -1;
    double *key_t = NULL;
    picture_keep pk = {NULL, 1, 0};
    tio_out out = TIO_OUT_NONE, svg = TIO_OUT_NONE, html = TIO_OUT_NONE;
    if (extrap_ends(smp))
        goto done;
    if (drawn) { /* the picture labels the keys with their times as read */
        key_t = malloc(n * sizeof *key_t);
        pk.stride = smp->ns > PICTURE_MAX ? (smp->ns + PICTURE_MAX - 1) / PICTURE_MAX : 1;
        pk.m = malloc(((smp->ns + pk.stride - 1) / pk.stride + 1) * sizeof *pk.m);
        if (!key_t || !pk.m) {
            ic_oom();
            goto done;
        }
        for (size_t i = 0; i < n; i++) key_t[i] = strtod(in->in.first[i], NULL); /* KITTI: i, or its stamp */
    }
    if (tio_out_open(&out, o->out))
        goto done;
    if (smp->out_fmt == IC_OUT_CSV) {
        out.sep = ',';
        csv_header(smp, &out);
    }
    size_t ns = 0;
    if (run(smp, &out, drawn ? &pk : NULL, &ns) != 0 ||
        (drawn && draw(io, in, key_t, pk.m, pk.n, ns, &svg, &html) != 0)) {
        tio_out_close(&out, 0);
        goto done;
    }
    if (tio_out_finish(&out) != 0) {
        tio_out_close(&out, 0);
        goto done;
    }
    /* every output written: renamed, the samples last; a rename that fails
       (rare: each is renamed within its own directory) takes back the ones
       renamed before it */
    if (tio_out_commit(&svg) != 0)
        goto done;
    if (tio_out_commit(&html) != 0) {
        if (o->svg)
            tio_out_unwrite(o->svg);
        goto done;
    }
    if (tio_out_commit(&out) != 0) {
        if (o->svg)
            tio_out_unwrite(o->svg);
        if (o->html)
            tio_out_unwrite(o->html);
        goto done;
    }
    rc = 0;
done:
    tio_out_discard(&svg);
    tio_out_discard(&html);
    if (rc)
        tio_out_discard(&out);
    free(key_t);
    free(pk.m);
    return rc;
}
