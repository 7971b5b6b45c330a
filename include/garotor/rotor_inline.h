/* garotor/rotor_inline.h: the hot path of rotor.h, inline.
 *
 *   #include <garotor/rotor_inline.h>
 *
 * Each function here is the body of the library function of the same name
 * without the _inline suffix: ga_rotor_mul (rotor.c) is
 * `return ga_rotor_mul_inline(a, b);`, so the two give the same bits, and
 * the linkable symbols stay for function pointers, other languages and
 * callers that do not want the code in their own object (the pair of cglm's
 * glm_ and glmc_ functions). Inline, the compiler keeps the 64-byte rotors in
 * registers and schedules the arithmetic with the caller's (docs/benchmarks.md
 * times both: motor_mul against motor_mul_call, motor_apply against
 * motor_apply_call).
 *
 * Contracts, statuses and conventions are those of the functions in rotor.h.
 * The header needs <math.h> (sqrt, isfinite) and so -lm, as the library does.
 */
#ifndef GAROTOR_ROTOR_INLINE_H
#define GAROTOR_ROTOR_INLINE_H

#include <math.h>

#include "rotor.h"
#include "types.h"
#ifdef __cplusplus
extern "C" {
#endif

/* ga_rotor_mul_inline(a, b): the product a b, 48 multiplications, written by
 * gen/generate.py into rotor_mul.h. */
#include "rotor_mul.h"

/** ga_rotor_reverse: ~r = ~q - ~P n. */
static inline ga_rotor ga_rotor_reverse_inline(ga_rotor r)
{
    ga_rotor o = {r.s, -r.e12, -r.e13, -r.e23, -r.e1n, -r.e2n, -r.e3n, r.e123n};
    return o;
}

/** ga_rotor_to_translation: t = -2 <P ~q>_1 = -2 (s p + p4 b + p x b), with
 *  b = (e23, -e13, e12) and p = (e1n, e2n, e3n). */
static inline ga_vec3 ga_rotor_to_translation_inline(ga_rotor r)
{
    double bx = r.e23, by = -r.e13, bz = r.e12;
    ga_vec3 t = {-2.0 * ((r.s * r.e1n + r.e123n * bx) + (r.e2n * bz - r.e3n * by)),
                 -2.0 * ((r.s * r.e2n + r.e123n * by) + (r.e3n * bx - r.e1n * bz)),
                 -2.0 * ((r.s * r.e3n + r.e123n * bz) + (r.e1n * by - r.e2n * bx))};
    return t;
}

/** ga_rotor_apply: the point x moved by r (on the group): q x ~q + t as one
 *  sandwich. In quaternion terms, with q = (s, v), v = (-e23, e13, -e12), and
 *  the dual part d = -(e123n, e1n, e2n, e3n) (so that t = 2 d q*), it is
 *  y = vec((q x + 2 d) q*): m = q x + 2 d, then the vector part of m q*, 24
 *  multiplications and 25 additions (docs/benchmarks.md compares it with a
 *  4x4 matrix's 9 and 9). */
static inline ga_vec3 ga_rotor_apply_inline(ga_rotor r, ga_vec3 x)
{
    /* m = (mx, my, mz; m0) */
    double mx = ((x.x * r.s + x.y * r.e12) + x.z * r.e13) - (r.e1n + r.e1n);
    double my = ((x.y * r.s - x.x * r.e12) + x.z * r.e23) - (r.e2n + r.e2n);
    double mz = ((x.z * r.s - x.x * r.e13) - x.y * r.e23) - (r.e3n + r.e3n);
    double m0 = ((x.x * r.e23 - x.y * r.e13) + x.z * r.e12) - (r.e123n + r.e123n);
    ga_vec3 y = {(r.s * mx + m0 * r.e23) + (mz * r.e13 + r.e12 * my),
                 (r.s * my - m0 * r.e13) + (mz * r.e23 - r.e12 * mx),
                 (r.s * mz + r.e12 * m0) - (r.e23 * my + r.e13 * mx)};
    return y;
}

/** ga_rotor_to_mat4: [Rot(q), t; 0 0 0 1], row-major. */
static inline ga_mat4 ga_rotor_to_mat4_inline(ga_rotor r)
{
    double w = r.s, x = -r.e23, y = r.e13, z = -r.e12;
    ga_vec3 t = ga_rotor_to_translation_inline(r);
    ga_mat4 m = {{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y), t.x, 2 * (x * y + w * z),
                  1 - 2 * (x * x + z * z), 2 * (y * z - w * x), t.y, 2 * (x * z - w * y), 2 * (y * z + w * x),
                  1 - 2 * (x * x + y * y), t.z, 0, 0, 0, 1}};
    return m;
}

