/* tests/soak_chain.c: a chain of ten million small motions, and the drift
 * the library's normalisation leaves.
 *
 *   soak_chain [N]      (default 1e7)
 *
 * One small screw M = exp(B(xi)), rotation 1e-3 rad, translation 1e-3 across
 * the axis and 1e-6 along it, is composed N times: R_k = normalize(M R_{k-1})
 * (ga_rotor_mul, then ga_rotor_normalize, every step). Beside it the same
 * chain without normalisation, and the reference: the same products of the
 * same double M in long double dual quaternions (ga_rotor_to_dualquat is an
 * algebra isomorphism, rotor.h). The reference's own rounding is that of a
 * 64-bit mantissa, 2^-64 = 5e-20 a product; even added up linearly over 1e7
 * products (16 roundings each) it stays below 2e-11, and as a random walk
 * (what it is) near 1e-16: far below what is measured in double.
 *
 * At 20 checkpoints it measures, for both double chains:
 *   group  max(| |q|^2 - 1 |, 2 |q.d| / max(1, |d|)) of the dual quaternion
 *          (q.d = 0 on the group: R ~R - 1 in other words);
 *   pose   the largest distance between where the chain and the reference
 *          take the points 0, e1, e2, e3, each taken as the rigid motion it
 *          stands for (ldq_project).
 * Bounds asserted (normalised chain):
 *   group <= 4 EPS: normalisation projects onto the group to rounding every
 *          step, so nothing may build up;
 *   pose  <= k (16 EPS) (1 + 2 T), k the steps so far, T the largest
 *          translation along the chain: each step rounds its 8 outputs (a sum
 *          of 8 products each) and normalises (a few roundings), at most
 *          16 EPS relative to the rotor's size, and an error of the rotation
 *          moves a point at distance up to 1 + T from the origin by that many
 *          times more; errors of a rigid motion composed with exact rigid
 *          motions add (left multiplication by M is an isometry of the
 *          rotation part and shifts translations by the rotated error), so
 *          the worst case grows linearly in k.
 * The measured figures (printed) are the real result; the linear bound is a
 * net that could only fail if the errors stopped cancelling, or grew faster
 * than linearly. The unnormalised chain is reported only: its group error
 * is the drift normalisation removes. */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "testkit.h"

#define EPS DBL_EPSILON

typedef struct {
    long double w, x, y, z;
} lq;
typedef struct {
    lq r, d;
} ldq;

