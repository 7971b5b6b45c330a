/* garotor/rotor.c: the compact rigid-motion rotor R = q + P n (see rotor.h).
 *
 * Inside, q = s + I b and P = p + I p4 with I = e123 (central in G(3), I^2 = -1)
 * and b, p vectors: e12 = I e3, e13 = -I e2, e23 = I e1, so
 *     b = (e23, -e13, e12),  p = (e1n, e2n, e3n),  p4 = e123n.
 * With u v = u.v + I u x v for vectors, the G(3) products used below are
 *     q1 q2 = (s1 s2 - b1.b2) + I (s1 b2 + s2 b1 - b1 x b2),
 *     q P   = (s p - p4 b - b x p) + I (s p4 + b.p),
 *     P q   = (s p - p4 b - p x b) + I (s p4 + p.b),
 *     P ~q  = (s p + p4 b + p x b) + I (s p4 - p.b).
 */
#include <garotor/rotor.h>
#include <garotor/mat4.h>
#include <garotor/rotor_inline.h>

#include <float.h>
#include <math.h>
#include <stddef.h>

#include "internal/object.h"
#include "internal/vec3.h"

/* R X ~R of ga_rotor_apply_mv: written by gen/generate.py */
#include "rotor_sandwich.inc"

static ga_vec3 rotor_b(ga_rotor r) { return ga__v3(r.e23, -r.e13, r.e12); }
static ga_vec3 rotor_p(ga_rotor r) { return ga__v3(r.e1n, r.e2n, r.e3n); }

static ga_rotor rotor_make(double s, ga_vec3 b, ga_vec3 p, double p4)
{
    ga_rotor r = {s, b.z, -b.y, b.x, p.x, p.y, p.z, p4};
    return r;
}

static int rotor_isfinite(ga_rotor r)
{
    return isfinite(r.s) && isfinite(r.e12) && isfinite(r.e13) && isfinite(r.e23) && isfinite(r.e1n) &&
           isfinite(r.e2n) && isfinite(r.e3n) && isfinite(r.e123n);
}

ga_rotor ga_rotor_identity(void)
{
    ga_rotor r = {1, 0, 0, 0, 0, 0, 0, 0};
    return r;
}

/* The hot path is in <garotor/rotor_inline.h>; these are its linkable symbols. */
ga_rotor ga_rotor_mul(ga_rotor a, ga_rotor b) { return ga_rotor_mul_inline(a, b); }

ga_rotor ga_rotor_reverse(ga_rotor r) { return ga_rotor_reverse_inline(r); }

ga_mv ga_rotor_to_mv(ga_rotor r)
{
    ga_mv m = ga_mv_zero();
    m.c[GA_BLADE_SCALAR] = r.s;
    m.c[GA_BLADE_E12] = r.e12;
    m.c[GA_BLADE_E13] = r.e13;
    m.c[GA_BLADE_E23] = r.e23;
    m.c[GA_BLADE_E14] = m.c[GA_BLADE_E15] = r.e1n;
    m.c[GA_BLADE_E24] = m.c[GA_BLADE_E25] = r.e2n;
    m.c[GA_BLADE_E34] = m.c[GA_BLADE_E35] = r.e3n;
    m.c[GA_BLADE_E1234] = m.c[GA_BLADE_E1235] = r.e123n;
    return m;
}

ga_mv ga_generator_to_mv(ga_generator b)
{
    ga_mv m = ga_mv_zero();
    m.c[GA_BLADE_E12] = b.e12, m.c[GA_BLADE_E13] = b.e13, m.c[GA_BLADE_E23] = b.e23;
    m.c[GA_BLADE_E14] = m.c[GA_BLADE_E15] = b.e1n;
    m.c[GA_BLADE_E24] = m.c[GA_BLADE_E25] = b.e2n;
    m.c[GA_BLADE_E34] = m.c[GA_BLADE_E35] = b.e3n;
    return m;
}

/* The e123 part of P ~q: zero on the group. */
static double rotor_pq3(ga_rotor r) { return r.s * r.e123n - ga__v3_dot(rotor_p(r), rotor_b(r)); }

/* Distance from the group (rotor.h, ga_rotor_check); NaN for non-finite input. */
static double rotor_drift(ga_rotor r)
{
    double q2 = r.s * r.s + r.e12 * r.e12 + r.e13 * r.e13 + r.e23 * r.e23;
    double psize = sqrt(r.e1n * r.e1n + r.e2n * r.e2n + r.e3n * r.e3n + r.e123n * r.e123n);
    return fmax(fabs(q2 - 1.0), 2.0 * fabs(rotor_pq3(r)) / fmax(1.0, psize));
}

ga_status ga_rotor_check(ga_rotor r, double tol)
{
    if (!rotor_isfinite(r))
        return GA_ERR_NOTFINITE;
    double d = rotor_drift(r);
    return (d <= tol && isfinite(d)) ? GA_OK : GA_ERR_NOTRIGID;
}

/* The fast test of ga_rotor_log: true only if r is finite and
 * rotor_drift(r) <= GA_ROTOR_DRIFT_MAX, and then always, except for
 * |P|^2 > 1e300. The test is squared, so it needs neither a sqrt nor a division:
 *     | |q|^2 - 1 | <= tol   and   4 <P ~q>_3^2 <= tol^2 max(1, |P|^2).
 * With |q|^2 within tol of 1, <P ~q>_3^2 <= |q|^2 |P|^2 (Cauchy-Schwarz), so
 * nothing overflows while |P|^2 <= 1e300. NaN or Inf fails a comparison. */
