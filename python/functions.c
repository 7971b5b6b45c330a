/* python/functions.c: the module's element-wise functions (docs/python.md,
 * "Calls"): exp, log, compose, inverse, apply on a group; quaternions, poses
 * and dual quaternions (cga, through the rotor); conformal points up and
 * down. Each is a kernel for one element (gpy_k_*, which ufuncs.c's
 * generalized ufuncs run too) and a function that parses its arguments and
 * hands both to gpy_run_kernel (kernel.c).
 */
#include "module.h"

#include <math.h>

/* ---- on a group: exp, log, compose, inverse, apply ------------------------- */

/* exp: a twist (rigid groups) or a 4x4 with last row zero (affine) */
int gpy_k_exp(void *ctx, const double *const *in, double *out, npy_intp k)
{
    (void)k;
    const ga_group *g = ctx;
    double x[GA_GROUP_MAX_DIM], e[GA_GROUP_MAX_ELEM];
    if (g->rigid)
        memcpy(x, in[0], 6 * sizeof *x);
    else if (g->vee(gpy_mat_get(in[0]), x) != GA_OK)
        return GA_ERR_ARG;
    int st = g->exp(x, e);
    if (st == GA_OK)
        gpy_mat_put(g->to_mat4(e), out);
    return st;
}

int gpy_k_log(void *ctx, const double *const *in, double *out, npy_intp k)
{
    (void)k;
    const ga_group *g = ctx;
    double x[GA_GROUP_MAX_DIM], e[GA_GROUP_MAX_ELEM];
    int st = g->from_mat4(gpy_mat_get(in[0]), e);
    if (st == GA_OK)
        st = g->log(e, x);
    if (st != GA_OK)
        return st;
    if (g->rigid)
        memcpy(out, x, 6 * sizeof *x);
    else
        gpy_mat_put(g->hat(x), out);
    return GA_OK;
}

int gpy_k_compose(void *ctx, const double *const *in, double *out, npy_intp k)
{
    (void)k;
    const ga_group *g = ctx;
    double a[GA_GROUP_MAX_ELEM], b[GA_GROUP_MAX_ELEM], c[GA_GROUP_MAX_ELEM];
    int st = g->from_mat4(gpy_mat_get(in[0]), a);
    if (st == GA_OK)
        st = g->from_mat4(gpy_mat_get(in[1]), b);
    if (st != GA_OK)
        return st;
    g->compose(a, b, c);
    gpy_mat_put(g->to_mat4(c), out);
    return GA_OK;
}

int gpy_k_inverse(void *ctx, const double *const *in, double *out, npy_intp k)
{
    (void)k;
    const ga_group *g = ctx;
    double a[GA_GROUP_MAX_ELEM], b[GA_GROUP_MAX_ELEM];
    int st = g->from_mat4(gpy_mat_get(in[0]), a);
    if (st == GA_OK)
        st = g->inverse(a, b);
    if (st == GA_OK)
        gpy_mat_put(g->to_mat4(b), out);
    return st;
}

int gpy_k_apply(void *ctx, const double *const *in, double *out, npy_intp k)
{
    (void)k;
    const ga_group *g = ctx;
    double a[GA_GROUP_MAX_ELEM];
    int st = g->from_mat4(gpy_mat_get(in[0]), a);
    if (st != GA_OK)
        return st;
    /* the batch functions on one point: the numbers of gpy_apply_many */
    ga_vec3 x = {in[1][0], in[1][1], in[1][2]}, y;
    if (g == &ga_group_cga)
        st = ga_rotor_apply_many(*(const ga_rotor *)a, &x, 1, &y);
    else
        st = ga_mat4_apply_many(g->to_mat4(a), &x, 1, &y);
    out[0] = y.x, out[1] = y.y, out[2] = y.z;
    return st;
}

/* One motion T, n points: T converted once, then the batch (cga: the rotor's
   matrix, ga_rotor_apply_many; the others: the group's matrix,
   ga_mat4_apply_many), 9 multiplications and 9 additions a point. x and y
   are n ga_vec3 in C order (y may be x: each point is read before it is
   written). */
int gpy_apply_many(void *ctx, const double *T, const double *x, npy_intp n, double *y)
{
    const ga_group *g = ctx;
    double a[GA_GROUP_MAX_ELEM];
    int st = g->from_mat4(gpy_mat_get(T), a);
    if (st != GA_OK)
        return st;
    if (g == &ga_group_cga)
        return ga_rotor_apply_many(*(const ga_rotor *)a, (const ga_vec3 *)x, (size_t)n, (ga_vec3 *)y);
    return ga_mat4_apply_many(g->to_mat4(a), (const ga_vec3 *)x, (size_t)n, (ga_vec3 *)y);
}

