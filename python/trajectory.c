/* python/trajectory.c: trajectories compared and fitted (docs/python.md,
 * "Evaluating and fitting trajectories"): evaluate, ape, rpe, align and fit,
 * the numbers of `garotor eval` and `garotor fit` through the same library
 * calls (garotor/trajectory.h), so that the same poses give the same numbers
 * bit for bit. A trajectory is an (n, 8) array of TUM rows t x y z qx qy qz
 * qw (numpy.loadtxt of a TUM file). The table gpy_trajectory_methods is
 * added to the module by PyInit__garotor.
 */
#include "path.h"

/* ---- reading -------------------------------------------------------------- */

/* A trajectory read from an (n, 8) array or a pair (times, poses): the
 * stamps as given, the times relative to the reference stamp, the poses. */
typedef struct {
    double *t;        /* relative times, seconds */
    gpy_stamp *stamp; /* the stamps as given (whole nanoseconds with ns) */
    ga_mat4 *m;
    npy_intp n;
} traj;

/* How the times are read: time_unit 's' or 'ns' (ns), or None (guess: a
 * first stamp that is a whole number of 12 digits or more is refused, as
 * the tool refuses it without --time-unit); normalize=. */
typedef struct {
    int normalize, ns, guess;
} traj_opts;

static void traj_free(traj *tr)
{
    PyMem_Free(tr->t);
    PyMem_Free(tr->stamp);
    PyMem_Free(tr->m);
    tr->t = NULL;
    tr->stamp = NULL;
    tr->m = NULL;
}

/* time_unit= None, 's' or 'ns' into o; -1 with a ValueError */
static int traj_unit(const char *what, const char *unit, traj_opts *o)
{
    o->guess = unit == NULL;
    return gpy_path_unit(what, unit, &o->ns);
}

/* The tool's refusal of a first stamp that looks like epoch milliseconds,
 * microseconds or nanoseconds (tools/stamps.c, st_guess_unit), in Python's
 * words: why filled and 1, or 0 when s is not such a whole number. */
static int looks_like_ms_us_ns(gpy_stamp s, int isint, char *why, size_t size)
{
    gpy_stamp w = s;
    while (w.m && w.m % 10 == 0) w.m /= 10, w.e++;
    if (w.m == 0 || w.e < 0)
        return 0;
    int digits = w.e;
    for (uint64_t u = w.m < 0 ? (uint64_t)0 - (uint64_t)w.m : (uint64_t)w.m; u; u /= 10) digits++;
    if (digits < 12)
        return 0;
    char text[32];
    const char *unit = digits >= 18 ? "nanoseconds" : digits >= 15 ? "microseconds" : "milliseconds";
    snprintf(why, size, "the time %s looks like %s (a whole number of %d digits): %s",
             gpy_stamp_text(s, isint, text), unit, digits,
             digits >= 18 ? "pass time_unit='ns' (or time_unit='s' if it is seconds)"
                          : "time_unit takes 's' or 'ns': convert the times (or pass time_unit='s' if they "
                            "are seconds)");
    return 1;
}

/* obj as n >= min_rows rows: an (n, 8) array of TUM rows t x y z qx qy qz
 * qw, or a tuple (times (n,), poses (n, 7)), the times of an integer dtype
 * read exactly (python/path_times.c). Each stamp is read as Path reads it
 * (its exact decimal; whole nanoseconds with o->ns) and its time is
 * (stamp + shift - *ref) rounded once to seconds, as the tool's; *ref is
 * set to the first stamp unless have_ref. -1 with an exception naming the
 * array (name) and the row. */