/** ga_rotor_from_quat: T_t q, P = -t q / 2 = ((t x b - s t) - I (t.b)) / 2, b = -(x, y, z). */
static inline ga_rotor ga_rotor_from_quat_inline(ga_quat q, ga_vec3 t)
{
    double bx = -q.x, by = -q.y, bz = -q.z;
    ga_rotor r = {q.w,
                  bz,
                  -by,
                  bx,
                  0.5 * ((t.y * bz - t.z * by) - q.w * t.x),
                  0.5 * ((t.z * bx - t.x * bz) - q.w * t.y),
                  0.5 * ((t.x * by - t.y * bx) - q.w * t.z),
                  -0.5 * (t.x * bx + t.y * by + t.z * bz)};
    return r;
}

/** ga_rotor_from_mat4: the checked rotor of a rigid-motion matrix (Shepperd);
 *  statuses as rotor.h says. */
static inline GA_NODISCARD ga_status ga_rotor_from_mat4_inline(ga_mat4 mm, ga_rotor *out)
{
    const double *m = mm.m;
    const double tol = 1e-9;
    for (int i = 0; i < 16; i++)
        if (!isfinite(m[i]))
            return GA_ERR_NOTFINITE;
    if (!(fabs(m[12]) <= tol && fabs(m[13]) <= tol && fabs(m[14]) <= tol && fabs(m[15] - 1.0) <= tol))
        return GA_ERR_NOTRIGID;
    for (int i = 0; i < 3; i++)
        for (int j = i; j < 3; j++) {
            double d = m[i] * m[j] + m[4 + i] * m[4 + j] + m[8 + i] * m[8 + j];
            if (!(fabs(d - (i == j)) <= tol))
                return GA_ERR_NOTRIGID;
        }
    double det = m[0] * (m[5] * m[10] - m[6] * m[9]) - m[1] * (m[4] * m[10] - m[6] * m[8]) +
                 m[2] * (m[4] * m[9] - m[5] * m[8]);
    if (!(det > 0.0))
        return GA_ERR_NOTRIGID;
    /* Shepperd: divide by the largest of 4w^2, 4x^2, 4y^2, 4z^2 */
    double tr = m[0] + m[5] + m[10], w, x, y, z, h;
    if (tr >= m[0] && tr >= m[5] && tr >= m[10]) {
        h = sqrt(1.0 + tr);
        w = 0.5 * h, h = 0.5 / h;
        x = (m[9] - m[6]) * h, y = (m[2] - m[8]) * h, z = (m[4] - m[1]) * h;
    } else if (m[0] >= m[5] && m[0] >= m[10]) {
        h = sqrt(1.0 + m[0] - m[5] - m[10]);
        x = 0.5 * h, h = 0.5 / h;
        w = (m[9] - m[6]) * h, y = (m[1] + m[4]) * h, z = (m[2] + m[8]) * h;
    } else if (m[5] >= m[10]) {
        h = sqrt(1.0 - m[0] + m[5] - m[10]);
        y = 0.5 * h, h = 0.5 / h;
        w = (m[2] - m[8]) * h, x = (m[1] + m[4]) * h, z = (m[6] + m[9]) * h;
    } else {
        h = sqrt(1.0 - m[0] - m[5] + m[10]);
        z = 0.5 * h, h = 0.5 / h;
        w = (m[4] - m[1]) * h, x = (m[2] + m[8]) * h, y = (m[6] + m[9]) * h;
    }
    double k = (w < 0.0 ? -1.0 : 1.0) / sqrt(w * w + x * x + y * y + z * z);
    ga_quat q = {k * w, k * x, k * y, k * z};
    ga_vec3 t = {m[3], m[7], m[11]};
    /* P = t q / 2 sums products of t: a translation near DBL_MAX overflows */
    ga_rotor r = ga_rotor_from_quat_inline(q, t);
    const double c[8] = {r.s, r.e12, r.e13, r.e23, r.e1n, r.e2n, r.e3n, r.e123n};
    for (int i = 0; i < 8; i++)
        if (!isfinite(c[i]))
            return GA_ERR_DOMAIN;
    *out = r;
    return GA_OK;
}

#ifdef __cplusplus
}
#endif
#endif
