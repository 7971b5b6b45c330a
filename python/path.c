/* python/path.c: garotor.Path, a path through key poses (ga_path,
 * docs/python.md): its lock, its construction from numpy arrays (the
 * checks of times, poses and velocities), pickling and copying, and the
 * type's tables. Sampling and the derivatives are path_sample.c's, append
 * and the attributes path_keys.c's (path.h).
 */
#include "path.h"

#include <math.h>

/* ---- the lock ---------------------------------------------------------- */

/* the lock (path.h says why) */

void gpy_path_locked(gpy_PathObject *self, gpy_path_fn f, void *arg)
{
    if (PyThread_acquire_lock(self->lock, NOWAIT_LOCK)) {
        f(self, arg);
        PyThread_release_lock(self->lock);
        return;
    }
    Py_BEGIN_ALLOW_THREADS;
    PyThread_acquire_lock(self->lock, WAIT_LOCK);
    f(self, arg);
    PyThread_release_lock(self->lock);
    Py_END_ALLOW_THREADS;
}

/* ---- construction ---------------------------------------------------------- */

static PyObject *Path_new(PyTypeObject *type, PyObject *args, PyObject *kw)
{
    gpy_PathObject *self = (gpy_PathObject *)PyType_GenericNew(type, args, kw);
    if (self && !(self->lock = PyThread_allocate_lock())) {
        Py_DECREF(self);
        return PyErr_NoMemory();
    }
    return (PyObject *)self;
}

static void Path_dealloc(gpy_PathObject *self)
{
    PyMem_Free(self->work);
    PyMem_Free(self->vel);
    PyMem_Free(self->stamp);
    if (self->lock)
        PyThread_free_lock(self->lock);
    Py_TYPE(self)->tp_free((PyObject *)self);
}

/* velocities for lihao2 ((6,) or, affine, (4, 4)) and lihao3 ((n, 6) / (n, 4, 4)) into dim doubles each */
static int read_velocities(const ga_group *g, PyObject *obj, size_t count, double *vel)
{
    PyArrayObject *a = gpy_as_doubles(obj);
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
    npy_intp n = (npy_intp)count, per = PyArray_SIZE(a) / n;
    npy_intp bad = gpy_first_nonfinite(v, PyArray_SIZE(a));
    if (bad >= 0) {
        char why[160];
        gpy_nonfinite_why("velocities", a, bad, why, sizeof why);
        gpy_raise_status_why("Path: velocities", lihao3, &n, bad / per, GA_ERR_NOTFINITE, why);
        Py_DECREF(a);
        return -1;
    }
    for (size_t i = 0; i < count; i++) {
        ga_mat4 m = twist ? ga_twist_hat((ga_twist){{v[6 * i], v[6 * i + 1], v[6 * i + 2]},
                                                    {v[6 * i + 3], v[6 * i + 4], v[6 * i + 5]}})
                          : gpy_mat_get(v + 16 * i);
        int st = g->vee(m, vel + i * g->dim);
        if (st == GA_OK) {
            for (size_t d = 0; d < g->dim; d++)
                if (!isfinite(vel[i * g->dim + d]))
                    st = GA_ERR_NOTFINITE;
        }
        if (st != GA_OK) {
            gpy_raise_status("Path: velocities", lihao3, &n, (npy_intp)i, st);
            Py_DECREF(a);
            return -1;
        }
    }
    Py_DECREF(a);
    return 0;
}

/* Build self's path (Path_init, Path.__setstate__) in a new workspace of
 * wbytes: n keys at the relative times t, 4x4 matrices (mat4) or group
 * elements; *vel (nvel doubles, or NULL) becomes self's on success (kept
 * for pickling) and *vel NULL, as *stamp (the times as given, room for the
 * capacity's) does with ns. 0, or -1 with an exception. */