static int traj_read(const char *what, const char *name, PyObject *obj, const traj_opts *o, int have_ref,
                     gpy_stamp *ref, gpy_stamp shift, npy_intp min_rows, traj *tr)
{
    char where[96], why[300], tname[64], pname[64];
    snprintf(where, sizeof where, "%s: %s", what, name);
    int pair = PyTuple_Check(obj) && PyTuple_GET_SIZE(obj) == 2;
    PyArrayObject *ta = NULL, *pa = NULL;
    int rc = -1;
    if (pair) {
        ta = gpy_path_times_in(PyTuple_GET_ITEM(obj, 0));
        pa = ta ? gpy_as_doubles(PyTuple_GET_ITEM(obj, 1)) : NULL;
    } else {
        pa = gpy_as_doubles(obj);
        ta = pa ? gpy_path_times_in(obj) : NULL;
    }
    if (!ta || !pa)
        goto done;
    int cols = pair ? 7 : 8;
    npy_intp n = PyArray_NDIM(pa) >= 1 ? PyArray_DIM(pa, 0) : 0;
    if (PyArray_NDIM(pa) != 2 || PyArray_DIM(pa, 1) != cols || n < min_rows ||
        (pair && (PyArray_NDIM(ta) != 1 || PyArray_DIM(ta, 0) != n))) {
        char shape[64] = "";
        for (PyArrayObject *x = pair ? ta : pa;; x = pa) {
            if (pair)
                snprintf(shape + strlen(shape), sizeof shape - strlen(shape), "%s(", x == ta ? "" : " and ");
            for (int d = 0; d < PyArray_NDIM(x) && d < 4; d++)
                snprintf(shape + strlen(shape), sizeof shape - strlen(shape), "%s%zd", d ? ", " : "",
                         (Py_ssize_t)PyArray_DIM(x, d));
            if (pair)
                snprintf(shape + strlen(shape), sizeof shape - strlen(shape), ")");
            if (!pair || x == pa)
                break;
        }
        PyErr_Format(PyExc_ValueError,
                     "%s must be an (n, 8) array of TUM rows t x y z qx qy qz qw (numpy.loadtxt of a TUM "
                     "file), or a tuple (times (n,), poses (n, 7)), with n >= %zd, not %s%s%s",
                     where, (Py_ssize_t)min_rows, pair ? "shapes " : "shape (", shape, pair ? "" : ")");
        goto done;
    }
    snprintf(tname, sizeof tname, pair ? "%s[0]" : "%s", name);
    snprintf(pname, sizeof pname, pair ? "%s[1]" : "%s", name);
    const double *v = PyArray_DATA(pa);
    tr->n = n;
    tr->t = PyMem_Malloc((size_t)(n ? n : 1) * sizeof *tr->t);
    tr->stamp = PyMem_Malloc((size_t)(n ? n : 1) * sizeof *tr->stamp);
    tr->m = PyMem_Malloc((size_t)(n ? n : 1) * sizeof *tr->m);
    if (!tr->t || !tr->stamp || !tr->m) {
        PyErr_NoMemory();
        goto done;
    }
    npy_intp bad = gpy_first_nonfinite(v, cols * n);
    if (bad >= 0) {
        gpy_nonfinite_why(pname, pa, bad, why, sizeof why);
        gpy_raise_status_why(where, 1, &n, bad / cols, GA_ERR_NOTFINITE, why);
        goto done;
    }
    int isint = PyArray_TYPE(ta) == NPY_INT64;
    for (npy_intp i = 0; i < n; i++) {
        const double *r = v + cols * i + (pair ? 0 : 1); /* x y z qx qy qz qw */
        npy_intp ti = pair ? i : 8 * i;
        char x[32], y[32], pos[48];
        snprintf(pos, sizeof pos, pair ? "%s[%zd]" : "%s[%zd, 0]", tname, (Py_ssize_t)i);
        int st = gpy_path_stamp_at(ta, ti, o->ns, &tr->stamp[i]);
        if (st == -1) {
            gpy_nonfinite_why(tname, ta, ti, why, sizeof why);
            gpy_raise_status_why(where, 1, &n, i, GA_ERR_NOTFINITE, why);
            goto done;
        }
        if (st) {
            snprintf(why, sizeof why, "%s = %s is not %s (time_unit='ns' takes whole nanoseconds)", pos,
                     gpy_repr_text(((const double *)PyArray_DATA(ta))[ti], x),
                     st == -2 ? "a whole number" : "within an int64");
            gpy_raise_status_why(where, 1, &n, i, GA_ERR_ARG, why);
            goto done;
        }
        if (i == 0 && o->guess && looks_like_ms_us_ns(tr->stamp[0], isint, why, sizeof why)) {
            gpy_raise_status_why(where, 1, &n, 0, GA_ERR_ARG, why);
            goto done;
        }
        if (i == 0 && !have_ref)
            *ref = tr->stamp[0];
        tr->t[i] = gpy_stamp_rel_plus(tr->stamp[i], 1, shift, *ref, o->ns);
        if (i > 0 && !(tr->t[i] > tr->t[i - 1])) {
            snprintf(why, sizeof why, "times must increase strictly: %s = %s after %s (%s)", pos,
                     gpy_stamp_text(tr->stamp[i], isint || o->ns, x),
                     gpy_stamp_text(tr->stamp[i - 1], isint || o->ns, y),
                     !(tr->t[i] < tr->t[i - 1]) ? "a repeated stamp" : "out of order: sort the rows by time");
            gpy_raise_status_why(where, 1, &n, i, GA_ERR_ARG, why);
            goto done;
        }
        st = ga_traj_pose_from_tum(r, o->normalize, &tr->m[i]);
        if (st != GA_OK) {
            snprintf(why, sizeof why,
                     "%s[%zd, %s] (qx qy qz qw): the quaternion has norm %s, not 1 (to 1e-9; normalize=True "
                     "accepts up to 1e-3)",
                     pname, (Py_ssize_t)i, pair ? "3:7" : "4:8",
                     gpy_repr_text(sqrt(r[3] * r[3] + r[4] * r[4] + r[5] * r[5] + r[6] * r[6]), x));
            gpy_raise_status_why(where, 1, &n, i, st, why);
            goto done;
        }
    }
    rc = 0;
done:
    Py_XDECREF(ta);
    Py_XDECREF(pa);
    return rc;
}