/* ---- quaternions, poses, dual quaternions (cga: through the rotor) --------- */

/* A unit quaternion to 1e-9, as the tool reads poses. */
static int quat_check(ga_quat q)
{
    if (!(isfinite(q.w) && isfinite(q.x) && isfinite(q.y) && isfinite(q.z)))
        return GA_ERR_NOTFINITE;
    double norm = sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
    return fabs(norm - 1.0) > 1e-9 ? GA_ERR_NOTRIGID : GA_OK;
}

int gpy_pose_to_mat(const double *v, ga_mat4 *m)
{
    ga_quat q = {v[6], v[3], v[4], v[5]};
    int st = quat_check(q);
    if (st == GA_OK && !(isfinite(v[0]) && isfinite(v[1]) && isfinite(v[2])))
        st = GA_ERR_NOTFINITE;
    if (st == GA_OK)
        *m = ga_rotor_to_mat4(ga_rotor_from_quat(q, (ga_vec3){v[0], v[1], v[2]}));
    return st;
}

int gpy_k_from_quat(void *ctx, const double *const *in, double *out, npy_intp k)
{
    (void)ctx, (void)k;
    const double *q = in[0], *t = in[1];
    double v[7] = {t[0], t[1], t[2], q[0], q[1], q[2], q[3]};
    ga_mat4 m;
    int st = gpy_pose_to_mat(v, &m);
    if (st == GA_OK)
        gpy_mat_put(m, out);
    return st;
}

int gpy_k_from_pose(void *ctx, const double *const *in, double *out, npy_intp k)
{
    (void)ctx, (void)k;
    ga_mat4 m;
    int st = gpy_pose_to_mat(in[0], &m);
    if (st == GA_OK)
        gpy_mat_put(m, out);
    return st;
}

int gpy_k_to_quat(void *ctx, const double *const *in, double *out, npy_intp k)
{
    (void)ctx, (void)k;
    ga_rotor r;
    int st = ga_rotor_from_mat4(gpy_mat_get(in[0]), &r);
    if (st != GA_OK)
        return st;
    ga_quat q = ga_rotor_to_quat(r);
    out[0] = q.x, out[1] = q.y, out[2] = q.z, out[3] = q.w;
    return GA_OK;
}

/* to_pose: the quaternion's sign follows the previous element along the last
 * leading axis (as the tool keeps it continuous), starting from w >= 0
 * (gpy_pose_ctx, module.h) */

int gpy_k_to_pose(void *ctx, const double *const *in, double *out, npy_intp k)
{
    gpy_pose_ctx *c = ctx;
    ga_mat4 m = gpy_mat_get(in[0]);
    ga_rotor r;
    int st = ga_rotor_from_mat4(m, &r);
    if (st != GA_OK)
        return st;
    ga_quat q = ga_rotor_to_quat(r);
    if (c->run == 0 || k % c->run == 0)
        c->prev = (ga_quat){1, 0, 0, 0};
    if (q.w * c->prev.w + q.x * c->prev.x + q.y * c->prev.y + q.z * c->prev.z < 0.0)
        q = (ga_quat){-q.w, -q.x, -q.y, -q.z};
    c->prev = q;
    double v[7] = {m.m[3], m.m[7], m.m[11], q.x, q.y, q.z, q.w};
    memcpy(out, v, sizeof v);
    return GA_OK;
}

/* dual quaternions as 8 numbers: real (x y z w), then dual (x y z w) */
int gpy_k_to_dualquat(void *ctx, const double *const *in, double *out, npy_intp k)
{
    (void)ctx, (void)k;
    ga_rotor r;
    int st = ga_rotor_from_mat4(gpy_mat_get(in[0]), &r);
    if (st != GA_OK)
        return st;
    ga_dualquat d = ga_rotor_to_dualquat(r);
    double v[8] = {d.real.x, d.real.y, d.real.z, d.real.w, d.dual.x, d.dual.y, d.dual.z, d.dual.w};
    memcpy(out, v, sizeof v);
    return GA_OK;
}

int gpy_k_from_dualquat(void *ctx, const double *const *in, double *out, npy_intp k)
{
    (void)ctx, (void)k;
    const double *v = in[0];
    ga_dualquat d = {{v[3], v[0], v[1], v[2]}, {v[7], v[4], v[5], v[6]}};
    ga_rotor r = ga_rotor_from_dualquat(d);
    int st = ga_rotor_check(r, 1e-9);
    if (st == GA_OK)
        gpy_mat_put(ga_rotor_to_mat4(r), out);
    return st;
}

