/* tools/timetext.c: see timetext.h. */
#include "timetext.h"

#include <garotor/numtext.h>

#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void canonical(tt_dec *a)
{
    int lead = 0;
    while (lead < a->n && a->d[lead] == 0) lead++;
    if (lead)
        memmove(a->d, a->d + lead, (size_t)(a->n - lead));
    a->n -= lead;
    while (a->n > 0 && a->d[a->n - 1] == 0) {
        a->n--;
        a->exp++;
    }
    if (a->n == 0)
        a->neg = a->exp = 0;
}

/* The exact decimal of text, or -1 if it is not plain decimal within the limits. */
static int parse_decimal(const char *s, tt_dec *a)
{
    a->neg = 0;
    a->n = 0;
    a->exp = 0;
    while (isspace((unsigned char)*s)) s++;
    if (*s == '+' || *s == '-')
        a->neg = *s++ == '-';
    int digits = 0, point = 0, frac = 0;
    for (;; s++) {
        if (*s == '.' && !point) {
            point = 1;
            continue;
        }
        if (!isdigit((unsigned char)*s))
            break;
        digits++;
        if (a->n == 0 && *s == '0') { /* leading zeros carry no digit */
            frac += point;
            continue;
        }
        if (a->n >= TT_DIG)
            return -1;
        a->d[a->n++] = (unsigned char)(*s - '0');
        frac += point;
    }
    if (!digits)
        return -1;
    long e = 0;
    if (*s == 'e' || *s == 'E') {
        s++;
        int eneg = 0;
        if (*s == '+' || *s == '-')
            eneg = *s++ == '-';
        if (!isdigit((unsigned char)*s))
            return -1;
        for (; isdigit((unsigned char)*s); s++)
            if (e < 100000)
                e = e * 10 + (*s - '0');
        if (eneg)
            e = -e;
    }
    if (*s != '\0')
        return -1;
    long exp = e - frac;
    if (exp < -100000 || exp > 100000)
        return -1;
    a->exp = (int)exp;
    canonical(a);
    if (a->n > TT_SIG || (a->n && (a->exp < -TT_LOW || a->exp + a->n > TT_TOP)))
        return -1;
    return 0;
}

void tt_parse(const char *text, tt_dec *out)
{
    if (parse_decimal(text, out) == 0)
        return;
    char buf[64];
    snprintf(buf, sizeof buf, "%.16e", strtod(text, NULL));
    parse_decimal(buf, out); /* a finite double with 17 digits: always within */
}

/* |a| against |b|: -1, 0, 1 */
static int cmp_mag(const tt_dec *a, const tt_dec *b)
{
    if (a->n == 0 || b->n == 0)
        return (a->n != 0) - (b->n != 0);
    int ta = a->exp + a->n, tb = b->exp + b->n;
    if (ta != tb)
        return ta < tb ? -1 : 1;
    for (int i = 0; i < a->n || i < b->n; i++) {
        int x = i < a->n ? a->d[i] : 0, y = i < b->n ? b->d[i] : 0;
        if (x != y)
            return x < y ? -1 : 1;
    }
    return 0;
}

/* digit of a at the place 10^p */
static int digit_at(const tt_dec *a, int p)
{
    int i = a->exp + a->n - 1 - p;
    return i >= 0 && i < a->n ? a->d[i] : 0;
}

int tt_add(const tt_dec *a, const tt_dec *b, int sub, tt_dec *out)
{
    int bneg = b->n ? b->neg ^ sub : 0;
    if (a->n == 0 || b->n == 0) {
        const tt_dec *x = a->n ? a : b;
        if (x != out)
            memcpy(out, x, sizeof *out);
        if (x == b)
            out->neg = bneg;
        return 0;
    }
    int lo = a->exp < b->exp ? a->exp : b->exp;
    int ta = a->exp + a->n, tb = b->exp + b->n, hi = (ta > tb ? ta : tb) + 1;
    int len = hi - lo;
    if (len > TT_DIG)
        return -1;
    unsigned char r[TT_DIG];
    int neg;
    if (a->neg == bneg) {
        int carry = 0;
        for (int p = lo; p < hi; p++) {
            int s = digit_at(a, p) + digit_at(b, p) + carry;
            r[p - lo] = (unsigned char)(s % 10);
            carry = s / 10;
        }
        neg = a->neg;
    } else {
        int c = cmp_mag(a, b);
        const tt_dec *big = c >= 0 ? a : b, *small = c >= 0 ? b : a;
        neg = c >= 0 ? a->neg : bneg;
        int borrow = 0;
        for (int p = lo; p < hi; p++) {
            int s = digit_at(big, p) - digit_at(small, p) - borrow;
            borrow = s < 0;
            r[p - lo] = (unsigned char)(s + 10 * borrow);
        }
    }
    out->neg = neg;
    out->n = len;
    out->exp = lo;
    for (int i = 0; i < len; i++) out->d[i] = r[len - 1 - i];
    canonical(out);
    return 0;
}

double tt_to_double(const tt_dec *a, int shift)
{
    if (a->n == 0)
        return 0.0;
    char buf[TT_DIG + 32];
    int k = 0;
    if (a->neg)
        buf[k++] = '-';
    for (int i = 0; i < a->n; i++) buf[k++] = (char)('0' + a->d[i]);
    snprintf(buf + k, sizeof buf - (size_t)k, "e%d", a->exp + shift);
    return strtod(buf, NULL);
}

void tt_shortest(double x, tt_dec *out)
{
    uint64_t f;
    int e, n = ga_double_shortest(x, &f, &e);
    out->neg = f != 0 && x < 0.0;
    out->n = f ? n : 0;
    out->exp = f ? e : 0;
    for (int i = n - 1; f && i >= 0; i--, f /= 10) out->d[i] = (unsigned char)(f % 10);
}

int tt_is_integer(const tt_dec *a) { return a->n == 0 || a->exp >= 0; }

void tt_format(const tt_dec *a, char *buf)
{
    char dig[TT_DIG];
    for (int i = 0; i < a->n; i++) dig[i] = (char)('0' + a->d[i]);
    ga_decimal_format(a->neg, dig, a->n, a->exp, buf);
}
