/* python/mvarray.c: garotor.MultivectorArray, an array of multivectors of
 * G(4,1) (docs/python.md, "MultivectorArray"): a read-only float64 array of
 * shape (..., 32) whose products, exp and log, versor sandwich, read-back
 * and points each run as one C loop over the elements (gpy_run_kernel,
 * kernel.c: broadcasting, the GIL released, the first bad element named by
 * its index). The per-element kernels (gpy_k_gp, ...) are the ones the
 * generalized ufuncs of ufuncs.c run, and each is one call of the C function
 * that Multivector's method calls, so every element is Multivector's answer
 * bit for bit.
 */
#include "module.h"

#include <math.h>

/* ---- the kernels: one multivector (or two) per element ------------------ */

static inline ga_mv mv_at(const double *p)
{
    ga_mv m;
    memcpy(m.c, p, sizeof m.c);
    return m;
}

static inline void mv_put(ga_mv m, double *out) { memcpy(out, m.c, sizeof m.c); }

#define K_BINARY(name, fn)                                                                                   \
    int gpy_k_##name(void *ctx, const double *const *in, double *out, npy_intp k)                            \
    {                                                                                                        \
        (void)ctx, (void)k;                                                                                  \
        mv_put(fn(mv_at(in[0]), mv_at(in[1])), out);                                                         \
        return GA_OK;                                                                                        \
    }
#define K_BINARY_STATUS(name, fn)                                                                            \
    int gpy_k_##name(void *ctx, const double *const *in, double *out, npy_intp k)                            \
    {                                                                                                        \
        (void)ctx, (void)k;                                                                                  \
        ga_mv r;                                                                                             \
        int st = fn(mv_at(in[0]), mv_at(in[1]), &r);                                                         \
        if (st == GA_OK)                                                                                     \
            mv_put(r, out);                                                                                  \
        return st;                                                                                           \
    }
#define K_UNARY(name, fn)                                                                                    \
    int gpy_k_##name(void *ctx, const double *const *in, double *out, npy_intp k)                            \
    {                                                                                                        \
        (void)ctx, (void)k;                                                                                  \
        mv_put(fn(mv_at(in[0])), out);                                                                       \
        return GA_OK;                                                                                        \
    }
#define K_UNARY_STATUS(name, fn)                                                                             \
    int gpy_k_##name(void *ctx, const double *const *in, double *out, npy_intp k)                            \
    {                                                                                                        \
        (void)ctx, (void)k;                                                                                  \
        ga_mv r;                                                                                             \
        int st = fn(mv_at(in[0]), &r);                                                                       \
        if (st == GA_OK)                                                                                     \
            mv_put(r, out);                                                                                  \
        return st;                                                                                           \
    }

K_BINARY(gp, ga_mv_gp)
K_BINARY(op, ga_mv_op)
K_BINARY(lc, ga_mv_lc)
K_BINARY(dot, ga_mv_dot)
K_BINARY(ip, ga_mv_ip)
K_BINARY(regressive, ga_mv_regressive)
K_BINARY(commutator, ga_mv_commutator)
K_BINARY(meet, ga_mv_meet)
K_BINARY(add, ga_mv_add)
K_BINARY(sub, ga_mv_sub)
K_BINARY_STATUS(join, ga_mv_join)
K_BINARY_STATUS(meet_rel, ga_mv_meet_rel)
K_BINARY_STATUS(project, ga_mv_project)
K_BINARY_STATUS(reject, ga_mv_reject)
K_BINARY_STATUS(versor_apply, ga_versor_apply)

/* One versor V, n multivectors (gpy_kernel_call.many): ga_versor_apply_many,
   V's checks and inverse once, each result what gpy_k_versor_apply gives, bit
   for bit (versor.h). X and out are n ga_mv in C order (out may be X). */
int gpy_versor_apply_many(void *ctx, const double *V, const double *X, npy_intp n, double *out)
{
    (void)ctx;
    return ga_versor_apply_many(mv_at(V), (const ga_mv *)X, (size_t)n, (ga_mv *)out);
}
K_UNARY(reverse, ga_mv_reverse)
K_UNARY(involute, ga_mv_involute)
K_UNARY(conjugate, ga_mv_conjugate)
K_UNARY(dual, ga_mv_dual)
K_UNARY(undual, ga_mv_undual)
K_UNARY_STATUS(mv_inverse, ga_mv_inverse)
K_UNARY_STATUS(mv_exp, gpy_mv_exp)
K_UNARY_STATUS(mv_log, gpy_mv_log)
K_UNARY_STATUS(mv_sqrt, ga_mv_sqrt)

