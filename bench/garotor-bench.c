/* bench/garotor-bench.c: where garotor stands against 4x4 matrices, dual
 * quaternions and Eigen, in one process run.
 *
 *   garotor-bench            a plain text table
 *   garotor-bench --json     one JSON object: {"ns": {...}, "err": {...}, ...}
 *   garotor-bench --quick    fewer and shorter batches (a smoke test)
 *   garotor-bench --only K,K only these keys (for a profiler; no throughput)
 *
 * Method. Every figure is the median, over repeated timed batches, of the
 * nanoseconds per call (clock_gettime(CLOCK_MONOTONIC) around a batch, divided
 * by the calls in it). Each benchmark is first calibrated so that one batch
 * takes about BATCH_MS; then the batches of all benchmarks are interleaved
 * (round r runs batch r of every benchmark in turn), so that a slow phase of a
 * noisy machine hits every figure alike and the ratios between them hold.
 * Inputs come from a seeded PRNG (xoshiro256**) and are stored in rings of
 * RING entries, walked in order and continued from batch to batch, so nothing
 * is constant or loop-invariant; every result is stored to an output ring that
 * is read into a volatile sink after each batch, so nothing is dead. Each
 * operation is called as a user's code calls it: the hot path of
 * <garotor/rotor_inline.h> inline, everything else through the library's
 * symbols (the bench links the library's objects); the floors (a dual-
 * quaternion product, a 4x4 matrix on a point, a table-driven dense product)
 * are plain inline C written here, at full strength. Keys ending in _chain
 * time latency: each call waits for the previous one's result.
 *
 * The keys under "ns" and "err" are those of docs/conventions.md ("The benchmark
 * garotor-bench"); everything else is extra. docs/benchmarks.md explains each
 * figure and ratio.
 */
#define _POSIX_C_SOURCE 200809L

#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include <garotor/garotor.h>
#include <garotor/conformal.h>
#include <garotor/mat4.h>
#include <garotor/path.h>
#include <garotor/rotor.h>
#include <garotor/rotor_inline.h>

#ifdef GAROTOR_BENCH_EIGEN
#include "eigen_peer.h"
#endif

#ifndef GAROTOR_BENCH_BUILD
#define GAROTOR_BENCH_BUILD "unknown"
#endif

#define RING 1024
#define MASK (RING - 1)
#define PI 3.14159265358979323846

/* Paths: N_KEYS keys at t = 0, 1, ..., N_KEYS - 1; N_SAMPLES evenly spaced
 * samples over the whole path, which puts SAMPLES_PER_SEG samples on every
 * segment at u = k / SAMPLES_PER_SEG, exactly on the Euler grid of step
 * EULER_STEP: so every Euler sample is exactly one Euler step. */
#define N_KEYS 8
#define N_PATHS 4
#define SAMPLES_PER_SEG 1024
#define N_SAMPLES ((N_KEYS - 1) * SAMPLES_PER_SEG + 1)
#define EULER_STEP (1.0 / SAMPLES_PER_SEG)
#define BATCH_POSES 1000000

/* Many short batches: on a busy machine a short batch is more often
 * uninterrupted, and the median then ignores the interrupted ones. */
#define DEFAULT_BATCHES 101
#define DEFAULT_BATCH_MS 0.5

/* ---- PRNG: xoshiro256**, seeded by splitmix64 --------------------------- */

static uint64_t rng_s[4];

static uint64_t splitmix64(uint64_t *x)
{
    uint64_t z = (*x += 0x9e3779b97f4a7c15u);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
    return z ^ (z >> 31);
}

static void rng_seed(uint64_t seed)
{
    for (int i = 0; i < 4; i++) rng_s[i] = splitmix64(&seed);
}

static uint64_t rotl(uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }

static uint64_t rng_next(void)
{
    uint64_t r = rotl(rng_s[1] * 5, 7) * 9, t = rng_s[1] << 17;
    rng_s[2] ^= rng_s[0];
    rng_s[3] ^= rng_s[1];
    rng_s[1] ^= rng_s[2];
    rng_s[0] ^= rng_s[3];
    rng_s[2] ^= t;
    rng_s[3] = rotl(rng_s[3], 45);
    return r;
}

/* uniform in [a, b) */
static double uniform(double a, double b)
{
    return a + (b - a) * ((double)(rng_next() >> 11) * (1.0 / 9007199254740992.0));
}

static ga_vec3 random_unit(void)
{
    for (;;) {
        ga_vec3 v = {uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)};
        double n2 = v.x * v.x + v.y * v.y + v.z * v.z;
        if (n2 > 1e-4 && n2 <= 1.0) {
            double k = 1.0 / sqrt(n2);
            ga_vec3 u = {k * v.x, k * v.y, k * v.z};
            return u;
        }
    }
}

/* A twist of rotation angle uniform in [0.05, 3.0] rad about a uniform axis
 * and a translation part uniform in [-2, 2]^3. */
static ga_twist random_twist(void)
{
    ga_vec3 u = random_unit();
    double th = uniform(0.05, 3.0);
    ga_twist xi = {{th * u.x, th * u.y, th * u.z}, {uniform(-2, 2), uniform(-2, 2), uniform(-2, 2)}};
    return xi;
}

static ga_rotor rotor_of_twist(ga_twist xi) { return ga_rotor_exp(ga_twist_to_generator(xi)); }

/* ---- the floors: what a user would otherwise write --------------------------
 * Each floor is plain C written here, static inline, compiled at full strength
 * into its timed loop exactly as a user's own code would be: no call, no
 * by-value struct crossing a library boundary. */

/* Hamilton's product of quaternions, as in any textbook. */
static inline ga_quat quat_mul(ga_quat a, ga_quat b)
{
    ga_quat r;
    r.w = a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z;
    r.x = a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y;
    r.y = a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x;
    r.z = a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w;
    return r;
}

static inline ga_quat quat_add(ga_quat a, ga_quat b)
{
    ga_quat r = {a.w + b.w, a.x + b.x, a.y + b.y, a.z + b.z};
    return r;
}

/* (ra + eps da)(rb + eps db) = ra rb + eps (ra db + da rb): 48 multiplications. */
static inline ga_dualquat dualquat_mul(ga_dualquat a, ga_dualquat b)
{
    ga_dualquat r;
    r.real = quat_mul(a.real, b.real);
    r.dual = quat_add(quat_mul(a.real, b.dual), quat_mul(a.dual, b.real));
    return r;
}

/* A rigid-motion matrix applied to a point: 9 multiplications, 9 additions. */
static inline ga_vec3 mat4_apply(const ga_mat4 *m, ga_vec3 x)
{
    const double *a = m->m;
    ga_vec3 r = {a[0] * x.x + a[1] * x.y + a[2] * x.z + a[3], a[4] * x.x + a[5] * x.y + a[6] * x.z + a[7],
                 a[8] * x.x + a[9] * x.y + a[10] * x.z + a[11]};
    return r;
}

/* The table-driven dense product a user writes from a GA textbook: for every
 * pair of blades (i, j), the sign of e_i e_j and the index of its blade, from
 * two 32x32 tables filled once (by ga_blade_mask and the swap-counting rule),
 * then two nested loops. */
static double gp_sign[32][32];
static unsigned char gp_index[32][32];

static void gp_tables(void)
{
    int index_of[32];
    for (int i = 0; i < 32; i++) index_of[ga_blade_mask(i)] = i;
    for (int i = 0; i < 32; i++)
        for (int j = 0; j < 32; j++) {
            unsigned a = ga_blade_mask(i), b = ga_blade_mask(j);
            int swaps = 0;
            for (unsigned x = a >> 1; x; x >>= 1)
                for (unsigned y = x & b; y; y &= y - 1) swaps++;
            if (a & b & 0x10u) /* e5 e5 = -1 */
                swaps++;
            gp_sign[i][j] = (swaps & 1) ? -1.0 : 1.0;
            gp_index[i][j] = (unsigned char)index_of[a ^ b];
        }
}

