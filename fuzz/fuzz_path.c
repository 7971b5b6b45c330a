/* fuzz/fuzz_path.c: libFuzzer target for the interpolation paths (path.h) on
 * every group, with every scheme and evaluator.
 *
 * Input: byte 0 picks the group (cga, matrix, affine) and the scheme; byte 1
 * the evaluator and the number of keys (2..6, whatever the scheme needs, so
 * wrong counts are tried too); byte 2 flags (times raw or as increments; keys
 * as algebra elements through the group's exp, or as perturbed 4x4 matrices
 * through ga_path_init_mat4; velocities or none). Then doubles (fuzz_reader.h)
 * for times, keys, velocities, evaluation times and the Euler step.
 *
 * Invariants, besides "no crash, no sanitizer report, no read or write past
 * the workspace of exactly ga_path_workspace_size bytes":
 *   - every status is a GA_* code; NaN/Inf times or keys give GA_ERR_NOTFINITE
 *     or GA_ERR_ARG, times not increasing GA_ERR_ARG, a wrong key count GA_ERR_ARG;
 *   - GA_OK never comes with a non-finite sample or velocity;
 *   - for a valid path (below), init, eval, velocity and every evaluator
 *     succeed, and every sample is on the group: a rotor to 1e-12
 *     (ga_rotor_check), an SE(3) matrix to 1e-10 (ga_se3_check), an affine
 *     matrix with last row exactly 0 0 0 1; and exact stepping agrees with
 *     direct sampling to 1e-9 plus the path's speed times the gap between
 *     their two time grids (grid_gap below).
 *
 * Valid path: finite times, increasing by spacings in [1e-3, 1e3], |t| <= 1e6;
 * key twists and velocities with components at most 1e3 (cga, matrix) or key
 * generators with entries at most 0.25 (affine: ||X||_1 <= 1, so every
 * relative log is principal); the Euler step in [EULER_FLOOR, 1]. An Euler
 * step below EULER_FLOOR is raised to it before the call (steps down to 1e-9
 * are accepted by the library but cost up to 1e9 products a sample: a fuzzer
 * timeout, not a bug); at most 17 uniform and 8 given-time samples.
 */
#include <float.h>
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "fuzz_check.h"
#include "fuzz_reader.h"
#include <garotor/garotor.h>

#define MAXK 6
/* The smallest Euler step tried: 100 steps a segment. Smaller steps run the
 * same code more often; 1e-3 made this target 10 times slower. */
#define EULER_FLOOR 1e-2

static const ga_group *const groups[3] = {&ga_group_cga, &ga_group_se3, &ga_group_affine};

static int is_status(int st)
{
    return st == GA_OK || st == GA_ERR_NOTFINITE || st == GA_ERR_SINGULAR || st == GA_ERR_NOTPOINT ||
           st == GA_ERR_NOTRIGID || st == GA_ERR_DOMAIN || st == GA_ERR_ARG || st == GA_ERR_NOTBLADE;
}

/* Is a group element finite, and (strict) on its group? */
static int elem_finite(const ga_group *g, const void *e)
{
    return fz_all_finite((const double *)e, (int)(g->elem_size / sizeof(double)));
}

static void check_elem(const ga_group *g, const void *e, int strict, const char *what)
{
    FZ_CHECK(elem_finite(g, e), "%s on %s: GA_OK with a non-finite element", what, g->name);
    if (!strict)
        return;
    if (g == &ga_group_cga) {
        int st = ga_rotor_check(*(const ga_rotor *)e, 1e-12);
        FZ_CHECK(st == GA_OK, "%s on cga: rotor off the group (R ~R != 1 to 1e-12)", what);
    } else if (g == &ga_group_se3) {
        int st = ga_se3_check(*(const ga_mat4 *)e, 1e-10);
        FZ_CHECK(st == GA_OK, "%s on matrix: not rigid to 1e-10", what);
    } else {
        const double *m = ((const ga_mat4 *)e)->m;
        FZ_CHECK(m[12] == 0 && m[13] == 0 && m[14] == 0 && m[15] == 1, "%s on affine: last row not 0 0 0 1",
                 what);
    }
}