static int rotor_near_group(ga_rotor r)
{
    const double tol = GA_ROTOR_DRIFT_MAX;
    double q2 = r.s * r.s + r.e12 * r.e12 + r.e13 * r.e13 + r.e23 * r.e23;
    double p2 = r.e1n * r.e1n + r.e2n * r.e2n + r.e3n * r.e3n + r.e123n * r.e123n;
    double pq3 = rotor_pq3(r);
    return p2 <= 1e300 && fabs(q2 - 1.0) <= tol && 4.0 * pq3 * pq3 <= tol * tol * (p2 > 1.0 ? p2 : 1.0);
}

/* R (R ~R)^(-1/2) for a finite r with q != 0 (not overflowing), given
 * k = 1/|q|; k = -1/|q| gives -R (R ~R)^(-1/2) (every term is odd in k).
 * With q and P scaled by k, P ~q = x + I mu (mu = <P ~q>_3), and dropping mu
 * is P <- x q = P - mu I q, with I q = -b + I s. This is exact: R ~R =
 * 1 + 2 mu I n and (I n)^2 = 0, so (R ~R)^(-1/2) = 1 - mu I n and
 * R (1 - mu I n) = q + (P - mu I q) n. */
static inline ga_rotor rotor_project(ga_rotor r, double k)
{
    double s = k * r.s, p4 = k * r.e123n;
    ga_vec3 b = ga__v3_scale(rotor_b(r), k), p = ga__v3_scale(rotor_p(r), k);
    double mu = s * p4 - ga__v3_dot(p, b);
    return rotor_make(s, b, ga__v3_add(p, ga__v3_scale(b, mu)), p4 - mu * s);
}

ga_status ga_rotor_normalize(ga_rotor r, ga_rotor *out)
{
    if (!out)
        return GA_ERR_ARG;
    if (!rotor_isfinite(r))
        return GA_ERR_NOTFINITE;
    double m = fmax(fmax(fabs(r.s), fabs(r.e12)), fmax(fabs(r.e13), fabs(r.e23)));
    if (m == 0.0)
        return GA_ERR_NOTRIGID;
    /* scale to |q| ~ 1 first, so that neither |q|^2 nor P / |q| can overflow */
    ga_rotor t = {r.s / m, r.e12 / m, r.e13 / m, r.e23 / m, r.e1n / m, r.e2n / m, r.e3n / m, r.e123n / m};
    /* P / |q| or the projection may overflow (P near DBL_MAX): that rotor is
       rigid but its projection is not representable, GA_ERR_DOMAIN, not
       GA_ERR_NOTRIGID (found by fuzz/fuzz_numeric;
       fuzz/regress/numeric/normalize-overflow-status replays it) */
    if (!rotor_isfinite(t))
        return GA_ERR_DOMAIN;
    ga_rotor o = rotor_project(t, 1.0 / sqrt(t.s * t.s + t.e12 * t.e12 + t.e13 * t.e13 + t.e23 * t.e23));
    /* Once more (q is now unit, k = 1): the projection's e123 update
       p4 - mu s cancels when P ~q has a large e123 part (far from the group),
       leaving <P ~q>_3 at eps |p4| |b|; the second pass removes that (found by
       fuzz/fuzz_numeric: R ~R - 1 was 3.5e-10 for e123n = 5e54;
       fuzz/regress/numeric/normalize-far-e123 replays it). */
    o = rotor_project(o, 1.0);
    /* Each pass leaves about eps of what it removed, so a P ~q whose e123 part
       is r times |q| needs log(r)/log(1/eps) passes: more where r > 1/eps
       (P ~ 1e24 |q|: 2.4e-7 left after two; found by fuzz/fuzz_numeric,
       fuzz/regress/numeric/normalize-subnormal-q-huge-p). A rotor near the
       group stops here, unchanged. At most 40: r < 1e616 (DBL_MAX/DBL_TRUE_MIN). */
    for (int k = 0; k < 40 && rotor_isfinite(o); k++) {
        double psize = sqrt(o.e1n * o.e1n + o.e2n * o.e2n + o.e3n * o.e3n + o.e123n * o.e123n);
        if (2.0 * fabs(rotor_pq3(o)) <= 4 * DBL_EPSILON * fmax(1.0, psize)) /* rotor_drift's P part */
            break;
        o = rotor_project(o, 1.0);
    }
    if (!rotor_isfinite(o))
        return GA_ERR_DOMAIN;
    *out = o;
    return GA_OK;
}

