/* python/path.h: what the files of garotor.Path share (internal to the
 * module, prefix gpy_path_; module.h says which file holds what):
 *
 *   path.c         the lock, construction and its checks, pickling, the
 *                  type's tables
 *   path_sample.c  sample, sample_pose, velocity, acceleration, jerk
 *   path_keys.c    append and the attributes
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

#endif