static inline void gp_table(const ga_mv *a, const ga_mv *b, ga_mv *r)
{
    double acc[32] = {0};
    for (int i = 0; i < 32; i++)
        for (int j = 0; j < 32; j++) acc[gp_index[i][j]] += gp_sign[i][j] * (a->c[i] * b->c[j]);
    memcpy(r->c, acc, sizeof acc);
}

/* ---- inputs and outputs --------------------------------------------------- */

static ga_mv mv_a[RING], mv_b[RING];
static ga_rotor rot_a[RING], rot_b[RING];
static ga_dualquat dq_a[RING], dq_b[RING];
static ga_vec3 pts[RING];
static ga_twist twists[RING];
static ga_generator gens[RING];
static ga_mat4 rigid_a[RING], rigid_b[RING]; /* the matrices of rot_a, rot_b */
static ga_mat4 hats[RING];                   /* twist^ of twists */
static ga_mat4 gen_x[RING];                  /* general 4x4, last row zero */
static ga_mat4 gen_m[RING];                  /* expm(gen_x): general invertible */

static ga_mv out_mv[RING];
static ga_rotor out_rot[RING];
static ga_dualquat out_dq[RING];
static ga_vec3 out_v3[RING];
static ga_generator out_gen[RING];
static ga_twist out_tw[RING];
static ga_mat4 out_mat[RING];
#ifdef GAROTOR_BENCH_EIGEN
static double out_pose[RING][7];
#endif

static volatile double sink;
static size_t cursor; /* where the next batch continues in the rings */
static int status_or; /* OR of every status returned in the timed loops */

/* ---- paths ----------------------------------------------------------------- */

enum { PG_CGA_SCREW, PG_SE3_SCREW, PG_CGA_LIHAO3, PG_SE3_LIHAO3, N_PATH_KINDS };

static const struct {
    const ga_group *group;
    ga_scheme scheme;
} path_kind[N_PATH_KINDS] = {
    {&ga_group_cga, GA_SCHEME_SCREW},
    {&ga_group_se3, GA_SCHEME_SCREW},
    {&ga_group_cga, GA_SCHEME_LIHAO3},
    {&ga_group_se3, GA_SCHEME_LIHAO3},
};

static ga_path paths[N_PATH_KINDS][N_PATHS];
static ga_rotor key_rotors[N_PATHS][N_KEYS];
static double key_poses[N_PATHS][N_KEYS][7]; /* x y z qx qy qz qw */
static double sample_buf[N_SAMPLES * GA_GROUP_MAX_ELEM];
static size_t path_cursor;

static int build_paths(void)
{
    double times[N_KEYS];
    ga_mat4 keys[N_KEYS];
    for (int i = 0; i < N_KEYS; i++) times[i] = i;
    for (int p = 0; p < N_PATHS; p++) {
        for (int i = 0; i < N_KEYS; i++) {
            ga_rotor r = rotor_of_twist(random_twist());
            ga_vec3 t = ga_rotor_to_translation(r);
            ga_quat q = ga_rotor_to_quat(r);
            double pose[7] = {t.x, t.y, t.z, q.x, q.y, q.z, q.w};
            key_rotors[p][i] = r;
            keys[i] = ga_rotor_to_mat4(r);
            memcpy(key_poses[p][i], pose, sizeof pose);
        }
        for (int k = 0; k < N_PATH_KINDS; k++) {
            const ga_group *g = path_kind[k].group;
            size_t bytes = ga_path_workspace_size(g, path_kind[k].scheme, N_KEYS);
            void *work = malloc(bytes);
            if (!work)
                return GA_ERR_ARG;
            int st = ga_path_init_mat4(g, path_kind[k].scheme, N_KEYS, times, keys, NULL, work, bytes,
                                       &paths[k][p]);
            if (st != GA_OK)
                return st;
        }
    }
    return GA_OK;
}

/* The largest entry difference between the 4x4 matrices of two sample arrays. */
static double samples_maxdiff(const ga_group *g, const double *a, const double *b, size_t n)
{
    double worst = 0.0;
    for (size_t k = 0; k < n; k++) {
        ga_mat4 ma = g->to_mat4((const unsigned char *)a + k * g->elem_size);
        ga_mat4 mb = g->to_mat4((const unsigned char *)b + k * g->elem_size);
        for (int i = 0; i < 16; i++) worst = fmax(worst, fabs(ma.m[i] - mb.m[i]));
    }
    return worst;
}

/* The largest error of Euler and exact samples against the closed form, over
 * all N_PATHS paths of a kind. */
static void path_errors(int kind, double *euler_max, double *exact_max)
{
    const ga_group *g = path_kind[kind].group;
    size_t doubles = (size_t)N_SAMPLES * GA_GROUP_MAX_ELEM;
    double *direct = malloc(doubles * sizeof(double));
    double *other = malloc(doubles * sizeof(double));
    *euler_max = *exact_max = NAN;
    if (!direct || !other) {
        free(direct);
        free(other);
        return;
    }
    double eu = 0.0, ex = 0.0;
    int st = 0;
    for (int p = 0; p < N_PATHS; p++) {
        const ga_path *path = &paths[kind][p];
        st |= ga_path_sample_uniform(path, GA_EVAL_DIRECT, EULER_STEP, N_SAMPLES, 0.0, N_KEYS - 1.0, direct);
        st |= ga_path_sample_uniform(path, GA_EVAL_EULER, EULER_STEP, N_SAMPLES, 0.0, N_KEYS - 1.0, other);
        eu = fmax(eu, samples_maxdiff(g, direct, other, N_SAMPLES));
        st |= ga_path_sample_uniform(path, GA_EVAL_EXACT, EULER_STEP, N_SAMPLES, 0.0, N_KEYS - 1.0, other);
        ex = fmax(ex, samples_maxdiff(g, direct, other, N_SAMPLES));
    }
    if (st == GA_OK) {
        *euler_max = eu;
        *exact_max = ex;
    }
    free(direct);
    free(other);
}

/* ---- the timed loops ---------------------------------------------------------
 * Each takes its calls n and returns how many it made (the sampling loops make
 * whole paths of N_SAMPLES poses). */

typedef size_t (*run_fn)(const void *ctx, size_t n);

/* Every loop over the input rings has this shape: for each call, j is the
 * next slot of the rings (k & MASK), BODY computes the output at j (st |= the
 * status where one comes back, in = the ring ctx selects where there is a
 * choice), and the last output, LAST (at slot `last`), goes to the sink so
 * that nothing can be optimised away. A macro, so that each loop is compiled
 * with its call inlined, as a loop written out by hand would be. */
#define RING_LOOP(name, BODY, LAST)                                                                          \
    static size_t name(const void *ctx, size_t n)                                                            \
    {                                                                                                        \
        const ga_mat4 *in = ctx;                                                                             \
        (void)in;                                                                                            \
        size_t k = cursor;                                                                                   \
        int st = 0;                                                                                          \
        for (size_t i = 0; i < n; i++, k++) {                                                                \
            size_t j = k & MASK;                                                                             \
            BODY;                                                                                            \
        }                                                                                                    \
        cursor = k;                                                                                          \
        status_or |= st;                                                                                     \
        size_t last = (k - 1) & MASK;                                                                        \
        sink = (LAST);                                                                                       \
        return n;                                                                                            \
    }

