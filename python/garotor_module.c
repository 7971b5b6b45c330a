/* python/garotor_module.c: the CPython extension module `garotor`, on the
 * numpy C API (docs/python.md).
 *
 * Every vectorised call follows one pattern (run_kernel below): its inputs
 * are converted to C-contiguous float64 arrays (a copy only where the input
 * is not one already: other dtypes, non-contiguous or Fortran-ordered
 * arrays), each with a fixed trailing "core" shape ((6,) for a twist, (4, 4)
 * for a motion, ...); their leading shapes broadcast as numpy's do; one C loop
 * over the broadcast elements calls a kernel per element, with the GIL
 * released. The result goes to a new array; an `out=` array receives it only
 * when every element succeeded, so an error leaves `out` untouched. An error
 * is a garotor.Error (a ValueError) naming the index of the first bad element
 * and the library's status text (ga_status_string), with the attributes
 * `index` (a tuple) and `status` (the GA_ERR_* code).
 */
#define PY_SSIZE_T_CLEAN
#include <Python.h>
#define NPY_NO_DEPRECATED_API NPY_1_7_API_VERSION
#include <numpy/arrayobject.h>

#include <math.h>
#include <string.h>
#include <time.h>

#include <garotor/garotor.h>

static PyObject *garotor_error; /* garotor.Error, a subclass of ValueError */

/* ---- errors ------------------------------------------------------------ */

/* Raise garotor.Error("<what>: index <i>: <status text>[: <why>]") with
 * attributes index (a tuple, () for a single element) and status; why (or
 * NULL) says what is wrong with the element where the status alone does not. */
static void raise_status_why(const char *what, int nlead, const npy_intp *lead, npy_intp flat, int status,
                             const char *why)
{
    PyObject *idx = PyTuple_New(nlead);
    if (!idx)
        return;
    for (int d = nlead - 1; d >= 0; d--) {
        npy_intp n = lead[d] ? lead[d] : 1;
        PyTuple_SET_ITEM(idx, d, PyLong_FromSsize_t((Py_ssize_t)(flat % n)));
        flat /= n;
    }
    PyObject *msg;
    const char *sep = why ? ": " : "", *tail = why ? why : "";
    if (nlead == 0)
        msg = PyUnicode_FromFormat("%s: %s%s%s", what, ga_status_string(status), sep, tail);
    else if (nlead == 1)
        msg = PyUnicode_FromFormat("%s: index %S: %s%s%s", what, PyTuple_GET_ITEM(idx, 0),
                                   ga_status_string(status), sep, tail);
    else
        msg = PyUnicode_FromFormat("%s: index %S: %s%s%s", what, idx, ga_status_string(status), sep, tail);
    PyObject *exc = msg ? PyObject_CallOneArg(garotor_error, msg) : NULL;
    Py_XDECREF(msg);
    if (exc) {
        PyObject *st = PyLong_FromLong(status);
        if (st && PyObject_SetAttrString(exc, "index", idx) == 0 &&
            PyObject_SetAttrString(exc, "status", st) == 0)
            PyErr_SetObject(garotor_error, exc);
        Py_XDECREF(st);
        Py_DECREF(exc);
    }
    Py_DECREF(idx);
}

static void raise_status(const char *what, int nlead, const npy_intp *lead, npy_intp flat, int status)
{
    raise_status_why(what, nlead, lead, flat, status, NULL);
}

/* x as Python's repr writes it (the shortest text that reads back as x) in
 * buf[32]; buf. With the GIL held. */
static const char *repr_text(double x, char buf[32])
{
    char *r = PyOS_double_to_string(x, 'r', 0, Py_DTSF_ADD_DOT_0, NULL);
    snprintf(buf, 32, "%s", r ? r : "?");
    PyMem_Free(r);
    return buf;
}

/* ---- the vectorised loop ------------------------------------------------ */

#define MAX_IN 3

typedef struct {
    int ncore;        /* trailing dimensions of one element */
    npy_intp core[2]; /* their sizes */
    const char *name; /* the argument's name, for messages */
} core_spec;

/* One element: in[j] points at input j's element, out at the output's.
 * Returns GA_OK or a GA_ERR_* status. k is the flat index of the element. */
typedef int (*kernel_fn)(void *ctx, const double *const *in, double *out, npy_intp k);

typedef struct {
    const char *what; /* the call's name in messages */
    int nin;
    core_spec in[MAX_IN];
    core_spec out;
    kernel_fn kernel;
    void *ctx;
    /* set by run_kernel: the broadcast leading shape, for kernels that care */
    int nlead;
    npy_intp lead[NPY_MAXDIMS];
    /* or NULL: for the first bad element (its inputs, the kernel's status),
       why it is bad where the status alone does not say, into why[size] */
    void (*explain)(void *ctx, const double *const *in, int status, char *why, size_t size);
} kernel_call;

static npy_intp core_size(const core_spec *c)
{
    npy_intp s = 1;
    for (int i = 0; i < c->ncore; i++) s *= c->core[i];
    return s;
}

static void shape_text(char *buf, size_t size, const core_spec *c)
{
    if (c->ncore == 0)
        snprintf(buf, size, "(...)");
    else if (c->ncore == 1)
        snprintf(buf, size, "(..., %ld)", (long)c->core[0]);
    else
        snprintf(buf, size, "(..., %ld, %ld)", (long)c->core[0], (long)c->core[1]);
}

/* obj as a C-contiguous aligned float64 array whose trailing dims are c's core;
 * NULL with an exception set otherwise. */
static PyArrayObject *as_input(const kernel_call *kc, const core_spec *c, PyObject *obj)
{
    PyArrayObject *a = (PyArrayObject *)PyArray_FROM_OTF(obj, NPY_DOUBLE, NPY_ARRAY_IN_ARRAY);
    if (!a)
        return NULL;
    int nd = PyArray_NDIM(a), ok = nd >= c->ncore;
    for (int i = 0; ok && i < c->ncore; i++) ok = PyArray_DIM(a, nd - c->ncore + i) == c->core[i];
    if (!ok) {
        char want[64];
        shape_text(want, sizeof want, c);
        PyObject *shape = PyObject_GetAttrString((PyObject *)a, "shape");
        if (shape)
            PyErr_Format(PyExc_ValueError, "%s: %s must have shape %s, not %S", kc->what, c->name, want,
                         shape);
        Py_XDECREF(shape);
        Py_DECREF(a);
        return NULL;
    }
    return a;
}

/* Check `out` (None or an array) against the result's shape: float64,
 * writeable, the same shape. 0, or -1 with an exception. */
static int check_out(const char *what, PyObject *out, PyArrayObject *res)
{
    if (out == NULL || out == Py_None)
        return 0;
    if (!PyArray_Check(out)) {
        PyErr_Format(PyExc_TypeError, "%s: out must be a numpy array", what);
        return -1;
    }
    PyArrayObject *o = (PyArrayObject *)out;
    if (PyArray_TYPE(o) != NPY_DOUBLE) {
        PyErr_Format(PyExc_TypeError, "%s: out must have dtype float64", what);
        return -1;
    }
    if (!PyArray_ISWRITEABLE(o)) {
        PyErr_Format(PyExc_ValueError, "%s: out is not writeable", what);
        return -1;
    }
    if (PyArray_NDIM(o) != PyArray_NDIM(res) ||
        !PyArray_CompareLists(PyArray_DIMS(o), PyArray_DIMS(res), PyArray_NDIM(res))) {
        PyObject *want = PyObject_GetAttrString((PyObject *)res, "shape");
        PyObject *got = PyObject_GetAttrString(out, "shape");
        if (want && got)
            PyErr_Format(PyExc_ValueError, "%s: out has shape %S, the result %S", what, got, want);
        Py_XDECREF(want);
        Py_XDECREF(got);
        return -1;
    }
    return 0;
}

/* Run kc over the inputs objs[0..nin-1]: broadcast, loop, raise or return
 * the result (or `out`, filled). */
