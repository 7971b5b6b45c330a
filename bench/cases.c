/* bench/cases.c: the measured cases of garotor-bench: its timed loops (each
 * operation called as a user's code calls it, over rings of inputs) and the
 * table of benchmarks, their keys and what one call of each does.
 *
 * The rings, paths and tables the loops read are defined here, beside the
 * loops, so that every loop addresses them directly as in one file.
 */
#include "floors.h"

/* The library's pointer forms of five products (not exported; the bench
   links the library's objects): only for the by-value/by-pointer keys. */
#include "../ga/internal/mv_kernels.h"

/* ---- inputs and outputs --------------------------------------------------- */

ga_mv mv_a[RING], mv_b[RING];
ga_mv mv_rot[RING], mv_rot_rev[RING], mv_pt[RING];
double even_rot[RING][16], vec_pt[RING][5];
ga_rotor rot_a[RING], rot_b[RING];
ga_dualquat dq_a[RING], dq_b[RING];
ga_vec3 pts[RING];
ga_twist twists[RING];
ga_generator gens[RING];
ga_mat4 rigid_a[RING], rigid_b[RING];
ga_mat4 hats[RING];
ga_mat4 gen_x[RING];
ga_mat4 gen_m[RING];
double gp_sign[32][32];
unsigned char gp_index[32][32];

static ga_mv out_mv[RING];
static ga_rotor out_rot[RING];
static ga_dualquat out_dq[RING];
static ga_vec3 out_v3[RING];
static double out_odd[RING][16];
static ga_generator out_gen[RING];
static ga_twist out_tw[RING];
static ga_mat4 out_mat[RING];
#ifdef GAROTOR_BENCH_EIGEN
static double out_pose[RING][7];
#endif

volatile double sink;
static size_t cursor; /* where the next batch continues in the rings */
int status_or;

/* ---- paths ----------------------------------------------------------------- */

const path_kind_def path_kind[N_PATH_KINDS] = {
    {&ga_group_cga, GA_SCHEME_SCREW},     {&ga_group_se3, GA_SCHEME_SCREW},
    {&ga_group_cga, GA_SCHEME_LIHAO3},    {&ga_group_se3, GA_SCHEME_LIHAO3},
    {&ga_group_cga, GA_SCHEME_DECOUPLED},
};

ga_path paths[N_PATH_KINDS][N_PATHS];
double key_poses[N_PATHS][N_KEYS][7];
static double sample_buf[N_SAMPLES * GA_GROUP_MAX_ELEM];
static size_t path_cursor;

/* ---- the timed loops ---------------------------------------------------------
 * Each takes its calls n and returns how many it made (the sampling loops make
 * whole paths of N_SAMPLES poses). */

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
/* the other products of two dense multivectors, and their pointer forms */
RING_LOOP(run_lc, out_mv[j] = ga_mv_lc(mv_a[j], mv_b[j]), out_mv[last].c[31])
RING_LOOP(run_op, out_mv[j] = ga_mv_op(mv_a[j], mv_b[j]), out_mv[last].c[31])
RING_LOOP(run_dot, out_mv[j] = ga_mv_dot(mv_a[j], mv_b[j]), out_mv[last].c[31])
RING_LOOP(run_ip, out_mv[j] = ga_mv_ip(mv_a[j], mv_b[j]), out_mv[last].c[31])
RING_LOOP(run_sp, out_v3[j].x = ga_mv_sp(mv_a[j], mv_b[j]), out_v3[last].x)
RING_LOOP(run_regressive, out_mv[j] = ga_mv_regressive(mv_a[j], mv_b[j]), out_mv[last].c[31])
RING_LOOP(run_commutator, out_mv[j] = ga_mv_commutator(mv_a[j], mv_b[j]), out_mv[last].c[31])
RING_LOOP(run_gp_full_ptr, gak_gp_p(&mv_a[j], &mv_b[j], &out_mv[j]), out_mv[last].c[31])
RING_LOOP(run_lc_ptr, gak_lc_p(&mv_a[j], &mv_b[j], &out_mv[j]), out_mv[last].c[31])
RING_LOOP(run_op_ptr, gak_op_p(&mv_a[j], &mv_b[j], &out_mv[j]), out_mv[last].c[31])
RING_LOOP(run_dot_ptr, gak_dot_p(&mv_a[j], &mv_b[j], &out_mv[j]), out_mv[last].c[31])
RING_LOOP(run_gp_rotor_vector_ptr, gak_gp_even_vector_p(&mv_rot[j], &mv_pt[j], &out_mv[j]),
          out_mv[last].c[31])
