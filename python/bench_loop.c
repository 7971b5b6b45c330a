/* python/bench_loop.c: _garotor_bench, python/bench.py's reference: the
 * library calls that garotor's exp, log and Path.sample make per element,
 * in a plain C loop timed in C. Built beside the module for the benchmark
 * and its test only, never installed (python/meson.build); public C API
 * only.
 */
#define PY_SSIZE_T_CLEAN
#include <Python.h>
#define NPY_NO_DEPRECATED_API NPY_1_7_API_VERSION
#include <numpy/arrayobject.h>

#include <string.h>
#include <time.h>

#include <garotor/garotor.h>

/* wall time, or with cpu the calling thread's CPU time (bench.py --clock
   cpu, on a machine shared with other work) */
static double now_seconds(int cpu)
{
    struct timespec ts;
    clock_gettime(cpu ? CLOCK_THREAD_CPUTIME_ID : CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static PyArrayObject *doubles(PyObject *o)
{
    return (PyArrayObject *)PyArray_FROM_OTF(o, NPY_DOUBLE, NPY_ARRAY_IN_ARRAY);
}

/* c_loop(kind, x, keytimes=None, keys=None, cpu=False): seconds for the
 * library calls that exp ("exp": x (n, 6) twists), log ("log": x (n, 4, 4)
 * motions), Path(keytimes, keys, scheme="screw").sample ("sample": x (n,)
 * times, keys (m, 4, 4)) and compose ("compose": x and keytimes (n, 4, 4))
 * make per element on group cga, or that
 * MultivectorArray's * makes ("gp": x and keytimes (n, 32), ga_mv_gp), or
 * one versor's apply on n multivectors ("apply": x (n, 32), keytimes the
 * versor (32,), ga_versor_apply per element; "apply_many": the one call
 * ga_versor_apply_many that Multivector.apply makes), in a plain C loop into a scratch
 * buffer whose pages are touched before the clock starts: no numpy, no
 * broadcasting, no kernel pointer, no check of the numbers beyond the
 * library's own. A bad element raises ValueError naming its index. */
static PyObject *c_loop(PyObject *self, PyObject *args)
{
    (void)self;
    const char *kind;
    PyObject *xo, *to = Py_None, *ko = Py_None;
    int cpu = 0;
    if (!PyArg_ParseTuple(args, "sO|OOp:c_loop", &kind, &xo, &to, &ko, &cpu))
        return NULL;
    int k = strcmp(kind, "exp") == 0        ? 0
          : strcmp(kind, "log") == 0        ? 1
          : strcmp(kind, "sample") == 0     ? 2
          : strcmp(kind, "gp") == 0         ? 3
          : strcmp(kind, "apply") == 0      ? 4
          : strcmp(kind, "apply_many") == 0 ? 5
          : strcmp(kind, "compose") == 0    ? 6
                                            : -1;
    PyArrayObject *x = doubles(xo), *kt = NULL, *kk = NULL;
    PyObject *ret = NULL;
    double *buf = NULL;
    void *work = NULL;
    ga_path path;
    if (!x)
        return NULL;
    npy_intp n = PyArray_NDIM(x) ? PyArray_DIM(x, 0) : 0;
    npy_intp width = k == 0 ? 6 : k == 1 || k == 6 ? 16 : k >= 3 ? 32 : 1, owidth = k >= 3 && k < 6 ? 32 : 16;
    if (k < 0 || PyArray_SIZE(x) != n * width) {
        PyErr_SetString(PyExc_ValueError, "c_loop: kind exp (n, 6), log or compose (n, 4, 4), sample (n,), "
                                          "gp, apply or apply_many (n, 32)");
        goto done;
    }
    if (k == 3 && (!(kt = doubles(to)) || PyArray_SIZE(kt) != n * width)) {
        if (kt)
            PyErr_SetString(PyExc_ValueError, "c_loop: gp needs the second factors (n, 32)");
        goto done;
    }
    if (k == 6 && (!(kt = doubles(to)) || PyArray_SIZE(kt) != n * width)) {
        if (kt)
            PyErr_SetString(PyExc_ValueError, "c_loop: compose needs the second motions (n, 4, 4)");
        goto done;
    }
    if ((k == 4 || k == 5) && (!(kt = doubles(to)) || PyArray_SIZE(kt) != 32)) {
        if (kt)
            PyErr_SetString(PyExc_ValueError, "c_loop: apply needs the versor (32,)");
        goto done;
    }
    const ga_group *g = &ga_group_cga;
    if (k == 2) {
        if (!(kt = doubles(to)) || !(kk = doubles(ko)))
            goto done;
        npy_intp m = PyArray_SIZE(kt);
        size_t wbytes = ga_path_workspace_size(g, GA_SCHEME_SCREW, (size_t)m);
        if (PyArray_SIZE(kk) != 16 * m || wbytes == 0) {
            PyErr_SetString(PyExc_ValueError, "c_loop: sample needs key times (m,) and keys (m, 4, 4)");
            goto done;
        }
        if (!(work = PyMem_Malloc(wbytes))) {
            PyErr_NoMemory();
            goto done;
        }
        int st = ga_path_init_mat4(g, GA_SCHEME_SCREW, (size_t)m, PyArray_DATA(kt), PyArray_DATA(kk), NULL,
                                   work, wbytes, &path);
        if (st != GA_OK) {
            PyErr_Format(PyExc_ValueError, "c_loop: the path: %s", ga_status_string(st));
            goto done;
        }
    }
    size_t bytes = (size_t)(n ? n : 1) * (size_t)owidth * sizeof *buf;
    if (!(buf = PyMem_Malloc(bytes))) {
        PyErr_NoMemory();
        goto done;
    }
    const double *in = PyArray_DATA(x);
    int st = GA_OK;
    npy_intp bad = -1;
    memset(buf, 0, bytes); /* the pages, before the clock starts */
    double t0 = now_seconds(cpu);
    Py_BEGIN_ALLOW_THREADS;
    if (k == 5) { /* one call; a failure is reported at index 0 */
        ga_mv V;
        memcpy(V.c, PyArray_DATA(kt), sizeof V.c);
        if ((st = ga_versor_apply_many(V, (const ga_mv *)in, (size_t)n, (ga_mv *)buf)) != GA_OK)
            bad = 0;
    }
    /* a failed call writes nothing to e (the library's rule): e is read only
       after a success, and the loop stops at the first failure */
    for (npy_intp i = 0; k != 5 && i < n; i++) {
        double e[GA_GROUP_MAX_ELEM];
        if (k == 0) {
            if ((st = g->exp(in + 6 * i, e)) == GA_OK) {
                ga_mat4 M = g->to_mat4(e);
                memcpy(buf + 16 * i, M.m, sizeof M.m);
            }
        } else if (k == 1) {
            ga_mat4 M;
            memcpy(M.m, in + 16 * i, sizeof M.m);
            if ((st = g->from_mat4(M, e)) == GA_OK)
                st = g->log(e, buf + 16 * i);
        } else if (k == 3) {
            ga_mv a, b;
            memcpy(a.c, in + 32 * i, sizeof a.c);
            memcpy(b.c, (const double *)PyArray_DATA(kt) + 32 * i, sizeof b.c);
            ga_mv c = ga_mv_gp(a, b);
            memcpy(buf + 32 * i, c.c, sizeof c.c);
        } else if (k == 6) {
            double a[GA_GROUP_MAX_ELEM], b[GA_GROUP_MAX_ELEM];
            ga_mat4 A, B;
            memcpy(A.m, in + 16 * i, sizeof A.m);
            memcpy(B.m, (const double *)PyArray_DATA(kt) + 16 * i, sizeof B.m);
            if ((st = g->from_mat4(A, a)) == GA_OK && (st = g->from_mat4(B, b)) == GA_OK) {
                g->compose(a, b, e);
                ga_mat4 M = g->to_mat4(e);
                memcpy(buf + 16 * i, M.m, sizeof M.m);
            }
        } else if (k == 4) {
            ga_mv V, X, Y;
            memcpy(V.c, PyArray_DATA(kt), sizeof V.c);
            memcpy(X.c, in + 32 * i, sizeof X.c);
            if ((st = ga_versor_apply(V, X, &Y)) == GA_OK)
                memcpy(buf + 32 * i, Y.c, sizeof Y.c);
        } else if ((st = ga_path_sample(&path, GA_EVAL_DIRECT, 1.0, 1, in + i, e)) == GA_OK) {
            ga_mat4 M = g->to_mat4(e);
            memcpy(buf + 16 * i, M.m, sizeof M.m);
        }
        if (st != GA_OK) {
            bad = i;
            break;
        }
    }
    Py_END_ALLOW_THREADS;
    double dt = now_seconds(cpu) - t0;
    if (bad >= 0)
        PyErr_Format(PyExc_ValueError, "c_loop: index %zd: %s", (Py_ssize_t)bad, ga_status_string(st));
    else
        ret = PyFloat_FromDouble(dt);
done:
    PyMem_Free(buf);
    PyMem_Free(work);
    Py_XDECREF(x);
    Py_XDECREF(kt);
    Py_XDECREF(kk);
    return ret;
}

static PyMethodDef methods[] = {
    {"c_loop", c_loop, METH_VARARGS,
     "c_loop(kind, x, keytimes=None, keys=None, cpu=False): seconds of the plain C loop (python/bench.py)."},
    {NULL, NULL, 0, NULL}};

static struct PyModuleDef bench_module = {PyModuleDef_HEAD_INIT,
                                          "_garotor_bench",
                                          "python/bench.py's plain C loop; not part of garotor.",
                                          -1,
                                          methods,
                                          NULL,
                                          NULL,
                                          NULL,
                                          NULL};

PyMODINIT_FUNC PyInit__garotor_bench(void)
{
    import_array();
    return PyModule_Create(&bench_module);
}