/* x y without overflow into *r: 1, else 0 */
static int mul_ok(int64_t x, int64_t y, int64_t *r)
{
    if (x && y && (x > INT64_MAX / (y < 0 ? -y : y) || x < -(INT64_MAX / (y < 0 ? -y : y))))
        return 0;
    *r = x * y;
    return 1;
}

/* 1 and *hn the spacing in whole nanoseconds when it is one and every knot
 * t0 + (j - 1) hn, j < nc, fits an int64; else 0 */
static int knots_ns(gpy_stamp t0, gpy_stamp h, size_t nc, int64_t *hn)
{
    if (h.e < 0 || h.e > 18)
        return 0;
    *hn = h.m;
    for (int e = 0; e < h.e; e++)
        if (!mul_ok(*hn, 10, hn))
            return 0;
    int64_t a, b;
    if (!mul_ok(-1, *hn, &a) || !mul_ok((int64_t)nc - 2, *hn, &b))
        return 0; /* the first and last knots' offsets from t0 */
    return !(t0.m > 0 && b > INT64_MAX - t0.m) && !(t0.m < 0 && a < INT64_MIN - t0.m) &&
           !(t0.m > 0 && a > INT64_MAX - t0.m) && !(t0.m < 0 && b < INT64_MIN - t0.m);
}

/* a number of seconds (an offset, a spacing) as an exact stamp in the
 * unit of the times: its shortest decimal, x 10^9 with ns */
static gpy_stamp seconds_stamp(double x, int ns)
{
    gpy_stamp s = {0, 0};
    if (gpy_stamp_of_double(x, 0, &s) == 0 && ns && s.m)
        s.e += 9;
    return s;
}

/* ---- results -------------------------------------------------------------- */

static PyObject *array_of(const double *v, npy_intp n0, npy_intp n1)
{
    npy_intp dims[2] = {n0, n1};
    PyObject *a = PyArray_SimpleNew(n1 ? 2 : 1, dims, NPY_DOUBLE);
    if (a && n0 * (n1 ? n1 : 1) > 0)
        memcpy(PyArray_DATA((PyArrayObject *)a), v, (size_t)(n0 * (n1 ? n1 : 1)) * sizeof *v);
    return a;
}

static PyObject *index_array(const size_t *v, npy_intp n)
{
    PyObject *a = PyArray_SimpleNew(1, &n, NPY_INT64);
    if (a)
        for (npy_intp i = 0; i < n; i++) ((npy_int64 *)PyArray_DATA((PyArrayObject *)a))[i] = (npy_int64)v[i];
    return a;
}

