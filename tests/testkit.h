/* tests/testkit.h: what every test shares: the seeded PRNG, the input
 * families, and the reporting of checks.
 *
 * Header-only (static functions), so each test stays one file plus this.
 *
 * Reporting: every check prints one line,
 *   ok   name                                     n=12345   worst 1.234e-15  tol 7.1e-15
 *   FAIL ...
 * and counts a failure if its measured worst is above its tolerance (a NaN
 * counts as infinite). The kinds of check:
 *   - errors against one tolerance: tk_begin(name, tol), tk_add(&c, err);
 *   - errors against a tolerance of their own (derived per case from what is
 *     computed): tk_add_tol(&c, err, tol); the line shows the case nearest its
 *     tolerance (its error and its tolerance) and the ratio err/tol;
 *   - a lower bound, for an error that must be there (a formula of a paper
 *     known to be wrong): tk_begin_least(name, bound), tk_add(&c, value); the
 *     line shows the least value;
 *   - statuses (tk_add_status(&c, got, want)) and conditions
 *     (tk_add_bool(&c, cond)), counted; tk_expect and tk_expect_status are the
 *     one-case forms.
 * tk_end(&c) prints the line. A check met in many places can be named
 * instead: tk_get(name) opens it at its first use and tk_end_named() ends
 * every named check opened since the last call, in order of first use.
 * tk_finish(test) prints the summary and gives the exit status.
 *
 * Sections: a test is a table of named sections, {name, function, flags},
 * run in order by tk_main(argc, argv, test, table, count), or by
 * tk_main_arg(..., setup) for a test with an argument of its own, which
 * takes the test's options:
 *   --list        print the section names, one a line, and exit;
 *   --only NAME   run only the section NAME, or, where NAME names no
 *                 section, every section printing only the checks whose
 *                 name contains NAME (none: an error listing the sections);
 *                 repeatable, the union is run;
 *   ARG           tk_main_arg: the test's one plain argument (a scale, as
 *                 `test_rotor 100`, a seed, -v), given to setup(ARG) before
 *                 the sections run (setup(NULL) without one).
 * Without options every section runs and prints what it always printed.
 * A section flagged TK_SETUP always runs (it prepares what the others use).
 * One flagged TK_STREAM draws from a generator later sections share: left
 * out before a section that runs, it still runs, silently (no line, no
 * failure), so that the section run alone sees the very inputs it sees in
 * the whole test. tk_note prints a section's own lines (headers, counts),
 * silenced with its checks.
 *
 * A check that fails as a known, reported bug is marked tk_xfail(&c, why):
 * its line reads XFAIL, with why, and fails nothing; once the bug is gone it
 * reads XPASS and fails the test, so that the mark is taken off.
 */
#ifndef GAROTOR_TESTKIT_H
#define GAROTOR_TESTKIT_H

#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <garotor/garotor.h>

#define TK_PI 3.14159265358979323846

/* ---- splitmix64: the same sequence on every machine and compiler -------- */
typedef struct {
    uint64_t s;
} tk_rng;