ga_status ga_rotor_from_mv(ga_mv m, double tol, ga_rotor *out)
{
    if (!out)
        return GA_ERR_ARG;
    static const int inside[12] = {GA_BLADE_SCALAR, GA_BLADE_E12, GA_BLADE_E13,   GA_BLADE_E23,
                                   GA_BLADE_E14,    GA_BLADE_E15, GA_BLADE_E24,   GA_BLADE_E25,
                                   GA_BLADE_E34,    GA_BLADE_E35, GA_BLADE_E1234, GA_BLADE_E1235};
    if (!ga_mv_isfinite(m))
        return GA_ERR_NOTFINITE;
    double lim = tol * fmax(1.0, ga_mv_maxabs(m));
    ga_mv rest = m;
    for (int i = 0; i < 12; i++) rest.c[inside[i]] = 0.0;
    if (!(ga_mv_maxabs(rest) <= lim) || !(fabs(m.c[GA_BLADE_E14] - m.c[GA_BLADE_E15]) <= lim) ||
        !(fabs(m.c[GA_BLADE_E24] - m.c[GA_BLADE_E25]) <= lim) ||
        !(fabs(m.c[GA_BLADE_E34] - m.c[GA_BLADE_E35]) <= lim) ||
        !(fabs(m.c[GA_BLADE_E1234] - m.c[GA_BLADE_E1235]) <= lim))
        return GA_ERR_NOTRIGID;
    /* the mean as 0.5 a + 0.5 b: (a + b) overflows for a, b near DBL_MAX and
       made a finite input GA_ERR_NOTFINITE (found by fuzz/fuzz_numeric;
       fuzz/regress/numeric/from-mv-mean-overflow replays it) */
    ga_rotor r = {m.c[GA_BLADE_SCALAR],
                  m.c[GA_BLADE_E12],
                  m.c[GA_BLADE_E13],
                  m.c[GA_BLADE_E23],
                  0.5 * m.c[GA_BLADE_E14] + 0.5 * m.c[GA_BLADE_E15],
                  0.5 * m.c[GA_BLADE_E24] + 0.5 * m.c[GA_BLADE_E25],
                  0.5 * m.c[GA_BLADE_E34] + 0.5 * m.c[GA_BLADE_E35],
                  0.5 * m.c[GA_BLADE_E1234] + 0.5 * m.c[GA_BLADE_E1235]};
    int st = ga_rotor_check(r, tol);
    if (st != GA_OK)
        return st;
    return ga_rotor_normalize(r, out);
}

/* ---- action ---------------------------------------------------------------- */

ga_vec3 ga_rotor_apply(ga_rotor r, ga_vec3 x) { return ga_rotor_apply_inline(r, x); }

ga_status ga_rotor_apply_many(ga_rotor r, const ga_vec3 *in, size_t n, ga_vec3 *out)
{
    /* 9 multiplications and 9 additions a point against ga_rotor_apply's 24 and 25 */
    return ga_mat4_apply_many(ga_rotor_to_mat4_inline(r), in, n, out);
}

ga_mv ga_rotor_apply_mv(ga_rotor r, ga_mv X)
{
    /* R = T_t q: the rotation q X ~q by the generated sandwich (it mixes the
       coefficients of one class of blades only, nothing cancels), then the
       translation exactly, rounded once (gao_translate): the whole sandwich
       at once cancelled terms of the size of t^2 X. t = R(0), over |q|^2 as
       the sandwich scales the rotated part by it. */
    ga_rotor q = {r.s, r.e12, r.e13, r.e23, 0.0, 0.0, 0.0, 0.0};
    ga_mv Y;
    rotor_sandwich_dense(q, X.c, Y.c);
    double qq = r.s * r.s + r.e12 * r.e12 + r.e13 * r.e13 + r.e23 * r.e23;
    if ((r.e1n == 0.0 && r.e2n == 0.0 && r.e3n == 0.0 && r.e123n == 0.0) || !(qq > 0.0))
        return Y; /* a rotation (or no motion at all: q = 0 makes R X ~R 0) */
    ga_vec3 t = ga_rotor_apply(r, ga__v3(0.0, 0.0, 0.0));
    return gao_translate(Y, ga__v3_scale(t, 1.0 / qq));
}

/* ---- constructors ------------------------------------------------------- */

ga_rotor ga_rotor_rotation(ga_vec3 axis, double angle)
{
    double len = ga__v3_norm_scaled(axis);
    if (!(len > 0.0))
        return ga_rotor_identity();
    double h = 0.5 * angle, sh = sin(h) / len;
    /* cos(h) - sin(h) u I3: b = -sin(h) u */
    return rotor_make(cos(h), ga__v3_scale(axis, -sh), ga__v3(0, 0, 0), 0.0);
}

ga_rotor ga_rotor_translation(ga_vec3 a)
{
    /* 1 + n a/2 = 1 - (a/2) n */
    return rotor_make(1.0, ga__v3(0, 0, 0), ga__v3_scale(a, -0.5), 0.0);
}

ga_rotor ga_rotor_twist(double psi, ga_generator plane, ga_vec3 a)
{
    ga_vec3 b = ga__v3(plane.e23, -plane.e13, plane.e12);
    double len = ga__v3_norm_scaled(b);
    ga_rotor rot = ga_rotor_identity();
    if (len > 0.0)
        rot = rotor_make(cos(0.5 * psi), ga__v3_scale(b, sin(0.5 * psi) / len), ga__v3(0, 0, 0), 0.0);
    return ga_rotor_mul(rot, ga_rotor_translation(a));
}

ga_generator ga_twist_to_generator(ga_twist xi)
{
    /* beta = -w/2, c = -v/2; (e12, e13, e23) = (beta_z, -beta_y, beta_x) */
    ga_generator g = {-0.5 * xi.w.z, 0.5 * xi.w.y,  -0.5 * xi.w.x,
                      -0.5 * xi.v.x, -0.5 * xi.v.y, -0.5 * xi.v.z};
    return g;
}

