/* ga/numtext.c: the shortest decimal of a double (garotor/numtext.h).
 *
 * ga_double_shortest follows R. Giulietti, "The Schubfach way to render doubles"
 * (2020), as in its reference implementation (Java's DoubleToDecimal): with
 * x = c 2^q, the rounding interval of x is [c - 1/2, c + 1/2] 2^q (the lower
 * half a quarter at the bottom of a binade), closed when c is even. Scaled by
 * 10^-k, k = floor(log10 2^q), and by 4, its centre and ends are computed by
 * rop (a product with g(k) rounded to odd, which keeps them ordered and
 * tells an exact end from an inexact one); then the candidates are the one
 * multiple of ten s' and the two integers s, s + 1 around the centre.
 * Two departures from Java's, whose rules ask for at least two digits: s'
 * is tried from s >= 10 (Java: 100), and the two smallest subnormals, whose
 * intervals hold several one-digit decimals, are given directly (5e-324,
 * 1e-323) instead of being scaled by ten. */
#include <garotor/numtext.h>

#include <string.h>

#include "numtext_table.inc"

#define C_MIN ((uint64_t)1 << 52) /* the hidden bit */
#define Q_MIN (-1074)
#define MASK63 (((uint64_t)1 << 63) - 1)

/* The high 64 bits of a 64 x 64-bit product. */
#if defined(__SIZEOF_INT128__) && !defined(NT_NO_INT128)
__extension__ typedef unsigned __int128 nt_u128;
static inline uint64_t mul_hi(uint64_t a, uint64_t b, uint64_t *lo)
{
    nt_u128 p = (nt_u128)a * b;
    *lo = (uint64_t)p;
    return (uint64_t)(p >> 64);
}
#else
static inline uint64_t mul_hi(uint64_t a, uint64_t b, uint64_t *lo)
{
    uint64_t a0 = a & 0xffffffffu, a1 = a >> 32, b0 = b & 0xffffffffu, b1 = b >> 32;
    uint64_t p00 = a0 * b0, p01 = a0 * b1, p10 = a1 * b0, p11 = a1 * b1;
    uint64_t mid = (p00 >> 32) + (p01 & 0xffffffffu) + (p10 & 0xffffffffu);
    *lo = (mid << 32) | (p00 & 0xffffffffu);
    return p11 + (p01 >> 32) + (p10 >> 32) + (mid >> 32);
}
#endif

/* floor(g cp / 2^127) rounded to odd (its last bit set when inexact), for
 * g = g1 2^63 + g0 (each half below 2^63) and cp < 2^63. */
static inline uint64_t rop(uint64_t g1, uint64_t g0, uint64_t cp)
{
    uint64_t lo;
    uint64_t x1 = mul_hi(g0, cp, &lo);
    uint64_t y1 = mul_hi(g1, cp, &lo);
    uint64_t z = (lo >> 1) + x1;
    uint64_t vbp = y1 + (z >> 63);
    return vbp | (((z & MASK63) + MASK63) >> 63);
}

/* floor(n 2^-s) for a possibly negative n (no right shift of a negative). */
static inline int floor_shift(long long n, int s)
{
    long long d = (long long)1 << s;
    return (int)(n >= 0 ? n / d : -((-n + d - 1) / d));
}

/* x = c 2^q (c >= 3); the result is *f x 10^*e. */
static void to_decimal(int q, uint64_t c, uint64_t *f, int *e)
{
    uint64_t out = c & 1, cb = c << 2, cbr = cb + 2, cbl;
    int k;
    if (c != C_MIN || q == Q_MIN) {
        cbl = cb - 2;
        k = floor_shift((long long)q * NT_LOG10_2, NT_LOG10_2_SHIFT);
    } else { /* the bottom of a binade: the lower half-interval is half as wide */
        cbl = cb - 1;
        k = floor_shift((long long)q * NT_LOG10_2 + NT_LOG10_3_4, NT_LOG10_2_SHIFT);
    }
    int h = q + floor_shift((long long)-k * NT_LOG2_10, NT_LOG2_10_SHIFT) + 2; /* 1..4 */
    uint64_t g1 = nt_g[k - NT_K_MIN][0], g0 = nt_g[k - NT_K_MIN][1];
    uint64_t vb = rop(g1, g0, cb << h), vbl = rop(g1, g0, cbl << h), vbr = rop(g1, g0, cbr << h);
    uint64_t s = vb >> 2;
    *e = k;
    if (s >= 10) { /* one digit fewer: the multiple of ten below or above */
        uint64_t sp10 = s / 10 * 10, tp10 = sp10 + 10;
        int upin = vbl + out <= sp10 << 2, wpin = (tp10 << 2) + out <= vbr;
        if (upin != wpin) {
            *f = upin ? sp10 : tp10;
            return;
        }
    }
    uint64_t t = s + 1;
    int uin = vbl + out <= s << 2, win = (t << 2) + out <= vbr;
    if (uin != win) {
        *f = uin ? s : t;
        return;
    }
    /* both in: the nearer, a tie to the even one */
    uint64_t mid = (s + t) << 1;
    *f = vb < mid || (vb == mid && (s & 1) == 0) ? s : t;
}