static PyObject *run_kernel(kernel_call *kc, PyObject *const *objs, PyObject *out)
{
    PyArrayObject *a[MAX_IN] = {NULL};
    PyArrayObject *res = NULL;
    PyObject *ret = NULL;
    npy_intp step[MAX_IN][NPY_MAXDIMS]; /* doubles per leading index, 0 if broadcast */
    npy_intp csize[MAX_IN];
    int nl[MAX_IN];
    kc->nlead = 0;
    for (int j = 0; j < kc->nin; j++) {
        if (!(a[j] = as_input(kc, &kc->in[j], objs[j])))
            goto done;
        nl[j] = PyArray_NDIM(a[j]) - kc->in[j].ncore;
        csize[j] = core_size(&kc->in[j]);
        if (nl[j] > kc->nlead)
            kc->nlead = nl[j];
    }
    if (kc->nlead + kc->out.ncore > NPY_MAXDIMS) {
        PyErr_Format(PyExc_ValueError, "%s: too many dimensions", kc->what);
        goto done;
    }
    /* the broadcast leading shape (numpy's rule: align on the right) */
    for (int d = 0; d < kc->nlead; d++) kc->lead[d] = 1;
    for (int j = 0; j < kc->nin; j++)
        for (int d = 0; d < nl[j]; d++) {
            npy_intp n = PyArray_DIM(a[j], d);
            npy_intp *L = &kc->lead[kc->nlead - nl[j] + d];
            if (*L == 1)
                *L = n;
            else if (n != 1 && n != *L) {
                PyErr_Format(PyExc_ValueError, "%s: the leading shapes of the inputs do not broadcast",
                             kc->what);
                goto done;
            }
        }
    int same = 1; /* every input has the broadcast shape: plain pointer steps */
    for (int j = 0; j < kc->nin; j++) {
        npy_intp s = csize[j];
        for (int d = kc->nlead - 1; d >= 0; d--) {
            int dj = d - (kc->nlead - nl[j]);
            npy_intp n = dj >= 0 ? PyArray_DIM(a[j], dj) : 1;
            step[j][d] = (n == 1 && kc->lead[d] != 1) ? 0 : s;
            if (step[j][d] == 0 || dj < 0)
                same = same && kc->lead[d] == 1;
            s *= n;
        }
    }
    npy_intp dims[NPY_MAXDIMS], total = 1;
    for (int d = 0; d < kc->nlead; d++) {
        dims[d] = kc->lead[d];
        total *= kc->lead[d];
    }
    for (int i = 0; i < kc->out.ncore; i++) dims[kc->nlead + i] = kc->out.core[i];
    res = (PyArrayObject *)PyArray_SimpleNew(kc->nlead + kc->out.ncore, dims, NPY_DOUBLE);
    if (!res || check_out(kc->what, out, res))
        goto done;

    const double *base[MAX_IN], *p[MAX_IN];
    for (int j = 0; j < kc->nin; j++) base[j] = p[j] = (const double *)PyArray_DATA(a[j]);
    double *o = (double *)PyArray_DATA(res);
    npy_intp osize = core_size(&kc->out), bad = -1;
    int st = GA_OK;
    const double *badin[MAX_IN];
    npy_intp idx[NPY_MAXDIMS] = {0};
    Py_BEGIN_ALLOW_THREADS;
    if (same) {
        for (npy_intp k = 0; k < total; k++) {
            const double *in[MAX_IN];
            for (int j = 0; j < kc->nin; j++) in[j] = base[j] + k * csize[j];
            if ((st = kc->kernel(kc->ctx, in, o + k * osize, k)) != GA_OK) {
                bad = k;
                memcpy(badin, in, sizeof in);
                break;
            }
        }
    } else {
        for (npy_intp k = 0; k < total; k++) {
            if ((st = kc->kernel(kc->ctx, p, o + k * osize, k)) != GA_OK) {
                bad = k;
                memcpy(badin, p, sizeof p);
                break;
            }
            /* the odometer: advance the last leading index, carry left */
            for (int d = kc->nlead - 1; d >= 0; d--) {
                for (int j = 0; j < kc->nin; j++) p[j] += step[j][d];
                if (++idx[d] < kc->lead[d])
                    break;
                for (int j = 0; j < kc->nin; j++) p[j] -= step[j][d] * kc->lead[d];
                idx[d] = 0;
            }
        }
    }
    Py_END_ALLOW_THREADS;
    if (bad >= 0) {
        char why[160] = "";
        if (kc->explain)
            kc->explain(kc->ctx, badin, st, why, sizeof why);
        raise_status_why(kc->what, kc->nlead, kc->lead, bad, st, *why ? why : NULL);
        goto done;
    }
    if (out && out != Py_None) {
        if (PyArray_CopyInto((PyArrayObject *)out, res) < 0)
            goto done;
        Py_INCREF(out);
        ret = out;
    } else {
        ret = (PyObject *)res;
        res = NULL;
    }
done:
    for (int j = 0; j < kc->nin; j++) Py_XDECREF(a[j]);
    Py_XDECREF(res);
    return ret;
}

/* ---- groups ------------------------------------------------------------ */

static const ga_group *group_arg(const char *what, const char *name)
{
    const ga_group *g = ga_group_by_name(name ? name : "cga");
    if (!g)
        PyErr_Format(PyExc_ValueError, "%s: group must be 'cga', 'matrix' or 'affine', not '%s'", what, name);
    return g;
}

static void mat_put(ga_mat4 m, double *out) { memcpy(out, m.m, sizeof m.m); }
static ga_mat4 mat_get(const double *v)
{
    ga_mat4 m;
    memcpy(m.m, v, sizeof m.m);
    return m;
}

/* exp: a twist (rigid groups) or a 4x4 with last row zero (affine) */
static int k_exp(void *ctx, const double *const *in, double *out, npy_intp k)
{
    (void)k;
    const ga_group *g = ctx;
    double x[GA_GROUP_MAX_DIM], e[GA_GROUP_MAX_ELEM];
    if (g->rigid)
        memcpy(x, in[0], 6 * sizeof *x);
    else if (g->vee(mat_get(in[0]), x) != GA_OK)
        return GA_ERR_ARG;
    int st = g->exp(x, e);
    if (st == GA_OK)
        mat_put(g->to_mat4(e), out);
    return st;
}

static int k_log(void *ctx, const double *const *in, double *out, npy_intp k)
{
    (void)k;
    const ga_group *g = ctx;
    double x[GA_GROUP_MAX_DIM], e[GA_GROUP_MAX_ELEM];
    int st = g->from_mat4(mat_get(in[0]), e);
    if (st == GA_OK)
        st = g->log(e, x);
    if (st != GA_OK)
        return st;
    if (g->rigid)
        memcpy(out, x, 6 * sizeof *x);
    else
        mat_put(g->hat(x), out);
    return GA_OK;
}

static int k_compose(void *ctx, const double *const *in, double *out, npy_intp k)
{
    (void)k;
    const ga_group *g = ctx;
    double a[GA_GROUP_MAX_ELEM], b[GA_GROUP_MAX_ELEM], c[GA_GROUP_MAX_ELEM];
    int st = g->from_mat4(mat_get(in[0]), a);
    if (st == GA_OK)
        st = g->from_mat4(mat_get(in[1]), b);
    if (st != GA_OK)
        return st;
    g->compose(a, b, c);
    mat_put(g->to_mat4(c), out);
    return GA_OK;
}

static int k_inverse(void *ctx, const double *const *in, double *out, npy_intp k)
{
    (void)k;
    const ga_group *g = ctx;
    double a[GA_GROUP_MAX_ELEM], b[GA_GROUP_MAX_ELEM];
    int st = g->from_mat4(mat_get(in[0]), a);
    if (st == GA_OK)
        st = g->inverse(a, b);
    if (st == GA_OK)
        mat_put(g->to_mat4(b), out);
    return st;
}

static int k_apply(void *ctx, const double *const *in, double *out, npy_intp k)
{
    (void)k;
    const ga_group *g = ctx;
    double a[GA_GROUP_MAX_ELEM];
    int st = g->from_mat4(mat_get(in[0]), a);
    if (st != GA_OK)
        return st;
    const double *x = in[1];
    if (g == &ga_group_cga) {
        ga_vec3 y = ga_rotor_apply(*(const ga_rotor *)a, (ga_vec3){x[0], x[1], x[2]});
        out[0] = y.x, out[1] = y.y, out[2] = y.z;
    } else {
        ga_mat4 m = g->to_mat4(a);
        double y[3];
        for (int r = 0; r < 3; r++)
            y[r] = m.m[4 * r] * x[0] + m.m[4 * r + 1] * x[1] + m.m[4 * r + 2] * x[2] + m.m[4 * r + 3];
        memcpy(out, y, sizeof y);
    }
    return GA_OK;
}

/* ---- quaternions, poses, dual quaternions (cga: through the rotor) --------- */

/* A unit quaternion to 1e-9, as the tool reads poses. */
static int quat_check(ga_quat q)
{
    if (!(isfinite(q.w) && isfinite(q.x) && isfinite(q.y) && isfinite(q.z)))
        return GA_ERR_NOTFINITE;
    double norm = sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
    return fabs(norm - 1.0) > 1e-9 ? GA_ERR_NOTRIGID : GA_OK;
}

/* (x y z qx qy qz qw) -> 4x4, exactly as `garotor interp --format pose` reads a key */
static int pose_to_mat(const double *v, ga_mat4 *m)
{
    ga_quat q = {v[6], v[3], v[4], v[5]};
    int st = quat_check(q);
    if (st == GA_OK && !(isfinite(v[0]) && isfinite(v[1]) && isfinite(v[2])))
        st = GA_ERR_NOTFINITE;
    if (st == GA_OK)
        *m = ga_rotor_to_mat4(ga_rotor_from_quat(q, (ga_vec3){v[0], v[1], v[2]}));
    return st;
}

static int k_from_quat(void *ctx, const double *const *in, double *out, npy_intp k)
{
    (void)ctx, (void)k;
    const double *q = in[0], *t = in[1];
    double v[7] = {t[0], t[1], t[2], q[0], q[1], q[2], q[3]};
    ga_mat4 m;
    int st = pose_to_mat(v, &m);
    if (st == GA_OK)
        mat_put(m, out);
    return st;
}

static int k_from_pose(void *ctx, const double *const *in, double *out, npy_intp k)
{
    (void)ctx, (void)k;
    ga_mat4 m;
    int st = pose_to_mat(in[0], &m);
    if (st == GA_OK)
        mat_put(m, out);
    return st;
}

static int k_to_quat(void *ctx, const double *const *in, double *out, npy_intp k)
{
    (void)ctx, (void)k;
    ga_rotor r;
    int st = ga_rotor_from_mat4(mat_get(in[0]), &r);
    if (st != GA_OK)
        return st;
    ga_quat q = ga_rotor_to_quat(r);
    out[0] = q.x, out[1] = q.y, out[2] = q.z, out[3] = q.w;
    return GA_OK;
}

/* to_pose: the quaternion's sign follows the previous element along the last
 * leading axis (as the tool keeps it continuous), starting from w >= 0 */
typedef struct {
    npy_intp run; /* elements in one run (the last leading dimension), 0: no continuity */
    ga_quat prev;
} pose_ctx;

