/* python/multivector.c: garotor.Multivector, one multivector of G(4,1) as
 * its 32 coefficients (docs/python.md, "Multivector"): the operators, the
 * ga_mv_* methods, exp and log through the compact rotor where the element
 * is a rigid motion's, and the basis blades by name or index.
 */
#include "module.h"

#include <math.h>

typedef gpy_MVObject MVObject;

PyObject *gpy_mv_new(ga_mv m)
{
    MVObject *o = PyObject_New(MVObject, &gpy_MVType);
    if (o)
        o->mv = m;
    return (PyObject *)o;
}

/* A Multivector's coefficients are finite: one is never made from a NaN or
 * an infinity (garotor.Error, GA_ERR_NOTFINITE), and an operation whose
 * result would not be finite raises instead (GA_ERR_DOMAIN), as the array
 * calls do (kernel.c). Comparing is not computing: == takes any number. */

/* m as a new Multivector from the operation `what`; NULL with garotor.Error
 * if a coefficient is not finite. */
PyObject *gpy_mv_result(const char *what, ga_mv m)
{
    if (!ga_mv_isfinite(m)) {
        gpy_raise_status_why(what, 0, NULL, 0, GA_ERR_DOMAIN, "the result would not be finite");
        return NULL;
    }
    return gpy_mv_new(m);
}

static PyObject *number_result(const char *what, double x)
{
    if (!isfinite(x)) {
        gpy_raise_status_why(what, 0, NULL, 0, GA_ERR_DOMAIN, "the result would not be finite");
        return NULL;
    }
    return PyFloat_FromDouble(x);
}

/* A Multivector, or a real number as a scalar multivector; 0 if neither. */
static int mv_coerce(PyObject *x, ga_mv *out)
{
    if (PyObject_TypeCheck(x, &gpy_MVType)) {
        *out = ((MVObject *)x)->mv;
        return 1;
    }
    if (PyFloat_Check(x) || PyLong_Check(x) || PyArray_IsScalar(x, Floating) ||
        PyArray_IsScalar(x, Integer)) {
        double s = PyFloat_AsDouble(x);
        if (s == -1.0 && PyErr_Occurred()) {
            PyErr_Clear();
            return 0;
        }
        *out = ga_mv_scalar(s);
        return 1;
    }
    return 0;
}

/* 1 if s is finite; -1 with garotor.Error naming it if not. */
int gpy_finite_number(const char *what, double s)
{
    if (isfinite(s))
        return 1;
    char why[64], num[32];
    snprintf(why, sizeof why, "the number is %s", gpy_repr_text(s, num));
    gpy_raise_status_why(what, 0, NULL, 0, GA_ERR_NOTFINITE, why);
    return -1;
}

/* mv_coerce for an operand of `what`: 1, 0 if x is neither (NotImplemented),
 * -1 with garotor.Error for a number that is NaN or infinite. */
int gpy_mv_operand(const char *what, PyObject *x, ga_mv *out)
{
    if (!mv_coerce(x, out))
        return 0;
    return PyObject_TypeCheck(x, &gpy_MVType) ? 1 : gpy_finite_number(what, out->c[0]);
}

/* obj, a 1-d array-like of count finite numbers, into v; what (the call)
 * and name (the argument) for messages. 0, or -1 with an exception. */
int gpy_read_numbers(const char *what, const char *name, PyObject *obj, npy_intp count, const char *shape_msg,
                     double *v)
{
    PyArrayObject *a = gpy_as_doubles(obj);
    if (!a)
        return -1;
    if (PyArray_NDIM(a) != 1 || PyArray_DIM(a, 0) != count) {
        Py_DECREF(a);
        PyErr_SetString(PyExc_ValueError, shape_msg);
        return -1;
    }
    npy_intp bad = gpy_first_nonfinite(PyArray_DATA(a), count);
    if (bad >= 0) {
        char why[160];
        gpy_nonfinite_why(name, a, bad, why, sizeof why);
        gpy_raise_status_why(what, 0, NULL, 0, GA_ERR_NOTFINITE, why);
        Py_DECREF(a);
        return -1;
    }
    memcpy(v, PyArray_DATA(a), (size_t)count * sizeof *v);
    Py_DECREF(a);
    return 0;
}

