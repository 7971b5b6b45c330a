/* tests/test_numtext.c: the shortest-decimal writer (ga/numtext.c, numtext.h)
 * against strtod and a slow reference.
 *
 * For every double tried (seeded: random bit patterns, subnormals, every
 * power of two and its neighbours, integers, short decimals, the extremes):
 *   - the text ga_double_format gives reads back (strtod) as the same double, bit for
 *     bit, and has the digits ga_double_shortest gives;
 *   - no shorter decimal reads back: the nearest decimal of one digit fewer
 *     (printf's %.*e, correctly rounded) does not;
 *   - where the nearest decimal of as many digits reads back, it is the one
 *     written (the nearest, a tie to even); where it does not, x is at the
 *     bottom of a binade (its rounding interval is lopsided there, so a
 *     decimal inside it need not be the nearest of its length);
 *   - for one double in REF_EVERY, the reference itself: the least p in
 *     1..17 for which %.{p-1}e reads back, which must be no less than the
 *     number of digits written.
 * An argument N multiplies the random counts (a soak: `test_numtext 100`).
 */
#include <garotor/numtext.h>
#include "testkit.h"

#include <stdlib.h>

enum { REF_EVERY = 8 };

static long n_tried, n_lopsided, n_ref;

static uint64_t bits_of(double x)
{
    uint64_t b;
    memcpy(&b, &x, sizeof b);
    return b;
}

static double from_bits(uint64_t b)
{
    double x;
    memcpy(&x, &b, sizeof x);
    return x;
}

/* The digits and exponent of a %.*e text, trailing zeros dropped. */
static void parse_e(const char *s, uint64_t *f, int *e)
{
    uint64_t v = 0;
    int n = 0;
    if (*s == '-')
        s++;
    for (; *s && *s != 'e'; s++)
        if (*s != '.') {
            v = v * 10 + (uint64_t)(*s - '0');
            n++;
        }
    int ex = atoi(s + 1) - (n - 1);
    while (v && v % 10 == 0) {
        v /= 10;
        ex++;
    }
    *f = v;
    *e = v ? ex : 0;
}

static int round_trips(double x, int p, char *buf, size_t size)
{
    snprintf(buf, size, "%.*e", p - 1, x);
    return bits_of(strtod(buf, NULL)) == bits_of(x);
}

static void check(double x, int most_digits, tk_check *trip, tk_check *shortest, tk_check *nearest,
                  tk_check *reference)
{
    char buf[GA_DOUBLE_TEXT_MAX + 8], ref[64];
    size_t len = ga_double_format(x, buf);
    uint64_t f, rf;
    int e, re, n = ga_double_shortest(x, &f, &e);
    n_tried++;
    tk_add_bool(trip,
                strlen(buf) == len && len < GA_DOUBLE_TEXT_MAX && bits_of(strtod(buf, NULL)) == bits_of(x));
    /* the text has exactly the digits of ga_double_shortest: those of its
       significand, less the zeros that only place the point */
    char sig[GA_DOUBLE_TEXT_MAX];
    int k = 0;
    for (const char *c = buf; *c && *c != 'e'; c++)
        if (*c >= '0' && *c <= '9' && (k || *c != '0'))
            sig[k++] = *c;
    while (k && sig[k - 1] == '0') k--;
    uint64_t g = 0;
    for (int i = 0; i < k && i < 19; i++) g = g * 10 + (uint64_t)(sig[i] - '0');
    tk_add_bool(trip, x == 0.0 ? f == 0 && n == 1 && k == 0 : k == n && g == f && n <= 17 && f % 10 != 0);
    /* ga_double_format lays the digits out as ga_decimal_format does */
    char dig[24], lay[GA_DOUBLE_TEXT_MAX + 8];
    snprintf(dig, sizeof dig, "%llu", (unsigned long long)f);
    ga_decimal_format(signbit(x) != 0, dig, f ? n : 0, e, lay);
    tk_add_bool(trip, strcmp(lay, buf) == 0 || (x == 0.0 && signbit(x) && strcmp(buf, "-0") == 0));
    if (x == 0.0)
        return;
    tk_add_bool(shortest, n <= most_digits && (n == 1 || !round_trips(x, n - 1, ref, sizeof ref)));
    if (round_trips(x, n, ref, sizeof ref)) {
        parse_e(ref, &rf, &re);
        tk_add_bool(nearest, rf == f && re == e);
    } else {
        n_lopsided++;
        tk_add_bool(nearest, (bits_of(x) & (((uint64_t)1 << 52) - 1)) == 0);
    }
    if (n_tried % REF_EVERY == 0) {
        int p = 1;
        while (p < 17 && !round_trips(x, p, ref, sizeof ref)) p++;
        n_ref++;
        tk_add_bool(reference, n <= p);
    }
}