static inline uint64_t tk_next(tk_rng *r)
{
    uint64_t z = (r->s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}
/** The stream seeded `seed` after n draws: splitmix64's state moves by the
 *  same constant every draw, so a test can start a section where the draws
 *  before it left the stream without making them. */
static inline tk_rng tk_rng_after(uint64_t seed, uint64_t n)
{
    return (tk_rng){seed + n * 0x9E3779B97F4A7C15ull};
}
/* ---- the seed sweep ------------------------------------------------------------
 * A test seeds its streams with fixed numbers, so that every run is the same.
 * The environment variable GAROTOR_TEST_SEED=N (N >= 1; unset, empty or 0:
 * the fixed seeds) moves every stream a test seeds through tk_seed to another
 * one, the same for every def and N on every machine, so that a sweep over N
 * (tests/seed_sweep.sh, the soak suite's object-seeds) tries other inputs
 * and any failure it finds reproduces with its N. tk_finish names N where it
 * is set. */
static inline uint64_t tk_seed_n(void)
{
    const char *s = getenv("GAROTOR_TEST_SEED");
    return s && *s ? strtoull(s, NULL, 0) : 0;
}
/** The seed def, or, under GAROTOR_TEST_SEED=N, def moved by a mix of N
 *  (distinct defs stay distinct). */
static inline uint64_t tk_seed(uint64_t def)
{
    uint64_t n = tk_seed_n();
    if (n == 0)
        return def;
    tk_rng m = {n};
    return def ^ tk_next(&m);
}

/** Uniform in [0, 1). */
static inline double tk_uni(tk_rng *r) { return (double)(tk_next(r) >> 11) * 0x1p-53; }
/** Uniform in [lo, hi). */
static inline double tk_range(tk_rng *r, double lo, double hi) { return lo + (hi - lo) * tk_uni(r); }
/** Log-uniform in [lo, hi). */
static inline double tk_loguni(tk_rng *r, double lo, double hi) { return exp(tk_range(r, log(lo), log(hi))); }
/** A uniformly distributed unit vector (one draw per statement: C leaves the
 *  order of evaluation of arguments and initializers unspecified). */
static inline ga_vec3 tk_unit(tk_rng *r)
{
    for (;;) {
        ga_vec3 u;
        u.x = tk_range(r, -1, 1);
        u.y = tk_range(r, -1, 1);
        u.z = tk_range(r, -1, 1);
        double n = sqrt(u.x * u.x + u.y * u.y + u.z * u.z);
        if (n > 0.1 && n <= 1.0)
            return (ga_vec3){u.x / n, u.y / n, u.z / n};
    }
}
static inline ga_vec3 tk_scale(ga_vec3 u, double k) { return (ga_vec3){k * u.x, k * u.y, k * u.z}; }
/** max(a, b) keeping a NaN, where fmax drops it: for error measures, so that
 *  a NaN anywhere fails its check. */
static inline double tk_max(double a, double b) { return a > b || isnan(a) ? a : b; }
/** The largest |coefficient| of a multivector, NaN if one is NaN
 *  (ga_mv_maxabs skips NaN, being built on fmax). */
static inline double tk_mv_maxabs(ga_mv a)
{
    double m = 0.0;
    for (int i = 0; i < 32; i++) m = tk_max(m, fabs(a.c[i]));
    return m;
}
static inline double tk_norm(ga_vec3 u) { return sqrt(u.x * u.x + u.y * u.y + u.z * u.z); }

/* ---- the input families -------------------------------------------------------
 * One list. The twist families (below TK_TWIST_FAMILIES) give twists
 * xi = (w, v), rotation angle |w|, through tk_twist; the matrix families give
 * 4x4 algebra elements (last row zero) that are not twists: scalings and
 * shears, for groups whose algebra holds them (the affine group). tk_algebra
 * gives any family as a 4x4 (a twist as its hat). Where a family draws "v 0 or
 * U(0,2)" half of its twists are pure rotations.
 *
 * Rotors have one family more, built on a twist family: TK_SCREW's rotors with
 * every coefficient moved by ~1e-12 (tk_drift), rotors just off the group. */
enum {
    TK_IDENTITY,           /* the zero twist */
    TK_NEAR_IDENTITY,      /* |w| and |v| each 0 or 1e-300..1e-12 */
    TK_TRANSLATION,        /* w = 0, |v| 1e-12..1e6 */
    TK_ROT_TINY,           /* |w| 1e-12 or 1e-8, v 0 or U(0,2) */
    TK_ROT_SMALL,          /* |w| 1e-4, v 0 or U(0,2) */
    TK_ROT_SPREAD,         /* |w| 1e-6..1, |v| 1e-3..1e6 */
    TK_ROT_QUARTER,        /* |w| pi/2, v 0 or U(0,2) */
    TK_ROT_NEAR_PI,        /* |w| pi - 1e-9, v 0 or U(0,2) */
    TK_ROT_NEAR_PI_SPREAD, /* |w| pi - 1e-12..1e-1 (a fifth: pi - 1e-9), |v| 1e-3..1e6 */
    TK_ROT_PI,             /* |w| pi; 3 in 10 about a coordinate axis; v 0, U(0,2) or 1e-3..1e6 */
    TK_TINY_UNDER_LARGE,   /* |w| 1e-12..1e-6, |v| 1..1e6 */
    TK_SCREW,              /* |w| U(0, pi), |v| 1e-3..1e3 */
    TK_BEYOND_PI,          /* |w| U(pi, 3 pi), |v| 1e-3..1e6 */
    TK_TWIST_FAMILIES,
    TK_SCALING = TK_TWIST_FAMILIES, /* [diag(d), b], d U(-3,3), |b| 1e-3..1e3 */
    TK_SHEAR,                       /* [N, b], N strictly upper U(-2,2), |b| 1e-3..1e3 */
    TK_AFFINE,                      /* [A, b], A U(-1,1) entrywise, b U(-10,10) */
    TK_FAMILIES
};
static const char *const tk_family_name[TK_FAMILIES] = {
    "identity",
    "near identity: |w|, |v| 0 or 1e-300..1e-12",
    "pure translations 1e-12..1e6",
    "rotations 1e-12 and 1e-8 rad",
    "rotations 1e-4 rad",
    "rotations 1e-6..1 rad, translations 1e-3..1e6",
    "rotations pi/2",
    "rotations pi - 1e-9",
    "rotations pi - 1e-12..1e-1, translations 1e-3..1e6",
    "rotations pi (half turns)",
    "tiny rotations 1e-12..1e-6 under translations 1..1e6",
    "general screws (angle < pi, |v| 1e-3..1e3)",
    "rotations pi..3pi (beyond a half turn)",
    "scalings e^-3..e^3 with translations",
    "shears (nilpotent) with translations",
    "general 3x4: entries U(-1,1), translations U(-10,10)"};

/** A random twist of twist family f (f < TK_TWIST_FAMILIES); its rotation
 *  angle is |w|. */
static inline ga_twist tk_twist(tk_rng *r, int f)
{
    ga_vec3 u = tk_unit(r), d = tk_unit(r);
    double angle = 0, v = 0;
    switch (f) {
    case TK_IDENTITY: break;
    case TK_NEAR_IDENTITY:
        if (tk_uni(r) < 0.5)
            v = tk_loguni(r, 1e-300, 1e-12);
        if (tk_uni(r) < 0.5)
            angle = tk_loguni(r, 1e-300, 1e-12);
        break;
    case TK_TRANSLATION: v = tk_loguni(r, 1e-12, 1e6); break;
    case TK_ROT_TINY:
        angle = tk_uni(r) < 0.5 ? 1e-12 : 1e-8;
        v = tk_uni(r) < 0.5 ? 0 : tk_range(r, 0, 2);
        break;
    case TK_ROT_SMALL:
        angle = 1e-4;
        v = tk_uni(r) < 0.5 ? 0 : tk_range(r, 0, 2);
        break;
    case TK_ROT_SPREAD:
        angle = tk_loguni(r, 1e-6, 1.0);
        v = tk_loguni(r, 1e-3, 1e6);
        break;
    case TK_ROT_QUARTER:
        angle = TK_PI / 2;
        v = tk_uni(r) < 0.5 ? 0 : tk_range(r, 0, 2);
        break;
    case TK_ROT_NEAR_PI:
        angle = TK_PI - 1e-9;
        v = tk_uni(r) < 0.5 ? 0 : tk_range(r, 0, 2);
        break;
    case TK_ROT_NEAR_PI_SPREAD:
        angle = TK_PI - (tk_uni(r) < 0.2 ? 1e-9 : tk_loguni(r, 1e-12, 1e-1));
        v = tk_loguni(r, 1e-3, 1e6);
        break;
    case TK_ROT_PI: {
        angle = TK_PI;
        if (tk_uni(r) < 0.3) { /* about a coordinate axis */
            uint64_t k = tk_next(r) % 3;
            u = (ga_vec3){k == 0, k == 1, k == 2};
        }
        double c = tk_uni(r);
        v = c < 1.0 / 3 ? 0 : c < 2.0 / 3 ? tk_range(r, 0, 2) : tk_loguni(r, 1e-3, 1e6);
        break;
    }
    case TK_TINY_UNDER_LARGE:
        angle = tk_loguni(r, 1e-12, 1e-6);
        v = tk_loguni(r, 1, 1e6);
        break;
    case TK_SCREW:
        angle = tk_range(r, 0, TK_PI);
        v = tk_loguni(r, 1e-3, 1e3);
        break;
    case TK_BEYOND_PI:
        angle = tk_range(r, TK_PI, 3 * TK_PI);
        v = tk_loguni(r, 1e-3, 1e6);
        break;
    default: break; /* not a twist family: the zero twist */
    }
    return (ga_twist){tk_scale(u, angle), tk_scale(d, v)};
}

/** A random algebra element of family f as a 4x4 with a zero last row: the
 *  hat of a twist for the twist families, else a scaling, a shear or a
 *  general 3x4. */
static inline ga_mat4 tk_algebra(tk_rng *r, int f)
{
    if (f < TK_TWIST_FAMILIES)
        return ga_twist_hat(tk_twist(r, f));
    ga_mat4 x;
    memset(&x, 0, sizeof x);
    if (f == TK_AFFINE) {
        for (int i = 0; i < 12; i++) x.m[i] = i % 4 == 3 ? tk_range(r, -10, 10) : tk_range(r, -1, 1);
        return x;
    }
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            if (f == TK_SCALING && i == j)
                x.m[4 * i + j] = tk_range(r, -3, 3);
            else if (f == TK_SHEAR && j > i)
                x.m[4 * i + j] = tk_range(r, -2, 2);
        }
    ga_vec3 b = tk_scale(tk_unit(r), tk_loguni(r, 1e-3, 1e3));
    x.m[3] = b.x;
    x.m[7] = b.y;
    x.m[11] = b.z;
    return x;
}

