/* tests/test_mvtext.c: multivectors as text (ga_mv_format, ga_mv_parse) and
 * the two inner products (ga_mv_dot, ga_mv_ip).
 *
 * Text: random multivectors (a random subset of the 32 blades, coefficients
 * of every kind: +-1, small exact ones, random doubles from 1e-310 to 1e308,
 * subnormals, 1e-5, 0.1) are written and read back to the same doubles, bit
 * for bit; the text is never longer than GA_MV_TEXT_MAX promises, and the
 * longest text there is (32 terms, every coefficient minus the double after
 * 1e-7, whose shortest decimal has 17 digits written from the place 10^-7)
 * is exactly GA_MV_TEXT_MAX - 1 bytes. Then the exact text of a few (the
 * shortest decimals, in the tool's layout), and the statuses:
 * a buffer too small, NaN, an unknown name, a missing sign, an overflow.
 *
 * Inner products: against their definitions through the geometric product
 * and grade projections, sum over r, s of <<a>_r <b>_s>_|r-s| (the fat dot)
 * and the same without r = 0 or s = 0 (Hestenes), on random multivectors with
 * coefficients in [-1, 1]. Each coefficient of either side is a sum of at
 * most 32 x 32 products of size at most 1, each rounded once and summed in a
 * different order: within 2048 u = 2.3e-13 of each other (a bound, not a
 * measurement). And the special cases: for vectors both are the scalar
 * product, for a blade of grade r <= s they are the left contraction, a scalar
 * dots as a multiplication and has no Hestenes inner product.
 */
#include "testkit.h"

#include <float.h>
#include <stdlib.h>
#include <string.h>

static double coefficient(tk_rng *r)
{
    switch (tk_next(r) % 8) {
    case 0: return 1.0;
    case 1: return -1.0;
    case 2: return (double)((int)(tk_next(r) % 33) - 16) / 4; /* small exact, 0 included */
    case 3: return 1e-5;
    case 4: return ldexp((double)(tk_next(r) % 1000 + 1), -1074); /* subnormal */
    case 5: return -DBL_MAX;
    default: { /* any double, 1e-310 to 1e308, either sign */
        double x = exp(tk_range(r, log(1e-310), log(1e308)));
        return tk_next(r) % 2 ? x : -x;
    }
    }
}

static ga_mv random_mv(tk_rng *r, double keep)
{
    ga_mv X = ga_mv_zero();
    for (int i = 0; i < 32; i++)
        if (tk_uni(r) < keep)
            X.c[i] = coefficient(r);
    return X;
}

static ga_mv random_unit(tk_rng *r)
{
    ga_mv X;
    for (int i = 0; i < 32; i++) X.c[i] = tk_range(r, -1, 1);
    return X;
}

/* The definitions: sum of <<a>_r <b>_s>_|r-s| over r, s (from = 0 the fat
   dot, from = 1 Hestenes'). */
static ga_mv by_definition(ga_mv a, ga_mv b, int from)
{
    ga_mv s = ga_mv_zero();
    for (int r = from; r <= 5; r++)
        for (int q = from; q <= 5; q++)
            s = ga_mv_add(s, ga_mv_grade(ga_mv_gp(ga_mv_grade(a, r), ga_mv_grade(b, q)), abs(r - q)));
    return s;
}

static void expect_text(ga_mv X, const char *want)
{
    char buf[GA_MV_TEXT_MAX];
    size_t len = 0;
    int st = ga_mv_format(X, buf, sizeof buf, &len);
    int ok = st == GA_OK && strcmp(buf, want) == 0 && len == strlen(want);
    tk_add_bool(tk_get("exact text of a few"), ok);
    if (!ok)
        tk_note("     format gave '%s' (status %d), want '%s'\n", st == GA_OK ? buf : "", st, want);
}

static void expect_parse(const char *text, int want_st, ga_mv want)
{
    ga_mv X = ga_mv_scalar(42);
    int st = ga_mv_parse(text, &X);
    int ok = st == want_st && (st == GA_OK ? tk_mv_maxabs(ga_mv_sub(X, want)) == 0.0
                                           : X.c[0] == 42 && tk_mv_maxabs(X) == 42); /* untouched */
    tk_add_bool(tk_get(want_st == GA_OK ? "parse: texts read as meant" : "parse: refusals, output untouched"),
                ok);
    if (!ok)
        tk_note("     parse '%s': status %d, want %d\n", text, st, want_st);
}

