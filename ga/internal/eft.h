/* ga/internal/eft.h (internal, not installed): error-free transformations,
 * a sum's exact rounding error and a dot product carried to about twice the
 * working precision. Prefix ga__eft. They rely on each a + b and a * b
 * being rounded on its own: the build passes -ffp-contract=off.
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

/* a sum of products s + c carried to about twice the working precision
 * (Ogita, Rump & Oishi 2005, Dot2): each product's rounding error by fma,
 * each addition's by two_sum, gathered in c */
typedef struct {
    double s, c;
} ga__eft_dot2;

static inline void ga__eft_dot2_add(ga__eft_dot2 *a, double x, double y)
{
    double p = x * y, s, e;
    ga__eft_two_sum(a->s, p, &s, &e);
    a->c += e + fma(x, y, -p);
    a->s = s;
}

#endif