/** Rotors just off the group: every coefficient of R moved by ~1e-12
 *  relative (the bivector part absolutely, the n part relative to
 *  max(1, |coefficient|)). */
static inline ga_rotor tk_drift(tk_rng *r, ga_rotor R)
{
    double *c = &R.s;
    for (int k = 0; k < 8; k++) c[k] += 1e-12 * tk_range(r, -1, 1) * (k < 4 ? 1 : fmax(1, fabs(c[k])));
    return R;
}

/* ---- reporting --------------------------------------------------------------- */
enum { TK_MAX, TK_PER_CASE, TK_LEAST, TK_STATUS, TK_BOOL };

typedef struct {
    char name[128];
    int kind;
    long n, bad;       /* cases; cases that failed (statuses, conditions, per-case) */
    double worst;      /* TK_MAX: largest error; TK_PER_CASE: the error of the case
                          nearest its tolerance; TK_LEAST: smallest value */
    double tol;        /* the tolerance (TK_PER_CASE: that case's); TK_LEAST: the bound */
    double ratio;      /* TK_PER_CASE: largest err/tol */
    int got, want;     /* TK_STATUS: the first wrong status (or the last right one) */
    const char *xfail; /* tk_xfail: why this check is expected to fail */
} tk_check;

static int tk_failures;
/* set by tk_main: 1 while a section runs silently, or the check names that
   may print (--only NAME naming no section) */