static ga_mv term(int i, double v)
{
    ga_mv X = ga_mv_zero();
    X.c[i] = v;
    return X;
}

static tk_rng r = {2024}; /* the stream of the round trips, then of the inner products */
static char buf[GA_MV_TEXT_MAX];
static size_t len;

/* round trips, bit for bit */
static void section_round_trips(void)
{
    tk_check *rt = tk_get("format then parse: the same doubles (10^4 multivectors)");
    tk_check *ln = tk_get("text length < GA_MV_TEXT_MAX and = strlen");
    for (int n = 0; n < 10000; n++) {
        ga_mv X = random_mv(&r, n % 4 == 0 ? 1.0 : tk_uni(&r)), Y = ga_mv_scalar(7);
        int st = ga_mv_format(X, buf, sizeof buf, &len);
        tk_add_status(tk_get("format: GA_OK"), st, GA_OK);
        tk_add_bool(ln, st == GA_OK && len < GA_MV_TEXT_MAX && len == strlen(buf));
        st = ga_mv_parse(buf, &Y);
        tk_add_status(tk_get("parse of a formatted text: GA_OK"), st, GA_OK);
        int same = 1;
        for (int i = 0; i < 32; i++) same &= Y.c[i] == X.c[i];
        tk_add_bool(rt, same);
        if (!same)
            tk_note("     round trip lost: %s\n", buf);
    }
    /* the longest text: every coefficient minus the double after 1e-7 */
    ga_mv big;
    for (int i = 0; i < 32; i++) big.c[i] = -nextafter(1e-7, 1.0);
    tk_add_status(tk_get("the longest text fits GA_MV_TEXT_MAX"), ga_mv_format(big, buf, sizeof buf, &len),
                  GA_OK);
    /* "-0.00000010000000000000001" (26), then 31 times " - ", the 25 bytes of
       the number and the name: 31 x 28 + 111 bytes of names */
    tk_add_bool(ln, len == GA_MV_TEXT_MAX - 1 && len == 26 + 31 * 28 + 111 &&
                        strncmp(buf, "-0.00000010000000000000001 - ", 29) == 0);
    /* and -DBL_MAX, the longest number of the other layout */
    for (int i = 0; i < 32; i++) big.c[i] = -DBL_MAX;
    tk_add_bool(ln, ga_mv_format(big, buf, sizeof buf, &len) == GA_OK && len == 24 + 31 * 26 + 111);
}

/* exact texts */
static void section_texts(void)
{
    expect_text(ga_mv_add(ga_mv_add(ga_mv_scalar(1), term(GA_BLADE_E12, 2)), term(GA_BLADE_E1234, -0.5)),
                "1 + 2e12 - 0.5e1234");
    expect_text(ga_mv_zero(), "0");
    expect_text(ga_mv_add(term(GA_BLADE_E1, -1), term(GA_BLADE_E2, 1e-5)), "-e1 + 0.00001e2");
    expect_text(ga_mv_add(term(GA_BLADE_SCALAR, -1), term(GA_BLADE_E12345, 1e20)),
                "-1 + 100000000000000000000e12345");
    expect_text(ga_mv_add(term(GA_BLADE_SCALAR, 1e21), term(GA_BLADE_E3, -1e-8)), "1e+21 - 1e-08e3");
    expect_text(term(GA_BLADE_E45, 0.1), "0.1e45");
    expect_text(term(GA_BLADE_E1, ldexp(1, -1074)), "5e-324e1");
}

