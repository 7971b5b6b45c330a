/* python/module.c: the CPython extension module `garotor` (docs/python.md):
 * its function table, PyInit_garotor, and _c_loop, the benchmark's plain C
 * loop. module.h says which file holds what.
 */
#define GPY_IMPORT_ARRAY /* import_array below fills numpy's API table */
#include "module.h"

#include <time.h>

/* ---- the benchmark's reference: the same work as a plain C loop ----------- */

/* wall time, or with cpu the calling thread's CPU time (python/bench.py
   --clock cpu: time.thread_time, on a machine shared with other work) */
static double now_seconds(int cpu)
{
    struct timespec ts;
    clock_gettime(cpu ? CLOCK_THREAD_CPUTIME_ID : CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* _c_loop(kind, x, path=None, cpu=False): seconds for the library calls that exp, log,
 * Path.sample or MultivectorArray's * make per element, in a plain C loop
 * over a C-contiguous float64 x ((n, 6) twists, (n, 4, 4) motions, (n,)
 * times, (n, 32) multivectors, the second factors y (n, 32) in place of the
 * path) into a scratch buffer: no
 * numpy, no broadcasting, no kernel pointer, no check of the numbers beyond
 * the library's own (python/bench.py). A bad element stops it with
 * garotor.Error naming its index, as the module's calls do. */
static PyObject *c_loop(PyObject *self, PyObject *args)
{
    (void)self;
    const char *kind;
    PyObject *xo, *po = Py_None;
    int cpu = 0;
    if (!PyArg_ParseTuple(args, "sO|Op:_c_loop", &kind, &xo, &po, &cpu))
        return NULL;
    PyArrayObject *x = gpy_as_doubles(xo);
    if (!x)
        return NULL;
    int k = strcmp(kind, "exp") == 0    ? 0
          : strcmp(kind, "log") == 0    ? 1
          : strcmp(kind, "sample") == 0 ? 2
          : strcmp(kind, "gp") == 0     ? 3
                                        : -1;
    npy_intp n = PyArray_NDIM(x) ? PyArray_DIM(x, 0) : 0;
    npy_intp width = k == 0 ? 6 : k == 1 ? 16 : k == 3 ? 32 : 1, owidth = k == 3 ? 32 : 16;
    PyArrayObject *y = k == 3 ? gpy_as_doubles(po) : NULL;
    if (k == 3 && !y) {
        Py_DECREF(x);
        return NULL;
    }
    /* an uninitialised Path has no group to sample with */
    if (k < 0 || PyArray_SIZE(x) != n * width || (k == 3 && PyArray_SIZE(y) != n * width) ||
        (k == 2 && !(PyObject_TypeCheck(po, &gpy_PathType) && ((gpy_PathObject *)po)->work))) {
        Py_DECREF(x);
        Py_XDECREF(y);
        PyErr_SetString(PyExc_ValueError,
                        "_c_loop: kind exp (n, 6), log (n, 4, 4), sample (n,) with a Path or gp (n, 32) "
                        "with (n, 32)");
        return NULL;
    }
    const ga_path *p = k == 2 ? &((gpy_PathObject *)po)->path : NULL;
    PyThread_type_lock lock = k == 2 ? ((gpy_PathObject *)po)->lock : NULL; /* as Path.sample takes it */
    double *buf = PyMem_Malloc((size_t)(n ? n : 1) * (size_t)owidth * sizeof *buf);
    if (!buf) {
        Py_DECREF(x);
        Py_XDECREF(y);
        return PyErr_NoMemory();
    }
    const double *in2 = y ? PyArray_DATA(y) : NULL;
    const double *in = PyArray_DATA(x);
    const ga_group *g = &ga_group_cga;
    int st = GA_OK;
    npy_intp bad = -1;
    memset(buf, 0,
           (size_t)(n ? n : 1) * (size_t)owidth * sizeof *buf); /* the pages, before the clock starts */
    double t0 = now_seconds(cpu);
    Py_BEGIN_ALLOW_THREADS;
    if (lock)
        PyThread_acquire_lock(lock, WAIT_LOCK);
    /* a failed call writes nothing to e (the library's rule): e is read only
       after a success, and the loop stops at the first failure */
    for (npy_intp i = 0; i < n; i++) {
        double e[GA_GROUP_MAX_ELEM];
        if (k == 0) {
            if ((st = g->exp(in + 6 * i, e)) == GA_OK)
                gpy_mat_put(g->to_mat4(e), buf + 16 * i);
        } else if (k == 1) {
            st = g->from_mat4(gpy_mat_get(in + 16 * i), e);
            if (st == GA_OK)
                st = g->log(e, buf + 16 * i);
        } else if (k == 3) {
            ga_mv a, b;
            memcpy(a.c, in + 32 * i, sizeof a.c);
            memcpy(b.c, in2 + 32 * i, sizeof b.c);
            ga_mv r = ga_mv_gp(a, b);
            memcpy(buf + 32 * i, r.c, sizeof r.c);
        } else if ((st = ga_path_sample(p, GA_EVAL_DIRECT, 1.0, 1, in + i, e)) == GA_OK)
            gpy_mat_put(p->group->to_mat4(e), buf + 16 * i);
        if (st != GA_OK) {
            bad = i;
            break;
        }
    }
    if (lock)
        PyThread_release_lock(lock);
    Py_END_ALLOW_THREADS;
    double dt = now_seconds(cpu) - t0;
    PyMem_Free(buf);
    Py_DECREF(x);
    Py_XDECREF(y);
    if (bad >= 0) { /* as the module's calls name the element */
        gpy_raise_status("_c_loop", 1, &n, bad, st);
        return NULL;
    }
    return PyFloat_FromDouble(dt);
}

/* ---- the module ---------------------------------------------------------- */

#define KW (METH_VARARGS | METH_KEYWORDS)
#define FN(f) (PyCFunction)(void (*)(void))(f)

static PyMethodDef module_methods[] = {
    {"exp", FN(gpy_exp), KW,
     "exp(xi, group='cga', *, out=None): twists (..., 6) -> rigid motions (..., 4, 4).\n"
     "group 'affine' takes (..., 4, 4) generators with last row zero."},
    {"log", FN(gpy_log), KW,
     "log(T, group='cga', *, out=None): rigid motions (..., 4, 4) -> principal twists (..., 6)\n"
     "(affine: the principal log as (..., 4, 4))."},
    {"compose", FN(gpy_compose), KW, "compose(A, B, group='cga', *, out=None): A B (B first), broadcast."},
    {"inverse", FN(gpy_inverse), KW, "inverse(T, group='cga', *, out=None): T^-1."},
    {"apply", FN(gpy_apply), KW,
     "apply(T, points, group='cga', *, out=None): T moves points (..., 3), broadcast."},
    {"from_quat", FN(gpy_from_quat), KW,
     "from_quat(q, t=None, *, out=None): unit quaternions (..., 4) in x y z w order and translations (..., "
     "3)\n"
     "-> (..., 4, 4): rotate by q, then translate by t."},
    {"to_quat", FN(gpy_to_quat), KW,
     "to_quat(T, *, out=None): the rotation of T as a quaternion x y z w, w >= 0."},
    {"from_pose", FN(gpy_from_pose), KW,
     "from_pose(poses, *, out=None): rows x y z qx qy qz qw (..., 7) -> (..., 4, 4)."},
    {"to_pose", FN(gpy_to_pose), KW,
     "to_pose(T, continuous=True, *, out=None): (..., 4, 4) -> rows x y z qx qy qz qw (..., 7);\n"
     "with continuous, the quaternion's sign follows the previous pose along the last leading axis."},
    {"to_dualquat", FN(gpy_to_dualquat), KW,
     "to_dualquat(T, *, out=None): (..., 4, 4) -> (..., 8): real x y z w, then dual x y z w."},
    {"from_dualquat", FN(gpy_from_dualquat), KW,
     "from_dualquat(d, *, out=None): unit dual quaternions (..., 8) -> (..., 4, 4)."},
    {"up", FN(gpy_up), KW, "up(x, *, out=None): points (..., 3) -> conformal points (..., 32)."},
    {"down", FN(gpy_down), KW, "down(X, *, out=None): conformal points (..., 32) -> points (..., 3)."},
    {"fit_sphere", gpy_fit_sphere, METH_O,
     "fit_sphere(points): the least-squares sphere through (n, 3) points, n >= 4: (centre, radius)."},
    {"fit_plane", gpy_fit_plane, METH_O,
     "fit_plane(points): the least-squares plane m.x = d through (n, 3) points, n >= 3: (m, d)."},
    {"fit_circle", gpy_fit_circle, METH_O,
     "fit_circle(points): the least-squares circle through (n, 3) points, n >= 3: (centre, radius, normal)."},
    {"fit_line", gpy_fit_line, METH_O,
     "fit_line(points): the least-squares line through (n, 3) points, n >= 2: (direction, point)."},
    {"_c_loop", c_loop, METH_VARARGS,
     "_c_loop(kind, x, path=None, cpu=False): the benchmark's plain C loop (python/bench.py)."},
    {NULL, NULL, 0, NULL}};

static struct PyModuleDef garotor_module = {PyModuleDef_HEAD_INIT,
                                            "garotor",
                                            "garotor: rigid motions in conformal geometric algebra G(4,1), "
                                            "vectorised over numpy arrays (docs/python.md).",
                                            -1,
                                            module_methods,
                                            NULL,
                                            NULL,
                                            NULL,
                                            NULL};

PyMODINIT_FUNC PyInit_garotor(void)
{
    import_array();
    if (PyType_Ready(&gpy_PathType) < 0 || PyType_Ready(&gpy_MVType) < 0 || PyType_Ready(&gpy_MVAType) < 0)
        return NULL;
    /* numpy defers to Multivector's and MultivectorArray's own operators
       (2.0 * m, m * numpy.float64(2)) */
    if (PyDict_SetItemString(gpy_MVType.tp_dict, "__array_ufunc__", Py_None) < 0 ||
        PyDict_SetItemString(gpy_MVAType.tp_dict, "__array_ufunc__", Py_None) < 0)
        return NULL;
    PyType_Modified(&gpy_MVType);
    PyType_Modified(&gpy_MVAType);
    PyObject *m = PyModule_Create(&garotor_module);
    if (!m)
        return NULL;
    gpy_error = PyErr_NewExceptionWithDoc("garotor.Error",
                                          "A garotor call met a bad element: a ValueError with the index "
                                          "of the first one (index, a tuple) and the "
                                          "library's status code (status) and text.",
                                          PyExc_ValueError, NULL);
    if (!gpy_error || PyModule_AddObjectRef(m, "Error", gpy_error) < 0 ||
        PyModule_AddObjectRef(m, "Path", (PyObject *)&gpy_PathType) < 0 ||
        PyModule_AddObjectRef(m, "Multivector", (PyObject *)&gpy_MVType) < 0 ||
        PyModule_AddObjectRef(m, "MultivectorArray", (PyObject *)&gpy_MVAType) < 0 ||
        gpy_objects_init(m) < 0 || gpy_ufuncs_init(m) < 0 ||
        PyModule_AddStringConstant(m, "__version__", GAROTOR_VERSION_STRING) < 0 ||
        PyModule_AddFunctions(m, gpy_jacobian_methods) < 0)
        goto fail;
    for (int i = 1; i < 32; i++) {
        PyObject *b = gpy_mv_new(ga_mv_blade(i));
        if (!b || PyModule_AddObject(m, ga_blade_name(i), b) < 0) {
            Py_XDECREF(b);
            goto fail;
        }
    }
    PyObject *n = gpy_mv_new(ga_mv_n()), *nbar = gpy_mv_new(ga_mv_nbar());
    if (!n || PyModule_AddObject(m, "n", n) < 0) {
        Py_XDECREF(n);
        Py_XDECREF(nbar);
        goto fail;
    }
    if (!nbar || PyModule_AddObject(m, "nbar", nbar) < 0) {
        Py_XDECREF(nbar);
        goto fail;
    }
    return m;
fail:
    Py_DECREF(m);
    return NULL;
}