RING_LOOP(run_gp_full, out_mv[j] = ga_mv_gp(mv_a[j], mv_b[j]), out_mv[last].c[31])
RING_LOOP(run_motor_mul, out_rot[j] = ga_rotor_mul_inline(rot_a[j], rot_b[j]), out_rot[last].e123n)
RING_LOOP(run_motor_mul_call, out_rot[j] = ga_rotor_mul(rot_a[j], rot_b[j]), out_rot[last].e123n)
RING_LOOP(run_dualquat_mul, out_dq[j] = dualquat_mul(dq_a[j], dq_b[j]), out_dq[last].dual.z)
RING_LOOP(run_gp_table, gp_table(&mv_a[j], &mv_b[j], &out_mv[j]), out_mv[last].c[31])
RING_LOOP(run_mat4_mul, out_mat[j] = ga_mat4_mul(rigid_a[j], rigid_b[j]), out_mat[last].m[11])
RING_LOOP(run_motor_apply, out_v3[j] = ga_rotor_apply_inline(rot_a[j], pts[j]), out_v3[last].z)
RING_LOOP(run_motor_apply_call, out_v3[j] = ga_rotor_apply(rot_a[j], pts[j]), out_v3[last].z)
/* the same point moved through the full algebra: F(x), R F(x) ~R, down */
RING_LOOP(run_apply_sandwich,
          st |= ga_point_down(ga_rotor_apply_mv(rot_a[j], ga_point_up(pts[j])), &out_v3[j]), out_v3[last].z)
RING_LOOP(run_mat4_apply, out_v3[j] = mat4_apply(&rigid_a[j], pts[j]), out_v3[last].z)
RING_LOOP(run_exp, out_rot[j] = ga_rotor_exp(gens[j]), out_rot[last].e123n)
RING_LOOP(run_log, st |= ga_rotor_log(rot_a[j], &out_gen[j]), out_gen[last].e3n)
RING_LOOP(run_se3_exp, out_mat[j] = ga_se3_exp(twists[j]), out_mat[last].m[11])
RING_LOOP(run_se3_log, st |= ga_se3_log(rigid_a[j], &out_tw[j]), out_tw[last].v.z)
/* twist -> 4x4 matrix through the rotor: exp, then the rotor's matrix */
RING_LOOP(run_exp_to_mat4,
          out_mat[j] = ga_rotor_to_mat4_inline(ga_rotor_exp(ga_twist_to_generator(twists[j]))),
          out_mat[last].m[11])
/* 4x4 rigid matrix -> twist through the rotor: checked Shepperd, then the log */
RING_LOOP(run_log_from_mat4, ga_rotor r; ga_generator g; st |= ga_rotor_from_mat4_inline(rigid_a[j], &r);
          st |= ga_rotor_log(r, &g); out_tw[j] = ga_generator_to_twist(g), out_tw[last].v.z)
/* Chains (latency): each call takes the previous call's result, so the figure
 * is the time from an input to its result, not the throughput of independent
 * calls. A product chain multiplies its running result by the next ring
 * entry; an exp chain adds 0.0 * (previous result) to one component of the
 * next input (exactly the same input, but the compiler cannot know it: one
 * multiplication and one addition of latency, the same in exp_chain and
 * se3_exp_chain). */
#define CHAIN_LOOP(name, T, init, STEP, LAST)                                                                \
    static size_t name(const void *ctx, size_t n)                                                            \
    {                                                                                                        \
        (void)ctx;                                                                                           \
        static T carry;                                                                                      \
        static int started;                                                                                  \
        if (!started) {                                                                                      \
            carry = (init);                                                                                  \
            started = 1;                                                                                     \
        }                                                                                                    \
        T x = carry;                                                                                         \
        size_t k = cursor;                                                                                   \
        for (size_t i = 0; i < n; i++, k++) {                                                                \
            size_t j = k & MASK;                                                                             \
            STEP;                                                                                            \
        }                                                                                                    \
        cursor = k;                                                                                          \
        carry = x;                                                                                           \
        sink = (LAST);                                                                                       \
        return n;                                                                                            \
    }

CHAIN_LOOP(run_motor_mul_chain, ga_rotor, rot_a[0], x = ga_rotor_mul_inline(x, rot_b[j]), x.e123n)
CHAIN_LOOP(run_dualquat_mul_chain, ga_dualquat, dq_a[0], x = dualquat_mul(x, dq_b[j]), x.dual.z)
CHAIN_LOOP(run_exp_chain, ga_rotor, rot_a[0], ga_generator g = gens[j]; g.e12 += 0.0 * x.e123n;
           x = ga_rotor_exp(g), x.e123n)
CHAIN_LOOP(run_se3_exp_chain, ga_mat4, rigid_a[0], ga_twist xi = twists[j]; xi.w.x += 0.0 * x.m[11];
           x = ga_se3_exp(xi), x.m[11])

/* ga_mat4_expm / ga_mat4_logm (and Eigen's) of the ring selected by ctx */
RING_LOOP(run_mat4_expm, st |= ga_mat4_expm(in[j], &out_mat[j]), out_mat[last].m[11])
RING_LOOP(run_mat4_logm, st |= ga_mat4_logm(in[j], &out_mat[j]), out_mat[last].m[11])

#ifdef GAROTOR_BENCH_EIGEN
RING_LOOP(run_eigen_expm, garotor_eigen_expm(in[j].m, out_mat[j].m), out_mat[last].m[11])
RING_LOOP(run_eigen_logm, garotor_eigen_logm(in[j].m, out_mat[j].m), out_mat[last].m[11])

/* Decoupled interpolation at the same sample times as the sample_* figures:
 * locate the segment, then slerp + lerp between its two keys. */
static size_t run_eigen_slerp_lerp(const void *ctx, size_t n)
{
    (void)ctx;
    size_t done = 0;
    while (done < n) {
        double(*pose)[7] = key_poses[path_cursor++ % N_PATHS];
        for (size_t s = 0; s < N_SAMPLES; s++) {
            double t = (double)s * (1.0 / SAMPLES_PER_SEG);
            int seg = (int)t;
            if (seg > N_KEYS - 2)
                seg = N_KEYS - 2;
            garotor_eigen_slerp_lerp(pose[seg], pose[seg + 1], t - seg, out_pose[s & MASK]);
        }
        done += N_SAMPLES;
    }
    sink = out_pose[0][6];
    return done;
}
#endif

/* ctx for the sampling loops: the path kind and the evaluator */
typedef struct {
    int kind;
    ga_eval eval;
} sample_ctx;

/* One call of ga_path_sample_uniform fills N_SAMPLES poses; the figure is per pose. */
static size_t run_sample(const void *ctx, size_t n)
{
    const sample_ctx *c = ctx;
    size_t done = 0;
    int st = 0;
    while (done < n) {
        const ga_path *p = &paths[c->kind][path_cursor++ % N_PATHS];
        st |= ga_path_sample_uniform(p, c->eval, EULER_STEP, N_SAMPLES, 0.0, N_KEYS - 1.0, sample_buf);
        done += N_SAMPLES;
    }
    status_or |= st;
    sink = sample_buf[7];
    return done;
}

/* ---- the benchmark table --------------------------------------------------- */

typedef struct {
    const char *key;
    const char *what;
    run_fn run;
    const void *ctx;
    size_t calls; /* per batch, after calibration */
    double *ns;   /* ns per call, one per batch */
    double median, p25, p75;
} bench;

static const sample_ctx ctx_cga_screw_direct = {PG_CGA_SCREW, GA_EVAL_DIRECT};
static const sample_ctx ctx_cga_screw_exact = {PG_CGA_SCREW, GA_EVAL_EXACT};
static const sample_ctx ctx_cga_screw_euler = {PG_CGA_SCREW, GA_EVAL_EULER};
static const sample_ctx ctx_se3_screw_direct = {PG_SE3_SCREW, GA_EVAL_DIRECT};
static const sample_ctx ctx_se3_screw_exact = {PG_SE3_SCREW, GA_EVAL_EXACT};
static const sample_ctx ctx_se3_screw_euler = {PG_SE3_SCREW, GA_EVAL_EULER};
static const sample_ctx ctx_cga_lihao3_direct = {PG_CGA_LIHAO3, GA_EVAL_DIRECT};
static const sample_ctx ctx_cga_lihao3_exact = {PG_CGA_LIHAO3, GA_EVAL_EXACT};
static const sample_ctx ctx_cga_lihao3_euler = {PG_CGA_LIHAO3, GA_EVAL_EULER};
static const sample_ctx ctx_se3_lihao3_direct = {PG_SE3_LIHAO3, GA_EVAL_DIRECT};
static const sample_ctx ctx_se3_lihao3_exact = {PG_SE3_LIHAO3, GA_EVAL_EXACT};
static const sample_ctx ctx_se3_lihao3_euler = {PG_SE3_LIHAO3, GA_EVAL_EULER};