static const uint64_t pow10[20] = {1u,
                                   10u,
                                   100u,
                                   1000u,
                                   10000u,
                                   100000u,
                                   1000000u,
                                   10000000u,
                                   100000000u,
                                   1000000000u,
                                   10000000000u,
                                   100000000000u,
                                   1000000000000u,
                                   10000000000000u,
                                   100000000000000u,
                                   1000000000000000u,
                                   10000000000000000u,
                                   100000000000000000u,
                                   1000000000000000000u,
                                   10000000000000000000u};

/* The number of decimal digits of f > 0. */
static inline int digit_count(uint64_t f)
{
#if defined(__GNUC__)
    int bits = 64 - __builtin_clzll(f);   /* 2^(bits-1) <= f < 2^bits */
    int n = (bits * 1233) >> 12;          /* floor(bits log10 2), 0..19 */
    return n + (n < 20 && f >= pow10[n]); /* pow10[n] <= 2^bits: one step up at most */
#else
    int n = 1;
    while (n < 20 && f >= pow10[n]) n++;
    return n;
#endif
}

/* ga_double_shortest's work, inlined into ga_double_format (no call through
 * the PLT for every number). */
static inline int shortest(double x, uint64_t *digits, int *exp)
{
    uint64_t bits;
    memcpy(&bits, &x, sizeof bits);
    int bq = (int)(bits >> 52) & 0x7ff;
    uint64_t t = bits & (C_MIN - 1), f;
    int e;
    if (bq == 0x7ff) { /* NaN or an infinity: no decimal */
        *digits = 0;
        *exp = 0;
        return 0;
    }
    if (bq == 0 && t == 0) {
        *digits = 0;
        *exp = 0;
        return 1;
    }
    if (bq != 0) {
        int mq = 1075 - bq; /* x = c 2^-mq */
        uint64_t c = C_MIN | t;
        if (mq > 0 && mq < 53 && (c >> mq) << mq == c) {
            /* a whole number below 2^53: every one is a double, so its own
               digits are the shortest */
            f = c >> mq;
            e = 0;
        } else
            to_decimal(-mq, c, &f, &e);
    } else if (t < 3) {
        /* 2^-1074 and 2^-1073, whose intervals are too wide for the scaled
           search (they hold several one-digit decimals): the nearest of them,
           as the tests check against the reference */
        f = t == 1 ? 5 : 1;
        e = t == 1 ? -324 : -323;
    } else
        to_decimal(Q_MIN, t, &f, &e);
    while (f % 10 == 0) {
        f /= 10;
        e++;
    }
    *digits = f;
    *exp = e;
    return digit_count(f);
}

int ga_double_shortest(double x, uint64_t *digits, int *exp) { return shortest(x, digits, exp); }

static const char pairs[201] =
    "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
    "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
    "8081828384858687888990919293949596979899";

size_t ga_decimal_format(int neg, const char *dig, int n, int exp, char *buf)
{
    char *p = buf;
    if (n == 0) {
        *p++ = '0';
        *p = '\0';
        return 1;
    }
    if (neg)
        *p++ = '-';
    int x = exp + n - 1; /* the place of the leading digit */
    if (x >= -7 && x <= 20) {
        if (x < 0) {
            *p++ = '0';
            *p++ = '.';
            for (int i = -1; i > x; i--) *p++ = '0';
            memcpy(p, dig, (size_t)n);
            p += n;
        } else if (n <= x + 1) {
            memcpy(p, dig, (size_t)n);
            p += n;
            for (int i = n; i <= x; i++) *p++ = '0';
        } else {
            memcpy(p, dig, (size_t)x + 1);
            p += x + 1;
            *p++ = '.';
            memcpy(p, dig + x + 1, (size_t)(n - x - 1));
            p += n - x - 1;
        }
        *p = '\0';
        return (size_t)(p - buf);
    }
    *p++ = dig[0];
    if (n > 1) {
        *p++ = '.';
        memcpy(p, dig + 1, (size_t)n - 1);
        p += n - 1;
    }
    *p++ = 'e';
    *p++ = x < 0 ? '-' : '+';
    int ax = x < 0 ? -x : x;
    if (ax >= 100)
        *p++ = (char)('0' + ax / 100);
    memcpy(p, pairs + 2 * (ax % 100), 2);
    p += 2;
    *p = '\0';
    return (size_t)(p - buf);
}