static PyObject *MV_new(PyTypeObject *type, PyObject *args, PyObject *kw)
{
    (void)type;
    static char *kwlist[] = {"c", NULL};
    PyObject *c = NULL;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "|O:Multivector", kwlist, &c))
        return NULL;
    ga_mv m = ga_mv_zero();
    if (c && PyObject_TypeCheck(c, &gpy_MVType))
        return gpy_mv_new(((MVObject *)c)->mv);
    if (c && gpy_read_numbers("Multivector", "c", c, 32,
                              "Multivector: needs 32 coefficients in canonical order", m.c))
        return NULL;
    return gpy_mv_new(m);
}

static PyObject *MV_repr(MVObject *self)
{
    PyObject *parts = PyList_New(0);
    if (!parts)
        return NULL;
    for (int i = 0; i < 32; i++) {
        double v = self->mv.c[i];
        if (v == 0.0)
            continue;
        char *num = PyOS_double_to_string(fabs(v), 'r', 0, 0, NULL);
        if (!num) {
            Py_DECREF(parts);
            return NULL;
        }
        int first = PyList_GET_SIZE(parts) == 0;
        const char *sign = signbit(v) ? (first ? "-" : " - ") : (first ? "" : " + ");
        PyObject *s = i == 0         ? PyUnicode_FromFormat("%s%s", sign, num)
                    : fabs(v) == 1.0 ? PyUnicode_FromFormat("%s%s", sign, ga_blade_name(i))
                                     : PyUnicode_FromFormat("%s%s*%s", sign, num, ga_blade_name(i));
        PyMem_Free(num);
        if (!s || PyList_Append(parts, s) < 0) {
            Py_XDECREF(s);
            Py_DECREF(parts);
            return NULL;
        }
        Py_DECREF(s);
    }
    PyObject *empty = PyUnicode_FromString("");
    PyObject *body = empty ? PyUnicode_Join(empty, parts) : NULL;
    Py_XDECREF(empty);
    Py_DECREF(parts);
    if (!body)
        return NULL;
    PyObject *r = PyUnicode_GET_LENGTH(body) ? PyUnicode_FromFormat("Multivector(%U)", body)
                                             : PyUnicode_FromString("Multivector(0)");
    Py_DECREF(body);
    return r;
}

#define MV_BINOP(name, op, expr)                                                                             \
    static PyObject *MV_##name(PyObject *x, PyObject *y)                                                     \
    {                                                                                                        \
        ga_mv a, b;                                                                                          \
        int ra = gpy_mv_operand("Multivector " op, x, &a),                                                   \
            rb = ra > 0 ? gpy_mv_operand("Multivector " op, y, &b) : 0;                                      \
        if (ra < 0 || rb < 0)                                                                                \
            return NULL;                                                                                     \
        if (!ra || !rb)                                                                                      \
            Py_RETURN_NOTIMPLEMENTED;                                                                        \
        return gpy_mv_result("Multivector " op, expr);                                                       \
    }
MV_BINOP(add, "+", ga_mv_add(a, b))
MV_BINOP(sub, "-", ga_mv_sub(a, b))
MV_BINOP(mul, "*", ga_mv_gp(a, b))
MV_BINOP(xor, "^", ga_mv_op(a, b))
MV_BINOP(or, "|", ga_mv_lc(a, b))
MV_BINOP(and, "&", ga_mv_regressive(a, b))

/* a / s for a number s: every coefficient divided by s (ZeroDivisionError
 * for 0, as floats); a / b for a Multivector b (a a Multivector or a
 * number): a * b.inverse(), ga_mv_gp(a, ga_mv_inverse(b)) bit for bit */