static int path_build(gpy_PathObject *self, const ga_group *g, ga_scheme scheme, size_t n, const double *t,
                      const void *keys, int mat4, double **vel, size_t nvel, gpy_stamp **stamp, int ns,
                      gpy_stamp ref, size_t wbytes)
{
    void *work = PyMem_Malloc(wbytes);
    if (!work) {
        PyErr_NoMemory();
        return -1;
    }
    ga_path path;
    int st;
    /* the build is C only on memory no other thread sees yet (a c2 path of
       many keys takes a while): without the GIL */
    Py_BEGIN_ALLOW_THREADS;
    st = mat4 ? ga_path_init_mat4(g, scheme, n, t, keys, *vel, work, wbytes, &path)
              : ga_path_init(g, scheme, n, t, keys, *vel, work, wbytes, &path);
    Py_END_ALLOW_THREADS;
    if (st != GA_OK) {
        PyErr_Format(gpy_error, "Path: cannot build the %s path: %s", ga_scheme_name(scheme),
                     ga_status_string(st));
        PyMem_Free(work);
        return -1;
    }
    self->path = path;
    self->work = work;
    self->group = g;
    self->scheme = scheme;
    self->vel = *vel;
    self->nvel = *vel ? nvel : 0;
    *vel = NULL;
    self->stamp = *stamp;
    self->ns = ns;
    self->ref = ref;
    *stamp = NULL;
    return 0;
}