/* {"errors": err (as computed), "max": ..., "std": ...}; err is sorted after */
static PyObject *stats_dict(double *err, npy_intp n)
{
    PyObject *errors = array_of(err, n, 0);
    ga_traj_stats s;
    if (!errors || ga_traj_statistics(err, (size_t)n, &s) != GA_OK) {
        Py_XDECREF(errors);
        return errors ? gpy_status_error("statistics", GA_ERR_NOTFINITE) : NULL;
    }
    return Py_BuildValue("{s:N,s:d,s:d,s:d,s:d,s:d,s:d,s:d}", "errors", errors, "max", s.max, "mean", s.mean,
                         "median", s.median, "min", s.min, "rmse", s.rmse, "sse", s.sse, "std", s.std);
}

/* the statistics of the translation and rotation errors under their keys:
   0, or -1 with the Python error set */
static int put_stats(PyObject *res, const char *kt, double *et, const char *kr, double *er, npy_intp n)
{
    PyObject *a = stats_dict(et, n), *b = a ? stats_dict(er, n) : NULL;
    int rc = b && PyDict_SetItemString(res, kt, a) == 0 && PyDict_SetItemString(res, kr, b) == 0 ? 0 : -1;
    Py_XDECREF(a);
    Py_XDECREF(b);
    return rc;
}

/* ---- evaluate, ape, rpe ---------------------------------------------------- */

enum { WANT_APE = 1, WANT_RPE = 2 };

