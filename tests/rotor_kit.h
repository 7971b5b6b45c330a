/* tests/rotor_kit.h: what the tests of the compact rotor (test_rotor.c,
 * test_rotor_screws.c) share: the seeded stream and the scale argument,
 * vector, rotor and generator helpers, and the independent references
 * (Taylor series with scaling and squaring, in double through ga_mv_gp and
 * in long double for 4x4 matrices; quaternion and dual-quaternion products).
 *
 * Header-only (static functions), beside testkit.h.
 *
 * Every error is measured, printed (worst per family) and compared with a
 * tolerance derived from the computation: EPS times the number of rounding
 * steps the formula takes, times the size of what is compared.
 */
#ifndef GAROTOR_ROTOR_KIT_H
#define GAROTOR_ROTOR_KIT_H

#include <stdlib.h>

#include "testkit.h"

#define N_CASES 10000 /* per family in the default run */
#define N_PATH 1000   /* samples along a path */
#define EPS DBL_EPSILON
#define PI TK_PI

#define ROTOR_SEED 0x9E3779B97F4A7C15u
static tk_rng rng = {ROTOR_SEED}; /* testkit.h: splitmix64 */
static long n_cases;              /* per family: N_CASES times the scale argument */

/* ---- small vector helpers ------------------------------------------------ */
static inline ga_vec3 v3(double x, double y, double z)
{
    ga_vec3 r = {x, y, z};
    return r;
}
static inline ga_vec3 vadd(ga_vec3 a, ga_vec3 b) { return v3(a.x + b.x, a.y + b.y, a.z + b.z); }
static inline ga_vec3 vsub(ga_vec3 a, ga_vec3 b) { return v3(a.x - b.x, a.y - b.y, a.z - b.z); }
static inline ga_vec3 vscale(ga_vec3 a, double k) { return v3(k * a.x, k * a.y, k * a.z); }
static inline double vdot(ga_vec3 a, ga_vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static inline double vnorm(ga_vec3 a) { return sqrt(vdot(a, a)); }
static inline double vmaxabs(ga_vec3 a) { return tk_max(fabs(a.x), tk_max(fabs(a.y), fabs(a.z))); }
static inline ga_vec3 vcross(ga_vec3 a, ga_vec3 b)
{
    return v3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
/* Random vectors, each draw its own statement (C leaves the order of
 * evaluation of arguments and initializers unspecified): a unit direction,
 * then its length (len, k times uniform in [0, 1), log-uniform in [lo, hi)). */
static inline ga_vec3 rnd_vec(double len) { return vscale(tk_unit(&rng), len); }
static inline ga_vec3 rnd_vec_u(double k)
{
    ga_vec3 u = tk_unit(&rng);
    return vscale(u, k * tk_uni(&rng));
}
static inline ga_vec3 rnd_vec_logu(double lo, double hi)
{
    ga_vec3 u = tk_unit(&rng);
    return vscale(u, tk_loguni(&rng, lo, hi));
}
/* A unit vector perpendicular to the unit vector u. */
static inline ga_vec3 rnd_perp(ga_vec3 u)
{
    for (;;) {
        ga_vec3 v = tk_unit(&rng);
        ga_vec3 p = vsub(v, vscale(u, vdot(u, v)));
        double n = vnorm(p);
        if (n > 0.1)
            return vscale(p, 1.0 / n);
    }
}

/* ---- rotor, generator helpers ---------------------------------------- */
static inline double r_comp(ga_rotor r, int i)
{
    const double c[8] = {r.s, r.e12, r.e13, r.e23, r.e1n, r.e2n, r.e3n, r.e123n};
    return c[i];
}
static inline double rdiff(ga_rotor a, ga_rotor b)
{
    double d = 0.0;
    for (int i = 0; i < 8; i++) d = tk_max(d, fabs(r_comp(a, i) - r_comp(b, i)));
    return d;
}
static inline ga_rotor rneg(ga_rotor r)
{
    ga_rotor o = {-r.s, -r.e12, -r.e13, -r.e23, -r.e1n, -r.e2n, -r.e3n, -r.e123n};
    return o;
}
/* Distance up to sign (R and -R are the same motion). */
static inline double rdiff_pm(ga_rotor a, ga_rotor b) { return fmin(rdiff(a, b), rdiff(a, rneg(b))); }
static inline double rmaxabs(ga_rotor r) { return rdiff(r, rneg(r)) / 2.0; }
static inline ga_rotor rnd_rotor8(double scale)
{
    ga_rotor r;
    double *c = &r.s;
    for (int k = 0; k < 8; k++) c[k] = scale * tk_range(&rng, -1, 1);
    return r;
}
static inline double gdiff(ga_generator a, ga_generator b)
{
    return tk_max(tk_max(fabs(a.e12 - b.e12), tk_max(fabs(a.e13 - b.e13), fabs(a.e23 - b.e23))),
                  tk_max(fabs(a.e1n - b.e1n), tk_max(fabs(a.e2n - b.e2n), fabs(a.e3n - b.e3n))));
}
static inline ga_twist twist(ga_vec3 w, ga_vec3 v)
{
    ga_twist t = {w, v};
    return t;
}
static inline ga_generator gen(ga_vec3 w, ga_vec3 v) { return ga_twist_to_generator(twist(w, v)); }

/* ---- references ------------------------------------------------------------ */

/* exp(B) in the full algebra: Taylor series of ga_mv_gp with scaling and squaring.
 * Powers of B = beta I3 + c n grow like |beta|^k + k |beta|^(k-1) |c| (c n is
 * nilpotent), so the scaling is chosen by |beta| alone: |beta| / 2^k <= 1/8,
 * where 14 terms leave < 1e-20. *k_out = k (each squaring doubles the error).
 * The c n c n terms cancel inside ga_mv_gp's sums, which costs EPS |c|^2 in the
 * scalar part; so the series is summed for c / |c| and the n part scaled by |c|
 * afterwards (exp is affine in c: (c n) X (c n) = 0 for every even X). */
static inline ga_rotor mv_exp(ga_generator g, int *k_out)
{
    double nb = sqrt(g.e12 * g.e12 + g.e13 * g.e13 + g.e23 * g.e23);
    double nc = sqrt(g.e1n * g.e1n + g.e2n * g.e2n + g.e3n * g.e3n), kc = nc > 0 ? 1 / nc : 0;
    ga_generator gu = {g.e12, g.e13, g.e23, kc * g.e1n, kc * g.e2n, kc * g.e3n};
    int k = 0;
    while (nb > 0.125) nb *= 0.5, k++;
    ga_mv X = ga_mv_scale(ga_generator_to_mv(gu), ldexp(1.0, -k)), E = ga_mv_scalar(1.0), T = E;
    for (int j = 1; j <= 14; j++) {
        T = ga_mv_scale(ga_mv_gp(T, X), 1.0 / j);
        E = ga_mv_add(E, T);
    }
    for (int i = 0; i < k; i++) E = ga_mv_gp(E, E);
    *k_out = k;
    ga_rotor r;
    tk_add_bool(tk_get("full-algebra exp lies in the 8-component form"),
                ga_rotor_from_mv(E, 1e-6, &r) == GA_OK);
    ga_rotor raw = {E.c[GA_BLADE_SCALAR],   E.c[GA_BLADE_E12],       E.c[GA_BLADE_E13],
                    E.c[GA_BLADE_E23],      nc * E.c[GA_BLADE_E14],  nc * E.c[GA_BLADE_E24],
                    nc * E.c[GA_BLADE_E34], nc * E.c[GA_BLADE_E1234]};
    return raw;
}

/* expm(xi^) in long double: Taylor with scaling and squaring (scaled by |w|,
 * as above: the powers of xi^ are [[W^k, W^(k-1) v]; 0]). */
typedef long double ld;
static inline void mm_ld(const ld *a, const ld *b, ld *c)
{
    ld t[16];
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            ld s = 0;
            for (int k = 0; k < 4; k++) s += a[4 * i + k] * b[4 * k + j];
            t[4 * i + j] = s;
        }
    for (int i = 0; i < 16; i++) c[i] = t[i];
}
static inline ga_mat4 expm_ref(ga_twist xi)
{
    ld A[16] = {0,       -xi.w.z, xi.w.y, xi.v.x, xi.w.z, 0, -xi.w.x, xi.v.y,
                -xi.w.y, xi.w.x,  0,      xi.v.z, 0,      0, 0,       0};
    ld th = sqrtl((ld)xi.w.x * xi.w.x + (ld)xi.w.y * xi.w.y + (ld)xi.w.z * xi.w.z);
    int k = 0;
    while (th > 0.125L) th *= 0.5L, k++;
    for (int i = 0; i < 16; i++) A[i] = ldexpl(A[i], -k);
    ld E[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}, T[16];
    for (int i = 0; i < 16; i++) T[i] = E[i];
    for (int j = 1; j <= 20; j++) {
        mm_ld(T, A, T);
        for (int i = 0; i < 16; i++) T[i] /= j, E[i] += T[i];
    }
    for (int i = 0; i < k; i++) mm_ld(E, E, E);
    ga_mat4 m;
    for (int i = 0; i < 16; i++) m.m[i] = (double)E[i];
    return m;
}
static inline double mdiff(ga_mat4 a, ga_mat4 b)
{
    double d = 0.0;
    for (int i = 0; i < 16; i++) d = tk_max(d, fabs(a.m[i] - b.m[i]));
    return d;
}
static inline ga_mat4 mmul(ga_mat4 a, ga_mat4 b)
{
    ga_mat4 c;
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            double s = 0;
            for (int k = 0; k < 4; k++) s += a.m[4 * i + k] * b.m[4 * k + j];
            c.m[4 * i + j] = s;
        }
    return c;
}