static int Path_init(gpy_PathObject *self, PyObject *args, PyObject *kw)
{
    static char *kwlist[] = {"times",     "poses",     "scheme",  "group", "velocities", "capacity",
                             "time_unit", "normalize", "min_gap", "dedup", NULL};
    PyObject *tobj, *pobj, *vobj = Py_None, *cobj = Py_None, *gobj = Py_None;
    const char *sname = "screw", *gname = "cga", *unit = NULL;
    int ns, normalize = 0, dedup = 0;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "OO|ssO$OzpOp:Path", kwlist, &tobj, &pobj, &sname, &gname,
                                     &vobj, &cobj, &unit, &normalize, &gobj, &dedup) ||
        gpy_path_unit("Path", unit, &ns))
        return -1;
    if (self->work) {
        PyErr_SetString(PyExc_TypeError, "Path: already initialised");
        return -1;
    }
    const ga_group *g = gpy_group_arg("Path", gname);
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
    size_t nvel = 0;
    ga_mat4 *keys = NULL;
    gpy_stamp *stamp = NULL;
    double *rel = NULL;
    PyArrayObject *t = gpy_path_times_in(tobj);
    PyArrayObject *p = t ? gpy_as_doubles(pobj) : NULL;
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
    if (normalize && !g->rigid) { /* the tool's --normalize, as its message says */
        PyErr_SetString(PyExc_ValueError, "Path: normalize applies to the groups 'cga' and 'matrix'");
        goto done;
    }
    size_t min = ga_scheme_min_keys(scheme);
    if (n != 1 && ((size_t)n < min || (scheme == GA_SCHEME_QUADRATIC && n != 3))) { /* 1: constant */
        PyErr_Format(PyExc_ValueError, "Path: scheme '%s' needs one key or %s %zu, got %zd", sname,
                     scheme == GA_SCHEME_QUADRATIC ? "exactly" : "at least", min, (Py_ssize_t)n);
        goto done;
    }
    size_t wbytes = ga_path_workspace_size(g, scheme, (size_t)n), room = (size_t)n;
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
        if (wbytes == 0) { /* its size does not fit in a size_t (path.h) */
            PyErr_Format(PyExc_ValueError,
                         "Path: capacity %zd is too large: its workspace does not fit in memory", cap);
            goto done;
        }
        room = (size_t)cap;
    }
    const double *pv = PyArray_DATA(p);
    stamp = PyMem_Malloc(room * sizeof *stamp);
    rel = PyMem_Malloc((size_t)n * sizeof *rel);
    if (!stamp || !rel) {
        PyErr_NoMemory();
        goto done;
    }
    if (gpy_path_key_times("Path", t, ns, stamp, rel))
        goto done;
    npy_intp badp = gpy_first_nonfinite(pv, PyArray_SIZE(p));
    if (badp >= 0) {
        char why[160];
        gpy_nonfinite_why("poses", p, badp, why, sizeof why);
        gpy_raise_status_why("Path: poses", 1, &n, badp / (pose ? 7 : 16), GA_ERR_NOTFINITE, why);
        goto done;
    }
    keys = PyMem_Malloc((size_t)n * sizeof *keys);
    if (!keys) {
        PyErr_NoMemory();
        goto done;
    }
    npy_intp badk = -1;
    int kst = GA_OK;
    Py_BEGIN_ALLOW_THREADS; /* C only, on this call's arrays */
    for (npy_intp i = 0; i < n && badk < 0; i++) {
        double e[GA_GROUP_MAX_ELEM];
        int st = pose ? gpy_key_pose(pv + 7 * i, normalize, &keys[i]) : GA_OK;
        if (!pose)
            keys[i] = gpy_key_mat(g, pv + 16 * i, normalize);
        if (st == GA_OK)
            st = g->from_mat4(keys[i], e);
        if (st != GA_OK)
            badk = i, kst = st;
    }
    Py_END_ALLOW_THREADS;
    if (badk >= 0) {
        char why[200];
        gpy_key_why(g, pose ? pv + 7 * badk : pv + 16 * badk, pose, normalize, badk, why, sizeof why);
        gpy_raise_status_why("Path: poses", 1, &n, badk, kst, why[0] ? why : NULL);
        goto done;
    }
    /* keys closer than min_gap: an error, or with dedup merged (as the tool's
       --min-gap, --dedup, before its count of keys and bspline's grid) */
    gpy_stamp ref = stamp[0]; /* the first key's time as given, before any merge */
    if (gpy_path_near_dups(self, g, gobj, dedup, ns, ref, &n, stamp, rel, keys))
        goto done;
    if (n != 1 && ((size_t)n < min || (scheme == GA_SCHEME_QUADRATIC && n != 3))) {
        PyErr_Format(PyExc_ValueError, "Path: scheme '%s' needs one key or %s %zu, got %zd after dedup",
                     sname, scheme == GA_SCHEME_QUADRATIC ? "exactly" : "at least", min, (Py_ssize_t)n);
        goto done;
    }
    size_t bad = scheme == GA_SCHEME_BSPLINE ? ga_times_uneven((size_t)n, rel) : 0;
    if (bad) {
        PyErr_Format(
            PyExc_ValueError,
            "Path: scheme 'bspline' needs evenly spaced times (to 1e-9 of the spacing): index %zu is off "
            "the even grid of the first and last",
            bad);
        goto done;
    }
    if (vobj != Py_None) {
        if (scheme != GA_SCHEME_LIHAO2 && scheme != GA_SCHEME_LIHAO3) {
            PyErr_SetString(PyExc_ValueError,
                            "Path: velocities apply only to the schemes 'lihao2' and 'lihao3'");
            goto done;
        }
        size_t count = scheme == GA_SCHEME_LIHAO3 ? (size_t)n : 1;
        nvel = count * g->dim;
        vel = PyMem_Malloc(nvel * sizeof *vel);
        if (!vel) {
            PyErr_NoMemory();
            goto done;
        }
        if (read_velocities(g, vobj, count, vel))
            goto done;
    }
    rc = path_build(self, g, scheme, (size_t)n, rel, keys, 1, &vel, nvel, &stamp, ns, ref, wbytes);
    if (rc == 0) {
        self->merged = n < PyArray_DIM(t, 0);
        self->normalize = normalize; /* for the keys append adds */
    }
    if (rc == 0)
        rc = gpy_path_warn_growth(self, "Path");
done:
    PyMem_Free(keys);
    PyMem_Free(stamp);
    PyMem_Free(rel);
    PyMem_Free(vel);
    Py_XDECREF(t);
    Py_XDECREF(p);
    return rc;
}

int gpy_path_ready(gpy_PathObject *self)
{
    if (!self->work) {
        PyErr_SetString(PyExc_ValueError, "Path: not initialised");
        return 0;
    }
    return 1;
}

/* ---- pickling and copying ----------------------------------------------------- */