static int bits_negative(double x)
{
    uint64_t bits;
    memcpy(&bits, &x, sizeof bits);
    return (int)(bits >> 63);
}

/* The 8 digits of v < 10^8 written to p[0..7]. On a little-endian machine
 * all eight at once in one 64-bit word (SWAR): v split into 4-digit halves in
 * 32-bit lanes, each into 2-digit pairs in 16-bit lanes (x 10486 >> 20 is
 * x / 100 for x < 10^4), each pair into digits in bytes (x 103 >> 10 is
 * x / 10 for x < 100), the first digit in the lowest byte; elsewhere by
 * pairs from the table. */
static inline void put8(uint32_t v, char *p)
{
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
    uint64_t x = (uint64_t)(v / 10000) | ((uint64_t)(v % 10000) << 32);
    uint64_t hi = ((x * 10486) >> 20) & 0x0000007F0000007Fu;
    x = hi | ((x - hi * 100) << 16);
    hi = ((x * 103) >> 10) & 0x000F000F000F000Fu;
    x = hi | ((x - hi * 10) << 8);
    x += 0x3030303030303030u;
    memcpy(p, &x, 8);
#else
    uint32_t a = v / 10000, b = v % 10000;
    memcpy(p, pairs + 2 * (a / 100), 2);
    memcpy(p + 2, pairs + 2 * (a % 100), 2);
    memcpy(p + 4, pairs + 2 * (b / 100), 2);
    memcpy(p + 6, pairs + 2 * (b % 100), 2);
#endif
}

/* The n digits of f written to p[0..n-1]. */
static inline void put_digits(uint64_t f, int n, char *p)
{
    char *d = p + n;
    while (f >= 100000000u) {
        d -= 8;
        put8((uint32_t)(f % 100000000u), d);
        f /= 100000000u;
    }
    uint32_t v = (uint32_t)f;
    while (v >= 100) {
        d -= 2;
        memcpy(d, pairs + 2 * (v % 100), 2);
        v /= 100;
    }
    if (v >= 10)
        memcpy(d - 2, pairs + 2 * v, 2);
    else
        d[-1] = (char)('0' + v);
}

size_t ga_double_format(double x, char *buf)
{
    uint64_t f;
    int e, n = shortest(x, &f, &e);
    char *p = buf;
    if (n == 0) { /* NaN or an infinity, in the words strtod reads back */
        const char *w = x != x ? "nan" : x < 0 ? "-inf" : "inf";
        size_t k = strlen(w);
        memcpy(buf, w, k + 1);
        return k;
    }
    if (bits_negative(x))
        *p++ = '-';
    if (f == 0) {
        memcpy(p, "0", 2);
        return (size_t)(p + 1 - buf);
    }
    /* ga_decimal_format's rule, with the digits written in place */
    int xp = e + n - 1;
    if (xp >= -7 && xp <= 20) {
        if (xp < 0) {
            memcpy(p, "0.000000", 8);
            p += 1 - xp;
            put_digits(f, n, p);
            p += n;
        } else if (n <= xp + 1) {
            put_digits(f, n, p);
            p += n;
            for (int i = n; i <= xp; i++) *p++ = '0';
        } else if (xp <= 12) {
            /* the digits in d, then copied in two fixed-size pieces (no
               memmove call for a byte or two): the whole part's xp + 1 and
               the point before the rest; buf holds them (1 + 16 + 16 bytes
               at most, before the zero) */
            char d[40];
            put_digits(f, n, d);
            memcpy(p, d, 16);
            memcpy(p + xp + 2, d + xp + 1, 16);
            p[xp + 1] = '.';
            p += n + 1;
        } else {
            put_digits(f, n, p + 1);
            for (int i = 0; i <= xp; i++) p[i] = p[i + 1];
            p[xp + 1] = '.';
            p += n + 1;
        }
        *p = '\0';
        return (size_t)(p - buf);
    }
    put_digits(f, n, p + 1);
    p[0] = p[1];
    if (n > 1) {
        p[1] = '.';
        p += n + 1;
    } else
        p += 1;
    *p++ = 'e';
    *p++ = xp < 0 ? '-' : '+';
    int ax = xp < 0 ? -xp : xp;
    if (ax >= 100)
        *p++ = (char)('0' + ax / 100);
    memcpy(p, pairs + 2 * (ax % 100), 2);
    p += 2;
    *p = '\0';
    return (size_t)(p - buf);
}
