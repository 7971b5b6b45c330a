/* interp/jet.c: the Lie bracket and the derivatives of exp along a curve,
 * both through 4x4 matrices (group.h hat and vee): the jet
 * exp(X + e X' + e^2 X''/2) by scaling, Taylor series and squaring
 * (Higham 2005). They serve the accelerations (eval.c, scheme_lihao.c) and
 * the nonlinear term of the C2 system (scheme_c2.c).
 */
#include <math.h>
#include <string.h>

#include <garotor/mat4.h>
#include <garotor/path.h>

#include "internal/path.h"

/* x = vee(a) for a matrix a in the algebra up to rounding. vee is linear, but
 * the rigid groups' vee refuses a 3x3 block whose symmetric part exceeds 1e-9
 * of its largest entry, and a result that is small against the terms it was
 * formed from (a commutator of near-parallel twists, a body acceleration
 * near 0) carries a symmetric part of rounding about eps times those terms.
 * So vee is taken of a + hat(c), c = (S, ..., S) with S >= the terms'
 * scale, and c is subtracted again: exact up to a rounding of S. The last
 * row, zero in the algebra of every group here (homogeneous matrices), is
 * set to zero. */
static int vee_scaled(const ga_group *g, ga_mat4 a, double scale, double *x)
{
    double c[GIP_MAXD];
    size_t d = g->dim;
    for (size_t k = 0; k < d; ++k) c[k] = scale;
    ga_mat4 h = g->hat(c);
    for (int k = 0; k < 12; ++k) a.m[k] += h.m[k];
    for (int k = 12; k < 16; ++k) a.m[k] = 0.0;
    int st = g->vee(a, x);
    if (st != GA_OK)
        return GA_ERR_DOMAIN;
    for (size_t k = 0; k < d; ++k) x[k] -= scale;
    return GA_OK;
}

static double mat_maxabs(ga_mat4 a)
{
    double m = 0.0;
    for (int k = 0; k < 16; ++k) m = fmax(m, fabs(a.m[k]));
    return m;
}

/* out = [x, y] = vee(x^ y^ - y^ x^), the Lie bracket in the convention of
 * hat, in closed form on the rigid groups (body velocities: d/du Ad_{F^-1} w = Ad_{F^-1} w' + [Ad_{F^-1} w,
 * p'X] for F = exp(p X))). */
int gip_bracket(const ga_group *g, const double *x, const double *y, double *out)
{
    if (g->rigid) { /* twists: (w1 x w2, w1 x v2 - w2 x v1) */
        double o[6];
        o[0] = x[1] * y[2] - x[2] * y[1];
        o[1] = x[2] * y[0] - x[0] * y[2];
        o[2] = x[0] * y[1] - x[1] * y[0];
        o[3] = (x[1] * y[5] - x[2] * y[4]) - (y[1] * x[5] - y[2] * x[4]);
        o[4] = (x[2] * y[3] - x[0] * y[5]) - (y[2] * x[3] - y[0] * x[5]);
        o[5] = (x[0] * y[4] - x[1] * y[3]) - (y[0] * x[4] - y[1] * x[3]);
        memcpy(out, o, sizeof o);
        return GA_OK;
    }
    ga_mat4 a = g->hat(x), b = g->hat(y), ab = ga_mat4_mul(a, b), ba = ga_mat4_mul(b, a), c;
    for (int k = 0; k < 16; ++k) c.m[k] = ab.m[k] - ba.m[k];
    double s = 1.0 + mat_maxabs(ab) + mat_maxabs(ba);
    return vee_scaled(g, c, s, out);
}

/* The 4x4 jets a0 + e a1 + e^2 a2 + e^3 a3 (e^{m+1} = 0, m <= 3): exp of a
 * jet by scaling, Taylor series and squaring (Higham 2005, as the affine dexp
 * of group_affine.c does to first order). exp(X + e X' + e^2 X''/2 +
 * e^3 X'''/6) = G + e G' + e^2 G''/2 + e^3 G'''/6 along a curve X(t) at t. */
typedef struct {
    ga_mat4 c[4];
} jet;

static jet jet_mul(int m, const jet *a, const jet *b)
{
    jet r;
    r.c[0] = ga_mat4_mul(a->c[0], b->c[0]);
    ga_mat4 p = ga_mat4_mul(a->c[0], b->c[1]), q = ga_mat4_mul(a->c[1], b->c[0]);
    for (int k = 0; k < 16; ++k) r.c[1].m[k] = p.m[k] + q.m[k];
    ga_mat4 u = ga_mat4_mul(a->c[0], b->c[2]), v = ga_mat4_mul(a->c[1], b->c[1]),
            w = ga_mat4_mul(a->c[2], b->c[0]);
    for (int k = 0; k < 16; ++k) r.c[2].m[k] = u.m[k] + v.m[k] + w.m[k];
    if (m >= 3) {
        ga_mat4 x0 = ga_mat4_mul(a->c[0], b->c[3]), x1 = ga_mat4_mul(a->c[1], b->c[2]),
                x2 = ga_mat4_mul(a->c[2], b->c[1]), x3 = ga_mat4_mul(a->c[3], b->c[0]);
        for (int k = 0; k < 16; ++k) r.c[3].m[k] = x0.m[k] + x1.m[k] + x2.m[k] + x3.m[k];
    }
    return r;
}