static int finite_bits(tk_rng *r, double *x)
{
    *x = from_bits(tk_next(r));
    return isfinite(*x);
}

static long scale; /* the scale argument: random doubles times scale */

/* every kind of double: the shortest text that reads back */
static void section_shortest(void)
{
    tk_rng rng = {20261201};
    tk_check trip = tk_begin(
        "numtext: the text reads back as x, has ga_double_shortest's digits, ga_decimal_format's layout", 0);
    tk_check shortest = tk_begin("numtext: no decimal of one digit fewer reads back", 0);
    tk_check nearest = tk_begin("numtext: the nearest of its length (or a binade's bottom)", 0);
    tk_check reference = tk_begin("numtext: no longer than the least %.{p-1}e that reads back", 0);
#define CHECK(x, most) check((x), (most), &trip, &shortest, &nearest, &reference)

    /* the extremes, and a few by hand */
    const double fixed[] = {0.0,
                            -0.0,
                            DBL_MAX,
                            -DBL_MAX,
                            DBL_MIN,
                            DBL_TRUE_MIN,
                            0x1p-1022 - 0x1p-1074,
                            1.0,
                            0.1,
                            0.3,
                            1.0 / 3.0,
                            2.0 / 3.0,
                            9007199254740992.0,
                            9007199254740993.0,
                            1e21,
                            1e22,
                            1e23,
                            5e-324,
                            1e-7,
                            1.5e-8,
                            123.456,
                            1e308};
    for (size_t i = 0; i < sizeof fixed / sizeof *fixed; i++) CHECK(fixed[i], 17);
    /* every power of two, and its neighbours */
    for (int p = -1074; p <= 1023; p++) {
        double x = ldexp(1.0, p);
        CHECK(x, 17);
        CHECK(-x, 17);
        CHECK(nextafter(x, 0.0), 17);
        CHECK(nextafter(x, INFINITY), 17);
    }
    /* random bit patterns: every binade alike */
    for (long i = 0; i < 400000 * scale; i++) {
        double x;
        if (finite_bits(&rng, &x))
            CHECK(x, 17);
    }
    /* subnormals */
    for (long i = 0; i < 100000 * scale; i++) {
        uint64_t b = tk_next(&rng) & ((((uint64_t)1 << 52) - 1) | ((uint64_t)1 << 63));
        CHECK(from_bits(b), 17);
    }
    /* whole numbers, below 2^53 and beyond */
    for (long i = 0; i < 200000 * scale; i++) {
        uint64_t v = tk_next(&rng) >> (tk_next(&rng) % 64);
        CHECK((double)v, 17);
        CHECK(-(double)(v >> 11), 17);
    }
    /* short decimals: m x 10^e with d <= 15 digits reads back with at most d */
    for (long i = 0; i < 200000 * scale; i++) {
        int d = 1 + (int)(tk_next(&rng) % 15);
        uint64_t m = 1 + tk_next(&rng) % 999999999999999ull;
        uint64_t p10 = 1;
        for (int k = 0; k < d; k++) p10 *= 10;
        m %= p10;
        if (m == 0)
            m = 1;
        int e = (int)(tk_next(&rng) % 640) - 330;
        char s[64];
        snprintf(s, sizeof s, "%llue%d", (unsigned long long)m, e);
        double x = strtod(s, NULL);
        if (isfinite(x) && x >= DBL_MIN)
            CHECK(x, d); /* below DBL_MIN the double may hold fewer digits than m */
    }
    /* uniform and log-uniform values of everyday size */
    for (long i = 0; i < 100000 * scale; i++) {
        CHECK(tk_uni(&rng), 17);
        CHECK(-tk_loguni(&rng, 1e-9, 1e9), 17);
    }
    tk_end(&trip);
    tk_end(&shortest);
    tk_end(&nearest);
    tk_end(&reference);
}

