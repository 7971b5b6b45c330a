/* tools/numtext.h: doubles written as the shortest decimal that reads back as
 * the same double.
 *
 * nt_shortest finds, for a finite double x, the decimal d x 10^e with the
 * fewest significant digits that strtod (round to nearest, ties to even)
 * reads back as x; of those, the one nearest x (a tie: the even d). So 0.1 is
 * 1 x 10^-1, not 0.10000000000000001, and 2^-1074 is 5 x 10^-324. The method
 * is Giulietti's Schubfach: x is scaled by a 126-bit approximation of a power
 * of ten (tools/numtext_table.inc, written by gen/generate.py) so that the
 * rounding interval of x and the candidates within it are read off 64-bit
 * integers, with no loop over digit counts and no big numbers.
 *
 * One layout for every number the tool writes (nt_layout): positional when the
 * leading digit is between the places 10^20 and 10^-7 (1305031102.1858, 0.25,
 * 0.0000001, 100000000000000000000), else d.ddde+XX with at least two exponent
 * digits (1e+21, 1.5e-08, 5e-324). */
#ifndef GAROTOR_TOOLS_NUMTEXT_H
#define GAROTOR_TOOLS_NUMTEXT_H

#include <stddef.h>
#include <stdint.h>

/* The library compiles these into ga/mv.c for ga_mv_format, as static
 * functions: it defines NT_API as static and NT_WRITE_ONLY (no nt_layout)
 * before it includes numtext.c. The tool and the tests link numtext.c. */
#ifndef NT_API
#define NT_API
#endif

/** Bytes nt_write may need, the terminating zero included. */
enum { NT_BUF = 32 };

/** The shortest decimal of a finite x as *digits x 10^*exp, *digits without
 *  trailing zeros (0 and exp 0 for a zero); the sign is x's. Returns the
 *  number of digits (1 to 17). */
NT_API int nt_shortest(double x, uint64_t *digits, int *exp);
/** x (finite) written in the layout above into buf (NT_BUF bytes); a negative
 *  zero is written "-0". Returns the length, without the terminating zero. */
NT_API size_t nt_write(double x, char *buf);
/** A decimal, sign then the characters dig[0..n-1] ('0'..'9', dig[0] not '0',
 *  n >= 1) x 10^exp, in the layout above; n = 0 writes "0". buf needs n + 30
 *  bytes. Returns the length. */
#ifndef NT_WRITE_ONLY
size_t nt_layout(int neg, const char *dig, int n, int exp, char *buf);
#endif

#endif
