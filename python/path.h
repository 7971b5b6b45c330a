/* python/path.h: what the files of garotor.Path share (internal to the
 * module, prefix gpy_path_; module.h says which file holds what):
 *
 *   path.c         the lock, construction and its checks, pickling, the
 *                  type's tables
 *   path_sample.c  sample, sample_pose, velocity, acceleration, jerk
 *   path_keys.c    append and the attributes
 *   path_times.c   the times: stamps as given, relative seconds (also read
 *                  by trajectory.c: evaluate, ape, rpe and fit take their
 *                  stamps as Path does)
 *   path_opts.c    the tool's options: normalize=, the growth warning, clip
 */
#ifndef GAROTOR_PYTHON_PATH_H
#define GAROTOR_PYTHON_PATH_H

#include "module.h"

/* Path.append changes a path (its keys, segments and n) that another thread
 * may be reading with the GIL released (sample, velocity, acceleration in
 * gpy_run_kernel's loop), so each Path has a lock, held by both. No thread
 * waits for it while holding the GIL: one holding the lock and waiting for
 * the GIL, and one holding the GIL and waiting for the lock, would wait
 * forever. f runs with the lock held and is C only (no Python API, as the
 * GIL may be released): taken at once where it is free, the GIL is kept;
 * else the wait (and f) happen with the GIL released. */
typedef void (*gpy_path_fn)(gpy_PathObject *self, void *arg);
void gpy_path_locked(gpy_PathObject *self, gpy_path_fn f, void *arg);

/* 1 if self is built, else 0 with a ValueError */
int gpy_path_ready(gpy_PathObject *self);

/* a gpy_path_fn: self's number of keys into *(size_t *)n */
void gpy_path_read_n(gpy_PathObject *self, void *n);

/* ---- the methods (path_sample.c) ---- */
PyObject *gpy_path_sample(gpy_PathObject *self, PyObject *args, PyObject *kw);
PyObject *gpy_path_sample_pose(gpy_PathObject *self, PyObject *args, PyObject *kw);
PyObject *gpy_path_velocity(gpy_PathObject *self, PyObject *args, PyObject *kw);
PyObject *gpy_path_acceleration(gpy_PathObject *self, PyObject *args, PyObject *kw);
PyObject *gpy_path_jerk(gpy_PathObject *self, PyObject *args, PyObject *kw);

/* ---- append and the attributes (path_keys.c) ---- */
PyObject *gpy_path_append(gpy_PathObject *self, PyObject *args, PyObject *kw);
PyObject *gpy_path_get_times(gpy_PathObject *self, void *c);
PyObject *gpy_path_get_capacity(gpy_PathObject *self, void *c);
PyObject *gpy_path_get_scheme(gpy_PathObject *self, void *c);
PyObject *gpy_path_get_range(gpy_PathObject *self, void *c);
PyObject *gpy_path_get_group(gpy_PathObject *self, void *c);
PyObject *gpy_path_repr(gpy_PathObject *self);
/* the first count key times as given: float64 seconds, or int64
 * nanoseconds (ns); a new writeable array, NULL with an exception */
PyArrayObject *gpy_path_times_array(gpy_PathObject *self, size_t count);

/* ---- the times (path_times.c) ---- */

/* (a - ref) x 10^-9 (ns) or x 1 in seconds, the exact difference rounded
 * once to a double: the tool's relative time (ic_rel_time) */
double gpy_stamp_rel(gpy_stamp a, gpy_stamp ref, int ns);
/* (a + k c - ref) x 10^-9 (ns) or x 1, exact and rounded once: a stamp
 * shifted by k times c (an offset, a knot spacing) relative to ref, as the
 * tool's decimal sums (tt_add) are; |k| < 2^59 */
double gpy_stamp_rel_plus(gpy_stamp a, int64_t k, gpy_stamp c, gpy_stamp ref, int ns);
/* x as its shortest decimal (with ns, whole nanoseconds, e = 0): 0, or -1
 * for a NaN or an infinity, -2 (ns) not whole, -3 (ns) beyond an int64 */
