/* tools/cmd_interp.c: `garotor interp`, samples of a path through key poses.
 *
 * Reads keyframes (t, then a pose: 16 numbers with --format mat, 7 with
 * --format pose), builds the path of --scheme on --group (path.h), and writes
 * t and the pose of each sample in the same format. Everything is read and
 * checked before anything is written; the samples are then made and written
 * a chunk at a time, never all held (see run() below), and a failure still
 * leaves no output. With --svg FILE it also draws the path (svg.h); a failure
 * then leaves neither the samples' file nor the picture. */
#include "cli.h"
#include "html.h"
#include <garotor/numtext.h>
#include "svg.h"
#include "timetext.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* A unit quaternion (ROS order qx qy qz qw) and a position to a 4x4 matrix;
 * -1 after a message when q is not unit to 1e-9, or with --normalize to
 * GA_SE3_NORMALIZE_TOL (then q is divided by its norm: ga_quat_normalize). */
static int pose_to_mat4(const tio_items *in, size_t i, const double *v, int normalize, ga_mat4 *out)
{
    ga_quat q = {v[6], v[3], v[4], v[5]};
    double norm = sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
    if (normalize && ga_quat_normalize(q, GA_SE3_NORMALIZE_TOL, &q) != GA_OK)
        return tio_error(in, i,
                         "not a rigid motion: the quaternion has norm %.17g, farther from 1 "
                         "than --normalize accepts (1e-3)",
                         norm);
    if (!normalize && fabs(norm - 1.0) > 1e-9)
        return tio_error(in, i,
                         "not a rigid motion: the quaternion has norm %.17g, not 1 "
                         "(to 1e-9; --normalize accepts up to 1e-3)",
                         norm);
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

/* --at t1,t2,...: the texts of the times, checked to be finite numbers, as
 * pointers into *buf (a copy of s); -1 after a message. */
static int parse_times(const char *s, char **buf, char ***out, size_t *n)
{
    size_t cap = 1;
    for (const char *c = s; *c; c++) cap += *c == ',';
    char *b = malloc(strlen(s) + 1);
    char **t = malloc(cap * sizeof *t);
    if (!b || !t) {
        free(b);
        free(t);
        fprintf(stderr, "garotor interp: out of memory\n");
        return -1;
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
    *buf = b;
    *out = t;
    *n = k;
    return 0;
}

/* Times (docs/tool.md, "Times"): each read exactly from its text
 * (timetext.h) and taken relative to the first key's, exactly, before it is
 * rounded to a double: so the path sees the same doubles whatever constant
 * every time is shifted by. With --time-unit ns the relative times are
 * converted to seconds (exactly, rounded once). */
typedef struct {
    tt_dec ref; /* the first key's time, exactly */
    int ns;     /* --time-unit ns */
} timebase;

/* The time of text relative to the reference, in seconds, as a double. */
static double rel_time(const timebase *tb, const char *text)
{
    tt_dec t;
    tt_parse(text, &t);
    if (tt_add(&t, &tb->ref, 1, &t)) /* cannot happen (timetext.h) */
        return (strtod(text, NULL) - tt_to_double(&tb->ref, 0)) * (tb->ns ? 1e-9 : 1.0);
    return tt_to_double(&t, tb->ns ? -9 : 0);
}

static int whole(const char *text)
{
    tt_dec t;
    tt_parse(text, &t);
    return tt_is_integer(&t);
}

/* --rate HZ as P x 10^q, P a whole number below 2^53 (15 digits): 1, or 0
 * if HZ has more digits. */
static int rate_parts(const char *text, uint64_t *p, int *q)
{
    tt_dec h;
    tt_parse(text, &h);
    if (h.n == 0 || h.n > 15)
        return 0;
    uint64_t v = 0;
    for (int i = 0; i < h.n; i++) v = v * 10 + h.d[i];
    *p = v;
    *q = h.exp;
    return 1;
}

/* k/HZ in seconds, correctly rounded where k and the digits of HZ allow one
 * exact division (numerator and denominator whole numbers below 2^53). */
static double rate_seconds(uint64_t k, int exact, uint64_t p, int q, double hz)
{
    const double two53 = 9007199254740992.0;
    if (exact) {
        double num = (double)k, den = (double)p;
        for (int e = q; e > 0 && den < two53; e--) den *= 10.0;
        for (int e = q; e < 0 && num < two53; e++) num *= 10.0;
        if (num < two53 && den < two53)
            return num / den;
    }
    return (double)k / hz;
}

/* round(k 10^9 / HZ), whole nanoseconds, in exact integer arithmetic where
 * it fits in 64 bits (ties away from zero). */
static double rate_nanoseconds(uint64_t k, int exact, uint64_t p, int q, double hz)
{
    if (exact) {
        uint64_t num = k, den = p;
        int ok = 1;
        for (int e = 9 - q; e > 0 && ok; e--) ok = num <= UINT64_MAX / 20 ? (num *= 10, 1) : 0;
        for (int e = 9 - q; e < 0 && ok; e++) ok = den <= UINT64_MAX / 20 ? (den *= 10, 1) : 0;
        if (ok)
            return (double)((num + den / 2) / den);
    }
    return floor((double)k * (1e9 / hz) + 0.5);
}

/* The key whose (relative) time is t, if any: 1 and *key, else 0. */
static int key_at(const double *times, size_t n, double t, size_t *key)
{
    size_t lo = 0, hi = n;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (times[mid] < t)
            lo = mid + 1;
        else
            hi = mid;
    }
    if (lo < n && times[lo] == t) {
        *key = lo;
        return 1;
    }
    return 0;
}

/* The stamp of a computed sample: the reference plus the shortest decimal
 * that reads back as its relative time rel (seconds), or plus its whole
 * nanoseconds off (--time-unit ns). */
static void computed_stamp(const timebase *tb, double rel, double off, char *buf)
{
    tt_dec o;
    if (tb->ns) {
        char b[400];
        snprintf(b, sizeof b, "%.0f", off);
        tt_parse(b, &o);
    } else
        tt_shortest(rel, &o);
    if (tt_add(&tb->ref, &o, 0, &o)) /* cannot happen (timetext.h) */
        ga_double_format(tt_to_double(&tb->ref, 0) + (tb->ns ? off : rel), buf);
    else
        tt_format(&o, buf);
}

/* A velocity as the tool reads it: 6 numbers, a twist (on every group: its
 * hat read by the group's vee), or on a group that is not rigid 16, a 4x4
 * with last row zero. Writes g->dim doubles. */
static int read_velocity(const ga_group *g, const double *v, int count, double *x)
{
    ga_mat4 a;
    if (count == 6)
        a = ga_twist_hat((ga_twist){{v[0], v[1], v[2]}, {v[3], v[4], v[5]}});
    else if (count == 16 && !g->rigid)
        memcpy(a.m, v, sizeof a.m);
    else
        return -1;
    return g->vee(a, x) == GA_OK ? 0 : -1;
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

/* Velocity and acceleration at t, extrapolated as the samples are. */
static int differentiate(const ga_path *p, int extrap, double t, ga_frame f, double *v, double *a)
{
    size_t seg;
    double u;
    if (!extrap || !outside(p, extrap, t, &seg, &u))
        return ga_path_differentiate(p, t, f, v, a);
    if (seg == SIZE_MAX) {
        memset(v, 0, p->group->dim * sizeof *v);
        memset(a, 0, p->group->dim * sizeof *a);
        return GA_OK;
    }
    return ga_path_differentiate_segment(p, seg, u, f, v, a);
}

/* The picture of the path: the keys, the samples m[0..ns-1] (in the order
 * sampled) and, for the screw scheme on keys that follow one screw motion,
 * its axis. 0, or -1 after a message. */
/* m: the nm samples kept for the picture, of ns made */
static int draw(const cli_opts *o, const ga_group *g, ga_scheme scheme, ga_eval ev, svg_view view,
                const ga_mat4 *keys, const double *times, size_t n, const ga_mat4 *m, size_t nm, size_t ns)
{
    char title[256], step[64] = "";
    if (ev == GA_EVAL_EULER)
        snprintf(step, sizeof step, ", step %g", o->step);
    snprintf(title, sizeof title, "%s: %zu keys, %zu samples (group %s, eval %s%s)", ga_scheme_name(scheme),
             n, ns, g->name, ga_eval_name(ev), step);
    int frames = 4 * (int)(n - 1) < 12 ? 12 : 4 * (int)(n - 1) > 48 ? 48 : 4 * (int)(n - 1);
    svg_path path = {ga_scheme_name(scheme), "#333333", m, nm, frames};
    svg_picture pic = {title, view, keys, times, n, &path, 1, 0, {0, 0, 0}, {0, 0, 0}};
    pic.has_axis = scheme == GA_SCHEME_SCREW && svg_screw_axis(keys, n, &pic.axis_point, &pic.axis_dir);
    int st = o->svg ? svg_write(o->svg, &pic) : 0;
    if (st == 0 && o->html && (st = html_write(o->html, &pic)) != 0 && o->svg)
        tio_out_unwrite(o->svg);
    return st;
}

/* ---- the samples, made and written a chunk at a time ------------------------
 * Nothing but the keys (and given times) is held: each chunk of CHUNK sample
 * times is made, sampled, turned into rows and written before the next, so
 * memory does not grow with the number of samples. */
enum { CHUNK = 512 };
typedef enum { UNIFORM, GIVEN, RATE, NS_SAMPLES } when_kind;

typedef struct {
    const cli_opts *o;
    const ga_group *g;
    const ga_path *path;
    const tio_items *in;
    const timebase *tb;
    ga_eval ev;
    double step;
    int extrap, pose, with_v, with_a, spatial;
    int pw, dw, width;   /* pose, algebra element and row widths */
    const double *times; /* the keys' relative times */
    size_t n;            /* keys */
    size_t i0, i1;       /* the path's range: from key i0 to key i1 (bspline: 1 and n - 2) */
    when_kind kind;
    size_t ns;            /* samples (RATE: the most there can be) */
    const double *at;     /* GIVEN: the times, relative */
    char *const *at_text; /* GIVEN: as written */
    uint64_t rp;          /* RATE: HZ = rp 10^rq when rexact */
    int rq, rexact;
    size_t k0;     /* RATE: the first k in the range */
    double s0, sp; /* NS_SAMPLES: the range's start and span in nanoseconds */
} sampler;

/* t0 + off, off whole nanoseconds, in seconds relative to the first key. */
static double ns_seconds(double off)
{
    char b[400];
    snprintf(b, sizeof b, "%.0f", off);
    tt_dec d;
    tt_parse(b, &d);
    return tt_to_double(&d, -9);
}

/* The time of sample k relative to the first key, and with --time-unit ns
 * its whole nanoseconds *off; 0 when there is no sample k. */
static int sample_time(const sampler *s, size_t k, double *t, double *off)
{
    double first = s->times[s->i0], last = s->times[s->i1];
    *off = 0.0;
    if (k >= s->ns)
        return 0;
    switch (s->kind) {
    case UNIFORM: /* ga_path_sample_uniform's t0 + k dt, the last exactly t1 */
        *t = k + 1 == s->ns ? last
                            : first + (double)k * (s->ns > 1 ? (last - first) / (double)(s->ns - 1) : 0.0);
        return 1;
    case GIVEN: *t = s->at[k]; return 1;
    case RATE: /* t_0 + k/HZ, each from k, those in the range (from k0 on, while <= its end) */
        k += s->k0;
        if (s->tb->ns) {
            *off = rate_nanoseconds(k, s->rexact, s->rp, s->rq, s->o->rate);
            *t = ns_seconds(*off);
        } else
            *t = rate_seconds(k, s->rexact, s->rp, s->rq, s->o->rate);
        return *t <= last;
    case NS_SAMPLES: /* whole nanoseconds: t_i0 + round(k span/(N - 1)), span = t_i1 - t_i0 */
        *off = s->s0 + (k + 1 == s->ns ? s->sp : floor((double)k * s->sp / (double)(s->ns - 1) + 0.5));
        *t = k + 1 == s->ns ? last : ns_seconds(*off);
        return 1;
    }
    return 0;
}

/* The stamp of sample k, taken at t: a key's time as the key was written; a
 * given one as given; a computed one from the reference. */
static const char *stamp_of(const sampler *s, size_t k, double t, double off, char *buf)
{
    size_t key;
    if (key_at(s->times, s->n, t, &key))
        return s->in->first[key];
    if (s->kind == GIVEN)
        return s->at_text[k];
    if (s->tb->ref.n == 0 && !s->tb->ns) /* the reference is 0: t itself */
        ga_double_format(t == 0.0 ? 0.0 : t, buf);
    else
        computed_stamp(s->tb, t, off, buf);
    return buf;
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
static int run(const sampler *s, tio_out *out, picture_keep *keep, size_t *count)
{
    const ga_group *g = s->g;
    const char *name = s->in->name;
    double t[CHUNK], off[CHUNK], row[17 + 2 * 16];
    static char stamp[TT_DIG + 32];
    unsigned char *buf = malloc(CHUNK * g->elem_size);
    ga_path_stepper stepper;
    ga_quat prev = {1, 0, 0, 0};
    size_t k = 0;
    int st = buf ? GA_OK : GA_ERR_ARG, rc = -1;
    if (!buf) {
        fprintf(stderr, "garotor interp: out of memory\n");
        return -1;
    }
    if (s->kind == UNIFORM)
        st = ga_path_stepper_init(s->path, s->ev, s->step, s->ns, s->times[s->i0], s->times[s->i1], &stepper);
    for (int more = 1; st == GA_OK && more;) {
        size_t m = 0;
        while (m < CHUNK && (more = sample_time(s, k + m, &t[m], &off[m]))) m++;
        if (m == 0)
            break;
        if (s->kind == UNIFORM)
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
            if (s->with_v) {
                double dv[GA_GROUP_MAX_DIM], da[GA_GROUP_MAX_DIM];
                st = differentiate(s->path, s->extrap, t[j], s->spatial ? GA_FRAME_SPATIAL : GA_FRAME_BODY,
                                   dv, da);
                if (st != GA_OK) {
                    fprintf(stderr, "garotor interp: %s: sample %zu: no velocity: %s\n", name, k + 1,
                            ga_status_string(st));
                    goto done;
                }
                put_algebra(g, dv, row + s->pw);
                if (s->with_a)
                    put_algebra(g, da, row + s->pw + s->dw);
            }
            if (out)
                tio_out_stamped(out, stamp_of(s, k, t[j], off[j], stamp), row + 1, s->width - 1);
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

int cmd_interp(const cli_opts *o)
{
    const char *cmd = "interp";
    const ga_group *g = cli_group(cmd, o);
    if (!g)
        return 2;
    ga_scheme scheme = GA_SCHEME_SCREW;
    if (o->scheme && ga_scheme_by_name(o->scheme, &scheme) != GA_OK) {
        fprintf(stderr,
                "garotor interp: --scheme must be screw, bivector, quadratic, smooth, "
                "lihao2, lihao3, decoupled, decoupled-c2, bspline or c2, not '%s'\n",
                o->scheme);
        return 2;
    }
    ga_eval ev = GA_EVAL_DIRECT;
    if (o->eval && ga_eval_by_name(o->eval, &ev) != GA_OK) {
        fprintf(stderr, "garotor interp: --eval must be direct, euler or exact, not '%s'\n", o->eval);
        return 2;
    }
    if (ev == GA_EVAL_EULER && !(o->given & OPT_STEP)) {
        fprintf(stderr, "garotor interp: --eval euler needs --step H (in u units, 1e-9 <= H <= 1)\n");
        return 2;
    }
    if ((o->given & OPT_STEP) && ev != GA_EVAL_EULER) {
        fprintf(stderr, "garotor interp: --step applies only to --eval euler\n");
        return 2;
    }
    int pose = 0;
    if (o->format && strcmp(o->format, "pose") == 0)
        pose = 1;
    else if (o->format && strcmp(o->format, "mat") != 0) {
        fprintf(stderr, "garotor interp: --format must be mat or pose, not '%s'\n", o->format);
        return 2;
    }
    if (pose && !g->rigid) {
        fprintf(stderr, "garotor interp: --group %s takes keys as matrices (--format mat)\n", g->name);
        return 2;
    }
    int nwhen = !!(o->given & OPT_SAMPLES) + !!(o->given & OPT_AT) + !!(o->given & OPT_RATE) +
                !!(o->given & OPT_TIMES);
    if (nwhen != 1) {
        fprintf(stderr, "garotor interp: give one of --samples N, --at t1,t2,..., --rate HZ, --times FILE\n");
        return 2;
    }
    int extrap = 0; /* 0 error, 1 hold, 2 extend */
    if (o->extrapolate && strcmp(o->extrapolate, "hold") == 0)
        extrap = 1;
    else if (o->extrapolate && strcmp(o->extrapolate, "extend") == 0)
        extrap = 2;
    else if (o->extrapolate && strcmp(o->extrapolate, "error") != 0) {
        fprintf(stderr, "garotor interp: --extrapolate must be error, hold or extend, not '%s'\n",
                o->extrapolate);
        return 2;
    }
    if ((o->given & OPT_V0) && scheme != GA_SCHEME_LIHAO2) {
        fprintf(stderr, "garotor interp: --v0 applies only to --scheme lihao2\n");
        return 2;
    }
    if ((o->given & OPT_VELOCITIES) && scheme != GA_SCHEME_LIHAO3) {
        fprintf(stderr, "garotor interp: --velocities applies only to --scheme lihao3\n");
        return 2;
    }
    if (o->normalize && !g->rigid) {
        fprintf(stderr, "garotor interp: --normalize applies to --group cga or matrix\n");
        return 2;
    }
    int with_v = 0, with_a = 0, spatial = 0;
    if (o->with && strcmp(o->with, "velocity") == 0)
        with_v = 1;
    else if (o->with && strcmp(o->with, "velocity,acceleration") == 0)
        with_v = with_a = 1;
    else if (o->with) {
        fprintf(stderr, "garotor interp: --with must be velocity or velocity,acceleration, not '%s'\n",
                o->with);
        return 2;
    }
    if (o->frame && strcmp(o->frame, "spatial") == 0)
        spatial = 1;
    else if (o->frame && strcmp(o->frame, "body") != 0) {
        fprintf(stderr, "garotor interp: --frame must be body or spatial, not '%s'\n", o->frame);
        return 2;
    }
    if (o->frame && !with_v) {
        fprintf(stderr, "garotor interp: --frame applies only with --with velocity[,acceleration]\n");
        return 2;
    }
    static timebase tb; /* static: a tt_dec is large */
    memset(&tb, 0, sizeof tb);
    if (o->time_unit && strcmp(o->time_unit, "ns") == 0)
        tb.ns = 1;
    else if (o->time_unit && strcmp(o->time_unit, "s") != 0) {
        fprintf(stderr, "garotor interp: --time-unit must be s or ns, not '%s'\n", o->time_unit);
        return 2;
    }
    svg_view view;
    if (svg_options(cmd, o->svg, o->view, &view) || html_options(cmd, o->html))
        return 2;
    /* one file for two outputs: the second would silently replace the first */
    const char *files[3] = {o->out, o->svg, o->html}, *opt[3] = {"--out", "--svg", "--html"};
    for (int i = 0; i < 3; i++)
        for (int j = i + 1; j < 3; j++)
            if (files[i] && files[j] && strcmp(files[i], files[j]) == 0) {
                fprintf(stderr, "garotor interp: %s and %s name the same file: %s\n", opt[i], opt[j],
                        files[i]);
                return 2;
            }

    tio_items in = {0}, vin = {0}, tin = {0};
    double *times = NULL, *at = NULL, *vel = NULL, *key_t = NULL;
    ga_mat4 *kept = NULL;
    char *at_buf = NULL, **at_arg = NULL, **at_text = NULL;
    ga_mat4 *keys = NULL;
    void *work = NULL;
    int rc = 2;
    size_t nat = 0;
    if (o->at && parse_times(o->at, &at_buf, &at_arg, &nat))
        goto done;
    if (tio_read_first(o->in, o->header, &in))
        goto done;
    int want = pose ? 8 : 17;
    size_t n = in.n;
    times = malloc((n ? n : 1) * sizeof *times);
    keys = malloc((n ? n : 1) * sizeof *keys);
    if (!times || !keys)
        goto oom;
    for (size_t i = 0; i < n; i++) {
        /* a line of separators only is an item of no numbers, and with no
           number in the whole input value is NULL: no pointer arithmetic on
           it (undefined; found by fuzz/fuzz_tool under UBSan:
           fuzz/regress/tool/interp-comma-line-no-numbers) */
        const double *v = in.item[i].count ? in.value + in.item[i].first : NULL;
        if (in.item[i].count != want) {
            tio_error(&in, i, "expected %d numbers (t, then %s), found %d", want,
                      pose ? "x y z qx qy qz qw" : "a 4x4 matrix", in.item[i].count);
            goto done;
        }
        if (tb.ns && !whole(in.first[i])) {
            tio_error(&in, i, "--time-unit ns takes whole nanoseconds, not '%s'", in.first[i]);
            goto done;
        }
        if (i == 0)
            tt_parse(in.first[0], &tb.ref);
        times[i] = rel_time(&tb, in.first[i]);
        if (i > 0 && !(times[i] > times[i - 1])) {
            tio_error(&in, i, "key times must increase strictly: %s after %s", in.first[i], in.first[i - 1]);
            goto done;
        }
        if (pose ? pose_to_mat4(&in, i, v + 1, o->normalize, &keys[i]) : 0)
            goto done;
        if (!pose) {
            int krc;
            memcpy(keys[i].m, v + 1, sizeof keys[i].m);
            if (normalize_key(g, o->normalize, &in, i, &keys[i], &krc) ? krc
                                                                       : cli_check_motion(g, keys[i], &in, i))
                goto done;
        }
    }
    size_t min = ga_scheme_min_keys(scheme);
    if (n != 1 && (n < min || (scheme == GA_SCHEME_QUADRATIC && n != 3))) {
        fprintf(stderr, "garotor interp: %s: --scheme %s needs one key or %s %zu, found %zu\n", in.name,
                ga_scheme_name(scheme), scheme == GA_SCHEME_QUADRATIC ? "exactly" : "at least", min, n);
        goto done;
    }
    size_t bad = scheme == GA_SCHEME_BSPLINE ? ga_times_uneven(n, times) : 0;
    if (bad) {
        double grid = times[0] + (times[n - 1] - times[0]) * (double)bad / (double)(n - 1);
        tio_error(&in, bad,
                  "--scheme bspline needs evenly spaced key times (to 1e-9 of the spacing): %s is %.3g s "
                  "off the even grid of the first and last key (spacing %.17g s)",
                  in.first[bad], (times[bad] - grid) * (tb.ns ? 1e9 : 1.0),
                  (times[n - 1] - times[0]) / (double)(n - 1));
        goto done;
    }
    /* the path's range (ga_path_range): from key i0 to key i1, the first
       and last key, but for bspline the second and the last but one */
    size_t i0 = scheme == GA_SCHEME_BSPLINE && n > 1, i1 = n - 1 - i0;
    if (o->times) { /* --times FILE: one time a line */
        if (tio_read_first(o->times, 0, &tin))
            goto done;
        nat = tin.n;
        for (size_t k = 0; k < nat; k++)
            if (tin.item[k].count != 1) {
                tio_error(&tin, k, "expected 1 number (a time), found %d", tin.item[k].count);
                goto done;
            } else if (tb.ns && !whole(tin.first[k])) {
                tio_error(&tin, k, "--time-unit ns takes whole nanoseconds, not '%s'", tin.first[k]);
                goto done;
            }
        if (nat == 0) {
            fprintf(stderr, "garotor interp: %s: no times\n", tin.name);
            goto done;
        }
        at_text = tin.first;
    }
    if (o->at) {
        for (size_t k = 0; k < nat; k++)
            if (tb.ns && !whole(at_arg[k])) {
                fprintf(stderr, "garotor interp: --at: --time-unit ns takes whole nanoseconds, not '%s'\n",
                        at_arg[k]);
                goto done;
            }
        at_text = at_arg;
    }
    if (at_text) { /* given times, relative to the first key's */
        at = malloc(nat * sizeof *at);
        if (!at)
            goto oom;
        for (size_t k = 0; k < nat; k++) at[k] = rel_time(&tb, at_text[k]);
    }
    sampler smp = {.o = o,
                   .g = g,
                   .in = &in,
                   .tb = &tb,
                   .ev = ev,
                   .step = ev == GA_EVAL_EULER ? o->step : 1.0,
                   .extrap = extrap,
                   .pose = pose,
                   .with_v = with_v,
                   .with_a = with_a,
                   .spatial = spatial,
                   .times = times,
                   .n = n,
                   .i0 = i0,
                   .i1 = i1,
                   .kind = UNIFORM,
                   .ns = (size_t)o->samples};
    if (o->given & OPT_RATE) { /* t0 + k/HZ, each from k, those in the range [t_i0, t_i1] */
        double span = times[n - 1] * o->rate;
        if (!(span < 1e9)) {
            fprintf(stderr, "garotor interp: --rate %.17g gives more than 1e9 samples\n", o->rate);
            goto done;
        }
        smp.kind = RATE;
        smp.ns = (size_t)floor(span) + 2;
        smp.rexact = rate_parts(o->rate_text, &smp.rp, &smp.rq);
        double t, off;
        while (sample_time(&smp, 0, &t, &off) && t < times[i0]) { /* bspline: its range starts at t_1 */
            smp.k0++;
            smp.ns--;
        }
        if (!sample_time(&smp, 0, &t, &off)) {
            fprintf(stderr, "garotor interp: --rate %s: no sample time in the path's range [%s, %s]\n",
                    o->rate_text, in.first[i0], in.first[i1]);
            goto done;
        }
    }
    if (tb.ns && (o->given & OPT_SAMPLES)) {
        /* whole nanoseconds: t_i0 + round(k span/(N - 1)), span = t_i1 - t_i0 */
        tt_dec span, start;
        tt_parse(in.first[i1], &span);
        tt_parse(in.first[i0], &start);
        if (tt_add(&span, &tb.ref, 1, &span) || tt_add(&start, &tb.ref, 1, &start)) /* cannot happen */
            goto oom;
        smp.kind = NS_SAMPLES;
        smp.s0 = tt_to_double(&start, 0); /* whole ns below 2^53 */
        smp.sp = tt_to_double(&span, 0) - smp.s0;
    }
    if (at_text) {
        smp.kind = GIVEN;
        smp.ns = nat;
        smp.at = at;
        smp.at_text = at_text;
    }
    for (size_t k = 0; k < nat && !extrap && at_text; k++)
        if (!(at[k] >= times[i0] && at[k] <= times[i1])) {
            fprintf(stderr,
                    "garotor interp: %s time %s is outside the %s range [%s, %s] (see "
                    "--extrapolate)\n",
                    o->times ? "--times" : "--at", at_text[k], i0 ? "B-spline's" : "keys'", in.first[i0],
                    in.first[i1]);
            goto done;
        }

    /* velocities: --v0 for lihao2, --velocities FILE (one a key) for lihao3 */
    if (o->given & OPT_V0) {
        vel = malloc(GA_GROUP_MAX_DIM * sizeof *vel);
        if (!vel)
            goto oom;
        read_velocity(g, o->v0, 6, vel);
    }
    if (o->velocities) {
        if (tio_read(o->velocities, 0, &vin))
            goto done;
        if (vin.n != n) {
            if (vin.n > n)
                tio_error(&vin, n, "one velocity per key: %zu keys, but %zu velocities", n, vin.n);
            else
                fprintf(stderr,
                        "garotor interp: %s: one velocity per key: %zu keys, but %zu "
                        "velocities\n",
                        vin.name, n, vin.n);
            goto done;
        }
        vel = malloc(n * (size_t)g->dim * sizeof *vel);
        if (!vel)
            goto oom;
        for (size_t i = 0; i < n; i++)
            if (read_velocity(g, vin.item[i].count ? vin.value + vin.item[i].first : NULL, vin.item[i].count,
                              vel + i * (size_t)g->dim)) {
                tio_error(&vin, i,
                          "expected 6 numbers (a body velocity w1 w2 w3 v1 v2 v3)%s, "
                          "found %d",
                          g->rigid ? "" : " or 16 (a 4x4, last row zero)", vin.item[i].count);
                goto done;
            }
    }

    ga_path path;
    size_t wbytes = ga_path_workspace_size(g, scheme, n);
    if (wbytes == 0) { /* the scheme is not defined on the group (path.h) */
        fprintf(stderr, "garotor interp: --scheme %s is not defined on --group %s\n", ga_scheme_name(scheme),
                g->name);
        goto done;
    }
    work = malloc(wbytes);
    if (!work)
        goto oom;
    int st = ga_path_init_mat4(g, scheme, n, times, keys, vel, work, wbytes, &path);
    if (st != GA_OK) {
        fprintf(stderr, "garotor interp: %s: cannot build the %s path: %s\n", in.name, ga_scheme_name(scheme),
                ga_status_string(st));
        goto done;
    }
    /* the growth rule (path.h, docs/schemes.md "lihao2"): a warning, the
       samples are written all the same (exit status 0) */
    ga_path_growth gr;
    if (ga_path_measure_growth(&path, &gr) == GA_OK && gr.first < n) {
        size_t f = gr.first, a = f ? f - 1 : 0, b = f ? f : 1;
        char ratio[32]; /* 3 digits, or as many as show it past the bound (3.0004, not 3) */
        for (int dig = 3; dig <= 17; dig++) {
            snprintf(ratio, sizeof ratio, "%.*g", dig, gr.ratio);
            if (strtod(ratio, NULL) > GA_PATH_GROWTH_MAX)
                break;
        }
        fprintf(
            stderr,
            "garotor interp: warning: %s: the %s path's velocity grows past %g times the fastest chord on "
            "the segment t = %s to %s (lines %ld to %ld), up to %s times at t = %s; --scheme lihao3 or c2 "
            "follow the chords (docs/schemes.md)\n",
            in.name, ga_scheme_name(scheme), GA_PATH_GROWTH_MAX, in.first[a], in.first[b], in.item[a].line,
            in.item[b].line, ratio, in.first[gr.key]);
    }

    /* an algebra element as the tool writes it: a twist (6) on a rigid group,
       else its hat, a 4x4 with zero last row (16) */
    smp.path = &path;
    smp.dw = g->rigid ? 6 : 16;
    smp.pw = pose ? 8 : 17;
    smp.width = smp.pw + (with_v + with_a) * smp.dw;
    /* A regular --out file is written beside its name and renamed onto it
     * only when every sample was written, so the samples are made once. To
     * standard output or a FIFO, whatever is written stays written: every
     * sample is made and checked first, without a line written, and made
     * again as it is written. The picture (--svg, --html) needs the samples'
     * matrices before the samples are written: they are kept in that first
     * pass (at most PICTURE_MAX + 1 of them, 128 bytes each). */
    int drawn = o->svg || o->html;
    picture_keep pk = {NULL, 1, 0};
    if (drawn) { /* the picture labels the keys with their times as read */
        key_t = malloc(n * sizeof *key_t);
        pk.stride = smp.ns > PICTURE_MAX ? (smp.ns + PICTURE_MAX - 1) / PICTURE_MAX : 1;
        kept = malloc(((smp.ns + pk.stride - 1) / pk.stride + 1) * sizeof *kept);
        pk.m = kept;
        if (!key_t || !kept)
            goto oom;
        for (size_t i = 0; i < n; i++) key_t[i] = strtod(in.first[i], NULL);
    }
    tio_out out;
    if (tio_out_open(&out, o->out))
        goto done;
    size_t ns = 0;
    if ((drawn || !out.path || out.direct) && run(&smp, NULL, drawn ? &pk : NULL, &ns)) {
        tio_out_close(&out, 0);
        goto done;
    }
    if (drawn && draw(o, g, scheme, ev, view, keys, key_t, n, kept, pk.n, ns)) {
        tio_out_close(&out, 0);
        goto done;
    }
    int ok = run(&smp, &out, NULL, &ns) == 0;
    if (tio_out_close(&out, ok) == 0)
        rc = 0;
    else if (drawn) {
        if (o->svg)
            tio_out_unwrite(o->svg);
        if (o->html)
            tio_out_unwrite(o->html);
    }
    goto done;
oom:
    fprintf(stderr, "garotor interp: out of memory\n");
done:
    free(times);
    free(keys);
    free(at);
    free(key_t);
    free(at_buf);
    free(at_arg);
    free(vel);
    free(kept);
    free(work);
    tio_free(&in);
    tio_free(&vin);
    tio_free(&tin);
    return rc;
}