ga_twist ga_generator_to_twist(ga_generator b)
{
    ga_twist xi = {{-2.0 * b.e23, 2.0 * b.e13, -2.0 * b.e12}, {-2.0 * b.e1n, -2.0 * b.e2n, -2.0 * b.e3n}};
    return xi;
}

/* ---- exp and log ------------------------------------------------------- */

/* cos, sinc and k as series; pi/2 in two parts (as the screw sampler of interp/group_cga.c) */
#include "internal/series.h"

ga_rotor ga_rotor_exp(ga_generator g)
{
    ga_vec3 beta = ga__v3(g.e23, -g.e13, g.e12), c = ga__v3(g.e1n, g.e2n, g.e3n);
    double phi2 = ga__v3_dot(beta, beta), bc = ga__v3_dot(beta, c), cs, sinc;
    ga_vec3 p;
    if (phi2 <= (GA_PI / 4) * (GA_PI / 4)) {
        /* phi <= pi/4: the series, no trig call and no division */
        double y2 = phi2 * phi2, y4 = y2 * y2, y8 = y4 * y4;
        cs = ga__series_estrin9(GA__SERIES_F0, phi2, y2, y4, y8);
        sinc = ga__series_estrin9(GA__SERIES_F1, phi2, y2, y4, y8);
        double k = ga__series_estrin9(GA__SERIES_K, phi2, y2, y4, y8);
        /* P = cos c_par + sinc c_perp + sinc (beta.c) I = sinc c + k (beta.c) beta + I sinc (beta.c) */
        p = ga__v3_add(ga__v3_scale(c, sinc), ga__v3_scale(beta, k * bc));
    } else if (isinf(phi2)) {
        /* phi = |beta| beyond ~1.3e154 (a twist's angle beyond ~2.7e154),
         * where phi^2 overflows (and gave NaN): the scaled norm, the unit
         * axis u = beta / phi, c_par = (u.c) u and sinc (beta.c) =
         * sin phi (u.c), so that libm's sin and cos see the angle, as
         * ga_se3_exp does; the rotation is exact for the double angle, but
         * an angle that large is known only to its ulp (>= 2 from 2^53) */
        ga_vec3 bs = ga__v3_scale(beta, 0x1p-600);
        double ns = sqrt(ga__v3_dot(bs, bs)), phi = ns * 0x1p600, sn = sin(phi);
        ga_vec3 u = ga__v3_div(bs, ns);
        double uc = ga__v3_dot(u, c);
        cs = cos(phi);
        sinc = sn / phi;
        p = ga__v3_add(ga__v3_scale(c, sinc), ga__v3_scale(u, (cs - sinc) * uc));
        return rotor_make(cs, ga__v3_scale(u, sn), p, sn * uc);
    } else {
        double phi = sqrt(phi2), m = bc / phi2; /* c_par = m beta */
        if (phi <= 3 * GA_PI / 4) {
            /* with r = pi/2 - phi in [-pi/4, pi/4], sin phi = cos r and
             * cos phi = r sinc r, the same series; GA_PIO2_HI - phi is exact
             * (Sterbenz), so r is pi/2 - phi to an ulp of r and cos phi keeps
             * its relative accuracy where it vanishes, at phi = pi/2 */
            double r = (GA_PIO2_HI - phi) + GA_PIO2_LO, y = r * r, y2 = y * y, y4 = y2 * y2, y8 = y4 * y4;
            cs = r * ga__series_estrin9(GA__SERIES_F1, y, y2, y4, y8);
            sinc = ga__series_estrin9(GA__SERIES_F0, y, y2, y4, y8) / phi;
        } else { /* a rotation by more than 3 pi/2: libm reduces the angle */
            cs = cos(phi);
            sinc = sin(phi) / phi;
        }
        /* P = sinc c + (cos - sinc) c_par: for phi >= pi/4 the difference
         * loses at most 2.3 bits of its own, which is an absolute error of
         * a few 2^-53 |c_par|, as large as the rounding of sinc c anyway */
        p = ga__v3_add(ga__v3_scale(c, sinc), ga__v3_scale(beta, (cs - sinc) * m));
    }
    return rotor_make(cs, ga__v3_scale(beta, sinc), p, sinc * bc);
}

/* atan2(y, x) for y > 0 and x >= 0, in [0, pi/2], without a call: with
 * a = j pi/8 the multiple of pi/8 nearest the angle (j counted from
 * comparisons of y with x tan((2j+1) pi/16), no division),
 * z = tan(angle - a) = (y cos a - x sin a) / (x cos a + y sin a) is at most
 * tan(pi/16) = 0.199 in magnitude (a little more where the comparisons
 * round), and atan z its Taylor series to z^23, whose first omitted term is
 * below 3e-19 of z. For j = 0 (cos a = 1, sin a = 0) z = y/x, so small angles
 * keep their relative accuracy; otherwise the angle is at least pi/16 and
 * has an absolute error of a few 2^-53. */
