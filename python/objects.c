/* python/objects.c: Multivector's methods for conformal objects and the
 * algebra beside them (docs/python.md, "Objects"): meet, join, meet_rel and
 * the read-back garotor.Object (object.h), the versor constructors and
 * apply (versor.h), commutator, projection, rejection, powers and square
 * roots (mv.h), and the fits (fit.h) as module functions. Each is one call
 * of the C library, so its answer is the C function's bit for bit; a C
 * status raises garotor.Error with the status (docs/python.md, "Errors").
 */
#include "module.h"

#include <math.h>

#define MV(o) (((gpy_MVObject *)(o))->mv)

/* ---- garotor.Object -------------------------------------------------------- */

static PyStructSequence_Field object_fields[] = {
    {"kind", "'empty', 'flat point', 'line', 'plane', 'point pair', 'circle' or 'sphere'"},
    {"reality", "'real', 'tangent' or 'imaginary' (flats are real)"},
    {"centre", "the centre (a round, a flat point) or the point nearest the origin (a line, a plane), (3,)"},
    {"direction", "the unit direction (line, point pair) or normal (plane, circle); 0 for a sphere, (3,)"},
    {"r2", "the signed squared radius of a round; 0 for a flat"},
    {"err", "bound of the error of centre, in its length units"},
    {"r2_err", "bound of the error of r2 (0 for a flat)"},
    {"angle_err", "bound of the angle of direction from the exact one, radians (0 where none)"},
    {NULL, NULL}};

static PyStructSequence_Desc object_desc = {
    "garotor.Object",
    "What a conformal object is and where: ga_object (garotor/object.h), from Multivector.object().",
    object_fields, 8};

static PyTypeObject *object_type;

int gpy_objects_init(PyObject *m)
{
    object_type = PyStructSequence_NewType(&object_desc);
    if (!object_type)
        return -1;
    return PyModule_AddObjectRef(m, "Object", (PyObject *)object_type);
}

static PyObject *vec3_array(ga_vec3 v)
{
    npy_intp n = 3;
    PyObject *a = PyArray_SimpleNew(1, &n, NPY_DOUBLE);
    if (a) {
        double *d = PyArray_DATA((PyArrayObject *)a);
        d[0] = v.x, d[1] = v.y, d[2] = v.z;
    }
    return a;
}

static const char *const kind_names[] = {"empty",      "flat point", "line",  "plane",
                                         "point pair", "circle",     "sphere"};
static const char *const reality_names[] = {"real", "tangent", "imaginary"};

static PyObject *object_new(const ga_object *ob)
{
    if (ob->kind < 0 || ob->kind > GA_OBJECT_SPHERE || ob->reality < 0 ||
        ob->reality > GA_REALITY_IMAGINARY) {
        PyErr_SetString(PyExc_SystemError, "Multivector.object: unknown kind or reality");
        return NULL;
    }
    PyObject *o = PyStructSequence_New(object_type);
    if (!o)
        return NULL;
    PyObject *items[8] = {PyUnicode_FromString(kind_names[ob->kind]),
                          PyUnicode_FromString(reality_names[ob->reality]),
                          vec3_array(ob->centre),
                          vec3_array(ob->direction),
                          PyFloat_FromDouble(ob->r2),
                          PyFloat_FromDouble(ob->err),
                          PyFloat_FromDouble(ob->r2_err),
                          PyFloat_FromDouble(ob->angle_err)};
    int ok = 1;
    for (int i = 0; i < 8; i++) {
        ok = ok && items[i];
        PyStructSequence_SET_ITEM(o, i, items[i] ? items[i] : Py_NewRef(Py_None));
    }
    if (!ok) {
        Py_DECREF(o);
        return NULL;
    }
    return o;
}