/* A path's state: the first n keys (as the group holds them) */
typedef struct {
    size_t n;
    double *keys;
} state_copy;

static void copy_state(gpy_PathObject *self, void *arg)
{
    state_copy *c = arg;
    const ga_path *p = &self->path;
    size_t ed = p->group->elem_size / sizeof(double);
    for (size_t i = 0; i < c->n; i++)
        memcpy(c->keys + i * ed, p->key + i * p->key_stride, ed * sizeof(double));
}

/* __reduce__: copyreg.__newobj__(Path), then __setstate__(state) with state
 * (group, scheme, times, keys, velocities, capacity, time_unit): the times
 * as given (Path.times: float64 seconds, or int64 nanoseconds with
 * time_unit 'ns'), the keys as the group
 * holds them ((n, elem_size / 8) doubles: a rotor's 8 coefficients on cga,
 * a 4x4 matrix on matrix and affine), the velocities given to the
 * constructor in the group's coordinates ((count, dim), or None). Built from
 * these by ga_path_init, the path is the one pickled, bit for bit: the same
 * keys, times, velocities and room, and an appended path equals the one built
 * from all its keys (ga_path_append). Nothing in it is a pointer. Three
 * items may follow: (the reference, the relative times) where dedup merged
 * keys, else None; (gap, median, auto), the min_gap append checks, where
 * there is one and room to append (else (0.0, 0.0, 0)); True where append
 * projects its keys (normalize=) and there is room to append. */
static PyObject *Path_reduce(gpy_PathObject *self, PyObject *unused)
{
    (void)unused;
    if (!gpy_path_ready(self))
        return NULL;
    const ga_group *g = self->group;
    size_t n;
    gpy_path_locked(self, gpy_path_read_n, &n); /* keys are only added: the first n stay */
    npy_intp kd[2] = {(npy_intp)n, (npy_intp)(g->elem_size / sizeof(double))};
    PyArrayObject *t = gpy_path_times_array(self, n);
    PyArrayObject *k = t ? (PyArrayObject *)PyArray_SimpleNew(2, kd, NPY_DOUBLE) : NULL;
    PyObject *v = Py_None, *copyreg = k ? PyImport_ImportModule("copyreg") : NULL;
    PyObject *newobj = copyreg ? PyObject_GetAttrString(copyreg, "__newobj__") : NULL;
    Py_INCREF(v);
    if (newobj && self->vel) {
        npy_intp vd[2] = {(npy_intp)(self->nvel / g->dim), (npy_intp)g->dim};
        Py_SETREF(v, PyArray_SimpleNew(2, vd, NPY_DOUBLE));
        if (v)
            memcpy(PyArray_DATA((PyArrayObject *)v), self->vel, self->nvel * sizeof(double));
    }
    PyObject *r = NULL;
    if (newobj && v) {
        state_copy sc = {n, PyArray_DATA(k)};
        gpy_path_locked(self, copy_state, &sc);
        /* where dedup merged keys, an eighth item: (the reference, the
           relative times), as a merged key's stamp may have more digits
           than its float in times */
        PyObject *ref = NULL;
        if (self->merged) {
            npy_intp nn = (npy_intp)n;
            PyObject *ra = PyArray_SimpleNew(1, &nn, NPY_DOUBLE);
            if (ra)
                memcpy(PyArray_DATA((PyArrayObject *)ra), self->path.t, n * sizeof(double));
            ref = ra ? Py_BuildValue("(NN)", gpy_stamp_value(self->ref, self->ns), ra) : NULL;
        }
        /* where append checks a gap (min_gap=), a ninth item: (the gap in
           relative seconds, the median spacing, 1 for 'auto'); where append
           projects its keys (normalize=), a tenth: True, the ninth then
           (0.0, 0.0, 0) where there is no gap; the eighth is None where no
           keys were merged and an item follows. Each only where there is
           room to append */
        int room = self->path.cap > n, gap = self->gap > 0.0 && room, norm = self->normalize && room;
        Py_ssize_t size = norm ? 10 : gap ? 9 : ref ? 8 : 7;
        PyObject *state = Py_BuildValue("(ssOOOns)", g->name, ga_scheme_name(self->scheme), (PyObject *)t,
                                        (PyObject *)k, v, (Py_ssize_t)self->path.cap, self->ns ? "ns" : "s");
        if (state && self->merged && !ref) { /* the merged keys' item failed */
            Py_CLEAR(state);
        } else if (state && size > 7) {
            PyObject *r8 = ref ? ref : Py_None, *more;
            double gv = gap ? self->gap : 0.0, gm = gap ? self->gap_median : 0.0;
            int ga = gap ? self->gap_auto : 0;
            if (size == 8)
                more = Py_BuildValue("(O)", r8);
            else if (size == 9)
                more = Py_BuildValue("(O(ddi))", r8, gv, gm, ga);
            else
                more = Py_BuildValue("(O(ddi)O)", r8, gv, gm, ga, Py_True);
            Py_SETREF(state, more ? PySequence_Concat(state, more) : NULL);
            Py_XDECREF(more);
        }
        Py_XDECREF(ref);
        if (state)
            r = Py_BuildValue("O(O)N", newobj, (PyObject *)Py_TYPE(self), state);
    }
    Py_XDECREF(t);
    Py_XDECREF(k);
    Py_XDECREF(v);
    Py_XDECREF(copyreg);
    Py_XDECREF(newobj);
    return r;
}