static inline double atan2_quadrant(double y, double x)
{
    static const double bound[4] = {0.19891236737965801, 0.66817863791929888, 1.4966057626654889,
                                    5.0273394921258463};
    static const double cos_a[5] = {1.0, 0.92387953251128674, 0.70710678118654757, 0.38268343236508984, 0.0};
    static const double sin_a[5] = {0.0, 0.38268343236508978, 0.70710678118654746, 0.92387953251128674, 1.0};
    static const double a[5] = {0.0, 0.39269908169872414, 0.78539816339744828, 1.1780972450961724,
                                1.5707963267948966};
    static const double atan_taylor[12] = {1.0,      -1.0 / 3,  1.0 / 5,  -1.0 / 7,  1.0 / 9,  -1.0 / 11,
                                           1.0 / 13, -1.0 / 15, 1.0 / 17, -1.0 / 19, 1.0 / 21, -1.0 / 23};
    int j = (y > bound[0] * x) + (y > bound[1] * x) + (y > bound[2] * x) + (y > bound[3] * x);
    double z = (y * cos_a[j] - x * sin_a[j]) / (x * cos_a[j] + y * sin_a[j]);
    double w = z * z, w2 = w * w, w4 = w2 * w2, w8 = w4 * w4;
    const double *c = atan_taylor;
    double poly = ga__estrin9(c, w, w2, w4, 0.0) + w8 * ((c[8] + c[9] * w) + w2 * (c[10] + c[11] * w));
    return a[j] + z * poly;
}

#if defined(__GNUC__)
#define ROTOR_COLD __attribute__((noinline, cold))
#define ROTOR_UNLIKELY(x) __builtin_expect(!!(x), 0)
#else
#define ROTOR_COLD
#define ROTOR_UNLIKELY(x) (x)
#endif

/* Every case of ga_rotor_log and ga_rotor_log_literal: the rare ones (far
 * from the group, not finite, |b| < 2^-450, a full turn) and the literal log
 * of s < 0 (through rotor_log_cold); the principal log's common case is
 * rotor_log_principal below. */
static inline int rotor_log(ga_rotor r, int principal, ga_generator *out)
{
    if (!rotor_near_group(r)) { /* rare: decide as ga_rotor_check does */
        if (!rotor_isfinite(r))
            return GA_ERR_NOTFINITE;
        if (!(rotor_drift(r) <= GA_ROTOR_DRIFT_MAX))
            return GA_ERR_NOTRIGID;
    }
    ga_vec3 b = rotor_b(r), beta, c;
    double nb2 = ga__v3_dot(b, b);
    if (nb2 >= 0x1p-900) {
        /* The common case, |b| >= 2^-450 (so 1/|b| is finite): l of the
         * projection R (R ~R)^(-1/2), computed from R itself. Projecting
         * (rotor_project) scales q and P by k = 1/|q| and adds mu (b - I s) to
         * P, along the axis and in its e123 part only. That changes neither
         * the angle phi = atan2(|b|, s) nor the axis u = b/|b|, nor
         * c_perp = (phi/|b|) p_perp (the k of p_perp cancels the 1/k of
         * phi/|b|), and it scales c.u = cos(phi) (p.u) + sin(phi) p4 (below)
         * by exactly 1/|q|^2 (the mu terms cancel): no sqrt for |q|, no
         * projected copy. The principal log takes -R when <R>_0 < 0. */
        double sg = principal && r.s < 0.0 ? -1.0 : 1.0, q2 = r.s * r.s + nb2;
        double s = sg * r.s, nb = sqrt(nb2), inv = 1.0 / nb;
        /* the angle in [0, pi/2] for the principal log; the literal log's
           s < 0 gives pi - atan2(nb, -s), with pi = 2 GA_PIO2_HI + 2 GA_PIO2_LO */
        double phi = s >= 0.0 ? atan2_quadrant(nb, s)
                              : (2 * GA_PIO2_HI - atan2_quadrant(nb, -s)) + 2 * GA_PIO2_LO;
        ga_vec3 u = ga__v3_scale(b, sg * inv), p = ga__v3_scale(rotor_p(r), sg);
        double pu = ga__v3_dot(p, u);
        double cpar = (s * pu + nb * (sg * r.e123n)) / q2;
        ga_vec3 pperp = ga__v3_sub(p, ga__v3_scale(u, pu));
        beta = ga__v3_scale(u, phi);
        ga_vec3 cperp = ga__v3_scale(pperp, phi * inv);
        /* pperp is perpendicular to u only to rounding of |p|; near a full
           turn (the literal log, s < 0) phi / |b| ~ pi / (pi - phi) magnifies
           that along u, where exp does not damp it (the translation along the
           axis): 2.4e-12 of |p| at pi - phi = 1e-4 in exp(l(R)) - R. Taken
           out again, it is rounding of |c_perp|. */
        if (!principal && s < 0.0) /* (the principal log has s >= 0) */
            cperp = ga__v3_sub(cperp, ga__v3_scale(u, ga__v3_dot(cperp, u)));
        c = ga__v3_add(cperp, ga__v3_scale(u, cpar));
        /* finite when rotor_near_group(r) (|p| <= 1e150, phi/|b| <= pi 2^450);
         * past it, as below: x - x is 0 for finite x, NaN for Inf and NaN */
        if (!((c.x - c.x) + (c.y - c.y) + (c.z - c.z) == 0.0))
            return GA_ERR_DOMAIN;
        ga_generator g = {beta.z, -beta.y, beta.x, c.x, c.y, c.z};
        *out = g;
        return GA_OK;
    }
    /* project onto the group; the principal log takes -R when <R>_0 < 0, by
     * the sign of the projection's scale */
    double k = 1.0 / sqrt(r.s * r.s + r.e12 * r.e12 + r.e13 * r.e13 + r.e23 * r.e23);
    r = rotor_project(r, principal && r.s < 0.0 ? -k : k);
    ga_vec3 p = rotor_p(r);
    b = rotor_b(r);
    /* nb = sin(phi) = |b|, b = sin(phi) u. |b| <= 1 after the projection, so
     * b.b cannot overflow; for |b| >= 2^-450 it does not underflow either,
     * its plain sqrt is exact to rounding and 1/|b| is finite. Below that,
     * the scaled norm, and divisions (a subnormal |b| has no finite reciprocal). */
    nb2 = ga__v3_dot(b, b);
    int big = nb2 >= 0x1p-900;
    double nb = big ? sqrt(nb2) : ga__v3_norm_scaled(b);
    if (nb == 0.0) {
        if (r.s > 0.0) { /* q = 1: a pure translation, P = c */
            beta = ga__v3(0, 0, 0);
            c = p;
        } else { /* q = -1: a turn of 2 pi; P = cos(pi) c_par, so the axis is along p */
            double np = ga__v3_norm_scaled(p);
            ga_vec3 u = np > 0.0 ? ga__v3_div(p, np) : ga__v3(0, 0, 1);
            beta = ga__v3_scale(u, GA_PI);
            c = ga__v3_scale(p, -1.0);
        }
    } else {
        double phi = atan2(nb, r.s), f; /* f = phi / sin(phi) = 1 / sinc(phi) */
        ga_vec3 u;
        if (big) {
            double inv = 1.0 / nb;
            u = ga__v3_scale(b, inv);
            f = phi * inv;
        } else {
            /* u from b scaled up by 2^600 (exact): nb itself may be subnormal,
               rounded to a few bits, and b / nb then not a unit vector (found by
               fuzz/fuzz_numeric: 0.4% off for a rotation of 1e-321 rad;
               fuzz/regress/numeric/log-subnormal-rotation-axis replays it) */
            ga_vec3 bs = ga__v3_scale(b, 0x1p600);
            u = ga__v3_div(bs, sqrt(ga__v3_dot(bs, bs)));
            f = phi / nb;
        }
        double pu = ga__v3_dot(p, u);
        /* P = cos c_par + sinc c_perp + I sin (c.u): c.u = cos (p.u) + sin p4 */
        double cpar = r.s * pu + nb * r.e123n;
        ga_vec3 pperp = ga__v3_sub(p, ga__v3_scale(u, pu));
        beta = ga__v3_scale(u, phi);
        /* when f = phi / nb overflows (a literal log within 1e-308 of a full
           turn), (pperp phi) / nb: 0 for pperp = 0, else Inf, reported below */
        c = ga__v3_add(isfinite(f) ? ga__v3_scale(pperp, f) : ga__v3_div(ga__v3_scale(pperp, phi), nb),
                       ga__v3_scale(u, cpar));
    }
    /* A generator beyond the range of double (a translation near DBL_MAX, or
       the literal log's translation across the axis divided by sin(phi) -> 0
       near a full turn) is reported, never returned as Inf or NaN (found by
       fuzz/fuzz_numeric; fuzz/regress/numeric/log-translation-overflow and
       literal-log-near-full-turn replay it). */
    if (!(isfinite(c.x) && isfinite(c.y) && isfinite(c.z)))
        return GA_ERR_DOMAIN;
    ga_generator g = {beta.z, -beta.y, beta.x, c.x, c.y, c.z};
    *out = g;
    return GA_OK;
}