PyObject *gpy_MV_object(PyObject *self, PyObject *args, PyObject *kw)
{
    static char *kwlist[] = {"origin", "scale", NULL};
    PyObject *origin = Py_None;
    double scale = 1.0;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "|Od:object", kwlist, &origin, &scale))
        return NULL;
    ga_object ob;
    int st;
    if (origin == Py_None && scale == 1.0) {
        st = ga_object_from_mv(MV(self), &ob);
    } else {
        double o[3] = {0, 0, 0};
        if (origin != Py_None && gpy_read_numbers("Multivector.object", "origin", origin, 3,
                                                  "Multivector.object: origin must have shape (3,)", o))
            return NULL;
        if (gpy_finite_number("Multivector.object", scale) < 0)
            return NULL;
        st = ga_object_from_mv_about(MV(self), (ga_vec3){o[0], o[1], o[2]}, scale, &ob);
    }
    if (st == GA_ERR_SINGULAR) {
        int zero = 1;
        for (int i = 0; i < 32; i++) zero = zero && MV(self).c[i] == 0.0;
        if (zero) {
            gpy_raise_status_why("Multivector.object", 0, NULL, 0, st,
                                 "the multivector is 0 (the meet of objects in special position: "
                                 "meet_rel gives it)");
            return NULL;
        }
    }
    return st == GA_OK ? object_new(&ob) : gpy_status_error("Multivector.object", st);
}

/* ---- binary operations --------------------------------------------------------- */

/* the other operand of a method `what`: a Multivector or a number (1), or -1
 * with an exception (TypeError for anything else) */
static int other_operand(const char *what, PyObject *o, ga_mv *b)
{
    int r = gpy_mv_operand(what, o, b);
    if (r == 0)
        PyErr_Format(PyExc_TypeError, "%s: a Multivector or a number", what);
    return r > 0 ? 1 : -1;
}

/* a method whose C function has no status; with a MultivectorArray o, the
   MultivectorArray of the method over o's elements (kern, mvarray.c) */
#define MV_PLAIN(name, what, fn, kern)                                                                       \
    PyObject *gpy_MV_##name(PyObject *self, PyObject *o)                                                     \
    {                                                                                                        \
        ga_mv b;                                                                                             \
        if (PyObject_TypeCheck(o, &gpy_MVAType))                                                             \
            return gpy_mva_binary(what, kern, self, o);                                                      \
        if (other_operand(what, o, &b) < 0)                                                                  \
            return NULL;                                                                                     \
        return gpy_mv_result(what, fn(MV(self), b));                                                         \
    }
/* a method whose C function returns a status */
#define MV_STATUS(name, what, fn, kern)                                                                      \
    PyObject *gpy_MV_##name(PyObject *self, PyObject *o)                                                     \
    {                                                                                                        \
        ga_mv b, r;                                                                                          \
        if (PyObject_TypeCheck(o, &gpy_MVAType))                                                             \
            return gpy_mva_binary(what, kern, self, o);                                                      \
        if (other_operand(what, o, &b) < 0)                                                                  \
            return NULL;                                                                                     \
        int st = fn(MV(self), b, &r);                                                                        \
        return st == GA_OK ? gpy_mv_result(what, r) : gpy_status_error(what, st);                            \
    }

MV_PLAIN(meet, "Multivector.meet", ga_mv_meet, gpy_k_meet)
MV_PLAIN(commutator, "Multivector.commutator", ga_mv_commutator, gpy_k_commutator)
MV_STATUS(join, "Multivector.join", ga_mv_join, gpy_k_join)
MV_STATUS(meet_rel, "Multivector.meet_rel", ga_mv_meet_rel, gpy_k_meet_rel)
MV_STATUS(project, "Multivector.project", ga_mv_project, gpy_k_project)
MV_STATUS(reject, "Multivector.reject", ga_mv_reject, gpy_k_reject)
MV_STATUS(apply, "Multivector.apply", ga_versor_apply, gpy_k_versor_apply)

/* ---- powers ------------------------------------------------------------------------ */