static PyObject *eval_call(const char *what, int want, PyObject *args, PyObject *kw)
{
    static char *kwlist[] = {"ref",       "est",   "max_diff",  "offset",    "align", "delta",
                             "all_pairs", "angle", "normalize", "time_unit", NULL};
    PyObject *ref_obj, *est_obj;
    double max_diff = 0.01, offset = 0.0;
    const char *align = "none", *angle = "deg";
    Py_ssize_t delta = 1;
    const char *time_unit = NULL;
    traj_opts o = {0, 0, 0};
    int all_pairs = 0;
    char fmt[64];
    snprintf(fmt, sizeof fmt, "OO|$ddsnpspz:%s", what);
    if (!PyArg_ParseTupleAndKeywords(args, kw, fmt, kwlist, &ref_obj, &est_obj, &max_diff, &offset, &align,
                                     &delta, &all_pairs, &angle, &o.normalize, &time_unit))
        return NULL;
    if (traj_unit(what, time_unit, &o))
        return NULL;
    char num[32], num2[32];
    if (!(max_diff >= 0) || !isfinite(max_diff))
        return PyErr_Format(PyExc_ValueError, "%s: max_diff must be a number of seconds >= 0, not %s", what,
                            gpy_repr_text(max_diff, num));
    if (!isfinite(offset))
        return PyErr_Format(PyExc_ValueError, "%s: offset must be a finite number of seconds, not %s", what,
                            gpy_repr_text(offset, num));
    int do_align = 0, with_scale = 0;
    if (strcmp(align, "se3") == 0)
        do_align = 1;
    else if (strcmp(align, "sim3") == 0)
        do_align = 1, with_scale = 1;
    else if (strcmp(align, "none") != 0)
        return PyErr_Format(PyExc_ValueError, "%s: align must be 'none', 'se3' or 'sim3', not '%s'", what,
                            align);
    if (strcmp(angle, "deg") != 0 && strcmp(angle, "rad") != 0)
        return PyErr_Format(PyExc_ValueError, "%s: angle must be 'deg' or 'rad', not '%s'", what, angle);
    if (delta < 1)
        return PyErr_Format(PyExc_ValueError, "%s: delta must be a whole number of poses >= 1, not %zd", what,
                            delta);
    double unit = strcmp(angle, "deg") == 0 ? 180.0 / 3.14159265358979323846 : 1.0;
    traj ref = {0}, est = {0};
    gpy_stamp t0 = {0, 0}, zero = {0, 0};
    size_t *ir = NULL, *ie = NULL;
    ga_mat4 *R = NULL, *E = NULL;
    double *e1 = NULL, *e2 = NULL;
    PyObject *res = NULL;
    if (traj_read(what, "ref", ref_obj, &o, 0, &t0, zero, 1, &ref) ||
        traj_read(what, "est", est_obj, &o, 1, &t0, seconds_stamp(offset, o.ns), 1, &est))
        goto done;
    size_t cap = (size_t)(ref.n < est.n ? ref.n : est.n), n = 0;
    ir = PyMem_Malloc(cap * sizeof *ir), ie = PyMem_Malloc(cap * sizeof *ie);
    R = PyMem_Malloc(cap * sizeof *R), E = PyMem_Malloc(cap * sizeof *E);
    e1 = PyMem_Malloc(cap * sizeof *e1), e2 = PyMem_Malloc(cap * sizeof *e2);
    if (!ir || !ie || !R || !E || !e1 || !e2) {
        PyErr_NoMemory();
        goto done;
    }
    int st = ga_traj_associate(ref.t, (size_t)ref.n, est.t, (size_t)est.n, max_diff, ir, ie, &n);
    if (st != GA_OK) {
        gpy_status_error(what, st);
        goto done;
    }
    if (n == 0) {
        char why[200];
        snprintf(why, sizeof why, "no pose of the %s is within max_diff %s s of a pose of the %s (offset %s)",
                 est.n > ref.n ? "reference" : "estimate", gpy_repr_text(max_diff, num),
                 est.n > ref.n ? "estimate" : "reference", gpy_repr_text(offset, num2));
        gpy_raise_status_why(what, 0, NULL, 0, GA_ERR_DOMAIN, why);
        goto done;
    }
    for (size_t k = 0; k < n; k++) R[k] = ref.m[ir[k]], E[k] = est.m[ie[k]];
    ga_mat4 T = ga_mat4_identity();
    double scale = 1.0;
    if (do_align) {
        st = ga_traj_align(R, E, n, with_scale, &T, &scale);
        if (st == GA_OK)
            st = ga_traj_transform(T, scale, E, n, E);
        if (st != GA_OK) {
            char why[160];
            snprintf(why, sizeof why,
                     "align='%s': the %zu associated positions do not fix an alignment (fewer than 3, or on "
                     "one line)",
                     align, n);
            gpy_raise_status_why(what, 0, NULL, 0, st, why);
            goto done;
        }
    }
    size_t npairs = ga_traj_rpe_count(n, (size_t)delta, all_pairs);
    if ((want & WANT_RPE) && npairs == 0) {
        char why[120];
        snprintf(why, sizeof why, "delta %zd leaves no pair among the %zu associated poses", delta, n);
        gpy_raise_status_why(what, 0, NULL, 0, GA_ERR_ARG, why);
        goto done;
    }
    res = Py_BuildValue("{s:n,s:N,s:N,s:d,s:N}", "pairs", (Py_ssize_t)n, "ref_index",
                        index_array(ir, (npy_intp)n), "est_index", index_array(ie, (npy_intp)n), "scale",
                        scale, "transform", array_of(T.m, 4, 4));
    if (!res)
        goto done;
    if (want & WANT_APE) {
        if ((st = ga_traj_ape(R, E, n, unit, e1, e2)) != GA_OK) {
            Py_CLEAR(res);
            gpy_status_error(what, st);
            goto done;
        }
        if (put_stats(res, "ape_trans", e1, "ape_rot", e2, (npy_intp)n) < 0) {
            Py_CLEAR(res);
            goto done;
        }
    }
    if (want & WANT_RPE) {
        if ((st = ga_traj_rpe(R, E, n, (size_t)delta, all_pairs, unit, e1, e2)) != GA_OK) {
            Py_CLEAR(res);
            gpy_status_error(what, st);
            goto done;
        }
        if (put_stats(res, "rpe_trans", e1, "rpe_rot", e2, (npy_intp)npairs) < 0) {
            Py_CLEAR(res);
            goto done;
        }
    }
done:
    traj_free(&ref);
    traj_free(&est);
    PyMem_Free(ir);
    PyMem_Free(ie);
    PyMem_Free(R);
    PyMem_Free(E);
    PyMem_Free(e1);
    PyMem_Free(e2);
    return res;
}

static PyObject *py_evaluate(PyObject *s, PyObject *a, PyObject *k)
{
    return (void)s, eval_call("evaluate", WANT_APE | WANT_RPE, a, k);
}
static PyObject *py_ape(PyObject *s, PyObject *a, PyObject *k)
{
    return (void)s, eval_call("ape", WANT_APE, a, k);
}
static PyObject *py_rpe(PyObject *s, PyObject *a, PyObject *k)
{
    return (void)s, eval_call("rpe", WANT_RPE, a, k);
}