/* rotor_log out of line; r by pointer, so that the hot path's caller does
 * not copy the rotor for a call it rarely makes */
static ROTOR_COLD int rotor_log_cold(const ga_rotor *r, int principal, ga_generator *out)
{
    return rotor_log(*r, principal, out);
}

/* The principal log's common case, s >= 0 taken as it is and s < 0 as -R:
 * r near the group (the test of rotor_near_group, the same operations) and
 * |b| >= 2^-450; anything else goes to rotor_log. Its steps
 * (docs/numerics.md, "The rotor logarithm"):
 *  - |q| = (1 + d)^(1/2), d = |q|^2 - 1, |d| <= GA_ROTOR_DRIFT_MAX: 1/|q| and
 *    1/|q|^2 from their series to d^2 (the first omitted term below 4e-19);
 *  - the half angle phi = atan2(|b|, |s|) in [0, pi/2] as a + asin(sigma):
 *    a = j pi/16 (rounded) the multiple nearest phi (j counts the k with
 *    |b|^2 > tan^2((2k+1) pi/32) s^2: no sqrt, no division), and
 *    sigma = sin(phi - a) = (|b| cos a - |s| sin a) / |q|, |sigma| <= sin(pi/32)
 *    (a little more where the comparisons round); asin by its Taylor series to
 *    sigma^15, whose first omitted term is below 1e-18 of sigma. For j = 0,
 *    sigma = |b| / |q| and small angles keep their relative accuracy; a
 *    rotor made from the angle a itself (cos a, sin a: 45 or 90 degrees) has
 *    sigma = 0 and phi = a;
 *  - beta = phi u, u = b / |b|, and with F = phi / |b|,
 *    c = F p + H b with H b = (c.u - F p.u) u (step 5 of numerics.md:
 *    c.u = (s p.u + |b| p4) / |q|^2): c_perp = F p_perp and c_par, without
 *    forming p_perp. Every term is finite: |p| <= 1e150 and F <= pi 2^449.
 * One sqrt and one division (1/|b|), the sector found while the sqrt runs. */
