/* ga/internal/rotor_series.h (internal, not installed): the series of the
 * rotor exp, shared by ga_rotor_exp (rotor.c) and the screw sampler of the
 * cga group (interp/group_cga.c), which evaluate the same functions of the
 * angle.
 */
#ifndef GA_ROTOR_SERIES_H
#define GA_ROTOR_SERIES_H

#define GA_PI 3.14159265358979323846

/* A polynomial of 9 coefficients in y by Estrin's scheme (y2 = y^2, y4 = y^4,
 * y8 = y^8): a dependency chain of four multiply-adds instead of Horner's
 * eight, for the same number of operations; ga_rotor_exp is bound by that
 * chain, not by its arithmetic. */
static inline double estrin9(const double c[9], double y, double y2, double y4, double y8)
{
    return ((c[0] + c[1] * y) + y2 * (c[2] + c[3] * y)) + y4 * ((c[4] + c[5] * y) + y2 * (c[6] + c[7] * y)) +
           y8 * c[8];
}

/* Taylor coefficients, in x^2, of cos x, sin(x)/x and
 * k(x) = (cos x - sinc x) / x^2 = sum_{j>=1} (-1)^j 2j x^(2j-2) / (2j+1)!,
 * each to the term in x^16. For |x| <= pi/4 the first omitted term is below
 * 3e-18 of the sum (x^18/18! against cos x >= 0.7, x^18/19! against
 * sinc x >= 0.9, 20 x^18/21! against |k| >= 0.3). */
static const double cos_taylor[9] = {1.0,
                                     -1.0 / 2,
                                     1.0 / 24,
                                     -1.0 / 720,
                                     1.0 / 40320,
                                     -1.0 / 3628800,
                                     1.0 / 479001600,
                                     -1.0 / 87178291200.0,
                                     1.0 / 20922789888000.0};
static const double sinc_taylor[9] = {1.0,
                                      -1.0 / 6,
                                      1.0 / 120,
                                      -1.0 / 5040,
                                      1.0 / 362880,
                                      -1.0 / 39916800,
                                      1.0 / 6227020800.0,
                                      -1.0 / 1307674368000.0,
                                      1.0 / 355687428096000.0};
static const double k_taylor[9] = {-1.0 / 3,
                                   1.0 / 30,
                                   -1.0 / 840,
                                   1.0 / 45360,
                                   -1.0 / 3991680,
                                   1.0 / 518918400,
                                   -1.0 / 93405312000.0,
                                   1.0 / 22230464256000.0,
                                   -1.0 / 6758061133824000.0};

/* pi/2 = PIO2_HI + PIO2_LO to about 2^-107 */
#define PIO2_HI 1.5707963267948966    /* 0x1.921fb54442d18p+0 */
#define PIO2_LO 6.123233995736766e-17 /* 0x1.1a62633145c07p-54 */

#endif