/* sparse pairs: a rotor times a point, on their coefficients (16 even, 5),
   and both as full multivectors */
RING_LOOP(run_gp_rotor_vector, st |= ga_mv_gp_even_vector_sparse(even_rot[j], vec_pt[j], out_odd[j]),
          out_odd[last][15])
RING_LOOP(run_gp_rotor_vector_mv, out_mv[j] = ga_mv_gp_even_vector(mv_rot[j], mv_pt[j]), out_mv[last].c[31])
/* the sandwich of a point: ga_versor_apply, and by hand (two ga_mv_gp, the
   reverse taken beforehand) */
RING_LOOP(run_versor_apply, st |= ga_versor_apply(mv_rot[j], mv_pt[j], &out_mv[j]), out_mv[last].c[5])
RING_LOOP(run_sandwich_hand, out_mv[j] = ga_mv_gp(ga_mv_gp(mv_rot[j], mv_pt[j]), mv_rot_rev[j]),
          out_mv[last].c[5])

/* APPLY_POINTS points under one motion a call (the ring's next), per point:
   the library's batch, and the loop a user writes around an inline 4x4 */
static ga_vec3 out_pts[APPLY_POINTS];
#define POINTS_LOOP(name, BODY)                                                                              \
    static size_t name(const void *ctx, size_t n)                                                            \
    {                                                                                                        \
        (void)ctx;                                                                                           \
        size_t done = 0, k = cursor;                                                                         \
        int st = 0;                                                                                          \
        while (done < n) {                                                                                   \
            size_t j = k++ & MASK;                                                                           \
            BODY;                                                                                            \
            done += APPLY_POINTS;                                                                            \
        }                                                                                                    \
        cursor = k;                                                                                          \
        status_or |= st;                                                                                     \
        sink = out_pts[APPLY_POINTS - 1].z;                                                                  \
        return done;                                                                                         \
    }
POINTS_LOOP(run_apply_many, st |= ga_rotor_apply_many(rot_a[j], pts, APPLY_POINTS, out_pts))
POINTS_LOOP(run_mat4_apply_many, st |= ga_mat4_apply_many(rigid_a[j], pts, APPLY_POINTS, out_pts))
POINTS_LOOP(run_mat4_loop, const ga_mat4 *m = &rigid_a[j];
            for (size_t i = 0; i < APPLY_POINTS; i++) out_pts[i] = mat4_apply(m, pts[i]))
POINTS_LOOP(run_motor_apply_loop, ga_rotor r = rot_a[j];
            for (size_t i = 0; i < APPLY_POINTS; i++) out_pts[i] = ga_rotor_apply(r, pts[i]))
/* The machine's multiply-add peak, a call one multiply-add (a lane's): in
 * this build's scalar code (a multiplication, then an addition: the library
 * compiles without contraction), one dependent chain (latency) and 16
 * independent ones (throughput, as -O3 vectorises them); and with gcc on
 * x86-64, fused multiply-adds in vectors of 8 (AVX-512F + FMA, where the CPU
 * has them; else the scalar loops), 1 chain and 16. The multiplier 1 - 2^-30
 * and the addend keep every chain finite and its numbers never denormal. */