static PyObject *MV_truediv(PyObject *x, PyObject *y)
{
    ga_mv a, sv;
    if (PyObject_TypeCheck(y, &gpy_MVType)) {
        int r = gpy_mv_operand("Multivector /", x, &a);
        if (r <= 0) {
            if (r == 0)
                Py_RETURN_NOTIMPLEMENTED;
            return NULL;
        }
        ga_mv inv;
        int st = ga_mv_inverse(((MVObject *)y)->mv, &inv);
        if (st != GA_OK)
            return gpy_status_error("Multivector /", st);
        return gpy_mv_result("Multivector /", ga_mv_gp(a, inv));
    }
    if (!PyObject_TypeCheck(x, &gpy_MVType) ||
        !(PyFloat_Check(y) || PyLong_Check(y) || PyArray_IsScalar(y, Number)))
        Py_RETURN_NOTIMPLEMENTED;
    a = ((MVObject *)x)->mv;
    int r = gpy_mv_operand("Multivector /", y, &sv);
    if (r < 0)
        return NULL;
    double s = sv.c[0];
    if (r == 0) { /* another numpy number (a complex one): as float() reads it */
        s = PyFloat_AsDouble(y);
        if ((s == -1.0 && PyErr_Occurred()) || gpy_finite_number("Multivector /", s) < 0)
            return NULL;
    }
    if (s == 0.0) { /* as Python's float division */
        PyErr_SetString(PyExc_ZeroDivisionError, "Multivector division by zero");
        return NULL;
    }
    for (int i = 0; i < 32; i++) a.c[i] /= s;
    return gpy_mv_result("Multivector /", a);
}

static PyObject *MV_neg(MVObject *x) { return gpy_mv_new(ga_mv_scale(x->mv, -1.0)); }
static PyObject *MV_pos(MVObject *x) { return gpy_mv_new(x->mv); }
static PyObject *MV_invert(MVObject *x) { return gpy_mv_new(ga_mv_reverse(x->mv)); }

/* False for the zero multivector (every coefficient 0 or -0), True otherwise */
static int MV_bool(MVObject *x)
{
    for (int i = 0; i < 32; i++)
        if (x->mv.c[i] != 0.0)
            return 1;
    return 0;
}

static PyNumberMethods MV_as_number = {
    .nb_add = MV_add,
    .nb_subtract = MV_sub,
    .nb_multiply = MV_mul,
    .nb_xor = MV_xor,
    .nb_or = MV_or,
    .nb_and = MV_and,
    .nb_power = gpy_MV_power,
    .nb_true_divide = MV_truediv,
    .nb_negative = (unaryfunc)MV_neg,
    .nb_positive = (unaryfunc)MV_pos,
    .nb_invert = (unaryfunc)MV_invert,
    .nb_bool = (inquiry)MV_bool,
};

static PyObject *MV_richcompare(PyObject *x, PyObject *y, int op)
{
    ga_mv a, b;
    if ((op != Py_EQ && op != Py_NE) || !mv_coerce(x, &a) || !mv_coerce(y, &b))
        Py_RETURN_NOTIMPLEMENTED;
    int eq = 1;
    for (int i = 0; i < 32; i++) eq = eq && a.c[i] == b.c[i];
    return PyBool_FromLong(op == Py_EQ ? eq : !eq);
}

static int blade_index(PyObject *key)
{
    if (PyUnicode_Check(key)) {
        const char *s = PyUnicode_AsUTF8(key);
        if (!s)
            return -1;
        for (int i = 0; i < 32; i++)
            if (strcmp(s, ga_blade_name(i)) == 0)
                return i;
        PyErr_Format(PyExc_KeyError, "no blade named '%s' (names: 1, e1, ..., e12345)", s);
        return -1;
    }
    Py_ssize_t i = PyNumber_AsSsize_t(key, PyExc_IndexError);
    if (i == -1 && PyErr_Occurred())
        return -1;
    if (i < -32 || i >= 32) {
        PyErr_SetString(PyExc_IndexError, "a blade index is 0..31");
        return -1;
    }
    return (int)(i < 0 ? i + 32 : i);
}

