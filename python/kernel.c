/* python/kernel.c: the vectorised loop every element-wise call of the module
 * runs (docs/python.md), how the module reads numbers, and its errors.
 *
 * The inputs are converted to C-contiguous float64 arrays (a copy only where
 * the input is not one already: other dtypes, object arrays, non-contiguous or
 * Fortran-ordered arrays), each with a fixed trailing "core" shape ((6,) for a
 * twist, (4, 4) for a motion, ...); their leading shapes broadcast as numpy's
 * do; one C loop over the broadcast elements calls a kernel per element, with
 * the GIL released. A NaN or an infinity in an element is refused
 * (GA_ERR_NOTFINITE, naming its position), and so is a result that is not
 * finite (GA_ERR_DOMAIN). Results go to a new array, or element by element
 * straight into `out=` in whatever layout it has, with no array of the
 * result's size in between; an error at element k leaves `out` with the
 * results of the elements before k. An error is a
 * garotor.Error (a ValueError) naming the index of the first bad element and
 * the library's status text (ga_status_string), with the attributes `index`
 * (a tuple) and `status` (the GA_ERR_* code).
 */
#include "module.h"

#include <math.h>
#include <stdint.h>

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
    gpy_raise_status_why(what, 0, NULL, 0, status, NULL);
    return NULL;
}

const char *gpy_repr_text(double x, char buf[32])
{
    char *r = PyOS_double_to_string(x, 'r', 0, Py_DTSF_ADD_DOT_0, NULL);
    snprintf(buf, 32, "%s", r ? r : "?");
    PyMem_Free(r);
    return buf;
}

/* ---- numbers in ---------------------------------------------------------- */

PyArrayObject *gpy_as_doubles(PyObject *obj)
{
    /* numpy reads a list's items with float() when float64 is asked for; an
       object array's cast to float64 reads its items with the same float(),
       but numpy calls that cast unsafe, so it is asked for by name */
    int flags = NPY_ARRAY_IN_ARRAY;
    if (PyArray_Check(obj) && PyArray_TYPE((PyArrayObject *)obj) == NPY_OBJECT)
        flags |= NPY_ARRAY_FORCECAST;
    return (PyArrayObject *)PyArray_FROM_OTF(obj, NPY_DOUBLE, flags);
}

/* The sign bit set if v[0..n-1] holds a NaN or an infinity: an integer test
 * of the exponent bits (all ones there), which sets the sign bit of
 * (bits & exponent) + its lowest bit; OR-ed over the numbers, with no
 * floating-point dependency chain, it vectorises. */
static inline uint64_t nonfinite_bits(const double *v, npy_intp n)
{
    uint64_t acc = 0;
    for (npy_intp i = 0; i < n; i++) {
        uint64_t u;
        memcpy(&u, v + i, sizeof u);
        acc |= (u & UINT64_C(0x7ff0000000000000)) + UINT64_C(0x0010000000000000);
    }
    return acc;
}

/* The sizes of the module's elements each with a loop of known length,
 * straight vector code: gpy_run_kernel checks every result. */
int gpy_all_finite(const double *v, npy_intp n)
{
    uint64_t acc;
    switch (n) {
    case 1: acc = nonfinite_bits(v, 1); break;
    case 3: acc = nonfinite_bits(v, 3); break;
    case 6: acc = nonfinite_bits(v, 6); break;
    case 7: acc = nonfinite_bits(v, 7); break;
    case 16: acc = nonfinite_bits(v, 16); break;
    default: acc = nonfinite_bits(v, n); break;
    }
    return !(acc >> 63);
}

npy_intp gpy_first_nonfinite(const double *v, npy_intp n)
{
    if (gpy_all_finite(v, n)) /* the common case: one test */
        return -1;
    for (npy_intp i = 0; i < n; i++)
        if (!isfinite(v[i]))
            return i;
    return -1;
}