static int k_to_pose(void *ctx, const double *const *in, double *out, npy_intp k)
{
    pose_ctx *c = ctx;
    ga_mat4 m = mat_get(in[0]);
    ga_rotor r;
    int st = ga_rotor_from_mat4(m, &r);
    if (st != GA_OK)
        return st;
    ga_quat q = ga_rotor_to_quat(r);
    if (c->run == 0 || k % c->run == 0)
        c->prev = (ga_quat){1, 0, 0, 0};
    if (q.w * c->prev.w + q.x * c->prev.x + q.y * c->prev.y + q.z * c->prev.z < 0.0)
        q = (ga_quat){-q.w, -q.x, -q.y, -q.z};
    c->prev = q;
    double v[7] = {m.m[3], m.m[7], m.m[11], q.x, q.y, q.z, q.w};
    memcpy(out, v, sizeof v);
    return GA_OK;
}

/* dual quaternions as 8 numbers: real (x y z w), then dual (x y z w) */
static int k_to_dualquat(void *ctx, const double *const *in, double *out, npy_intp k)
{
    (void)ctx, (void)k;
    ga_rotor r;
    int st = ga_rotor_from_mat4(mat_get(in[0]), &r);
    if (st != GA_OK)
        return st;
    ga_dualquat d = ga_rotor_to_dualquat(r);
    double v[8] = {d.real.x, d.real.y, d.real.z, d.real.w, d.dual.x, d.dual.y, d.dual.z, d.dual.w};
    memcpy(out, v, sizeof v);
    return GA_OK;
}

static int k_from_dualquat(void *ctx, const double *const *in, double *out, npy_intp k)
{
    (void)ctx, (void)k;
    const double *v = in[0];
    ga_dualquat d = {{v[3], v[0], v[1], v[2]}, {v[7], v[4], v[5], v[6]}};
    ga_rotor r = ga_rotor_from_dualquat(d);
    int st = ga_rotor_check(r, 1e-9);
    if (st == GA_OK)
        mat_put(ga_rotor_to_mat4(r), out);
    return st;
}

/* ---- points ---------------------------------------------------------------- */

static int k_up(void *ctx, const double *const *in, double *out, npy_intp k)
{
    (void)ctx, (void)k;
    const double *x = in[0];
    ga_mv X = ga_point_up((ga_vec3){x[0], x[1], x[2]});
    memcpy(out, X.c, sizeof X.c);
    return GA_OK;
}

static int k_down(void *ctx, const double *const *in, double *out, npy_intp k)
{
    (void)ctx, (void)k;
    ga_mv X;
    memcpy(X.c, in[0], sizeof X.c);
    ga_vec3 x;
    int st = ga_point_down(X, &x);
    if (st == GA_OK)
        out[0] = x.x, out[1] = x.y, out[2] = x.z;
    return st;
}

/* ---- module functions ------------------------------------------------------ */

#define CORE0                                                                                                \
    {                                                                                                        \
        0, {0, 0}, NULL                                                                                      \
    }
#define CORE1(n, name)                                                                                       \
    {                                                                                                        \
        1, {n, 0}, name                                                                                      \
    }
#define CORE2(n, m, name)                                                                                    \
    {                                                                                                        \
        2, {n, m}, name                                                                                      \
    }

static PyObject *py_exp(PyObject *self, PyObject *args, PyObject *kw)
{
    (void)self;
    static char *kwlist[] = {"xi", "group", "out", NULL};
    PyObject *xi, *out = NULL;
    const char *gname = NULL;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "O|s$O:exp", kwlist, &xi, &gname, &out))
        return NULL;
    const ga_group *g = group_arg("exp", gname);
    if (!g)
        return NULL;
    kernel_call kc = {"exp",
                      1,
                      {g->rigid ? (core_spec)CORE1(6, "xi") : (core_spec)CORE2(4, 4, "xi")},
                      CORE2(4, 4, NULL),
                      k_exp,
                      (void *)g,
                      0,
                      {0},
                      NULL};
    return run_kernel(&kc, &xi, out);
}

static PyObject *py_log(PyObject *self, PyObject *args, PyObject *kw)
{
    (void)self;
    static char *kwlist[] = {"T", "group", "out", NULL};
    PyObject *T, *out = NULL;
    const char *gname = NULL;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "O|s$O:log", kwlist, &T, &gname, &out))
        return NULL;
    const ga_group *g = group_arg("log", gname);
    if (!g)
        return NULL;
    kernel_call kc = {"log",
                      1,
                      {CORE2(4, 4, "T")},
                      g->rigid ? (core_spec)CORE1(6, NULL) : (core_spec)CORE2(4, 4, NULL),
                      k_log,
                      (void *)g,
                      0,
                      {0},
                      NULL};
    return run_kernel(&kc, &T, out);
}

static PyObject *py_compose(PyObject *self, PyObject *args, PyObject *kw)
{
    (void)self;
    static char *kwlist[] = {"A", "B", "group", "out", NULL};
    PyObject *in[2], *out = NULL;
    const char *gname = NULL;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "OO|s$O:compose", kwlist, &in[0], &in[1], &gname, &out))
        return NULL;
    const ga_group *g = group_arg("compose", gname);
    if (!g)
        return NULL;
    kernel_call kc = {
        "compose", 2,   {CORE2(4, 4, "A"), CORE2(4, 4, "B")}, CORE2(4, 4, NULL), k_compose, (void *)g, 0,
        {0},       NULL};
    return run_kernel(&kc, in, out);
}

static PyObject *py_inverse(PyObject *self, PyObject *args, PyObject *kw)
{
    (void)self;
    static char *kwlist[] = {"T", "group", "out", NULL};
    PyObject *T, *out = NULL;
    const char *gname = NULL;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "O|s$O:inverse", kwlist, &T, &gname, &out))
        return NULL;
    const ga_group *g = group_arg("inverse", gname);
    if (!g)
        return NULL;
    kernel_call kc = {"inverse", 1,   {CORE2(4, 4, "T")}, CORE2(4, 4, NULL), k_inverse, (void *)g, 0,
                      {0},       NULL};
    return run_kernel(&kc, &T, out);
}

static PyObject *py_apply(PyObject *self, PyObject *args, PyObject *kw)
{
    (void)self;
    static char *kwlist[] = {"T", "points", "group", "out", NULL};
    PyObject *in[2], *out = NULL;
    const char *gname = NULL;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "OO|s$O:apply", kwlist, &in[0], &in[1], &gname, &out))
        return NULL;
    const ga_group *g = group_arg("apply", gname);
    if (!g)
        return NULL;
    kernel_call kc = {
        "apply", 2, {CORE2(4, 4, "T"), CORE1(3, "points")}, CORE1(3, NULL), k_apply, (void *)g, 0, {0}, NULL};
    return run_kernel(&kc, in, out);
}

static PyObject *py_from_quat(PyObject *self, PyObject *args, PyObject *kw)
{
    (void)self;
    static char *kwlist[] = {"q", "t", "out", NULL};
    PyObject *in[2] = {NULL, NULL}, *out = NULL, *zero = NULL;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "O|O$O:from_quat", kwlist, &in[0], &in[1], &out))
        return NULL;
    if (!in[1] || in[1] == Py_None) {
        npy_intp three = 3;
        in[1] = zero = PyArray_ZEROS(1, &three, NPY_DOUBLE, 0);
        if (!zero)
            return NULL;
    }
    kernel_call kc = {
        "from_quat", 2, {CORE1(4, "q"), CORE1(3, "t")}, CORE2(4, 4, NULL), k_from_quat, NULL, 0, {0}, NULL};
    PyObject *r = run_kernel(&kc, in, out);
    Py_XDECREF(zero);
    return r;
}