#define MADD_A (1.0 - 0x1p-30)
#define MADD_B 0x1p-40
static double madd_x[16] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16};
static size_t run_madd_dep(const void *ctx, size_t n)
{
    (void)ctx;
    double x = madd_x[0], a = MADD_A * (1.0 + 0.0 * sink), b = MADD_B;
    for (size_t i = 0; i < n; i++) x = x * a + b;
    madd_x[0] = x;
    sink = x;
    return n;
}
static size_t run_madd_indep(const void *ctx, size_t n)
{
    (void)ctx;
    double x[16], a = MADD_A * (1.0 + 0.0 * sink), b = MADD_B;
    memcpy(x, madd_x, sizeof x);
    size_t m = (n + 15) / 16;
    for (size_t i = 0; i < m; i++)
        for (int k = 0; k < 16; k++) x[k] = x[k] * a + b;
    memcpy(madd_x, x, sizeof x);
    sink = x[0] + x[15];
    return 16 * m;
}
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#define BENCH_FMA_V8 1
typedef double v8d __attribute__((vector_size(64)));
__attribute__((target("avx512f,fma"))) static size_t fma_v8(size_t n, int chains)
{
    v8d x[16], a, b;
    for (int k = 0; k < 16; k++)
        for (int l = 0; l < 8; l++) x[k][l] = madd_x[k] + l;
    for (int l = 0; l < 8; l++) a[l] = MADD_A * (1.0 + 0.0 * sink), b[l] = MADD_B;
    size_t m;
    if (chains == 1) {
        m = (n + 7) / 8;
        for (size_t i = 0; i < m; i++)
            x[0] = __builtin_ia32_vfmaddpd512_mask(x[0], a, b, (unsigned char)-1, 4);
        m *= 8;
    } else {
        m = (n + 127) / 128;
        for (size_t i = 0; i < m; i++)
            for (int k = 0; k < 16; k++)
                x[k] = __builtin_ia32_vfmaddpd512_mask(x[k], a, b, (unsigned char)-1, 4);
        m *= 128;
    }
    double s = 0.0;
    for (int k = 0; k < 16; k++) s += x[k][0] + x[k][7];
    sink = s;
    return m;
}
static int fma_v8_here(void)
{
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("fma");
}
#endif
static size_t run_fma_dep(const void *ctx, size_t n)
{
#ifdef BENCH_FMA_V8
    if (fma_v8_here())
        return fma_v8(n, 1);
#endif
    return run_madd_dep(ctx, n);
}
static size_t run_fma_indep(const void *ctx, size_t n)
{
#ifdef BENCH_FMA_V8
    if (fma_v8_here())
        return fma_v8(n, 16);
#endif
    return run_madd_indep(ctx, n);
}
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
static const sample_ctx ctx_cga_decoupled_direct = {PG_CGA_DECOUPLED, GA_EVAL_DIRECT};