/* ---- align ------------------------------------------------------------------ */

/* (n, 4, 4) poses or (n, 3) positions as poses; NULL with an exception */
static ga_mat4 *read_poses(const char *name, PyObject *obj, npy_intp *n)
{
    PyArrayObject *a = gpy_as_doubles(obj);
    if (!a)
        return NULL;
    int nd = PyArray_NDIM(a);
    int poses = nd == 3 && PyArray_DIM(a, 1) == 4 && PyArray_DIM(a, 2) == 4;
    if (!poses && !(nd == 2 && PyArray_DIM(a, 1) == 3)) {
        PyErr_Format(PyExc_ValueError, "align: %s must be (n, 4, 4) poses or (n, 3) positions", name);
        Py_DECREF(a);
        return NULL;
    }
    *n = PyArray_DIM(a, 0);
    const double *v = PyArray_DATA(a);
    ga_mat4 *m = PyMem_Malloc((size_t)(*n ? *n : 1) * sizeof *m);
    if (!m) {
        Py_DECREF(a);
        PyErr_NoMemory();
        return NULL;
    }
    for (npy_intp i = 0; i < *n; i++) {
        if (poses)
            m[i] = gpy_mat_get(v + 16 * i);
        else {
            m[i] = ga_mat4_identity();
            m[i].m[3] = v[3 * i], m[i].m[7] = v[3 * i + 1], m[i].m[11] = v[3 * i + 2];
        }
    }
    Py_DECREF(a);
    return m;
}

static PyObject *py_align(PyObject *self, PyObject *args, PyObject *kw)
{
    (void)self;
    static char *kwlist[] = {"ref", "est", "scale", NULL};
    PyObject *ro, *eo;
    int with_scale = 0;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "OO|$p:align", kwlist, &ro, &eo, &with_scale))
        return NULL;
    npy_intp nr = 0, ne = 0;
    ga_mat4 *R = read_poses("ref", ro, &nr), *E = R ? read_poses("est", eo, &ne) : NULL;
    PyObject *res = NULL;
    if (!R || !E)
        goto done;
    if (nr != ne) {
        PyErr_Format(PyExc_ValueError,
                     "align: ref and est must hold as many poses (associated pairs), not %zd and %zd",
                     (Py_ssize_t)nr, (Py_ssize_t)ne);
        goto done;
    }
    ga_mat4 T;
    double s;
    int st = nr == 0 ? GA_ERR_DOMAIN : ga_traj_align(R, E, (size_t)nr, with_scale, &T, &s);
    if (st != GA_OK) {
        gpy_raise_status_why("align", 0, NULL, 0, st,
                             st == GA_ERR_DOMAIN
                                 ? "the positions do not fix an alignment (fewer than 3, or on one "
                                   "line; with scale, est's positions all equal)"
                                 : NULL);
        goto done;
    }
    res = Py_BuildValue("(Nd)", array_of(T.m, 4, 4), s);
done:
    PyMem_Free(R);
    PyMem_Free(E);
    return res;
}

/* ---- fit -------------------------------------------------------------------- */

