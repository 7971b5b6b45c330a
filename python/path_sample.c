/* python/path_sample.c: garotor.Path's sample, sample_pose, velocity,
 * acceleration and jerk (path.h), through gpy_run_kernel (kernel.c).
 */
#include "path.h"

#include <math.h>

/* ---- sample, velocity, acceleration ---------------------------------------- */

/* A path kernel's context: the path, and its range when an element failed,
 * read there under the lock for explain_time, which runs after it (with the
 * keys' times as given, and the failed element's flat index k in given, the
 * times as given where they were converted: gpy_path_rel_times). */
typedef struct {
    const ga_path *path;
    int range_status;
    double t0, t1;
    ga_frame frame; /* velocity, acceleration, jerk: the frame= asked */
    const gpy_stamp *stamp;
    int ns;
    PyArrayObject *given;
    npy_intp k;
    gpy_stamp at0, at1;
    /* extrapolate= other than 'error': the path with its mode, set up at the
       first element (under the lock, so on the path the loop reads) */
    ga_extrap mode;
    int xready, xfailed;
    ga_path_extrap xp;
} path_ctx;

#define PATH_CTX(path, stamp, ns, given)                                                                     \
    {                                                                                                        \
        (path), GA_ERR_ARG, 0.0, 0.0, GA_FRAME_BODY, (stamp), (ns), (given), -1, {0, 0}, {0, 0},             \
            GA_EXTRAP_ERROR, 0, 0,                                                                           \
        {                                                                                                    \
            0                                                                                                \
        }                                                                                                    \
    }

static int path_failed(path_ctx *c, int status, npy_intp k)
{
    c->range_status = ga_path_range(c->path, &c->t0, &c->t1);
    if (c->range_status == GA_OK) {
        c->at0 = c->stamp[gpy_path_key_index(c->path, c->t0)];
        c->at1 = c->stamp[gpy_path_key_index(c->path, c->t1)];
    }
    c->k = k;
    return status;
}

/* The extrapolation's ends, once (ga_path_extrap_init): GA_OK or its status */
static int extrap_ready(path_ctx *c)
{
    if (c->xready)
        return GA_OK;
    int st = ga_path_extrap_init(c->path, c->mode, &c->xp);
    if (st != GA_OK)
        c->xfailed = 1;
    else
        c->xready = 1;
    return st;
}

/* The pose at t: with extrapolate= 'error' ga_path_sample's (as before),
 * else ga_path_extrap_eval's (garotor interp --extrapolate's) */
static int pose_at(path_ctx *c, const double *t, void *e)
{
    if (c->mode == GA_EXTRAP_ERROR)
        return ga_path_sample(c->path, GA_EVAL_DIRECT, 1.0, 1, t, e);
    int st = extrap_ready(c);
    return st != GA_OK ? st : ga_path_extrap_eval(&c->xp, t[0], e);
}

static int k_sample(void *ctx, const double *const *in, double *out, npy_intp k)
{
    const ga_path *p = ((path_ctx *)ctx)->path;
    double e[GA_GROUP_MAX_ELEM];
    int st = pose_at(ctx, in[0], e);
    if (st != GA_OK)
        return path_failed(ctx, st, k);
    gpy_mat_put(p->group->to_mat4(e), out);
    return GA_OK;
}

/* k_sample's numbers for n times t in C order (gpy_kernel_call.many):
 * ga_path_sample on blocks of times, which locates them in the library
 * (its search skipped for times in order, the searches of times in any
 * order run side by side) and evaluates each as one ga_path_sample call
 * does, bit for bit. On a status the loop runs the chunk's elements one by
 * one through k_sample, which names the time. */