/* -a, as Multivector's unary minus */
static int k_neg(void *ctx, const double *const *in, double *out, npy_intp k)
{
    (void)ctx, (void)k;
    mv_put(ga_mv_scale(mv_at(in[0]), -1.0), out);
    return GA_OK;
}

/* the grade-k part, k (an int) in ctx */
static int k_grade(void *ctx, const double *const *in, double *out, npy_intp k)
{
    (void)k;
    mv_put(ga_mv_grade(mv_at(in[0]), *(const int *)ctx), out);
    return GA_OK;
}

int gpy_k_norm2(void *ctx, const double *const *in, double *out, npy_intp k)
{
    (void)ctx, (void)k;
    out[0] = ga_mv_norm2(mv_at(in[0]));
    return GA_OK;
}

/* R^t: the rotor in[0], the number in[1] */
int gpy_k_mv_pow(void *ctx, const double *const *in, double *out, npy_intp k)
{
    (void)ctx, (void)k;
    ga_mv r;
    int st = ga_mv_pow(mv_at(in[0]), in[1][0], &r);
    if (st == GA_OK)
        mv_put(r, out);
    return st;
}

/* the read-back as 12 numbers: kind, reality, centre (3), direction (3),
 * r2, err, r2_err, angle_err (ga_object's fields in order) */
#define OBJECT_NUMBERS 12
int gpy_k_object(void *ctx, const double *const *in, double *out, npy_intp k)
{
    (void)ctx, (void)k;
    ga_object ob;
    int st = ga_object_from_mv(mv_at(in[0]), &ob);
    if (st != GA_OK)
        return st;
    double v[OBJECT_NUMBERS] = {ob.kind,     ob.reality,     ob.centre.x,    ob.centre.y,
                                ob.centre.z, ob.direction.x, ob.direction.y, ob.direction.z,
                                ob.r2,       ob.err,         ob.r2_err,      ob.angle_err};
    memcpy(out, v, sizeof v);
    return GA_OK;
}

/* ---- the type -------------------------------------------------------------- */

typedef struct {
    PyObject_HEAD PyArrayObject *a; /* float64 (..., 32), read-only, every number finite */
} MVAObject;

PyTypeObject gpy_MVAType;

#define MVA(o) (((MVAObject *)(o))->a)

/* A new MultivectorArray holding a (a float64 (..., 32) array of finite
 * numbers that nothing else writes to), taking the reference; NULL if a is. */
static PyObject *mva_wrap(PyObject *a)
{
    if (!a)
        return NULL;
    PyArray_CLEARFLAGS((PyArrayObject *)a, NPY_ARRAY_WRITEABLE);
    MVAObject *o = PyObject_New(MVAObject, &gpy_MVAType);
    if (!o) {
        Py_DECREF(a);
        return NULL;
    }
    o->a = (PyArrayObject *)a;
    return (PyObject *)o;
}

/* A new (32,) float64 array holding m */
static PyObject *mv_array(ga_mv m)
{
    npy_intp n = 32;
    PyObject *a = PyArray_SimpleNew(1, &n, NPY_DOUBLE);
    if (a)
        memcpy(PyArray_DATA((PyArrayObject *)a), m.c, sizeof m.c);
    return a;
}

/* x, an operand of `what`, as a new reference to an array (..., 32): a
 * MultivectorArray's own, a Multivector's 32 numbers, a real number's
 * scalar multivector. NULL with no exception if x is none of these; NULL
 * with garotor.Error for a number that is NaN or infinite. */
static PyObject *operand(const char *what, PyObject *x)
{
    if (PyObject_TypeCheck(x, &gpy_MVAType))
        return Py_NewRef((PyObject *)MVA(x));
    ga_mv m;
    int r = gpy_mv_operand(what, x, &m);
    return r > 0 ? mv_array(m) : NULL;
}

/* Run `kernel` over objs[0..nin-1] (arrays, or anything gpy_run_kernel
 * reads) with the core shapes in[]; the result as a MultivectorArray when
 * its elements are multivectors (out core 32), else the array. */