static PyObject *state_error(const char *what)
{
    PyErr_Format(PyExc_ValueError, "Path: state: %s", what);
    return NULL;
}

/* __setstate__(state): an uninitialised Path (copyreg.__newobj__) built
 * from the state __reduce__ gives, each part checked as the constructor
 * checks its arguments: the keys must be the group's elements (each read
 * back from its 4x4 matrix by the group, to 1e-9) */
static PyObject *Path_setstate(gpy_PathObject *self, PyObject *state)
{
    if (self->work) {
        PyErr_SetString(PyExc_TypeError, "Path: already initialised");
        return NULL;
    }
    /* a state of 6, of before time_unit: seconds */
    if (!PyTuple_Check(state) || PyTuple_GET_SIZE(state) < 6 || PyTuple_GET_SIZE(state) > 10 ||
        !PyUnicode_Check(PyTuple_GET_ITEM(state, 0)) || !PyUnicode_Check(PyTuple_GET_ITEM(state, 1)) ||
        (PyTuple_GET_SIZE(state) >= 7 && !PyUnicode_Check(PyTuple_GET_ITEM(state, 6))))
        return state_error("must be a tuple (group, scheme, times, keys, velocities, capacity, time_unit)");
    int ns = 0;
    if (PyTuple_GET_SIZE(state) >= 7) {
        const char *unit = PyUnicode_AsUTF8(PyTuple_GET_ITEM(state, 6));
        if (!unit || gpy_path_unit("Path: state", unit, &ns))
            return NULL;
    }
    const char *gname = PyUnicode_AsUTF8(PyTuple_GET_ITEM(state, 0));
    const char *sname = gname ? PyUnicode_AsUTF8(PyTuple_GET_ITEM(state, 1)) : NULL;
    if (!sname)
        return NULL;
    const ga_group *g = gpy_group_arg("Path: state", gname);
    ga_scheme scheme;
    if (!g)
        return NULL;
    if (ga_scheme_by_name(sname, &scheme) != GA_OK)
        return state_error("no such scheme");
    Py_ssize_t cap = PyNumber_AsSsize_t(PyTuple_GET_ITEM(state, 5), PyExc_OverflowError);
    if (cap == -1 && PyErr_Occurred())
        return NULL;
    PyObject *ret = NULL;
    double *vel = NULL;
    size_t nvel = 0, ed = g->elem_size / sizeof(double);
    gpy_stamp *stamp = NULL;
    double *rel = NULL;
    PyArrayObject *t = gpy_path_times_in(PyTuple_GET_ITEM(state, 2));
    PyArrayObject *k = t ? gpy_as_doubles(PyTuple_GET_ITEM(state, 3)) : NULL;
    PyArrayObject *v = NULL;
    if (!k)
        goto done;
    npy_intp n = PyArray_NDIM(t) == 1 ? PyArray_DIM(t, 0) : 0;
    if (n < 1) {
        state_error("times must be a 1-d array of one time or more");
        goto done;
    }
    if (PyArray_NDIM(k) != 2 || PyArray_DIM(k, 0) != n || PyArray_DIM(k, 1) != (npy_intp)ed) {
        PyErr_Format(PyExc_ValueError, "Path: state: keys must have shape (%zd, %zu)", (Py_ssize_t)n, ed);
        goto done;
    }
    if (cap < n || (cap > n && !ga_scheme_can_append(scheme))) {
        state_error("the capacity does not fit the keys and the scheme");
        goto done;
    }
    const double *kv = PyArray_DATA(k);
    for (npy_intp i = 0; i < n; i++) {
        double e[GA_GROUP_MAX_ELEM];
        int st = gpy_first_nonfinite(kv + i * ed, (npy_intp)ed) >= 0
                   ? GA_ERR_NOTFINITE
                   : g->from_mat4(g->to_mat4(kv + i * ed), e);
        if (st != GA_OK) {
            gpy_raise_status("Path: state: keys", 1, &n, i, st);
            goto done;
        }
    }
    if (PyTuple_GET_ITEM(state, 4) != Py_None) {
        npy_intp count = scheme == GA_SCHEME_LIHAO3 ? n : 1;
        if (!(v = gpy_as_doubles(PyTuple_GET_ITEM(state, 4))))
            goto done;
        if ((scheme != GA_SCHEME_LIHAO2 && scheme != GA_SCHEME_LIHAO3) || PyArray_NDIM(v) != 2 ||
            PyArray_DIM(v, 0) != count || PyArray_DIM(v, 1) != (npy_intp)g->dim) {
            state_error("the velocities do not fit the keys and the scheme");
            goto done;
        }
        nvel = (size_t)count * g->dim;
        if (gpy_first_nonfinite(PyArray_DATA(v), (npy_intp)nvel) >= 0) {
            state_error("the velocities are not finite");
            goto done;
        }
        if (!(vel = PyMem_Malloc(nvel * sizeof *vel))) {
            PyErr_NoMemory();
            goto done;
        }
        memcpy(vel, PyArray_DATA(v), nvel * sizeof *vel);
    }
    size_t wbytes = ga_path_workspace_size(g, scheme, (size_t)cap);
    if (wbytes == 0) {
        state_error("the capacity is too large, or the scheme is not defined on the group");
        goto done;
    }
    stamp = PyMem_Malloc((size_t)cap * sizeof *stamp);
    rel = PyMem_Malloc((size_t)n * sizeof *rel);
    if (!stamp || !rel) {
        PyErr_NoMemory();
        goto done;
    }
    if (gpy_path_key_times("Path: state", t, ns, stamp, rel))
        goto done;
    gpy_stamp ref = stamp[0];
    int merged = PyTuple_GET_SIZE(state) >= 8 && PyTuple_GET_ITEM(state, 7) != Py_None;
    double gap = 0.0, gap_median = 0.0;
    int gap_auto = 0;
    if (PyTuple_GET_SIZE(state) >= 9 &&
        (!PyArg_ParseTuple(PyTuple_GET_ITEM(state, 8), "ddi", &gap, &gap_median, &gap_auto) ||
         !(gap >= 0.0) || !isfinite(gap) || !isfinite(gap_median))) {
        if (!PyErr_Occurred() || PyErr_ExceptionMatches(PyExc_TypeError)) {
            PyErr_Clear();
            state_error("the gap's item must be (gap >= 0, median spacing, auto)");
        }
        goto done;
    }
    /* a tenth item: normalize= for the keys append adds (True or False) */
    int normalize = PyTuple_GET_SIZE(state) == 10 ? PyTuple_GET_ITEM(state, 9) == Py_True : 0;
    if (PyTuple_GET_SIZE(state) == 10 &&
        (!PyBool_Check(PyTuple_GET_ITEM(state, 9)) || (normalize && !g->rigid))) {
        state_error("the normalize item must be True or False (True: groups 'cga' and 'matrix')");
        goto done;
    }
    if (merged) { /* (reference, relative times) of a path whose keys dedup merged */
        PyObject *m = PyTuple_GET_ITEM(state, 7);
        PyArrayObject *ra = PyTuple_Check(m) && PyTuple_GET_SIZE(m) == 2
                              ? gpy_path_times_in(PyTuple_GET_ITEM(m, 0))
                              : NULL;
        PyArrayObject *rr = ra ? gpy_as_doubles(PyTuple_GET_ITEM(m, 1)) : NULL;
        int bad = !rr || PyArray_SIZE(ra) != 1 || PyArray_NDIM(ra) != 0 ||
                  gpy_path_stamp_at(ra, 0, ns, &ref) || PyArray_NDIM(rr) != 1 || PyArray_DIM(rr, 0) != n;
        for (npy_intp i = 0; !bad && i < n; i++) {
            rel[i] = ((const double *)PyArray_DATA(rr))[i];
            bad = !isfinite(rel[i]) || (i > 0 && !(rel[i] > rel[i - 1]));
        }
        Py_XDECREF(ra);
        Py_XDECREF(rr);
        if (bad) {
            if (!PyErr_Occurred())
                state_error("the merged keys' item must be (a time, n increasing relative times)");
            goto done;
        }
    }
    if (path_build(self, g, scheme, (size_t)n, rel, kv, 0, &vel, nvel, &stamp, ns, ref, wbytes) == 0) {
        self->merged = merged;
        self->gap = gap;
        self->gap_median = gap_median;
        self->gap_auto = gap_auto != 0;
        self->normalize = normalize;
        Py_INCREF(Py_None);
        ret = Py_None;
    }
done:
    PyMem_Free(stamp);
    PyMem_Free(rel);
    PyMem_Free(vel);
    Py_XDECREF(t);
    Py_XDECREF(k);
    Py_XDECREF(v);
    return ret;
}