/* statuses of format: nothing written on failure */
static void section_format_status(void)
{
    ga_mv one = ga_mv_scalar(1);
    memset(buf, 'x', sizeof buf);
    len = 99;
    tk_add_status(tk_get("format: cap too small"), ga_mv_format(term(GA_BLADE_E12, 2), buf, 4, &len),
                  GA_ERR_ARG);
    tk_add_bool(tk_get("format: cap too small writes nothing"), buf[0] == 'x' && len == 99);
    tk_add_status(tk_get("format: cap exactly enough"), ga_mv_format(term(GA_BLADE_E12, 2), buf, 5, &len),
                  GA_OK);
    tk_add_status(tk_get("format: NULL buffer"), ga_mv_format(one, NULL, 0, &len), GA_ERR_ARG);
    tk_add_status(tk_get("format: NaN"), ga_mv_format(term(3, NAN), buf, sizeof buf, &len), GA_ERR_NOTFINITE);
    tk_add_status(tk_get("format: Inf"), ga_mv_format(term(9, -INFINITY), buf, sizeof buf, &len),
                  GA_ERR_NOTFINITE);
}

/* what parse reads, and what it refuses */
static void section_parse(void)
{
    ga_mv one = ga_mv_scalar(1);
    expect_parse("1 + 2e12 - 0.5e1234", GA_OK,
                 ga_mv_add(ga_mv_add(ga_mv_scalar(1), term(GA_BLADE_E12, 2)), term(GA_BLADE_E1234, -0.5)));
    expect_parse("2 e12", GA_OK, term(GA_BLADE_E12, 2));
    expect_parse("  2 * e12\n", GA_OK, term(GA_BLADE_E12, 2));
    expect_parse("-e1+e1", GA_OK, ga_mv_zero());
    expect_parse("e1 + e1 - .5e2", GA_OK, ga_mv_add(term(GA_BLADE_E1, 2), term(GA_BLADE_E2, -0.5)));
    expect_parse("1E3", GA_OK, ga_mv_scalar(1000));
    expect_parse("2e+3e1", GA_OK, term(GA_BLADE_E1, 2000));
    expect_parse("2.5e-3", GA_OK, ga_mv_scalar(0.0025));
    expect_parse("+3.", GA_OK, ga_mv_scalar(3));
    expect_parse("0", GA_OK, ga_mv_zero());
    expect_parse("", GA_ERR_ARG, one);
    expect_parse("   ", GA_ERR_ARG, one);
    expect_parse("e21", GA_ERR_ARG, one);
    expect_parse("e6", GA_ERR_ARG, one);
    expect_parse("e", GA_ERR_ARG, one);
    expect_parse("nan", GA_ERR_ARG, one);
    expect_parse("inf e1", GA_ERR_ARG, one);
    expect_parse("1 2", GA_ERR_ARG, one);
    expect_parse("e1 e2", GA_ERR_ARG, one);
    expect_parse("2 *", GA_ERR_ARG, one);
    expect_parse("2 * 3", GA_ERR_ARG, one);
    expect_parse("1 +", GA_ERR_ARG, one);
    expect_parse("1 + - 2", GA_ERR_ARG, one);
    expect_parse("2 e9", GA_ERR_ARG, one);
    expect_parse("1e999", GA_ERR_ARG, one); /* 1 e999: no such blade */
    expect_parse("1e+999", GA_ERR_NOTFINITE, one);
    expect_parse("1e+999e3", GA_ERR_NOTFINITE, one);
    /* beyond the double range as the tool's reader (strtod) takes it: above,
       +-Inf, refused as not finite; below, 0 or a subnormal. "1e400" is
       1 e400 (as "1e999" above): an unknown name, not a number */
    expect_parse("1e400", GA_ERR_ARG, one);
    expect_parse("1E400", GA_ERR_NOTFINITE, one);
    expect_parse("-1e+400 e12", GA_ERR_NOTFINITE, one);
    expect_parse("1 + 1e+400e12", GA_ERR_NOTFINITE, one);
    /* terms of one blade adding up past DBL_MAX: refused as one literal
       beyond the range is (GA_ERR_NOTFINITE), whether the sum stays infinite or comes back */
    expect_parse("1e+308 + 1e+308", GA_ERR_NOTFINITE, one);
    expect_parse("-1e+308e12 - 1e+308 e12", GA_ERR_NOTFINITE, one);
    expect_parse("1e+308 + 1e+308 - 1e+308", GA_ERR_NOTFINITE, one);
    expect_parse("1.7976931348623157e+308 e1 + 1e+292 e1", GA_ERR_NOTFINITE, one);
    /* up to DBL_MAX it is read: no false refusal */
    {
        ga_mv m = ga_mv_zero();
        m.c[0] = DBL_MAX;
        expect_parse("1e+308 + 7.976931348623157e+307", GA_OK, m);
    }
    expect_parse("1e-400", GA_OK, ga_mv_zero());
    expect_parse("-4e-324e3", GA_OK, term(GA_BLADE_E3, -0x1p-1074));
    /* a decimal of any length, as the tool reads it (one of 400 characters
       or more was refused); only a mantissa that long glued to a blade name
       is not read */
    {
        static char big[1200];
        size_t n = 0;
        big[n++] = '0', big[n++] = '.';
        for (int i = 0; i < 450; i++) big[n++] = '0';
        memcpy(big + n, "25e+451", 8); /* 0.(450 zeros)25 x 10^451 = 2.5 */
        expect_parse(big, GA_OK, ga_mv_scalar(2.5));
        memcpy(big + n, "25E+451 e12", 12);
        expect_parse(big, GA_OK, term(GA_BLADE_E12, 2.5));
        memcpy(big + n, "25e12", 6);
        expect_parse(big, GA_ERR_ARG, one);
        n = 0;
        big[n++] = '1';
        for (int i = 0; i < 999; i++) big[n++] = '0';
        big[n] = '\0'; /* 10^999 */
        expect_parse(big, GA_ERR_NOTFINITE, one);
    }
    tk_add_status(tk_get("parse: NULL text"), ga_mv_parse(NULL, &one), GA_ERR_ARG);
}