void gpy_nonfinite_why(const char *name, PyArrayObject *a, npy_intp flat, char *why, size_t size)
{
    const double *v = PyArray_DATA(a);
    int nd = PyArray_NDIM(a);
    char num[32], pos[NPY_MAXDIMS * 24] = "";
    npy_intp idx[NPY_MAXDIMS], r = flat;
    for (int d = nd - 1; d >= 0; d--) {
        npy_intp n = PyArray_DIM(a, d);
        idx[d] = n ? r % n : 0;
        r = n ? r / n : 0;
    }
    for (int d = 0; d < nd; d++) {
        size_t len = strlen(pos);
        snprintf(pos + len, sizeof pos - len, "%s%ld", d ? ", " : "[", (long)idx[d]);
    }
    if (nd)
        strcat(pos, "]");
    snprintf(why, size, "%s%s is %s", name, pos, gpy_repr_text(v[flat], num));
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
    PyArrayObject *a = gpy_as_doubles(obj);
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

/* Check `out` (an array) against the result's shape dims[0..nd-1]: float64,
 * writeable, the same shape. 0, or -1 with an exception. */
static int check_out(const char *what, PyObject *out, int nd, npy_intp *dims)
{
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
    if (PyArray_NDIM(o) != nd || !PyArray_CompareLists(PyArray_DIMS(o), dims, nd)) {
        PyObject *want = PyArray_IntTupleFromIntp(nd, dims);
        PyObject *got = PyObject_GetAttrString(out, "shape");
        if (want && got)
            PyErr_Format(PyExc_ValueError, "%s: out has shape %S, the result %S", what, got, want);
        Py_XDECREF(want);
        Py_XDECREF(got);
        return -1;
    }
    return 0;
}

/* The bytes [lo, hi) an array's elements lie in. */
static void extent(PyArrayObject *a, char **lo, char **hi)
{
    char *l = PyArray_BYTES(a), *h = l + PyArray_ITEMSIZE(a);
    for (int d = 0; d < PyArray_NDIM(a); d++) {
        npy_intp n = PyArray_DIM(a, d), s = PyArray_STRIDE(a, d);
        if (n == 0) {
            *lo = *hi = l;
            return;
        }
        if (s > 0)
            h += (n - 1) * s;
        else
            l += (n - 1) * s;
    }
    *lo = l, *hi = h;
}

/* Where the results go: element k's osize doubles at its place in dst, an
 * array of the result's shape (a new one or `out`, in any layout). */
typedef struct {
    char *data;
    int nlead, ncore, plain; /* plain: C-contiguous, native byte order: one memcpy */
    int swap;                /* not in native byte order */
    npy_intp osize;
    npy_intp lead[NPY_MAXDIMS], lstride[NPY_MAXDIMS], core[2], cstride[2];
} sink;

static void sink_init(sink *s, PyArrayObject *dst, int nlead, const gpy_core *oc)
{
    s->data = PyArray_BYTES(dst);
    s->nlead = nlead;
    s->ncore = oc->ncore;
    s->swap = PyArray_ISBYTESWAPPED(dst);
    s->plain = PyArray_IS_C_CONTIGUOUS(dst) && !s->swap;
    s->osize = core_size(oc);
    for (int d = 0; d < nlead; d++) {
        s->lead[d] = PyArray_DIM(dst, d);
        s->lstride[d] = PyArray_STRIDE(dst, d);
    }
    for (int i = 0; i < oc->ncore; i++) {
        s->core[i] = oc->core[i];
        s->cstride[i] = PyArray_STRIDE(dst, nlead + i);
    }
}

static void put_double(char *p, double v, int swap)
{
    unsigned char b[sizeof v];
    memcpy(b, &v, sizeof v);
    if (swap)
        for (size_t i = 0; i < sizeof v / 2; i++) {
            unsigned char c = b[i];
            b[i] = b[sizeof v - 1 - i];
            b[sizeof v - 1 - i] = c;
        }
    memcpy(p, b, sizeof v);
}

/* With the GIL released: no Python API. */
static inline void sink_put(const sink *s, npy_intp k, const double *v)
{
    if (s->plain) { /* the common sizes as copies of known length: no call */
        char *p = s->data + (size_t)k * (size_t)s->osize * sizeof(double);
        switch (s->osize) {
        case 3: memcpy(p, v, 3 * sizeof *v); return;
        case 6: memcpy(p, v, 6 * sizeof *v); return;
        case 16: memcpy(p, v, 16 * sizeof *v); return;
        default: memcpy(p, v, (size_t)s->osize * sizeof *v); return;
        }
    }
    char *p = s->data;
    for (int d = s->nlead - 1; d >= 0; d--) {
        p += (k % s->lead[d]) * s->lstride[d];
        k /= s->lead[d];
    }
    npy_intp n0 = s->ncore > 0 ? s->core[0] : 1, n1 = s->ncore > 1 ? s->core[1] : 1;
    npy_intp s0 = s->ncore > 0 ? s->cstride[0] : 0, s1 = s->ncore > 1 ? s->cstride[1] : 0;
    for (npy_intp i = 0; i < n0; i++)
        for (npy_intp j = 0; j < n1; j++) put_double(p + i * s0 + j * s1, v[i * n1 + j], s->swap);
}

/* What went wrong at the first bad element. */
enum { BAD_KERNEL, BAD_INPUT, BAD_RESULT };

PyObject *gpy_run_kernel(gpy_kernel_call *kc, PyObject *const *objs, PyObject *out)
{
    PyArrayObject *a[GPY_MAX_IN] = {NULL};
    PyArrayObject *res = NULL;
    PyObject *ret = NULL;
    npy_intp step[GPY_MAX_IN][NPY_MAXDIMS]; /* doubles per leading index, 0 if broadcast */
    npy_intp csize[GPY_MAX_IN];
    int nl[GPY_MAX_IN];
    if (out == Py_None)
        out = NULL;
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
    npy_intp dims[NPY_MAXDIMS], total = 1;
    for (int d = 0; d < kc->nlead; d++) {
        dims[d] = kc->lead[d];
        total *= kc->lead[d];
    }
    for (int i = 0; i < kc->out.ncore; i++) dims[kc->nlead + i] = kc->out.core[i];
    int ndim = kc->nlead + kc->out.ncore;
    npy_intp osize = core_size(&kc->out);
    if (osize > GPY_MAX_OUT) { /* a kernel call that this file was not told of */
        PyErr_Format(PyExc_SystemError, "%s: a result element of %ld numbers", kc->what, (long)osize);
        goto done;
    }
    /* the results go straight to `out`, element by element, with no array of
       the result's size in between. An input that shares memory with out is
       read from a copy, unless it is out itself element for element (its
       element k is read whole before result k is written) */
    if (out) {
        if (check_out(kc->what, out, ndim, dims))
            goto done;
        char *olo, *ohi;
        extent((PyArrayObject *)out, &olo, &ohi);
        for (int j = 0; j < kc->nin; j++) {
            char *lo, *hi;
            extent(a[j], &lo, &hi);
            if (hi <= olo || ohi <= lo)
                continue;
            int same = PyArray_BYTES(a[j]) == PyArray_BYTES((PyArrayObject *)out) &&
                       PyArray_IS_C_CONTIGUOUS((PyArrayObject *)out) && nl[j] == kc->nlead &&
                       csize[j] == osize;
            for (int d = 0; same && d < nl[j]; d++) same = PyArray_DIM(a[j], d) == kc->lead[d];
            if (same)
                continue;
            PyArrayObject *c = (PyArrayObject *)PyArray_NewCopy(a[j], NPY_CORDER);
            if (!c)
                goto done;
            Py_SETREF(a[j], c);
        }
    } else if (!(res = (PyArrayObject *)PyArray_SimpleNew(ndim, dims, NPY_DOUBLE)))
        goto done;
    sink dst;
    sink_init(&dst, out ? (PyArrayObject *)out : res, kc->nlead, &kc->out);

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
    const double *base[GPY_MAX_IN], *p[GPY_MAX_IN];
    for (int j = 0; j < kc->nin; j++) base[j] = p[j] = (const double *)PyArray_DATA(a[j]);
    npy_intp bad = -1;
    int st = GA_OK, why_kind = BAD_KERNEL, badj = 0;
    const double *badin[GPY_MAX_IN];
    npy_intp idx[NPY_MAXDIMS] = {0};
    Py_BEGIN_ALLOW_THREADS;
    /* waited for with the GIL released, as every wait for a Path's lock is
       (path.c, path_locked) */
    if (kc->lock)
        PyThread_acquire_lock(kc->lock, WAIT_LOCK);
    /* a new result is written in place (discarded on an error); out= through
       a buffer, so that an element that fails leaves it untouched */
    double *direct = out ? NULL : (double *)PyArray_DATA(res);
    npy_intp k0 = 0;        /* the elements before k0 done by kc->many */
    int last = kc->nin - 1; /* the input of many elements */
    int whole1 = kc->many && (kc->nin == 1 || (kc->nin == 2 && nl[0] == 0)) && nl[last] == kc->nlead;
    for (int d = 0; whole1 && d < nl[last]; d++) whole1 = PyArray_DIM(a[last], d) == kc->lead[d];
    if (whole1) {
        double chunk[1536]; /* out=: results through here, checked before they are written */
        npy_intp room = (npy_intp)(sizeof chunk / sizeof *chunk) / (osize > 0 ? osize : 1);
        while (k0 < total) {
            npy_intp m = direct || total - k0 < room ? total - k0 : room;
            double *o = direct ? direct + k0 * osize : chunk;
            if (kc->many(kc->ctx, last ? base[0] : NULL, base[last] + k0 * csize[last], m, o) != GA_OK ||
                !gpy_all_finite(o, m * osize))
                break;
            if (!direct)
                for (npy_intp i = 0; i < m; i++) sink_put(&dst, k0 + i, o + i * osize);
            k0 += m;
        }
        if (k0 < total && !same) { /* the odometer at k0 */
            npy_intp rest = k0;
            for (int d = kc->nlead - 1; d >= 0; d--) {
                idx[d] = rest % kc->lead[d];
                rest /= kc->lead[d];
            }
            for (int j = 0; j < kc->nin; j++) {
                p[j] = base[j];
                for (int d = 0; d < kc->nlead; d++) p[j] += idx[d] * step[j][d];
            }
        }
    }
    for (npy_intp k = k0; k < total; k++) {
        const double *in[GPY_MAX_IN];
        double buf[GPY_MAX_OUT], *o = direct ? direct + k * osize : buf;
        for (int j = 0; j < kc->nin; j++) in[j] = same ? base[j] + k * csize[j] : p[j];
        /* a result that is not finite is refused; so is a NaN or an infinity
           in, the same for every call: a kernel's library calls refuse one
           (GA_ERR_NOTFINITE, or another status: a NaN time is outside a
           path's range) or pass it on to the result, so the inputs are looked
           at only where an element failed, and then that is the error */
        if ((st = kc->kernel(kc->ctx, in, o, k)) == GA_OK && !gpy_all_finite(o, osize))
            st = GA_ERR_DOMAIN, why_kind = BAD_RESULT;
        if (st != GA_OK) {
            for (int j = 0; j < kc->nin; j++)
                if (!gpy_all_finite(in[j], csize[j])) {
                    st = GA_ERR_NOTFINITE, why_kind = BAD_INPUT, badj = j;
                    break;
                }
            bad = k;
            memcpy(badin, in, sizeof in);
            break;
        }
        if (!direct)
            sink_put(&dst, k, o);
        if (!same) /* the odometer: advance the last leading index, carry left */
            for (int d = kc->nlead - 1; d >= 0; d--) {
                for (int j = 0; j < kc->nin; j++) p[j] += step[j][d];
                if (++idx[d] < kc->lead[d])
                    break;
                for (int j = 0; j < kc->nin; j++) p[j] -= step[j][d] * kc->lead[d];
                idx[d] = 0;
            }
    }
    if (kc->lock)
        PyThread_release_lock(kc->lock);
    Py_END_ALLOW_THREADS;
    if (bad >= 0) {
        char why[160] = "";
        if (why_kind == BAD_INPUT)
            gpy_nonfinite_why(kc->in[badj].name, a[badj],
                              (badin[badj] - base[badj]) + gpy_first_nonfinite(badin[badj], csize[badj]), why,
                              sizeof why);
        else if (why_kind == BAD_RESULT)
            snprintf(why, sizeof why, "the result would not be finite");
        else if (kc->explain)
            kc->explain(kc->ctx, badin, st, why, sizeof why);
        gpy_raise_status_why(kc->what, kc->nlead, kc->lead, bad, st, *why ? why : NULL);
        goto done;
    }
    if (out) {
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
