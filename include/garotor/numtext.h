/* garotor/numtext.h: doubles written as the shortest decimal that reads back
 * as the same double.
 *
 * ga_double_shortest finds, for a finite double x, the decimal d x 10^e with
 * the fewest significant digits that strtod (round to nearest, ties to even)
 * reads back as x; of those, the one nearest x (a tie: the even d). So 0.1 is
 * 1 x 10^-1, not 0.10000000000000001, and 2^-1074 is 5 x 10^-324. The method
 * is R. Giulietti's Schubfach ("The Schubfach way to render doubles", 2020):
 * no loop over digit counts, no big numbers, no allocation, no locale.
 *
 * One layout for every number garotor writes (the tool, ga_mv_format):
 * positional when the leading digit is between the places 10^20 and 10^-7
 * (1305031102.1858, 0.25, 0.0000001, 100000000000000000000), else d.ddde+XX
 * with at least two exponent digits (1e+21, 1.5e-08, 5e-324).
 */
#ifndef GAROTOR_NUMTEXT_H
#define GAROTOR_NUMTEXT_H

#include <stddef.h>
#include <stdint.h>

#include "export.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Bytes ga_double_format may need, the terminating zero included. */
enum { GA_DOUBLE_TEXT_MAX = 32 };

/** The shortest decimal of x as *digits x 10^*exp, *digits without trailing
 *  zeros (0 and exp 0 for a zero); the sign is x's. Returns the number of
 *  digits (1 to 17); for a NaN or an infinity, 0 (and *digits = 0,
 *  *exp = 0). */
GA_API int ga_double_shortest(double x, uint64_t *digits, int *exp);

/** x written in the layout above into buf (GA_DOUBLE_TEXT_MAX bytes), the
 *  shortest text that strtod reads back as x; a negative zero is written
 *  "-0", an infinity "inf" or "-inf", a NaN "nan". Returns the length,
 *  without the terminating zero. */
GA_API size_t ga_double_format(double x, char *buf);

/** A decimal, sign (neg nonzero: '-') then the digits dig[0..n-1] ('0'..'9',
 *  dig[0] not '0', n >= 1) x 10^exp, in the layout above; n = 0 writes "0".
 *  buf needs n + 30 bytes. Returns the length, without the terminating zero.
 *  For decimals that are not doubles (an exact sum of a time stamp and an
 *  offset, say) written like every other number. */
GA_API size_t ga_decimal_format(int neg, const char *dig, int n, int exp, char *buf);

#ifdef __cplusplus
}
#endif
#endif