static PyObject *run(const char *what, gpy_kernel_fn kernel, void *ctx, int nin, const gpy_core *in,
                     gpy_core out, PyObject *const *objs)
{
    gpy_kernel_call kc = {.what = what, .nin = nin, .out = out, .kernel = kernel, .ctx = ctx};
    if (kernel == gpy_k_versor_apply) /* one versor on many: its inverse once */
        kc.many = gpy_versor_apply_many;
    for (int j = 0; j < nin; j++) kc.in[j] = in[j];
    PyObject *r = gpy_run_kernel(&kc, objs, NULL);
    return out.ncore == 1 && out.core[0] == 32 ? mva_wrap(r) : r;
}

static const gpy_core core_ab[2] = {GPY_CORE1(32, "a"), GPY_CORE1(32, "b")};
static const gpy_core core_self[1] = {GPY_CORE1(32, "self")};

/* a binary operation of two operands, either of which is a MultivectorArray */
static PyObject *binary(const char *what, gpy_kernel_fn kernel, PyObject *x, PyObject *y)
{
    PyObject *objs[2] = {operand(what, x), NULL};
    if (objs[0])
        objs[1] = operand(what, y);
    if (!objs[0] || !objs[1]) {
        Py_XDECREF(objs[0]);
        if (PyErr_Occurred())
            return NULL;
        Py_RETURN_NOTIMPLEMENTED;
    }
    PyObject *r = run(what, kernel, NULL, 2, core_ab, (gpy_core)GPY_CORE1(32, NULL), objs);
    Py_DECREF(objs[0]);
    Py_DECREF(objs[1]);
    return r;
}

PyObject *gpy_mva_binary(const char *what, gpy_kernel_fn kernel, PyObject *x, PyObject *y)
{
    return binary(what, kernel, x, y);
}

/* a method self.name(other): TypeError for another kind of other */
static PyObject *method2(const char *what, gpy_kernel_fn kernel, PyObject *self, PyObject *o)
{
    PyObject *r = binary(what, kernel, self, o);
    if (r == Py_NotImplemented) {
        Py_DECREF(r);
        PyErr_Format(PyExc_TypeError, "%s: a MultivectorArray, a Multivector or a number", what);
        return NULL;
    }
    return r;
}

static PyObject *unary(const char *what, gpy_kernel_fn kernel, void *ctx, PyObject *self, gpy_core out)
{
    PyObject *a = (PyObject *)MVA(self);
    return run(what, kernel, ctx, 1, core_self, out, &a);
}

#define OPERATOR(name, op, kern)                                                                             \
    static PyObject *MVA_##name(PyObject *x, PyObject *y)                                                    \
    {                                                                                                        \
        return binary("MultivectorArray " op, kern, x, y);                                                   \
    }
OPERATOR(add, "+", gpy_k_add)
OPERATOR(sub, "-", gpy_k_sub)
OPERATOR(mul, "*", gpy_k_gp)
OPERATOR(xor, "^", gpy_k_op)
OPERATOR(or, "|", gpy_k_lc)
OPERATOR(and, "&", gpy_k_regressive)