enum { SAMPLE_MANY = 128 };
static int m_sample(void *ctx, const double *unused, const double *t, npy_intp n, double *out)
{
    (void)unused;
    const ga_path *p = ((path_ctx *)ctx)->path;
    size_t es = p->group->elem_size;
    double e[SAMPLE_MANY * GA_GROUP_MAX_ELEM]; /* m elements of es bytes, contiguous */
    for (npy_intp k = 0; k < n; k += SAMPLE_MANY) {
        size_t m = n - k < SAMPLE_MANY ? (size_t)(n - k) : SAMPLE_MANY;
        int st = ga_path_sample(p, GA_EVAL_DIRECT, 1.0, m, t + k, e);
        if (st != GA_OK)
            return st;
        for (size_t i = 0; i < m; i++)
            gpy_mat_put(p->group->to_mat4((const unsigned char *)e + i * es), out + (k + (npy_intp)i) * 16);
    }
    return GA_OK;
}

/* The derivative of order o (1 velocity, 2 acceleration, 3 jerk) in the
 * context's frame, computed alone (ga_path_derivatives: the tool's --with
 * columns bit for bit; the body velocity is ga_path_velocity's). */
static int k_derivative(void *ctx, const double *const *in, double *out, npy_intp k, int o)
{
    path_ctx *c = ctx;
    const ga_path *p = c->path;
    double x[GA_GROUP_MAX_DIM];
    int st = c->mode == GA_EXTRAP_ERROR ? GA_OK : extrap_ready(c);
    if (st == GA_OK && c->mode == GA_EXTRAP_ERROR)
        st = ga_path_derivatives(p, in[0][0], c->frame, o == 1 ? x : NULL, o == 2 ? x : NULL,
                                 o == 3 ? x : NULL);
    else if (st == GA_OK)
        st = ga_path_extrap_derivatives(&c->xp, in[0][0], c->frame, o == 1 ? x : NULL, o == 2 ? x : NULL,
                                        o == 3 ? x : NULL);
    if (st != GA_OK)
        return path_failed(c, st, k);
    if (p->group->rigid)
        memcpy(out, x, 6 * sizeof *x);
    else
        gpy_mat_put(p->group->hat(x), out);
    return GA_OK;
}
static int k_velocity(void *ctx, const double *const *in, double *out, npy_intp k)
{
    return k_derivative(ctx, in, out, k, 1);
}
static int k_acceleration(void *ctx, const double *const *in, double *out, npy_intp k)
{
    return k_derivative(ctx, in, out, k, 2);
}
static int k_jerk(void *ctx, const double *const *in, double *out, npy_intp k)
{
    return k_derivative(ctx, in, out, k, 3);
}

/* A time the path is not defined at: outside its range (a NaN or an
 * infinity does not come here: the loop refuses it first). */
static void explain_time(void *ctx, const double *const *in, int status, char *why, size_t size)
{
    const path_ctx *pc = ctx;
    double t0 = pc->t0, t1 = pc->t1, t = in[0][0];
    if (pc->xfailed) {
        snprintf(why, size, "no velocity at the end of the path (extrapolate='%s')",
                 ga_extrap_name(pc->mode));
        return;
    }
    if (status == GA_ERR_NOTFINITE || pc->range_status != GA_OK)
        return;
    char a[32], b[32], c[32];
    const char *given = gpy_repr_text(t, a); /* t as given: t itself where not converted */
    if (pc->given && pc->k >= 0 && pc->k < PyArray_SIZE(pc->given)) {
        if (PyArray_TYPE(pc->given) == NPY_INT64)
            snprintf(a, sizeof a, "%lld", (long long)((const int64_t *)PyArray_DATA(pc->given))[pc->k]);
        else
            gpy_repr_text(((const double *)PyArray_DATA(pc->given))[pc->k], a);
    }
    if ((t < t0 || t > t1) && pc->mode == GA_EXTRAP_ERROR)
        snprintf(why, size, "t = %s is outside the path's range [%s, %s] (Path.range)", given,
                 gpy_stamp_text(pc->at0, pc->ns, b), gpy_stamp_text(pc->at1, pc->ns, c));
    else if (t < t0 || t > t1)
        snprintf(why, size, "t = %s, outside the path's range [%s, %s], extrapolated (extrapolate='%s')",
                 given, gpy_stamp_text(pc->at0, pc->ns, b), gpy_stamp_text(pc->at1, pc->ns, c),
                 ga_extrap_name(pc->mode));
}