PyObject *gpy_MV_pow(PyObject *self, PyObject *arg)
{
    double t = PyFloat_AsDouble(arg);
    if (t == -1.0 && PyErr_Occurred())
        return NULL;
    if (gpy_finite_number("Multivector.pow", t) < 0)
        return NULL;
    ga_mv r;
    int st = ga_mv_pow(MV(self), t, &r);
    return st == GA_OK ? gpy_mv_result("Multivector.pow", r) : gpy_status_error("Multivector.pow", st);
}

PyObject *gpy_MV_sqrt(PyObject *self, PyObject *u)
{
    (void)u;
    ga_mv r;
    int st = ga_mv_sqrt(MV(self), &r);
    return st == GA_OK ? gpy_mv_result("Multivector.sqrt", r) : gpy_status_error("Multivector.sqrt", st);
}

/* The largest |k| of a ** k: the product is taken k - 1 times in turn */
#define MV_POWER_MAX 1000000L

/* a ** k, k an integer: 1 for k = 0, else (...((b b) b)...) b with k factors
 * b = a (k > 0) or b = a.inverse() (k < 0), left to right, each product
 * ga_mv_gp: a ** 3 is a * a * a bit for bit. */
PyObject *gpy_MV_power(PyObject *x, PyObject *y, PyObject *z)
{
    if (z != Py_None) {
        PyErr_SetString(PyExc_TypeError, "Multivector **: no modulus");
        return NULL;
    }
    if (!PyObject_TypeCheck(x, &gpy_MVType) || !(PyLong_Check(y) || PyArray_IsScalar(y, Integer)))
        Py_RETURN_NOTIMPLEMENTED;
    int overflow = 0;
    PyObject *yl = PyNumber_Index(y);
    if (!yl)
        return NULL;
    long k = PyLong_AsLongAndOverflow(yl, &overflow);
    Py_DECREF(yl);
    if (k == -1 && PyErr_Occurred())
        return NULL;
    if (overflow || k > MV_POWER_MAX || k < -MV_POWER_MAX) {
        PyErr_Format(PyExc_ValueError, "Multivector **: the exponent must be an integer in [-%ld, %ld]",
                     MV_POWER_MAX, MV_POWER_MAX);
        return NULL;
    }
    if (k == 0)
        return gpy_mv_new(ga_mv_scalar(1.0));
    ga_mv b = MV(x);
    if (k < 0) {
        int st = ga_mv_inverse(b, &b);
        if (st != GA_OK)
            return gpy_status_error("Multivector **", st);
        k = -k;
    }
    ga_mv r = b;
    for (long i = 1; i < k; i++) {
        r = ga_mv_gp(r, b);
        if (!ga_mv_isfinite(r))
            break; /* gpy_mv_result says so */
    }
    return gpy_mv_result("Multivector **", r);
}

/* ---- versor constructors ------------------------------------------------------- */

static int read_vec3(const char *what, const char *name, PyObject *obj, ga_vec3 *v)
{
    double x[3];
    char msg[96];
    snprintf(msg, sizeof msg, "%s: %s must have shape (3,)", what, name);
    if (gpy_read_numbers(what, name, obj, 3, msg, x))
        return -1;
    *v = (ga_vec3){x[0], x[1], x[2]};
    return 0;
}

/* (vector, number) arguments of the constructor `what` */
static int vec_and_number(const char *what, PyObject *args, const char *vname, ga_vec3 *v, double *s)
{
    PyObject *vo;
    if (!PyArg_ParseTuple(args, "Od", &vo, s))
        return -1;
    if (read_vec3(what, vname, vo, v) < 0 || gpy_finite_number(what, *s) < 0)
        return -1;
    return 0;
}

PyObject *gpy_MV_reflection(PyObject *cls, PyObject *args)
{
    (void)cls;
    ga_vec3 v;
    double d;
    if (vec_and_number("Multivector.reflection", args, "normal", &v, &d) < 0)
        return NULL;
    return gpy_mv_result("Multivector.reflection", ga_versor_reflection(v, d));
}

