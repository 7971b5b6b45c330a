/* python/path_opts.c: garotor.Path's options that `garotor interp` has
 * (path.h, docs/python.md "Path options"): keys near the group projected
 * (normalize=, the tool's --normalize), the growth rule's warning, and clip
 * (the tool's --clip). Each decides with the library's code the tool calls,
 * so both give the same keys, words and times.
 */
#include "path.h"

#include <math.h>

int gpy_key_pose(const double *v, int normalize, ga_mat4 *m)
{
    /* normalize: ga_quat_normalize to GA_SE3_NORMALIZE_TOL, then the pose,
       as the tool's --format pose --normalize */
    return normalize ? ga_traj_pose_from_tum(v, 1, m) : gpy_pose_to_mat(v, m);
}

ga_mat4 gpy_key_mat(const ga_group *g, const double *v, int normalize)
{
    ga_mat4 m = gpy_mat_get(v), r;
    /* the tool's --normalize on a matrix: projected where within the
       tolerance; farther, left for the group to refuse */
    if (normalize && g->rigid && ga_se3_normalize(m, GA_SE3_NORMALIZE_TOL, &r) == GA_OK)
        return r;
    return m;
}

void gpy_key_why(const ga_group *g, const double *v, int pose, int normalize, npy_intp i, char *why,
                 size_t size)
{
    char x[32], name[32] = "pose";
    why[0] = '\0';
    if (gpy_first_nonfinite(v, pose ? 7 : 16) >= 0)
        return;
    if (i >= 0) /* Path(...)'s key i; else append's key */
        snprintf(name, sizeof name, "poses[%zd%s", (Py_ssize_t)i, pose ? ", " : "]");
    else if (pose)
        snprintf(name, sizeof name, "pose[");
    if (pose) {
        double norm = sqrt(v[3] * v[3] + v[4] * v[4] + v[5] * v[5] + v[6] * v[6]);
        if (fabs(norm - 1.0) <= 1e-9)
            return;
        if (normalize)
            snprintf(why, size,
                     "%s3:7] (qx qy qz qw): the quaternion has norm %s, farther from 1 than "
                     "normalize=True accepts (1e-3)",
                     name, gpy_repr_text(norm, x));
        else
            snprintf(why, size,
                     "%s3:7] (qx qy qz qw): the quaternion has norm %s, not 1 (to 1e-9; "
                     "normalize=True accepts up to 1e-3)",
                     name, gpy_repr_text(norm, x));
        return;
    }
    ga_mat4 m = gpy_mat_get(v), r;
    if (normalize || !g->rigid || ga_se3_normalize(m, GA_SE3_NORMALIZE_TOL, &r) != GA_OK)
        return;
    double off = 0.0;
    for (int k = 0; k < 16; k++) off = fmax(off, fabs(m.m[k] - r.m[k]));
    snprintf(why, size,
             "%s is not a rigid motion to 1e-9 (it is %.3g from the nearest one); normalize=True "
             "accepts up to 1e-3",
             name, off);
}

/* the growth rule measured under the lock (append may run in another
 * thread): found, and the warning's text */
typedef struct {
    const char *what;
    int found;
    char msg[512];
} growth_read;

static void measure_growth(gpy_PathObject *self, void *arg)
{
    growth_read *r = arg;
    ga_path_growth gr;
    ga_path_growth_words w;
    const ga_path *p = &self->path;
    r->found = ga_path_measure_growth(p, &gr) == GA_OK && ga_path_growth_describe(p, &gr, &w) == GA_OK;
    if (!r->found)
        return;
    char a[32], b[32], k[32];
    /* the tool's words (cmd_interp.c), the keys named by index */
    snprintf(r->msg, sizeof r->msg,
             "%s: the %s path's velocity grows past %g times the fastest chord on the segment t = %s to %s "
             "(indices %zu to %zu), up to %s times at t = %s; %s (docs/schemes.md)",
             r->what, ga_scheme_name(p->scheme), GA_PATH_GROWTH_MAX,
             gpy_stamp_text(self->stamp[w.a], self->ns, a), gpy_stamp_text(self->stamp[w.b], self->ns, b),
             w.a, w.b, w.ratio, gpy_stamp_text(self->stamp[gr.key], self->ns, k), w.advice);
}

int gpy_path_warn_growth(gpy_PathObject *self, const char *what)
{
    growth_read r = {what, 0, ""};
    gpy_path_locked(self, measure_growth, &r);
    return r.found && PyErr_WarnEx(PyExc_RuntimeWarning, r.msg, 1) < 0 ? -1 : 0;
}

/* the path's range, under the lock */
typedef struct {
    int st;
    double t0, t1;
} range_read;

