/* python/path_keys.c: garotor.Path's keys after construction (path.h):
 * append, and the attributes times, capacity, scheme, range, group and the
 * repr.
 */
#include "path.h"

#include <math.h>

/* ---- append and the attributes ---------------------------------------------- */

void gpy_path_read_n(gpy_PathObject *self, void *n) { *(size_t *)n = self->path.n; }

/* the first n key times as given (keys are only added: they are still there) */
typedef struct {
    size_t n;
    int ns;
    void *t;
} times_copy;

static void copy_times(gpy_PathObject *self, void *arg)
{
    times_copy *c = arg;
    for (size_t i = 0; i < c->n; i++)
        if (c->ns)
            ((int64_t *)c->t)[i] = self->stamp[i].m;
        else
            ((double *)c->t)[i] = gpy_stamp_double(self->stamp[i]);
}

PyArrayObject *gpy_path_times_array(gpy_PathObject *self, size_t count)
{
    npy_intp n = (npy_intp)count;
    PyArrayObject *a = (PyArrayObject *)PyArray_SimpleNew(1, &n, self->ns ? NPY_INT64 : NPY_DOUBLE);
    if (!a)
        return NULL;
    times_copy tc = {count, self->ns, PyArray_DATA(a)};
    gpy_path_locked(self, copy_times, &tc);
    return a;
}

PyObject *gpy_path_get_times(gpy_PathObject *self, void *c)
{
    (void)c;
    if (!gpy_path_ready(self))
        return NULL;
    size_t count;
    gpy_path_locked(self, gpy_path_read_n, &count);
    PyArrayObject *a = gpy_path_times_array(self, count);
    if (a)
        PyArray_CLEARFLAGS(a, NPY_ARRAY_WRITEABLE);
    return (PyObject *)a;
}

PyObject *gpy_path_get_capacity(gpy_PathObject *self, void *c)
{
    (void)c;
    return gpy_path_ready(self) ? PyLong_FromSize_t(self->path.cap) : NULL;
}

/* One look at the path for append, under the lock: whether a key at t can
 * follow (n, the last key's time), and with commit, the key appended. */
typedef struct {
    double t;     /* relative to the first key's, in seconds */
    gpy_stamp at; /* t as given */
    ga_mat4 m;
    int commit;
    size_t n;    /* the keys, after the append where it is made */
    double last; /* the last key's time before it */
    gpy_stamp last_at;
    int refused;  /* the path is full or t is not after last */
    int close;    /* t is closer to last than min_gap (why says so) */
    ga_status st; /* of ga_path_append_mat4 */
    char why[400];
} append_op;

static void append_step(gpy_PathObject *self, void *arg)
{
    append_op *op = arg;
    op->n = self->path.n;
    op->last = self->path.t[op->n - 1];
    op->last_at = self->stamp[op->n - 1];
    op->refused = op->n >= self->path.cap || !isfinite(op->t) || !(op->t > op->last);
    op->close = !op->refused && gpy_path_append_gap(self, op->t, op->at, op->last, op->last_at, op->n - 1,
                                                    op->why, sizeof op->why);
    op->refused |= op->close;
    if (op->commit && !op->refused) {
        op->st = ga_path_append_mat4(&self->path, op->t, op->m);
        if (op->st == GA_OK)
            self->stamp[op->n] = op->at;
        op->n = self->path.n;
    }
}

static PyObject *append_refused(gpy_PathObject *self, const append_op *op)
{
    if (op->close) { /* the tool's near-duplicate keys, as Path(...) finds them */
        gpy_raise_status_why("Path.append", 0, NULL, 0, GA_ERR_ARG, op->why);
        return NULL;
    }
    if (op->n >= self->path.cap) {
        PyErr_Format(PyExc_ValueError,
                     "Path.append: the path is full (capacity %zu; give Path a larger capacity=)",
                     self->path.cap);
        return NULL;
    }
    char buf[128], a[32], b[32];
    snprintf(buf, sizeof buf, "t = %s must be finite and after the last key's time %s",
             self->ns ? gpy_stamp_text(op->at, 1, a)
                      : (snprintf(a, sizeof a, "%.17g", gpy_stamp_double(op->at)), a),
             self->ns ? gpy_stamp_text(op->last_at, 1, b)
                      : (snprintf(b, sizeof b, "%.17g", gpy_stamp_double(op->last_at)), b));
    PyErr_Format(PyExc_ValueError, "Path.append: %s", buf);
    return NULL;
}

