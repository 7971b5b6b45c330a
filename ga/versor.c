/* ga/versor.c: the versors of G(4,1) (products of vectors, even or odd) and
 * their sandwich V X^ V^-1 (ga_versor_apply, on the sparse kernels of
 * ga/mv_kernels.c, and over arrays: ga_versor_apply_many), and the conformal
 * transformations as versors: reflection, inversion, dilation,
 * transversion, rotation, translation. docs/versors.md has their table.
 * exp, log and split of bivectors and rotors: ga/mv_exp.c, ga/mv_log.c,
 * ga/mv_split.c.
 */
#include <garotor/versor.h>

#include <garotor/conformal.h>
#include <garotor/rotor.h>
#include <math.h>

#include "internal/mv_kernels.h"

/* What the sandwich of V needs, computed once: V^-1 and V's parity. */
typedef struct {
    ga_mv V, Vi;
    int odd;
} versor_prep;

static ga_status versor_prepare(ga_mv V, versor_prep *p)
{
    if (!ga_mv_isfinite(V))
        return GA_ERR_NOTFINITE;
    double ev = 0.0, od = 0.0;
    for (int i = 0; i < 32; i++) {
        if (ga_blade_grade(i) % 2)
            od = fmax(od, fabs(V.c[i]));
        else
            ev = fmax(ev, fabs(V.c[i]));
    }
    if (ev > 0.0 && od > 0.0)
        return GA_ERR_ARG;
    int st = ga_mv_inverse(V, &p->Vi);
    if (st != GA_OK)
        return st;
    p->V = V;
    p->odd = od > 0.0;
    return GA_OK;
}

/* (V X^) V^-1: V and V^-1 have one parity, so each product runs on the
   kernels of X's grades (gak_gp: V times one grade of X, or one parity; then
   that parity times V^-1), the numbers of the two dense products. */
static void versor_sandwich(const versor_prep *p, const ga_mv *X, ga_mv *out)
{
    ga_mv Y = p->odd ? ga_mv_involute(*X) : *X, T;
    gak_gp(p->V.c, Y.c, T.c);
    gak_gp(T.c, p->Vi.c, out->c);
}

ga_status ga_versor_apply(ga_mv V, ga_mv X, ga_mv *out)
{
    if (!out)
        return GA_ERR_ARG;
    if (!ga_mv_isfinite(V) || !ga_mv_isfinite(X))
        return GA_ERR_NOTFINITE;
    versor_prep p;
    ga_status st = versor_prepare(V, &p);
    if (st != GA_OK)
        return st;
    versor_sandwich(&p, &X, out);
    return GA_OK;
}

ga_status ga_versor_apply_many(ga_mv V, const ga_mv *in, size_t n, ga_mv *out)
{
    if (!in || !out)
        return GA_ERR_ARG;
    for (size_t i = 0; i < n; i++)
        if (!ga_mv_isfinite(in[i]))
            return GA_ERR_NOTFINITE;
    versor_prep p;
    ga_status st = versor_prepare(V, &p);
    if (st != GA_OK)
        return st;
    for (size_t i = 0; i < n; i++) {
        ga_mv y;
        versor_sandwich(&p, &in[i], &y);
        out[i] = y;
    }
    return GA_OK;
}

ga_mv ga_versor_reflection(ga_vec3 normal, double distance) { return ga_plane_dual(normal, distance); }

ga_mv ga_versor_inversion(ga_vec3 centre, double radius) { return ga_sphere_dual(centre, radius); }

ga_status ga_versor_dilation(ga_vec3 c, double s, ga_mv *out)
{
    if (!out)
        return GA_ERR_ARG;
    if (!isfinite(s) || !isfinite(c.x) || !isfinite(c.y) || !isfinite(c.z))
        return GA_ERR_NOTFINITE;
    if (!(s > 0.0))
        return GA_ERR_ARG;
    /* exp(a e45) = cosh a + sinh a e45 scales by e^(-2a) (docs/versors.md) */
    double a = -0.5 * log(s);
    ga_mv D = ga_mv_scalar(cosh(a));
    D.c[GA_BLADE_E45] = sinh(a);
    ga_mv T = ga_versor_translation(c), Ti = ga_versor_translation((ga_vec3){-c.x, -c.y, -c.z});
    *out = ga_mv_gp(ga_mv_gp(T, D), Ti);
    return GA_OK;
}

ga_mv ga_versor_transversion(ga_vec3 b)
{
    /* 1 + nbar b/2, nbar = e4 - e5: the products e4 b and -e5 b */
    ga_mv K = ga_mv_scalar(1.0);
    K.c[GA_BLADE_E14] = -0.5 * b.x; /* e4 e1 = -e14 */
    K.c[GA_BLADE_E24] = -0.5 * b.y;
    K.c[GA_BLADE_E34] = -0.5 * b.z;
    K.c[GA_BLADE_E15] = 0.5 * b.x; /* -e5 e1 = e15 */
    K.c[GA_BLADE_E25] = 0.5 * b.y;
    K.c[GA_BLADE_E35] = 0.5 * b.z;
    return K;
}

ga_mv ga_versor_rotation(ga_vec3 axis, double angle)
{
    return ga_rotor_to_mv(ga_rotor_rotation(axis, angle));
}

ga_mv ga_versor_translation(ga_vec3 a) { return ga_rotor_to_mv(ga_rotor_translation(a)); }