/* ---- points ---------------------------------------------------------------- */

int gpy_k_up(void *ctx, const double *const *in, double *out, npy_intp k)
{
    (void)ctx, (void)k;
    const double *x = in[0];
    ga_mv X = ga_point_up((ga_vec3){x[0], x[1], x[2]});
    memcpy(out, X.c, sizeof X.c);
    return GA_OK;
}

int gpy_k_down(void *ctx, const double *const *in, double *out, npy_intp k)
{
    (void)ctx, (void)k;
    ga_mv X;
    memcpy(X.c, in[0], sizeof X.c);
    ga_vec3 x;
    int st = ga_point_down(X, &x);
    if (st == GA_OK)
        out[0] = x.x, out[1] = x.y, out[2] = x.z;
    return st;
}

/* ---- module functions ------------------------------------------------------ */

PyObject *gpy_exp(PyObject *self, PyObject *args, PyObject *kw)
{
    (void)self;
    static char *kwlist[] = {"xi", "group", "out", NULL};
    PyObject *xi, *out = NULL;
    const char *gname = NULL;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "O|s$O:exp", kwlist, &xi, &gname, &out))
        return NULL;
    const ga_group *g = gpy_group_arg("exp", gname);
    if (!g)
        return NULL;
    gpy_kernel_call kc = {.what = "exp",
                          .nin = 1,
                          .in = {g->rigid ? (gpy_core)GPY_CORE1(6, "xi") : (gpy_core)GPY_CORE2(4, 4, "xi")},
                          .out = GPY_CORE2(4, 4, NULL),
                          .kernel = gpy_k_exp,
                          .ctx = (void *)g};
    return gpy_run_kernel(&kc, &xi, out);
}

PyObject *gpy_log(PyObject *self, PyObject *args, PyObject *kw)
{
    (void)self;
    static char *kwlist[] = {"T", "group", "out", NULL};
    PyObject *T, *out = NULL;
    const char *gname = NULL;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "O|s$O:log", kwlist, &T, &gname, &out))
        return NULL;
    const ga_group *g = gpy_group_arg("log", gname);
    if (!g)
        return NULL;
    gpy_kernel_call kc = {.what = "log",
                          .nin = 1,
                          .in = {GPY_CORE2(4, 4, "T")},
                          .out = g->rigid ? (gpy_core)GPY_CORE1(6, NULL) : (gpy_core)GPY_CORE2(4, 4, NULL),
                          .kernel = gpy_k_log,
                          .ctx = (void *)g};
    return gpy_run_kernel(&kc, &T, out);
}

PyObject *gpy_compose(PyObject *self, PyObject *args, PyObject *kw)
{
    (void)self;
    static char *kwlist[] = {"A", "B", "group", "out", NULL};
    PyObject *in[2], *out = NULL;
    const char *gname = NULL;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "OO|s$O:compose", kwlist, &in[0], &in[1], &gname, &out))
        return NULL;
    const ga_group *g = gpy_group_arg("compose", gname);
    if (!g)
        return NULL;
    gpy_kernel_call kc = {.what = "compose",
                          .nin = 2,
                          .in = {GPY_CORE2(4, 4, "A"), GPY_CORE2(4, 4, "B")},
                          .out = GPY_CORE2(4, 4, NULL),
                          .kernel = gpy_k_compose,
                          .ctx = (void *)g};
    return gpy_run_kernel(&kc, in, out);
}

PyObject *gpy_inverse(PyObject *self, PyObject *args, PyObject *kw)
{
    (void)self;
    static char *kwlist[] = {"T", "group", "out", NULL};
    PyObject *T, *out = NULL;
    const char *gname = NULL;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "O|s$O:inverse", kwlist, &T, &gname, &out))
        return NULL;
    const ga_group *g = gpy_group_arg("inverse", gname);
    if (!g)
        return NULL;
    gpy_kernel_call kc = {.what = "inverse",
                          .nin = 1,
                          .in = {GPY_CORE2(4, 4, "T")},
                          .out = GPY_CORE2(4, 4, NULL),
                          .kernel = gpy_k_inverse,
                          .ctx = (void *)g};
    return gpy_run_kernel(&kc, &T, out);
}