#define ONE_INPUT_FN(fname, argname, incore, outcore, kernel)                                                \
    static PyObject *py_##fname(PyObject *self, PyObject *args, PyObject *kw)                                \
    {                                                                                                        \
        (void)self;                                                                                          \
        static char *kwlist[] = {argname, "out", NULL};                                                      \
        PyObject *x, *out = NULL;                                                                            \
        if (!PyArg_ParseTupleAndKeywords(args, kw, "O|$O:" #fname, kwlist, &x, &out))                        \
            return NULL;                                                                                     \
        kernel_call kc = {#fname, 1, {incore}, outcore, kernel, NULL, 0, {0}, NULL};                         \
        return run_kernel(&kc, &x, out);                                                                     \
    }

ONE_INPUT_FN(to_quat, "T", CORE2(4, 4, "T"), CORE1(4, NULL), k_to_quat)
ONE_INPUT_FN(from_pose, "poses", CORE1(7, "poses"), CORE2(4, 4, NULL), k_from_pose)
ONE_INPUT_FN(to_dualquat, "T", CORE2(4, 4, "T"), CORE1(8, NULL), k_to_dualquat)
ONE_INPUT_FN(from_dualquat, "d", CORE1(8, "d"), CORE2(4, 4, NULL), k_from_dualquat)
ONE_INPUT_FN(up, "x", CORE1(3, "x"), CORE1(32, NULL), k_up)
ONE_INPUT_FN(down, "X", CORE1(32, "X"), CORE1(3, NULL), k_down)

static PyObject *py_to_pose(PyObject *self, PyObject *args, PyObject *kw)
{
    (void)self;
    static char *kwlist[] = {"T", "continuous", "out", NULL};
    PyObject *T, *out = NULL;
    int continuous = 1;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "O|p$O:to_pose", kwlist, &T, &continuous, &out))
        return NULL;
    /* the run length is the last leading dimension, known only after the
     * broadcast: run_kernel sets kc.lead before the loop; the kernel reads it
     * through the context */
    pose_ctx c = {0, {1, 0, 0, 0}};
    PyArrayObject *a = (PyArrayObject *)PyArray_FROM_OTF(T, NPY_DOUBLE, NPY_ARRAY_IN_ARRAY);
    if (!a)
        return NULL;
    if (continuous && PyArray_NDIM(a) >= 3)
        c.run = PyArray_DIM(a, PyArray_NDIM(a) - 3);
    kernel_call kc = {"to_pose", 1, {CORE2(4, 4, "T")}, CORE1(7, NULL), k_to_pose, &c, 0, {0}, NULL};
    PyObject *r = run_kernel(&kc, (PyObject **)&a, out);
    Py_DECREF(a);
    return r;
}

/* ---- Path -------------------------------------------------------------- */

typedef struct {
    PyObject_HEAD const ga_group *group;
    ga_scheme scheme;
    ga_path path;
    void *work;
} PathObject;

static void Path_dealloc(PathObject *self)
{
    PyMem_Free(self->work);
    Py_TYPE(self)->tp_free((PyObject *)self);
}

/* velocities for lihao2 ((6,) or, affine, (4, 4)) and lihao3 ((n, 6) / (n, 4, 4)) into dim doubles each */
static int read_velocities(const ga_group *g, PyObject *obj, size_t count, double *vel)
{
    PyArrayObject *a = (PyArrayObject *)PyArray_FROM_OTF(obj, NPY_DOUBLE, NPY_ARRAY_IN_ARRAY);
    if (!a)
        return -1;
    int nd = PyArray_NDIM(a), lihao3 = count > 1;
    int twist = nd == 1 + lihao3 && PyArray_DIM(a, nd - 1) == 6;
    int mat = !g->rigid && nd == 2 + lihao3 && PyArray_DIM(a, nd - 1) == 4 && PyArray_DIM(a, nd - 2) == 4;
    if ((!twist && !mat) || (lihao3 && (size_t)PyArray_DIM(a, 0) != count)) {
        PyErr_Format(PyExc_ValueError, "Path: velocities must have shape %s%s", lihao3 ? "(n, 6)" : "(6,)",
                     g->rigid ? "" : (lihao3 ? " or (n, 4, 4)" : " or (4, 4)"));
        Py_DECREF(a);
        return -1;
    }
    const double *v = PyArray_DATA(a);
    for (size_t i = 0; i < count; i++) {
        ga_mat4 m = twist ? ga_twist_hat((ga_twist){{v[6 * i], v[6 * i + 1], v[6 * i + 2]},
                                                    {v[6 * i + 3], v[6 * i + 4], v[6 * i + 5]}})
                          : mat_get(v + 16 * i);
        int st = g->vee(m, vel + i * g->dim);
        if (st == GA_OK) {
            for (size_t d = 0; d < g->dim; d++)
                if (!isfinite(vel[i * g->dim + d]))
                    st = GA_ERR_NOTFINITE;
        }
        if (st != GA_OK) {
            npy_intp n = (npy_intp)count;
            raise_status("Path: velocities", lihao3, &n, (npy_intp)i, st);
            Py_DECREF(a);
            return -1;
        }
    }
    Py_DECREF(a);
    return 0;
}

static int Path_init(PathObject *self, PyObject *args, PyObject *kw)
{
    static char *kwlist[] = {"times", "poses", "scheme", "group", "velocities", "capacity", NULL};
    PyObject *tobj, *pobj, *vobj = Py_None, *cobj = Py_None;
    const char *sname = "screw", *gname = "cga";
    if (!PyArg_ParseTupleAndKeywords(args, kw, "OO|ssO$O:Path", kwlist, &tobj, &pobj, &sname, &gname, &vobj,
                                     &cobj))
        return -1;
    if (self->work) {
        PyErr_SetString(PyExc_TypeError, "Path: already initialised");
        return -1;
    }
    const ga_group *g = group_arg("Path", gname);
    if (!g)
        return -1;
    ga_scheme scheme;
    if (ga_scheme_by_name(sname, &scheme) != GA_OK) {
        char names[256] = "";
        for (int i = 0; i < GA_SCHEME_COUNT; i++) {
            size_t len = strlen(names);
            snprintf(names + len, sizeof names - len, "%s'%s'", i ? ", " : "", ga_scheme_name((ga_scheme)i));
        }
        PyErr_Format(PyExc_ValueError, "Path: scheme must be one of %s, not '%s'", names, sname);
        return -1;
    }
    int rc = -1;
    double *vel = NULL;
    ga_mat4 *keys = NULL;
    PyArrayObject *t = (PyArrayObject *)PyArray_FROM_OTF(tobj, NPY_DOUBLE, NPY_ARRAY_IN_ARRAY);
    PyArrayObject *p = t ? (PyArrayObject *)PyArray_FROM_OTF(pobj, NPY_DOUBLE, NPY_ARRAY_IN_ARRAY) : NULL;
    if (!p)
        goto done;
    if (PyArray_NDIM(t) != 1) {
        PyErr_SetString(PyExc_ValueError, "Path: times must be a 1-d array");
        goto done;
    }
    npy_intp n = PyArray_DIM(t, 0);
    int pose = PyArray_NDIM(p) == 2 && PyArray_DIM(p, 1) == 7;
    int mat = PyArray_NDIM(p) == 3 && PyArray_DIM(p, 1) == 4 && PyArray_DIM(p, 2) == 4;
    if ((!pose && !mat) || PyArray_DIM(p, 0) != n) {
        PyErr_Format(PyExc_ValueError,
                     "Path: poses must have shape (n, 4, 4) or (n, 7) with n = len(times) = %zd",
                     (Py_ssize_t)n);
        goto done;
    }
    if (pose && !g->rigid) {
        PyErr_Format(PyExc_ValueError, "Path: group '%s' takes keys as (n, 4, 4) matrices", g->name);
        goto done;
    }
    size_t min = ga_scheme_min_keys(scheme);
    if (n != 1 && ((size_t)n < min || (scheme == GA_SCHEME_QUADRATIC && n != 3))) { /* 1: constant */
        PyErr_Format(PyExc_ValueError, "Path: scheme '%s' needs one key or %s %zu, got %zd", sname,
                     scheme == GA_SCHEME_QUADRATIC ? "exactly" : "at least", min, (Py_ssize_t)n);
        goto done;
    }
    size_t wbytes = ga_path_workspace_size(g, scheme, (size_t)n);
    if (wbytes == 0) { /* the scheme is not defined on the group (path.h) */
        PyErr_Format(PyExc_ValueError, "Path: scheme '%s' is not defined on group '%s'", sname, g->name);
        goto done;
    }
    if (cobj != Py_None) { /* room for keys to come (Path.append) */
        Py_ssize_t cap = PyNumber_AsSsize_t(cobj, PyExc_OverflowError);
        if (cap == -1 && PyErr_Occurred())
            goto done;
        if (!ga_scheme_can_append(scheme)) {
            PyErr_Format(PyExc_ValueError,
                         "Path: capacity: scheme '%s' cannot append keys (build a new Path)", sname);
            goto done;
        }
        if (cap < n) {
            PyErr_Format(PyExc_ValueError, "Path: capacity %zd is less than the %zd keys given", cap,
                         (Py_ssize_t)n);
            goto done;
        }
        wbytes = ga_path_workspace_size(g, scheme, (size_t)cap);
    }
    const double *tv = PyArray_DATA(t), *pv = PyArray_DATA(p);
    for (npy_intp i = 0; i < n; i++)
        if (!isfinite(tv[i]) || (i > 0 && !(tv[i] > tv[i - 1]))) {
            char why[128] = "", a[32], b[32];
            if (isfinite(tv[i]))
                snprintf(why, sizeof why, "%s is not after the time before it, %s (times must increase)",
                         repr_text(tv[i], a), repr_text(tv[i - 1], b));
            raise_status_why("Path: times", 1, &n, i, isfinite(tv[i]) ? GA_ERR_ARG : GA_ERR_NOTFINITE,
                             *why ? why : NULL);
            goto done;
        }
    size_t bad = scheme == GA_SCHEME_BSPLINE ? ga_times_uneven((size_t)n, tv) : 0;
    if (bad) {
        PyErr_Format(
            PyExc_ValueError,
            "Path: scheme 'bspline' needs evenly spaced times (to 1e-9 of the spacing): index %zu is off "
            "the even grid of the first and last",
            bad);
        goto done;
    }
    keys = PyMem_Malloc((size_t)n * sizeof *keys);
    if (!keys) {
        PyErr_NoMemory();
        goto done;
    }
    for (npy_intp i = 0; i < n; i++) {
        double e[GA_GROUP_MAX_ELEM];
        int st = pose ? pose_to_mat(pv + 7 * i, &keys[i]) : GA_OK;
        if (!pose)
            keys[i] = mat_get(pv + 16 * i);
        if (st == GA_OK)
            st = g->from_mat4(keys[i], e);
        if (st != GA_OK) {
            raise_status("Path: poses", 1, &n, i, st);
            goto done;
        }
    }
    if (vobj != Py_None) {
        if (scheme != GA_SCHEME_LIHAO2 && scheme != GA_SCHEME_LIHAO3) {
            PyErr_SetString(PyExc_ValueError,
                            "Path: velocities apply only to the schemes 'lihao2' and 'lihao3'");
            goto done;
        }
        size_t count = scheme == GA_SCHEME_LIHAO3 ? (size_t)n : 1;
        vel = PyMem_Malloc(count * g->dim * sizeof *vel);
        if (!vel) {
            PyErr_NoMemory();
            goto done;
        }
        if (read_velocities(g, vobj, count, vel))
            goto done;
    }
    self->work = PyMem_Malloc(wbytes);
    if (!self->work) {
        PyErr_NoMemory();
        goto done;
    }
    int st = ga_path_init_mat4(g, scheme, (size_t)n, tv, keys, vel, self->work, wbytes, &self->path);
    if (st != GA_OK) {
        PyErr_Format(garotor_error, "Path: cannot build the %s path: %s", sname, ga_status_string(st));
        PyMem_Free(self->work);
        self->work = NULL;
        goto done;
    }
    self->group = g;
    self->scheme = scheme;
    rc = 0;
done:
    PyMem_Free(keys);
    PyMem_Free(vel);
    Py_XDECREF(t);
    Py_XDECREF(p);
    return rc;
}

static int path_ready(PathObject *self)
{
    if (!self->work) {
        PyErr_SetString(PyExc_ValueError, "Path: not initialised");
        return 0;
    }
    return 1;
}

static int k_sample(void *ctx, const double *const *in, double *out, npy_intp k)
{
    (void)k;
    const ga_path *p = ctx;
    double e[GA_GROUP_MAX_ELEM];
    int st = ga_path_sample(p, GA_EVAL_DIRECT, 1.0, 1, in[0], e);
    if (st == GA_OK)
        mat_put(p->group->to_mat4(e), out);
    return st;
}

static int k_velocity(void *ctx, const double *const *in, double *out, npy_intp k)
{
    (void)k;
    const ga_path *p = ctx;
    double v[GA_GROUP_MAX_DIM];
    if (!isfinite(in[0][0]))
        return GA_ERR_NOTFINITE;
    int st = ga_path_velocity(p, in[0][0], v);
    if (st != GA_OK)
        return st;
    if (p->group->rigid)
        memcpy(out, v, 6 * sizeof *v);
    else
        mat_put(p->group->hat(v), out);
    return GA_OK;
}

static int k_acceleration(void *ctx, const double *const *in, double *out, npy_intp k)
{
    (void)k;
    const ga_path *p = ctx;
    double a[GA_GROUP_MAX_DIM];
    if (!isfinite(in[0][0]))
        return GA_ERR_NOTFINITE;
    int st = ga_path_acceleration(p, in[0][0], a);
    if (st != GA_OK)
        return st;
    if (p->group->rigid)
        memcpy(out, a, 6 * sizeof *a);
    else
        mat_put(p->group->hat(a), out);
    return GA_OK;
}

/* A time the path is not defined at: outside its range (or NaN). */
static void explain_time(void *ctx, const double *const *in, int status, char *why, size_t size)
{
    double t0, t1, t = in[0][0];
    if (status == GA_ERR_NOTFINITE || ga_path_range(ctx, &t0, &t1) != GA_OK)
        return;
    char a[32], b[32], c[32];
    if (isnan(t))
        snprintf(why, size, "t is NaN");
    else if (t < t0 || t > t1)
        snprintf(why, size, "t = %s is outside the path's range [%s, %s] (Path.range)", repr_text(t, a),
                 repr_text(t0, b), repr_text(t1, c));
}

static PyObject *path_call(PathObject *self, PyObject *args, PyObject *kw, const char *what, kernel_fn kernel,
                           core_spec outcore)
{
    static char *kwlist[] = {"t", "out", NULL};
    PyObject *t, *out = NULL;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "O|$O", kwlist, &t, &out) || !path_ready(self))
        return NULL;
    kernel_call kc = {what, 1, {CORE0}, outcore, kernel, &self->path, 0, {0}, NULL};
    kc.in[0].name = "t";
    kc.explain = explain_time;
    return run_kernel(&kc, &t, out);
}