static PyObject *py_fit(PyObject *self, PyObject *args, PyObject *kw)
{
    (void)self;
    static char *kwlist[] = {"poses", "spacing", "smooth", "normalize", "time_unit", NULL};
    PyObject *obj;
    double h, smooth = 0.0;
    const char *time_unit = NULL;
    traj_opts o = {0, 0, 0};
    if (!PyArg_ParseTupleAndKeywords(args, kw, "Od|$dpz:fit", kwlist, &obj, &h, &smooth, &o.normalize,
                                     &time_unit))
        return NULL;
    if (traj_unit("fit", time_unit, &o))
        return NULL;
    char num[32];
    if (!(h > 0) || !isfinite(h))
        return PyErr_Format(PyExc_ValueError, "fit: spacing must be a number > 0, not %s",
                            gpy_repr_text(h, num));
    if (!(smooth >= 0) || !isfinite(smooth))
        return PyErr_Format(PyExc_ValueError, "fit: smooth must be a number >= 0, not %s",
                            gpy_repr_text(smooth, num));
    traj z = {0};
    gpy_stamp t0 = {0, 0}, zero = {0, 0};
    ga_mat4 *X = NULL, *F = NULL;
    double *res = NULL, *rows = NULL;
    void *work = NULL;
    PyObject *out = NULL;
    if (traj_read("fit", "poses", obj, &o, 0, &t0, zero, 4, &z))
        goto done;
    size_t nc;
    int st = ga_traj_fit_count(z.t[z.n - 1], h, &nc);
    if (st != GA_OK) {
        char why[120];
        snprintf(why, sizeof why, "spacing %s makes more than %d knot intervals over the keys' span",
                 gpy_repr_text(h, num), GA_TRAJ_FIT_MAX_SEGMENTS);
        gpy_raise_status_why("fit", 0, NULL, 0, st, why);
        goto done;
    }
    size_t ws = ga_traj_fit_workspace_size(nc);
    X = PyMem_Malloc(nc * sizeof *X), F = PyMem_Malloc((size_t)z.n * sizeof *F);
    res = PyMem_Malloc(2 * (size_t)z.n * sizeof *res);
    rows = PyMem_Malloc(8 * (nc > (size_t)z.n ? nc : (size_t)z.n) * sizeof *rows);
    work = ws ? PyMem_Malloc(ws) : NULL;
    if (!X || !F || !res || !rows || !work) {
        PyErr_NoMemory();
        goto done;
    }
    PyThreadState *ts = PyEval_SaveThread();
    st = ga_traj_fit_bspline(z.t, z.m, (size_t)z.n, h, smooth, work, ws, X, nc);
    if (st == GA_OK)
        st = ga_traj_fit_residuals(z.t, z.m, (size_t)z.n, X, nc, h, F, res);
    PyEval_RestoreThread(ts);
    if (st != GA_OK) {
        gpy_raise_status_why("fit", 0, NULL, 0, st,
                             st == GA_ERR_DOMAIN
                                 ? "the least-squares problem has no finite solution (a control "
                                   "pose with no key near it: try a larger spacing or smooth)"
                                 : NULL);
        goto done;
    }
    /* the rows: the keys' own stamps, the knots t_0 + (j - 1) spacing as
       exact decimals rounded once (the tool writes them exactly); the
       quaternion's sign continuous, as the tool writes them */
    ga_quat prev = {1, 0, 0, 0};
    for (npy_intp k = 0; k < z.n && st == GA_OK; k++) {
        rows[8 * k] = gpy_stamp_double(z.stamp[k]);
        st = ga_traj_pose_to_tum(F[k], &prev, rows + 8 * k + 1);
    }
    PyObject *fitted = array_of(rows, z.n, 8), *times = NULL, *ctimes = NULL;
    gpy_stamp hs = seconds_stamp(h, o.ns);
    prev = (ga_quat){1, 0, 0, 0};
    for (size_t j = 0; j < nc && st == GA_OK; j++) {
        rows[8 * j] = gpy_stamp_rel_plus(t0, (int64_t)j - 1, hs, zero, 0);
        st = ga_traj_pose_to_tum(X[j], &prev, rows + 8 * j + 1);
    }
    PyObject *controls = array_of(rows, (npy_intp)nc, 8), *resid = array_of(res, z.n, 2);
    if (o.ns && st == GA_OK) {
        /* the stamps as given, int64; the knots in whole nanoseconds where
           spacing is (9 decimals or fewer), else their nearest doubles */
        npy_intp nk = z.n, ncn = (npy_intp)nc;
        times = PyArray_SimpleNew(1, &nk, NPY_INT64);
        int64_t hn;
        int whole = knots_ns(t0, hs, nc, &hn);
        ctimes = PyArray_SimpleNew(1, &ncn, whole ? NPY_INT64 : NPY_DOUBLE);
        if (times && ctimes) {
            for (npy_intp k = 0; k < nk; k++)
                ((int64_t *)PyArray_DATA((PyArrayObject *)times))[k] = z.stamp[k].m;
            for (size_t j = 0; j < nc; j++) {
                if (whole)
                    ((int64_t *)PyArray_DATA((PyArrayObject *)ctimes))[j] = t0.m + ((int64_t)j - 1) * hn;
                else
                    ((double *)PyArray_DATA((PyArrayObject *)ctimes))[j] =
                        gpy_stamp_rel_plus(t0, (int64_t)j - 1, hs, zero, 0);
            }
        }
    }
    if (fitted && controls && resid && st == GA_OK && (!o.ns || (times && ctimes))) {
        out = Py_BuildValue("{s:N,s:N,s:N,s:d}", "fitted", fitted, "residuals", resid, "controls", controls,
                            "spacing", h);
        if (out && o.ns &&
            (PyDict_SetItemString(out, "times", times) || PyDict_SetItemString(out, "control_times", ctimes)))
            Py_CLEAR(out);
    } else {
        Py_XDECREF(fitted);
        Py_XDECREF(controls);
        Py_XDECREF(resid);
    }
    Py_XDECREF(times);
    Py_XDECREF(ctimes);
done:
    traj_free(&z);
    PyMem_Free(X);
    PyMem_Free(F);
    PyMem_Free(res);
    PyMem_Free(rows);
    PyMem_Free(work);
    return out;
}