static bench benches[] = {
    /* the keys of docs/conventions.md */
    {"gp_full", "ga_mv_gp: full 32x32 geometric product, two dense multivectors", run_gp_full, NULL, 0, NULL,
     0, 0, 0},
    {"motor_mul", "ga_rotor_mul_inline: product of two compact rotors (8 doubles)", run_motor_mul, NULL, 0,
     NULL, 0, 0, 0},
    {"dualquat_mul", "textbook unit dual-quaternion product (in the bench, inline, 48 mul)", run_dualquat_mul,
     NULL, 0, NULL, 0, 0, 0},
    {"gp_table", "plain table-driven dense 32x32 product (in the bench: sign and index tables)", run_gp_table,
     NULL, 0, NULL, 0, 0, 0},
    {"motor_apply", "ga_rotor_apply_inline: one 3D point moved by a rotor", run_motor_apply, NULL, 0, NULL, 0,
     0, 0},
    {"mat4_apply", "4x4 rigid motion times a point (in the bench, inline)", run_mat4_apply, NULL, 0, NULL, 0,
     0, 0},
    {"exp", "ga_rotor_exp: generator -> rotor, closed form", run_exp, NULL, 0, NULL, 0, 0, 0},
    {"log", "ga_rotor_log: rotor -> generator, principal", run_log, NULL, 0, NULL, 0, 0, 0},
    {"se3_exp", "ga_se3_exp: twist -> 4x4, Eberly's closed form", run_se3_exp, NULL, 0, NULL, 0, 0, 0},
    {"se3_log", "ga_se3_log: 4x4 rigid -> twist (checked), Eberly", run_se3_log, NULL, 0, NULL, 0, 0, 0},
    {"sample_direct", "screw path on rotors, per pose: closed form", run_sample, &ctx_cga_screw_direct, 0,
     NULL, 0, 0, 0},
    {"sample_exact", "screw path on rotors, per pose: exact incremental stepping", run_sample,
     &ctx_cga_screw_exact, 0, NULL, 0, 0, 0},
    {"sample_euler", "screw path on rotors, per pose: Li-Hao Euler, 1 step", run_sample, &ctx_cga_screw_euler,
     0, NULL, 0, 0, 0},
    /* extras */
    {"mat4_mul", "ga_mat4_mul: product of two 4x4 rigid motions", run_mat4_mul, NULL, 0, NULL, 0, 0, 0},
    {"motor_mul_call", "ga_rotor_mul: the same product through the library's symbol", run_motor_mul_call,
     NULL, 0, NULL, 0, 0, 0},
    {"motor_apply_call", "ga_rotor_apply: the same point action through the library's symbol",
     run_motor_apply_call, NULL, 0, NULL, 0, 0, 0},
    {"motor_mul_chain", "ga_rotor_mul_inline, each call on the previous result (latency)",
     run_motor_mul_chain, NULL, 0, NULL, 0, 0, 0},
    {"dualquat_mul_chain", "the bench's dual-quaternion product, chained (latency)", run_dualquat_mul_chain,
     NULL, 0, NULL, 0, 0, 0},
    {"exp_chain", "ga_rotor_exp, input depending on the previous result (latency)", run_exp_chain, NULL, 0,
     NULL, 0, 0, 0},
    {"se3_exp_chain", "ga_se3_exp, input depending on the previous result (latency)", run_se3_exp_chain, NULL,
     0, NULL, 0, 0, 0},
    {"apply_sandwich", "ga_point_down(ga_rotor_apply_mv(R, ga_point_up(x))): full sandwich",
     run_apply_sandwich, NULL, 0, NULL, 0, 0, 0},
    {"exp_to_mat4", "twist -> 4x4 through the rotor: exp, ga_rotor_to_mat4_inline", run_exp_to_mat4, NULL, 0,
     NULL, 0, 0, 0},
    {"log_from_mat4", "4x4 -> twist through the rotor: ga_rotor_from_mat4_inline, log", run_log_from_mat4,
     NULL, 0, NULL, 0, 0, 0},
    {"mat4_expm_se3", "ga_mat4_expm (Pade) of the se3_exp inputs' twist^", run_mat4_expm, hats, 0, NULL, 0, 0,
     0},
    {"mat4_logm_se3", "ga_mat4_logm (inverse scaling and squaring) of the se3_log inputs", run_mat4_logm,
     rigid_a, 0, NULL, 0, 0, 0},
    {"mat4_expm", "ga_mat4_expm of general 4x4 (last row 0)", run_mat4_expm, gen_x, 0, NULL, 0, 0, 0},
    {"mat4_logm", "ga_mat4_logm of general invertible 4x4", run_mat4_logm, gen_m, 0, NULL, 0, 0, 0},
#ifdef GAROTOR_BENCH_EIGEN
    {"eigen_expm", "Eigen MatrixFunctions .exp() of the se3_exp inputs' twist^", run_eigen_expm, hats, 0,
     NULL, 0, 0, 0},
    {"eigen_logm", "Eigen MatrixFunctions .log() of the se3_log inputs", run_eigen_logm, rigid_a, 0, NULL, 0,
     0, 0},
    {"eigen_expm_general", "Eigen .exp() of the mat4_expm inputs", run_eigen_expm, gen_x, 0, NULL, 0, 0, 0},
    {"eigen_logm_general", "Eigen .log() of the mat4_logm inputs", run_eigen_logm, gen_m, 0, NULL, 0, 0, 0},
    {"eigen_slerp_lerp", "Eigen Quaterniond slerp + lerp, per pose, same sample times", run_eigen_slerp_lerp,
     NULL, 0, NULL, 0, 0, 0},
#endif
    {"sample_direct_se3", "screw path on 4x4 matrices, per pose: closed form", run_sample,
     &ctx_se3_screw_direct, 0, NULL, 0, 0, 0},
    {"sample_exact_se3", "screw path on 4x4 matrices, per pose: exact stepping", run_sample,
     &ctx_se3_screw_exact, 0, NULL, 0, 0, 0},
    {"sample_euler_se3", "screw path on 4x4 matrices, per pose: Euler, 1 step", run_sample,
     &ctx_se3_screw_euler, 0, NULL, 0, 0, 0},
    {"sample_direct_lihao3", "lihao3 path on rotors, per pose: closed form", run_sample,
     &ctx_cga_lihao3_direct, 0, NULL, 0, 0, 0},
    {"sample_exact_lihao3", "lihao3 path on rotors, per pose: exact stepping", run_sample,
     &ctx_cga_lihao3_exact, 0, NULL, 0, 0, 0},
    {"sample_euler_lihao3", "lihao3 path on rotors, per pose: Euler, 1 step", run_sample,
     &ctx_cga_lihao3_euler, 0, NULL, 0, 0, 0},
    {"sample_direct_lihao3_se3", "lihao3 path on 4x4 matrices, per pose: closed form", run_sample,
     &ctx_se3_lihao3_direct, 0, NULL, 0, 0, 0},
    {"sample_exact_lihao3_se3", "lihao3 path on 4x4 matrices, per pose: exact stepping", run_sample,
     &ctx_se3_lihao3_exact, 0, NULL, 0, 0, 0},
    {"sample_euler_lihao3_se3", "lihao3 path on 4x4 matrices, per pose: Euler, 1 step", run_sample,
     &ctx_se3_lihao3_euler, 0, NULL, 0, 0, 0},
};
#define N_BENCH (sizeof benches / sizeof benches[0])

static double now_ns(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e9 + (double)ts.tv_nsec;
}

/* ns per call of one batch of b */
static double time_batch(bench *b)
{
    double t0 = now_ns();
    size_t done = b->run(b->ctx, b->calls);
    double t1 = now_ns();
    return (t1 - t0) / (double)done;
}

