/* tools/interp_times.c: the times of `garotor interp` (docs/tool.md, "Times"):
 * key and given times relative to the first key's, exactly (timetext.h); the
 * sample times of --samples, --rate, --at and --times (ic_sampler), with
 * --time-unit ns in whole nanoseconds; and the stamp each sample is written
 * with. */
#include "interp_cmd.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include <garotor/numtext.h>

double ic_rel_time(const ic_timebase *tb, const char *text)
{
    tt_dec t;
    tt_parse(text, &t);
    if (tt_add(&t, &tb->ref, 1, &t)) /* cannot happen (timetext.h) */
        return (strtod(text, NULL) - tt_to_double(&tb->ref, 0)) * (tb->ns ? 1e-9 : 1.0);
    return tt_to_double(&t, tb->ns ? -9 : 0);
}

int ic_whole(const char *text)
{
    tt_dec t;
    tt_parse(text, &t);
    return tt_is_integer(&t);
}

/* --rate HZ as P x 10^q, P a whole number below 2^53 (15 digits): 1, or 0
 * if HZ has more digits. */
static int rate_parts(const char *text, uint64_t *p, int *q)
{
    tt_dec h;
    tt_parse(text, &h);
    if (h.n == 0 || h.n > 15)
        return 0;
    uint64_t v = 0;
    for (int i = 0; i < h.n; i++) v = v * 10 + h.d[i];
    *p = v;
    *q = h.exp;
    return 1;
}

/* k/HZ in seconds, correctly rounded where k and the digits of HZ allow one
 * exact division (numerator and denominator whole numbers below 2^53). */
static double rate_seconds(uint64_t k, int exact, uint64_t p, int q, double hz)
{
    const double two53 = 9007199254740992.0;
    if (exact) {
        double num = (double)k, den = (double)p;
        for (int e = q; e > 0 && den < two53; e--) den *= 10.0;
        for (int e = q; e < 0 && num < two53; e++) num *= 10.0;
        if (num < two53 && den < two53)
            return num / den;
    }
    return (double)k / hz;
}

/* round(k 10^9 / HZ), whole nanoseconds, in exact integer arithmetic where
 * it fits in 64 bits (ties away from zero). */
static double rate_nanoseconds(uint64_t k, int exact, uint64_t p, int q, double hz)
{
    if (exact) {
        uint64_t num = k, den = p;
        int ok = 1;
        for (int e = 9 - q; e > 0 && ok; e--) ok = num <= UINT64_MAX / 20 ? (num *= 10, 1) : 0;
        for (int e = 9 - q; e < 0 && ok; e++) ok = den <= UINT64_MAX / 20 ? (den *= 10, 1) : 0;
        if (ok)
            return (double)((num + den / 2) / den);
    }
    return floor((double)k * (1e9 / hz) + 0.5);
}

/* t0 + off, off whole nanoseconds, in seconds relative to the first key. */
static double ns_seconds(double off)
{
    char b[400];
    snprintf(b, sizeof b, "%.0f", off);
    tt_dec d;
    tt_parse(b, &d);
    return tt_to_double(&d, -9);
}

/* --rate HZ: t0 + k/HZ, each from k, those in the range [t_i0, t_i1]. */
static int plan_rate(const ic_input *in, ic_sampler *smp)
{
    const cli_opts *o = smp->o;
    double span = in->times[in->n - 1] * o->rate;
    if (!(span < 1e9)) {
        fprintf(stderr, "garotor interp: --rate %.17g gives more than 1e9 samples\n", o->rate);
        return -1;
    }
    smp->kind = IC_RATE;
    smp->ns = (size_t)floor(span) + 2;
    smp->rexact = rate_parts(o->rate_text, &smp->rp, &smp->rq);
    double t, off;
    while (ic_sample_time(smp, 0, &t, &off) && t < in->times[in->i0]) { /* bspline: its range starts at t_1 */
        smp->k0++;
        smp->ns--;
    }
    if (!ic_sample_time(smp, 0, &t, &off)) {
        fprintf(stderr, "garotor interp: --rate %s: no sample time in the path's range [%s, %s]\n",
                o->rate_text, in->in.first[in->i0], in->in.first[in->i1]);
        return -1;
    }
    return 0;
}