static PyObject *MV_getitem(MVObject *self, PyObject *key)
{
    int i = blade_index(key);
    return i < 0 ? NULL : PyFloat_FromDouble(self->mv.c[i]);
}

static PyMappingMethods MV_as_mapping = {.mp_subscript = (binaryfunc)MV_getitem};

static PyObject *MV_array(MVObject *self, PyObject *args, PyObject *kw)
{
    static char *kwlist[] = {"dtype", "copy", NULL};
    PyObject *dtype = Py_None, *copy = Py_None;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "|OO:__array__", kwlist, &dtype, &copy))
        return NULL;
    npy_intp n = 32;
    PyObject *a = PyArray_SimpleNew(1, &n, NPY_DOUBLE);
    if (!a)
        return NULL;
    memcpy(PyArray_DATA((PyArrayObject *)a), self->mv.c, sizeof self->mv.c);
    if (dtype != Py_None) {
        PyArray_Descr *d = NULL;
        if (!PyArray_DescrConverter(dtype, &d)) {
            Py_DECREF(a);
            return NULL;
        }
        PyObject *b = PyArray_CastToType((PyArrayObject *)a, d, 0);
        Py_DECREF(a);
        return b;
    }
    return a;
}

static PyObject *MV_grade(MVObject *self, PyObject *arg)
{
    long k = PyLong_AsLong(arg);
    if (k == -1 && PyErr_Occurred())
        return NULL;
    return gpy_mv_new(ga_mv_grade(self->mv, k < 0 || k > 5 ? -1 : (int)k));
}

static PyObject *MV_dual(MVObject *self, PyObject *u)
{
    (void)u;
    return gpy_mv_new(ga_mv_dual(self->mv));
}
static PyObject *MV_undual(MVObject *self, PyObject *u)
{
    (void)u;
    return gpy_mv_new(ga_mv_undual(self->mv));
}
static PyObject *MV_reverse(MVObject *self, PyObject *u)
{
    (void)u;
    return gpy_mv_new(ga_mv_reverse(self->mv));
}
static PyObject *MV_involute(MVObject *self, PyObject *u)
{
    (void)u;
    return gpy_mv_new(ga_mv_involute(self->mv));
}
static PyObject *MV_conjugate(MVObject *self, PyObject *u)
{
    (void)u;
    return gpy_mv_new(ga_mv_conjugate(self->mv));
}
static PyObject *MV_norm2(MVObject *self, PyObject *u)
{
    (void)u;
    return number_result("Multivector.norm2", ga_mv_norm2(self->mv));
}

static PyObject *MV_inverse(MVObject *self, PyObject *u)
{
    (void)u;
    ga_mv r;
    int st = ga_mv_inverse(self->mv, &r);
    return st == GA_OK ? gpy_mv_new(r) : gpy_status_error("Multivector.inverse", st);
}

/* The generator of a bivector in span{e_ij, e_i n}: e_i4 and e_i5 equal,
 * everything else zero, to 1e-9 of max(1, max|m|). */
static int mv_to_generator(ga_mv m, ga_generator *b)
{
    if (!ga_mv_isfinite(m))
        return GA_ERR_NOTFINITE;
    double tol = 1e-9 * fmax(1.0, ga_mv_maxabs(m));
    static const int used[] = {GA_BLADE_E12, GA_BLADE_E13, GA_BLADE_E23, GA_BLADE_E14, GA_BLADE_E15,
                               GA_BLADE_E24, GA_BLADE_E25, GA_BLADE_E34, GA_BLADE_E35};
    for (int i = 0; i < 32; i++) {
        int u = 0;
        for (size_t j = 0; j < sizeof used / sizeof *used; j++) u |= used[j] == i;
        if (!u && fabs(m.c[i]) > tol)
            return GA_ERR_NOTBLADE;
    }
    const double *c = m.c;
    if (fabs(c[GA_BLADE_E14] - c[GA_BLADE_E15]) > tol || fabs(c[GA_BLADE_E24] - c[GA_BLADE_E25]) > tol ||
        fabs(c[GA_BLADE_E34] - c[GA_BLADE_E35]) > tol)
        return GA_ERR_NOTBLADE;
    *b = (ga_generator){c[GA_BLADE_E12],
                        c[GA_BLADE_E13],
                        c[GA_BLADE_E23],
                        0.5 * (c[GA_BLADE_E14] + c[GA_BLADE_E15]),
                        0.5 * (c[GA_BLADE_E24] + c[GA_BLADE_E25]),
                        0.5 * (c[GA_BLADE_E34] + c[GA_BLADE_E35])};
    return GA_OK;
}

