/* python/ufuncs.c: garotor.ufunc, numpy generalized ufuncs of the module's
 * element-wise kernels (docs/python.md, "Generalized ufuncs"), made with
 * PyUFunc_FromFuncAndDataAndSignature: exp (6)->(4,4), log (4,4)->(6),
 * compose, inverse, apply on each group, the quaternion, pose and dual
 * quaternion conversions, up and down, and the multivector products and
 * functions (32),(32)->(32), ... numpy's machinery gives them broadcasting,
 * out=, any memory layout, dtype casting (a float64 loop, inputs cast
 * with numpy's casting rules), the GIL released around the loop, and the
 * protocols of other array libraries (__array_ufunc__).
 *
 * Each element is computed by the kernel that the module's own call runs
 * (functions.c, mvarray.c), so the results are that call's bit for bit. A
 * loop sees pointers and strides, never the element's position in the
 * arrays, so it cannot name an index as the module's calls do; its policy is
 * numpy's own for invalid operations instead: an element whose kernel fails
 * (a status, a NaN or an infinity in, a result that would not be finite) gets
 * NaN in every number of its result, and the loop raises the floating-point
 * flag "invalid", which numpy reports as its errstate says (a
 * RuntimeWarning by default, FloatingPointError under
 * numpy.errstate(invalid="raise")). The flags the kernels raise while
 * computing good elements are put back as they were: "invalid" after a call
 * means a bad element.
 */
#include "module.h"

#include <fenv.h>
#include <math.h>
#include <stdint.h>

#include <numpy/ufuncobject.h>

typedef struct {
    const char *name, *sig, *doc;
    gpy_kernel_fn kernel;
    const void *ctx;
    int nin;
    gpy_core in[GPY_MAX_IN], out; /* fixed core shapes (names unused) */
} ufdef;

#define C1(n) GPY_CORE1(n, NULL)
#define C2(n, m) GPY_CORE2(n, m, NULL)
#define C0                                                                                                   \
    {                                                                                                        \
        0, {0, 0}, NULL                                                                                      \
    }
#define MAT C2(4, 4)
#define MV C1(32)

#define GROUP_UFUNCS(sfx, g, docg)                                                                           \
    {"exp" sfx,                                                                                              \
     "(6)->(4,4)",                                                                                           \
     "exp" sfx "(xi): twists (..., 6) -> rigid motions (..., 4, 4)" docg,                                    \
     gpy_k_exp,                                                                                              \
     g,                                                                                                      \
     1,                                                                                                      \
     {C1(6)},                                                                                                \
     MAT},                                                                                                   \
        {"log" sfx,                                                                                          \
         "(4,4)->(6)",                                                                                       \
         "log" sfx "(T): rigid motions (..., 4, 4) -> principal twists (..., 6)" docg,                       \
         gpy_k_log,                                                                                          \
         g,                                                                                                  \
         1,                                                                                                  \
         {MAT},                                                                                              \
         C1(6)},                                                                                             \
        {"compose" sfx,                                                                                      \
         "(4,4),(4,4)->(4,4)",                                                                               \
         "compose" sfx "(A, B): A B (B first)" docg,                                                         \
         gpy_k_compose,                                                                                      \
         g,                                                                                                  \
         2,                                                                                                  \
         {MAT, MAT},                                                                                         \
         MAT},                                                                                               \
        {"inverse" sfx, "(4,4)->(4,4)", "inverse" sfx "(T): T^-1" docg, gpy_k_inverse, g, 1, {MAT}, MAT},    \
    {                                                                                                        \
        "apply" sfx, "(4,4),(3)->(3)", "apply" sfx "(T, points): T moves points (..., 3)" docg, gpy_k_apply, \
            g, 2, {MAT, C1(3)}, C1(3)                                                                        \
    }

#define MV2(name, kern, what)                                                                                \
    {                                                                                                        \
        name, "(32),(32)->(32)", name "(a, b): " what ", element by element", gpy_k_##kern, NULL, 2,         \
            {MV, MV}, MV                                                                                     \
    }