/* append(t, pose): one key, a (4, 4) matrix or a (7,) row. The path is
 * looked at before the pose is read (its errors come first) and again when
 * the key is appended, as another thread may have appended in between. */
PyObject *gpy_path_append(gpy_PathObject *self, PyObject *args, PyObject *kw)
{
    static char *kwlist[] = {"t", "pose", "warn_growth", NULL};
    append_op op = {0};
    PyObject *tobj, *pobj;
    int warn_growth = 0;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "OO|$p:append", kwlist, &tobj, &pobj, &warn_growth) ||
        !gpy_path_ready(self))
        return NULL;
    if (!ga_scheme_can_append(self->scheme)) {
        PyErr_Format(PyExc_ValueError, "Path.append: scheme '%s' cannot append keys (build a new Path)",
                     ga_scheme_name(self->scheme));
        return NULL;
    }
    /* t: an integer exactly, anything else as a float */
    if (PyIndex_Check(tobj)) { /* an int, np.int64, ...: exactly */
        PyObject *i = PyNumber_Index(tobj);
        int over = 0;
        op.at.m = i ? PyLong_AsLongLongAndOverflow(i, &over) : -1;
        Py_XDECREF(i);
        if (!i)
            return NULL;
        if (over || (op.at.m == -1 && PyErr_Occurred())) {
            PyErr_Clear();
            PyErr_SetString(PyExc_ValueError, "Path.append: t is beyond an int64");
            return NULL;
        }
    } else {
        double t = PyFloat_AsDouble(tobj);
        if (t == -1.0 && PyErr_Occurred())
            return NULL;
        int sst = gpy_stamp_of_double(t, self->ns, &op.at);
        if (sst == -1) { /* as every call refuses a NaN or an infinity */
            char why[64], num[32];
            snprintf(why, sizeof why, "t is %s", gpy_repr_text(t, num));
            gpy_raise_status_why("Path.append", 0, NULL, 0, GA_ERR_NOTFINITE, why);
            return NULL;
        }
        if (sst) {
            char num[32];
            PyErr_Format(PyExc_ValueError,
                         "Path.append: t = %s is not %s (time_unit='ns' takes whole nanoseconds)",
                         gpy_repr_text(t, num), sst == -2 ? "a whole number" : "within an int64");
            return NULL;
        }
    }
    op.t = gpy_stamp_rel(op.at, self->ref, self->ns);
    gpy_path_locked(self, append_step, &op);
    if (op.refused)
        return append_refused(self, &op);
    PyArrayObject *p = gpy_as_doubles(pobj);
    if (!p)
        return NULL;
    int pose = PyArray_NDIM(p) == 1 && PyArray_DIM(p, 0) == 7 && self->group->rigid;
    int mat = PyArray_NDIM(p) == 2 && PyArray_DIM(p, 0) == 4 && PyArray_DIM(p, 1) == 4;
    int st = GA_OK;
    if (!pose && !mat) {
        PyErr_SetString(PyExc_ValueError, self->group->rigid
                                              ? "Path.append: pose must have shape (4, 4) or (7,)"
                                              : "Path.append: pose must have shape (4, 4)");
        Py_DECREF(p);
        return NULL;
    }
    npy_intp bad = gpy_first_nonfinite(PyArray_DATA(p), PyArray_SIZE(p));
    if (bad >= 0) {
        char why[160];
        gpy_nonfinite_why("pose", p, bad, why, sizeof why);
        gpy_raise_status_why("Path.append", 0, NULL, 0, GA_ERR_NOTFINITE, why);
        Py_DECREF(p);
        return NULL;
    }
    /* the key as Path(...) reads its keys, normalize= included */
    if (pose)
        st = gpy_key_pose(PyArray_DATA(p), self->normalize, &op.m);
    else
        op.m = gpy_key_mat(self->group, PyArray_DATA(p), self->normalize);
    if (st == GA_OK) {
        op.commit = 1;
        gpy_path_locked(self, append_step, &op);
        if (op.refused) {
            Py_DECREF(p);
            return append_refused(self, &op);
        }
        st = op.st;
    }
    if (st == GA_ERR_ARG && self->scheme == GA_SCHEME_BSPLINE) {
        PyErr_Format(PyExc_ValueError, "Path.append: scheme 'bspline' takes a key %s",
                     op.n < 4 ? "only after 4 keys or more" : "only at evenly spaced times");
        Py_DECREF(p);
        return NULL;
    }
    if (st != GA_OK) {
        /* a key off the group: why, in Path(...)'s words (naming normalize=) */
        char why[200];
        gpy_key_why(self->group, PyArray_DATA(p), pose, self->normalize, -1, why, sizeof why);
        if (why[0])
            gpy_raise_status_why("Path.append", 0, NULL, 0, st, why);
        else
            PyErr_Format(st == GA_ERR_DOMAIN ? gpy_error : PyExc_ValueError, "Path.append: %s",
                         ga_status_string(st));
        Py_DECREF(p);
        return NULL;
    }
    Py_DECREF(p);
    /* warn_growth: the growth rule over every key, as Path(...) measures it
       (a pass over all the keys: opt-in); the key stays appended */
    if (warn_growth && gpy_path_warn_growth(self, "Path.append") < 0)
        return NULL;
    Py_RETURN_NONE;
}
PyObject *gpy_path_get_scheme(gpy_PathObject *self, void *c)
{
    (void)c;
    return gpy_path_ready(self) ? PyUnicode_FromString(ga_scheme_name(self->scheme)) : NULL;
}
/* the path's range, read under the lock */
typedef struct {
    int range_status;
    double t0, t1;
    gpy_stamp at0, at1; /* as given: the keys' at t0 and t1 */
} range_read;

