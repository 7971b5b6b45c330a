/* ga/mv_split.c: the split of any bivector of G(4,1) into commuting 2-blades
 * (ga_mv_split) and of a rotor into commuting simple factors (ga_mv_factor):
 * the ideals of Spin(4) for two rotations, the l forms, and the rigid frame
 * of a null part, keeping the split with the smallest residual. Notation:
 * ga/internal/bivector_fns.h; docs/versors.md derives every formula.
 */
#include <garotor/versor.h>

#include "internal/bivector_fns.h"
#include "internal/bivector_frames.h"
#include <float.h>
#include <math.h>

/* The coefficient-wise dot product (a Euclidean metric on the 32 numbers). */
static double cdot(ga_mv a, ga_mv b)
{
    double r = 0.0;
    for (int i = 0; i < 32; i++) r += a.c[i] * b.c[i];
    return r;
}

/* How far x, y are from commuting 2-blades, for x + y = b to 2^-40 (b of
   size 1); a split that misses b by more is no split (INFINITY). */
static double split_residual(ga_mv b, ga_mv x, ga_mv y)
{
    if (!ga_mv_isfinite(x) || !ga_mv_isfinite(y))
        return INFINITY;
    double sum = ga_mv_maxabs(ga_mv_sub(gab_lin(1.0, x, 1.0, y), b));
    if (!(sum <= 0x1p-40))
        return INFINITY;
    return fmax(sum, fmax(ga_mv_maxabs(ga_mv_sub(ga_mv_gp(x, y), ga_mv_gp(y, x))),
                          fmax(ga_mv_maxabs(ga_mv_grade(ga_mv_gp(x, x), 4)),
                               ga_mv_maxabs(ga_mv_grade(ga_mv_gp(y, y), 4)))));
}

/* b = tE + N split in the rigid frame of its null part (as log_null_part in
   ga/mv_log.c):
   there b is a generator Omega + T n, and with a the axis of Omega,
   B2 = (T.a) a n / |a|^2 (the translation along the axis, null) and
   B1 = Omega + T_perp n (the rotation about the axis), which commute and are
   2-blades to rounding of |b| whatever t is; the l forms find E from
   t^2 = -<b^2>_0, known only to u |b|^2. 0 where b has no null vector. */
static int split_null_part(ga_mv b, int cand, ga_mv *x, ga_mv *y)
{
    double M[5][5];
    ga_mv V;
    gabf_contraction_matrix(b, M);
    if (!gabf_rigid_frame(M, cand, &V))
        return 0;
    ga_mv br = ga_mv_grade(gabf_sandwich(V, b), 2);
    static const int in4[3] = {GA_BLADE_E14, GA_BLADE_E24, GA_BLADE_E34},
                     in5[3] = {GA_BLADE_E15, GA_BLADE_E25, GA_BLADE_E35};
    double a[3] = {br.c[GA_BLADE_E23], -br.c[GA_BLADE_E13], br.c[GA_BLADE_E12]}, t[3];
    double aa = a[0] * a[0] + a[1] * a[1] + a[2] * a[2], ta = 0.0, pa = 0.0;
    for (int i = 0; i < 3; i++) t[i] = 0.5 * br.c[in4[i]] + 0.5 * br.c[in5[i]], ta += t[i] * a[i];
    ga_mv B1 = ga_mv_zero(), B2 = ga_mv_zero();
    B1.c[GA_BLADE_E12] = br.c[GA_BLADE_E12], B1.c[GA_BLADE_E13] = br.c[GA_BLADE_E13];
    B1.c[GA_BLADE_E23] = br.c[GA_BLADE_E23];
    double tp[3];
    for (int i = 0; i < 3; i++) tp[i] = aa > 0.0 ? t[i] - ta / aa * a[i] : 0.0, pa += tp[i] * a[i];
    for (int i = 0; i < 3; i++) {
        double perp = aa > 0.0 ? tp[i] - pa / aa * a[i] : 0.0; /* once more: T_perp.a is rounding */
        B1.c[in4[i]] = B1.c[in5[i]] = perp;
        B2.c[in4[i]] = B2.c[in5[i]] = t[i] - perp;
    }
    ga_mv Vr = ga_mv_reverse(V);
    *x = ga_mv_grade(gabf_sandwich(Vr, B1), 2);
    *y = ga_mv_grade(gabf_sandwich(Vr, B2), 2);
    return 1;
}

/* two rotations: the split in the ideals of P+- (the comment in split_unit),
   and its residual */
static double split_ideals(ga_mv b, gab_square sq, ga_mv *x, ga_mv *y)
{
    ga_mv J = ga_mv_scale(sq.q, 1.0 / sqrt(sq.qq)), U[2];
    double t[2];
    for (int i = 0; i < 2; i++) {
        ga_mv P = ga_mv_scale(J, i == 0 ? 0.5 : -0.5), B3[3], X = ga_mv_zero();
        P.c[0] += 0.5;
        /* b P in the coordinates of an orthonormal basis of the ideal
           (<B3k B3k>_0 = -1/2): exactly in the ideal to rounding of its
           own size, which a product with P is not for a small part
           (the rounding of b, of |b|, leaves the 4-space of J) */
        gabf_ideal_basis(J, P, B3);
        ga_mv bp = ga_mv_gp(b, P);
        double t2 = 0.0;
        for (int k = 0; k < 3; k++) {
            double v = -2.0 * ga_mv_sp(bp, B3[k]);
            X = gab_lin(1.0, X, v, B3[k]);
            t2 += v * v;
        }
        t[i] = sqrt(t2);
        U[i] = t[i] > 0.0 ? ga_mv_scale(X, 1.0 / t[i]) : B3[0]; /* U^2 = -P */
    }
    *x = ga_mv_scale(gab_lin(1.0, U[0], 1.0, U[1]), 0.5 * (t[0] + t[1]));
    *y = ga_mv_scale(gab_lin(1.0, U[0], -1.0, U[1]), 0.5 * (t[0] - t[1]));
    /* b outside the 4-space of J (rounding of b, or a J of rounding)
       is dropped by the projection: kept only if the residual says
       so, as the l forms of split_unit */
    return split_residual(b, *x, *y);
}