static jet jet_exp(int order, jet z)
{
    /* scale by 2^-s so that ||z_0||_1 <= 1/2: nrm = f 2^e, f in [1/2, 1),
     * s = e + 1. An infinite or NaN norm (finite input that overflowed) is not
     * scaled (its log2 has no int): the result is then not finite, which
     * the caller reports */
    double nrm = ga_mat4_norm1(z.c[0]);
    int s = 0;
    if (nrm > 0.5 && isfinite(nrm)) {
        frexp(nrm, &s);
        s += 1;
    }
    double sc = ldexp(1.0, -s);
    for (int i = 0; i <= order; ++i)
        for (int k = 0; k < 16; ++k) z.c[i].m[k] *= sc;
    /* Horner: I + z (I + z/2 (I + z/3 (...))), 18 terms: 0.5^19/19! < 1e-22 */
    jet r;
    memset(&r, 0, sizeof r);
    r.c[0] = ga_mat4_identity();
    for (int m = 18; m >= 1; --m) {
        jet t = jet_mul(order, &z, &r);
        for (int i = 0; i <= order; ++i)
            for (int k = 0; k < 16; ++k) t.c[i].m[k] /= m;
        for (int k = 0; k < 16; ++k) t.c[0].m[k] += (k % 5 == 0);
        r = t;
    }
    for (int i = 0; i < s; ++i) r = jet_mul(order, &r, &r);
    return r;
}

/* The body velocity v (may be NULL) and acceleration a of G = exp(X(t)) with
 * X = x, X' = xd, X'' = xdd (per unit t): v = J_r(X) X' (group.h dexp); the
 * jet exp(X + e X' + e^2 X''/2) gives G' and G''/2, and
 * a = d/dt(G^-1 G') = G^-1 G'' - (G^-1 G')^2. The affine group's; the rigid
 * groups have the closed form of twist_deriv.c (gip_exp_curve_jet). */
int gip_exp_curve_deriv(const ga_group *g, const double *x, const double *xd, const double *xdd, double *v,
                        double *a)
{
    size_t d = g->dim;
    double half[GIP_MAXD], gi[GIP_MAXE], ge[GIP_MAXE];
    int st;
    for (size_t k = 0; k < d; ++k) half[k] = 0.5 * xdd[k];
    jet z;
    memset(&z, 0, sizeof z);
    z.c[0] = g->hat(x);
    z.c[1] = g->hat(xd);
    z.c[2] = g->hat(half);
    jet e = jet_exp(2, z);
    if ((st = g->exp(x, ge)) || (st = g->inverse(ge, gi)))
        return st;
    ga_mat4 G1 = g->to_mat4(gi), V = ga_mat4_mul(G1, e.c[1]), P = ga_mat4_mul(G1, e.c[2]),
            V2 = ga_mat4_mul(V, V), A;
    for (int k = 0; k < 16; ++k) A.m[k] = 2.0 * P.m[k] - V2.m[k];
    if (v)
        g->dexp(x, xd, v); /* the velocity as ga_path_velocity has it */
    return vee_scaled(g, A, 1.0 + 2.0 * mat_maxabs(P) + mat_maxabs(V2), a);
}

/* The body jerk j of G = exp(X(t)) by the jet of order 3 (X''' = x[3]):
 * with P_k = G^-1 G^(k), V = P_1, a = P_2 - V^2 and d/dt G^-1 = -V G^-1,
 * j = P_3 - V P_2 - a V - V a. */
static int exp_curve_jerk(const ga_group *g, const double *const *x, double *j)
{
    size_t d = g->dim;
    double h2[GIP_MAXD], h3[GIP_MAXD], gi[GIP_MAXE], ge[GIP_MAXE];
    int st;
    for (size_t k = 0; k < d; ++k) {
        h2[k] = 0.5 * x[2][k];
        h3[k] = x[3][k] / 6.0;
    }
    jet z = {{g->hat(x[0]), g->hat(x[1]), g->hat(h2), g->hat(h3)}};
    jet e = jet_exp(3, z);
    if ((st = g->exp(x[0], ge)) || (st = g->inverse(ge, gi)))
        return st;
    ga_mat4 G1 = g->to_mat4(gi), V = ga_mat4_mul(G1, e.c[1]), P2 = ga_mat4_mul(G1, e.c[2]),
            P3 = ga_mat4_mul(G1, e.c[3]), V2 = ga_mat4_mul(V, V), A, J;
    for (int k = 0; k < 16; ++k) {
        P2.m[k] *= 2.0;
        P3.m[k] *= 6.0;
        A.m[k] = P2.m[k] - V2.m[k];
    }
    ga_mat4 VP = ga_mat4_mul(V, P2), AV = ga_mat4_mul(A, V), VA = ga_mat4_mul(V, A);
    for (int k = 0; k < 16; ++k) J.m[k] = P3.m[k] - VP.m[k] - AV.m[k] - VA.m[k];
    double sc = 1.0 + mat_maxabs(P3) + mat_maxabs(VP) + mat_maxabs(AV) + mat_maxabs(VA);
    return vee_scaled(g, J, sc, j);
}

int gip_exp_curve_jet(const ga_group *g, const double *const *x, int m, double *v, double *a, double *j)
{
    int st;
    if (v)
        g->dexp(x[0], x[1], v); /* the velocity as ga_path_velocity has it */
    if (m < 2)
        return GA_OK;
    if (g->rigid) {
        gip_twist_exp_derivs(x, m, NULL, a, j);
        return GA_OK;
    }
    if (a && (st = gip_exp_curve_deriv(g, x[0], x[1], x[2], NULL, a)))
        return st;
    return m >= 3 && j ? exp_curve_jerk(g, x, j) : GA_OK;
}
