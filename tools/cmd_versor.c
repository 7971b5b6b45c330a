/* tools/cmd_versor.c: `garotor versor exp|log|apply`, the general algebra of
 * G(4,1) in a pipe (docs/tool.md, docs/versors.md):
 *   exp     a bivector (10 numbers: e12 e13 e14 e15 e23 e24 e25 e34 e35 e45)
 *           -> exp(B) (32 numbers, canonical order)
 *   log     a rotor (32 numbers) -> its principal log (10 numbers)
 *   apply   a versor (32 numbers) then a point x (3 numbers) -> the point
 *           whose embedding is V F(x)^ V^-1 (3 numbers)
 * With --text each multivector is written with blade names, in and out
 * (`0.5e45`, docs/conventions.md), and apply reads "V; x y z".
 * Everything is computed before anything is written: an error on any line
 * leaves no output. */
#include "cli.h"
#include "mvtext.h"
#include "textio.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <garotor/garotor.h>

enum { VERB_EXP, VERB_LOG, VERB_APPLY };

static int one(int verb, const double *v, double *r, const tio_items *in, size_t i)
{
    ga_mv X = ga_mv_zero();
    int st;
    switch (verb) {
    case VERB_EXP:
        memcpy(X.c + GA_BLADE_E12, v, 10 * sizeof *v);
        X = ga_mv_exp(X);
        if (!ga_mv_isfinite(X)) /* a hyperbolic part too large: cosh overflows */
            return tio_error(in, i, "%s", ga_status_string(GA_ERR_DOMAIN));
        memcpy(r, X.c, 32 * sizeof *r);
        return 0;
    case VERB_LOG:
        memcpy(X.c, v, 32 * sizeof *v);
        st = ga_mv_log(X, &X);
        if (st == GA_ERR_DOMAIN)
            return tio_error(in, i, "no real logarithm: not a rotor (an even versor with R ~R = 1) to 1e-9");
        if (st != GA_OK)
            return tio_error(in, i, "%s", ga_status_string(st));
        memcpy(r, X.c + GA_BLADE_E12, 10 * sizeof *r);
        return 0;
    default: {
        ga_mv Y;
        ga_vec3 x = {v[32], v[33], v[34]};
        memcpy(X.c, v, 32 * sizeof *v);
        st = ga_versor_apply(X, ga_point_up(x), &Y);
        if (st == GA_ERR_ARG)
            return tio_error(in, i, "not a versor: it has both even and odd parts");
        if (st != GA_OK)
            return tio_error(in, i, "not a versor: %s", ga_status_string(st));
        st = ga_point_down(Y, &x);
        if (st != GA_OK)
            return tio_error(in, i, "the point goes to infinity (or V is not a versor): %s",
                             ga_status_string(st));
        r[0] = x.x, r[1] = x.y, r[2] = x.z;
        return 0;
    }
    }
}

/* --text: one line of t, in the verb's form, into r (32 coefficients, or
   the point in r[0..3) for apply) */
static int one_text(int verb, const tio_texts *t, size_t i, double *r)
{
    mvt_field f[2];
    int nf = mvt_fields(t, i, f, verb == VERB_APPLY ? 2 : 1);
    if (nf < 0)
        return -1;
    if (verb == VERB_APPLY && nf != 2)
        return tio_text_error(t, i, f[0].len, "expected a versor, ';', then a point (x y z): 'e4; 2 0 0'");
    ga_mv X;
    if (mvt_parse(t, i, f[0], &X))
        return -1;
    if (verb == VERB_EXP) {
        for (int k = 0; k < 32; k++)
            if (X.c[k] != 0.0 && !(k >= GA_BLADE_E12 && k <= GA_BLADE_E45))
                return tio_text_error(t, i, f[0].at, "not a bivector: it has a part of grade %d",
                                      k == 0              ? 0
                                      : k < GA_BLADE_E12  ? 1
                                      : k < GA_BLADE_E123 ? 3
                                      : k < 31            ? 4
                                                          : 5);
        X = ga_mv_exp(X);
        if (!ga_mv_isfinite(X))
            return tio_text_error(t, i, f[0].at, "%s", ga_status_string(GA_ERR_DOMAIN));
        memcpy(r, X.c, 32 * sizeof *r);
        return 0;
    }
    if (verb == VERB_LOG) {
        ga_mv B;
        int st = ga_mv_log(X, &B);
        if (st == GA_ERR_DOMAIN)
            return tio_text_error(t, i, f[0].at,
                                  "no real logarithm: not a rotor (an even versor with R ~R = 1) to 1e-9");
        if (st != GA_OK)
            return tio_text_error(t, i, f[0].at, "%s", ga_status_string(st));
        memcpy(r, B.c, 32 * sizeof *r);
        return 0;
    }
    double p[3];
    int m = mvt_numbers(t, i, f[1], 0, p, 3);
    if (m < 0)
        return -1;
    if (m != 3)
        return tio_text_error(t, i, f[1].at, "expected 3 numbers (a point x y z) after ';', found %d", m);
    ga_mv Y;
    ga_vec3 x = {p[0], p[1], p[2]};
    int st = ga_versor_apply(X, ga_point_up(x), &Y);
    if (st == GA_ERR_ARG)
        return tio_text_error(t, i, f[0].at, "not a versor: it has both even and odd parts");
    if (st != GA_OK)
        return tio_text_error(t, i, f[0].at, "not a versor: %s", ga_status_string(st));
    if ((st = ga_point_down(Y, &x)) != GA_OK)
        return tio_text_error(t, i, f[0].at, "the point goes to infinity (or V is not a versor): %s",
                              ga_status_string(st));
    r[0] = x.x, r[1] = x.y, r[2] = x.z;
    return 0;
}

