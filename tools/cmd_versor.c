/* tools/cmd_versor.c: `garotor versor exp|log|apply`, the general algebra of
 * G(4,1) in a pipe (docs/tool.md, docs/versors.md):
 *   exp     a bivector (10 numbers: e12 e13 e14 e15 e23 e24 e25 e34 e35 e45)
 *           -> exp(B) (32 numbers, canonical order)
 *   log     a rotor (32 numbers) -> its principal log (10 numbers)
 *   apply   a versor (32 numbers) then a point x (3 numbers) -> the point
 *           whose embedding is V F(x)^ V^-1 (3 numbers)
 * Everything is computed before anything is written: an error on any line
 * leaves no output. */
#include "cli.h"
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
