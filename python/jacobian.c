/* python/jacobian.c: the module's Lie-group Jacobians (docs/python.md,
 * "Jacobians"), element-wise over numpy arrays as the other calls are:
 * jr, jl, jr_inverse, jl_inverse and ad of twists (..., 6) -> (..., 6, 6);
 * adjoint, jac_compose, jac_inverse, jac_between, jac_act and jac_log of
 * rigid motions (..., 4, 4) on group 'cga' (through the rotor, the ga_rotor_*
 * functions of jacobian.h) or 'matrix' (ga_se3_*), right or left. The table
 * gpy_jacobian_methods is added to the module by PyInit_garotor.
 */
#include "module.h"

/* ---- twists ------------------------------------------------------------------ */

enum { T_JR, T_JL, T_JR_INV, T_JL_INV, T_AD };

static int k_twist(void *ctx, const double *const *in, double *out, npy_intp k)
{
    (void)k;
    const double *x = in[0];
    ga_twist xi = {{x[0], x[1], x[2]}, {x[3], x[4], x[5]}};
    ga_mat6 j;
    int st = GA_OK;
    switch (*(const int *)ctx) {
    case T_JR: j = ga_twist_jr(xi); break;
    case T_JL: j = ga_twist_jl(xi); break;
    case T_JR_INV: st = ga_twist_jr_inverse(xi, &j); break;
    case T_JL_INV: st = ga_twist_jl_inverse(xi, &j); break;
    default: j = ga_twist_ad(xi); break;
    }
    if (st == GA_OK)
        memcpy(out, j.m, sizeof j.m);
    return st;
}

static void explain_twist(void *ctx, const double *const *in, int status, char *why, size_t size)
{
    (void)ctx;
    if (status == GA_ERR_DOMAIN) {
        const double *x = in[0];
        char num[32];
        snprintf(why, size, "the rotation angle |w| = %s is not below 2 pi",
                 gpy_repr_text(sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]), num));
    }
}

static PyObject *twist_call(const char *what, int kind, PyObject *args, PyObject *kw)
{
    static char *kwlist[] = {"xi", "out", NULL};
    PyObject *xi, *out = NULL;
    char fmt[48];
    snprintf(fmt, sizeof fmt, "O|$O:%s", what);
    if (!PyArg_ParseTupleAndKeywords(args, kw, fmt, kwlist, &xi, &out))
        return NULL;
    gpy_kernel_call kc = {.what = what,
                          .nin = 1,
                          .in = {GPY_CORE1(6, "xi")},
                          .out = GPY_CORE2(6, 6, NULL),
                          .kernel = k_twist,
                          .ctx = &kind,
                          .explain = explain_twist};
    return gpy_run_kernel(&kc, &xi, out);
}

static PyObject *py_jr(PyObject *s, PyObject *a, PyObject *k)
{
    return (void)s, twist_call("jr", T_JR, a, k);
}
static PyObject *py_jl(PyObject *s, PyObject *a, PyObject *k)
{
    return (void)s, twist_call("jl", T_JL, a, k);
}
static PyObject *py_jr_inverse(PyObject *s, PyObject *a, PyObject *k)
{
    return (void)s, twist_call("jr_inverse", T_JR_INV, a, k);
}
static PyObject *py_jl_inverse(PyObject *s, PyObject *a, PyObject *k)
{
    return (void)s, twist_call("jl_inverse", T_JL_INV, a, k);
}
static PyObject *py_ad(PyObject *s, PyObject *a, PyObject *k)
{
    return (void)s, twist_call("ad", T_AD, a, k);
}

/* ---- the affine algebra: (..., 4, 4) elements (last row ignored) -> (..., 12, 12) */

static int k_affine(void *ctx, const double *const *in, double *out, npy_intp k)
{
    (void)k;
    ga_mat4 x = gpy_mat_get(in[0]);
    ga_mat12 j;
    int st = GA_OK;
    for (int i = 0; i < 16; i++) /* the last row too, which ad ignores: no number passed over */
        if (!isfinite(x.m[i]))
            return GA_ERR_NOTFINITE;
    switch (*(const int *)ctx) {
    case T_JR: st = ga_affine_jr(x, &j); break;
    case T_JL: st = ga_affine_jl(x, &j); break;
    case T_JR_INV: st = ga_affine_jr_inverse(x, &j); break;
    case T_JL_INV: st = ga_affine_jl_inverse(x, &j); break;
    default: j = ga_affine_ad(x); break;
    }
    if (st == GA_OK)
        memcpy(out, j.m, sizeof j.m);
    return st;
}