/* Distance between two elements as 4x4 matrices, translation relative. */
static double elem_dist(const ga_group *g, const void *a, const void *b)
{
    ga_mat4 x = g->to_mat4(a), y = g->to_mat4(b);
    double s = 1.0, d = 0.0;
    for (int i = 0; i < 3; i++) s = fmax(s, fmax(fabs(x.m[4 * i + 3]), fabs(y.m[4 * i + 3])));
    for (int i = 0; i < 16; i++) d = fmax(d, fabs(x.m[i] - y.m[i]) / (i % 4 == 3 ? s : 1.0));
    return d;
}

/* How far apart in t the samples of exact stepping and of direct sampling can
 * be. Both start from t_k = t0 + k dt rounded to a double (within about
 * 1.5 ulp(T) of the exact grid point, T the largest |t|); direct evaluates
 * there, exact stepping only at its anchors (each new segment, every
 * GA_PATH_EXACT_REANCHOR samples) and in between advances u by the fixed
 * dt / h, which adds a relative 2 DBL_EPSILON of dt a step and DBL_EPSILON of
 * h at the anchor. At |t| near 1e6 the gap is about 1e-10, which a path
 * moving at 10 per unit t turns into 1e-9 (fuzz/regress/path/
 * exact-vs-direct-time-grid: 1.06e-9; the stepper against direct evaluation
 * at its own times there: 2.2e-15). */
static double grid_gap(double t0, double t1)
{
    double T = fmax(fmax(fabs(t0), fabs(t1)), t1 - t0);
    return 4 * (nextafter(T, INFINITY) - T) + 2 * (GA_PATH_EXACT_REANCHOR + 1) * DBL_EPSILON * (t1 - t0);
}

/* A bound on |dA/dt| in elem_dist's measure at the element a with body
 * velocity v (dA/dt = A v^): on cga/se3 the rotation block R [w]x has entries
 * at most |w| and the translation column R v at most |v|; on affine an entry
 * of A X is at most a row sum of A's 3x3 block times the largest |X| entry. */
static double speed(const ga_group *g, const void *a, const double *v)
{
    if (g != &ga_group_affine)
        return sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) + sqrt(v[3] * v[3] + v[4] * v[4] + v[5] * v[5]);
    ga_mat4 m = g->to_mat4(a);
    double row = 0.0;
    for (int i = 0; i < 3; i++)
        row = fmax(row, fabs(m.m[4 * i]) + fabs(m.m[4 * i + 1]) + fabs(m.m[4 * i + 2]));
    return row * fz_maxabs(v, g->dim);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_reader rd = fz_begin(data, size);
    uint8_t b0 = fz_byte(&rd), b1 = fz_byte(&rd), flags = fz_byte(&rd);
    const ga_group *g = groups[b0 % 3];
    /* b0 / 3 is 0..85: below 80 the first 8 schemes as before more came, so
       that the regression inputs keep theirs; 80..85 the later ones */
    unsigned sb = b0 / 3u;
    ga_scheme scheme = (ga_scheme)(sb < 80 ? sb % 8 : 8 + (sb - 80) % (GA_SCHEME_COUNT - 8));
    ga_eval ev = (ga_eval)(b1 % 3);
    int n = 2 + (b1 / 3) % (MAXK - 1);
    int dim = g->dim;
    int affine = g == &ga_group_affine;
    double key_max = affine ? 0.25 : 1e3;

    /* times */
    double times[MAXK];
    int valid = 1;
    if (flags & 1) {
        fz_doubles(&rd, times, n);
    } else {
        times[0] = fz_double(&rd);
        for (int i = 1; i < n; i++) {
            double h = fz_double(&rd);
            times[i] = times[i - 1] + fabs(h);
        }
        /* bspline needs even times: the first spacing throughout, from t_0
           (each t_i formed from t_0, not by summing) */
        if (scheme == GA_SCHEME_BSPLINE && n > 1)
            for (int i = 2; i < n; i++) times[i] = times[0] + (double)i * (times[1] - times[0]);
    }
    int times_finite = fz_all_finite(times, n), increasing = 1;
    double hmax = 0.0;
    for (int i = 0; i < n; i++) {
        if (!(fabs(times[i]) <= 1e6))
            valid = 0;
        if (i > 0) {
            double h = times[i] - times[i - 1];
            if (!(h > 0))
                increasing = 0;
            if (!(h >= 1e-3 && h <= 1e3))
                valid = 0;
            hmax = fmax(hmax, h);
        }
    }

    /* keys */
    /* the keys contiguous, elem_size bytes each, as ga_path_init reads them */
    double keybuf[MAXK * GA_GROUP_MAX_ELEM];
    size_t estride = g->elem_size / sizeof(double);