/* extrapolate= "error" (or None), "hold", "extend", "constant-velocity" */
static int parse_extrap(const char *what, const char *name, ga_extrap *x)
{
    *x = GA_EXTRAP_ERROR;
    if (name && ga_extrap_by_name(name, x) != GA_OK) {
        PyErr_Format(PyExc_ValueError,
                     "%s: extrapolate must be 'error', 'hold', 'extend' or 'constant-velocity', not '%s'",
                     what, name);
        return -1;
    }
    return 0;
}

/* frame= of velocity, acceleration, jerk: "body", "spatial" or "world" */
static int parse_frame(const char *what, const ga_group *g, const char *name, ga_frame *f)
{
    if (!name || strcmp(name, "body") == 0)
        *f = GA_FRAME_BODY;
    else if (strcmp(name, "spatial") == 0)
        *f = GA_FRAME_SPATIAL;
    else if (strcmp(name, "world") == 0)
        *f = GA_FRAME_WORLD;
    else {
        PyErr_Format(PyExc_ValueError, "%s: frame must be 'body', 'spatial' or 'world', not '%s'", what,
                     name);
        return -1;
    }
    if (*f == GA_FRAME_WORLD && g && !g->rigid) {
        PyErr_Format(PyExc_ValueError, "%s: frame='world' needs a rigid group (cga or matrix), not '%s'",
                     what, g->name);
        return -1;
    }
    return 0;
}

static PyObject *path_call(gpy_PathObject *self, PyObject *args, PyObject *kw, const char *what,
                           gpy_kernel_fn kernel, gpy_core outcore)
{
    static char *kwlist[] = {"t", "extrapolate", "out", NULL};
    static char *kwlist_frame[] = {"t", "frame", "extrapolate", "out", NULL};
    PyObject *t, *out = NULL;
    const char *frame = NULL, *extrap = NULL;
    int derivative = kernel != k_sample;
    if (!(derivative
              ? PyArg_ParseTupleAndKeywords(args, kw, "O|$zzO", kwlist_frame, &t, &frame, &extrap, &out)
              : PyArg_ParseTupleAndKeywords(args, kw, "O|$zO", kwlist, &t, &extrap, &out)) ||
        !gpy_path_ready(self))
        return NULL;
    path_ctx c = PATH_CTX(&self->path, self->stamp, self->ns, NULL);
    if ((derivative && parse_frame(what, self->group, frame, &c.frame)) ||
        parse_extrap(what, extrap, &c.mode))
        return NULL;
    gpy_kernel_call kc = {.what = what,
                          .nin = 1,
                          .in = {{.ncore = 0, .name = "t"}},
                          .out = outcore,
                          .kernel = kernel,
                          .ctx = &c,
                          .explain = explain_time,
                          .many = kernel == k_sample ? m_sample : NULL,
                          .lock = self->lock};
    PyObject *rel = gpy_path_rel_times(self, t, &c.given);
    PyObject *r = rel ? gpy_run_kernel(&kc, &rel, out) : NULL;
    Py_XDECREF(rel);
    Py_XDECREF(c.given);
    return r;
}

PyObject *gpy_path_sample(gpy_PathObject *self, PyObject *args, PyObject *kw)
{
    return path_call(self, args, kw, "Path.sample", k_sample, (gpy_core)GPY_CORE2(4, 4, NULL));
}

PyObject *gpy_path_velocity(gpy_PathObject *self, PyObject *args, PyObject *kw)
{
    return path_call(self, args, kw, "Path.velocity", k_velocity,
                     self->group && !self->group->rigid ? (gpy_core)GPY_CORE2(4, 4, NULL)
                                                        : (gpy_core)GPY_CORE1(6, NULL));
}