#define METHOD2(name, kern)                                                                                  \
    static PyObject *MVA_##name(PyObject *self, PyObject *o)                                                 \
    {                                                                                                        \
        return method2("MultivectorArray." #name, kern, self, o);                                            \
    }
METHOD2(dot, gpy_k_dot)
METHOD2(ip, gpy_k_ip)
METHOD2(commutator, gpy_k_commutator)
METHOD2(meet, gpy_k_meet)
METHOD2(join, gpy_k_join)
METHOD2(meet_rel, gpy_k_meet_rel)
METHOD2(project, gpy_k_project)
METHOD2(reject, gpy_k_reject)
METHOD2(apply, gpy_k_versor_apply)

#define METHOD1(name, kern)                                                                                  \
    static PyObject *MVA_##name(PyObject *self, PyObject *u)                                                 \
    {                                                                                                        \
        (void)u;                                                                                             \
        return unary("MultivectorArray." #name, kern, NULL, self, (gpy_core)GPY_CORE1(32, NULL));            \
    }
METHOD1(reverse, gpy_k_reverse)
METHOD1(involute, gpy_k_involute)
METHOD1(conjugate, gpy_k_conjugate)
METHOD1(dual, gpy_k_dual)
METHOD1(undual, gpy_k_undual)
METHOD1(inverse, gpy_k_mv_inverse)
METHOD1(exp, gpy_k_mv_exp)
METHOD1(log, gpy_k_mv_log)
METHOD1(sqrt, gpy_k_mv_sqrt)

static PyObject *MVA_neg(PyObject *self)
{
    return unary("MultivectorArray -", k_neg, NULL, self, core_self[0]);
}
static PyObject *MVA_invert(PyObject *self)
{
    return unary("MultivectorArray ~", gpy_k_reverse, NULL, self, core_self[0]);
}
static PyObject *MVA_pos(PyObject *self) { return Py_NewRef(self); }

static PyObject *MVA_grade(PyObject *self, PyObject *arg)
{
    long k = PyLong_AsLong(arg);
    if (k == -1 && PyErr_Occurred())
        return NULL;
    int g = k < 0 || k > 5 ? -1 : (int)k; /* as Multivector.grade: no such grade, 0 */
    return unary("MultivectorArray.grade", k_grade, &g, self, core_self[0]);
}

static PyObject *MVA_norm2(PyObject *self, PyObject *u)
{
    (void)u;
    return unary("MultivectorArray.norm2", gpy_k_norm2, NULL, self, (gpy_core){0, {0, 0}, NULL});
}

static PyObject *MVA_pow(PyObject *self, PyObject *t)
{
    static const gpy_core core[2] = {GPY_CORE1(32, "self"), {0, {0, 0}, "t"}};
    PyObject *objs[2] = {(PyObject *)MVA(self), t};
    return run("MultivectorArray.pow", gpy_k_mv_pow, NULL, 2, core, (gpy_core)GPY_CORE1(32, NULL), objs);
}

static PyObject *MVA_down(PyObject *self, PyObject *u)
{
    (void)u;
    return unary("MultivectorArray.down", gpy_k_down, NULL, self, (gpy_core)GPY_CORE1(3, NULL));
}

static PyObject *MVA_up(PyObject *cls, PyObject *x)
{
    (void)cls;
    static const gpy_core core[1] = {GPY_CORE1(3, "x")};
    return run("MultivectorArray.up", gpy_k_up, NULL, 1, core, (gpy_core)GPY_CORE1(32, NULL), &x);
}

/* ---- the read-back: a structured array of garotor.Object's fields ---------- */

static const char *const kind_names[] = {"empty",      "flat point", "line",  "plane",
                                         "point pair", "circle",     "sphere"};
static const char *const reality_names[] = {"real", "tangent", "imaginary"};

static PyArray_Descr *object_dtype;

/* numpy.dtype of the read-back, made once */
static PyArray_Descr *object_descr(void)
{
    if (object_dtype)
        return object_dtype;
    PyObject *spec = Py_BuildValue("[(ss)(ss)(ss(i))(ss(i))(ss)(ss)(ss)(ss)]", "kind", "U10", "reality", "U9",
                                   "centre", "f8", 3, "direction", "f8", 3, "r2", "f8", "err", "f8", "r2_err",
                                   "f8", "angle_err", "f8");
    if (spec && !PyArray_DescrConverter(spec, &object_dtype))
        object_dtype = NULL;
    Py_XDECREF(spec);
    return object_dtype;
}

/* the byte offset of field `name` in d; -1 with an exception */
static npy_intp field_offset(PyArray_Descr *d, const char *name)
{
    PyObject *f = d->fields ? PyDict_GetItemString(d->fields, name) : NULL;
    if (!f || !PyTuple_Check(f) || PyTuple_GET_SIZE(f) < 2) {
        PyErr_Format(PyExc_SystemError, "MultivectorArray.object: no field %s", name);
        return -1;
    }
    return PyLong_AsSsize_t(PyTuple_GET_ITEM(f, 1));
}

static void put_text(char *p, const char *s, int width)
{
    Py_UCS4 c[16] = {0};
    for (int i = 0; i < width && s[i]; i++) c[i] = (unsigned char)s[i];
    memcpy(p, c, (size_t)width * sizeof *c);
}

static PyObject *MVA_object(PyObject *self, PyObject *u)
{
    (void)u;
    PyArray_Descr *d = object_descr();
    if (!d)
        return NULL;
    PyObject *nums = unary("MultivectorArray.object", gpy_k_object, NULL, self,
                           (gpy_core)GPY_CORE1(OBJECT_NUMBERS, NULL));
    if (!nums)
        return NULL;
    static const char *const names[] = {"kind", "reality", "centre", "direction",
                                        "r2",   "err",     "r2_err", "angle_err"};
    npy_intp off[8];
    for (int i = 0; i < 8; i++)
        if ((off[i] = field_offset(d, names[i])) < 0) {
            Py_DECREF(nums);
            return NULL;
        }
    int nd = PyArray_NDIM((PyArrayObject *)nums) - 1;
    Py_INCREF(d);
    PyObject *r = PyArray_Zeros(nd, PyArray_DIMS((PyArrayObject *)nums), d, 0);
    if (!r) {
        Py_DECREF(nums);
        return NULL;
    }
    npy_intp n = PyArray_SIZE((PyArrayObject *)r), size = PyArray_ITEMSIZE((PyArrayObject *)r);
    const double *v = PyArray_DATA((PyArrayObject *)nums);
    char *base = PyArray_BYTES((PyArrayObject *)r);
    for (npy_intp i = 0; i < n; i++, v += OBJECT_NUMBERS) {
        char *p = base + i * size;
        int kind = (int)v[0], reality = (int)v[1];
        put_text(p + off[0], kind >= 0 && kind <= 6 ? kind_names[kind] : "?", 10);
        put_text(p + off[1], reality >= 0 && reality <= 2 ? reality_names[reality] : "?", 9);
        memcpy(p + off[2], v + 2, 3 * sizeof *v);
        memcpy(p + off[3], v + 5, 3 * sizeof *v);
        for (int f = 4; f < 8; f++) memcpy(p + off[f], v + 4 + f, sizeof *v);
    }
    Py_DECREF(nums);
    return r;
}

/* ---- construction, shape, items ------------------------------------------- */

static PyObject *MVA_new(PyTypeObject *type, PyObject *args, PyObject *kw)
{
    (void)type;
    static char *kwlist[] = {"c", NULL};
    PyObject *c;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "O:MultivectorArray", kwlist, &c))
        return NULL;
    if (PyObject_TypeCheck(c, &gpy_MVAType)) /* read-only: shared */
        return mva_wrap(Py_NewRef((PyObject *)MVA(c)));
    if (PyObject_TypeCheck(c, &gpy_MVType))
        return mva_wrap(mv_array(((gpy_MVObject *)c)->mv));
    PyArrayObject *a = gpy_as_doubles(c);
    if (!a)
        return NULL;
    int nd = PyArray_NDIM(a);
    if (nd == 0 || PyArray_DIM(a, nd - 1) != 32) {
        PyObject *shape = PyObject_GetAttrString((PyObject *)a, "shape");
        if (shape)
            PyErr_Format(PyExc_ValueError, "MultivectorArray: c must have shape (..., 32), not %S", shape);
        Py_XDECREF(shape);
        Py_DECREF(a);
        return NULL;
    }
    npy_intp bad = gpy_first_nonfinite(PyArray_DATA(a), PyArray_SIZE(a));
    if (bad >= 0) {
        char why[160];
        gpy_nonfinite_why("c", a, bad, why, sizeof why);
        gpy_raise_status_why("MultivectorArray", nd - 1, PyArray_DIMS(a), bad / 32, GA_ERR_NOTFINITE, why);
        Py_DECREF(a);
        return NULL;
    }
    /* a copy of its own (c may be the caller's array, written to later) */
    PyObject *own = PyArray_NewCopy(a, NPY_CORDER);
    Py_DECREF(a);
    return mva_wrap(own);
}

