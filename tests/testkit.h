/* tests/testkit.h: what the tests share: a seeded PRNG, the adversarial
 * families of twists, and one-line reporting of measured worst errors.
 *
 * Header-only (static functions), so each test stays one file plus this. */
#ifndef GAROTOR_TESTKIT_H
#define GAROTOR_TESTKIT_H

#include <math.h>
#include <stdint.h>
#include <stdio.h>

#include <garotor/garotor.h>

#define TK_PI 3.14159265358979323846

/* ---- splitmix64: the same sequence on every machine and compiler -------- */
typedef struct { uint64_t s; } tk_rng;

static inline uint64_t tk_next(tk_rng *r)
{
    uint64_t z = (r->s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}
/** Uniform in [0, 1). */
static inline double tk_uni(tk_rng *r) { return (double)(tk_next(r) >> 11) * 0x1p-53; }
/** Uniform in [lo, hi). */
static inline double tk_range(tk_rng *r, double lo, double hi) { return lo + (hi - lo) * tk_uni(r); }
/** Log-uniform in [lo, hi). */
static inline double tk_loguni(tk_rng *r, double lo, double hi)
{
    return exp(tk_range(r, log(lo), log(hi)));
}
/** A uniformly distributed unit vector (one draw per statement: C leaves the
 *  order of evaluation of arguments unspecified). */
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
static inline double tk_norm(ga_vec3 u) { return sqrt(u.x * u.x + u.y * u.y + u.z * u.z); }

/* ---- the adversarial families of twists (issues 3 and 4) ---------------- */
enum {
    TK_IDENTITY, TK_TRANSLATION, TK_ROT_TINY, TK_ROT_SMALL, TK_ROT_QUARTER,
    TK_ROT_NEAR_PI, TK_ROT_PI, TK_TINY_UNDER_LARGE, TK_SCREW, TK_FAMILIES
};
static const char *const tk_family_name[TK_FAMILIES] = {
    "identity", "pure translations 1e-12..1e6", "rotations 1e-12 and 1e-8 rad",
    "rotations 1e-4 rad", "rotations pi/2", "rotations pi - 1e-9", "rotations pi (half turns)",
    "tiny rotations 1e-12..1e-6 under translations 1..1e6", "general screws"};

/** A random twist of family f; its rotation angle is |w|. */
static inline ga_twist tk_twist(tk_rng *r, int f)
{
    ga_vec3 u = tk_unit(r), d = tk_unit(r);
    double angle = 0, v = 0;
    switch (f) {
    case TK_IDENTITY: break;
    case TK_TRANSLATION: v = tk_loguni(r, 1e-12, 1e6); break;
    case TK_ROT_TINY: angle = tk_uni(r) < 0.5 ? 1e-12 : 1e-8; v = tk_uni(r) < 0.5 ? 0 : tk_range(r, 0, 2); break;
    case TK_ROT_SMALL: angle = 1e-4; v = tk_uni(r) < 0.5 ? 0 : tk_range(r, 0, 2); break;
    case TK_ROT_QUARTER: angle = TK_PI / 2; v = tk_uni(r) < 0.5 ? 0 : tk_range(r, 0, 2); break;
    case TK_ROT_NEAR_PI: angle = TK_PI - 1e-9; v = tk_uni(r) < 0.5 ? 0 : tk_range(r, 0, 2); break;
    case TK_ROT_PI: angle = TK_PI; v = tk_uni(r) < 0.5 ? 0 : tk_range(r, 0, 2); break;
    case TK_TINY_UNDER_LARGE: angle = tk_loguni(r, 1e-12, 1e-6); v = tk_loguni(r, 1, 1e6); break;
    default: angle = tk_range(r, 0, TK_PI); v = tk_loguni(r, 1e-3, 1e3); break;
    }
    return (ga_twist){tk_scale(u, angle), tk_scale(d, v)};
}

/* ---- reporting --------------------------------------------------------------- */
typedef struct { const char *name; long n; double worst, tol; } tk_check;

static int tk_failures;

static inline tk_check tk_begin(const char *name, double tol) { return (tk_check){name, 0, 0.0, tol}; }
/** Record one measured error (NaN counts as a failure). */
static inline void tk_add(tk_check *c, double err)
{
    c->n++;
    if (!(err <= c->worst))
        c->worst = isnan(err) ? INFINITY : fmax(c->worst, err);
}
/** Print "ok|FAIL name n worst tol" and count a failure if worst > tol. */
static inline void tk_end(const tk_check *c)
{
    int ok = c->worst <= c->tol;
    printf("%-4s %-62s n=%-7ld worst %.3e  tol %.1e\n", ok ? "ok" : "FAIL", c->name, c->n, c->worst,
           c->tol);
    if (!ok)
        tk_failures++;
}
static inline void tk_expect(int cond, const char *what)
{
    printf("%-4s %s\n", cond ? "ok" : "FAIL", what);
    if (!cond)
        tk_failures++;
}
static inline int tk_finish(const char *test)
{
    if (tk_failures)
        printf("%s: %d check(s) FAILED\n", test, tk_failures);
    else
        printf("%s: all passed\n", test);
    return tk_failures != 0;
}

#endif
