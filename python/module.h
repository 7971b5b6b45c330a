/* python/module.h: what the files of the CPython extension module garotor._garotor
 * (docs/python.md) share: the vectorised loop's types (kernel.c), the error
 * helpers, the Path and Multivector types, and the module functions that
 * module.c's table lists. Internal to the module, prefix gpy_; every file of
 * the module includes this header first, for Python.h and numpy's API.
 *
 *   module.c       the module: its function table, PyInit__garotor
 *   kernel.c       errors, array conversion, the broadcasting kernel runner
 *   functions.c    the element-wise functions: exp, log, compose, ..., up, down
 *   path.c         the Path type (with path_sample.c and path_keys.c: path.h)
 *   multivector.c  the Multivector type
 *   objects.c      Multivector's object methods (meet, join, read-back,
 *                  versors, projections, powers), garotor.Object, the fits
 *   mvarray.c      the MultivectorArray type and the multivector kernels
 *   ufuncs.c       garotor.ufunc: numpy generalized ufuncs of the kernels
 *   jacobian.c     the Lie-group Jacobians (gpy_jacobian_methods)
 *   trajectory.c   trajectories compared and fitted: evaluate, ape, rpe,
 *                  align, fit (gpy_trajectory_methods)
 */
#ifndef GAROTOR_PYTHON_MODULE_H
#define GAROTOR_PYTHON_MODULE_H

#define PY_SSIZE_T_CLEAN
#include <Python.h>
#include <pythread.h>
#define NPY_NO_DEPRECATED_API NPY_1_7_API_VERSION
/* numpy's API is a table that import_array fills in PyInit__garotor
 * (module.c defines GPY_IMPORT_ARRAY); the other files share the table */
#define PY_ARRAY_UNIQUE_SYMBOL gpy_ARRAY_API
#ifndef GPY_IMPORT_ARRAY
#define NO_IMPORT_ARRAY
#endif
#include <numpy/arrayobject.h>

#include <string.h>

#include <garotor/garotor.h>

/* ---- errors (kernel.c) --------------------------------------------------- */

extern PyObject *gpy_error; /* garotor.Error, a subclass of ValueError */

/* Raise garotor.Error("<what>: index <i>: <status text>[: <why>]") with
 * attributes index (a tuple, () for a single element) and status; why (or
 * NULL) says what is wrong with the element where the status alone does not.
 * lead[0..nlead-1] is the leading shape, flat the element's flat index. */
void gpy_raise_status_why(const char *what, int nlead, const npy_intp *lead, npy_intp flat, int status,
                          const char *why);
void gpy_raise_status(const char *what, int nlead, const npy_intp *lead, npy_intp flat, int status);
/* garotor.Error("<what>: <status text>"), index () and status; NULL */
PyObject *gpy_status_error(const char *what, int status);
/* x as Python's repr writes it (the shortest text that reads back as x) in
 * buf[32]; buf. With the GIL held. */
const char *gpy_repr_text(double x, char buf[32]);

/* ---- numbers in (kernel.c) ------------------------------------------------- */

/* obj as a C-contiguous aligned float64 array, read as numpy reads a list of
 * numbers: an array of another real dtype cast, an object array's items each
 * read by float() (as a list's are), anything else as np.asarray(obj, float)
 * reads it. NULL with an exception. */
PyArrayObject *gpy_as_doubles(PyObject *obj);
/* 1 if v[0..n-1] holds no NaN and no infinity. Without the GIL too. */
int gpy_all_finite(const double *v, npy_intp n);
/* The index of the first NaN or infinity in v[0..n-1]; -1 if there is none.
 * Without the GIL too. */
npy_intp gpy_first_nonfinite(const double *v, npy_intp n);
/* "<name>[i, j] is nan": the number at flat index `flat` of a (C-contiguous
 * float64), with its index in a's shape ("<name> is inf" for a 0-d a), into
 * why[size]. With the GIL held. */
void gpy_nonfinite_why(const char *name, PyArrayObject *a, npy_intp flat, char *why, size_t size);

/* ---- the vectorised loop (kernel.c) --------------------------------------- */

#define GPY_MAX_IN 3
#define GPY_MAX_OUT 144 /* numbers in one element of a result (a 12x12 affine Jacobian) */

typedef struct {
    int ncore;        /* trailing dimensions of one element */
    npy_intp core[2]; /* their sizes */
    const char *name; /* the argument's name, for messages */
} gpy_core;

#define GPY_CORE1(n, name)                                                                                   \
    {                                                                                                        \
        1, {n, 0}, name                                                                                      \
    }
#define GPY_CORE2(n, m, name)                                                                                \
    {                                                                                                        \
        2, {n, m}, name                                                                                      \
    }