static const double log_sector_t2[8] = {0.009700556535263626, 0.09201921045557308, 0.28570215445540564,
                                        0.673513677715992,    1.4847508418703281,  3.5001486142313527,
                                        10.867296024918627,   103.08686891981746}; /* tan^2((2k+1) pi/32) */
static const struct {
    double c, s, a; /* a = j pi/16 rounded, cos a and sin a rounded (libm's) */
} log_sector[9] = {{1.0, 0.0, 0.0},
                   {0.9807852804032304, 0.19509032201612825, 0.19634954084936207},
                   {0.9238795325112867, 0.3826834323650898, 0.39269908169872414},
                   {0.8314696123025452, 0.5555702330196022, 0.5890486225480862},
                   {0.7071067811865476, 0.7071067811865475, 0.7853981633974483},
                   {0.5555702330196023, 0.8314696123025452, 0.9817477042468103},
                   {0.38268343236508984, 0.9238795325112867, 1.1780972450961724},
                   {0.19509032201612833, 0.9807852804032304, 1.3744467859455345},
                   {6.123233995736766e-17, 1.0, 1.5707963267948966}};
/* asin(x) / x = sum_k (2k)! / (4^k (k!)^2 (2k + 1)) x^(2k) */
static const double asin_taylor[8] = {1.0,           1.0 / 6,       3.0 / 40,        5.0 / 112,
                                      35.0 / 1152.0, 63.0 / 2816.0, 231.0 / 13312.0, 143.0 / 10240.0};

#if defined(__GNUC__)
typedef double rotor_v2d __attribute__((vector_size(16)));
typedef long long rotor_v2i __attribute__((vector_size(16)));
#endif

/* gcc's SLP vectorizer packed the rotor's doubles in pairs and out again
 * (205 instructions a call against 191, and in one build of garotor-bench
 * twice the time), and math-errno kept a call to libm's sqrt for a negative
 * argument (never here) with its spills: the functions of the common case
 * are built without both (the same operations, the same bits). */
#if defined(__GNUC__) && !defined(__clang__)
#define ROTOR_LOG_FLAGS __attribute__((optimize("no-tree-slp-vectorize", "no-math-errno")))
#else
#define ROTOR_LOG_FLAGS
#endif

/* j: how many of tan^2((2k+1) pi/32) s2 lie below nb2 (the same
 * comparisons in pairs where the compiler has vectors) */
ROTOR_LOG_FLAGS static inline int log_sector_of(double nb2, double s2)
{
#if defined(__GNUC__)
    rotor_v2d n = {nb2, nb2}, q = {s2, s2}, t[4];
    for (int k = 0; k < 4; k++) t[k] = (rotor_v2d){log_sector_t2[2 * k], log_sector_t2[2 * k + 1]};
    rotor_v2i m = ((n > t[0] * q) + (n > t[1] * q)) + ((n > t[2] * q) + (n > t[3] * q));
    return (int)-(m[0] + m[1]);
#else
    int j = 0;
    for (int k = 0; k < 8; k++) j += nb2 > log_sector_t2[k] * s2;
    return j;
#endif
}

ROTOR_LOG_FLAGS static inline ga_status rotor_log_principal(const ga_rotor *rp, ga_generator *out)
{
    double rs = rp->s;
    double bx = rp->e23, e13 = rp->e13, bz = rp->e12; /* b = (bx, -e13, bz) */
    double px = rp->e1n, py = rp->e2n, pz = rp->e3n, p4 = rp->e123n;
    const double tol = GA_ROTOR_DRIFT_MAX;
    /* rotor_near_group's test, operation for operation */
    double s2 = rs * rs, q2 = s2 + bz * bz + e13 * e13 + bx * bx;
    double p2 = px * px + py * py + pz * pz + p4 * p4;
    double pb = px * bx - py * e13 + pz * bz, pq3 = rs * p4 - pb;
    double nb2 = bx * bx + e13 * e13 + bz * bz, d = q2 - 1.0;
    if (ROTOR_UNLIKELY(!(p2 <= 1e300 && fabs(d) <= tol &&
                         4.0 * pq3 * pq3 <= tol * tol * (p2 > 1.0 ? p2 : 1.0) && nb2 >= 0x1p-900)))
        return rotor_log_cold(rp, 1, out);
    int j = log_sector_of(nb2, s2);
    double iq = 1.0 + d * (-0.5 + d * 0.375), iq2 = 1.0 + d * (d - 1.0); /* 1/|q|, 1/|q|^2 */
    double nb = sqrt(nb2), inv = 1.0 / nb;
    double sg = copysign(1.0, rs + 0.0); /* -0.0 counts as +0.0 */
    double sig = (nb * log_sector[j].c - fabs(rs) * log_sector[j].s) * iq, x = sig * sig, x2 = x * x,
           x4 = x2 * x2;
    const double *c = asin_taylor;
    double asn = ((c[0] + c[1] * x) + x2 * (c[2] + c[3] * x)) +
                 x4 * ((c[4] + c[5] * x) + x2 * (c[6] + c[7] * x));
    /* phi with the sign of s (-R for s < 0); beta = phi u with u = b / |b|
     * (u rounds to exactly +-1 for most rotations about a basis axis, and
     * then beta = phi) */
    double phi = sg * (log_sector[j].a + sig * asn), F = phi * inv;
    double pu = pb * inv, H = ((rs * pu + nb * p4) * iq2 - F * pu) * inv;
    ga_generator g = {(bz * inv) * phi, (e13 * inv) * phi, (bx * inv) * phi,
                      F * px + H * bx,  F * py - H * e13,  F * pz + H * bz};
    *out = g;
    return GA_OK;
}