static PyObject *affine_call(const char *what, int kind, PyObject *args, PyObject *kw)
{
    static char *kwlist[] = {"X", "out", NULL};
    PyObject *x, *out = NULL;
    char fmt[48];
    snprintf(fmt, sizeof fmt, "O|$O:%s", what);
    if (!PyArg_ParseTupleAndKeywords(args, kw, fmt, kwlist, &x, &out))
        return NULL;
    gpy_kernel_call kc = {.what = what,
                          .nin = 1,
                          .in = {GPY_CORE2(4, 4, "X")},
                          .out = GPY_CORE2(12, 12, NULL),
                          .kernel = k_affine,
                          .ctx = &kind};
    return gpy_run_kernel(&kc, &x, out);
}

static PyObject *py_affine_jr(PyObject *s, PyObject *a, PyObject *k)
{
    return (void)s, affine_call("affine_jr", T_JR, a, k);
}
static PyObject *py_affine_jl(PyObject *s, PyObject *a, PyObject *k)
{
    return (void)s, affine_call("affine_jl", T_JL, a, k);
}
static PyObject *py_affine_jr_inverse(PyObject *s, PyObject *a, PyObject *k)
{
    return (void)s, affine_call("affine_jr_inverse", T_JR_INV, a, k);
}
static PyObject *py_affine_jl_inverse(PyObject *s, PyObject *a, PyObject *k)
{
    return (void)s, affine_call("affine_jl_inverse", T_JL_INV, a, k);
}
static PyObject *py_affine_ad(PyObject *s, PyObject *a, PyObject *k)
{
    return (void)s, affine_call("affine_ad", T_AD, a, k);
}

/* ---- rigid motions ----------------------------------------------------------- */

enum { G_ADJOINT, G_COMPOSE, G_INVERSE, G_BETWEEN, G_ACT, G_LOG };

typedef struct {
    int op;
    int which; /* 0: the Jacobian of the first argument, 1: of the second */
    int rotor; /* 1: group cga (through the rotor), 0: matrix */
    ga_jac_side side;
    int affine; /* 1: group affine (ga_affine_*, 12x12) */
} group_ctx;

/* the affine group's Jacobians (ga_affine_*) */
static int k_group_affine(const group_ctx *c, const double *const *in, double *out)
{
    ga_mat4 a = gpy_mat_get(in[0]), b = a;
    ga_vec3 p = {0, 0, 0};
    if (c->op == G_COMPOSE || c->op == G_BETWEEN)
        b = gpy_mat_get(in[1]);
    if (c->op == G_ACT)
        p = (ga_vec3){in[1][0], in[1][1], in[1][2]};
    ga_mat12 j1, j2;
    ga_mat3x12 ja;
    ga_mat3 jp;
    int st;
    switch (c->op) {
    case G_ADJOINT: st = ga_affine_adjoint_matrix(a, &j1); break;
    case G_COMPOSE: st = ga_affine_jac_compose(a, b, c->side, &j1, &j2); break;
    case G_INVERSE: st = ga_affine_jac_inverse(a, c->side, &j1); break;
    case G_BETWEEN: st = ga_affine_jac_between(a, b, c->side, &j1, &j2); break;
    case G_ACT:
        st = ga_affine_jac_act(a, p, c->side, &ja, &jp);
        if (st == GA_OK) {
            if (c->which)
                memcpy(out, jp.m, sizeof jp.m);
            else
                memcpy(out, ja.m, sizeof ja.m);
        }
        return st;
    default: st = ga_affine_jac_log(a, c->side, &j1); break;
    }
    if (st == GA_OK)
        memcpy(out, c->which ? j2.m : j1.m, sizeof j1.m);
    return st;
}

static int k_group(void *ctx, const double *const *in, double *out, npy_intp k)
{
    (void)k;
    const group_ctx *c = ctx;
    if (c->affine)
        return k_group_affine(c, in, out);
    ga_mat4 a = gpy_mat_get(in[0]), b = a;
    ga_rotor ra = {0}, rb = {0};
    ga_vec3 p = {0, 0, 0};
    int st = GA_OK;
    if (c->op == G_COMPOSE || c->op == G_BETWEEN)
        b = gpy_mat_get(in[1]);
    if (c->op == G_ACT)
        p = (ga_vec3){in[1][0], in[1][1], in[1][2]};
    if (c->rotor) {
        st = ga_rotor_from_mat4(a, &ra);
        if (st == GA_OK)
            st = ga_rotor_from_mat4(b, &rb);
    } else if (c->op == G_ADJOINT) {
        st = ga_se3_check(a, GA_SE3_TOL);
    }
    if (st != GA_OK)
        return st;
    ga_mat6 j1, j2;
    ga_mat36 ja;
    ga_mat3 jp;
    switch (c->op) {
    case G_ADJOINT: j1 = c->rotor ? ga_rotor_adjoint_matrix(ra) : ga_se3_adjoint_matrix(a); break;
    case G_COMPOSE:
        st = c->rotor ? ga_rotor_jac_compose(ra, rb, c->side, &j1, &j2)
                      : ga_se3_jac_compose(a, b, c->side, &j1, &j2);
        break;
    case G_INVERSE:
        st = c->rotor ? ga_rotor_jac_inverse(ra, c->side, &j1) : ga_se3_jac_inverse(a, c->side, &j1);
        break;
    case G_BETWEEN:
        st = c->rotor ? ga_rotor_jac_between(ra, rb, c->side, &j1, &j2)
                      : ga_se3_jac_between(a, b, c->side, &j1, &j2);
        break;
    case G_ACT:
        st = c->rotor ? ga_rotor_jac_act(ra, p, c->side, &ja, &jp) : ga_se3_jac_act(a, p, c->side, &ja, &jp);
        if (st == GA_OK) {
            if (c->which)
                memcpy(out, jp.m, sizeof jp.m);
            else
                memcpy(out, ja.m, sizeof ja.m);
        }
        return st;
    default: st = c->rotor ? ga_rotor_jac_log(ra, c->side, &j1) : ga_se3_jac_log(a, c->side, &j1); break;
    }
    if (st == GA_OK)
        memcpy(out, c->which ? j2.m : j1.m, sizeof j1.m);
    return st;
}