/* exp: a rigid-motion generator through the compact rotor (the tool's exp,
   bit for bit), any other bivector through ga_mv_exp; anything with other
   grades is refused (to 1e-9 of max(1, max|m|), as mv_to_generator) */
int gpy_mv_exp(ga_mv m, ga_mv *out)
{
    ga_generator b;
    int st = mv_to_generator(m, &b);
    if (st == GA_OK) {
        *out = ga_rotor_to_mv(ga_rotor_exp(b));
        return GA_OK;
    }
    if (st == GA_ERR_NOTBLADE) {
        double tol = 1e-9 * fmax(1.0, ga_mv_maxabs(m));
        if (ga_mv_maxabs(ga_mv_sub(m, ga_mv_grade(m, 2))) <= tol) {
            *out = ga_mv_exp(ga_mv_grade(m, 2));
            return GA_OK;
        }
    }
    return st;
}

static PyObject *MV_exp(MVObject *self, PyObject *u)
{
    (void)u;
    ga_mv r;
    int st = gpy_mv_exp(self->mv, &r);
    return st == GA_OK ? gpy_mv_result("Multivector.exp", r) : gpy_status_error("Multivector.exp", st);
}

/* log: a rigid-motion rotor through the compact rotor (the tool's log), any
   other rotor through ga_mv_log (GA_ERR_DOMAIN where it has no real log) */
int gpy_mv_log(ga_mv m, ga_mv *out)
{
    ga_rotor r;
    ga_generator b;
    int st = ga_rotor_from_mv(m, GA_ROTOR_DRIFT_MAX, &r);
    if (st == GA_OK)
        st = ga_rotor_log(r, &b);
    if (st == GA_OK) {
        *out = ga_generator_to_mv(b);
        return GA_OK;
    }
    if (st == GA_ERR_NOTRIGID)
        st = ga_mv_log(m, out);
    return st;
}

static PyObject *MV_log(MVObject *self, PyObject *u)
{
    (void)u;
    ga_mv L;
    int st = gpy_mv_log(self->mv, &L);
    return st == GA_OK ? gpy_mv_new(L) : gpy_status_error("Multivector.log", st);
}

static PyObject *MV_dot(MVObject *self, PyObject *o)
{
    ga_mv b;
    if (PyObject_TypeCheck(o, &gpy_MVAType))
        return gpy_mva_binary("Multivector.dot", gpy_k_dot, (PyObject *)self, o);
    int r = gpy_mv_operand("Multivector.dot", o, &b);
    if (r == 0)
        PyErr_SetString(PyExc_TypeError, "Multivector.dot: a Multivector or a number");
    return r > 0 ? gpy_mv_result("Multivector.dot", ga_mv_dot(self->mv, b)) : NULL;
}

static PyObject *MV_ip(MVObject *self, PyObject *o)
{
    ga_mv b;
    if (PyObject_TypeCheck(o, &gpy_MVAType))
        return gpy_mva_binary("Multivector.ip", gpy_k_ip, (PyObject *)self, o);
    int r = gpy_mv_operand("Multivector.ip", o, &b);
    if (r == 0)
        PyErr_SetString(PyExc_TypeError, "Multivector.ip: a Multivector or a number");
    return r > 0 ? gpy_mv_result("Multivector.ip", ga_mv_ip(self->mv, b)) : NULL;
}

