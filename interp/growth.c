/* interp/growth.c: the growth rule of path.h (docs/schemes.md, "lihao2:
 * growth"): each key's velocity against the fastest chord of the path, the
 * chords taken over spans of at least 1/16 of the mean key spacing, so that a
 * near-duplicate key (its chord the noise of the keys over a tiny gap) does
 * not set the bound.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <garotor/path.h>

#include "internal/path.h"

/* A chord spans at least this fraction of the mean key spacing (path.h). */
#define GIP_GROWTH_SPAN (1.0 / 16.0)

/* The Euclidean norms of the parts of x: rotation and translation on the
 * rigid groups, the whole element on affine; returns the number of parts. */
static size_t part_norms(const ga_group *g, const double *x, double *nrm)
{
    size_t parts = g->rigid ? 2 : 1, w = g->dim / parts;
    for (size_t q = 0; q < parts; ++q) {
        double s = 0.0;
        for (size_t k = 0; k < w; ++k) s = hypot(s, x[q * w + k]);
        nrm[q] = s;
    }
    return parts;
}

ga_status ga_path_measure_growth(const ga_path *p, ga_path_growth *out)
{
    if (!p || !out)
        return GA_ERR_ARG;
    const ga_group *g = p->group;
    size_t n = p->n, parts = 1;
    ga_path_growth r = {0.0, 0, n};
    double chord[2] = {0.0, 0.0}, x[GIP_MAXD], rel[GIP_MAXE], nrm[2];
    int st;
    /* the chords over spans of at least GIP_GROWTH_SPAN of the mean spacing:
       from key j to the first key e >= j + 1 that far on (or the last) */
    double span = n > 1 ? GIP_GROWTH_SPAN * (p->t[n - 1] - p->t[0]) / (double)(n - 1) : 0.0;
    for (size_t j = 0, e = 1; j + 1 < n; ++j) {
        if (e < j + 1)
            e = j + 1;
        while (e + 1 < n && p->t[e] - p->t[j] < span) ++e;
        if ((st = gip_rel_log(g, gip_key_of(p, j), gip_key_of(p, e), x, rel)))
            return st;
        parts = part_norms(g, x, nrm);
        for (size_t q = 0; q < parts; ++q) chord[q] = fmax(chord[q], nrm[q] / (p->t[e] - p->t[j]));
    }
    for (size_t i = 0; n > 1 && i < n; ++i) {
        /* BSPLINE's range is [t_1, t_{n-2}], its segment s [t_{s+1}, t_{s+2}]:
           its keys 1 .. n-2, by the velocity at their times */
        if (p->scheme == GA_SCHEME_BSPLINE && (i == 0 || i + 1 == n))
            continue;
        st = p->scheme == GA_SCHEME_BSPLINE
               ? ga_path_velocity(p, p->t[i], x)
               : ga_path_velocity_segment(p, i + 1 < n ? i : n - 2, i + 1 < n ? 0.0 : 1.0, x);
        if (st)
            return st;
        part_norms(g, x, nrm);
        double ratio = 0.0;
        for (size_t q = 0; q < parts; ++q)
            if (chord[q] > 0.0)
                ratio = fmax(ratio, nrm[q] / chord[q]);
        if (ratio > r.ratio) {
            r.ratio = ratio;
            r.key = i;
        }
        if (r.first == n && ratio > GA_PATH_GROWTH_MAX)
            r.first = i;
    }
    *out = r;
    return GA_OK;
}

/* x in dig significant digits as "%.*g" writes it under the C locale, made
 * from "%.*e"'s digits and exponent so that no locale's decimal point gets
 * in (buf: 32 bytes); returns its value, read back from the digits. */
static double g_digits(double x, int dig, char *buf)
{
    char e[48], d[24];
    snprintf(e, sizeof e, "%.*e", dig - 1, x);
    int n = 0;
    const char *c = e;
    for (; *c && *c != 'e'; c++)
        if (*c >= '0' && *c <= '9' && n < 20)
            d[n++] = *c;
    int ex = *c == 'e' ? (int)strtol(c + 1, NULL, 10) : 0;
    char r[48];
    snprintf(r, sizeof r, "%.*sE%d", n, d, ex - (n - 1)); /* no decimal point: any locale */
    double v = strtod(r, NULL);
    while (n > 1 && d[n - 1] == '0') n--; /* %g drops trailing zeros */
    char *o = buf;
    if (ex < -4 || ex >= dig) {
        *o++ = d[0];
        if (n > 1) {
            *o++ = '.';
            memcpy(o, d + 1, (size_t)n - 1);
            o += n - 1;
        }
        snprintf(o, 16, "e%c%02d", ex < 0 ? '-' : '+', ex < 0 ? -ex : ex);
        return v;
    }
    if (ex < 0) {
        *o++ = '0';
        *o++ = '.';
        for (int k = -1; k > ex; k--) *o++ = '0';
        memcpy(o, d, (size_t)n);
        o += n;
    } else {
        for (int k = 0; k <= ex; k++) *o++ = k < n ? d[k] : '0';
        if (n > ex + 1) {
            *o++ = '.';
            memcpy(o, d + ex + 1, (size_t)(n - ex - 1));
            o += n - ex - 1;
        }
    }
    *o = '\0';
    return v;
}

ga_status ga_path_growth_describe(const ga_path *p, const ga_path_growth *gr, ga_path_growth_words *out)
{
    if (!p || !gr || !out || gr->first >= p->n || isnan(gr->ratio))
        return GA_ERR_ARG;
    ga_path_growth_words w;
    w.a = gr->first ? gr->first - 1 : 0;
    w.b = gr->first ? gr->first : 1;
    /* 3 digits, or as many as show it past the bound (3.0004, not 3); an
       infinite ratio (a velocity over chords that underflow to subnormals)
       as %g writes it, "inf", in any locale */
    if (isinf(gr->ratio))
        snprintf(w.ratio, sizeof w.ratio, "%g", gr->ratio);
    else
        for (int dig = 3; dig <= 17; dig++)
            if (g_digits(gr->ratio, dig, w.ratio) > GA_PATH_GROWTH_MAX)
                break;
    /* lihao2 carries its velocity along; any other scheme breaks the rule
       through keys much closer than the others (near-duplicates) */
    w.advice = p->scheme == GA_SCHEME_LIHAO2 ? "--scheme lihao3 or c2 follow the chords"
                                             : "keys much closer together than the others (near-duplicates?) "
                                               "make any scheme fast there";
    *out = w;
    return GA_OK;
}