static void MVA_dealloc(PyObject *self)
{
    Py_XDECREF(MVA(self));
    Py_TYPE(self)->tp_free(self);
}

static Py_ssize_t MVA_len(PyObject *self)
{
    if (PyArray_NDIM(MVA(self)) < 2) {
        PyErr_SetString(PyExc_TypeError, "len() of a MultivectorArray of shape ()");
        return -1;
    }
    return PyArray_DIM(MVA(self), 0);
}

/* a[key]: key indexes the leading dimensions as numpy's indexing does; a
 * Multivector where it leaves none, else a MultivectorArray */
static PyObject *MVA_getitem(PyObject *self, PyObject *key)
{
    int has_ellipsis = key == Py_Ellipsis;
    Py_ssize_t nk = PyTuple_Check(key) ? PyTuple_GET_SIZE(key) : 1;
    for (Py_ssize_t i = 0; PyTuple_Check(key) && i < nk; i++)
        has_ellipsis = has_ellipsis || PyTuple_GET_ITEM(key, i) == Py_Ellipsis;
    /* key + (..., :) or, where key has its ..., key + (:,): the coefficients whole */
    PyObject *full = PyTuple_New(nk + (has_ellipsis ? 1 : 2));
    if (!full)
        return NULL;
    for (Py_ssize_t i = 0; i < nk; i++)
        PyTuple_SET_ITEM(full, i, Py_NewRef(PyTuple_Check(key) ? PyTuple_GET_ITEM(key, i) : key));
    if (!has_ellipsis)
        PyTuple_SET_ITEM(full, nk, Py_NewRef(Py_Ellipsis));
    PyObject *all = PySlice_New(NULL, NULL, NULL);
    if (!all) {
        Py_DECREF(full);
        return NULL;
    }
    PyTuple_SET_ITEM(full, PyTuple_GET_SIZE(full) - 1, all);
    PyObject *r = PyObject_GetItem((PyObject *)MVA(self), full);
    Py_DECREF(full);
    if (!r)
        return NULL;
    if (!PyArray_Check(r) || PyArray_NDIM((PyArrayObject *)r) < 1 ||
        PyArray_DIM((PyArrayObject *)r, PyArray_NDIM((PyArrayObject *)r) - 1) != 32) {
        Py_DECREF(r);
        PyErr_SetString(PyExc_IndexError, "MultivectorArray: the index reached into the coefficients");
        return NULL;
    }
    if (PyArray_NDIM((PyArrayObject *)r) == 1) {
        ga_mv m = mv_at(PyArray_DATA((PyArrayObject *)r)); /* a view of a float64 array: aligned */
        Py_DECREF(r);
        return gpy_mv_new(m);
    }
    /* a view of the read-only array (no copy) or a new one: read-only either way */
    return mva_wrap(r);
}