static PyObject *Path_sample(PathObject *self, PyObject *args, PyObject *kw)
{
    return path_call(self, args, kw, "Path.sample", k_sample, (core_spec)CORE2(4, 4, NULL));
}

static PyObject *Path_velocity(PathObject *self, PyObject *args, PyObject *kw)
{
    return path_call(self, args, kw, "Path.velocity", k_velocity,
                     self->group && !self->group->rigid ? (core_spec)CORE2(4, 4, NULL)
                                                        : (core_spec)CORE1(6, NULL));
}

static PyObject *Path_acceleration(PathObject *self, PyObject *args, PyObject *kw)
{
    return path_call(self, args, kw, "Path.acceleration", k_acceleration,
                     self->group && !self->group->rigid ? (core_spec)CORE2(4, 4, NULL)
                                                        : (core_spec)CORE1(6, NULL));
}

static PyObject *Path_get_times(PathObject *self, void *c)
{
    (void)c;
    if (!path_ready(self))
        return NULL;
    npy_intp n = (npy_intp)self->path.n;
    PyArrayObject *a = (PyArrayObject *)PyArray_SimpleNew(1, &n, NPY_DOUBLE);
    if (!a)
        return NULL;
    memcpy(PyArray_DATA(a), self->path.t, (size_t)n * sizeof(double));
    PyArray_CLEARFLAGS(a, NPY_ARRAY_WRITEABLE);
    return (PyObject *)a;
}

static PyObject *Path_get_capacity(PathObject *self, void *c)
{
    (void)c;
    return path_ready(self) ? PyLong_FromSize_t(self->path.cap) : NULL;
}

/* append(t, pose): one key, a (4, 4) matrix or a (7,) row */
static PyObject *Path_append(PathObject *self, PyObject *args, PyObject *kw)
{
    static char *kwlist[] = {"t", "pose", NULL};
    double t;
    PyObject *pobj;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "dO:append", kwlist, &t, &pobj) || !path_ready(self))
        return NULL;
    if (!ga_scheme_can_append(self->scheme)) {
        PyErr_Format(PyExc_ValueError, "Path.append: scheme '%s' cannot append keys (build a new Path)",
                     ga_scheme_name(self->scheme));
        return NULL;
    }
    if (self->path.n >= self->path.cap) {
        PyErr_Format(PyExc_ValueError,
                     "Path.append: the path is full (capacity %zu; give Path a larger capacity=)",
                     self->path.cap);
        return NULL;
    }
    if (!isfinite(t) || !(t > self->path.t[self->path.n - 1])) {
        char buf[128];
        snprintf(buf, sizeof buf, "t = %.17g must be finite and after the last key's time %.17g", t,
                 self->path.t[self->path.n - 1]);
        PyErr_Format(PyExc_ValueError, "Path.append: %s", buf);
        return NULL;
    }
    PyArrayObject *p = (PyArrayObject *)PyArray_FROM_OTF(pobj, NPY_DOUBLE, NPY_ARRAY_IN_ARRAY);
    if (!p)
        return NULL;
    int pose = PyArray_NDIM(p) == 1 && PyArray_DIM(p, 0) == 7 && self->group->rigid;
    int mat = PyArray_NDIM(p) == 2 && PyArray_DIM(p, 0) == 4 && PyArray_DIM(p, 1) == 4;
    ga_mat4 m;
    int st = GA_OK;
    if (!pose && !mat) {
        PyErr_SetString(PyExc_ValueError, self->group->rigid
                                              ? "Path.append: pose must have shape (4, 4) or (7,)"
                                              : "Path.append: pose must have shape (4, 4)");
        Py_DECREF(p);
        return NULL;
    }
    if (pose)
        st = pose_to_mat(PyArray_DATA(p), &m);
    else
        m = mat_get(PyArray_DATA(p));
    Py_DECREF(p);
    if (st == GA_OK)
        st = ga_path_append_mat4(&self->path, t, m);
    if (st == GA_ERR_ARG && self->scheme == GA_SCHEME_BSPLINE) {
        PyErr_Format(PyExc_ValueError, "Path.append: scheme 'bspline' takes a key %s",
                     self->path.n < 4 ? "only after 4 keys or more" : "only at evenly spaced times");
        return NULL;
    }
    if (st != GA_OK) {
        PyErr_Format(st == GA_ERR_DOMAIN ? garotor_error : PyExc_ValueError, "Path.append: %s",
                     ga_status_string(st));
        return NULL;
    }
    Py_RETURN_NONE;
}
static PyObject *Path_get_scheme(PathObject *self, void *c)
{
    (void)c;
    return path_ready(self) ? PyUnicode_FromString(ga_scheme_name(self->scheme)) : NULL;
}
static PyObject *Path_get_range(PathObject *self, void *c)
{
    (void)c;
    double t0, t1;
    if (!path_ready(self))
        return NULL;
    int st = ga_path_range(&self->path, &t0, &t1);
    if (st != GA_OK) {
        PyErr_SetString(PyExc_ValueError, ga_status_string(st));
        return NULL;
    }
    return Py_BuildValue("(dd)", t0, t1);
}
static PyObject *Path_get_group(PathObject *self, void *c)
{
    (void)c;
    return path_ready(self) ? PyUnicode_FromString(self->group->name) : NULL;
}

static PyObject *Path_repr(PathObject *self)
{
    if (!self->work)
        return PyUnicode_FromString("<garotor.Path (not initialised)>");
    return PyUnicode_FromFormat("<garotor.Path: %s on %s, %zu keys>", ga_scheme_name(self->scheme),
                                self->group->name, self->path.n);
}

static PyMethodDef Path_methods[] = {
    {"sample", (PyCFunction)(void (*)(void))Path_sample, METH_VARARGS | METH_KEYWORDS,
     "sample(t, *, out=None): the poses at the times t (any shape ...), as (..., 4, 4) matrices."},
    {"velocity", (PyCFunction)(void (*)(void))Path_velocity, METH_VARARGS | METH_KEYWORDS,
     "velocity(t, *, out=None): the body velocity A(t)^-1 dA/dt per unit time at the times t: (..., 6) "
     "twists "
     "(affine: (..., 4, 4))."},
    {"acceleration", (PyCFunction)(void (*)(void))Path_acceleration, METH_VARARGS | METH_KEYWORDS,
     "acceleration(t, *, out=None): the body acceleration d/dt (A^-1 dA/dt) per unit time^2 at the times t: "
     "(..., 6) (affine: (..., 4, 4))."},
    {"append", (PyCFunction)(void (*)(void))Path_append, METH_VARARGS | METH_KEYWORDS,
     "append(t, pose): add a key after the last (schemes screw, bivector, lihao2, decoupled, bspline), "
     "building one "
     "new segment; the Path then equals one built from all the keys, bit for bit. Room: Path(..., "
     "capacity=m)."},
    {NULL, NULL, 0, NULL}};