#define KW (METH_VARARGS | METH_KEYWORDS)
#define FN(f) (PyCFunction)(void (*)(void))(f)
#define EVAL_ARGS                                                                                            \
    "(ref, est, *, max_diff=0.01, offset=0.0, align='none', delta=1, all_pairs=False, angle='deg', "         \
    "normalize=False, time_unit=None)"

PyMethodDef gpy_trajectory_methods[] = {
    {"evaluate", FN(py_evaluate), KW,
     "evaluate" EVAL_ARGS ": `garotor eval` in Python, bit for bit.\n"
     "ref, est: (n, 8) TUM rows t x y z qx qy qz qw, t increasing (numpy.loadtxt of a TUM file),\n"
     "or tuples (times (n,), poses (n, 7)), integer times read exactly; each stamp is read as its\n"
     "exact decimal (Path's times) and taken relative to ref's first (est's plus offset, in seconds).\n"
     "time_unit: 's', 'ns' (whole nanoseconds) or None (a first stamp that is a whole number of 12\n"
     "digits or more is an error, as without --time-unit). Associates by time as evo does,\n"
     "aligns with align 'se3' or 'sim3' (Umeyama), and returns a dict: pairs, ref_index, est_index,\n"
     "scale, transform (4, 4), and ape_trans, ape_rot, rpe_trans, rpe_rot, each a dict of errors\n"
     "(the array, pair by pair) and evo's max, mean, median, min, rmse, sse, std."},
    {"ape", FN(py_ape), KW,
     "ape" EVAL_ARGS ": evaluate's dict without the RPE (delta and all_pairs are not used)."},
    {"rpe", FN(py_rpe), KW, "rpe" EVAL_ARGS ": evaluate's dict without the APE."},
    {"align", FN(py_align), KW,
     "align(ref, est, *, scale=False): the Umeyama alignment of associated est onto ref, (n, 4, 4)\n"
     "poses or (n, 3) positions: (T (4, 4), s) minimising sum |s R p_i + t - q_i|^2 (s = 1 unless\n"
     "scale); est aligned is T @ [R_i, s t_i]."},
    {"fit", FN(py_fit), KW,
     "fit(poses, spacing, *, smooth=0.0, normalize=False, time_unit=None): `garotor fit` in Python,\n"
     "bit for bit. The least-squares cumulative cubic B-spline on SE(3), knots spacing (seconds) apart\n"
     "from the first stamp, through (n, 8) TUM rows or a tuple (times (n,), poses (n, 7)), n >= 4;\n"
     "time_unit as evaluate's. Returns a dict: fitted (n, 8) the spline at the keys' times,\n"
     "residuals (n, 2) distance and angle (rad) from the fitted pose to the key, controls (m, 8) the\n"
     "control poses at their knots t_0 + (j - 1) spacing, and spacing; with time_unit='ns' also\n"
     "times (int64, the stamps as given) and control_times (the knots, int64 nanoseconds where\n"
     "spacing is a whole number of them)."},
    {NULL, NULL, 0, NULL}};