static void read_range(gpy_PathObject *self, void *arg)
{
    range_read *r = arg;
    r->st = ga_path_range(&self->path, &r->t0, &r->t1);
}

PyObject *gpy_path_clip(gpy_PathObject *self, PyObject *args, PyObject *kw)
{
    static char *kwlist[] = {"t", NULL};
    PyObject *t;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "O:clip", kwlist, &t) || !gpy_path_ready(self))
        return NULL;
    PyArrayObject *given;
    PyArrayObject *rel = (PyArrayObject *)gpy_path_rel_times(self, t, &given);
    if (!rel)
        return NULL;
    PyArrayObject *src = given ? given : rel; /* the times as given */
    PyObject *r = NULL;
    npy_intp n = PyArray_SIZE(rel), m = 0;
    const double *x = PyArray_DATA(rel);
    npy_intp bad = gpy_first_nonfinite(x, n);
    range_read rr;
    if (bad >= 0) {
        char why[160];
        gpy_nonfinite_why("t", src, bad, why, sizeof why);
        gpy_raise_status_why("Path.clip", 1, &n, bad, GA_ERR_NOTFINITE, why);
        goto done;
    }
    gpy_path_locked(self, read_range, &rr);
    if (rr.st != GA_OK) {
        gpy_status_error("Path.clip", rr.st);
        goto done;
    }
    /* the tool's --clip: a time kept where its relative time is in the
       range, t0 <= t <= t1, in the order given */
    for (npy_intp i = 0; i < n; i++) m += x[i] >= rr.t0 && x[i] <= rr.t1;
    r = PyArray_SimpleNew(1, &m, PyArray_TYPE(src));
    if (!r)
        goto done;
    size_t size = (size_t)PyArray_ITEMSIZE(src);
    const char *from = PyArray_DATA(src);
    char *to = PyArray_DATA((PyArrayObject *)r);
    for (npy_intp i = 0, j = 0; i < n; i++)
        if (x[i] >= rr.t0 && x[i] <= rr.t1)
            memcpy(to + size * (size_t)j++, from + size * (size_t)i, size);
done:
    Py_DECREF(rel);
    Py_XDECREF(given);
    return r;
}

/* a + b exactly as a stamp, where it fits (an int64 at the smaller
 * exponent): 0, else -1 */
static int stamp_add(gpy_stamp a, gpy_stamp b, gpy_stamp *out)
{
    int at = a.e < b.e ? a.e : b.e;
    int64_t ma = a.m, mb = b.m;
    for (int e = a.e; e > at; e--)
        if (ma > INT64_MAX / 10 || ma < INT64_MIN / 10)
            return -1;
        else
            ma *= 10;
    for (int e = b.e; e > at; e--)
        if (mb > INT64_MAX / 10 || mb < INT64_MIN / 10)
            return -1;
        else
            mb *= 10;
    if ((mb > 0 && ma > INT64_MAX - mb) || (mb < 0 && ma < INT64_MIN - mb))
        return -1;
    out->m = ma + mb;
    out->e = at;
    return 0;
}

/* min_gap=: 'auto' or None (the tool's default: 1% of the median
 * spacing), or a number >= 0 in the keys' unit (0: no check). *check 0:
 * none; *dflt 1: the default. -1 with a ValueError. */
static int min_gap_arg(PyObject *obj, int ns, int *check, int *dflt, double *gap)
{
    *check = *dflt = 0;
    *gap = 0.0;
    if (obj == Py_None) {
        *check = *dflt = 1;
        return 0;
    }
    if (PyUnicode_Check(obj)) {
        const char *s = PyUnicode_AsUTF8(obj);
        if (s && strcmp(s, "auto") == 0) {
            *check = *dflt = 1;
            return 0;
        }
    } else {
        double x = PyFloat_AsDouble(obj);
        if (x == -1.0 && PyErr_Occurred())
            PyErr_Clear();
        else if (x >= 0.0 && isfinite(x)) {
            *check = x > 0.0;
            *gap = x * (ns ? 1e-9 : 1.0);
            return 0;
        }
    }
    PyErr_SetString(PyExc_ValueError, "Path: min_gap must be None, 'auto' or a number >= 0");
    return -1;
}

/* the tool's words for key b closer than gap to key a (interp_read.c), the
 * keys named by index, and the advice */