PyObject *gpy_MV_inversion(PyObject *cls, PyObject *args)
{
    (void)cls;
    ga_vec3 v;
    double r;
    if (vec_and_number("Multivector.inversion", args, "centre", &v, &r) < 0)
        return NULL;
    return gpy_mv_result("Multivector.inversion", ga_versor_inversion(v, r));
}

PyObject *gpy_MV_dilation(PyObject *cls, PyObject *args)
{
    (void)cls;
    ga_vec3 v;
    double s;
    if (vec_and_number("Multivector.dilation", args, "centre", &v, &s) < 0)
        return NULL;
    ga_mv r;
    int st = ga_versor_dilation(v, s, &r);
    return st == GA_OK ? gpy_mv_result("Multivector.dilation", r)
                       : gpy_status_error("Multivector.dilation", st);
}

PyObject *gpy_MV_transversion(PyObject *cls, PyObject *arg)
{
    (void)cls;
    ga_vec3 v;
    if (read_vec3("Multivector.transversion", "b", arg, &v) < 0)
        return NULL;
    return gpy_mv_result("Multivector.transversion", ga_versor_transversion(v));
}

PyObject *gpy_MV_rotation(PyObject *cls, PyObject *args)
{
    (void)cls;
    ga_vec3 v;
    double a;
    if (vec_and_number("Multivector.rotation", args, "axis", &v, &a) < 0)
        return NULL;
    return gpy_mv_result("Multivector.rotation", ga_versor_rotation(v, a));
}

PyObject *gpy_MV_translation(PyObject *cls, PyObject *arg)
{
    (void)cls;
    ga_vec3 v;
    if (read_vec3("Multivector.translation", "a", arg, &v) < 0)
        return NULL;
    return gpy_mv_result("Multivector.translation", ga_versor_translation(v));
}

/* ---- fits ------------------------------------------------------------------------- */

/* points, an (n, 3) array-like of finite numbers, as a new ga_vec3[n]
 * (PyMem_Free it); NULL with an exception */
static ga_vec3 *read_points(const char *what, PyObject *obj, size_t *n)
{
    PyArrayObject *a = gpy_as_doubles(obj);
    if (!a)
        return NULL;
    if (PyArray_NDIM(a) != 2 || PyArray_DIM(a, 1) != 3) {
        Py_DECREF(a);
        PyErr_Format(PyExc_ValueError, "%s: points must have shape (n, 3)", what);
        return NULL;
    }
    npy_intp count = PyArray_DIM(a, 0);
    const double *d = PyArray_DATA(a);
    npy_intp bad = gpy_first_nonfinite(d, 3 * count);
    if (bad >= 0) {
        char why[160];
        gpy_nonfinite_why("points", a, bad, why, sizeof why);
        gpy_raise_status_why(what, 0, NULL, 0, GA_ERR_NOTFINITE, why);
        Py_DECREF(a);
        return NULL;
    }
    ga_vec3 *p = PyMem_Malloc((size_t)(count ? count : 1) * sizeof *p);
    if (!p) {
        Py_DECREF(a);
        PyErr_NoMemory();
        return NULL;
    }
    for (npy_intp i = 0; i < count; i++) p[i] = (ga_vec3){d[3 * i], d[3 * i + 1], d[3 * i + 2]};
    Py_DECREF(a);
    *n = (size_t)count;
    return p;
}

/* (a, b) (n = 2) or (a, b, c) (n = 3), taking the references; NULL if
 * any is NULL (an exception set) */
static PyObject *tuple_of(int n, PyObject *a, PyObject *b, PyObject *c)
{
    PyObject *t = !a || !b ? NULL : n == 2 ? PyTuple_Pack(2, a, b) : c ? PyTuple_Pack(3, a, b, c) : NULL;
    Py_XDECREF(a);
    Py_XDECREF(b);
    Py_XDECREF(c);
    return t;
}