static void read_range(gpy_PathObject *self, void *arg)
{
    range_read *r = arg;
    r->range_status = ga_path_range(&self->path, &r->t0, &r->t1);
    if (r->range_status == GA_OK) {
        r->at0 = self->stamp[gpy_path_key_index(&self->path, r->t0)];
        r->at1 = self->stamp[gpy_path_key_index(&self->path, r->t1)];
    }
}

PyObject *gpy_path_get_range(gpy_PathObject *self, void *c)
{
    (void)c;
    if (!gpy_path_ready(self))
        return NULL;
    range_read r = {GA_OK, 0.0, 0.0, {0, 0}, {0, 0}};
    gpy_path_locked(self, read_range, &r);
    if (r.range_status != GA_OK) {
        PyErr_SetString(PyExc_ValueError, ga_status_string(r.range_status));
        return NULL;
    }
    PyObject *a = gpy_stamp_value(r.at0, self->ns), *b = a ? gpy_stamp_value(r.at1, self->ns) : NULL;
    PyObject *res = b ? PyTuple_Pack(2, a, b) : NULL;
    Py_XDECREF(a);
    Py_XDECREF(b);
    return res;
}
PyObject *gpy_path_get_group(gpy_PathObject *self, void *c)
{
    (void)c;
    return gpy_path_ready(self) ? PyUnicode_FromString(self->group->name) : NULL;
}

PyObject *gpy_path_repr(gpy_PathObject *self)
{
    if (!self->work)
        return PyUnicode_FromString("<garotor.Path (not initialised)>");
    size_t n;
    gpy_path_locked(self, gpy_path_read_n, &n);
    return PyUnicode_FromFormat("<garotor.Path: %s on %s, %zu keys>", ga_scheme_name(self->scheme),
                                self->group->name, n);
}
