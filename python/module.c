/* python/module.c: the CPython extension module garotor._garotor, whose
 * names the package garotor gives (python/garotor/__init__.py,
 * docs/python.md): its function table and PyInit__garotor. module.h says
 * which file holds what.
 */
#define GPY_IMPORT_ARRAY /* import_array below fills numpy's API table */
#include "module.h"

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
    {"object_mean", (PyCFunction)(void (*)(void))gpy_object_mean, METH_VARARGS | METH_KEYWORDS,
     "object_mean(objects, weights=None, *, read=False): the weighted mean of Multivector objects of one "
     "kind (ga_object_mean; weights None: equal); read=True: (mean, Object), the Object with the bounds "
     "the mean is known to (ga_object_mean_read)."},
    {"fit_sphere", gpy_fit_sphere, METH_O,
     "fit_sphere(points): the least-squares sphere through (n, 3) points, n >= 4: (centre, radius)."},
    {"fit_plane", gpy_fit_plane, METH_O,
     "fit_plane(points): the least-squares plane m.x = d through (n, 3) points, n >= 3: (m, d)."},
    {"fit_circle", gpy_fit_circle, METH_O,
     "fit_circle(points): the least-squares circle through (n, 3) points, n >= 3: (centre, radius, normal)."},
    {"fit_line", gpy_fit_line, METH_O,
     "fit_line(points): the least-squares line through (n, 3) points, n >= 2: (direction, point)."},
    {NULL, NULL, 0, NULL}};

static struct PyModuleDef garotor_module = {PyModuleDef_HEAD_INIT,
                                            "garotor._garotor",
                                            "garotor: rigid motions in conformal geometric algebra G(4,1), "
                                            "vectorised over numpy arrays (docs/python.md).",
                                            -1,
                                            module_methods,
                                            NULL,
                                            NULL,
                                            NULL,
                                            NULL};

PyMODINIT_FUNC PyInit__garotor(void)
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
        PyModule_AddFunctions(m, gpy_jacobian_methods) < 0 ||
        PyModule_AddFunctions(m, gpy_trajectory_methods) < 0)
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
