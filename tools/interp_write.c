/* tools/interp_write.c: the output of `garotor interp`: each sample's stamp
 * and pose (a 4x4, or x y z qx qy qz qw with --format pose), with --with its
 * velocity and acceleration, at times outside the path's range as
 * --extrapolate says; and the picture of the path (--svg, --html: svg.h,
 * html.h).
 *
 * Nothing but the keys (and given times) is held: each chunk of CHUNK sample
 * times is made, sampled, turned into rows and written before the next, so
 * memory does not grow with the number of samples. A failure still leaves no
 * output: neither the samples' file nor the picture. */
#include "html.h"
#include "interp_cmd.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { CHUNK = 512 };

/* The pose (x y z qx qy qz qw) of a rigid 4x4 matrix; the quaternion's sign
 * follows *prev (the previous sample's) so that the output is continuous.
 * Returns the status of reading m as a rigid motion. */
static int mat4_to_pose(ga_mat4 m, ga_quat *prev, double *v)
{
    ga_rotor r;
    ga_vec3 t = {m.m[3], m.m[7], m.m[11]};
    int st = ga_rotor_from_mat4(m, &r);
    if (st != GA_OK)
        return st;
    ga_quat q = ga_rotor_to_quat(r);
    if (q.w * prev->w + q.x * prev->x + q.y * prev->y + q.z * prev->z < 0.0)
        q = (ga_quat){-q.w, -q.x, -q.y, -q.z};
    *prev = q;
    double pose[7] = {t.x, t.y, t.z, q.x, q.y, q.z, q.w};
    memcpy(v, pose, sizeof pose);
    return GA_OK;
}

/* An algebra element as written: 6 numbers on a rigid group, else the 16 of
 * its hat. */
static void put_algebra(const ga_group *g, const double *x, double *row)
{
    if (g->rigid) {
        memcpy(row, x, 6 * sizeof *row);
        return;
    }
    ga_mat4 h = g->hat(x);
    memcpy(row, h.m, sizeof h.m);
}

/* Where a time outside the path's range (ga_path_range: the keys' times,
 * bspline [t_1, t_{n-2}]) goes (--extrapolate): hold, the pose at the range's
 * end (segment SIZE_MAX, u 0 before, 1 after); extend, the end segment at its
 * u outside [0, 1]. 0 for a time inside, 1 outside. */
static int outside(const ga_path *p, int extrap, double t, size_t *seg, double *u)
{
    size_t m = ga_path_segments(p);
    double r0, r1, s0, s1;
    if (ga_path_range(p, &r0, &r1) != GA_OK || (t >= r0 && t <= r1))
        return 0; /* a built path has a range: ga_path_sample reports the rest */
    int after = t > r1;
    if (extrap == 1 || m == 0) {
        *seg = SIZE_MAX;
        *u = after;
    } else {
        *seg = after ? m - 1 : 0;
        if (ga_path_segment_range(p, *seg, &s0, &s1) != GA_OK) {
            *seg = SIZE_MAX; /* cannot happen for a built path: hold the end */
            *u = after;
        } else
            *u = (t - s0) / (s1 - s0);
    }
    return 1;
}

/* ga_path_sample with --extrapolate hold or extend for times outside. */
static int sample_extrapolated(const ga_path *p, ga_eval ev, double step, int extrap, size_t ns,
                               const double *at, void *out)
{
    const ga_group *g = p->group;
    for (size_t k = 0; k < ns; k++) {
        char *o = (char *)out + k * g->elem_size;
        size_t seg;
        double u;
        int st;
        if (!outside(p, extrap, at[k], &seg, &u))
            st = ga_path_sample(p, ev, step, 1, at + k, o);
        else if (seg == SIZE_MAX) { /* the range's end: the end key, or bspline's end pose */
            double r0, r1;
            st = ga_path_range(p, &r0, &r1);
            if (st == GA_OK)
                st = ga_path_eval(p, u > 0 ? r1 : r0, o);
        } else
            st = ga_path_eval_segment(p, seg, u, o);
        if (st != GA_OK)
            return st;
    }
    return GA_OK;
}

/* Velocity, acceleration and jerk at t (those not NULL: only they are
 * computed), extrapolated as the samples are. */
static int differentiate(const ga_path *p, int extrap, double t, ga_frame f, double *v, double *a, double *j)
{
    size_t seg;
    double u;
    if (!extrap || !outside(p, extrap, t, &seg, &u))
        return ga_path_derivatives(p, t, f, v, a, j);
    if (seg == SIZE_MAX) {
        double *x[3] = {v, a, j};
        for (int k = 0; k < 3; k++)
            if (x[k])
                memset(x[k], 0, p->group->dim * sizeof *x[k]);
        return GA_OK;
    }
    return ga_path_derivatives_segment(p, seg, u, f, v, a, j);
}

/* The samples a picture keeps: every stride-th from the first, and the last;
 * at most PICTURE_MAX + 1 matrices (128 bytes each) however many samples
 * are written: an 800-pixel picture shows no more. */
enum { PICTURE_MAX = 8192 };
typedef struct {
    ga_mat4 *m;
    size_t stride, n;
} picture_keep;

/* Every sample: made, checked, written to out (NULL: not written) and kept as
 * a matrix in keep (NULL: not kept); *count is the number of samples.
 * 0, or -1 after a message. */