/* the group and side arguments: 0, or -1 with a ValueError */
static int group_args(const char *what, const char *gname, const char *sname, group_ctx *c)
{
    const ga_group *g = gpy_group_arg(what, gname);
    if (!g)
        return -1;
    c->affine = g == &ga_group_affine;
    if (!g->rigid && !c->affine) {
        PyErr_Format(PyExc_ValueError, "%s: group must be 'cga', 'matrix' or 'affine', not '%s'", what,
                     g->name);
        return -1;
    }
    c->rotor = g == &ga_group_cga;
    if (!sname || strcmp(sname, "right") == 0)
        c->side = GA_JAC_RIGHT;
    else if (strcmp(sname, "left") == 0)
        c->side = GA_JAC_LEFT;
    else {
        PyErr_Format(PyExc_ValueError, "%s: side must be 'right' or 'left', not '%s'", what, sname);
        return -1;
    }
    return 0;
}

/* one call: nin inputs (names[]), the op's one or two Jacobians */
static PyObject *group_call(const char *what, int op, PyObject *args, PyObject *kw)
{
    int nin = op == G_COMPOSE || op == G_BETWEEN || op == G_ACT ? 2 : 1;
    int nout = nin == 2 ? 2 : 1;
    static char *kw1[] = {"T", "group", "side", NULL};
    static char *kw2[] = {"A", "B", "group", "side", NULL};
    static char *kwact[] = {"T", "points", "group", "side", NULL};
    PyObject *in[2] = {NULL, NULL};
    const char *gname = NULL, *sname = NULL;
    char fmt[48];
    int ok;
    if (nin == 1) {
        snprintf(fmt, sizeof fmt, "O|ss:%s", what);
        ok = PyArg_ParseTupleAndKeywords(args, kw, fmt, kw1, &in[0], &gname, &sname);
    } else {
        snprintf(fmt, sizeof fmt, "OO|ss:%s", what);
        ok = PyArg_ParseTupleAndKeywords(args, kw, fmt, op == G_ACT ? kwact : kw2, &in[0], &in[1], &gname,
                                         &sname);
    }
    if (!ok)
        return NULL;
    group_ctx c = {op, 0, 0, GA_JAC_RIGHT, 0};
    if (group_args(what, gname, sname, &c) < 0)
        return NULL;
    if (op == G_ADJOINT && sname) {
        PyErr_Format(PyExc_ValueError, "%s: takes no side", what);
        return NULL;
    }
    PyObject *res[2] = {NULL, NULL};
    for (int w = 0; w < nout; w++) {
        c.which = w;
        gpy_kernel_call kc = {.what = what, .nin = nin, .kernel = k_group, .ctx = &c};
        kc.in[0] = (gpy_core)GPY_CORE2(4, 4, op == G_ACT ? "T" : nin == 2 ? "A" : "T");
        if (nin == 2)
            kc.in[1] = op == G_ACT ? (gpy_core)GPY_CORE1(3, "points") : (gpy_core)GPY_CORE2(4, 4, "B");
        npy_intp d = c.affine ? 12 : 6;
        kc.out = op == G_ACT ? (w ? (gpy_core)GPY_CORE2(3, 3, NULL) : (gpy_core)GPY_CORE2(3, d, NULL))
                             : (gpy_core)GPY_CORE2(d, d, NULL);
        res[w] = gpy_run_kernel(&kc, in, NULL);
        if (!res[w]) {
            Py_XDECREF(res[0]);
            return NULL;
        }
    }
    if (nout == 1)
        return res[0];
    PyObject *t = PyTuple_Pack(2, res[0], res[1]);
    Py_DECREF(res[0]);
    Py_DECREF(res[1]);
    return t;
}