static PyGetSetDef Path_getset[] = {
    {"times", (getter)Path_get_times, NULL, "the key times (a read-only copy)", NULL},
    {"capacity", (getter)Path_get_capacity, NULL, "the keys the Path has room for (Path.append)", NULL},
    {"scheme", (getter)Path_get_scheme, NULL, "the scheme's name", NULL},
    {"range", (getter)Path_get_range, NULL,
     "(t0, t1), the times the path is defined on: the first and last key's (bspline: the second and the last "
     "but one's)",
     NULL},
    {"group", (getter)Path_get_group, NULL, "the group's name", NULL},
    {NULL, NULL, NULL, NULL, NULL}};

static PyTypeObject PathType = {
    PyVarObject_HEAD_INIT(NULL, 0).tp_name = "garotor.Path",
    .tp_basicsize = sizeof(PathObject),
    .tp_dealloc = (destructor)Path_dealloc,
    .tp_repr = (reprfunc)Path_repr,
    .tp_flags = Py_TPFLAGS_DEFAULT,
    .tp_doc =
        "Path(times, poses, scheme='screw', group='cga', velocities=None, *, capacity=None): a path through "
        "key "
        "poses.\n\n"
        "times: (n,) strictly increasing; poses: (n, 4, 4) matrices or (n, 7) rows x y z qx qy qz qw;\n"
        "scheme: screw, bivector, quadratic, smooth, lihao2, lihao3, decoupled, decoupled-c2, bspline, c2;\n"
        "group: cga, matrix, affine; velocities: lihao2 the first key's (6,), lihao3 one per key (n, 6);\n"
        "capacity: room for keys to come (append), for the schemes that can append.",
    .tp_methods = Path_methods,
    .tp_getset = Path_getset,
    .tp_init = (initproc)Path_init,
    .tp_new = PyType_GenericNew,
};

/* ---- Multivector ------------------------------------------------------- */

typedef struct {
    PyObject_HEAD ga_mv mv;
} MVObject;

static PyTypeObject MVType;

static PyObject *mv_new(ga_mv m)
{
    MVObject *o = PyObject_New(MVObject, &MVType);
    if (o)
        o->mv = m;
    return (PyObject *)o;
}

/* A Multivector, or a real number as a scalar multivector; 0 if neither. */
static int mv_coerce(PyObject *x, ga_mv *out)
{
    if (PyObject_TypeCheck(x, &MVType)) {
        *out = ((MVObject *)x)->mv;
        return 1;
    }
    if (PyFloat_Check(x) || PyLong_Check(x) || PyArray_IsScalar(x, Floating) ||
        PyArray_IsScalar(x, Integer)) {
        double s = PyFloat_AsDouble(x);
        if (s == -1.0 && PyErr_Occurred()) {
            PyErr_Clear();
            return 0;
        }
        *out = ga_mv_scalar(s);
        return 1;
    }
    return 0;
}

static PyObject *MV_new(PyTypeObject *type, PyObject *args, PyObject *kw)
{
    (void)type;
    static char *kwlist[] = {"c", NULL};
    PyObject *c = NULL;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "|O:Multivector", kwlist, &c))
        return NULL;
    ga_mv m = ga_mv_zero();
    if (c && PyObject_TypeCheck(c, &MVType))
        return mv_new(((MVObject *)c)->mv);
    if (c) {
        PyArrayObject *a = (PyArrayObject *)PyArray_FROM_OTF(c, NPY_DOUBLE, NPY_ARRAY_IN_ARRAY);
        if (!a)
            return NULL;
        if (PyArray_NDIM(a) != 1 || PyArray_DIM(a, 0) != 32) {
            Py_DECREF(a);
            PyErr_SetString(PyExc_ValueError, "Multivector: needs 32 coefficients in canonical order");
            return NULL;
        }
        memcpy(m.c, PyArray_DATA(a), sizeof m.c);
        Py_DECREF(a);
    }
    return mv_new(m);
}

static PyObject *MV_repr(MVObject *self)
{
    PyObject *parts = PyList_New(0);
    if (!parts)
        return NULL;
    for (int i = 0; i < 32; i++) {
        double v = self->mv.c[i];
        if (v == 0.0)
            continue;
        char *num = PyOS_double_to_string(fabs(v), 'r', 0, 0, NULL);
        if (!num) {
            Py_DECREF(parts);
            return NULL;
        }
        int first = PyList_GET_SIZE(parts) == 0;
        const char *sign = signbit(v) ? (first ? "-" : " - ") : (first ? "" : " + ");
        PyObject *s = i == 0         ? PyUnicode_FromFormat("%s%s", sign, num)
                    : fabs(v) == 1.0 ? PyUnicode_FromFormat("%s%s", sign, ga_blade_name(i))
                                     : PyUnicode_FromFormat("%s%s*%s", sign, num, ga_blade_name(i));
        PyMem_Free(num);
        if (!s || PyList_Append(parts, s) < 0) {
            Py_XDECREF(s);
            Py_DECREF(parts);
            return NULL;
        }
        Py_DECREF(s);
    }
    PyObject *empty = PyUnicode_FromString("");
    PyObject *body = empty ? PyUnicode_Join(empty, parts) : NULL;
    Py_XDECREF(empty);
    Py_DECREF(parts);
    if (!body)
        return NULL;
    PyObject *r = PyUnicode_GET_LENGTH(body) ? PyUnicode_FromFormat("Multivector(%U)", body)
                                             : PyUnicode_FromString("Multivector(0)");
    Py_DECREF(body);
    return r;
}

#define MV_BINOP(name, expr)                                                                                 \
    static PyObject *MV_##name(PyObject *x, PyObject *y)                                                     \
    {                                                                                                        \
        ga_mv a, b;                                                                                          \
        if (!mv_coerce(x, &a) || !mv_coerce(y, &b))                                                          \
            Py_RETURN_NOTIMPLEMENTED;                                                                        \
        return mv_new(expr);                                                                                 \
    }
MV_BINOP(add, ga_mv_add(a, b))
MV_BINOP(sub, ga_mv_sub(a, b))
MV_BINOP(mul, ga_mv_gp(a, b))
MV_BINOP(xor, ga_mv_op(a, b))
MV_BINOP(or, ga_mv_lc(a, b))

static PyObject *MV_truediv(PyObject *x, PyObject *y)
{
    ga_mv a;
    if (!PyObject_TypeCheck(x, &MVType) ||
        !(PyFloat_Check(y) || PyLong_Check(y) || PyArray_IsScalar(y, Number)))
        Py_RETURN_NOTIMPLEMENTED;
    a = ((MVObject *)x)->mv;
    double s = PyFloat_AsDouble(y);
    if (s == -1.0 && PyErr_Occurred())
        return NULL;
    if (s == 0.0) { /* as Python's float division */
        PyErr_SetString(PyExc_ZeroDivisionError, "Multivector division by zero");
        return NULL;
    }
    for (int i = 0; i < 32; i++) a.c[i] /= s;
    return mv_new(a);
}

static PyObject *MV_neg(MVObject *x) { return mv_new(ga_mv_scale(x->mv, -1.0)); }
static PyObject *MV_pos(MVObject *x) { return mv_new(x->mv); }
static PyObject *MV_invert(MVObject *x) { return mv_new(ga_mv_reverse(x->mv)); }

static PyNumberMethods MV_as_number = {
    .nb_add = MV_add,
    .nb_subtract = MV_sub,
    .nb_multiply = MV_mul,
    .nb_xor = MV_xor,
    .nb_or = MV_or,
    .nb_true_divide = MV_truediv,
    .nb_negative = (unaryfunc)MV_neg,
    .nb_positive = (unaryfunc)MV_pos,
    .nb_invert = (unaryfunc)MV_invert,
};

static PyObject *MV_richcompare(PyObject *x, PyObject *y, int op)
{
    ga_mv a, b;
    if ((op != Py_EQ && op != Py_NE) || !mv_coerce(x, &a) || !mv_coerce(y, &b))
        Py_RETURN_NOTIMPLEMENTED;
    int eq = 1;
    for (int i = 0; i < 32; i++) eq = eq && a.c[i] == b.c[i];
    return PyBool_FromLong(op == Py_EQ ? eq : !eq);
}

static int blade_index(PyObject *key)
{
    if (PyUnicode_Check(key)) {
        const char *s = PyUnicode_AsUTF8(key);
        if (!s)
            return -1;
        for (int i = 0; i < 32; i++)
            if (strcmp(s, ga_blade_name(i)) == 0)
                return i;
        PyErr_Format(PyExc_KeyError, "no blade named '%s' (names: 1, e1, ..., e12345)", s);
        return -1;
    }
    Py_ssize_t i = PyNumber_AsSsize_t(key, PyExc_IndexError);
    if (i == -1 && PyErr_Occurred())
        return -1;
    if (i < -32 || i >= 32) {
        PyErr_SetString(PyExc_IndexError, "a blade index is 0..31");
        return -1;
    }
    return (int)(i < 0 ? i + 32 : i);
}

static PyObject *MV_getitem(MVObject *self, PyObject *key)
{
    int i = blade_index(key);
    return i < 0 ? NULL : PyFloat_FromDouble(self->mv.c[i]);
}

static PyMappingMethods MV_as_mapping = {.mp_subscript = (binaryfunc)MV_getitem};