static int tk_quiet;
static const char *tk_check_filter[16];
static int tk_check_filter_n, tk_check_matched;

/** A line of a section's own (printf's arguments), silenced with its checks. */
static inline void tk_note(const char *fmt, ...)
{
    if (tk_quiet || tk_check_filter_n)
        return;
    va_list ap;
    va_start(ap, fmt);
    vprintf(fmt, ap);
    va_end(ap);
}

/** TK_OK(call): a call whose status the test relies on but does not
 *  otherwise check (an evaluation feeding a finite difference, a reference
 *  value): anything but GA_OK is a failure, reported with the call and its
 *  line. */
#define TK_OK(call) tk_ok_((call), #call, __FILE__, __LINE__)
static inline void tk_ok_(ga_status st, const char *call, const char *file, int line)
{
    if (st != GA_OK && !tk_quiet) {
        printf("FAIL %s:%d: %s returned %d (%s)\n", file, line, call, st, ga_status_string(st));
        tk_failures++;
    }
}

static inline tk_check tk_begin(const char *name, double tol)
{
    tk_check c;
    memset(&c, 0, sizeof c);
    snprintf(c.name, sizeof c.name, "%s", name);
    c.kind = TK_MAX;
    c.tol = tol;
    return c;
}
/** tk_begin with a name formatted as by printf. */
static inline tk_check tk_beginf(double tol, const char *fmt, ...)
{
    tk_check c = tk_begin("", tol);
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(c.name, sizeof c.name, fmt, ap);
    va_end(ap);
    return c;
}
/** A check that values stay at or above bound (an error that must be there). */
static inline tk_check tk_begin_least(const char *name, double bound)
{
    tk_check c = tk_begin(name, bound);
    c.kind = TK_LEAST;
    c.worst = INFINITY;
    return c;
}
/** Record one measured error (TK_LEAST: one value). NaN counts as a failure. */
static inline void tk_add(tk_check *c, double err)
{
    c->n++;
    if (c->kind == TK_LEAST) {
        if (!(err >= c->worst))
            c->worst = isnan(err) ? -INFINITY : err;
        return;
    }
    if (!(err <= c->worst))
        c->worst = isnan(err) ? INFINITY : fmax(c->worst, err);
}
/** Record one error against its own tolerance (derived for this case). */
static inline void tk_add_tol(tk_check *c, double err, double tol)
{
    c->kind = TK_PER_CASE;
    c->n++;
    double ratio = err == 0 ? 0.0 : err / tol; /* tol 0 demands exact; NaN fails */
    if (!(err <= tol)) {
        c->bad++;
        ratio = isnan(ratio) || isnan(err) ? INFINITY : ratio;
    }
    /* the case nearest its tolerance; among equals (all exact, say) the
       largest error, then the tightest tolerance */
    if (c->n == 1 || ratio > c->ratio || (ratio == c->ratio && err > c->worst) ||
        (ratio == c->ratio && err == c->worst && tol < c->tol)) {
        c->ratio = ratio;
        c->worst = isnan(err) ? INFINITY : err;
        c->tol = tol;
    }
}
static inline void tk_add_status(tk_check *c, int got, int want)
{
    c->kind = TK_STATUS;
    c->n++;
    if (got != want && c->bad++ == 0)
        c->got = got, c->want = want;
    if (c->bad == 0)
        c->got = got, c->want = want;
}
static inline void tk_add_bool(tk_check *c, int cond)
{
    c->kind = TK_BOOL;
    c->n++;
    c->bad += !cond;
}
/** Print the check's line and count a failure if it failed. */
static inline void tk_end(const tk_check *c)
{
    int ok;
    char tail[160];
    switch (c->kind) {
    case TK_LEAST:
        ok = c->worst >= c->tol;
        snprintf(tail, sizeof tail, "least %.3e  >= %.1e", c->worst, c->tol);
        break;
    case TK_PER_CASE:
        ok = c->bad == 0;
        snprintf(tail, sizeof tail, "worst %.3e  tol %.1e  (tol per case; worst err/tol %.3g)", c->worst,
                 c->tol, c->ratio);
        break;
    case TK_STATUS:
        ok = c->bad == 0;
        if (ok)
            snprintf(tail, sizeof tail, "status %s", ga_status_string(c->want));
        else
            snprintf(tail, sizeof tail, "%ld wrong; first: %s (%d), wanted %s (%d)", c->bad,
                     ga_status_string(c->got), c->got, ga_status_string(c->want), c->want);
        break;
    case TK_BOOL:
        ok = c->bad == 0;
        snprintf(tail, sizeof tail, ok ? "held" : "failed %ld times", c->bad);
        break;
    default:
        ok = c->worst <= c->tol;
        snprintf(tail, sizeof tail, "worst %.3e  tol %.1e", c->worst, c->tol);
        break;
    }
    if (tk_quiet)
        return;
    if (tk_check_filter_n) {
        int shown = 0;
        for (int i = 0; i < tk_check_filter_n; i++) shown |= strstr(c->name, tk_check_filter[i]) != NULL;
        if (!shown)
            return;
        tk_check_matched++;
    }
    const char *mark = ok ? "ok" : "FAIL";
    if (c->xfail) { /* a known bug: its failure expected, its passing news */
        mark = ok ? "XPASS" : "XFAIL";
        ok = !ok;
    }
    printf("%-4s %-62s n=%-7ld %s\n", mark, c->name, c->n, tail);
    if (c->xfail)
        printf("     (expected to fail: %s)\n", c->xfail);
    if (!ok)
        tk_failures++;
}
/** Mark c as expected to fail, for the reason why (a known bug, reported):
 *  tk_end then prints XFAIL and counts no failure, or XPASS and counts one. */