static PyObject *py_adjoint(PyObject *s, PyObject *a, PyObject *k)
{
    return (void)s, group_call("adjoint", G_ADJOINT, a, k);
}
static PyObject *py_jac_compose(PyObject *s, PyObject *a, PyObject *k)
{
    return (void)s, group_call("jac_compose", G_COMPOSE, a, k);
}
static PyObject *py_jac_inverse(PyObject *s, PyObject *a, PyObject *k)
{
    return (void)s, group_call("jac_inverse", G_INVERSE, a, k);
}
static PyObject *py_jac_between(PyObject *s, PyObject *a, PyObject *k)
{
    return (void)s, group_call("jac_between", G_BETWEEN, a, k);
}
static PyObject *py_jac_act(PyObject *s, PyObject *a, PyObject *k)
{
    return (void)s, group_call("jac_act", G_ACT, a, k);
}
static PyObject *py_jac_log(PyObject *s, PyObject *a, PyObject *k)
{
    return (void)s, group_call("jac_log", G_LOG, a, k);
}

#define KW (METH_VARARGS | METH_KEYWORDS)
#define FN(f) (PyCFunction)(void (*)(void))(f)

PyMethodDef gpy_jacobian_methods[] = {
    {"jr", FN(py_jr), KW,
     "jr(xi, *, out=None): the right Jacobian of exp at twists (..., 6) (w, v order) -> (..., 6, 6):\n"
     "exp(xi + d) = exp(xi) exp(jr(xi) d) to first order."},
    {"jl", FN(py_jl), KW,
     "jl(xi, *, out=None): the left Jacobian of exp, jl(xi) = jr(-xi): exp(xi + d) = exp(jl(xi) d) exp(xi)."},
    {"jr_inverse", FN(py_jr_inverse), KW,
     "jr_inverse(xi, *, out=None): the inverse of jr(xi), for a rotation angle |w| below 2 pi."},
    {"jl_inverse", FN(py_jl_inverse), KW,
     "jl_inverse(xi, *, out=None): the inverse of jl(xi), for a rotation angle |w| below 2 pi."},
    {"ad", FN(py_ad), KW, "ad(xi, *, out=None): the small adjoint [[w]x, 0; [v]x, [w]x] (..., 6, 6)."},
    {"affine_jr", FN(py_affine_jr), KW,
     "affine_jr(X, *, out=None): the right Jacobian of expm at affine algebra elements (..., 4, 4)\n"
     "(last row ignored; coordinates the 12 entries of rows 0..2) -> (..., 12, 12)."},
    {"affine_jl", FN(py_affine_jl), KW, "affine_jl(X, *, out=None): the left Jacobian, affine_jr(-X)."},
    {"affine_jr_inverse", FN(py_affine_jr_inverse), KW,
     "affine_jr_inverse(X, *, out=None): the inverse of affine_jr(X) (singular where eigenvalues of ad X\n"
     "are 2 pi i k apart)."},
    {"affine_jl_inverse", FN(py_affine_jl_inverse), KW,
     "affine_jl_inverse(X, *, out=None): the inverse of affine_jl(X)."},
    {"affine_ad", FN(py_affine_ad), KW,
     "affine_ad(X, *, out=None): the small adjoint of the affine algebra, Y -> X Y - Y X (..., 12, 12)."},
    {"adjoint", FN(py_adjoint), KW,
     "adjoint(T, group='cga'): Ad(T) = [R, 0; [t]x R, R] of rigid motions (..., 4, 4) -> (..., 6, 6);\n"
     "group='affine': Y -> T Y T^-1 (..., 12, 12). The jac_* below take group='affine' as well\n"
     "(12 x 12 Jacobians, 3 x 12 for the point's)."},
    {"jac_compose", FN(py_jac_compose), KW,
     "jac_compose(A, B, group='cga', side='right'): the Jacobians (J_A, J_B) of A B, each (..., 6, 6)."},
    {"jac_inverse", FN(py_jac_inverse), KW,
     "jac_inverse(T, group='cga', side='right'): the Jacobian of T^-1 (..., 6, 6)."},
    {"jac_between", FN(py_jac_between), KW,
     "jac_between(A, B, group='cga', side='right'): the Jacobians (J_A, J_B) of A^-1 B."},
    {"jac_act", FN(py_jac_act), KW,
     "jac_act(T, points, group='cga', side='right'): the Jacobians (J_T (..., 3, 6), J_p (..., 3, 3))\n"
     "of the moved point T p."},
    {"jac_log", FN(py_jac_log), KW,
     "jac_log(T, group='cga', side='right'): the Jacobian of the principal log, jr_inverse(log T)\n"
     "(right) or jl_inverse(log T) (left)."},
    {NULL, NULL, 0, NULL}};