/* One element: in[j] points at input j's element, out at a scratch buffer
 * for the output's (copied to its place when the kernel succeeds and it is
 * finite). Returns GA_OK or a GA_ERR_* status. k is the flat index of the
 * element. A NaN or an infinity in the element must give a status (any) or
 * a result that is not finite: the loop then names it (GA_ERR_NOTFINITE);
 * the library's functions with a status refuse one anywhere in their input
 * (docs/errors.md). */
typedef int (*gpy_kernel_fn)(void *ctx, const double *const *in, double *out, npy_intp k);

typedef struct {
    const char *what; /* the call's name in messages */
    int nin;
    gpy_core in[GPY_MAX_IN];
    gpy_core out;
    gpy_kernel_fn kernel;
    void *ctx;
    /* set by gpy_run_kernel: the broadcast leading shape, for kernels that care */
    int nlead;
    npy_intp lead[NPY_MAXDIMS];
    /* or NULL: for the first bad element (its inputs, the kernel's status),
       why it is bad where the status alone does not say, into why[size] */
    void (*explain)(void *ctx, const double *const *in, int status, char *why, size_t size);
    /* or NULL: n elements that share input 0's one element (in0), input 1's
       and the results' in C order (in1, out; out may be in1 itself): the
       numbers kernel gives element by element. Run where input 0 has no
       leading dimensions and input 1 the whole broadcast shape (one motion,
       many points), or where the one input (nin = 1: in0 NULL, in1 input
       0's elements) has that shape; any status or result not finite, and the
       elements from there on are run one by one, which names the error */
    int (*many)(void *ctx, const double *in0, const double *in1, npy_intp n, double *out);
    /* or NULL: held over the loop (taken with the GIL released), for a
       context that another thread may change (a Path's) */
    PyThread_type_lock lock;
} gpy_kernel_call;

/* Run kc over the inputs objs[0..nin-1]: convert each to a C-contiguous
 * float64 array with its core shape, broadcast, loop with the GIL released
 * (each result checked finite; a failed element's numbers too), then raise or
 * return the result (or `out`, filled in place). */
PyObject *gpy_run_kernel(gpy_kernel_call *kc, PyObject *const *objs, PyObject *out);

/* The group called name (NULL: "cga"); NULL with a ValueError naming what if
 * there is none. */
const ga_group *gpy_group_arg(const char *what, const char *name);

static inline void gpy_mat_put(ga_mat4 m, double *out) { memcpy(out, m.m, sizeof m.m); }
static inline ga_mat4 gpy_mat_get(const double *v)
{
    ga_mat4 m;
    memcpy(m.m, v, sizeof m.m);
    return m;
}

/* ---- the element-wise functions (functions.c) ----------------------------- */

/* (x y z qx qy qz qw) -> 4x4, exactly as `garotor interp --format pose` reads a key */
int gpy_pose_to_mat(const double *v, ga_mat4 *m);

/* Their kernels (gpy_kernel_fn), which the generalized ufuncs (ufuncs.c) run
 * too: ctx is the group (exp ... apply) or unused, but for to_pose's */
int gpy_k_exp(void *ctx, const double *const *in, double *out, npy_intp k);
int gpy_k_log(void *ctx, const double *const *in, double *out, npy_intp k);
int gpy_k_compose(void *ctx, const double *const *in, double *out, npy_intp k);
int gpy_k_inverse(void *ctx, const double *const *in, double *out, npy_intp k);
int gpy_k_apply(void *ctx, const double *const *in, double *out, npy_intp k);
/* apply of one motion to n points (gpy_kernel_call.many): the same numbers */
int gpy_apply_many(void *ctx, const double *T, const double *x, npy_intp n, double *y);
int gpy_k_from_quat(void *ctx, const double *const *in, double *out, npy_intp k);
int gpy_k_from_pose(void *ctx, const double *const *in, double *out, npy_intp k);
int gpy_k_to_quat(void *ctx, const double *const *in, double *out, npy_intp k);
int gpy_k_to_dualquat(void *ctx, const double *const *in, double *out, npy_intp k);
int gpy_k_from_dualquat(void *ctx, const double *const *in, double *out, npy_intp k);
int gpy_k_up(void *ctx, const double *const *in, double *out, npy_intp k);
int gpy_k_down(void *ctx, const double *const *in, double *out, npy_intp k);
/* to_pose's context: the quaternion's sign follows the previous element's
 * within a run of `run` elements (k % run == 0 starts one, with w >= 0) */
typedef struct {
    npy_intp run; /* elements in one run (the last leading dimension), 0: no continuity */
    ga_quat prev;
} gpy_pose_ctx;
int gpy_k_to_pose(void *ctx, const double *const *in, double *out, npy_intp k);