PyObject *gpy_path_acceleration(gpy_PathObject *self, PyObject *args, PyObject *kw)
{
    return path_call(self, args, kw, "Path.acceleration", k_acceleration,
                     self->group && !self->group->rigid ? (gpy_core)GPY_CORE2(4, 4, NULL)
                                                        : (gpy_core)GPY_CORE1(6, NULL));
}

PyObject *gpy_path_jerk(gpy_PathObject *self, PyObject *args, PyObject *kw)
{
    return path_call(self, args, kw, "Path.jerk", k_jerk,
                     self->group && !self->group->rigid ? (gpy_core)GPY_CORE2(4, 4, NULL)
                                                        : (gpy_core)GPY_CORE1(6, NULL));
}

/* Path.sample_pose: the pose x y z qx qy qz qw of each sample from the
 * group's own rotation and translation (to_qt, as `garotor interp --format
 * pose` writes it), the quaternion's sign following the previous sample's
 * along t's last axis (the first: qw >= 0). */
typedef struct {
    path_ctx pc;
    npy_intp run;
    double prev[4];
} pose_path_ctx;

static int k_sample_pose(void *ctx, const double *const *in, double *out, npy_intp k)
{
    pose_path_ctx *c = ctx;
    const ga_path *p = c->pc.path;
    double e[GA_GROUP_MAX_ELEM], q[4], t[3];
    int st = pose_at(&c->pc, in[0], e);
    if (st != GA_OK)
        return path_failed(&c->pc, st, k);
    p->group->to_qt(e, q, t);
    if (c->run == 0 || k % c->run == 0) {
        c->prev[0] = 1.0;
        c->prev[1] = c->prev[2] = c->prev[3] = 0.0;
    }
    if (q[0] * c->prev[0] + q[1] * c->prev[1] + q[2] * c->prev[2] + q[3] * c->prev[3] < 0.0)
        for (int i = 0; i < 4; i++) q[i] = -q[i];
    memcpy(c->prev, q, sizeof q);
    double v[7] = {t[0], t[1], t[2], q[1], q[2], q[3], q[0]};
    memcpy(out, v, sizeof v);
    return GA_OK;
}

PyObject *gpy_path_sample_pose(gpy_PathObject *self, PyObject *args, PyObject *kw)
{
    static char *kwlist[] = {"t", "extrapolate", "out", NULL};
    PyObject *t, *out = NULL;
    const char *extrap = NULL;
    ga_extrap mode;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "O|$zO", kwlist, &t, &extrap, &out) || !gpy_path_ready(self) ||
        parse_extrap("Path.sample_pose", extrap, &mode))
        return NULL;
    if (!self->group->to_qt) {
        PyErr_Format(PyExc_ValueError, "Path.sample_pose: group '%s' has no poses (sample gives matrices)",
                     self->group->name);
        return NULL;
    }
    PyArrayObject *given;
    PyArrayObject *a = (PyArrayObject *)gpy_path_rel_times(self, t, &given);
    if (!a)
        return NULL;
    pose_path_ctx c = {PATH_CTX(&self->path, self->stamp, self->ns, given), 0, {1, 0, 0, 0}};
    c.pc.mode = mode;
    if (PyArray_NDIM(a) >= 1)
        c.run = PyArray_DIM(a, PyArray_NDIM(a) - 1);
    gpy_kernel_call kc = {.what = "Path.sample_pose",
                          .nin = 1,
                          .in = {{.ncore = 0, .name = "t"}},
                          .out = GPY_CORE1(7, NULL),
                          .kernel = k_sample_pose,
                          .ctx = &c,
                          .explain = explain_time,
                          .lock = self->lock};
    PyObject *r = gpy_run_kernel(&kc, (PyObject **)&a, out);
    Py_DECREF(a);
    Py_XDECREF(given);
    return r;
}