static PyObject *MV_array(MVObject *self, PyObject *args, PyObject *kw)
{
    static char *kwlist[] = {"dtype", "copy", NULL};
    PyObject *dtype = Py_None, *copy = Py_None;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "|OO:__array__", kwlist, &dtype, &copy))
        return NULL;
    npy_intp n = 32;
    PyObject *a = PyArray_SimpleNew(1, &n, NPY_DOUBLE);
    if (!a)
        return NULL;
    memcpy(PyArray_DATA((PyArrayObject *)a), self->mv.c, sizeof self->mv.c);
    if (dtype != Py_None) {
        PyArray_Descr *d = NULL;
        if (!PyArray_DescrConverter(dtype, &d)) {
            Py_DECREF(a);
            return NULL;
        }
        PyObject *b = PyArray_CastToType((PyArrayObject *)a, d, 0);
        Py_DECREF(a);
        return b;
    }
    return a;
}

static PyObject *MV_grade(MVObject *self, PyObject *arg)
{
    long k = PyLong_AsLong(arg);
    if (k == -1 && PyErr_Occurred())
        return NULL;
    return mv_new(ga_mv_grade(self->mv, k < 0 || k > 5 ? -1 : (int)k));
}

static PyObject *MV_dual(MVObject *self, PyObject *u)
{
    (void)u;
    return mv_new(ga_mv_dual(self->mv));
}
static PyObject *MV_undual(MVObject *self, PyObject *u)
{
    (void)u;
    return mv_new(ga_mv_undual(self->mv));
}
static PyObject *MV_reverse(MVObject *self, PyObject *u)
{
    (void)u;
    return mv_new(ga_mv_reverse(self->mv));
}
static PyObject *MV_involute(MVObject *self, PyObject *u)
{
    (void)u;
    return mv_new(ga_mv_involute(self->mv));
}
static PyObject *MV_conjugate(MVObject *self, PyObject *u)
{
    (void)u;
    return mv_new(ga_mv_conjugate(self->mv));
}
static PyObject *MV_norm2(MVObject *self, PyObject *u)
{
    (void)u;
    return PyFloat_FromDouble(ga_mv_norm2(self->mv));
}

static PyObject *mv_status(const char *what, int st)
{
    PyErr_Format(garotor_error, "%s: %s", what, ga_status_string(st));
    return NULL;
}

static PyObject *MV_inverse(MVObject *self, PyObject *u)
{
    (void)u;
    ga_mv r;
    int st = ga_mv_inverse(self->mv, &r);
    return st == GA_OK ? mv_new(r) : mv_status("Multivector.inverse", st);
}

/* The generator of a bivector in span{e_ij, e_i n}: e_i4 and e_i5 equal,
 * everything else zero, to 1e-9 of max(1, max|m|). */
static int mv_to_generator(ga_mv m, ga_generator *b)
{
    if (!ga_mv_isfinite(m))
        return GA_ERR_NOTFINITE;
    double tol = 1e-9 * fmax(1.0, ga_mv_maxabs(m));
    static const int used[] = {GA_BLADE_E12, GA_BLADE_E13, GA_BLADE_E23, GA_BLADE_E14, GA_BLADE_E15,
                               GA_BLADE_E24, GA_BLADE_E25, GA_BLADE_E34, GA_BLADE_E35};
    for (int i = 0; i < 32; i++) {
        int u = 0;
        for (size_t j = 0; j < sizeof used / sizeof *used; j++) u |= used[j] == i;
        if (!u && fabs(m.c[i]) > tol)
            return GA_ERR_NOTBLADE;
    }
    const double *c = m.c;
    if (fabs(c[GA_BLADE_E14] - c[GA_BLADE_E15]) > tol || fabs(c[GA_BLADE_E24] - c[GA_BLADE_E25]) > tol ||
        fabs(c[GA_BLADE_E34] - c[GA_BLADE_E35]) > tol)
        return GA_ERR_NOTBLADE;
    *b = (ga_generator){c[GA_BLADE_E12],
                        c[GA_BLADE_E13],
                        c[GA_BLADE_E23],
                        0.5 * (c[GA_BLADE_E14] + c[GA_BLADE_E15]),
                        0.5 * (c[GA_BLADE_E24] + c[GA_BLADE_E25]),
                        0.5 * (c[GA_BLADE_E34] + c[GA_BLADE_E35])};
    return GA_OK;
}

static ga_mv generator_to_mv(ga_generator b)
{
    ga_mv m = ga_mv_zero();
    m.c[GA_BLADE_E12] = b.e12, m.c[GA_BLADE_E13] = b.e13, m.c[GA_BLADE_E23] = b.e23;
    m.c[GA_BLADE_E14] = m.c[GA_BLADE_E15] = b.e1n;
    m.c[GA_BLADE_E24] = m.c[GA_BLADE_E25] = b.e2n;
    m.c[GA_BLADE_E34] = m.c[GA_BLADE_E35] = b.e3n;
    return m;
}

/* exp: a rigid-motion generator through the compact rotor (as before, bit
   for bit), any other bivector through ga_mv_exp; anything with other
   grades is refused (to 1e-9 of max(1, max|m|), as mv_to_generator) */
static PyObject *MV_exp(MVObject *self, PyObject *u)
{
    (void)u;
    ga_generator b;
    int st = mv_to_generator(self->mv, &b);
    if (st == GA_OK)
        return mv_new(ga_rotor_to_mv(ga_rotor_exp(b)));
    if (st == GA_ERR_NOTBLADE) {
        ga_mv m = self->mv;
        double tol = 1e-9 * fmax(1.0, ga_mv_maxabs(m));
        if (ga_mv_maxabs(ga_mv_sub(m, ga_mv_grade(m, 2))) <= tol)
            return mv_new(ga_mv_exp(ga_mv_grade(m, 2)));
    }
    return mv_status("Multivector.exp", st);
}

/* log: a rigid-motion rotor through the compact rotor (as before), any
   other rotor through ga_mv_log (GA_ERR_DOMAIN where it has no real log) */
static PyObject *MV_log(MVObject *self, PyObject *u)
{
    (void)u;
    ga_rotor r;
    ga_generator b;
    int st = ga_rotor_from_mv(self->mv, GA_ROTOR_DRIFT_MAX, &r);
    if (st == GA_OK)
        st = ga_rotor_log(r, &b);
    if (st == GA_OK)
        return mv_new(generator_to_mv(b));
    if (st == GA_ERR_NOTRIGID) {
        ga_mv L;
        st = ga_mv_log(self->mv, &L);
        if (st == GA_OK)
            return mv_new(L);
    }
    return mv_status("Multivector.log", st);
}

static PyObject *MV_dot(MVObject *self, PyObject *o)
{
    ga_mv b;
    if (!mv_coerce(o, &b)) {
        PyErr_SetString(PyExc_TypeError, "Multivector.dot: a Multivector or a number");
        return NULL;
    }
    return mv_new(ga_mv_dot(self->mv, b));
}

static PyObject *MV_ip(MVObject *self, PyObject *o)
{
    ga_mv b;
    if (!mv_coerce(o, &b)) {
        PyErr_SetString(PyExc_TypeError, "Multivector.ip: a Multivector or a number");
        return NULL;
    }
    return mv_new(ga_mv_ip(self->mv, b));
}

static PyObject *MV_down(MVObject *self, PyObject *u)
{
    (void)u;
    ga_vec3 x;
    int st = ga_point_down(self->mv, &x);
    if (st != GA_OK)
        return mv_status("Multivector.down", st);
    npy_intp n = 3;
    PyObject *a = PyArray_SimpleNew(1, &n, NPY_DOUBLE);
    if (a) {
        double *d = PyArray_DATA((PyArrayObject *)a);
        d[0] = x.x, d[1] = x.y, d[2] = x.z;
    }
    return a;
}

static PyObject *MV_up(PyObject *cls, PyObject *arg)
{
    (void)cls;
    PyArrayObject *a = (PyArrayObject *)PyArray_FROM_OTF(arg, NPY_DOUBLE, NPY_ARRAY_IN_ARRAY);
    if (!a)
        return NULL;
    if (PyArray_NDIM(a) != 1 || PyArray_DIM(a, 0) != 3) {
        Py_DECREF(a);
        PyErr_SetString(PyExc_ValueError, "Multivector.up: x must have shape (3,)");
        return NULL;
    }
    const double *x = PyArray_DATA(a);
    ga_mv m = ga_point_up((ga_vec3){x[0], x[1], x[2]});
    Py_DECREF(a);
    return mv_new(m);
}

static PyObject *MV_blade(PyObject *cls, PyObject *key)
{
    (void)cls;
    int i = blade_index(key);
    return i < 0 ? NULL : mv_new(ga_mv_blade(i));
}

static PyMethodDef MV_methods[] = {
    {"__array__", (PyCFunction)(void (*)(void))MV_array, METH_VARARGS | METH_KEYWORDS,
     "the 32 coefficients as a float64 array"},
    {"grade", (PyCFunction)MV_grade, METH_O, "grade(k): the grade-k part"},
    {"dual", (PyCFunction)MV_dual, METH_NOARGS, "X* = X I^-1, I = e12345"},
    {"undual", (PyCFunction)MV_undual, METH_NOARGS, "X I, the inverse of dual()"},
    {"reverse", (PyCFunction)MV_reverse, METH_NOARGS, "~X"},
    {"involute", (PyCFunction)MV_involute, METH_NOARGS, "the grade involution"},
    {"conjugate", (PyCFunction)MV_conjugate, METH_NOARGS, "the Clifford conjugate"},
    {"norm2", (PyCFunction)MV_norm2, METH_NOARGS, "<X ~X>_0"},
    {"inverse", (PyCFunction)MV_inverse, METH_NOARGS, "~X / (X ~X) of a versor or blade"},
    {"exp", (PyCFunction)MV_exp, METH_NOARGS,
     "exp of a bivector: a rigid-motion generator through the compact rotor, any other by ga_mv_exp"},
    {"log", (PyCFunction)MV_log, METH_NOARGS,
     "the principal log of a rotor: a rigid one through the compact rotor, any other by ga_mv_log"},
    {"dot", (PyCFunction)MV_dot, METH_O, "the fat dot a . b (ga_mv_dot; ganja.js's |)"},
    {"ip", (PyCFunction)MV_ip, METH_O, "Hestenes' inner product (ga_mv_ip; clifford's |)"},
    {"down", (PyCFunction)MV_down, METH_NOARGS, "the point x of a conformal point X = w F(x)"},
    {"up", (PyCFunction)MV_up, METH_O | METH_CLASS, "Multivector.up(x): the conformal point F(x)"},
    {"blade", (PyCFunction)MV_blade, METH_O | METH_CLASS, "Multivector.blade(i or name): a basis blade"},
    {NULL, NULL, 0, NULL}};