#define MV1(name, kern, what)                                                                                \
    {                                                                                                        \
        name, "(32)->(32)", name "(a): " what ", element by element", gpy_k_##kern, NULL, 1, {MV}, MV        \
    }

static ufdef defs[] = {
    GROUP_UFUNCS("", &ga_group_cga, " (garotor.exp ... with group='cga')"),
    GROUP_UFUNCS("_matrix", &ga_group_se3, " (group='matrix')"),
    {"exp_affine",
     "(4,4)->(4,4)",
     "exp_affine(A): generators (last row zero) -> motions (group='affine')",
     gpy_k_exp,
     &ga_group_affine,
     1,
     {MAT},
     MAT},
    {"log_affine",
     "(4,4)->(4,4)",
     "log_affine(T): the principal log as (..., 4, 4) (group='affine')",
     gpy_k_log,
     &ga_group_affine,
     1,
     {MAT},
     MAT},
    {"compose_affine",
     "(4,4),(4,4)->(4,4)",
     "compose_affine(A, B): A B (group='affine')",
     gpy_k_compose,
     &ga_group_affine,
     2,
     {MAT, MAT},
     MAT},
    {"inverse_affine",
     "(4,4)->(4,4)",
     "inverse_affine(T): T^-1 (group='affine')",
     gpy_k_inverse,
     &ga_group_affine,
     1,
     {MAT},
     MAT},
    {"apply_affine",
     "(4,4),(3)->(3)",
     "apply_affine(T, points) (group='affine')",
     gpy_k_apply,
     &ga_group_affine,
     2,
     {MAT, C1(3)},
     C1(3)},
    {"from_quat",
     "(4),(3)->(4,4)",
     "from_quat(q, t): unit quaternions x y z w and translations -> (..., 4, 4)",
     gpy_k_from_quat,
     NULL,
     2,
     {C1(4), C1(3)},
     MAT},
    {"to_quat",
     "(4,4)->(4)",
     "to_quat(T): the rotation of T as a quaternion x y z w, w >= 0",
     gpy_k_to_quat,
     NULL,
     1,
     {MAT},
     C1(4)},
    {"from_pose",
     "(7)->(4,4)",
     "from_pose(P): rows x y z qx qy qz qw -> (..., 4, 4)",
     gpy_k_from_pose,
     NULL,
     1,
     {C1(7)},
     MAT},
    {"to_pose",
     "(n,4,4)->(n,7)",
     "to_pose(T): (..., n, 4, 4) -> rows x y z qx qy qz qw, the quaternion's sign following the previous "
     "pose along n (garotor.to_pose(T, continuous=True))",
     gpy_k_to_pose,
     NULL,
     1,
     {MAT},
     C1(7)},
    {"to_dualquat",
     "(4,4)->(8)",
     "to_dualquat(T): real x y z w, then dual x y z w",
     gpy_k_to_dualquat,
     NULL,
     1,
     {MAT},
     C1(8)},
    {"from_dualquat",
     "(8)->(4,4)",
     "from_dualquat(d): unit dual quaternions -> (..., 4, 4)",
     gpy_k_from_dualquat,
     NULL,
     1,
     {C1(8)},
     MAT},
    {"up", "(3)->(32)", "up(x): points -> conformal points", gpy_k_up, NULL, 1, {C1(3)}, MV},
    {"down", "(32)->(3)", "down(X): conformal points -> points", gpy_k_down, NULL, 1, {MV}, C1(3)},
    MV2("gp", gp, "the geometric product (ga_mv_gp)"),
    MV2("op", op, "the outer product (ga_mv_op)"),
    MV2("lc", lc, "the left contraction (ga_mv_lc)"),
    MV2("dot", dot, "the fat dot (ga_mv_dot)"),
    MV2("ip", ip, "Hestenes' inner product (ga_mv_ip)"),
    MV2("regressive", regressive, "the regressive product (ga_mv_regressive)"),
    MV2("commutator", commutator, "(a b - b a) / 2 (ga_mv_commutator)"),
    MV2("meet", meet, "the meet (ga_mv_meet)"),
    MV2("join", join, "the join (ga_mv_join)"),
    MV2("meet_rel", meet_rel, "the meet relative to the join (ga_mv_meet_rel)"),
    MV2("project", project, "the projection of a onto the blade b (ga_mv_project)"),
    MV2("reject", reject, "the rejection of a from the blade b (ga_mv_reject)"),
    MV2("mv_apply", versor_apply, "the versor a's sandwich of b (ga_versor_apply)"),
    MV1("reverse", reverse, "~a"),
    MV1("involute", involute, "the grade involution"),
    MV1("conjugate", conjugate, "the Clifford conjugate"),
    MV1("dual", dual, "a I^-1"),
    MV1("undual", undual, "a I"),
    MV1("mv_inverse", mv_inverse, "the inverse (ga_mv_inverse)"),
    MV1("mv_exp", mv_exp, "exp of a bivector (Multivector.exp)"),
    MV1("mv_log", mv_log, "the principal log of a rotor (Multivector.log)"),
    MV1("mv_sqrt", mv_sqrt, "the principal square root of a rotor (ga_mv_sqrt)"),
    {"mv_pow",
     "(32),()->(32)",
     "mv_pow(R, t): R^t of a rotor (ga_mv_pow), element by element",
     gpy_k_mv_pow,
     NULL,
     2,
     {MV, C0},
     MV},
    {"norm2", "(32)->()", "norm2(a): <a ~a>_0, element by element", gpy_k_norm2, NULL, 1, {MV}, C0},
};