static int run(const ic_sampler *s, tio_out *out, picture_keep *keep, size_t *count)
{
    const ga_group *g = s->g;
    const char *name = s->in->name;
    double t[CHUNK], off[CHUNK], row[17 + 3 * 16];
    static char stamp[TT_DIG + 32];
    unsigned char *buf = malloc(CHUNK * g->elem_size);
    ga_path_stepper stepper;
    ga_quat prev = {1, 0, 0, 0};
    size_t k = 0;
    int st = buf ? GA_OK : GA_ERR_ARG, rc = -1;
    if (!buf)
        return ic_oom();
    if (s->kind == IC_UNIFORM)
        st = ga_path_stepper_init(s->path, s->ev, s->step, s->ns, s->times[s->i0], s->times[s->i1], &stepper);
    /* an output that fails (a full disk; a pipe whose reader left, SIGPIPE
       ignored) stops the samples: tio_out_finish then says so */
    for (int more = 1; st == GA_OK && more && !(out && ferror(out->fp));) {
        size_t m = 0;
        while (m < CHUNK && (more = ic_sample_time(s, k + m, &t[m], &off[m]))) m++;
        if (m == 0)
            break;
        if (s->kind == IC_UNIFORM)
            for (size_t j = 0; j < m && st == GA_OK; j++)
                st = ga_path_stepper_next(&stepper, buf + j * g->elem_size);
        else if (!s->extrap)
            st = ga_path_sample(s->path, s->ev, s->step, m, t, buf);
        else
            st = sample_extrapolated(s->path, s->ev, s->step, s->extrap, m, t, buf);
        if (st != GA_OK)
            break;
        for (size_t j = 0; j < m; j++, k++) {
            ga_mat4 mat = g->to_mat4(buf + j * g->elem_size);
            if (keep && k % keep->stride == 0)
                keep->m[keep->n++] = mat;
            else if (keep) /* the last sample so far, in the slot after the kept ones */
                keep->m[keep->n] = mat;
            if (s->pose && (st = mat4_to_pose(mat, &prev, row + 1)) != GA_OK) {
                fprintf(stderr, "garotor interp: %s: sample %zu is not a rigid motion: %s\n", name, k + 1,
                        ga_status_string(st));
                goto done;
            }
            if (!s->pose)
                memcpy(row + 1, mat.m, sizeof mat.m);
            if (s->with_v || s->with_a || s->with_j) {
                double dv[GA_GROUP_MAX_DIM], da[GA_GROUP_MAX_DIM], dj[GA_GROUP_MAX_DIM];
                st = differentiate(s->path, s->extrap, t[j], s->frame, s->with_v ? dv : NULL,
                                   s->with_a ? da : NULL, s->with_j ? dj : NULL);
                if (st != GA_OK) {
                    fprintf(stderr, "garotor interp: %s: sample %zu: no velocity: %s\n", name, k + 1,
                            ga_status_string(st));
                    goto done;
                }
                double *col = row + s->pw;
                if (s->with_v)
                    put_algebra(g, dv, col), col += s->dw;
                if (s->with_a)
                    put_algebra(g, da, col), col += s->dw;
                if (s->with_j)
                    put_algebra(g, dj, col);
            }
            if (out)
                tio_out_stamped(out, ic_stamp(s, k, t[j], off[j], stamp), row + 1, s->width - 1);
        }
    }
    if (st != GA_OK)
        fprintf(stderr, "garotor interp: %s: sampling failed: %s\n", name, ga_status_string(st));
    else
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

/* A regular --out file is written beside its name and renamed onto it only
 * when every sample was written, so the samples are made once. To standard
 * output or a FIFO, whatever is written stays written: every sample is made
 * and checked first, without a line written, and made again as it is
 * written. The picture (--svg, --html) needs the samples' matrices before
 * the samples are written: they are kept in that first pass (at most
 * PICTURE_MAX + 1 of them). The picture is drawn to its temporary file and
 * renamed after the last sample was written (and flushed), so a run cut off
 * while it writes (a write error, `| head` and its SIGPIPE, any other
 * signal) leaves no picture of samples it did not write. */
int ic_write(const ic_opts *io, const ic_input *in, const ic_sampler *smp)
{
    const cli_opts *o = io->o;
    size_t n = in->n;
    int drawn = o->svg || o->html, rc = -1;
    double *key_t = NULL;
    picture_keep pk = {NULL, 1, 0};
    tio_out out = TIO_OUT_NONE, svg = TIO_OUT_NONE, html = TIO_OUT_NONE;
    if (drawn) { /* the picture labels the keys with their times as read */
        key_t = malloc(n * sizeof *key_t);
        pk.stride = smp->ns > PICTURE_MAX ? (smp->ns + PICTURE_MAX - 1) / PICTURE_MAX : 1;
        pk.m = malloc(((smp->ns + pk.stride - 1) / pk.stride + 1) * sizeof *pk.m);
        if (!key_t || !pk.m) {
            ic_oom();
            goto done;
        }
        for (size_t i = 0; i < n; i++) key_t[i] = strtod(in->in.first[i], NULL);
    }
    if (tio_out_open(&out, o->out))
        goto done;
    size_t ns = 0;
    if ((drawn || !out.path || out.direct) && run(smp, NULL, drawn ? &pk : NULL, &ns)) {
        tio_out_close(&out, 0);
        goto done;
    }
    if (drawn && draw(io, in, key_t, pk.m, pk.n, ns, &svg, &html)) {
        tio_out_close(&out, 0);
        goto done;
    }
    int ok = run(smp, &out, NULL, &ns) == 0;
    if (!ok || tio_out_finish(&out) != 0) {
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