#define KEY(i) (keybuf + (size_t)(i)*estride)
    ga_mat4 mkeys[MAXK];
    int via_mat = (flags & 2) != 0, keys_finite = 1;
    for (int i = 0; i < n; i++) {
        double x[GA_GROUP_MAX_DIM];
        fz_doubles(&rd, x, dim);
        if (!fz_all_finite(x, dim))
            return 0; /* no element to build */
        if (!(fz_maxabs(x, dim) <= key_max))
            valid = 0;
        int st = g->exp(x, KEY(i));
        FZ_CHECK(st == GA_OK || st == GA_ERR_DOMAIN, "%s exp status %d", g->name, st);
        if (st != GA_OK)
            return 0;
        FZ_CHECK(elem_finite(g, KEY(i)), "%s exp: GA_OK with a non-finite element", g->name);
        if (via_mat) {
            mkeys[i] = g->to_mat4(KEY(i));
            if (flags & 8) { /* perturb one entry by an arbitrary amount */
                uint8_t k = fz_byte(&rd);
                double d = fz_double(&rd);
                mkeys[i].m[k % 16] += d;
                valid = 0;
            }
            /* to_mat4 itself can overflow (a translation near DBL_MAX:
               fuzz/regress/path/cga-key-matrix-overflow) */
            if (!fz_all_finite(mkeys[i].m, 16))
                keys_finite = 0;
        }
    }

    /* velocities */
    double vel[MAXK * GA_GROUP_MAX_DIM];
    const double *velp = NULL;
    if (flags & 4) {
        int nv = scheme == GA_SCHEME_LIHAO3 ? n * dim : dim;
        fz_doubles(&rd, vel, nv);
        if (!(fz_maxabs(vel, nv) <= 1e3))
            valid = 0; /* NaN gives NaN here, so it is not valid either */
        /* affine: B_i = h_i V_i enters exp like a key generator, so it is
           held to the keys' bound (an exp of entries 4 on a 3x3 of ones is
           e^12, inverted in the adjoint; extrapolated to u = -1 the cubic
           factor reaches e^50 and its inverse is numerically singular:
           fuzz/regress/path/affine-lihao3-adjoint-singular) */
        if (affine && !(fz_maxabs(vel, nv) * hmax <= key_max))
            valid = 0;
        velp = vel;
    }
    int uses_vel = scheme == GA_SCHEME_LIHAO2 || scheme == GA_SCHEME_LIHAO3;
    int vel_finite = !velp || !uses_vel || fz_all_finite(vel, scheme == GA_SCHEME_LIHAO3 ? n * dim : dim);

    /* build */
    size_t wbytes = ga_path_workspace_size(g, scheme, n);
    void *work = malloc(wbytes ? wbytes : 1);
    if (!work)
        return 0;
    ga_path p;
    int st = via_mat ? ga_path_init_mat4(g, scheme, n, times, mkeys, velp, work, wbytes, &p)
                     : ga_path_init(g, scheme, n, times, keybuf, velp, work, wbytes, &p);
    FZ_CHECK(is_status(st), "init status %d", st);
    /* one key is the constant path on every scheme */
    /* rotation and translation apart: rigid groups only (path.h) */
    int decoupled = scheme == GA_SCHEME_DECOUPLED || scheme == GA_SCHEME_DECOUPLED_C2;
    /* c2: screw motions, rigid groups only (path.h) */
    if ((decoupled || scheme == GA_SCHEME_C2) && affine) {
        FZ_CHECK(st == GA_ERR_ARG && wbytes == 0, "%s on affine: status %d", ga_scheme_name(scheme), st);
        valid = 0;
    }
    /* decoupled-c2's and c2's Newton sweeps are documented to converge for
       neighbouring spacings within a factor 3 (docs/schemes.md); beyond,
       GA_ERR_DOMAIN may come instead */
    if (scheme == GA_SCHEME_DECOUPLED_C2 || scheme == GA_SCHEME_C2)
        for (int i = 2; i < n; i++) {
            double ra = (times[i] - times[i - 1]) / (times[i - 1] - times[i - 2]);
            if (!(ra >= 1.0 / 3 && ra <= 3.0))
                valid = 0;
        }
    /* bspline: evenly spaced times (ga_times_uneven), else GA_ERR_ARG */
    int uneven = scheme == GA_SCHEME_BSPLINE && ga_times_uneven(n, times) != 0;
    int count_ok = n == 1 ||
                   ((size_t)n >= ga_scheme_min_keys(scheme) && (scheme != GA_SCHEME_QUADRATIC || n == 3));
    if (!count_ok)
        FZ_CHECK(st == GA_ERR_ARG, "%s with %d keys: status %d", ga_scheme_name(scheme), n, st);
    if (count_ok && !times_finite)
        FZ_CHECK(st == GA_ERR_NOTFINITE || st == GA_ERR_ARG, "NaN/Inf times: status %d", st);
    if (count_ok && times_finite && !increasing)
        FZ_CHECK(st == GA_ERR_ARG, "times not increasing: status %d", st);
    if (count_ok && (!keys_finite || !vel_finite))
        FZ_CHECK(st != GA_OK, "NaN/Inf keys or velocities accepted");
    /* GA_ERR_NOTFINITE means NaN/Inf input; finite input that overflows is GA_ERR_DOMAIN */
    if (times_finite && keys_finite && vel_finite)
        FZ_CHECK(st != GA_ERR_NOTFINITE, "finite input, GA_ERR_NOTFINITE from init");
    if (uneven && count_ok && times_finite && increasing)
        FZ_CHECK(st == GA_ERR_ARG, "bspline on uneven times: status %d", st);
    valid = valid && count_ok && times_finite && increasing && !uneven;
    if (valid)
        FZ_CHECK(st == GA_OK, "valid %s path on %s fails to build: %d", ga_scheme_name(scheme), g->name, st);
    if (st != GA_OK) {
        free(work);
        return 0;
    }
    /* the range the path is defined on: the keys' times, bspline [t_1, t_{n-2}] */
    double t0 = times[0], t1 = times[n - 1];
    FZ_CHECK(ga_path_range(&p, &t0, &t1) == GA_OK, "range");
    if (scheme != GA_SCHEME_BSPLINE)
        FZ_CHECK(t0 == times[0] && t1 == times[n - 1], "range [%.17g, %.17g] not the keys'", t0, t1);
    int nseg = (int)ga_path_segments(&p);

    /* appending: the path grown from its first k keys by ga_path_append is
       the path built at once, bit for bit (path.h), and it can always be
       grown where the whole path was built */
    int bsp = scheme == GA_SCHEME_BSPLINE; /* 4 keys at least, to begin with */
    if (ga_scheme_can_append(scheme) && n >= (bsp ? 5 : 2)) {
        size_t k0 = bsp ? 4 : 1, k = k0 + (size_t)(flags >> 4) % ((size_t)n - k0); /* k0 .. n-1 keys first */
        void *w2 = malloc(wbytes);
        ga_path q;
        if (!w2) {
            free(work);
            return 0;
        }
        int s2 = via_mat ? ga_path_init_mat4(g, scheme, k, times, mkeys, velp, w2, wbytes, &q)
                         : ga_path_init(g, scheme, k, times, keybuf, velp, w2, wbytes, &q);
        FZ_CHECK(s2 == GA_OK, "%s on %s: the first %zu keys fail to build (%d)", ga_scheme_name(scheme),
                 g->name, k, s2);
        FZ_CHECK(q.cap == (size_t)n, "cap %zu, want %d", q.cap, n);
        for (size_t i = k; i < (size_t)n && s2 == GA_OK; i++) {
            s2 = via_mat ? ga_path_append_mat4(&q, times[i], mkeys[i]) : ga_path_append(&q, times[i], KEY(i));
            FZ_CHECK(s2 == GA_OK, "%s on %s: append of key %zu fails (%d)", ga_scheme_name(scheme), g->name,
                     i, s2);
        }
        s2 = via_mat ? ga_path_append_mat4(&q, t1 + 1.0, mkeys[0]) : ga_path_append(&q, t1 + 1.0, KEY(0));
        FZ_CHECK(s2 == GA_ERR_ARG, "append beyond cap: status %d", s2);
        for (int i = 0; i < 2 * n - 1; i++) { /* the keys and the segment midpoints */
            double t = i % 2 ? 0.5 * (times[i / 2] + times[i / 2 + 1]) : times[i / 2];
            double ea[GA_GROUP_MAX_ELEM], eb[GA_GROUP_MAX_ELEM], va[GA_GROUP_MAX_DIM], vb[GA_GROUP_MAX_DIM];
            int sa = ga_path_eval(&p, t, ea), sb = ga_path_eval(&q, t, eb);
            FZ_CHECK(sa == sb && (sa != GA_OK || !memcmp(ea, eb, g->elem_size)),
                     "%s on %s: appended path differs at t = %.17g", ga_scheme_name(scheme), g->name, t);
            sa = ga_path_velocity(&p, t, va);
            sb = ga_path_velocity(&q, t, vb);
            FZ_CHECK(sa == sb && (sa != GA_OK || !memcmp(va, vb, (size_t)dim * sizeof(double))),
                     "%s on %s: appended path's velocity differs at t = %.17g", ga_scheme_name(scheme),
                     g->name, t);
        }
        free(w2);
    }

    /* closed form and velocity at a few times, inside and outside */
    for (int k = 0; k < 3; k++) {
        double t = fz_double(&rd);
        if (fz_byte(&rd) & 1) /* mostly inside: t0 + frac (t1 - t0) */
            t = t0 + (t1 - t0) * (fabs(fmod(t, 1.0)) + 0.0);
        double A[GA_GROUP_MAX_ELEM], v[GA_GROUP_MAX_DIM];
        int inside = t >= t0 && t <= t1;
        int est = ga_path_eval(&p, t, A), vst = ga_path_velocity(&p, t, v);
        FZ_CHECK(is_status(est) && is_status(vst), "eval %d velocity %d", est, vst);
        if (!inside)
            FZ_CHECK(est != GA_OK && vst != GA_OK, "t = %.17g outside [%.17g, %.17g] accepted", t, t0, t1);
        if (valid && inside)
            FZ_CHECK(est == GA_OK && vst == GA_OK, "valid path: eval %d velocity %d at t %.17g", est, vst, t);
        if (est == GA_OK)
            check_elem(g, A, valid, "eval");
        if (vst == GA_OK)
            FZ_CHECK(fz_all_finite(v, dim), "velocity: GA_OK with a non-finite velocity");
        /* velocity and acceleration in either frame: the same statuses inside
           and outside, finite on GA_OK */
        double dv[GA_GROUP_MAX_DIM], da[GA_GROUP_MAX_DIM];
        int dst = ga_path_differentiate(&p, t, (ga_frame)(k & 1), dv, da);
        FZ_CHECK(is_status(dst), "differentiate %d", dst);
        if (!inside)
            FZ_CHECK(dst != GA_OK, "differentiate: t = %.17g outside accepted", t);
        if (dst == GA_OK)
            FZ_CHECK(fz_all_finite(dv, dim) && fz_all_finite(da, dim), "differentiate: GA_OK, not finite");
    }
    /* one segment formula at an arbitrary u (extrapolation beyond [0, 1]) */
    {
        int seg = fz_byte(&rd) % n; /* nseg (n - 1; bspline n - 3) and above are out of range */
        double u = fz_double(&rd);
        double A[GA_GROUP_MAX_ELEM], v[GA_GROUP_MAX_DIM];
        int est = ga_path_eval_segment(&p, seg, u, A), vst = ga_path_velocity_segment(&p, seg, u, v);
        FZ_CHECK(is_status(est) && is_status(vst), "eval_segment %d velocity_segment %d", est, vst);
        if (seg >= nseg || !isfinite(u))
            FZ_CHECK(est != GA_OK, "eval_segment seg %d u %.17g accepted", seg, u);
        int u_ok = valid && seg < nseg && fabs(u) <= 4;
        if (u_ok)
            FZ_CHECK(est == GA_OK && vst == GA_OK, "valid path: segment %d u %.17g: %d %d", seg, u, est, vst);
        if (est == GA_OK)
            check_elem(g, A, u_ok, "eval_segment");
        if (vst == GA_OK)
            FZ_CHECK(fz_all_finite(v, dim), "velocity_segment: GA_OK with a non-finite velocity");
    }
    /* uniform samples with the chosen evaluator, and the closed form beside them */
    {
        size_t ns = 2 + fz_byte(&rd) % 16;
        double step = fz_double(&rd);
        int step_ok = step >= EULER_FLOOR && step <= 1.0;
        if (step >= 1e-9 && step < EULER_FLOOR)
            step = EULER_FLOOR;
        double *out = malloc(ns * g->elem_size), *ref = malloc(ns * g->elem_size);
        if (out && ref) {
            int sst = ga_path_sample_uniform(&p, ev, step, ns, t0, t1, out);
            int rst = ga_path_sample_uniform(&p, GA_EVAL_DIRECT, 1.0, ns, t0, t1, ref);
            FZ_CHECK(is_status(sst) && is_status(rst), "sample_uniform %d %d", sst, rst);
            if (ev == GA_EVAL_EULER && !(step >= 1e-9 && step <= 1.0))
                FZ_CHECK(sst == GA_ERR_ARG, "Euler step %.17g accepted: %d", step, sst);
            if (valid)
                FZ_CHECK(rst == GA_OK && (sst == GA_OK || (ev == GA_EVAL_EULER && !step_ok)),
                         "valid path: sample_uniform (%s) %d, direct %d", ga_eval_name(ev), sst, rst);
            for (size_t k = 0; k < ns; k++) {
                const char *e = (const char *)out + k * g->elem_size;
                const char *r = (const char *)ref + k * g->elem_size;
                if (sst == GA_OK)
                    check_elem(g, e, valid, ga_eval_name(ev));
                if (rst == GA_OK)
                    check_elem(g, r, valid, "direct");
                if (valid && sst == GA_OK && rst == GA_OK && ev == GA_EVAL_EXACT) {
                    double d = elem_dist(g, e, r), v[GA_GROUP_MAX_DIM];
                    double tk = k + 1 == ns ? t1 : t0 + (double)k * ((t1 - t0) / (double)(ns - 1));
                    int vk = ga_path_velocity(&p, tk, v);
                    FZ_CHECK(vk == GA_OK, "velocity at sample %zu: %d (%s on %s, t %.17g in [%.17g, %.17g])",
                             k, vk, ga_scheme_name(p.scheme), g->name, tk, t0, t1);
                    double bound = 1e-9 + speed(g, r, v) * grid_gap(t0, t1);
                    FZ_CHECK(d <= bound, "exact stepping differs from direct by %.3g > %.3g (sample %zu)", d,
                             bound, k);
                }
            }
        }
        free(out);
        free(ref);
        /* samples at given times, in any order */
        size_t nt = 1 + fz_byte(&rd) % 8;
        double at[8];
        for (size_t k = 0; k < nt; k++) {
            double f = fz_double(&rd);
            at[k] = (fz_byte(&rd) & 1) ? f : t0 + (t1 - t0) * fabs(fmod(f, 1.0));
        }
        out = malloc(nt * g->elem_size);
        if (out) {
            int sst = ga_path_sample(&p, ev, step, nt, at, out);
            FZ_CHECK(is_status(sst), "sample %d", sst);
            int all_inside = 1;
            for (size_t k = 0; k < nt; k++) all_inside &= at[k] >= t0 && at[k] <= t1;
            if (!all_inside)
                FZ_CHECK(sst != GA_OK, "sample at a time outside the keys accepted");
            if (valid && all_inside && (ev != GA_EVAL_EULER || step_ok))
                FZ_CHECK(sst == GA_OK, "valid path: sample (%s) %d", ga_eval_name(ev), sst);
            if (sst == GA_OK)
                for (size_t k = 0; k < nt; k++)
                    check_elem(g, (const char *)out + k * g->elem_size, valid, "sample");
        }
        free(out);
    }
    free(work);
    return 0;
}