static inline void tk_xfail(tk_check *c, const char *why) { c->xfail = why; }
/** One condition, one line. */
static inline void tk_expect(int cond, const char *what)
{
    tk_check c = tk_begin(what, 0);
    tk_add_bool(&c, cond);
    tk_end(&c);
}
/** One status, one line. */
static inline void tk_expect_status(const char *what, int got, int want)
{
    tk_check c = tk_begin(what, 0);
    tk_add_status(&c, got, want);
    tk_end(&c);
}

/* ---- named checks: met in many places, ended together -------------------------- */
enum { TK_MAX_NAMED = 256 };
static tk_check tk_named[TK_MAX_NAMED];
static int tk_named_n;

/** The named check `name`, opened (kind and tolerance set by what is added)
 *  at its first use since the last tk_end_named. */
static inline tk_check *tk_get(const char *name)
{
    for (int i = 0; i < tk_named_n; i++)
        if (strcmp(tk_named[i].name, name) == 0)
            return &tk_named[i];
    if (tk_named_n == TK_MAX_NAMED) { /* reuse the last slot and count a failure */
        printf("FAIL testkit: more than %d named checks\n", TK_MAX_NAMED);
        tk_failures++;
        tk_named_n--;
    }
    tk_named[tk_named_n] = tk_begin(name, 0);
    return &tk_named[tk_named_n++];
}
/** End every named check opened since the last call, in order of first use. */
static inline void tk_end_named(void)
{
    for (int i = 0; i < tk_named_n; i++) tk_end(&tk_named[i]);
    tk_named_n = 0;
}

