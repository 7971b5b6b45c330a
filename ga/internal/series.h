/* ga/internal/series.h (internal, not installed): the sinc family of series,
 * one evaluator for every module.
 *
 * The closed forms of exp, log and their Jacobians (sin th / th,
 * (1 - cos th)/th^2, ...) cancel as the angle th goes to 0; below a threshold
 * each module sums the Taylor series instead. Every such series is a row of
 * GA__SERIES (series_coef.inc, written by gen/series.py): the coefficients of
 * x^k, x = th^2, each the double nearest its exact value. The callers choose
 * how many terms their range needs (the first omitted term below the unit
 * roundoff of the sum) and the evaluation order:
 *   ga__series        Horner's rule from the highest term: the fewest
 *                     roundings, for most callers;
 *   ga__series_estrin9  nine terms by Estrin's scheme, a dependency chain of
 *                     four multiply-adds instead of eight, for the latency-
 *                     bound hot paths (the rotor exp and the screw sampler).
 * Prefix ga__series; also the constants those hot paths reduce angles with.
 */
#ifndef GA_INTERNAL_SERIES_H
#define GA_INTERNAL_SERIES_H

#include "series_coef.inc"

#define GA_PI 3.14159265358979323846
/* pi/2 = GA_PIO2_HI + GA_PIO2_LO to about 2^-107 */
#define GA_PIO2_HI 1.5707963267948966    /* 0x1.921fb54442d18p+0 */
#define GA_PIO2_LO 6.123233995736766e-17 /* 0x1.1a62633145c07p-54 */

/* sum_{k < n} GA__SERIES[f][k] x^k, 1 <= n <= GA__SERIES_TERMS, Horner. */
static inline double ga__series(int f, int n, double x)
{
    const double *c = GA__SERIES[f];
    double s = c[n - 1];
    for (int k = n - 2; k >= 0; k--) s = s * x + c[k];
    return s;
}

/* The polynomial c[0] + c[1] y + ... + c[8] y^8 by Estrin's scheme, given
 * y2 = y^2, y4 = y^4, y8 = y^8 (shared by the several series a caller
 * evaluates at the same y). */
static inline double ga__estrin9(const double c[9], double y, double y2, double y4, double y8)
{
    return ((c[0] + c[1] * y) + y2 * (c[2] + c[3] * y)) + y4 * ((c[4] + c[5] * y) + y2 * (c[6] + c[7] * y)) +
           y8 * c[8];
}

/* sum_{k < 9} GA__SERIES[f][k] y^k by Estrin's scheme (ga__estrin9). */
static inline double ga__series_estrin9(int f, double y, double y2, double y4, double y8)
{
    return ga__estrin9(GA__SERIES[f], y, y2, y4, y8);
}

#endif
