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
    unsigned grades; /* V's parity: grades 0, 2, 4 or 1, 3, 5 */
} versor_prep;

/* p->V finite, its grades g */
static ga_status versor_prepare(unsigned g, versor_prep *p)
{
    int ev = (g & 0x15u) != 0, od = (g & 0x2au) != 0; /* grades 0, 2, 4 and 1, 3, 5 */
    if (ev && od)
        return GA_ERR_ARG;
    p->odd = od;
    p->grades = od ? 0x2au : 0x15u;
    return gak_inverse_one_parity(&p->V, p->grades, &p->Vi);
}

/* (V X^) V^-1: V and V^-1 have one parity, so each product runs on the
   kernels of X's grades (gak_gp: V times one grade of X, or one parity; then
   that parity times V^-1), the numbers of the two dense products. */
static unsigned versor_first(const versor_prep *p, const ga_mv *X, ga_mv *T)
{
    ga_mv Xh;
    if (p->odd)
        Xh = ga_mv_involute(*X);
    const ga_mv *Y = p->odd ? &Xh : X;
    unsigned gx = gak_grades(Y->c);
    gak_gp_g(p->V.c, p->grades, Y->c, gx, T->c);
    /* T has V's parity times each of X's: one parity where X has one */
    return (gx & 0x15u ? p->grades : 0u) | (gx & 0x2au ? p->grades ^ 0x3fu : 0u);
}

static void versor_sandwich(const versor_prep *p, const ga_mv *X, ga_mv *out)
{
    ga_mv T;
    unsigned gt = versor_first(p, X, &T);
    gak_gp_g(T.c, gt, p->Vi.c, p->grades, out->c);
}

ga_status ga_versor_apply(ga_mv V, ga_mv X, ga_mv *out)
{
    if (!out)
        return GA_ERR_ARG;
    if (!gak_isfinite(V.c) || !gak_isfinite(X.c))
        return GA_ERR_NOTFINITE;
    /* V X^ before V^-1: it does not need it, and runs beside it */
    versor_prep p;
    p.V = V;
    unsigned g = gak_grades(V.c);
    p.odd = (g & 0x2au) != 0;
    p.grades = p.odd ? 0x2au : 0x15u;
    ga_mv T;
    unsigned gt = versor_first(&p, &X, &T);
    ga_status st = versor_prepare(g, &p);
    if (st != GA_OK)
        return st;
    gak_gp_g(T.c, gt, p.Vi.c, p.grades, out->c);
    return GA_OK;
}

ga_status ga_versor_apply_many(ga_mv V, const ga_mv *in, size_t n, ga_mv *out)
{
    if (!in || !out)
        return GA_ERR_ARG;
    if (!gak_isfinite(V.c))
        return GA_ERR_NOTFINITE;
    for (size_t i = 0; i < n; i++)
        if (!gak_isfinite(in[i].c))
            return GA_ERR_NOTFINITE;
    versor_prep p;
    p.V = V;
    ga_status st = versor_prepare(gak_grades(V.c), &p);
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