static lq lq_of(ga_quat q) { return (lq){q.w, q.x, q.y, q.z}; }
static lq lq_mul(lq a, lq b)
{
    return (lq){a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z, a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
                a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x, a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}
static lq lq_add(lq a, lq b) { return (lq){a.w + b.w, a.x + b.x, a.y + b.y, a.z + b.z}; }
static lq lq_conj(lq a) { return (lq){a.w, -a.x, -a.y, -a.z}; }
static ldq ldq_of(ga_rotor R)
{
    ga_dualquat q = ga_rotor_to_dualquat(R);
    return (ldq){lq_of(q.real), lq_of(q.dual)};
}
static ldq ldq_mul(ldq a, ldq b)
{
    return (ldq){lq_mul(a.r, b.r), lq_add(lq_mul(a.r, b.d), lq_mul(a.d, b.r))};
}
/* Where the motion takes x: rotate by r, then translate by t = 2 d conj(r). */
static void ldq_apply(ldq m, const long double x[3], long double out[3])
{
    lq p = {0, x[0], x[1], x[2]};
    lq rx = lq_mul(lq_mul(m.r, p), lq_conj(m.r));
    lq t = lq_mul(m.d, lq_conj(m.r));
    out[0] = rx.x + 2 * t.x;
    out[1] = rx.y + 2 * t.y;
    out[2] = rx.z + 2 * t.z;
}

static double group_err(ldq q)
{
    long double n2 = q.r.w * q.r.w + q.r.x * q.r.x + q.r.y * q.r.y + q.r.z * q.r.z;
    long double dot = q.r.w * q.d.w + q.r.x * q.d.x + q.r.y * q.d.y + q.r.z * q.d.z;
    long double dn = sqrtl(q.d.w * q.d.w + q.d.x * q.d.x + q.d.y * q.d.y + q.d.z * q.d.z);
    return (double)fmaxl(fabsl(n2 - 1), 2 * fabsl(dot) / fmaxl(1, dn));
}

/* The rigid motion a dual quaternion near the group stands for: r / |r|, and
 * d / |r| less its part along r (in long double). The reference needs it as
 * much as the chains: it is the exact product of the rounded M, whose |q| is
 * 1 + O(EPS), so its own norm drifts like k EPS. */
static ldq ldq_project(ldq q)
{
    long double n = sqrtl(q.r.w * q.r.w + q.r.x * q.r.x + q.r.y * q.r.y + q.r.z * q.r.z);
    lq r = {q.r.w / n, q.r.x / n, q.r.y / n, q.r.z / n};
    lq d = {q.d.w / n, q.d.x / n, q.d.y / n, q.d.z / n};
    long double dot = r.w * d.w + r.x * d.x + r.y * d.y + r.z * d.z;
    return (ldq){r, {d.w - dot * r.w, d.x - dot * r.x, d.y - dot * r.y, d.z - dot * r.z}};
}

/* Where R and the reference take the points 0, e1, e2, e3, as rigid motions. */
static double pose_err(ga_rotor R, ldq ref)
{
    static const long double pts[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    ldq a = ldq_project(ldq_of(R));
    ref = ldq_project(ref);
    double worst = 0;
    for (int i = 0; i < 4; i++) {
        long double x[3], y[3];
        ldq_apply(a, pts[i], x);
        ldq_apply(ref, pts[i], y);
        long double d = sqrtl((x[0] - y[0]) * (x[0] - y[0]) + (x[1] - y[1]) * (x[1] - y[1]) +
                              (x[2] - y[2]) * (x[2] - y[2]));
        worst = fmax(worst, (double)d);
    }
    return worst;
}

int main(int argc, char **argv)
{
    long n = argc > 1 ? atol(argv[1]) : 10000000L;
    if (n < 20) {
        fprintf(stderr, "soak_chain: N >= 20\n");
        return 2;
    }
    /* rotation 1e-3 rad about (1, 2, 2)/3; translation 1e-3 across the axis,
       1e-6 along it: a circle of radius ~1 climbing 1e-6 a step */
    ga_vec3 u = {1.0 / 3, 2.0 / 3, 2.0 / 3}, across = {2.0 / 3, 1.0 / 3, -2.0 / 3};
    ga_twist xi = {
        tk_scale(u, 1e-3),
        {1e-3 * across.x + 1e-6 * u.x, 1e-3 * across.y + 1e-6 * u.y, 1e-3 * across.z + 1e-6 * u.z}};
    ga_rotor M = ga_rotor_exp(ga_twist_to_generator(xi));
    ldq Mq = ldq_of(M), ref = ldq_of(ga_rotor_identity());
    ga_rotor R = ga_rotor_identity(), raw = R;
    double T = 0, w_raw_group = 0, w_raw_pose = 0;
    tk_check c_group = tk_begin("normalised chain: group error at the checkpoints", 4 * EPS);
    tk_check c_pose = tk_begin("normalised chain: pose error <= k 16 EPS (1 + 2 T)", 0);
    printf("soak_chain: %ld steps of a screw of 1e-3 rad, 1e-3 across, 1e-6 along\n", n);
    printf("%10s %12s %12s %12s %12s %9s\n", "steps", "group", "pose", "raw group", "raw pose", "|t|");
    for (long k = 1; k <= n; k++) {
        ga_rotor P = ga_rotor_mul(M, R);
        int st = ga_rotor_normalize(P, &R);
        if (st != GA_OK) {
            tk_expect_status("ga_rotor_normalize along the chain", st, GA_OK);
            return tk_finish("soak_chain");
        }
        raw = ga_rotor_mul(M, raw);
        ref = ldq_mul(Mq, ref);
        if (k % (n / 20) == 0 || k == n) {
            ga_vec3 t = ga_rotor_to_translation(R);
            T = fmax(T, tk_norm(t));
            double g = group_err(ldq_of(R)), p = pose_err(R, ref);
            double rg = group_err(ldq_of(raw)), rp = pose_err(raw, ref);
            w_raw_group = fmax(w_raw_group, rg);
            w_raw_pose = fmax(w_raw_pose, rp);
            printf("%10ld %12.3e %12.3e %12.3e %12.3e %9.3g\n", k, g, p, rg, rp, tk_norm(t));
            tk_add(&c_group, g);
            tk_add_tol(&c_pose, p, (double)k * 16 * EPS * (1 + 2 * T));
        }
    }
    tk_end(&c_group);
    tk_end(&c_pose);
    printf("     (group error %.2f EPS; pose bound at the end %.3e)\n", c_group.worst / EPS,
           (double)n * 16 * EPS * (1 + 2 * T));
    printf("unnormalised chain (reported only): worst group error %.3e, worst pose error %.3e\n", w_raw_group,
           w_raw_pose);
    return tk_finish("soak_chain");
}
