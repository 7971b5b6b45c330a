/* tools/timetext.h: times read from their decimal text without loss.
 *
 * A time is kept as the exact decimal its text writes, +-d_0 d_1 ... d_{n-1}
 * x 10^exp, so that the difference of two times is exact and only the final
 * conversion to a double rounds (once, correctly: strtod of the exact
 * digits). `garotor interp` builds its path on times relative to the first
 * key's, so keys stamped T0 + s_i give the same doubles as keys stamped s_i
 * (docs/tool.md, "Times").
 *
 * Exact: a decimal text (digits, an optional point, an optional exponent)
 * with at most TT_SIG significant digits, all of them between the places
 * 10^TT_TOP and 10^-TT_LOW. Any other finite text strtod reads (hexadecimal,
 * or digits beyond those limits) is taken as its double, written with 17
 * significant digits. Sums and differences of two such values always fit.
 */
#ifndef GAROTOR_TOOLS_TIMETEXT_H
#define GAROTOR_TOOLS_TIMETEXT_H

#include <stddef.h>

enum { TT_SIG = 400, TT_TOP = 310, TT_LOW = 760, TT_DIG = TT_TOP + TT_LOW + 8 };

/** +-d[0..n-1] x 10^exp; d[0] and d[n-1] non-zero; zero is n = 0, neg = 0. */
typedef struct {
    int neg, n, exp;
    unsigned char d[TT_DIG];
} tt_dec;

/** The exact value of a text strtod reads as a finite double (see above). */
void tt_parse(const char *text, tt_dec *out);
/** out = a + b, or a - b with sub; exact. -1 if it does not fit (never for
 *  values of tt_parse or tt_shortest), 0 otherwise. */
int tt_add(const tt_dec *a, const tt_dec *b, int sub, tt_dec *out);
/** a x 10^shift, correctly rounded to a double (may be +-inf). */
double tt_to_double(const tt_dec *a, int shift);
/** The shortest decimal that reads back as x (x finite; numtext.h). */
void tt_shortest(double x, tt_dec *out);
/** 1 if a is a whole number. */
int tt_is_integer(const tt_dec *a);
/** a written out in the layout of every number the tool writes (ga_decimal_format:
 *  positional, 1305031102.1858 or 0.001, when its leading digit is between
 *  the places 10^20 and 10^-7, else d.ddde+XX); buf holds at least
 *  TT_DIG + 32 bytes. */
void tt_format(const tt_dec *a, char *buf);

#endif