/* Split b (max |b| in [1/2, 1)) into commuting 2-blades b1 + b2. */
static void split_unit(ga_mv b, ga_mv *b1, ga_mv *b2)
{
    gab_square sq = gab_square_of(b);
    double tol = 64.0 * DBL_EPSILON, qn = ga_mv_maxabs(sq.q), qc = cdot(sq.q, sq.q);
    if (qn <= tol) { /* b is a 2-blade to rounding */
        *b1 = b;
        *b2 = ga_mv_zero();
        return;
    }
    double ideal_res = INFINITY;
    ga_mv ideal_x = b, ideal_y = ga_mv_zero();
    if (sq.qq > 0x1p-26 * qc && sqrt(sq.qq) > 0x1p20 * DBL_EPSILON) {
        /* two rotations: q spans a Euclidean 4-space, J = q / sqrt(q.q),
           J^2 = 1. In the ideals of P+- = (1 +- J)/2, b = tp Up + tm Um with
           Up^2 = -P+, Um^2 = -P- (each ideal is a quaternion algebra), and
           E1 = Up + Um, E2 = Up - Um are commuting unit 2-blades (E^2 = -1,
           E1 E2 = -J) with b = (tp + tm)/2 E1 + (tp - tm)/2 E2: exact for
           any unit Um, so it holds for isoclinic b (tm = 0) and near it,
           where the roots l1, l2 are too close to divide by. */
        ga_mv x, y;
        double res = split_ideals(b, sq, &x, &y);
        if (res <= 64.0 * DBL_EPSILON) {
            *b1 = x;
            *b2 = y;
            return;
        }
        ideal_res = res, ideal_x = x, ideal_y = y;
    }
    /* separated parts (elliptic x hyperbolic, or a null part):
       b1 = (l1 b - bq/2)/(l1 - l2), b2 = (bq/2 - l2 b)/(l1 - l2) with l1, l2
       the roots of l^2 - s l + q.q/4. Beside a null part q.q = 4 l1 l2 is a
       sum of products of q's coefficients that cancel, so l2 = 0, l1 = s is
       tried too. Of these splits and (b, 0) (b a 2-blade to |q|/2), the one
       with the smallest residual (how far from commuting 2-blades summing
       to b) is kept. A rotation t beside a null part N is resolved only to
       u |b|^3 / t^3 of N (s = -t^2 is known to u |b|^2, and b1 is b minus
       b2 ~ N): below t ~ 1e-4 |b| the split is that poor (versor.h). */
    double sv[2] = {sq.s, sq.s};
    double best = 0.5 * qn;
    *b1 = b;
    *b2 = ga_mv_zero();
    if (ideal_res < best) {
        best = ideal_res;
        *b1 = ideal_x;
        *b2 = ideal_y;
    }
    for (int v = 0; v < 2; v++) {
        double l1, l2;
        gab_roots(sv[v % 2], sq.qq, &l1, &l2);
        if (v % 2)
            l1 = sv[v % 2], l2 = 0.0;
        double dl = l1 - l2;
        if (!(fabs(dl) > 0.0))
            continue;
        ga_mv x = gab_lin(l1 / dl, b, -0.5 / dl, sq.bq), y = gab_lin(0.5 / dl, sq.bq, -l2 / dl, b);
        double res = split_residual(b, x, y);
        if (res < best) {
            best = res;
            *b1 = x;
            *b2 = y;
        }
    }
    for (int cand = 0; cand < 2 && best > 8.0 * DBL_EPSILON; cand++) {
        ga_mv x, y;
        double res = split_null_part(b, cand, &x, &y) ? split_residual(b, x, y) : INFINITY;
        if (res < best) {
            best = res;
            *b1 = x;
            *b2 = y;
        }
    }
}

ga_status ga_mv_split(ga_mv B, ga_mv *B1, ga_mv *B2)
{
    if (!B1 || !B2)
        return GA_ERR_ARG;
    ga_mv b = ga_mv_grade(B, 2);
    if (!ga_mv_isfinite(b))
        return GA_ERR_NOTFINITE;
    double m = ga_mv_maxabs(b);
    if (m == 0.0) {
        *B1 = *B2 = ga_mv_zero();
        return GA_OK;
    }
    int e;
    frexp(m, &e);
    for (int i = 0; i < 32; i++) b.c[i] = ldexp(b.c[i], -e);
    ga_mv x, y;
    split_unit(b, &x, &y);
    for (int i = 0; i < 32; i++) x.c[i] = ldexp(x.c[i], e), y.c[i] = ldexp(y.c[i], e);
    if (!ga_mv_isfinite(x) || !ga_mv_isfinite(y))
        return GA_ERR_DOMAIN;
    *B1 = x;
    *B2 = y;
    return GA_OK;
}

ga_status ga_mv_factor(ga_mv R, ga_mv *R1, ga_mv *R2)
{
    if (!R1 || !R2)
        return GA_ERR_ARG;
    ga_mv L, B1, B2;
    int st = ga_mv_log(R, &L);
    if (st == GA_OK)
        st = ga_mv_split(L, &B1, &B2);
    if (st != GA_OK)
        return st;
    *R1 = ga_mv_exp(B1);
    *R2 = ga_mv_exp(B2);
    return GA_OK;
}