static PyMethodDef Path_methods[] = {
    {"sample", (PyCFunction)(void (*)(void))gpy_path_sample, METH_VARARGS | METH_KEYWORDS,
     "sample(t, *, extrapolate=None, out=None): the poses at the times t (any shape ...), as (..., 4, 4) "
     "matrices; extrapolate: outside the range 'error' (None), 'hold', 'extend' or 'constant-velocity' "
     "(garotor interp --extrapolate)."},
    {"sample_pose", (PyCFunction)(void (*)(void))gpy_path_sample_pose, METH_VARARGS | METH_KEYWORDS,
     "sample_pose(t, *, extrapolate=None, out=None): the poses at the times t as (..., 7) rows x y z qx qy "
     "qz qw, from the "
     "group's rotation and translation (garotor interp --format pose, bit for bit); the quaternion's sign "
     "follows the previous sample's along t's last axis (cga and matrix)."},
    {"velocity", (PyCFunction)(void (*)(void))gpy_path_velocity, METH_VARARGS | METH_KEYWORDS,
     "velocity(t, *, frame='body', extrapolate=None, out=None): the velocity per unit time at the times t: "
     "(..., 6) twists "
     "(affine: (..., 4, 4)); frame 'body' A(t)^-1 dA/dt, 'spatial' dA/dt A(t)^-1, 'world' (rigid groups) "
     "the angular rate in world axes and dp/dt."},
    {"acceleration", (PyCFunction)(void (*)(void))gpy_path_acceleration, METH_VARARGS | METH_KEYWORDS,
     "acceleration(t, *, frame='body', extrapolate=None, out=None): the derivative of the velocity in that "
     "frame per unit "
     "time^2 at the times t: (..., 6) (affine: (..., 4, 4)); 'world': the angular acceleration in world axes "
     "and d2p/dt2."},
    {"jerk", (PyCFunction)(void (*)(void))gpy_path_jerk, METH_VARARGS | METH_KEYWORDS,
     "jerk(t, *, frame='body', extrapolate=None, out=None): the derivative of the acceleration in that frame "
     "per unit time^3 "
     "at the times t: (..., 6) (affine: (..., 4, 4)); 'world': d3p/dt3 for the position."},
    {"clip", (PyCFunction)(void (*)(void))gpy_path_clip, METH_VARARGS | METH_KEYWORDS,
     "clip(t): the times of t (read in C order) in the path's range, as given and in their order: the "
     "times `garotor interp --clip` keeps."},
    {"append", (PyCFunction)(void (*)(void))gpy_path_append, METH_VARARGS | METH_KEYWORDS,
     "append(t, pose, *, warn_growth=False): add a key after the last (schemes screw, bivector, lihao2, "
     "decoupled, bspline), building one new segment; the Path then equals one built from all the keys, bit "
     "for bit. Room: Path(..., capacity=m). The key is read as Path(...) reads its keys: with "
     "normalize=True projected onto the group. A key closer to the last than the Path's min_gap is an "
     "error (the tool's words; with 'auto' the gap of the keys given to Path), never merged (dedup= merges "
     "only those); warn_growth: the growth rule measured over every key, warned as Path(...) does."},
    {"__reduce__", (PyCFunction)Path_reduce, METH_NOARGS,
     "pickling and copying: (copyreg.__newobj__, (Path,), state), state = (group, scheme, times, keys, "
     "velocities, capacity, time_unit), then where they apply: the merged keys (dedup=), the gap append "
     "checks (min_gap=), and whether append normalizes its keys (normalize=)"},
    {"__setstate__", (PyCFunction)Path_setstate, METH_O,
     "build an uninitialised Path from the state __reduce__ gives (unpickling, copying)"},
    {NULL, NULL, 0, NULL}};