/* Hamilton quaternion product and the plain dual-quaternion product. */
static inline ga_quat qmul(ga_quat a, ga_quat b)
{
    ga_quat r = {a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z, a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
                 a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x,
                 a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
    return r;
}
static inline ga_quat qadd(ga_quat a, ga_quat b)
{
    ga_quat r = {a.w + b.w, a.x + b.x, a.y + b.y, a.z + b.z};
    return r;
}
static inline double qdiff(ga_quat a, ga_quat b)
{
    return tk_max(tk_max(fabs(a.w - b.w), fabs(a.x - b.x)), tk_max(fabs(a.y - b.y), fabs(a.z - b.z)));
}
static inline double qdiff_pm(ga_quat a, ga_quat b)
{
    ga_quat nb = {-b.w, -b.x, -b.y, -b.z};
    return fmin(qdiff(a, b), qdiff(a, nb));
}
static inline ga_dualquat dqmul(ga_dualquat a, ga_dualquat b)
{
    ga_dualquat r = {qmul(a.real, b.real), qadd(qmul(a.real, b.dual), qmul(a.dual, b.real))};
    return r;
}

/** The scale argument M (NULL: 1): n_cases = M times the default counts. */
static inline void rotor_setup(const char *test, const char *arg)
{
    long mult = arg ? atol(arg) : 1;
    n_cases = N_CASES * (mult > 0 ? mult : 1);
    tk_note("%s: %ld cases per family\n", test, n_cases);
}

#endif