/** The summary line; the exit status (0: every check passed). */
static inline int tk_finish(const char *test)
{
    tk_end_named();
    if (tk_seed_n())
        printf("(GAROTOR_TEST_SEED=%llu)\n", (unsigned long long)tk_seed_n());
    if (tk_failures)
        printf("%s: %d check(s) FAILED\n", test, tk_failures);
    else
        printf("%s: all passed\n", test);
    return tk_failures != 0;
}

/* ---- sections: the registry and the options ------------------------------- */
enum { TK_SETUP = 1, TK_STREAM = 2 };
typedef struct {
    const char *name;
    void (*run)(void);
    int flags; /* TK_SETUP, TK_STREAM */
} tk_section;
#define TK_COUNT(table) (sizeof(table) / sizeof(table)[0])

static unsigned char tk_selected[64]; /* per section: --only named it */
static int tk_any_selected;

static inline void tk_list(const tk_section *s, size_t n, FILE *f)
{
    for (size_t i = 0; i < n; i++) fprintf(f, "%s\n", s[i].name);
}

/** Read the options (above). Returns -1 to go on, else the exit status
 *  (0 after --list, 2 on a bad option). */
static inline int tk_options(int argc, char **argv, const char *test, const tk_section *s, size_t n,
                             const char **arg)
{
    if (arg)
        *arg = NULL;
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--list") == 0) {
            tk_list(s, n, stdout);
            return 0;
        }
        if (strcmp(argv[i], "--only") == 0 && i + 1 < argc) {
            const char *name = argv[++i];
            int found = 0;
            for (size_t k = 0; k < n && k < sizeof tk_selected; k++)
                if (strcmp(s[k].name, name) == 0)
                    tk_selected[k] = 1, found = 1;
            if (found)
                tk_any_selected = 1;
            else if (tk_check_filter_n < (int)TK_COUNT(tk_check_filter))
                tk_check_filter[tk_check_filter_n++] = name;
            continue;
        }
        if (arg && !*arg && strncmp(argv[i], "--", 2) != 0) {
            *arg = argv[i];
            continue;
        }
        fprintf(stderr, "usage: %s [--list] [--only NAME]...%s\n", test, arg ? " [ARG]" : "");
        return 2;
    }
    return -1;
}