PyObject *gpy_fit_sphere(PyObject *self, PyObject *obj)
{
    (void)self;
    size_t n;
    ga_vec3 *p = read_points("fit_sphere", obj, &n), c;
    if (!p)
        return NULL;
    double r;
    int st;
    Py_BEGIN_ALLOW_THREADS st = ga_fit_sphere(p, n, &c, &r);
    Py_END_ALLOW_THREADS PyMem_Free(p);
    if (st != GA_OK)
        return gpy_status_error("fit_sphere", st);
    return tuple_of(2, vec3_array(c), PyFloat_FromDouble(r), NULL);
}

PyObject *gpy_fit_plane(PyObject *self, PyObject *obj)
{
    (void)self;
    size_t n;
    ga_vec3 *p = read_points("fit_plane", obj, &n), m;
    if (!p)
        return NULL;
    double d;
    int st;
    Py_BEGIN_ALLOW_THREADS st = ga_fit_plane(p, n, &m, &d);
    Py_END_ALLOW_THREADS PyMem_Free(p);
    if (st != GA_OK)
        return gpy_status_error("fit_plane", st);
    return tuple_of(2, vec3_array(m), PyFloat_FromDouble(d), NULL);
}

PyObject *gpy_fit_circle(PyObject *self, PyObject *obj)
{
    (void)self;
    size_t n;
    ga_vec3 *p = read_points("fit_circle", obj, &n), c, m;
    if (!p)
        return NULL;
    double r;
    int st;
    Py_BEGIN_ALLOW_THREADS st = ga_fit_circle(p, n, &c, &r, &m);
    Py_END_ALLOW_THREADS PyMem_Free(p);
    if (st != GA_OK)
        return gpy_status_error("fit_circle", st);
    return tuple_of(3, vec3_array(c), PyFloat_FromDouble(r), vec3_array(m));
}

PyObject *gpy_fit_line(PyObject *self, PyObject *obj)
{
    (void)self;
    size_t n;
    ga_vec3 *p = read_points("fit_line", obj, &n), u, q;
    if (!p)
        return NULL;
    int st;
    Py_BEGIN_ALLOW_THREADS st = ga_fit_line(p, n, &u, &q);
    Py_END_ALLOW_THREADS PyMem_Free(p);
    if (st != GA_OK)
        return gpy_status_error("fit_line", st);
    return tuple_of(2, vec3_array(u), vec3_array(q), NULL);
}

/* ---- between, interp, mean (object.h) ------------------------------------------ */

/* A.between(B): the rotor of G(4,1) taking A to B (ga_versor_between) */
PyObject *gpy_MV_between(PyObject *self, PyObject *o)
{
    ga_mv b, r;
    if (other_operand("Multivector.between", o, &b) < 0)
        return NULL;
    int st = ga_versor_between(MV(self), b, &r);
    return st == GA_OK ? gpy_mv_result("Multivector.between", r)
                       : gpy_status_error("Multivector.between", st);
}

/* A.interp(B, t): the object at t along A.between(B) (ga_object_interp) */
PyObject *gpy_MV_interp(PyObject *self, PyObject *args)
{
    PyObject *o;
    double t;
    if (!PyArg_ParseTuple(args, "Od:interp", &o, &t))
        return NULL;
    ga_mv b, r;
    if (other_operand("Multivector.interp", o, &b) < 0)
        return NULL;
    if (gpy_finite_number("Multivector.interp", t) < 0)
        return NULL;
    int st = ga_object_interp(MV(self), b, t, &r);
    return st == GA_OK ? gpy_mv_result("Multivector.interp", r) : gpy_status_error("Multivector.interp", st);
}

/* object_mean(objects, weights=None, *, read=False): ga_object_mean over a
 * sequence of Multivectors, or with read=True ga_object_mean_read: the mean
 * and its read-back with the bounds the mean is known to, (Multivector,
 * Object); an error names the first bad element (its index) */