static PyObject *MV_down(MVObject *self, PyObject *u)
{
    (void)u;
    ga_vec3 x;
    int st = ga_point_down(self->mv, &x);
    if (st != GA_OK)
        return gpy_status_error("Multivector.down", st);
    npy_intp n = 3;
    PyObject *a = PyArray_SimpleNew(1, &n, NPY_DOUBLE);
    if (a) {
        double *d = PyArray_DATA((PyArrayObject *)a);
        d[0] = x.x, d[1] = x.y, d[2] = x.z;
    }
    return a;
}

static PyObject *MV_up(PyObject *cls, PyObject *arg)
{
    (void)cls;
    double x[3];
    if (gpy_read_numbers("Multivector.up", "x", arg, 3, "Multivector.up: x must have shape (3,)", x))
        return NULL;
    return gpy_mv_result("Multivector.up", ga_point_up((ga_vec3){x[0], x[1], x[2]}));
}

/* pickling and copying: Multivector(c), c the 32 coefficients as floats */
static PyObject *MV_reduce(MVObject *self, PyObject *u)
{
    (void)u;
    PyObject *c = PyTuple_New(32);
    for (int i = 0; c && i < 32; i++) {
        PyObject *x = PyFloat_FromDouble(self->mv.c[i]);
        if (!x) {
            Py_CLEAR(c);
            break;
        }
        PyTuple_SET_ITEM(c, i, x);
    }
    return c ? Py_BuildValue("O(N)", (PyObject *)Py_TYPE(self), c) : NULL;
}

static PyObject *MV_blade(PyObject *cls, PyObject *key)
{
    (void)cls;
    int i = blade_index(key);
    return i < 0 ? NULL : gpy_mv_new(ga_mv_blade(i));
}