PyObject *gpy_apply(PyObject *self, PyObject *args, PyObject *kw)
{
    (void)self;
    static char *kwlist[] = {"T", "points", "group", "out", NULL};
    PyObject *in[2], *out = NULL;
    const char *gname = NULL;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "OO|s$O:apply", kwlist, &in[0], &in[1], &gname, &out))
        return NULL;
    const ga_group *g = gpy_group_arg("apply", gname);
    if (!g)
        return NULL;
    gpy_kernel_call kc = {.what = "apply",
                          .nin = 2,
                          .in = {GPY_CORE2(4, 4, "T"), GPY_CORE1(3, "points")},
                          .out = GPY_CORE1(3, NULL),
                          .kernel = gpy_k_apply,
                          .many = gpy_apply_many,
                          .ctx = (void *)g};
    return gpy_run_kernel(&kc, in, out);
}

PyObject *gpy_from_quat(PyObject *self, PyObject *args, PyObject *kw)
{
    (void)self;
    static char *kwlist[] = {"q", "t", "out", NULL};
    PyObject *in[2] = {NULL, NULL}, *out = NULL, *zero = NULL;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "O|O$O:from_quat", kwlist, &in[0], &in[1], &out))
        return NULL;
    if (!in[1] || in[1] == Py_None) {
        npy_intp three = 3;
        in[1] = zero = PyArray_ZEROS(1, &three, NPY_DOUBLE, 0);
        if (!zero)
            return NULL;
    }
    gpy_kernel_call kc = {.what = "from_quat",
                          .nin = 2,
                          .in = {GPY_CORE1(4, "q"), GPY_CORE1(3, "t")},
                          .out = GPY_CORE2(4, 4, NULL),
                          .kernel = gpy_k_from_quat};
    PyObject *r = gpy_run_kernel(&kc, in, out);
    Py_XDECREF(zero);
    return r;
}

#define ONE_INPUT_FN(fname, argname, incore, outcore, kern)                                                  \
    PyObject *gpy_##fname(PyObject *self, PyObject *args, PyObject *kw)                                      \
    {                                                                                                        \
        (void)self;                                                                                          \
        static char *kwlist[] = {argname, "out", NULL};                                                      \
        PyObject *x, *out = NULL;                                                                            \
        if (!PyArg_ParseTupleAndKeywords(args, kw, "O|$O:" #fname, kwlist, &x, &out))                        \
            return NULL;                                                                                     \
        gpy_kernel_call kc = {.what = #fname, .nin = 1, .in = {incore}, .out = outcore, .kernel = kern};     \
        return gpy_run_kernel(&kc, &x, out);                                                                 \
    }

ONE_INPUT_FN(to_quat, "T", GPY_CORE2(4, 4, "T"), GPY_CORE1(4, NULL), gpy_k_to_quat)
ONE_INPUT_FN(from_pose, "poses", GPY_CORE1(7, "poses"), GPY_CORE2(4, 4, NULL), gpy_k_from_pose)
ONE_INPUT_FN(to_dualquat, "T", GPY_CORE2(4, 4, "T"), GPY_CORE1(8, NULL), gpy_k_to_dualquat)
ONE_INPUT_FN(from_dualquat, "d", GPY_CORE1(8, "d"), GPY_CORE2(4, 4, NULL), gpy_k_from_dualquat)
ONE_INPUT_FN(up, "x", GPY_CORE1(3, "x"), GPY_CORE1(32, NULL), gpy_k_up)
ONE_INPUT_FN(down, "X", GPY_CORE1(32, "X"), GPY_CORE1(3, NULL), gpy_k_down)

PyObject *gpy_to_pose(PyObject *self, PyObject *args, PyObject *kw)
{
    (void)self;
    static char *kwlist[] = {"T", "continuous", "out", NULL};
    PyObject *T, *out = NULL;
    int continuous = 1;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "O|p$O:to_pose", kwlist, &T, &continuous, &out))
        return NULL;
    /* the run length is T's last leading dimension (one input: no
     * broadcast); the kernel reads it through the context */
    gpy_pose_ctx c = {0, {1, 0, 0, 0}};
    PyArrayObject *a = gpy_as_doubles(T);
    if (!a)
        return NULL;
    if (continuous && PyArray_NDIM(a) >= 3)
        c.run = PyArray_DIM(a, PyArray_NDIM(a) - 3);
    gpy_kernel_call kc = {.what = "to_pose",
                          .nin = 1,
                          .in = {GPY_CORE2(4, 4, "T")},
                          .out = GPY_CORE1(7, NULL),
                          .kernel = gpy_k_to_pose,
                          .ctx = &c};
    PyObject *r = gpy_run_kernel(&kc, (PyObject **)&a, out);
    Py_DECREF(a);
    return r;
}
