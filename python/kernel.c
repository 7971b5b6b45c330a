/* python/kernel.c: the vectorised loop every element-wise call of the module
 * runs (docs/python.md), and the module's errors.
 *
 * The inputs are converted to C-contiguous float64 arrays (a copy only where
 * the input is not one already: other dtypes, non-contiguous or
 * Fortran-ordered arrays), each with a fixed trailing "core" shape ((6,) for a
 * twist, (4, 4) for a motion, ...); their leading shapes broadcast as numpy's
 * do; one C loop over the broadcast elements calls a kernel per element, with
 * the GIL released. The result goes to a new array; an `out=` array receives
 * it only when every element succeeded, so an error leaves `out` untouched.
 * An error is a garotor.Error (a ValueError) naming the index of the first
 * bad element and the library's status text (ga_status_string), with the
 * attributes `index` (a tuple) and `status` (the GA_ERR_* code).
 */
#include "module.h"

PyObject *gpy_error;

/* ---- errors ------------------------------------------------------------ */

void gpy_raise_status_why(const char *what, int nlead, const npy_intp *lead, npy_intp flat, int status,
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
    PyObject *exc = msg ? PyObject_CallOneArg(gpy_error, msg) : NULL;
    Py_XDECREF(msg);
    if (exc) {
        PyObject *st = PyLong_FromLong(status);
        if (st && PyObject_SetAttrString(exc, "index", idx) == 0 &&
            PyObject_SetAttrString(exc, "status", st) == 0)
            PyErr_SetObject(gpy_error, exc);
        Py_XDECREF(st);
        Py_DECREF(exc);
    }
    Py_DECREF(idx);
}

void gpy_raise_status(const char *what, int nlead, const npy_intp *lead, npy_intp flat, int status)
{
    gpy_raise_status_why(what, nlead, lead, flat, status, NULL);
}

PyObject *gpy_status_error(const char *what, int status)
{
    PyErr_Format(gpy_error, "%s: %s", what, ga_status_string(status));
    return NULL;
}

const char *gpy_repr_text(double x, char buf[32])
{
    char *r = PyOS_double_to_string(x, 'r', 0, Py_DTSF_ADD_DOT_0, NULL);
    snprintf(buf, 32, "%s", r ? r : "?");
    PyMem_Free(r);
    return buf;
}

/* ---- the vectorised loop ------------------------------------------------ */

static npy_intp core_size(const gpy_core *c)
{
    npy_intp s = 1;
    for (int i = 0; i < c->ncore; i++) s *= c->core[i];
    return s;
}

static void shape_text(char *buf, size_t size, const gpy_core *c)
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
static PyArrayObject *as_input(const gpy_kernel_call *kc, const gpy_core *c, PyObject *obj)
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

PyObject *gpy_run_kernel(gpy_kernel_call *kc, PyObject *const *objs, PyObject *out)
{
    PyArrayObject *a[GPY_MAX_IN] = {NULL};
    PyArrayObject *res = NULL;
    PyObject *ret = NULL;
    npy_intp step[GPY_MAX_IN][NPY_MAXDIMS]; /* doubles per leading index, 0 if broadcast */
    npy_intp csize[GPY_MAX_IN];
    int nl[GPY_MAX_IN];
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

    const double *base[GPY_MAX_IN], *p[GPY_MAX_IN];
    for (int j = 0; j < kc->nin; j++) base[j] = p[j] = (const double *)PyArray_DATA(a[j]);
    double *o = (double *)PyArray_DATA(res);
    npy_intp osize = core_size(&kc->out), bad = -1;
    int st = GA_OK;
    const double *badin[GPY_MAX_IN];
    npy_intp idx[NPY_MAXDIMS] = {0};
    Py_BEGIN_ALLOW_THREADS;
    /* waited for with the GIL released, as every wait for a Path's lock is
       (path.c, path_locked) */
    if (kc->lock)
        PyThread_acquire_lock(kc->lock, WAIT_LOCK);
    if (same) {
        for (npy_intp k = 0; k < total; k++) {
            const double *in[GPY_MAX_IN];
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
    if (kc->lock)
        PyThread_release_lock(kc->lock);
    Py_END_ALLOW_THREADS;
    if (bad >= 0) {
        char why[160] = "";
        if (kc->explain)
            kc->explain(kc->ctx, badin, st, why, sizeof why);
        gpy_raise_status_why(kc->what, kc->nlead, kc->lead, bad, st, *why ? why : NULL);
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

const ga_group *gpy_group_arg(const char *what, const char *name)
{
    const ga_group *g = ga_group_by_name(name ? name : "cga");
    if (!g)
        PyErr_Format(PyExc_ValueError, "%s: group must be 'cga', 'matrix' or 'affine', not '%s'", what, name);
    return g;
}