/* versor --text: every line read and computed, then written */
static int versor_text(int verb, const cli_opts *o)
{
    tio_texts t;
    tio_read_opts ro = cli_input(o);
    if (tio_read_text(o->in, &ro, &t))
        return 2;
    double *res = malloc((t.n ? t.n : 1) * 32 * sizeof *res);
    int ok = res != NULL;
    if (!ok)
        fprintf(stderr, "garotor versor: out of memory\n");
    for (size_t i = 0; i < t.n && ok; i++) ok = !one_text(verb, &t, i, res + 32 * i);
    tio_out out;
    if (ok && tio_out_open(&out, o->out) == 0) {
        char buf[GA_MV_TEXT_MAX];
        for (size_t i = 0; i < t.n; i++) {
            if (verb == VERB_APPLY) {
                tio_out_line(&out, res + 32 * i, 3);
                continue;
            }
            ga_mv X;
            memcpy(X.c, res + 32 * i, sizeof X.c);
            tio_out_text(&out, buf, mvt_format(X, buf));
        }
        ok = tio_out_close(&out, 1) == 0;
    } else
        ok = 0;
    free(res);
    tio_texts_free(&t);
    return ok ? 0 : 2;
}

int cmd_versor(const cli_opts *o)
{
    static const char *const verbs[] = {"exp", "log", "apply"};
    static const int nin[] = {10, 32, 35}, nout[] = {32, 10, 3};
    static const char *const what[] = {"a bivector: e12 e13 e14 e15 e23 e24 e25 e34 e35 e45",
                                       "a rotor: 32 coefficients in canonical order",
                                       "a versor (32 coefficients) then a point (3)"};
    int verb = 0;
    if (!o->verb) {
        fprintf(stderr,
                "garotor versor: which one: exp, log or apply?\n(garotor versor --help shows the options)\n");
        return 2;
    }
    while (verb < 3 && strcmp(o->verb, verbs[verb]) != 0) verb++;
    if (verb == 3) {
        fprintf(
            stderr,
            "garotor versor: unknown operation '%s' (exp, log or apply)\n(garotor versor --help shows the "
            "options)\n",
            o->verb);
        return 2;
    }
    if (o->text)
        return versor_text(verb, o);
    tio_items in;
    tio_read_opts ro = cli_input(o);
    if (tio_read(o->in, &ro, &in))
        return 2;
    int ok = 1;
    for (size_t i = 0; i < in.n && ok; i++)
        if (in.item[i].count != nin[verb])
            ok = !tio_error(&in, i, "expected %d numbers (%s), found %d", nin[verb], what[verb],
                            in.item[i].count);
    double *res = ok ? malloc((in.n ? in.n : 1) * (size_t)nout[verb] * sizeof *res) : NULL;
    if (ok && !res) {
        fprintf(stderr, "garotor versor: out of memory\n");
        ok = 0;
    }
    for (size_t i = 0; i < in.n && ok; i++)
        ok = !one(verb, in.value + in.item[i].first, res + i * (size_t)nout[verb], &in, i);
    ok = ok && tio_write_rows(o->out, res, in.n, nout[verb]) == 0;
    free(res);
    tio_free(&in);
    return ok ? 0 : 2;
}