/* Grow the batch until it takes about target_ns. Each size is timed three
 * times and the fastest counts, so that one preempted trial cannot stop the
 * growth early (a batch of a few calls would then time the clock). */
static void calibrate(bench *b, double target_ns)
{
    b->calls = 1;
    for (int it = 0; it < 60; it++) {
        double el = INFINITY;
        for (int trial = 0; trial < 3; trial++) {
            double t0 = now_ns();
            size_t done = b->run(b->ctx, b->calls);
            double t = now_ns() - t0;
            if (done > b->calls)
                b->calls = done;
            el = t < el ? t : el;
        }
        if (el >= 0.8 * target_ns)
            break;
        double grow = el > 0 ? target_ns / el : 16.0;
        grow = grow > 16.0 ? 16.0 : grow < 1.25 ? 1.25 : grow;
        b->calls = (size_t)ceil((double)b->calls * grow);
    }
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* the q-quantile (0..1) of a sorted array, linearly interpolated */
static double quantile(const double *s, int n, double q)
{
    double pos = q * (n - 1);
    int i = (int)pos;
    if (i >= n - 1)
        return s[n - 1];
    return s[i] + (pos - i) * (s[i + 1] - s[i]);
}

static bench *find(const char *key)
{
    for (size_t i = 0; i < N_BENCH; i++)
        if (strcmp(benches[i].key, key) == 0)
            return &benches[i];
    return NULL;
}

static double ns_of(const char *key)
{
    bench *b = find(key);
    return b && b->ns ? b->median : NAN;
}

/* --only KEY,KEY,...: is key in the list (NULL: every key)? */
static int selected(const char *only, const char *key)
{
    size_t n = strlen(key);
    for (const char *p = only; p; p = strchr(p, ',')) {
        if (*p == ',')
            p++;
        if (strncmp(p, key, n) == 0 && (p[n] == ',' || p[n] == 0))
            return 1;
    }
    return only == NULL;
}

/* ---- setup and checks --------------------------------------------------------- */

static double maxdiff(const double *a, const double *b, int n)
{
    double w = 0.0;
    for (int i = 0; i < n; i++) w = fmax(w, fabs(a[i] - b[i]));
    return w;
}

static int setup_inputs(void)
{
    for (int j = 0; j < RING; j++) {
        for (int i = 0; i < 32; i++) {
            mv_a[j].c[i] = uniform(-1, 1);
            mv_b[j].c[i] = uniform(-1, 1);
        }
        twists[j] = random_twist();
        gens[j] = ga_twist_to_generator(twists[j]);
        rot_a[j] = ga_rotor_exp(gens[j]);
        rot_b[j] = rotor_of_twist(random_twist());
        dq_a[j] = ga_rotor_to_dualquat(rot_a[j]);
        dq_b[j] = ga_rotor_to_dualquat(rot_b[j]);
        rigid_a[j] = ga_rotor_to_mat4(rot_a[j]);
        rigid_b[j] = ga_rotor_to_mat4(rot_b[j]);
        hats[j] = ga_twist_hat(twists[j]);
        ga_vec3 x = {uniform(-5, 5), uniform(-5, 5), uniform(-5, 5)};
        pts[j] = x;
        /* a general real 4x4 generator: entries uniform in [-0.7, 0.7], last
           row zero; its exp is a general invertible homogeneous matrix whose
           principal log is the generator again (eigenvalues well inside the
           strip |Im| < pi) */
        for (;;) {
            ga_mat4 a;
            for (int i = 0; i < 16; i++) a.m[i] = i < 12 ? uniform(-0.7, 0.7) : 0.0;
            ga_mat4 e, l;
            if (ga_mat4_expm(a, &e) != GA_OK || ga_mat4_logm(e, &l) != GA_OK || maxdiff(l.m, a.m, 16) > 1e-9)
                continue;
            gen_x[j] = a;
            gen_m[j] = e;
            break;
        }
    }
    gp_tables();
    return build_paths();
}

/* Do the figures compute what they claim? Each is the largest entry difference
 * over the ring between two routes to the same result. */
typedef struct {
    double dualquat_vs_motor;  /* to_dualquat(ga_rotor_mul) vs the bench's dualquat_mul */
    double gp_vs_table;        /* ga_mv_gp vs the bench's gp_table */
    double apply_vs_matrix;    /* ga_rotor_apply vs the rotor's 4x4 times the point */
    double apply_vs_sandwich;  /* ga_rotor_apply vs the full sandwich */
    double exp_vs_se3;         /* ga_rotor_to_mat4(exp) vs ga_se3_exp */
    double log_vs_se3;         /* twist of ga_rotor_log vs ga_se3_log */
    double expm_vs_se3;        /* ga_mat4_expm(twist^) vs ga_se3_exp */
    double logm_vs_se3;        /* ga_mat4_logm vs twist^ of ga_se3_log */
    double eigen_expm_vs_se3;  /* Eigen .exp() vs ga_se3_exp */
    double eigen_logm_vs_se3;  /* Eigen .log() vs twist^ of ga_se3_log */
    double eigen_expm_general; /* Eigen .exp() vs ga_mat4_expm, general */
    double eigen_logm_general; /* Eigen .log() vs ga_mat4_logm, general */
} checks;

static checks run_checks(void)
{
    checks c;
    memset(&c, 0, sizeof c);
    c.eigen_expm_vs_se3 = c.eigen_logm_vs_se3 = NAN;
    c.eigen_expm_general = c.eigen_logm_general = NAN;
#ifdef GAROTOR_BENCH_EIGEN
    c.eigen_expm_vs_se3 = c.eigen_logm_vs_se3 = 0.0;
    c.eigen_expm_general = c.eigen_logm_general = 0.0;
#endif
    int bad = 0; /* a status other than GA_OK in the cross-checks */
    for (int j = 0; j < RING; j++) {
        ga_dualquat d1 = ga_rotor_to_dualquat(ga_rotor_mul(rot_a[j], rot_b[j]));
        ga_dualquat d2 = dualquat_mul(dq_a[j], dq_b[j]);
        c.dualquat_vs_motor = fmax(c.dualquat_vs_motor, maxdiff(&d1.real.w, &d2.real.w, 4));
        c.dualquat_vs_motor = fmax(c.dualquat_vs_motor, maxdiff(&d1.dual.w, &d2.dual.w, 4));
        ga_mv g1 = ga_mv_gp(mv_a[j], mv_b[j]), g2;
        gp_table(&mv_a[j], &mv_b[j], &g2);
        c.gp_vs_table = fmax(c.gp_vs_table, maxdiff(g1.c, g2.c, 32));

        ga_vec3 y1 = ga_rotor_apply(rot_a[j], pts[j]), y2 = mat4_apply(&rigid_a[j], pts[j]);
        ga_vec3 y3;
        bad |= ga_point_down(ga_rotor_apply_mv(rot_a[j], ga_point_up(pts[j])), &y3);
        c.apply_vs_matrix = fmax(c.apply_vs_matrix, maxdiff(&y1.x, &y2.x, 3));
        c.apply_vs_sandwich = fmax(c.apply_vs_sandwich, maxdiff(&y1.x, &y3.x, 3));

        ga_mat4 e1 = ga_rotor_to_mat4(ga_rotor_exp(gens[j])), e2 = ga_se3_exp(twists[j]), e3;
        c.exp_vs_se3 = fmax(c.exp_vs_se3, maxdiff(e1.m, e2.m, 16));
        ga_generator g;
        ga_twist t1, t2;
        bad |= ga_rotor_log(rot_a[j], &g);
        t1 = ga_generator_to_twist(g);
        bad |= ga_se3_log(rigid_a[j], &t2);
        c.log_vs_se3 = fmax(c.log_vs_se3, maxdiff(&t1.w.x, &t2.w.x, 6));
        bad |= ga_mat4_expm(hats[j], &e3);
        c.expm_vs_se3 = fmax(c.expm_vs_se3, maxdiff(e3.m, e2.m, 16));
        ga_mat4 lh = ga_twist_hat(t2), l3;
        bad |= ga_mat4_logm(rigid_a[j], &l3);
        c.logm_vs_se3 = fmax(c.logm_vs_se3, maxdiff(l3.m, lh.m, 16));
#ifdef GAROTOR_BENCH_EIGEN
        ga_mat4 m;
        garotor_eigen_expm(hats[j].m, m.m);
        c.eigen_expm_vs_se3 = fmax(c.eigen_expm_vs_se3, maxdiff(m.m, e2.m, 16));
        garotor_eigen_logm(rigid_a[j].m, m.m);
        c.eigen_logm_vs_se3 = fmax(c.eigen_logm_vs_se3, maxdiff(m.m, lh.m, 16));
        garotor_eigen_expm(gen_x[j].m, m.m);
        c.eigen_expm_general = fmax(c.eigen_expm_general, maxdiff(m.m, gen_m[j].m, 16));
        garotor_eigen_logm(gen_m[j].m, m.m);
        c.eigen_logm_general = fmax(c.eigen_logm_general, maxdiff(m.m, gen_x[j].m, 16));
#endif
    }
    if (bad) /* the inputs are valid rigid motions: a failure is a bug */
        fprintf(stderr, "garotor-bench: a cross-check call returned an error status\n");
    return c;
}

/* Batch sampling throughput: BATCH_POSES poses of a screw path on rotors
 * into a caller buffer, one ga_path_sample_uniform call; median of reps. */
static double batch_poses_per_s(ga_eval ev, int reps, void *buf)
{
    double best[16];
    if (reps > 16)
        reps = 16;
    int st = 0;
    for (int r = 0; r <= reps; r++) { /* r = 0 warms up */
        double t0 = now_ns();
        st |= ga_path_sample_uniform(&paths[PG_CGA_SCREW][r % N_PATHS], ev, EULER_STEP, BATCH_POSES, 0.0,
                                     N_KEYS - 1.0, buf);
        double el = now_ns() - t0;
        if (r > 0)
            best[r - 1] = el;
    }
    status_or |= st;
    sink = ((const double *)buf)[8 * (BATCH_POSES - 1)];
    qsort(best, (size_t)reps, sizeof best[0], cmp_double);
    return (double)BATCH_POSES / (quantile(best, reps, 0.5) * 1e-9);
}

/* ---- machine ------------------------------------------------------------------ */

static void cpu_model(char *buf, size_t len)
{
    snprintf(buf, len, "unknown");
    FILE *f = fopen("/proc/cpuinfo", "r");
    if (!f)
        return;
    char line[512];
    while (fgets(line, sizeof line, f)) {
        if (strncmp(line, "model name", 10) == 0) {
            char *p = strchr(line, ':');
            if (p) {
                p++;
                while (*p == ' ' || *p == '\t') p++;
                p[strcspn(p, "\n")] = 0;
                snprintf(buf, len, "%s", p);
            }
            break;
        }
    }
    fclose(f);
}

static const char *compiler(void)
{
#if defined(__clang__)
    return "clang " __clang_version__;
#elif defined(__GNUC__)
    return "gcc " __VERSION__;
#else
    return "unknown";
#endif
}

/* a string safe inside JSON quotes */
static void json_str(const char *s)
{
    putchar('"');
    for (; *s; s++) {
        if (*s == '"' || *s == '\\')
            printf("\\%c", *s);
        else if ((unsigned char)*s < 0x20)
            printf("\\u%04x", (unsigned char)*s);
        else
            putchar(*s);
    }
    putchar('"');
}

/* JSON has no NaN: print null instead */
static void json_num(const char *fmt, double x)
{
    if (isfinite(x))
        printf(fmt, x);
    else
        printf("null");
}

/* ---- the speed targets ------------------------------------------------------- */

typedef struct {
    const char *name; /* the ratio */
    const char *num, *den;
    double limit;
    int at_least; /* 1: ratio >= limit; 0: ratio <= limit */
    const char *meaning;
} ratio_def;

static const ratio_def ratios[] = {
    {"motor_mul/dualquat_mul", "motor_mul", "dualquat_mul", 1.2, 0,
     "compact rotor product against the inline dual-quaternion floor"},
    {"motor_apply/mat4_apply", "motor_apply", "mat4_apply", 1.5, 0,
     "point action: rotor against an inline 4x4 matrix"},
    {"gp_full/gp_table", "gp_full", "gp_table", 0.3, 0, "dense product against a plain table-driven loop"},
    {"gp_full/motor_mul", "gp_full", "motor_mul", 8.0, 1,
     "what the compact form saves over the full algebra"},
    {"exp/se3_exp", "exp", "se3_exp", 0.7, 0, "rotor exp against Eberly's 4x4 exp"},
    {"log/se3_log", "log", "se3_log", 0.7, 0, "rotor log against Eberly's 4x4 log"},
    {"sample_exact/sample_euler", "sample_exact", "sample_euler", 0.5, 0,
     "exact stepping against one Euler step, same poses"},
    {"sample_direct/exp", "sample_direct", "exp", 2.0, 0, "a closed-form screw pose against one exp"},
    {"sample_exact/motor_mul", "sample_exact", "motor_mul", 2.5, 0,
     "an exactly stepped screw pose against one product"},
    {"se3_exp/eigen_expm", "se3_exp", "eigen_expm", 1.0, 0,
     "closed-form SE(3) exp against Eigen's general expm"},
    {"se3_log/eigen_logm", "se3_log", "eigen_logm", 1.0, 0,
     "closed-form SE(3) log against Eigen's general logm"},
    /* extras, no target */
    {"motor_mul_call/motor_mul", "motor_mul_call", "motor_mul", NAN, 0,
     "the product through the library's symbol against inline"},
    {"motor_mul_chain/dualquat_mul_chain", "motor_mul_chain", "dualquat_mul_chain", NAN, 0,
     "product latency: rotor against dual quaternion"},
    {"exp_chain/se3_exp_chain", "exp_chain", "se3_exp_chain", NAN, 0, "exp latency: rotor against 4x4"},
    {"apply_sandwich/motor_apply", "apply_sandwich", "motor_apply", NAN, 0,
     "full sandwich against the fast point action"},
    {"motor_mul/mat4_mul", "motor_mul", "mat4_mul", NAN, 0, "composition: rotor against 4x4 matrix"},
    {"exp_to_mat4/se3_exp", "exp_to_mat4", "se3_exp", NAN, 0, "a 4x4 exp computed through the rotor"},
    {"log_from_mat4/se3_log", "log_from_mat4", "se3_log", NAN, 0, "a 4x4 log computed through the rotor"},
    {"mat4_expm_se3/se3_exp", "mat4_expm_se3", "se3_exp", NAN, 0,
     "general Pade expm against the closed form, same inputs"},
    {"mat4_logm_se3/se3_log", "mat4_logm_se3", "se3_log", NAN, 0,
     "general logm against the closed form, same inputs"},
    {"mat4_expm/eigen_expm_general", "mat4_expm", "eigen_expm_general", NAN, 0,
     "garotor's general expm against Eigen's"},
    {"mat4_logm/eigen_logm_general", "mat4_logm", "eigen_logm_general", NAN, 0,
     "garotor's general logm against Eigen's"},
    {"sample_direct/eigen_slerp_lerp", "sample_direct", "eigen_slerp_lerp", NAN, 0,
     "a screw pose against decoupled slerp + lerp"},
    {"sample_exact/eigen_slerp_lerp", "sample_exact", "eigen_slerp_lerp", NAN, 0,
     "an exactly stepped screw pose against slerp + lerp"},
    {"sample_exact/sample_direct", "sample_exact", "sample_direct", NAN, 0,
     "exact stepping against closed-form sampling"},
    {"sample_direct/sample_direct_se3", "sample_direct", "sample_direct_se3", NAN, 0,
     "screw sampling: rotors against 4x4 matrices"},
    {"sample_exact_lihao3/sample_euler_lihao3", "sample_exact_lihao3", "sample_euler_lihao3", NAN, 0,
     "exact against Euler on the cubic Li-Hao form"},
};
#define N_RATIOS (sizeof ratios / sizeof ratios[0])

static double ratio_value(const ratio_def *r) { return ns_of(r->num) / ns_of(r->den); }

/* 1 pass, 0 fail, -1 no target or not measured */
static int ratio_pass(const ratio_def *r)
{
    double v = ratio_value(r);
    if (isnan(r->limit) || !isfinite(v))
        return -1;
    return r->at_least ? v >= r->limit : v <= r->limit;
}

/* ---- main --------------------------------------------------------------------- */

static void usage(FILE *f)
{
    fprintf(f,
            "usage: garotor-bench [--json] [--quick] [--seed N] [--batches N] [--batch-ms X]\n"
            "                     [--only KEY,KEY,...]\n"
            "\n"
            "Times garotor's hot paths against 4x4 matrices, a textbook dual-quaternion\n"
            "product and (where built with Eigen 3) Eigen's MatrixFunctions and slerp.\n"
            "Each figure is the median ns per call over repeated interleaved batches.\n"
            "\n"
            "  --json         print one JSON object {\"ns\": ..., \"err\": ..., ...}, not a table\n"
            "  --quick        fewer, shorter batches: a smoke test, not a measurement\n"
            "  --seed N       seed of the input PRNG (default 1)\n"
            "  --batches N    timed batches per figure (default %d)\n"
            "  --batch-ms X   target duration of one batch in ms (default %g)\n"
            "  --only KEYS    time only these keys (comma-separated; for profiling)\n"
            "  --help         this text\n",
            DEFAULT_BATCHES, DEFAULT_BATCH_MS);
}

int main(int argc, char **argv)
{
    int json = 0, quick = 0, opt_batches = 0;
    double opt_batch_ms = 0.0;
    unsigned long long seed = 1;
    const char *only = NULL;
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--json") == 0)
            json = 1;
        else if (strcmp(argv[i], "--quick") == 0)
            quick = 1;
        else if (strcmp(argv[i], "--seed") == 0 && i + 1 < argc)
            seed = strtoull(argv[++i], NULL, 0);
        else if (strcmp(argv[i], "--batches") == 0 && i + 1 < argc)
            opt_batches = atoi(argv[++i]);
        else if (strcmp(argv[i], "--batch-ms") == 0 && i + 1 < argc)
            opt_batch_ms = atof(argv[++i]);
        else if (strcmp(argv[i], "--only") == 0 && i + 1 < argc)
            only = argv[++i];
        else if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) {
            usage(stdout);
            return 0;
        } else {
            fprintf(stderr, "garotor-bench: unknown option '%s'\n", argv[i]);
            usage(stderr);
            return 2;
        }
    }
    const int n_batches = opt_batches >= 1 ? opt_batches : quick ? 5 : DEFAULT_BATCHES;
    const double batch_ns = opt_batch_ms > 0 ? opt_batch_ms * 1e6 : quick ? 2e5 : DEFAULT_BATCH_MS * 1e6;
    const int batch_reps = quick ? 1 : 5;

    rng_seed(seed);
    int st = setup_inputs();
    if (st != GA_OK) {
        fprintf(stderr, "garotor-bench: building the inputs failed: %s\n", ga_status_string(st));
        return 1;
    }
    checks chk = run_checks();
    double euler_max, exact_max, euler_max_se3, exact_max_se3;
    double euler_max_l3, exact_max_l3, euler_max_l3_se3, exact_max_l3_se3;
    path_errors(PG_CGA_SCREW, &euler_max, &exact_max);
    path_errors(PG_SE3_SCREW, &euler_max_se3, &exact_max_se3);
    path_errors(PG_CGA_LIHAO3, &euler_max_l3, &exact_max_l3);
    path_errors(PG_SE3_LIHAO3, &euler_max_l3_se3, &exact_max_l3_se3);

    /* calibrate, warm up, then interleaved batches (b->ns == NULL: not
       selected by --only, not timed, printed as not measured) */
    for (size_t i = 0; i < N_BENCH; i++) {
        if (!selected(only, benches[i].key))
            continue;
        benches[i].ns = malloc((size_t)n_batches * sizeof(double));
        if (!benches[i].ns) {
            fprintf(stderr, "garotor-bench: out of memory\n");
            return 1;
        }
        calibrate(&benches[i], batch_ns);
        (void)time_batch(&benches[i]);
    }
    for (int r = 0; r < n_batches; r++)
        for (size_t i = 0; i < N_BENCH; i++)
            if (benches[i].ns)
                benches[i].ns[r] = time_batch(&benches[i]);
    for (size_t i = 0; i < N_BENCH; i++) {
        bench *b = &benches[i];
        if (!b->ns) {
            b->median = b->p25 = b->p75 = NAN;
            continue;
        }
        qsort(b->ns, (size_t)n_batches, sizeof(double), cmp_double);
        b->median = quantile(b->ns, n_batches, 0.5);
        b->p25 = quantile(b->ns, n_batches, 0.25);
        b->p75 = quantile(b->ns, n_batches, 0.75);
    }

    /* batch sampling throughput, N = 1e6 poses into a caller buffer */
    double pps_direct = NAN, pps_exact = NAN;
    void *big = malloc((size_t)BATCH_POSES * sizeof(ga_rotor));
    if (big && !only) {
        pps_direct = batch_poses_per_s(GA_EVAL_DIRECT, batch_reps, big);
        pps_exact = batch_poses_per_s(GA_EVAL_EXACT, batch_reps, big);
    }
    free(big);

    char cpu[256];
    cpu_model(cpu, sizeof cpu);
    long ncpu = sysconf(_SC_NPROCESSORS_ONLN);
    const char *eigen_version = NULL;