/** Run the sections the options chose (every one without --only). */
static inline void tk_run(const tk_section *s, size_t n)
{
    size_t last = 0; /* one past the last selected section */
    for (size_t i = 0; i < n; i++)
        if (tk_selected[i])
            last = i + 1;
    for (size_t i = 0; i < n; i++) {
        int run = !tk_any_selected || tk_selected[i] || (s[i].flags & TK_SETUP);
        if (!run && !(s[i].flags & TK_STREAM && i < last))
            continue;
        int named = tk_named_n;
        tk_quiet = !run;
        s[i].run();
        if (!run) /* what a silent run opened is no result */
            tk_named_n = named;
        tk_quiet = 0;
    }
}

/** The summary, or, where --only NAME named neither a section nor a check,
 *  an error that lists the sections (exit status 2). */
static inline int tk_done(const char *test, const tk_section *s, size_t n)
{
    tk_end_named();
    if (tk_check_filter_n && !tk_check_matched) {
        fprintf(stderr, "%s: no section or check named", test);
        for (int i = 0; i < tk_check_filter_n; i++) fprintf(stderr, " '%s'", tk_check_filter[i]);
        fprintf(stderr, "; the sections:\n");
        tk_list(s, n, stderr);
        return 2;
    }
    return tk_finish(test);
}

/** A section that prints the CPU time the test has taken, "(1.23 s)". */
static inline void tk_cpu_time(void) { tk_note("(%.2f s)\n", (double)clock() / CLOCKS_PER_SEC); }

/** The whole main of a test: the options, setup(ARG) (where setup is not
 *  NULL: the test takes an argument), the sections, the summary. */
static inline int tk_main_arg(int argc, char **argv, const char *test, const tk_section *s, size_t n,
                              void (*setup)(const char *arg))
{
    const char *arg;
    int st = tk_options(argc, argv, test, s, n, setup ? &arg : NULL);
    if (st >= 0)
        return st;
    if (setup)
        setup(arg);
    tk_run(s, n);
    return tk_done(test, s, n);
}
/** The same for a test without an argument of its own. */
static inline int tk_main(int argc, char **argv, const char *test, const tk_section *s, size_t n)
{
    return tk_main_arg(argc, argv, test, s, n, NULL);
}

/* ---- paths ---------------------------------------------------------------------- */
/** 1 if paths a and b give the same statuses and the same bits at t: the
 *  pose, the body velocity and the acceleration. */
static inline int tk_path_same_at(const ga_path *a, const ga_path *b, double t)
{
    double ea[GA_GROUP_MAX_ELEM], eb[GA_GROUP_MAX_ELEM];
    double va[GA_GROUP_MAX_DIM], vb[GA_GROUP_MAX_DIM], aa[GA_GROUP_MAX_DIM], ab[GA_GROUP_MAX_DIM];
    int sa = ga_path_eval(a, t, ea), sb = ga_path_eval(b, t, eb);
    if (sa != sb || (sa == GA_OK && memcmp(ea, eb, a->group->elem_size)))
        return 0;
    sa = ga_path_differentiate(a, t, GA_FRAME_BODY, va, aa);
    sb = ga_path_differentiate(b, t, GA_FRAME_BODY, vb, ab);
    size_t d = a->group->dim * sizeof(double);
    return sa == sb && (sa != GA_OK || (!memcmp(va, vb, d) && !memcmp(aa, ab, d)));
}

#endif