int gpy_stamp_of_double(double x, int ns, gpy_stamp *s);
/* s as the nearest double */
double gpy_stamp_double(gpy_stamp s);
/* s as a Python int (ns) or float */
PyObject *gpy_stamp_value(gpy_stamp s, int ns);
/* s as text for messages: repr of its double, or its integer (ns) */
const char *gpy_stamp_text(gpy_stamp s, int ns, char buf[32]);
/* times given: an array of a signed integer dtype as int64 (exact), any
 * other as gpy_as_doubles reads it; C-contiguous. NULL with an exception. */
PyArrayObject *gpy_path_times_in(PyObject *obj);
/* element i of such an array as a stamp (gpy_stamp_of_double's returns) */
int gpy_path_stamp_at(PyArrayObject *a, npy_intp i, int ns, gpy_stamp *s);
/* time_unit= "s" (or NULL) or "ns" into *ns; -1 with a ValueError */
int gpy_path_unit(const char *what, const char *name, int *ns);
/* the 1-d times t of n keys into stamp[0..n) and rel[0..n) (relative
 * seconds), each checked: finite, whole with ns, increasing. -1 with an
 * exception naming what. */
int gpy_path_key_times(const char *what, PyArrayObject *t, int ns, gpy_stamp *stamp, double *rel);
/* t (any shape) as the float64 array of its times relative to the first
 * key's, in seconds (t itself, converted, when that is the identity: no
 * ns and a first key at 0); *given the array of t as read, or NULL when
 * none was made. NULL with an exception. */
PyObject *gpy_path_rel_times(gpy_PathObject *self, PyObject *t, PyArrayObject **given);
/* the index of the key at the relative time t (the first at or after it) */
size_t gpy_path_key_index(const ga_path *p, double t);

/* ---- the tool's options (path_opts.c) ---- */

/* key i given as a pose row (7) or a 4x4 (16): with normalize projected onto
 * the group as `garotor interp --normalize` does (ga_quat_normalize,
 * ga_se3_normalize to GA_SE3_NORMALIZE_TOL); C only (no Python API) */
int gpy_key_pose(const double *v, int normalize, ga_mat4 *m);
ga_mat4 gpy_key_mat(const ga_group *g, const double *v, int normalize);
/* why key i (v, a pose row or a 4x4) was refused, naming normalize= where
 * it decides; "" when the status says it all. i < 0: Path.append's key
 * (named pose, where Path(...)'s is poses[i]) */
void gpy_key_why(const ga_group *g, const double *v, int pose, int normalize, npy_intp i, char *why,
                 size_t size);
/* the growth rule's warning (RuntimeWarning) where self's path breaks it,
 * in the tool's words, what ("Path", "Path.append") first; measured under
 * the lock; -1 when the warning is raised as an error */
int gpy_path_warn_growth(gpy_PathObject *self, const char *what);
/* min_gap= and dedup= (the tool's --min-gap, --dedup): keys closer than the
 * gap an error naming the later one, or with dedup each run merged into one
 * key (ga_path_merge_keys), stamp, rel and keys compacted and *n the keys
 * left; ref: the first key's stamp, which the times are relative to. The
 * gap used (relative seconds; 0: none), and for 'auto' (the default, as the
 * tool's) the median spacing, into self->gap, gap_median, gap_auto, for
 * append. -1 with an exception. */
int gpy_path_near_dups(gpy_PathObject *self, const ga_group *g, PyObject *min_gap, int dedup, int ns,
                       gpy_stamp ref, npy_intp *n, gpy_stamp *stamp, double *rel, ga_mat4 *keys);
/* why a key appended at relative time t, stamped at, is closer than
 * self->gap to the last key (at relative time last, stamped last_at, index
 * i): the tool's words; 0 when it is not, else 1 and why filled */
int gpy_path_append_gap(const gpy_PathObject *self, double t, gpy_stamp at, double last, gpy_stamp last_at,
                        size_t i, char *why, size_t size);
/* Path.clip(t) */
PyObject *gpy_path_clip(gpy_PathObject *self, PyObject *args, PyObject *kw);

#endif