PyObject *gpy_object_mean(PyObject *self, PyObject *args, PyObject *kw)
{
    (void)self;
    static const char *what = "object_mean";
    static char *kwlist[] = {"objects", "weights", "read", NULL};
    PyObject *objs, *wobj = Py_None;
    int read = 0;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "O|O$p:object_mean", kwlist, &objs, &wobj, &read))
        return NULL;
    PyObject *seq = PySequence_Fast(objs, "object_mean: objects must be a sequence of Multivectors");
    if (!seq)
        return NULL;
    npy_intp n = PySequence_Fast_GET_SIZE(seq);
    PyArrayObject *wa = NULL;
    ga_mv *A = PyMem_Malloc((size_t)(n ? n : 1) * sizeof *A), r;
    PyObject *result = NULL;
    char why[160];
    if (!A) {
        PyErr_NoMemory();
        goto done;
    }
    if (n == 0) {
        PyErr_Format(PyExc_ValueError, "%s: no objects", what);
        goto done;
    }
    for (npy_intp i = 0; i < n; i++) {
        PyObject *x = PySequence_Fast_GET_ITEM(seq, i);
        if (!PyObject_TypeCheck(x, &gpy_MVType)) {
            PyErr_Format(PyExc_TypeError, "%s: objects[%zd] is not a Multivector", what, (Py_ssize_t)i);
            goto done;
        }
        A[i] = MV(x);
        if (!ga_mv_isfinite(A[i])) {
            snprintf(why, sizeof why, "objects[%zd] holds NaN or an infinity", (Py_ssize_t)i);
            gpy_raise_status_why(what, 1, &n, i, GA_ERR_NOTFINITE, why);
            goto done;
        }
    }
    const double *w = NULL;
    if (wobj != Py_None) {
        if (!(wa = gpy_as_doubles(wobj)))
            goto done;
        if (PyArray_NDIM(wa) != 1 || PyArray_DIM(wa, 0) != n) {
            PyErr_Format(PyExc_ValueError, "%s: weights must have shape (%zd,), one for each object", what,
                         (Py_ssize_t)n);
            goto done;
        }
        w = PyArray_DATA(wa);
        for (npy_intp i = 0; i < n; i++)
            if (!isfinite(w[i]) || !(w[i] >= 0.0)) {
                snprintf(why, sizeof why, "weights[%zd] is %s", (Py_ssize_t)i,
                         isfinite(w[i]) ? "negative" : "not finite");
                gpy_raise_status_why(what, 1, &n, i, isfinite(w[i]) ? GA_ERR_ARG : GA_ERR_NOTFINITE, why);
                goto done;
            }
    }
    ga_object ob;
    int st = read ? ga_object_mean_read(A, w, (size_t)n, &r, &ob) : ga_object_mean(A, w, (size_t)n, &r);
    if (st == GA_OK) {
        result = gpy_mv_result(what, r);
        if (result && read) {
            PyObject *o = object_new(&ob);
            PyObject *pair = o ? PyTuple_Pack(2, result, o) : NULL;
            Py_XDECREF(o);
            Py_SETREF(result, pair);
        }
        goto done;
    }
    /* name the object the status is about, where one is */
    ga_object o0, oi;
    int s0 = ga_object_from_mv(A[0], &o0);
    for (npy_intp i = 0; i < n; i++) {
        int si = i ? ga_object_from_mv(A[i], &oi) : s0;
        if (si != GA_OK || (si == GA_OK && i == 0 && o0.kind == GA_OBJECT_EMPTY)) {
            snprintf(why, sizeof why, "objects[%zd] is no object to average", (Py_ssize_t)i);
            gpy_raise_status_why(what, 1, &n, i, si != GA_OK ? si : st, why);
            goto done;
        }
        if (i && s0 == GA_OK && oi.kind != o0.kind && st == GA_ERR_ARG) {
            snprintf(why, sizeof why, "objects[%zd] is of another kind than objects[0]", (Py_ssize_t)i);
            gpy_raise_status_why(what, 1, &n, i, st, why);
            goto done;
        }
    }
    gpy_status_error(what, st);
done:
    Py_XDECREF(wa);
    PyMem_Free(A);
    Py_DECREF(seq);
    return result;
}