/* inner products against their definitions */
static void section_inner(void)
{
    tk_check *fd = tk_get("fat dot = sum <<a>_r <b>_s>_|r-s| (10^3 pairs)");
    tk_check *hi = tk_get("Hestenes = the same without r or s = 0 (10^3 pairs)");
    for (int n = 0; n < 1000; n++) {
        ga_mv a = random_unit(&r), b = random_unit(&r);
        tk_add_tol(fd, tk_mv_maxabs(ga_mv_sub(ga_mv_dot(a, b), by_definition(a, b, 0))),
                   2048 * DBL_EPSILON / 2);
        tk_add_tol(hi, tk_mv_maxabs(ga_mv_sub(ga_mv_ip(a, b), by_definition(a, b, 1))),
                   2048 * DBL_EPSILON / 2);
        /* vectors: both are the scalar product; grade 1 and grade 3: the left contraction */
        ga_mv u = ga_mv_grade(a, 1), v = ga_mv_grade(b, 1), w = ga_mv_grade(b, 3);
        ga_mv d = ga_mv_dot(u, v);
        tk_add_tol(tk_get("vectors: u . v = <u v>_0, a scalar"),
                   tk_max(fabs(d.c[0] - ga_mv_sp(u, v)), tk_mv_maxabs(ga_mv_sub(d, ga_mv_grade(d, 0)))),
                   8 * DBL_EPSILON);
        tk_add_tol(tk_get("grade 1 on grade 3: u . W = u _| W = Hestenes"),
                   tk_max(tk_mv_maxabs(ga_mv_sub(ga_mv_dot(u, w), ga_mv_lc(u, w))),
                          tk_mv_maxabs(ga_mv_sub(ga_mv_ip(u, w), ga_mv_lc(u, w)))),
                   64 * DBL_EPSILON);
        tk_add_tol(tk_get("a scalar: 2 . b = 2 b; Hestenes 0"),
                   tk_max(tk_mv_maxabs(ga_mv_sub(ga_mv_dot(ga_mv_scalar(2), b), ga_mv_scale(b, 2))),
                          tk_mv_maxabs(ga_mv_ip(ga_mv_scalar(2), b))),
                   0);
    }
}

static const tk_section sections[] = {
    {"round_trips", section_round_trips, TK_STREAM},
    {"texts", section_texts, 0},
    {"format_status", section_format_status, 0},
    {"parse", section_parse, 0},
    {"inner", section_inner, TK_STREAM},
};

int main(int argc, char **argv) { return tk_main(argc, argv, "test_mvtext", sections, TK_COUNT(sections)); }