#define NDEFS (sizeof defs / sizeof *defs)

static npy_intp core_count(const gpy_core *c)
{
    npy_intp s = 1;
    for (int i = 0; i < c->ncore; i++) s *= c->core[i];
    return s;
}

/* 1 if an element of core shape c with core strides cs lies in C order */
static int plain(const gpy_core *c, const npy_intp *cs)
{
    const npy_intp w = (npy_intp)sizeof(double);
    return c->ncore == 0 || (c->ncore == 1 && cs[0] == w) ||
           (c->ncore == 2 && cs[1] == w && cs[0] == c->core[1] * w);
}

/* One operand's element at p, core shape c and core strides cs: a pointer to
 * its numbers in C order, p itself where they lie so, else buf filled. */
static const double *gather(const char *p, const gpy_core *c, const npy_intp *cs, double *buf)
{
    if (plain(c, cs) && (uintptr_t)p % sizeof(double) == 0)
        return (const double *)p;
    npy_intp n0 = c->ncore > 0 ? c->core[0] : 1, n1 = c->ncore > 1 ? c->core[1] : 1;
    npy_intp s0 = c->ncore > 0 ? cs[0] : 0, s1 = c->ncore > 1 ? cs[1] : 0;
    for (npy_intp i = 0; i < n0; i++)
        for (npy_intp j = 0; j < n1; j++) memcpy(buf + i * n1 + j, p + i * s0 + j * s1, sizeof *buf);
    return buf;
}

static void scatter(char *p, const gpy_core *c, const npy_intp *cs, const double *v)
{
    npy_intp n0 = c->ncore > 0 ? c->core[0] : 1, n1 = c->ncore > 1 ? c->core[1] : 1;
    npy_intp s0 = c->ncore > 0 ? cs[0] : 0, s1 = c->ncore > 1 ? cs[1] : 0;
    for (npy_intp i = 0; i < n0; i++)
        for (npy_intp j = 0; j < n1; j++) memcpy(p + i * s0 + j * s1, v + i * n1 + j, sizeof *v);
}

static void nan_fill(double *o, npy_intp osize)
{
    for (npy_intp m = 0; m < osize; m++) o[m] = NAN;
}