static PyObject *MVA_item(PyObject *self, Py_ssize_t i)
{
    if (PyArray_NDIM(MVA(self)) < 2 || i < 0 || i >= PyArray_DIM(MVA(self), 0)) {
        PyErr_SetString(PyExc_IndexError, "MultivectorArray index out of range");
        return NULL;
    }
    PyObject *key = PyLong_FromSsize_t(i);
    PyObject *r = key ? MVA_getitem(self, key) : NULL;
    Py_XDECREF(key);
    return r;
}

static PyObject *MVA_shape(PyObject *self, void *u)
{
    (void)u;
    PyArrayObject *a = MVA(self);
    return PyArray_IntTupleFromIntp(PyArray_NDIM(a) - 1, PyArray_DIMS(a));
}

static PyObject *MVA_ndim(PyObject *self, void *u)
{
    (void)u;
    return PyLong_FromLong(PyArray_NDIM(MVA(self)) - 1);
}

/* numpy.asarray(a): the (..., 32) coefficients, read-only (a view) */
static PyObject *MVA_array(PyObject *self, PyObject *args, PyObject *kw)
{
    static char *kwlist[] = {"dtype", "copy", NULL};
    PyObject *dtype = Py_None, *copy = Py_None;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "|OO:__array__", kwlist, &dtype, &copy))
        return NULL;
    PyArrayObject *a = MVA(self);
    if (dtype != Py_None) {
        PyArray_Descr *d = NULL;
        if (!PyArray_DescrConverter(dtype, &d))
            return NULL;
        return PyArray_CastToType(a, d, 0);
    }
    return PyArray_View(a, NULL, NULL);
}

static PyObject *MVA_repr(PyObject *self)
{
    PyObject *shape = MVA_shape(self, NULL);
    PyObject *r = shape ? PyUnicode_FromFormat("MultivectorArray(shape=%S)", shape) : NULL;
    Py_XDECREF(shape);
    return r;
}

/* pickling and copying: MultivectorArray(c), c the (..., 32) coefficients */
static PyObject *MVA_reduce(PyObject *self, PyObject *u)
{
    (void)u;
    PyObject *c = PyArray_NewCopy(MVA(self), NPY_CORDER);
    return c ? Py_BuildValue("O(N)", (PyObject *)Py_TYPE(self), c) : NULL;
}

static PyNumberMethods MVA_as_number = {
    .nb_add = MVA_add,
    .nb_subtract = MVA_sub,
    .nb_multiply = MVA_mul,
    .nb_xor = MVA_xor,
    .nb_or = MVA_or,
    .nb_and = MVA_and,
    .nb_negative = MVA_neg,
    .nb_positive = MVA_pos,
    .nb_invert = MVA_invert,
};

