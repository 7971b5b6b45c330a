/* ga/internal/eft.h (internal, not installed): error-free transformations,
 * a sum's and a product's exact rounding errors, a dot product carried to
 * about twice the working precision, and double-double arithmetic. Prefix
 * ga__eft. They rely on each a + b and a * b being rounded on its own: the
 * build passes -ffp-contract=off.
 */
#ifndef GA_INTERNAL_EFT_H
#define GA_INTERNAL_EFT_H

#include <math.h>

/* s + e = a + b exactly (Knuth's two-sum) */
static inline void ga__eft_two_sum(double a, double b, double *s, double *e)
{
    double t = a + b, bb = t - a;
    *s = t;
    *e = (a - (t - bb)) + (b - bb);
}

/* p + e = a b exactly (the two-product, by fma) */
static inline void ga__eft_two_prod(double a, double b, double *p, double *e)
{
    double t = a * b;
    *p = t;
    *e = fma(a, b, -t);
}

/* a sum of products s + c carried to about twice the working precision
 * (Ogita, Rump & Oishi 2005, Dot2): each product's rounding error by fma,
 * each addition's by two_sum, gathered in c */
typedef struct {
    double s, c;
} ga__eft_dot2;

static inline void ga__eft_dot2_add(ga__eft_dot2 *a, double x, double y)
{
    double p = x * y, s, e; /* the two-product of x y, as ga__eft_two_prod */
    ga__eft_two_sum(a->s, p, &s, &e);
    a->c += e + fma(x, y, -p);
    a->s = s;
}

/* Double-double arithmetic (Dekker, Knuth): a value hi + lo with
 * |lo| <= u |hi|, for differences of squares, which cancel. */
typedef struct {
    double hi, lo;
} ga__eft_dd;

/* s + e with |s| >= |e| as a double-double (Dekker's fast two-sum) */
static inline ga__eft_dd ga__eft_dd_norm(double s, double e)
{
    double h = s + e;
    ga__eft_dd r = {h, e - (h - s)};
    return r;
}
/* a + b and a b, exactly */
static inline ga__eft_dd ga__eft_dd_sum(double a, double b)
{
    double s, e;
    ga__eft_two_sum(a, b, &s, &e);
    return ga__eft_dd_norm(s, e);
}
static inline ga__eft_dd ga__eft_dd_prod(double a, double b)
{
    double p, e;
    ga__eft_two_prod(a, b, &p, &e);
    return ga__eft_dd_norm(p, e);
}
static inline ga__eft_dd ga__eft_dd_add(ga__eft_dd x, ga__eft_dd y)
{
    ga__eft_dd s = ga__eft_dd_sum(x.hi, y.hi);
    return ga__eft_dd_norm(s.hi, s.lo + (x.lo + y.lo));
}
static inline ga__eft_dd ga__eft_dd_neg(ga__eft_dd x)
{
    ga__eft_dd r = {-x.hi, -x.lo};
    return r;
}
static inline ga__eft_dd ga__eft_dd_mul(ga__eft_dd x, ga__eft_dd y)
{
    ga__eft_dd p = ga__eft_dd_prod(x.hi, y.hi);
    return ga__eft_dd_norm(p.hi, p.lo + (x.hi * y.lo + x.lo * y.hi));
}
/* x 2^e (exact barring overflow and underflow) */
static inline ga__eft_dd ga__eft_dd_ldexp(ga__eft_dd x, int e)
{
    ga__eft_dd r = {ldexp(x.hi, e), ldexp(x.lo, e)};
    return r;
}

#endif