/* One element: the kernel, and NaN for a failed one; 1 if it failed. */
static int element(const ufdef *d, void *ctx, const double *const *in, double *o, npy_intp osize, npy_intp k)
{
    int st = d->kernel(ctx, in, o, k);
    if (st == GA_OK && gpy_all_finite(o, osize))
        return 0;
    nan_fill(o, osize);
    return 1;
}

#define FAST_BLOCK 64 /* elements checked for NaN and infinity together */

/* The loop of every ufunc but to_pose: dims[0] elements; steps: the
 * operands' outer strides, then their core strides, operand by operand. */
static void loop(char **args, npy_intp const *dims, npy_intp const *steps, void *data)
{
    const ufdef *d = data;
    int nargs = d->nin + 1;
    const npy_intp *cs[GPY_MAX_IN + 1];
    const npy_intp *next = steps + nargs;
    for (int j = 0; j < d->nin; j++) {
        cs[j] = next;
        next += d->in[j].ncore;
    }
    cs[d->nin] = next;
    npy_intp osize = core_count(&d->out);
    /* results straight to their place where it is C order and aligned */
    int direct = plain(&d->out, cs[d->nin]) && (uintptr_t)args[d->nin] % sizeof(double) == 0 &&
                 steps[d->nin] % (npy_intp)sizeof(double) == 0;
    fexcept_t saved;
    fegetexceptflag(&saved, FE_ALL_EXCEPT);
    int failed = 0;
    /* one element of input 0 for all (a motion on many points): the batch,
       where the operands lie in C order; a status or a result not finite, and
       the loop below does them one by one (NaN for each failed one) */
    const npy_intp w = (npy_intp)sizeof(double);
    int (*many)(void *, const double *, const double *, npy_intp,
                double *) = d->kernel == gpy_k_apply        ? gpy_apply_many
                          : d->kernel == gpy_k_versor_apply ? gpy_versor_apply_many
                                                            : NULL; /* gpy_kernel_call.many */
    if (many && d->nin == 2 && dims[0] > 1 && direct && steps[0] == 0 && plain(&d->in[0], cs[0]) &&
        plain(&d->in[1], cs[1]) && steps[1] == core_count(&d->in[1]) * w && steps[2] == osize * w &&
        (uintptr_t)args[0] % sizeof(double) == 0 && (uintptr_t)args[1] % sizeof(double) == 0 &&
        many((void *)d->ctx, (const double *)args[0], (const double *)args[1], dims[0], (double *)args[2]) ==
            GA_OK &&
        gpy_all_finite((const double *)args[2], dims[0] * osize)) {
        fesetexceptflag(&saved, FE_ALL_EXCEPT);
        return;
    }
    /* every operand's elements in C order and aligned, the results one after
       the other: the kernels write straight to the result, which is checked
       for NaN and infinity a block at a time (one pass of vector code), an
       element at a time only in a block that holds one; the numbers of the
       loop below, bit for bit (issue 30: per element within 1.2 times the
       plain C loop's time) */
    int contiguous = direct && steps[d->nin] == osize * w;
    for (int j = 0; contiguous && j < d->nin; j++)
        contiguous = plain(&d->in[j], cs[j]) && (uintptr_t)args[j] % sizeof(double) == 0 && steps[j] % w == 0;
    for (npy_intp i0 = 0; contiguous && i0 < dims[0]; i0 += FAST_BLOCK) {
        npy_intp m = dims[0] - i0 < FAST_BLOCK ? dims[0] - i0 : FAST_BLOCK;
        double *o0 = (double *)args[d->nin] + i0 * osize;
        for (npy_intp i = 0; i < m; i++) {
            const double *in[GPY_MAX_IN];
            for (int j = 0; j < d->nin; j++) in[j] = (const double *)(args[j] + (i0 + i) * steps[j]);
            if (d->kernel((void *)d->ctx, in, o0 + i * osize, 0) != GA_OK) {
                nan_fill(o0 + i * osize, osize);
                failed = 1;
            }
        }
        if (!gpy_all_finite(o0, m * osize))
            for (npy_intp i = 0; i < m; i++)
                if (!gpy_all_finite(o0 + i * osize, osize)) {
                    nan_fill(o0 + i * osize, osize);
                    failed = 1;
                }
    }
    for (npy_intp i = 0; !contiguous && i < dims[0]; i++) {
        double buf[GPY_MAX_IN][GPY_MAX_OUT], obuf[GPY_MAX_OUT];
        const double *in[GPY_MAX_IN];
        char *op = args[d->nin] + i * steps[d->nin];
        double *o = direct ? (double *)op : obuf;
        for (int j = 0; j < d->nin; j++) in[j] = gather(args[j] + i * steps[j], &d->in[j], cs[j], buf[j]);
        failed |= element(d, (void *)d->ctx, in, o, osize, 0);
        if (!direct)
            scatter(op, &d->out, cs[d->nin], o);
    }
    fesetexceptflag(&saved, FE_ALL_EXCEPT);
    if (failed)
        feraiseexcept(FE_INVALID);
}