#ifdef GAROTOR_BENCH_EIGEN
    eigen_version = garotor_eigen_version();
#endif

    if (json) {
        printf("{\n  \"ns\": {");
        for (size_t i = 0; i < N_BENCH; i++) {
            printf("%s\n    ", i ? "," : "");
            json_str(benches[i].key);
            printf(": ");
            json_num("%.4g", benches[i].median);
        }
        printf("\n  },\n  \"err\": {\n");
        printf("    \"euler_max\": ");
        json_num("%.3e", euler_max);
        printf(",\n    \"exact_max\": ");
        json_num("%.3e", exact_max);
        printf(",\n    \"euler_max_se3\": ");
        json_num("%.3e", euler_max_se3);
        printf(",\n    \"exact_max_se3\": ");
        json_num("%.3e", exact_max_se3);
        printf(",\n    \"euler_max_lihao3\": ");
        json_num("%.3e", euler_max_l3);
        printf(",\n    \"exact_max_lihao3\": ");
        json_num("%.3e", exact_max_l3);
        printf(",\n    \"euler_max_lihao3_se3\": ");
        json_num("%.3e", euler_max_l3_se3);
        printf(",\n    \"exact_max_lihao3_se3\": ");
        json_num("%.3e", exact_max_l3_se3);
        printf("\n  },\n  \"ratios\": {");
        int first = 1;
        for (size_t i = 0; i < N_RATIOS; i++) {
            double v = ratio_value(&ratios[i]);
            if (!isfinite(v))
                continue;
            printf("%s\n    ", first ? "" : ",");
            first = 0;
            json_str(ratios[i].name);
            printf(": %.4g", v);
        }
        printf("\n  },\n  \"targets\": {");
        first = 1;
        for (size_t i = 0; i < N_RATIOS; i++) {
            int pass = ratio_pass(&ratios[i]);
            if (pass < 0)
                continue;
            printf("%s\n    ", first ? "" : ",");
            first = 0;
            json_str(ratios[i].name);
            printf(": {\"value\": %.4g, \"op\": \"%s\", \"bound\": %.4g, \"pass\": %s}",
                   ratio_value(&ratios[i]), ratios[i].at_least ? ">=" : "<=", ratios[i].limit,
                   pass ? "true" : "false");
        }
        printf("%s\n    \"exact_max\": {\"value\": ", first ? "" : ",");
        json_num("%.3e", exact_max);
        printf(", \"op\": \"<=\", \"bound\": 1e-12, \"pass\": %s}", exact_max <= 1e-12 ? "true" : "false");
        printf("\n  },\n  \"spread\": {");
        for (size_t i = 0; i < N_BENCH; i++) {
            printf("%s\n    ", i ? "," : "");
            json_str(benches[i].key);
            printf(": [");
            json_num("%.4g", benches[i].p25);
            printf(", ");
            json_num("%.4g", benches[i].p75);
            printf("]");
        }
        printf("\n  },\n  \"throughput\": {\n    \"batch_direct_poses_per_s\": ");
        json_num("%.4g", pps_direct);
        printf(",\n    \"batch_exact_poses_per_s\": ");
        json_num("%.4g", pps_exact);
        printf(",\n    \"batch_poses\": %d\n  },\n", BATCH_POSES);
        printf("  \"check\": {\n");
        printf("    \"dualquat_vs_motor\": %.3e,\n", chk.dualquat_vs_motor);
        printf("    \"gp_vs_table\": %.3e,\n", chk.gp_vs_table);
        printf("    \"apply_vs_matrix\": %.3e,\n", chk.apply_vs_matrix);
        printf("    \"apply_vs_sandwich\": %.3e,\n", chk.apply_vs_sandwich);
        printf("    \"exp_vs_se3\": %.3e,\n", chk.exp_vs_se3);
        printf("    \"log_vs_se3\": %.3e,\n", chk.log_vs_se3);
        printf("    \"expm_vs_se3\": %.3e,\n", chk.expm_vs_se3);
        printf("    \"logm_vs_se3\": %.3e,\n    \"eigen_expm_vs_se3\": ", chk.logm_vs_se3);
        json_num("%.3e", chk.eigen_expm_vs_se3);
        printf(",\n    \"eigen_logm_vs_se3\": ");
        json_num("%.3e", chk.eigen_logm_vs_se3);
        printf(",\n    \"eigen_expm_general\": ");
        json_num("%.3e", chk.eigen_expm_general);
        printf(",\n    \"eigen_logm_general\": ");
        json_num("%.3e", chk.eigen_logm_general);
        printf(",\n    \"status_or\": %d\n  },\n", status_or);
        printf("  \"config\": {\"batches\": %d, \"batch_ms\": %g, \"ring\": %d, \"seed\": %llu, "
               "\"quick\": %s, \"path_keys\": %d, \"path_samples\": %d, \"paths\": %d, "
               "\"sample_scheme\": \"screw\", \"sample_group\": \"cga\", \"euler_step\": %.17g, "
               "\"exact_reanchor\": %d},\n",
               n_batches, batch_ns * 1e-6, RING, seed, quick ? "true" : "false", N_KEYS, N_SAMPLES, N_PATHS,
               EULER_STEP, GA_PATH_EXACT_REANCHOR);
        printf("  \"machine\": {\"cpu\": ");
        json_str(cpu);
        printf(", \"nproc\": %ld, \"compiler\": ", ncpu);
        json_str(compiler());
        printf(", \"build\": ");
        json_str(GAROTOR_BENCH_BUILD);
        printf(", \"eigen\": ");
        if (eigen_version)
            json_str(eigen_version);
        else
            printf("null");
        printf("},\n  \"checksum\": %.17g\n}\n", (double)sink);
        return 0;
    }

    printf("garotor-bench: median ns per call over %d interleaved batches of ~%g ms;\n"
           "inputs: rings of %d seeded random values (seed %llu)%s\n\n",
           n_batches, batch_ns * 1e-6, RING, seed, quick ? "; --quick: not a measurement" : "");
    printf("%-26s %10s %14s  %s\n", "key", "ns/call", "p25..p75", "one call of");
    for (size_t i = 0; i < N_BENCH; i++) {
        const bench *b = &benches[i];
        if (!b->ns)
            continue;
        char spread[64];
        snprintf(spread, sizeof spread, "%.4g..%.4g", b->p25, b->p75);
        printf("%-26s %10.4g %14s  %s\n", b->key, b->median, spread, b->what);
        if (strcmp(b->key, "sample_euler") == 0)
            printf("  (extras)\n");
    }
    printf("\n%-40s %9s %8s  %s\n", "ratio", "value", "target", "meaning");
    for (size_t i = 0; i < N_RATIOS; i++) {
        const ratio_def *r = &ratios[i];
        double v = ratio_value(r);
        int pass = ratio_pass(r);
        char target[32] = "";
        if (!isnan(r->limit))
            snprintf(target, sizeof target, "%s %g", r->at_least ? ">=" : "<=", r->limit);
        if (!isfinite(v))
            printf("%-40s %9s %8s  %s (not measured)\n", r->name, "-", target, r->meaning);
        else
            printf("%-40s %9.3f %8s  %s%s\n", r->name, v, target, r->meaning,
                   pass < 0 ? ""
                   : pass   ? "  [pass]"
                            : "  [FAIL]");
    }
    printf("\nerrors against the closed form (max |entry difference| of the 4x4 matrices,\n"
           "%d paths of %d random keys at t = 0..%d, %d samples each, Euler step h = 1/%d in u):\n",
           N_PATHS, N_KEYS, N_KEYS - 1, N_SAMPLES, SAMPLES_PER_SEG);
    printf("  err.euler_max  %.3e   screw, rotors (cga), h = 1/%d\n", euler_max, SAMPLES_PER_SEG);
    printf("  err.exact_max  %.3e   screw, rotors (cga), re-anchored every %d samples  [%s]\n", exact_max,
           GA_PATH_EXACT_REANCHOR, exact_max <= 1e-12 ? "pass: <= 1e-12" : "FAIL: > 1e-12");
    printf("  euler_max_se3  %.3e   screw, 4x4 matrices\n", euler_max_se3);
    printf("  exact_max_se3  %.3e   screw, 4x4 matrices\n", exact_max_se3);
    printf("  euler_max_lihao3      %.3e   lihao3, rotors\n", euler_max_l3);
    printf("  exact_max_lihao3      %.3e   lihao3, rotors\n", exact_max_l3);
    printf("  euler_max_lihao3_se3  %.3e   lihao3, 4x4 matrices\n", euler_max_l3_se3);
    printf("  exact_max_lihao3_se3  %.3e   lihao3, 4x4 matrices\n", exact_max_l3_se3);
    printf("\nbatch sampling, %d poses of a screw path on rotors into a caller buffer:\n"
           "  direct %.4g poses/s, exact %.4g poses/s\n",
           BATCH_POSES, pps_direct, pps_exact);
    printf("\nchecks (max |difference| between two routes to the same result):\n"
           "  dualquat vs motor %.1e, gp vs table %.1e, apply vs matrix %.1e, apply vs sandwich %.1e,\n"
           "  exp vs se3_exp %.1e, log vs se3_log %.1e, mat4_expm vs se3_exp %.1e, "
           "mat4_logm vs se3_log %.1e,\n"
           "  eigen: expm vs se3_exp %.1e, logm vs se3_log %.1e, general expm %.1e, "
           "general logm %.1e; status %d\n",
           chk.dualquat_vs_motor, chk.gp_vs_table, chk.apply_vs_matrix, chk.apply_vs_sandwich, chk.exp_vs_se3,
           chk.log_vs_se3, chk.expm_vs_se3, chk.logm_vs_se3, chk.eigen_expm_vs_se3, chk.eigen_logm_vs_se3,
           chk.eigen_expm_general, chk.eigen_logm_general, status_or);
    printf("\nmachine: %s, %ld online CPUs; %s; build %s; Eigen %s\n", cpu, ncpu, compiler(),
           GAROTOR_BENCH_BUILD, eigen_version ? eigen_version : "absent");
    printf("checksum %.17g\n", (double)sink);
    return 0;
}