PyObject *gpy_exp(PyObject *self, PyObject *args, PyObject *kw);
PyObject *gpy_log(PyObject *self, PyObject *args, PyObject *kw);
PyObject *gpy_compose(PyObject *self, PyObject *args, PyObject *kw);
PyObject *gpy_inverse(PyObject *self, PyObject *args, PyObject *kw);
PyObject *gpy_apply(PyObject *self, PyObject *args, PyObject *kw);
PyObject *gpy_from_quat(PyObject *self, PyObject *args, PyObject *kw);
PyObject *gpy_to_quat(PyObject *self, PyObject *args, PyObject *kw);
PyObject *gpy_from_pose(PyObject *self, PyObject *args, PyObject *kw);
PyObject *gpy_to_pose(PyObject *self, PyObject *args, PyObject *kw);
PyObject *gpy_to_dualquat(PyObject *self, PyObject *args, PyObject *kw);
PyObject *gpy_from_dualquat(PyObject *self, PyObject *args, PyObject *kw);
PyObject *gpy_up(PyObject *self, PyObject *args, PyObject *kw);
PyObject *gpy_down(PyObject *self, PyObject *args, PyObject *kw);

/* ---- Jacobians (jacobian.c): added to the module by PyInit_garotor ---------- */

extern PyMethodDef gpy_jacobian_methods[];

/* ---- trajectories (trajectory.c): added to the module by PyInit_garotor ----- */

extern PyMethodDef gpy_trajectory_methods[];

/* ---- Path (path.c, path.h) ---------------------------------------------------- */

/* a time as the exact decimal m x 10^e it was given as (path_times.c) */
typedef struct {
    int64_t m;
    int e;
} gpy_stamp;

typedef struct {
    PyObject_HEAD const ga_group *group;
    ga_scheme scheme;
    ga_path path;
    void *work;
    /* the velocities given to the constructor (nvel doubles, the group's
       coordinates), or NULL: kept for pickling (Path.__reduce__) */
    double *vel;
    size_t nvel;
    /* guards path against Path.append in another thread while a call reads
       it with the GIL released; taken only with the GIL released (or
       without waiting), so that no thread waits for it holding the GIL */
    PyThread_type_lock lock;
    /* the key times as given (path.cap of them, path.n set), in seconds or,
       with ns, nanoseconds (whole: e = 0); the path's own times are each
       minus stamp[0], in seconds (gpy_stamp_rel), as the tool's are */
    gpy_stamp *stamp;
    int ns;
    /* the reference the path's times are relative to: stamp[0], or after
       Path(dedup=True) merged the first keys, the first key's as given */
    gpy_stamp ref;
    int merged; /* dedup merged keys: a pickle keeps ref and the relative times */
    /* min_gap= for the keys append adds (path_opts.c): the gap in relative
       seconds (0: none), and for 'auto' the median spacing it is 1% of */
    double gap, gap_median;
    int gap_auto;
    /* normalize= for the keys append adds (path_opts.c): each projected onto
       the group as the constructor's keys were */
    int normalize;
} gpy_PathObject;

extern PyTypeObject gpy_PathType;

/* ---- Multivector (multivector.c) -------------------------------------------- */

typedef struct {
    PyObject_HEAD ga_mv mv;
} gpy_MVObject;

extern PyTypeObject gpy_MVType;

/* A new Multivector holding m; NULL with an exception. */
PyObject *gpy_mv_new(ga_mv m);
/* m as a new Multivector from the operation `what`; NULL with garotor.Error
 * (GA_ERR_DOMAIN) if a coefficient is not finite. */
PyObject *gpy_mv_result(const char *what, ga_mv m);
/* x, a Multivector or a real number (a scalar multivector), into out: 1; 0
 * if x is neither; -1 with garotor.Error for a number that is NaN or
 * infinite. */
int gpy_mv_operand(const char *what, PyObject *x, ga_mv *out);
/* 1 if s is finite; -1 with garotor.Error (GA_ERR_NOTFINITE) naming it. */
int gpy_finite_number(const char *what, double s);
/* obj, a 1-d array-like of count finite numbers, into v; what (the call)
 * and name (the argument) for messages, shape_msg for a wrong shape
 * (ValueError). 0, or -1 with an exception. */
int gpy_read_numbers(const char *what, const char *name, PyObject *obj, npy_intp count, const char *shape_msg,
                     double *v);

/* exp and log of Multivector (its methods' rules: the compact rotor for a
 * rigid motion's, ga_mv_exp and ga_mv_log for any other): a status */
int gpy_mv_exp(ga_mv m, ga_mv *out);
int gpy_mv_log(ga_mv m, ga_mv *out);

/* ---- MultivectorArray and the multivector kernels (mvarray.c) --------------- */

extern PyTypeObject gpy_MVAType;

/* kernel over x and y (MultivectorArrays, Multivectors or numbers, one of
 * them a MultivectorArray): the MultivectorArray of the results, as its
 * operators give them (what names the call in messages) */