static void gap_words(double gap, double median, int dflt, int ns, gpy_stamp at_b, double rel_b,
                      gpy_stamp at_a, double rel_a, size_t a, const char *advice, char *why, size_t size)
{
    const double unit = ns ? 1e-9 : 1.0;
    const char *u = ns ? "ns" : "s";
    char x[32], y[32], d[96] = "";
    if (dflt)
        snprintf(d, sizeof d, " (1%% of the median spacing, %.6g %s)", median / unit, u);
    snprintf(
        why, size,
        "key at t = %s is %.3g %s after the key at t = %s (index %zu), closer than min_gap %.6g %s%s: %s",
        gpy_stamp_text(at_b, ns, x), (rel_b - rel_a) / unit, u, gpy_stamp_text(at_a, ns, y), a, gap / unit, u,
        d, advice);
}

int gpy_path_append_gap(const gpy_PathObject *self, double t, gpy_stamp at, double last, gpy_stamp last_at,
                        size_t i, char *why, size_t size)
{
    if (!(self->gap > 0.0) || !(t - last < self->gap))
        return 0;
    gap_words(
        self->gap, self->gap_median, self->gap_auto, self->ns, at, t, last_at, last, i,
        "append does not merge keys (dedup=True merges those given to Path): leave this one out, or build "
        "the Path with min_gap=0 to keep such keys",
        why, size);
    return 1;
}

int gpy_path_near_dups(gpy_PathObject *self, const ga_group *g, PyObject *min_gap, int dedup, int ns,
                       gpy_stamp ref, npy_intp *np, gpy_stamp *stamp, double *rel, ga_mat4 *keys)
{
    int check, dflt;
    double gap, median = 0.0;
    npy_intp n = *np;
    self->gap = self->gap_median = 0.0;
    self->gap_auto = 0;
    if (min_gap_arg(min_gap, ns, &check, &dflt, &gap))
        return -1;
    if (check && !dflt)
        self->gap = gap;
    if (dedup && !g->rigid) { /* the tool's --dedup, as its message says */
        PyErr_SetString(PyExc_ValueError, "Path: dedup applies to the groups 'cga' and 'matrix'");
        return -1;
    }
    if (!check || n < 2)
        return 0;
    if (dflt) {
        double *scratch = PyMem_Malloc((size_t)(n - 1) * sizeof *scratch);
        if (!scratch) {
            PyErr_NoMemory();
            return -1;
        }
        int st = ga_times_min_gap((size_t)n, rel, scratch, &median, &gap);
        PyMem_Free(scratch);
        if (st != GA_OK) {
            gpy_status_error("Path: min_gap", st);
            return -1;
        }
    }
    self->gap = gap;
    self->gap_median = median;
    self->gap_auto = dflt;
    npy_intp out = 0;
    for (npy_intp i = 0; i < n;) {
        npy_intp j = (npy_intp)ga_times_gap_run((size_t)n, rel, gap, (size_t)i);
        char why[400];
        if (j > i && !dedup) { /* the tool's words (interp_read.c), the keys named by index */
            gap_words(gap, median, dflt, ns, stamp[i + 1], rel[i + 1], stamp[i], rel[i], (size_t)i,
                      "pass dedup=True to merge such keys, or min_gap=0 to keep them", why, sizeof why);
            gpy_raise_status_why("Path: times", 1, np, i + 1, GA_ERR_ARG, why);
            return -1;
        }
        if (j > i) { /* merged into key i: ga_path_merge_keys, as the tool's --dedup */
            double t;
            ga_mat4 mean;
            int st = j - i + 1 > GA_PATH_MERGE_MAX
                       ? GA_ERR_ARG
                       : ga_path_merge_keys((size_t)(j - i + 1), rel + i, keys + i, ns, &t, &mean);
            if (st != GA_OK) {
                snprintf(why, sizeof why, "cannot merge the keys of indices %zd to %zd%s", (Py_ssize_t)i,
                         (Py_ssize_t)j,
                         j - i + 1 > GA_PATH_MERGE_MAX ? ": more than 64 in a row (is min_gap too large?)"
                                                       : "");
                gpy_raise_status_why("Path: times", 1, np, i, st, why);
                return -1;
            }
            /* its time: the first key's stamp plus the shortest decimal of
               the mean (whole ns with time_unit='ns'), exactly, as the tool
               stamps it; relative, that is the mean itself */
            gpy_stamp o = {(int64_t)t, 0}, sum;
            if (!ns)
                gpy_stamp_of_double(t, 0, &o);
            if (stamp_add(ref, o, &sum) == 0) {
                stamp[i] = sum;
                rel[i] = gpy_stamp_rel(sum, ref, ns);
            } else { /* more digits than an int64 holds: the stamp rounded, the time kept */
                gpy_stamp_of_double(gpy_stamp_double(ref) + t, 0, &stamp[i]);
                rel[i] = t;
            }
            keys[i] = mean;
        }
        stamp[out] = stamp[i];
        rel[out] = rel[i];
        keys[out] = keys[i];
        out++;
        i = j + 1;
    }
    *np = out;
    return 0;
}