/* the layout: one rule for every number */
static void section_layout(void)
{
    static const struct {
        double x;
        const char *text;
    } layout[] = {
        {0.0, "0"},
        {-0.0, "-0"},
        {0.1, "0.1"},
        {-2.5, "-2.5"},
        {100.0, "100"},
        {123.456, "123.456"},
        {1e20, "100000000000000000000"},
        {1e21, "1e+21"},
        {1.5e21, "1.5e+21"},
        {1e-7, "0.0000001"},
        {1.25e-7, "0.000000125"},
        {1.5e-8, "1.5e-08"},
        {5e-324, "5e-324"},
        {DBL_MAX, "1.7976931348623157e+308"},
        {DBL_MIN, "2.2250738585072014e-308"},
        {1.0 / 3.0, "0.3333333333333333"},
        {1305031102.1858, "1305031102.1858"},
        {9007199254740993.0, "9007199254740992"},
        {1.2246467991473532e-16, "1.2246467991473532e-16"},
    };
    tk_check lay = tk_begin("numtext: the layout of hand-picked numbers", 0);
    for (size_t i = 0; i < sizeof layout / sizeof *layout; i++) {
        char buf[GA_DOUBLE_TEXT_MAX];
        ga_double_format(layout[i].x, buf);
        int ok = strcmp(buf, layout[i].text) == 0;
        if (!ok)
            tk_note("  %s written as %s\n", layout[i].text, buf);
        tk_add_bool(&lay, ok);
    }
    tk_end(&lay);
    tk_note("  %ld doubles, %ld against the full reference, %ld at a binade's bottom shorter than the "
            "nearest of their length\n",
            n_tried, n_ref, n_lopsided);
}

/* NaN and the infinities: words that strtod reads back, and no digits */
static void section_nonfinite(void)
{
    const double x[3] = {INFINITY, -INFINITY, NAN};
    const char *text[3] = {"inf", "-inf", "nan"};
    tk_check c = tk_begin("numtext: inf, -inf, nan written as strtod reads them, no digits", 0);
    for (int i = 0; i < 3; i++) {
        char buf[GA_DOUBLE_TEXT_MAX];
        size_t len = ga_double_format(x[i], buf);
        double back = strtod(buf, NULL);
        uint64_t digits = 1;
        int e = 1, n = ga_double_shortest(x[i], &digits, &e);
        tk_add_bool(&c, strcmp(buf, text[i]) == 0 && len == strlen(text[i]));
        tk_add_bool(&c, isnan(x[i]) ? isnan(back) : back == x[i]);
        tk_add_bool(&c, n == 0 && digits == 0 && e == 0);
    }
    tk_end(&c);
}

static const tk_section sections[] = {
    {"shortest", section_shortest, 0},
    {"layout", section_layout, 0},
    {"nonfinite", section_nonfinite, 0},
};

/* the scale argument */
static void setup(const char *arg)
{
    scale = arg ? atol(arg) : 1;
    if (scale < 1)
        scale = 1;
}

int main(int argc, char **argv)
{
    return tk_main_arg(argc, argv, "numtext", sections, TK_COUNT(sections), setup);
}