PyObject *gpy_mva_binary(const char *what, gpy_kernel_fn kernel, PyObject *x, PyObject *y);

/* gpy_kernel_fn's of one multivector (32 numbers) or two, ctx unused: the
 * C function of the name (ga_mv_*; versor_apply ga_versor_apply, mv_exp and
 * mv_log gpy_mv_exp and gpy_mv_log; norm2 gives one number, object the 12
 * numbers of a ga_object in its fields' order, mv_pow takes the number t as
 * its second input) */
#define GPY_MV_KERNEL(name) int gpy_k_##name(void *ctx, const double *const *in, double *out, npy_intp k)
GPY_MV_KERNEL(gp);
GPY_MV_KERNEL(op);
GPY_MV_KERNEL(lc);
GPY_MV_KERNEL(dot);
GPY_MV_KERNEL(ip);
GPY_MV_KERNEL(regressive);
GPY_MV_KERNEL(commutator);
GPY_MV_KERNEL(meet);
GPY_MV_KERNEL(add);
GPY_MV_KERNEL(sub);
GPY_MV_KERNEL(join);
GPY_MV_KERNEL(meet_rel);
GPY_MV_KERNEL(project);
GPY_MV_KERNEL(reject);
GPY_MV_KERNEL(versor_apply);
GPY_MV_KERNEL(reverse);
GPY_MV_KERNEL(involute);
GPY_MV_KERNEL(conjugate);
GPY_MV_KERNEL(dual);
GPY_MV_KERNEL(undual);
GPY_MV_KERNEL(mv_inverse);
GPY_MV_KERNEL(mv_exp);
GPY_MV_KERNEL(mv_log);
GPY_MV_KERNEL(mv_sqrt);
GPY_MV_KERNEL(mv_pow);
GPY_MV_KERNEL(norm2);
GPY_MV_KERNEL(object);
/* versor_apply of one versor V (32 numbers) on n multivectors X (n x 32, C
 * order) into out (out may be X), as gpy_kernel_call.many: ga_versor_apply_many,
 * each result gpy_k_versor_apply's bit for bit */
int gpy_versor_apply_many(void *ctx, const double *V, const double *X, npy_intp n, double *out);

/* ---- generalized ufuncs (ufuncs.c) ------------------------------------------ */

/* the module garotor.ufunc (also in sys.modules) added to m; 0, or -1 */
int gpy_ufuncs_init(PyObject *m);

/* ---- objects (objects.c) ---------------------------------------------------- */

/* garotor.Object (a struct sequence) added to module m; 0, or -1 */
int gpy_objects_init(PyObject *m);
/* Multivector's methods of objects.c (their docs in its method table) */
PyObject *gpy_MV_meet(PyObject *self, PyObject *o);
PyObject *gpy_MV_join(PyObject *self, PyObject *o);
PyObject *gpy_MV_meet_rel(PyObject *self, PyObject *o);
PyObject *gpy_MV_object(PyObject *self, PyObject *args, PyObject *kw);
PyObject *gpy_MV_commutator(PyObject *self, PyObject *o);
PyObject *gpy_MV_project(PyObject *self, PyObject *o);
PyObject *gpy_MV_reject(PyObject *self, PyObject *o);
PyObject *gpy_MV_pow(PyObject *self, PyObject *t);
PyObject *gpy_MV_sqrt(PyObject *self, PyObject *u);
PyObject *gpy_MV_apply(PyObject *self, PyObject *o);
PyObject *gpy_MV_between(PyObject *self, PyObject *o);
PyObject *gpy_MV_interp(PyObject *self, PyObject *args);
/* object_mean(objects, weights=None), a module function */
PyObject *gpy_object_mean(PyObject *self, PyObject *args, PyObject *kw);
PyObject *gpy_MV_reflection(PyObject *cls, PyObject *args);
PyObject *gpy_MV_inversion(PyObject *cls, PyObject *args);
PyObject *gpy_MV_dilation(PyObject *cls, PyObject *args);
PyObject *gpy_MV_transversion(PyObject *cls, PyObject *arg);
PyObject *gpy_MV_rotation(PyObject *cls, PyObject *args);
PyObject *gpy_MV_translation(PyObject *cls, PyObject *arg);
/* a ** k for an integer k (nb_power) */
PyObject *gpy_MV_power(PyObject *x, PyObject *y, PyObject *z);
/* the fits: module functions fit_sphere(points), ... */
PyObject *gpy_fit_sphere(PyObject *self, PyObject *pts);
PyObject *gpy_fit_plane(PyObject *self, PyObject *pts);
PyObject *gpy_fit_circle(PyObject *self, PyObject *pts);
PyObject *gpy_fit_line(PyObject *self, PyObject *pts);

#endif
