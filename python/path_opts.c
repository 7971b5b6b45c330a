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
    char x[32];
    why[0] = '\0';
    if (gpy_first_nonfinite(v, pose ? 7 : 16) >= 0)
        return;
    if (pose) {
        double norm = sqrt(v[3] * v[3] + v[4] * v[4] + v[5] * v[5] + v[6] * v[6]);
        if (fabs(norm - 1.0) <= 1e-9)
            return;
        if (normalize)
            snprintf(why, size,
                     "poses[%zd, 3:7] (qx qy qz qw): the quaternion has norm %s, farther from 1 than "
                     "normalize=True accepts (1e-3)",
                     (Py_ssize_t)i, gpy_repr_text(norm, x));
        else
            snprintf(why, size,
                     "poses[%zd, 3:7] (qx qy qz qw): the quaternion has norm %s, not 1 (to 1e-9; "
                     "normalize=True accepts up to 1e-3)",
                     (Py_ssize_t)i, gpy_repr_text(norm, x));
        return;
    }
    ga_mat4 m = gpy_mat_get(v), r;
    if (normalize || !g->rigid || ga_se3_normalize(m, GA_SE3_NORMALIZE_TOL, &r) != GA_OK)
        return;
    double off = 0.0;
    for (int k = 0; k < 16; k++) off = fmax(off, fabs(m.m[k] - r.m[k]));
    snprintf(why, size,
             "poses[%zd] is not a rigid motion to 1e-9 (it is %.3g from the nearest one); normalize=True "
             "accepts up to 1e-3",
             (Py_ssize_t)i, off);
}

int gpy_path_warn_growth(gpy_PathObject *self)
{
    ga_path_growth gr;
    ga_path_growth_words w;
    const ga_path *p = &self->path;
    if (ga_path_measure_growth(p, &gr) != GA_OK || ga_path_growth_describe(p, &gr, &w) != GA_OK)
        return 0;
    char a[32], b[32], k[32], msg[512];
    /* the tool's words (cmd_interp.c), the keys named by index */
    snprintf(msg, sizeof msg,
             "Path: the %s path's velocity grows past %g times the fastest chord on the segment t = %s to %s "
             "(indices %zu to %zu), up to %s times at t = %s; %s (docs/schemes.md)",
             ga_scheme_name(p->scheme), GA_PATH_GROWTH_MAX, gpy_stamp_text(self->stamp[w.a], self->ns, a),
             gpy_stamp_text(self->stamp[w.b], self->ns, b), w.a, w.b, w.ratio,
             gpy_stamp_text(self->stamp[gr.key], self->ns, k), w.advice);
    return PyErr_WarnEx(PyExc_RuntimeWarning, msg, 1) < 0 ? -1 : 0;
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
