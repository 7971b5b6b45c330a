/* tools/mvtext.c: see mvtext.h. */
#include "mvtext.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

int mvt_fields(const tio_texts *t, size_t i, mvt_field *f, int max)
{
    const char *s = t->text[i];
    int n = 0;
    size_t at = 0;
    for (;;) {
        size_t len = strcspn(s + at, ";");
        if (n == max)
            return tio_text_error(t, i, at - 1, "too many fields: at most %d, separated by ';'", max);
        /* without the blanks around it */
        size_t a = at, l = len;
        while (l && (s[a] == ' ' || s[a] == '\t')) a++, l--;
        while (l && (s[a + l - 1] == ' ' || s[a + l - 1] == '\t')) l--;
        f[n++] = (mvt_field){a, l};
        if (s[at + len] == '\0')
            return n;
        at += len + 1;
    }
}

/* Is s[k] ('+' or '-') the sign of an exponent ("2e-3", "1.5E+2"): after an
   'e' or 'E' that follows a digit or a '.'? */
static int exponent_sign(const char *s, size_t k, size_t from)
{
    return k >= from + 2 && (s[k - 1] == 'e' || s[k - 1] == 'E') &&
           ((s[k - 2] >= '0' && s[k - 2] <= '9') || s[k - 2] == '.');
}

int mvt_parse(const tio_texts *t, size_t i, mvt_field f, ga_mv *out)
{
    const char *s = t->text[i] + f.at;
    char *buf = malloc(f.len + 1);
    if (!buf)
        return tio_text_error(t, i, f.at, "out of memory");
    memcpy(buf, s, f.len);
    buf[f.len] = '\0';
    ga_mv x;
    int st = ga_mv_parse(buf, &x);
    if (st == GA_OK) {
        free(buf);
        *out = x;
        return 0;
    }
    /* where it goes wrong: the first term (from a sign to the next sign that
       is not an exponent's) that does not read by itself */
    size_t k = 0, at = 0;
    while (k < f.len && (buf[k] == ' ' || buf[k] == '\t')) k++;
    if (k == f.len) {
        free(buf);
        return tio_text_error(t, i, f.at, "no multivector here (write one as 1 + 2e12 - 0.5e45)");
    }
    for (;;) {
        size_t start = k, end = k + 1;
        while (end < f.len && !((buf[end] == '+' || buf[end] == '-') && !exponent_sign(buf, end, start)))
            end++;
        char save = buf[end];
        buf[end] = '\0';
        int ts = ga_mv_parse(buf + start, &x);
        if (ts != GA_OK) {
            /* the term after its sign */
            at = start;
            if (buf[at] == '+' || buf[at] == '-')
                at++;
            while (at < end && (buf[at] == ' ' || buf[at] == '\t')) at++;
            if (at == end) {
                tio_text_error(t, i, f.at + start, "'%c' with no term after it", buf[start]);
                free(buf);
                return -1;
            }
            size_t tl = end - at;
            while (tl && (buf[at + tl - 1] == ' ' || buf[at + tl - 1] == '\t')) tl--;
            start = at;
            int shown = tl > 40 ? 40 : (int)tl;
            if (ts == GA_ERR_NOTFINITE)
                tio_text_error(t, i, f.at + at, "'%.*s%s': a number beyond the range of a double", shown,
                               buf + start, tl > 40 ? "..." : "");
            else
                tio_text_error(
                    t, i, f.at + at,
                    "'%.*s%s' is not a term of a multivector (a number, a blade name e1 .. e12345 "
                    "in canonical order, or both: 2e12, 2 e12, 2*e12; 'e' then a digit is a blade, "
                    "an exponent is 1e+12 or 1E12)",
                    shown, buf + start, tl > 40 ? "..." : "");
            free(buf);
            return -1;
        }
        buf[end] = save;
        if (end >= f.len)
            break;
        k = end;
    }
    free(buf);
    if (st == GA_ERR_NOTFINITE) /* every term reads alone: terms of one blade whose sum overflows */
        return tio_text_error(t, i, f.at, "not a multivector: its terms add up beyond the range of a double");
    return tio_text_error(t, i, f.at, "not a multivector: %s", ga_status_string(st));
}

int mvt_numbers(const tio_texts *t, size_t i, mvt_field f, size_t from, double *v, int max)
{
    const char *s = t->text[i] + f.at;
    size_t k = from;
    int n = 0, comma = 0;
    for (;;) {
        while (k < f.len && (s[k] == ' ' || s[k] == '\t' || (s[k] == ',' && !comma && n))) {
            if (s[k] == ',')
                comma = 1;
            k++;
        }
        if (k >= f.len) {
            if (comma)
                return tio_text_error(t, i, f.at + k - 1, "empty field after number %d", n);
            return n;
        }
        if (s[k] == ',')
            return tio_text_error(t, i, f.at + k, "empty field %s number %d", n ? "after" : "before",
                                  n ? n : 1);
        comma = 0;
        /* strtod on a copy of the word */
        size_t wl = 0;
        while (k + wl < f.len && !strchr(" \t,", s[k + wl])) wl++;
        char *word = malloc(wl + 1);
        if (!word)
            return tio_text_error(t, i, f.at + k, "out of memory");
        memcpy(word, s + k, wl);
        word[wl] = '\0';
        char *end;
        errno = 0;
        double x = strtod(word, &end);
        size_t bad = (size_t)(end - word);
        int rc = end == word
                   ? tio_text_error(t, i, f.at + k, "'%.*s' is not a number", wl > 40 ? 40 : (int)wl, word)
               : *end         ? tio_text_error(t, i, f.at + k + bad, "junk after number %d", n + 1)
               : !isfinite(x) ? tio_text_error(t, i, f.at + k, "number %d is not finite", n + 1)
                              : 0;
        free(word);
        if (rc)
            return rc;
        if (n < max)
            v[n] = x;
        n++;
        k += wl;
    }
}

size_t mvt_format(ga_mv a, char *buf)
{
    size_t len = 0;
    for (int k = 0; k < 32; k++)
        if (a.c[k] == 0.0)
            a.c[k] = 0.0; /* -0: no term, as 0 */
    return ga_mv_format(a, buf, GA_MV_TEXT_MAX, &len) == GA_OK ? len : 0;
}
