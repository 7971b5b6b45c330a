/* interp/group_affine.c: ga_group_affine, homogeneous 4x4 matrices with
 * det > 0 (ga_mat4): the general expm and logm (mat4.h; Higham's scaling
 * and squaring, inverse scaling and squaring); an algebra element is the
 * top three rows of a 4x4 whose last row is zero, and dexp is its series.
 */
#include <math.h>
#include <string.h>

#include <garotor/group.h>
#include <garotor/mat4.h>

#include "internal/groups.h"

/* Algebra element (12 doubles, rows 0..2) <-> 4x4 with a zero last row. */
static ga_mat4 aff_hat(const double *x)
{
    ga_mat4 a;
    memcpy(a.m, x, 12 * sizeof(double));
    a.m[12] = a.m[13] = a.m[14] = a.m[15] = 0.0;
    return a;
}
static void aff_vee(ga_mat4 a, double *x) { memcpy(x, a.m, 12 * sizeof(double)); }
static int aff_vee_checked(ga_mat4 a, double *x)
{
    for (int i = 0; i < 16; ++i)
        if (!isfinite(a.m[i]))
            return GA_ERR_NOTFINITE;
    if (a.m[12] != 0.0 || a.m[13] != 0.0 || a.m[14] != 0.0 || a.m[15] != 0.0)
        return GA_ERR_ARG;
    aff_vee(a, x);
    return GA_OK;
}

static int aff_inverse(const void *a, void *out)
{
    ga_mat4 r;
    int st = ga_mat4_inverse(*(const ga_mat4 *)a, &r);
    if (st != GA_OK)
        return st;
    r.m[12] = r.m[13] = r.m[14] = 0.0;
    r.m[15] = 1.0; /* exactly homogeneous */
    *(ga_mat4 *)out = r;
    return GA_OK;
}
static int aff_exp(const double *x, void *out)
{
    ga_mat4 r;
    int st = ga_mat4_expm(aff_hat(x), &r);
    if (st != GA_OK)
        return st;
    r.m[12] = r.m[13] = r.m[14] = 0.0;
    r.m[15] = 1.0; /* exp of a zero last row */
    *(ga_mat4 *)out = r;
    return GA_OK;
}
static int aff_log(const void *g, double *x)
{
    ga_mat4 l;
    int st = ga_mat4_logm(*(const ga_mat4 *)g, &l);
    if (st == GA_OK)
        aff_vee(l, x);
    return st;
}
static void aff_adjoint(const void *g, const double *x, double *out)
{
    ga_mat4 gi, m = *(const ga_mat4 *)g;
    if (aff_inverse(&m, &gi) != GA_OK) {
        for (int i = 0; i < 12; ++i) out[i] = NAN;
        return;
    }
    aff_vee(ga_mat4_mul(ga_mat4_mul(m, aff_hat(x)), gi), out);
}
/* GA_ERR_NOTFINITE for NaN/Inf; GA_ERR_DOMAIN if the last row is not 0 0 0 1 to
 * 1e-12 or det < 0 (a reflection: no real log); GA_ERR_SINGULAR if det = 0. */
static int aff_from_mat4(ga_mat4 m, void *out)
{
    for (int i = 0; i < 16; ++i)
        if (!isfinite(m.m[i]))
            return GA_ERR_NOTFINITE;
    if (fabs(m.m[12]) > 1e-12 || fabs(m.m[13]) > 1e-12 || fabs(m.m[14]) > 1e-12 ||
        fabs(m.m[15] - 1.0) > 1e-12)
        return GA_ERR_DOMAIN;
    double det = m.m[0] * (m.m[5] * m.m[10] - m.m[6] * m.m[9]) -
                 m.m[1] * (m.m[4] * m.m[10] - m.m[6] * m.m[8]) + m.m[2] * (m.m[4] * m.m[9] - m.m[5] * m.m[8]);
    if (!(det > 0.0))
        return det == 0.0 ? GA_ERR_SINGULAR : GA_ERR_DOMAIN;
    m.m[12] = m.m[13] = m.m[14] = 0.0;
    m.m[15] = 1.0;
    *(ga_mat4 *)out = m;
    return GA_OK;
}

static ga_mat4 m4_lin(double s, ga_mat4 a, double t, ga_mat4 b) /* s a + t b */
{
    for (int i = 0; i < 16; ++i) a.m[i] = s * a.m[i] + t * b.m[i];
    return a;
}

/* J_r(X) Y = sum_k (-ad_X)^k Y/(k+1)! for any 4x4 X: the series at X/2^s
 * (||X/2^s||_1 <= 1/2, 20 terms, truncation below 1e-20), then s doublings by
 *   J_r(2X)(2Y) = Ad_{exp(-X)} J_r(X) Y + J_r(X) Y,
 * which is the body velocity of exp(X)exp(X) (product rule). exp(+-X/2^s) are
 * summed from their Taylor series (18 terms) and squared along. */
static void aff_dexp(const double *x, const double *y, double *out)
{
    ga_mat4 X = aff_hat(x), Y = aff_hat(y);
    double nx = ga_mat4_norm1(X);
    int s = 0;
    while (nx > 0.5 && s < 1100) {
        nx *= 0.5;
        ++s;
    }
    double sc = ldexp(1.0, -s);
    X = m4_lin(sc, X, 0.0, X);
    Y = m4_lin(sc, Y, 0.0, Y);
    /* b = sum (-1)^k ad^k Y/(k+1)!, term_k = ad^k Y */
    ga_mat4 term = Y, b = Y;
    double f = 1.0;
    for (int k = 1; k <= 20; ++k) {
        term = m4_lin(1.0, ga_mat4_mul(X, term), -1.0, ga_mat4_mul(term, X));
        f *= (double)(k + 1);
        b = m4_lin(1.0, b, (k % 2 ? -1.0 : 1.0) / f, term);
    }
    ga_mat4 E = ga_mat4_identity(), F = E, pe = E, pf = E;
    double g = 1.0;
    for (int k = 1; k <= 18; ++k) {
        g *= (double)k;
        pe = ga_mat4_mul(pe, X);
        pf = ga_mat4_mul(pf, m4_lin(-1.0, X, 0.0, X));
        E = m4_lin(1.0, E, 1.0 / g, pe);
        F = m4_lin(1.0, F, 1.0 / g, pf);
    }
    for (int i = 0; i < s; ++i) {
        b = m4_lin(1.0, ga_mat4_mul(ga_mat4_mul(F, b), E), 1.0, b);
        E = ga_mat4_mul(E, E);
        F = ga_mat4_mul(F, F);
    }
    aff_vee(b, out);
}

const ga_group ga_group_affine = {
    .name = "affine",
    .elem_size = sizeof(ga_mat4),
    .dim = 12,
    .rigid = 0,
    .identity = gig_m4_identity,
    .compose = gig_m4_compose,
    .inverse = aff_inverse,
    .exp = aff_exp,
    .log = aff_log,
    .adjoint = aff_adjoint,
    .dexp = aff_dexp,
    .from_mat4 = aff_from_mat4,
    .to_mat4 = gig_m4_to_mat4,
    .hat = aff_hat,
    .vee = aff_vee_checked,
    .half_turn = NULL,
    .branch = NULL,
    .to_qt = NULL,
    .from_qt = NULL,
};