/* to_pose, (n,4,4)->(n,7): dims[1] is n; each run of n poses continuous */
static void loop_to_pose(char **args, npy_intp const *dims, npy_intp const *steps, void *data)
{
    const ufdef *d = data;
    npy_intp n = dims[1];
    const npy_intp *ics = steps + 2, *ocs = steps + 5; /* (n, 4, 4) and (n, 7) */
    fexcept_t saved;
    fegetexceptflag(&saved, FE_ALL_EXCEPT);
    int failed = 0;
    for (npy_intp i = 0; i < dims[0]; i++) {
        gpy_pose_ctx c = {n, {1, 0, 0, 0}};
        for (npy_intp k = 0; k < n; k++) {
            double buf[16], o[7];
            const double *in[1] = {gather(args[0] + i * steps[0] + k * ics[0], &d->in[0], ics + 1, buf)};
            failed |= element(d, &c, in, o, 7, k);
            scatter(args[1] + i * steps[1] + k * ocs[0], &d->out, ocs + 1, o);
        }
    }
    fesetexceptflag(&saved, FE_ALL_EXCEPT);
    if (failed)
        feraiseexcept(FE_INVALID);
}

static PyUFuncGenericFunction funcs[NDEFS][1];
static void *datas[NDEFS][1];
static char types[NDEFS][GPY_MAX_IN + 1];

int gpy_ufuncs_init(PyObject *m)
{
    if (_import_umath() < 0)
        return -1;
    PyObject *u = PyModule_New("garotor.ufunc");
    if (!u)
        return -1;
    if (PyModule_AddStringConstant(u, "__doc__",
                                   "garotor's element-wise calls as numpy generalized ufuncs "
                                   "(docs/python.md, \"Generalized ufuncs\"): a bad element gives NaN and "
                                   "numpy's 'invalid' floating-point error.") < 0)
        goto fail;
    for (size_t i = 0; i < NDEFS; i++) {
        const ufdef *d = &defs[i];
        funcs[i][0] = strcmp(d->name, "to_pose") == 0 ? loop_to_pose : loop;
        datas[i][0] = (void *)d;
        for (int j = 0; j <= d->nin; j++) types[i][j] = NPY_DOUBLE;
        PyObject *f = PyUFunc_FromFuncAndDataAndSignature(funcs[i], datas[i], types[i], 1, d->nin, 1,
                                                          PyUFunc_None, d->name, d->doc, 0, d->sig);
        if (!f || PyModule_AddObject(u, d->name, f) < 0) {
            Py_XDECREF(f);
            goto fail;
        }
    }
    /* `import garotor.ufunc` and pickling a ufunc by its module find it */
    PyObject *mods = PyImport_GetModuleDict();
    if (!mods || PyDict_SetItemString(mods, "garotor.ufunc", u) < 0)
        goto fail;
    return PyModule_AddObject(m, "ufunc", u) < 0 ? (Py_DECREF(u), -1) : 0;
fail:
    Py_DECREF(u);
    return -1;
}