int ic_plan(const ic_opts *io, const ic_timebase *tb, const ic_input *in, ic_sampler *smp)
{
    const cli_opts *o = io->o;
    size_t i0 = in->i0, i1 = in->i1;
    *smp = (ic_sampler){.o = o,
                        .g = io->g,
                        .in = &in->in,
                        .tb = tb,
                        .ev = io->ev,
                        .step = io->ev == GA_EVAL_EULER ? o->step : 1.0,
                        .extrap = io->extrap,
                        .pose = io->pose,
                        .with_v = io->with_v,
                        .with_a = io->with_a,
                        .with_j = io->with_j,
                        .frame = io->frame,
                        .out_fmt = io->out_fmt,
                        .wxyz = io->wxyz,
                        .vw = io->vw,
                        .times = in->times,
                        .n = in->n,
                        .i0 = i0,
                        .i1 = i1,
                        .kind = IC_UNIFORM,
                        .ns = (size_t)o->samples};
    if ((o->given & OPT_RATE) && plan_rate(in, smp))
        return -1;
    if (tb->ns && (o->given & OPT_SAMPLES)) {
        /* whole nanoseconds: t_i0 + round(k span/(N - 1)), span = t_i1 - t_i0 */
        tt_dec span, start;
        tt_parse(in->in.first[i1], &span);
        tt_parse(in->in.first[i0], &start);
        if (tt_add(&span, &tb->ref, 1, &span) || tt_add(&start, &tb->ref, 1, &start)) /* cannot happen */
            return ic_oom();
        smp->kind = IC_NS_SAMPLES;
        smp->s0 = tt_to_double(&start, 0); /* whole ns below 2^53 */
        smp->sp = tt_to_double(&span, 0) - smp->s0;
    }
    if (in->at_text) {
        smp->kind = IC_GIVEN;
        smp->ns = in->nat;
        smp->at = in->at;
        smp->at_text = in->at_text;
    }
    for (size_t k = 0; k < in->nat && !io->extrap && !io->clip && in->at_text; k++)
        if (!(in->at[k] >= in->times[i0] && in->at[k] <= in->times[i1])) {
            fprintf(stderr,
                    "garotor interp: %s time %s is outside the %s range [%s, %s] (see "
                    "--extrapolate)\n",
                    o->times ? "--times" : "--at", in->at_text[k], i0 ? "B-spline's" : "keys'",
                    in->in.first[i0], in->in.first[i1]);
            return -1;
        }
    return 0;
}

int ic_sample_time(const ic_sampler *s, size_t k, double *t, double *off)
{
    double first = s->times[s->i0], last = s->times[s->i1];
    *off = 0.0;
    if (k >= s->ns)
        return 0;
    switch (s->kind) {
    case IC_UNIFORM: /* ga_path_sample_uniform's t0 + k dt, the last exactly t1 */
        *t = k + 1 == s->ns ? last
                            : first + (double)k * (s->ns > 1 ? (last - first) / (double)(s->ns - 1) : 0.0);
        return 1;
    case IC_GIVEN: *t = s->at[k]; return 1;
    case IC_RATE: /* t_0 + k/HZ, each from k, those in the range (from k0 on, while <= its end) */
        k += s->k0;
        if (s->tb->ns) {
            *off = rate_nanoseconds(k, s->rexact, s->rp, s->rq, s->o->rate);
            *t = ns_seconds(*off);
        } else
            *t = rate_seconds(k, s->rexact, s->rp, s->rq, s->o->rate);
        return *t <= last;
    case IC_NS_SAMPLES: /* whole nanoseconds: t_i0 + round(k span/(N - 1)), span = t_i1 - t_i0 */
        *off = s->s0 + (k + 1 == s->ns ? s->sp : floor((double)k * s->sp / (double)(s->ns - 1) + 0.5));
        *t = k + 1 == s->ns ? last : ns_seconds(*off);
        return 1;
    }
    return 0;
}

/* The key whose (relative) time is t, if any: 1 and *key, else 0. */
static int key_at(const double *times, size_t n, double t, size_t *key)
{
    size_t lo = 0, hi = n;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (times[mid] < t)
            lo = mid + 1;
        else
            hi = mid;
    }
    if (lo < n && times[lo] == t) {
        *key = lo;
        return 1;
    }
    return 0;
}

/* The stamp of a computed sample: the reference plus the shortest decimal
 * that reads back as its relative time rel (seconds), or plus its whole
 * nanoseconds off (--time-unit ns). */
static void computed_stamp(const ic_timebase *tb, double rel, double off, char *buf)
{
    tt_dec o;
    if (tb->ns) {
        char b[400];
        snprintf(b, sizeof b, "%.0f", off);
        tt_parse(b, &o);
    } else
        tt_shortest(rel, &o);
    if (tt_add(&tb->ref, &o, 0, &o)) /* cannot happen (timetext.h) */
        ga_double_format(tt_to_double(&tb->ref, 0) + (tb->ns ? off : rel), buf);
    else
        tt_format(&o, buf);
}

/* A key's time as the key was written; a given one as given; a computed one
 * from the reference. */
const char *ic_stamp(const ic_sampler *s, size_t k, double t, double off, char *buf)
{
    size_t key;
    if (key_at(s->times, s->n, t, &key))
        return s->in->first[key];
    if (s->kind == IC_GIVEN)
        return s->at_text[k];
    if (s->tb->ref.n == 0 && !s->tb->ns) /* the reference is 0: t itself */
        ga_double_format(t == 0.0 ? 0.0 : t, buf);
    else
        computed_stamp(s->tb, t, off, buf);
    return buf;
}