static PyMethodDef MV_methods[] = {
    {"__array__", (PyCFunction)(void (*)(void))MV_array, METH_VARARGS | METH_KEYWORDS,
     "the 32 coefficients as a float64 array"},
    {"grade", (PyCFunction)MV_grade, METH_O, "grade(k): the grade-k part"},
    {"dual", (PyCFunction)MV_dual, METH_NOARGS, "X* = X I^-1, I = e12345"},
    {"undual", (PyCFunction)MV_undual, METH_NOARGS, "X I, the inverse of dual()"},
    {"reverse", (PyCFunction)MV_reverse, METH_NOARGS, "~X"},
    {"involute", (PyCFunction)MV_involute, METH_NOARGS, "the grade involution"},
    {"conjugate", (PyCFunction)MV_conjugate, METH_NOARGS, "the Clifford conjugate"},
    {"norm2", (PyCFunction)MV_norm2, METH_NOARGS, "<X ~X>_0"},
    {"inverse", (PyCFunction)MV_inverse, METH_NOARGS, "X^-1 of any invertible multivector (ga_mv_inverse)"},
    {"exp", (PyCFunction)MV_exp, METH_NOARGS,
     "exp of a bivector: a rigid-motion generator through the compact rotor, any other by ga_mv_exp"},
    {"log", (PyCFunction)MV_log, METH_NOARGS,
     "the principal log of a rotor: a rigid one through the compact rotor, any other by ga_mv_log"},
    {"dot", (PyCFunction)MV_dot, METH_O, "the fat dot a . b (ga_mv_dot; ganja.js's |)"},
    {"ip", (PyCFunction)MV_ip, METH_O, "Hestenes' inner product (ga_mv_ip; clifford's |)"},
    {"down", (PyCFunction)MV_down, METH_NOARGS, "the point x of a conformal point X = w F(x)"},
    {"up", (PyCFunction)MV_up, METH_O | METH_CLASS, "Multivector.up(x): the conformal point F(x)"},
    {"blade", (PyCFunction)MV_blade, METH_O | METH_CLASS, "Multivector.blade(i or name): a basis blade"},
    {"meet", gpy_MV_meet, METH_O, "meet(B): the meet of two objects, A* ^ B* undualised (ga_mv_meet)"},
    {"join", gpy_MV_join, METH_O, "join(B): the smallest blade holding both objects (ga_mv_join)"},
    {"meet_rel", gpy_MV_meet_rel, METH_O, "meet_rel(B): the meet relative to the join (ga_mv_meet_rel)"},
    {"between", gpy_MV_between, METH_O,
     "between(B): a rotor V of G(4,1) taking this object to B, of the same kind, maybe another size "
     "(ga_versor_between)"},
    {"interp", gpy_MV_interp, METH_VARARGS,
     "interp(B, t): the object at t along between(B): this object at t = 0, B at t = 1 (ga_object_interp)"},
    {"object", (PyCFunction)(void (*)(void))gpy_MV_object, METH_VARARGS | METH_KEYWORDS,
     "object(origin=None, scale=1.0): the object read back, a garotor.Object (ga_object_from_mv; "
     "ga_object_from_mv_about with an origin or a scale)"},
    {"commutator", gpy_MV_commutator, METH_O, "commutator(b): (a b - b a) / 2 (ga_mv_commutator)"},
    {"project", gpy_MV_project, METH_O, "project(B): the projection onto the blade B (ga_mv_project)"},
    {"reject", gpy_MV_reject, METH_O, "reject(B): the rejection from the blade B (ga_mv_reject)"},
    {"pow", gpy_MV_pow, METH_O, "pow(t): R^t = exp(t log R) of a rotor, t real (ga_mv_pow)"},
    {"sqrt", gpy_MV_sqrt, METH_NOARGS, "the principal square root of a rotor (ga_mv_sqrt)"},
    {"apply", gpy_MV_apply, METH_O, "apply(X): the versor's sandwich V X^ V^-1 (ga_versor_apply)"},
    {"reflection", gpy_MV_reflection, METH_VARARGS | METH_CLASS,
     "Multivector.reflection(normal, distance): the dual plane n + d e_inf (ga_versor_reflection)"},
    {"inversion", gpy_MV_inversion, METH_VARARGS | METH_CLASS,
     "Multivector.inversion(centre, radius): the dual sphere F(c) - r^2/2 n (ga_versor_inversion)"},
    {"dilation", gpy_MV_dilation, METH_VARARGS | METH_CLASS,
     "Multivector.dilation(centre, s): x -> c + s (x - c), s > 0 (ga_versor_dilation)"},
    {"transversion", gpy_MV_transversion, METH_O | METH_CLASS,
     "Multivector.transversion(b): 1 + nbar b / 2 (ga_versor_transversion)"},
    {"rotation", gpy_MV_rotation, METH_VARARGS | METH_CLASS,
     "Multivector.rotation(axis, angle): about the axis through the origin (ga_versor_rotation)"},
    {"translation", gpy_MV_translation, METH_O | METH_CLASS,
     "Multivector.translation(a): 1 + n a / 2 (ga_versor_translation)"},
    {"__reduce__", (PyCFunction)MV_reduce, METH_NOARGS, "pickling and copying: Multivector(c)"},
    {NULL, NULL, 0, NULL}};

PyTypeObject gpy_MVType = {
    PyVarObject_HEAD_INIT(NULL, 0).tp_name = "garotor.Multivector",
    .tp_basicsize = sizeof(MVObject),
    .tp_repr = (reprfunc)MV_repr,
    .tp_as_number = &MV_as_number,
    .tp_as_mapping = &MV_as_mapping,
    .tp_hash = PyObject_HashNotImplemented,
    .tp_flags = Py_TPFLAGS_DEFAULT,
    .tp_doc = "Multivector(c): a multivector of G(4,1) from its 32 coefficients in canonical order\n"
              "(1; e1..e5; e12..e45; e123..e345; e1234..e2345; e12345).\n"
              "* geometric, ^ outer, | left contraction, & regressive, ~ reverse, / by the inverse, ** "
              "integer powers;\n"
              "numpy.asarray(m) gives the coefficients.",
    .tp_richcompare = MV_richcompare,
    .tp_methods = MV_methods,
    .tp_new = MV_new,
};