static PyMappingMethods MVA_as_mapping = {.mp_length = MVA_len, .mp_subscript = MVA_getitem};
static PySequenceMethods MVA_as_sequence = {.sq_length = MVA_len, .sq_item = MVA_item};

static PyGetSetDef MVA_getset[] = {
    {"shape", MVA_shape, NULL, "the leading shape (the coefficients' axis left out)", NULL},
    {"ndim", MVA_ndim, NULL, "the number of leading dimensions", NULL},
    {NULL, NULL, NULL, NULL, NULL}};

#define M1(name, doc)                                                                                        \
    {                                                                                                        \
#name, (PyCFunction)MVA_##name, METH_NOARGS, doc                                                     \
    }
#define M2(name, doc)                                                                                        \
    {                                                                                                        \
#name, (PyCFunction)MVA_##name, METH_O, doc                                                          \
    }

static PyMethodDef MVA_methods[] = {
    {"__array__", (PyCFunction)(void (*)(void))MVA_array, METH_VARARGS | METH_KEYWORDS,
     "the (..., 32) coefficients (read-only)"},
    M2(dot, "the fat dot (ga_mv_dot), element by element, broadcast"),
    M2(ip, "Hestenes' inner product (ga_mv_ip)"),
    M2(commutator, "(a b - b a) / 2 (ga_mv_commutator)"),
    M2(meet, "the meet (ga_mv_meet)"),
    M2(join, "the join (ga_mv_join)"),
    M2(meet_rel, "the meet relative to the join (ga_mv_meet_rel)"),
    M2(project, "the projection onto the blades B (ga_mv_project)"),
    M2(reject, "the rejection from the blades B (ga_mv_reject)"),
    M2(apply, "apply(X): each versor's sandwich V X^ V^-1 (ga_versor_apply)"),
    M2(pow, "pow(t): R^t of each rotor, t a number or an array broadcast (ga_mv_pow)"),
    M2(grade, "grade(k): the grade-k parts"),
    M1(reverse, "~X"),
    M1(involute, "the grade involution"),
    M1(conjugate, "the Clifford conjugate"),
    M1(dual, "X I^-1"),
    M1(undual, "X I"),
    M1(inverse, "the inverse of each (ga_mv_inverse)"),
    M1(exp, "exp of each bivector, as Multivector.exp"),
    M1(log, "the principal log of each rotor, as Multivector.log"),
    M1(sqrt, "the principal square root of each rotor (ga_mv_sqrt)"),
    M1(norm2, "<X ~X>_0 of each, an array of the leading shape"),
    M1(down, "the points x of conformal points X = w F(x), (..., 3)"),
    M1(object, "the read-back of each (ga_object_from_mv): a structured array with garotor.Object's fields"),
    {"up", (PyCFunction)MVA_up, METH_O | METH_CLASS, "MultivectorArray.up(x): conformal points of (..., 3)"},
    {"__reduce__", (PyCFunction)MVA_reduce, METH_NOARGS, "pickling and copying: MultivectorArray(c)"},
    {NULL, NULL, 0, NULL}};

PyTypeObject gpy_MVAType = {
    PyVarObject_HEAD_INIT(NULL, 0).tp_name = "garotor.MultivectorArray",
    .tp_basicsize = sizeof(MVAObject),
    .tp_dealloc = MVA_dealloc,
    .tp_repr = MVA_repr,
    .tp_as_number = &MVA_as_number,
    .tp_as_sequence = &MVA_as_sequence,
    .tp_as_mapping = &MVA_as_mapping,
    .tp_hash = PyObject_HashNotImplemented,
    .tp_flags = Py_TPFLAGS_DEFAULT,
    .tp_doc = "MultivectorArray(c): multivectors of G(4,1), c of shape (..., 32) in canonical order.\n"
              "* geometric, ^ outer, | left contraction, & regressive, + -, ~ reverse, element by element\n"
              "and broadcast (a Multivector or a number acts on every element); numpy.asarray(a) gives\n"
              "the coefficients, a[i] a Multivector or a MultivectorArray.",
    .tp_methods = MVA_methods,
    .tp_getset = MVA_getset,
    .tp_new = MVA_new,
};
