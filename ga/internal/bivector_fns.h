/* ga/internal/bivector_fns.h (internal, not installed): what the closed forms
 * of exp (ga/mv_exp.c), log (ga/mv_log.c) and split (ga/mv_split.c) of
 * G(4,1) share: the functions of t, the square of a bivector and its roots.
 * Prefix gab_. docs/versors.md derives every formula.
 *
 * Notation. B = B1 + B2 with commuting 2-blades, B1^2 = l1, B2^2 = l2
 * (Dorst-Valkenburg 2011 §3). With s = <B^2>_0 and q = <B^2>_4 = 2 B1 B2:
 * l1 + l2 = s and l1 l2 = q.q/4 (q.q = <q q>_0, a scalar since q is a
 * 4-vector of a 5-dimensional space). The entire functions of one real t
 *   C(t) = cosh(sqrt t) = sum t^k/(2k)!         (cos sqrt(-t) for t < 0)
 *   S(t) = sinh(sqrt t)/sqrt t = sum t^k/(2k+1)!
 *   K(t) = (C - 1)/t,  T(t) = (S - 1)/t,  E(t) = (C - S)/t
 * give exp(Bi) = C(li) + S(li) Bi, whatever the sign of li (l = 0: 1 + Bi).
 */
#ifndef GA_INTERNAL_BIVECTOR_FNS_H
#define GA_INTERNAL_BIVECTOR_FNS_H

#include <garotor/mv.h>
#include <math.h>

#include "series.h"

/* ---- the functions of t ------------------------------------------------------ */

typedef struct {
    double c, s, k, t, e; /* C, S, K, T, E at one t */
} gab_fns;

static inline gab_fns gab_fns_at(double t)
{
    gab_fns f;
    if (fabs(t) <= 1.0) {
        /* C, S, K, T are f_0 .. f_3 of series.h at -t: sum t^j/(d + 2j)!;
           18 terms leave less than 1/36! of the first */
        f.c = ga__series(GA__SERIES_F0, 18, -t);
        f.s = ga__series(GA__SERIES_F1, 18, -t);
        f.k = ga__series(GA__SERIES_F2, 18, -t);
        f.t = ga__series(GA__SERIES_F3, 18, -t);
        f.e = f.k - f.t; /* (C - 1 - (S - 1))/t */
        return f;
    }
    double r = sqrt(fabs(t));
    f.c = t > 0 ? cosh(r) : cos(r);
    f.s = (t > 0 ? sinh(r) : sin(r)) / r;
    f.k = (f.c - 1.0) / t;
    f.t = (f.s - 1.0) / t;
    f.e = (f.c - f.s) / t;
    return f;
}

/* ---- the square of a bivector ------------------------------------------------ */

/* a x + b y, componentwise */
static inline ga_mv gab_lin(double a, ga_mv x, double b, ga_mv y)
{
    ga_mv r;
    for (int i = 0; i < 32; i++) r.c[i] = a * x.c[i] + b * y.c[i];
    return r;
}

/* s = <B^2>_0, q = <B^2>_4, qq = <q q>_0, Bq = <B q>_2 */
typedef struct {
    ga_mv b, q, bq;
    double s, qq;
} gab_square;

static inline gab_square gab_square_of(ga_mv B)
{
    gab_square r;
    r.b = ga_mv_grade(B, 2);
    ga_mv b2 = ga_mv_gp(r.b, r.b);
    r.s = b2.c[0];
    r.q = ga_mv_grade(b2, 4);
    r.qq = ga_mv_sp(r.q, r.q);
    r.bq = ga_mv_grade(ga_mv_gp(r.b, r.q), 2);
    return r;
}

/* l1, l2: the roots of l^2 - s l + qq/4, |l1| >= |l2|, without cancellation;
   d = s^2 - qq clamped at 0 (it is >= 0 for every bivector of G(4,1):
   docs/versors.md). */
static inline void gab_roots(double s, double qq, double *l1, double *l2)
{
    double d = fmax(s * s - qq, 0.0);
    double big = 0.5 * (s + copysign(sqrt(d), s));
    *l1 = big;
    *l2 = big != 0.0 ? 0.25 * qq / big : 0.0;
}

#endif