bench benches[] = {
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
    {"apply_many", "ga_rotor_apply_many: 1000 points under one rotor, per point", run_apply_many, NULL, 0,
     NULL, 0, 0, 0},
    {"lc", "ga_mv_lc: left contraction, two dense multivectors", run_lc, NULL, 0, NULL, 0, 0, 0},
    {"dot", "ga_mv_dot: fat dot, two dense multivectors", run_dot, NULL, 0, NULL, 0, 0, 0},
    {"versor_apply", "ga_versor_apply: a rotor (as ga_mv) on a point F(x)", run_versor_apply, NULL, 0, NULL,
     0, 0, 0},
    {"sandwich_hand", "ga_mv_gp(ga_mv_gp(R, F(x)), ~R), ~R given: the sandwich by hand", run_sandwich_hand,
     NULL, 0, NULL, 0, 0, 0},
    {"gp_rotor_vector", "ga_mv_gp_even_vector_sparse: a rotor's 16 even coefficients times a point's 5",
     run_gp_rotor_vector, NULL, 0, NULL, 0, 0, 0},
    {"sample_decoupled",
     "decoupled path on rotors, per pose: closed form (slerp + lerp, eigen_slerp_lerp's keys)", run_sample,
     &ctx_cga_decoupled_direct, 0, NULL, 0, 0, 0},
    /* extras */
    {"mat4_apply_many", "ga_mat4_apply_many: 1000 points under one 4x4, per point", run_mat4_apply_many, NULL,
     0, NULL, 0, 0, 0},
    {"mat4_loop", "1000 points under one 4x4, inline loop (in the bench), per point", run_mat4_loop, NULL, 0,
     NULL, 0, 0, 0},
    {"motor_apply_loop", "1000 points under one rotor, ga_rotor_apply per point", run_motor_apply_loop, NULL,
     0, NULL, 0, 0, 0},
    {"op", "ga_mv_op: outer product, two dense multivectors", run_op, NULL, 0, NULL, 0, 0, 0},
    {"ip", "ga_mv_ip: Hestenes' inner product, two dense multivectors", run_ip, NULL, 0, NULL, 0, 0, 0},
    {"sp", "ga_mv_sp: scalar product, two dense multivectors", run_sp, NULL, 0, NULL, 0, 0, 0},
    {"regressive", "ga_mv_regressive, two dense multivectors", run_regressive, NULL, 0, NULL, 0, 0, 0},
    {"commutator", "ga_mv_commutator, two dense multivectors", run_commutator, NULL, 0, NULL, 0, 0, 0},
    {"gp_full_ptr", "ga_mv_gp's code by pointer (the library's gak_gp_p, not exported)", run_gp_full_ptr,
     NULL, 0, NULL, 0, 0, 0},
    {"lc_ptr", "ga_mv_lc's code by pointer (gak_lc_p)", run_lc_ptr, NULL, 0, NULL, 0, 0, 0},
    {"op_ptr", "ga_mv_op's code by pointer (gak_op_p)", run_op_ptr, NULL, 0, NULL, 0, 0, 0},
    {"dot_ptr", "ga_mv_dot's code by pointer (gak_dot_p)", run_dot_ptr, NULL, 0, NULL, 0, 0, 0},
    {"gp_rotor_vector_mv", "ga_mv_gp_even_vector: the same product, both as ga_mv (by value)",
     run_gp_rotor_vector_mv, NULL, 0, NULL, 0, 0, 0},
    {"gp_rotor_vector_ptr", "ga_mv_gp_even_vector's code by pointer (gak_gp_even_vector_p)",
     run_gp_rotor_vector_ptr, NULL, 0, NULL, 0, 0, 0},
    {"madd_dep", "one multiply-add (mul, then add), scalar, one dependent chain: latency", run_madd_dep, NULL,
     0, NULL, 0, 0, 0},
    {"madd_indep", "one multiply-add (mul, then add), 16 independent chains as -O3 compiles them",
     run_madd_indep, NULL, 0, NULL, 0, 0, 0},
    {"fma_dep", "one fused multiply-add, a lane of an AVX-512F vector, one dependent chain", run_fma_dep,
     NULL, 0, NULL, 0, 0, 0},
    {"fma_indep", "one fused multiply-add, a lane of an AVX-512F vector, 16 independent chains",
     run_fma_indep, NULL, 0, NULL, 0, 0, 0},
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
    /* paths (cases_path.c): the C2 build, a pose against an acceleration */
    {"c2_build_2000", "ga_path_init: c2 through 2000 keys on rotors, per build (CPU)", run_c2_build,
     &path_keys_2000, 0, NULL, 0, 0, 0},
    {"c2_build_1e5", "ga_path_init: c2 through 1e5 keys on rotors, per build (CPU)", run_c2_build,
     &path_keys_1e5, 0, NULL, 0, 0, 0},
#define EVAL_ACCEL(s, name)                                                                                  \
    {"eval_" name,                                                                                           \
     "ga_path_eval on a " name " path (8 keys, rotors), per pose",                                           \
     run_eval,                                                                                               \
     &path_scheme[s],                                                                                        \
     0,                                                                                                      \
     NULL,                                                                                                   \
     0,                                                                                                      \
     0,                                                                                                      \
     0},                                                                                                     \
    {                                                                                                        \
        "accel_" name, "ga_path_acceleration, same path and times, per call", run_accel, &path_scheme[s], 0, \
            NULL, 0, 0, 0                                                                                    \
    }
    EVAL_ACCEL(GA_SCHEME_SCREW, "screw"),
    EVAL_ACCEL(GA_SCHEME_BIVECTOR, "bivector"),
    EVAL_ACCEL(GA_SCHEME_QUADRATIC, "quadratic"),
    EVAL_ACCEL(GA_SCHEME_SMOOTH, "smooth"),
    EVAL_ACCEL(GA_SCHEME_LIHAO2, "lihao2"),
    EVAL_ACCEL(GA_SCHEME_LIHAO3, "lihao3"),
    EVAL_ACCEL(GA_SCHEME_DECOUPLED, "decoupled"),
    EVAL_ACCEL(GA_SCHEME_DECOUPLED_C2, "decoupled_c2"),
    EVAL_ACCEL(GA_SCHEME_BSPLINE, "bspline"),
    EVAL_ACCEL(GA_SCHEME_C2, "c2"),
#undef EVAL_ACCEL
/* the object layer's meets (cases_meet.c) */
#define MEET_CASE(key, fn, p, what)                                                                          \
    {                                                                                                        \
        key, what, fn, &meet_pair_ix[p], 0, NULL, 0, 0, 0                                                    \
    }
    MEET_CASE("meet_plane_plane", run_meet, MP_PLANE_PLANE, "ga_mv_meet: two planes -> a line"),
    MEET_CASE("meet_line_plane", run_meet, MP_LINE_PLANE, "ga_mv_meet: a line and a plane -> a flat point"),
    MEET_CASE("meet_sphere_sphere", run_meet, MP_SPHERE_SPHERE, "ga_mv_meet: two spheres -> a circle"),
    MEET_CASE("meet_plane_sphere", run_meet, MP_PLANE_SPHERE, "ga_mv_meet: a plane and a sphere -> a circle"),
    MEET_CASE("meet_floor_plane_plane", run_meet_floor, MP_PLANE_PLANE,
              "undual(op(dual A, dual B)) inline (in the bench): two planes -> a line"),
    MEET_CASE("meet_floor_line_plane", run_meet_floor, MP_LINE_PLANE,
              "undual(op(dual A, dual B)) inline (in the bench): a line and a plane -> a flat point"),
    MEET_CASE("meet_floor_sphere_sphere", run_meet_floor, MP_SPHERE_SPHERE,
              "undual(op(dual A, dual B)) inline (in the bench): two spheres -> a circle"),
    MEET_CASE("meet_floor_plane_sphere", run_meet_floor, MP_PLANE_SPHERE,
              "undual(op(dual A, dual B)) inline (in the bench): a plane and a sphere -> a circle"),
    MEET_CASE("meet_rel_plane_plane", run_meet_rel, MP_PLANE_PLANE, "ga_mv_meet_rel: two planes -> a line"),
    MEET_CASE("meet_rel_line_plane", run_meet_rel, MP_LINE_PLANE,
              "ga_mv_meet_rel: a line and a plane -> a flat point"),
    MEET_CASE("meet_rel_sphere_sphere", run_meet_rel, MP_SPHERE_SPHERE,
              "ga_mv_meet_rel: two spheres -> a circle"),
    MEET_CASE("meet_rel_plane_sphere", run_meet_rel, MP_PLANE_SPHERE,
              "ga_mv_meet_rel: a plane and a sphere -> a circle"),
    MEET_CASE("meet_read_plane_plane", run_meet_read, MP_PLANE_PLANE,
              "ga_object_from_mv of the meet: two planes -> a line"),
    MEET_CASE("meet_read_line_plane", run_meet_read, MP_LINE_PLANE,
              "ga_object_from_mv of the meet: a line and a plane -> a flat point"),
    MEET_CASE("meet_read_sphere_sphere", run_meet_read, MP_SPHERE_SPHERE,
              "ga_object_from_mv of the meet: two spheres -> a circle"),
    MEET_CASE("meet_read_plane_sphere", run_meet_read, MP_PLANE_SPHERE,
              "ga_object_from_mv of the meet: a plane and a sphere -> a circle"),
#undef MEET_CASE
    {"meet_regressive", "ga_mv_regressive (one generated kernel) of meet_plane_plane's planes",
     run_meet_regressive, &meet_pair_ix[MP_PLANE_PLANE], 0, NULL, 0, 0, 0},
    {"meet_by_symbols", "ga_mv_undual(ga_mv_op(ga_mv_dual(A), ga_mv_dual(B))), the same planes",
     run_meet_by_symbols, &meet_pair_ix[MP_PLANE_PLANE], 0, NULL, 0, 0, 0},
};
const size_t n_benches = sizeof benches / sizeof benches[0];