ROTOR_LOG_FLAGS ga_status ga_rotor_log(ga_rotor r, ga_generator *out)
{
    return out ? rotor_log_principal(&r, out) : GA_ERR_ARG;
}
ROTOR_LOG_FLAGS ga_status ga_rotor_log_literal(ga_rotor r, ga_generator *out)
{
    if (!out)
        return GA_ERR_ARG;
    /* for s >= 0 the literal log is the principal one */
    return r.s >= 0.0 ? rotor_log_principal(&r, out) : rotor_log_cold(&r, 0, out);
}

/* ---- screws ---------------------------------------------------------------- */

ga_status ga_rotor_to_screw(ga_rotor r, ga_screw *out)
{
    if (!out)
        return GA_ERR_ARG;
    ga_generator g;
    int st = ga_rotor_log(r, &g);
    if (st != GA_OK)
        return st;
    ga_twist xi = ga_generator_to_twist(g);
    ga_vec3 w = xi.w, v = xi.v;
    double th = ga__v3_norm_scaled(w), nv = ga__v3_norm_scaled(v);
    ga_screw s = {0, {0, 0, 1}, {0, 0, 0}, 0, 0};
    if (th == 0.0) {
        if (nv > 0.0) {
            s.axis = ga__v3_div(v, nv);
            s.shift = nv;
            s.pitch = INFINITY;
        }
    } else {
        ga_vec3 u = ga__v3_div(w, th);
        s.angle = th;
        s.axis = u;
        s.shift = ga__v3_dot(u, v);
        s.point = ga__v3_div(ga__v3_cross(u, v), th);
        s.pitch = s.shift / th;
        if (!isfinite(s.pitch))
            return GA_ERR_DOMAIN;
    }
    /* the twist is twice the generator and may overflow where the generator
       did not (a translation beyond DBL_MAX / 2): report it, never return
       Inf or NaN (found by fuzz/fuzz_numeric;
       fuzz/regress/numeric/screw-translation-overflow replays it) */
    if (!isfinite(s.shift) || !isfinite(s.point.x) || !isfinite(s.point.y) || !isfinite(s.point.z) ||
        !isfinite(s.axis.x) || !isfinite(s.axis.y) || !isfinite(s.axis.z))
        return GA_ERR_DOMAIN;
    *out = s;
    return GA_OK;
}

ga_rotor ga_rotor_from_screw(ga_screw s)
{
    ga_vec3 u = s.axis;
    double len = ga__v3_norm_scaled(u);
    if (!(len > 0.0))
        return ga_rotor_identity();
    u = ga__v3_div(u, len);
    if (s.angle == 0.0)
        return ga_rotor_translation(ga__v3_scale(u, s.shift));
    /* w = angle u, v = -w x point + shift u */
    ga_vec3 w = ga__v3_scale(u, s.angle);
    ga_twist xi = {w, ga__v3_add(ga__v3_cross(s.point, w), ga__v3_scale(u, s.shift))};
    return ga_rotor_exp(ga_twist_to_generator(xi));
}

/* ---- the bridge ----------------------------------------------------------- */

ga_quat ga_rotor_to_quat(ga_rotor r) { return (ga_quat){r.s, -r.e23, r.e13, -r.e12}; }

ga_vec3 ga_rotor_to_translation(ga_rotor r) { return ga_rotor_to_translation_inline(r); }

ga_rotor ga_rotor_from_quat(ga_quat q, ga_vec3 t) { return ga_rotor_from_quat_inline(q, t); }

ga_mat4 ga_rotor_to_mat4(ga_rotor r) { return ga_rotor_to_mat4_inline(r); }

ga_status ga_rotor_from_mat4(ga_mat4 mm, ga_rotor *out)
{
    return out ? ga_rotor_from_mat4_inline(mm, out) : GA_ERR_ARG;
}

ga_dualquat ga_rotor_to_dualquat(ga_rotor r)
{
    ga_dualquat d = {{r.s, -r.e23, r.e13, -r.e12}, {-r.e123n, -r.e1n, -r.e2n, -r.e3n}};
    return d;
}

ga_rotor ga_rotor_from_dualquat(ga_dualquat d)
{
    ga_rotor r = {d.real.w, -d.real.z, d.real.y, -d.real.x, -d.dual.x, -d.dual.y, -d.dual.z, -d.dual.w};
    return r;
}

ga_status ga_quat_normalize(ga_quat q, double tol, ga_quat *out)
{
    if (!out)
        return GA_ERR_ARG;
    if (!(tol >= 0.0 && tol <= GA_SE3_NORMALIZE_TOL))
        return GA_ERR_ARG;
    if (!isfinite(q.w) || !isfinite(q.x) || !isfinite(q.y) || !isfinite(q.z))
        return GA_ERR_NOTFINITE;
    double norm = sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
    if (!(fabs(norm - 1.0) <= tol))
        return GA_ERR_NOTRIGID;
    *out = (ga_quat){q.w / norm, q.x / norm, q.y / norm, q.z / norm};
    return GA_OK;
}