static PyTypeObject MVType = {
    PyVarObject_HEAD_INIT(NULL, 0).tp_name = "garotor.Multivector",
    .tp_basicsize = sizeof(MVObject),
    .tp_repr = (reprfunc)MV_repr,
    .tp_as_number = &MV_as_number,
    .tp_as_mapping = &MV_as_mapping,
    .tp_hash = PyObject_HashNotImplemented,
    .tp_flags = Py_TPFLAGS_DEFAULT,
    .tp_doc = "Multivector(c): a multivector of G(4,1) from its 32 coefficients in canonical order\n"
              "(1; e1..e5; e12..e45; e123..e345; e1234..e2345; e12345).\n"
              "* geometric, ^ outer, | left contraction, ~ reverse; numpy.asarray(m) gives the coefficients.",
    .tp_richcompare = MV_richcompare,
    .tp_methods = MV_methods,
    .tp_new = MV_new,
};

/* ---- the benchmark's reference: the same work as a plain C loop ----------- */

static double now_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* _c_loop(kind, x, path=None): seconds for the library calls that exp, log or
 * Path.sample make per element, in a plain C loop over a C-contiguous float64
 * x ((n, 6) twists, (n, 4, 4) motions, (n,) times) into a scratch buffer: no
 * numpy, no broadcasting, no kernel pointer (python/bench.py). */
static PyObject *py_c_loop(PyObject *self, PyObject *args)
{
    (void)self;
    const char *kind;
    PyObject *xo, *po = Py_None;
    if (!PyArg_ParseTuple(args, "sO|O:_c_loop", &kind, &xo, &po))
        return NULL;
    PyArrayObject *x = (PyArrayObject *)PyArray_FROM_OTF(xo, NPY_DOUBLE, NPY_ARRAY_IN_ARRAY);
    if (!x)
        return NULL;
    int k = strcmp(kind, "exp") == 0    ? 0
          : strcmp(kind, "log") == 0    ? 1
          : strcmp(kind, "sample") == 0 ? 2
                                        : -1;
    npy_intp n = PyArray_NDIM(x) ? PyArray_DIM(x, 0) : 0;
    npy_intp width = k == 0 ? 6 : k == 1 ? 16 : 1;
    if (k < 0 || PyArray_SIZE(x) != n * width || (k == 2 && !PyObject_TypeCheck(po, &PathType))) {
        Py_DECREF(x);
        PyErr_SetString(PyExc_ValueError,
                        "_c_loop: kind exp (n, 6), log (n, 4, 4) or sample (n,) with a Path");
        return NULL;
    }
    const ga_path *p = k == 2 ? &((PathObject *)po)->path : NULL;
    double *buf = PyMem_Malloc((size_t)(n ? n : 1) * 16 * sizeof *buf);
    if (!buf) {
        Py_DECREF(x);
        return PyErr_NoMemory();
    }
    const double *in = PyArray_DATA(x);
    const ga_group *g = &ga_group_cga;
    int st = GA_OK;
    memset(buf, 0, (size_t)(n ? n : 1) * 16 * sizeof *buf); /* the pages, before the clock starts */
    double t0 = now_seconds();
    Py_BEGIN_ALLOW_THREADS;
    for (npy_intp i = 0; i < n && st == GA_OK; i++) {
        double e[GA_GROUP_MAX_ELEM];
        if (k == 0) {
            st = g->exp(in + 6 * i, e);
            mat_put(g->to_mat4(e), buf + 16 * i);
        } else if (k == 1) {
            st = g->from_mat4(mat_get(in + 16 * i), e);
            if (st == GA_OK)
                st = g->log(e, buf + 16 * i);
        } else {
            st = ga_path_sample(p, GA_EVAL_DIRECT, 1.0, 1, in + i, e);
            mat_put(p->group->to_mat4(e), buf + 16 * i);
        }
    }
    Py_END_ALLOW_THREADS;
    double dt = now_seconds() - t0;
    PyMem_Free(buf);
    Py_DECREF(x);
    if (st != GA_OK)
        return mv_status("_c_loop", st);
    return PyFloat_FromDouble(dt);
}

/* ---- the module ---------------------------------------------------------- */

#define KW (METH_VARARGS | METH_KEYWORDS)
#define FN(f) (PyCFunction)(void (*)(void))(f)

static PyMethodDef module_methods[] = {
    {"exp", FN(py_exp), KW,
     "exp(xi, group='cga', *, out=None): twists (..., 6) -> rigid motions (..., 4, 4).\n"
     "group 'affine' takes (..., 4, 4) generators with last row zero."},
    {"log", FN(py_log), KW,
     "log(T, group='cga', *, out=None): rigid motions (..., 4, 4) -> principal twists (..., 6)\n"
     "(affine: the principal log as (..., 4, 4))."},
    {"compose", FN(py_compose), KW, "compose(A, B, group='cga', *, out=None): A B (B first), broadcast."},
    {"inverse", FN(py_inverse), KW, "inverse(T, group='cga', *, out=None): T^-1."},
    {"apply", FN(py_apply), KW,
     "apply(T, points, group='cga', *, out=None): T moves points (..., 3), broadcast."},
    {"from_quat", FN(py_from_quat), KW,
     "from_quat(q, t=None, *, out=None): unit quaternions (..., 4) in x y z w order and translations (..., "
     "3)\n"
     "-> (..., 4, 4): rotate by q, then translate by t."},
    {"to_quat", FN(py_to_quat), KW,
     "to_quat(T, *, out=None): the rotation of T as a quaternion x y z w, w >= 0."},
    {"from_pose", FN(py_from_pose), KW,
     "from_pose(poses, *, out=None): rows x y z qx qy qz qw (..., 7) -> (..., 4, 4)."},
    {"to_pose", FN(py_to_pose), KW,
     "to_pose(T, continuous=True, *, out=None): (..., 4, 4) -> rows x y z qx qy qz qw (..., 7);\n"
     "with continuous, the quaternion's sign follows the previous pose along the last leading axis."},
    {"to_dualquat", FN(py_to_dualquat), KW,
     "to_dualquat(T, *, out=None): (..., 4, 4) -> (..., 8): real x y z w, then dual x y z w."},
    {"from_dualquat", FN(py_from_dualquat), KW,
     "from_dualquat(d, *, out=None): unit dual quaternions (..., 8) -> (..., 4, 4)."},
    {"up", FN(py_up), KW, "up(x, *, out=None): points (..., 3) -> conformal points (..., 32)."},
    {"down", FN(py_down), KW, "down(X, *, out=None): conformal points (..., 32) -> points (..., 3)."},
    {"_c_loop", py_c_loop, METH_VARARGS,
     "_c_loop(kind, x, path=None): the benchmark's plain C loop (python/bench.py)."},
    {NULL, NULL, 0, NULL}};

static struct PyModuleDef garotor_module = {PyModuleDef_HEAD_INIT,
                                            "garotor",
                                            "garotor: rigid motions in conformal geometric algebra G(4,1), "
                                            "vectorised over numpy arrays (docs/python.md).",
                                            -1,
                                            module_methods,
                                            NULL,
                                            NULL,
                                            NULL,
                                            NULL};

PyMODINIT_FUNC PyInit_garotor(void)
{
    import_array();
    if (PyType_Ready(&PathType) < 0 || PyType_Ready(&MVType) < 0)
        return NULL;
    /* numpy defers to Multivector's own operators (2.0 * m, m * numpy.float64(2)) */
    if (PyDict_SetItemString(MVType.tp_dict, "__array_ufunc__", Py_None) < 0)
        return NULL;
    PyType_Modified(&MVType);
    PyObject *m = PyModule_Create(&garotor_module);
    if (!m)
        return NULL;
    garotor_error = PyErr_NewExceptionWithDoc("garotor.Error",
                                              "A garotor call met a bad element: a ValueError with the index "
                                              "of the first one (index, a tuple) and the "
                                              "library's status code (status) and text.",
                                              PyExc_ValueError, NULL);
    if (!garotor_error || PyModule_AddObjectRef(m, "Error", garotor_error) < 0 ||
        PyModule_AddObjectRef(m, "Path", (PyObject *)&PathType) < 0 ||
        PyModule_AddObjectRef(m, "Multivector", (PyObject *)&MVType) < 0 ||
        PyModule_AddStringConstant(m, "__version__", GAROTOR_VERSION_STRING) < 0)
        goto fail;
    for (int i = 1; i < 32; i++) {
        PyObject *b = mv_new(ga_mv_blade(i));
        if (!b || PyModule_AddObject(m, ga_blade_name(i), b) < 0) {
            Py_XDECREF(b);
            goto fail;
        }
    }
    PyObject *n = mv_new(ga_mv_n()), *nbar = mv_new(ga_mv_nbar());
    if (!n || PyModule_AddObject(m, "n", n) < 0) {
        Py_XDECREF(n);
        Py_XDECREF(nbar);
        goto fail;
    }
    if (!nbar || PyModule_AddObject(m, "nbar", nbar) < 0) {
        Py_XDECREF(nbar);
        goto fail;
    }
    return m;
fail:
    Py_DECREF(m);
    return NULL;
}