static PyGetSetDef Path_getset[] = {
    {"times", (getter)gpy_path_get_times, NULL, "the key times (a read-only copy)", NULL},
    {"capacity", (getter)gpy_path_get_capacity, NULL, "the keys the Path has room for (Path.append)", NULL},
    {"scheme", (getter)gpy_path_get_scheme, NULL, "the scheme's name", NULL},
    {"range", (getter)gpy_path_get_range, NULL,
     "(t0, t1), the times the path is defined on: the first and last key's (bspline: the second and the last "
     "but one's)",
     NULL},
    {"group", (getter)gpy_path_get_group, NULL, "the group's name", NULL},
    {NULL, NULL, NULL, NULL, NULL}};

PyTypeObject gpy_PathType = {
    PyVarObject_HEAD_INIT(NULL, 0).tp_name = "garotor.Path",
    .tp_basicsize = sizeof(gpy_PathObject),
    .tp_dealloc = (destructor)Path_dealloc,
    .tp_repr = (reprfunc)gpy_path_repr,
    .tp_flags = Py_TPFLAGS_DEFAULT,
    .tp_doc =
        "Path(times, poses, scheme='screw', group='cga', velocities=None, *, capacity=None, time_unit='s', "
        "normalize=False, min_gap='auto', dedup=False): a path through key poses.\n\n"
        "times: (n,) strictly increasing; poses: (n, 4, 4) matrices or (n, 7) rows x y z qx qy qz qw;\n"
        "scheme: screw, bivector, quadratic, smooth, lihao2, lihao3, decoupled, decoupled-c2, bspline, c2;\n"
        "group: cga, matrix, affine; velocities: lihao2 the first key's (6,), lihao3 one per key (n, 6);\n"
        "capacity: room for keys to come (append), for the schemes that can append;\n"
        "normalize: keys up to 1e-3 off a rigid motion projected onto it (garotor interp --normalize);\n"
        "min_gap: keys closer are an error, 'auto' (or None: the tool's default) 1% of the median spacing,\n"
        "0 none (--min-gap); dedup: such keys merged into their mean (--dedup).\n"
        "A path whose velocity breaks the growth rule warns (RuntimeWarning) as the tool does.",
    .tp_methods = Path_methods,
    .tp_getset = Path_getset,
    .tp_init = (initproc)Path_init,
    .tp_new = Path_new,
};
