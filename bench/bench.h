/* bench/bench.h: what the files of garotor-bench share: the sizes of its
 * inputs and paths, the rings and paths the timed loops read (cases.c), the
 * benchmark table, and the entry points of its parts: the inputs (inputs.c),
 * the timing harness (harness.c), the cross-checks (checks.c) and the report
 * (report.c). The floors the cases are measured against are floors.h.
 */
#ifndef GAROTOR_BENCH_H
#define GAROTOR_BENCH_H

#include <stddef.h>
#include <stdint.h>

#include <garotor/garotor.h>
#include <garotor/conformal.h>
#include <garotor/mat4.h>
#include <garotor/object.h>
#include <garotor/path.h>
#include <garotor/rotor.h>
#include <garotor/rotor_inline.h>
#include <garotor/versor.h>

#ifdef GAROTOR_BENCH_EIGEN
#include "eigen_peer.h"
#endif

#ifndef GAROTOR_BENCH_BUILD
#define GAROTOR_BENCH_BUILD "unknown"
#endif

#define RING 1024
#define MASK (RING - 1)

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
#define APPLY_POINTS 1000 /* points under one motion in apply_many and its floors */

/* Many short batches: on a busy machine a short batch is more often
 * uninterrupted, and the median then ignores the interrupted ones. */
#define DEFAULT_BATCHES 101
#define DEFAULT_BATCH_MS 0.5

/* ---- the rings and paths (cases.c defines them, inputs.c fills them) ------- */

extern ga_mv mv_a[RING], mv_b[RING];
extern ga_mv mv_rot[RING], mv_rot_rev[RING];       /* rot_a as multivectors, and their reverses */
extern ga_mv mv_pt[RING];                          /* F(x) of pts */
extern double even_rot[RING][16], vec_pt[RING][5]; /* mv_rot's even and mv_pt's vector coefficients */
extern ga_rotor rot_a[RING], rot_b[RING];
extern ga_dualquat dq_a[RING], dq_b[RING];
extern ga_vec3 pts[RING];
extern ga_twist twists[RING];
extern ga_generator gens[RING];
extern ga_mat4 rigid_a[RING], rigid_b[RING]; /* the matrices of rot_a, rot_b */
extern ga_mat4 hats[RING];                   /* twist^ of twists */
extern ga_mat4 gen_x[RING];                  /* general 4x4, last row zero */
extern ga_mat4 gen_m[RING];                  /* expm(gen_x): general invertible */

extern volatile double sink;
extern int status_or; /* OR of every status returned in the timed loops */

enum { PG_CGA_SCREW, PG_SE3_SCREW, PG_CGA_LIHAO3, PG_SE3_LIHAO3, PG_CGA_DECOUPLED, N_PATH_KINDS };

typedef struct {
    const ga_group *group;
    ga_scheme scheme;
} path_kind_def;
extern const path_kind_def path_kind[N_PATH_KINDS];

extern ga_path paths[N_PATH_KINDS][N_PATHS];
extern double key_poses[N_PATHS][N_KEYS][7]; /* x y z qx qy qz qw */

/* the tables of the floor gp_table (floors.h) */
extern double gp_sign[32][32];
extern unsigned char gp_index[32][32];

/* ---- the benchmark table (cases.c) ----------------------------------------- */

typedef size_t (*run_fn)(const void *ctx, size_t n);

typedef struct {
    const char *key;
    const char *what;
    run_fn run;
    const void *ctx;
    size_t calls; /* per batch, after calibration */
    double *ns;   /* ns per call, one per batch */
    double median, p25, p75;
} bench;

extern bench benches[];
extern const size_t n_benches;

/* ---- cases_path.c: the C2 build, a pose against an acceleration --------------- */

/* ctx: &path_keys_2000 or &path_keys_1e5; a call is one build, a batch at
   least 1e5 keys' worth (returned as the calls done) */
size_t run_c2_build(const void *ctx, size_t n);
/* ctx: &path_scheme[s]; a call is one ga_path_eval, one ga_path_acceleration */
size_t run_eval(const void *ctx, size_t n);
size_t run_accel(const void *ctx, size_t n);
extern const size_t path_keys_2000, path_keys_1e5;
/* the batches a case is timed in: 0 every batch, else at most this many (the
   c2 builds: a batch of either builds 1e5 keys, about a second) */
int bench_max_batches(const bench *b);
/* 1 where a case is timed on the process's CPU clock, not the monotonic one
   (the c2 builds: a batch of a second on a shared machine is descheduled in
   proportion to the load of that second, which the ratio of the two builds
   would measure) */
int bench_cpu_clock(const bench *b);
extern const int path_scheme[GA_SCHEME_COUNT];

/* ---- cases_meet.c: the object layer's meets -------------------------------------- */

/* The pairs the meet keys time: two direct objects built by conformal.h's
   constructors from random points (inputs.c), in general position, and what
   ga_mv_meet makes of them: a line, a flat point, a circle, a circle. */
enum { MP_PLANE_PLANE, MP_LINE_PLANE, MP_SPHERE_SPHERE, MP_PLANE_SPHERE, N_MEET_PAIRS };
extern const int meet_pair_kind[N_MEET_PAIRS]; /* the GA_OBJECT_* of the meet */
extern ga_mv meet_a[N_MEET_PAIRS][RING], meet_b[N_MEET_PAIRS][RING];
extern ga_mv meet_w[N_MEET_PAIRS][RING]; /* ga_mv_meet of the pair: the read-back's input */
/* ctx: &meet_pair_ix[p] */
extern const int meet_pair_ix[N_MEET_PAIRS];
size_t run_meet(const void *ctx, size_t n);
size_t run_meet_floor(const void *ctx, size_t n);
size_t run_meet_regressive(const void *ctx, size_t n);
size_t run_meet_by_symbols(const void *ctx, size_t n);
size_t run_meet_rel(const void *ctx, size_t n);
size_t run_meet_read(const void *ctx, size_t n);
/** Whether the floor's dual signs (floors.h) are ga_mv_dual's and
    ga_mv_undual's: GA_OK, else GA_ERR_ARG. */
int meet_check_dual(void);

/* ---- inputs.c ---------------------------------------------------------------- */

/** Seed the input PRNG. */
void rng_seed(uint64_t seed);
/** Fill the rings, the floors' tables and the paths; a status. */
int setup_inputs(void);

/* ---- harness.c ----------------------------------------------------------- */

double now_ns(void);
double time_batch(bench *b);
void calibrate(bench *b, double target_ns);
int cmp_double(const void *a, const void *b);
double quantile(const double *s, int n, double q);
double ns_of(const char *key);
int selected(const char *only, const char *key);
double batch_poses_per_s(ga_eval ev, int reps, void *buf);

/* ---- checks.c ---------------------------------------------------------------- */

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
    /* the meets (cases_meet.c), relative to each meet's largest coefficient */
    double meet_vs_floor;    /* ga_mv_meet vs the dual-wedge floor meet_floor */
    double meet_rel_vs_meet; /* ga_mv_meet_rel vs ga_mv_meet (0: bit for bit in general position) */
    int meet_bad; /* pairs whose meet is 0 or whose read-back is not GA_OK and of the pair's kind */
} checks;

double maxdiff(const double *a, const double *b, int n);
checks run_checks(void);
void path_errors(int kind, double *euler_max, double *exact_max);

/* ---- report.c ---------------------------------------------------------------- */

/* What a run measured, for the report. */
typedef struct {
    int n_batches, quick;
    double batch_ns;
    unsigned long long seed;
    double euler_max, exact_max, euler_max_se3, exact_max_se3;
    double euler_max_l3, exact_max_l3, euler_max_l3_se3, exact_max_l3_se3;
    double pps_direct, pps_exact; /* batch sampling, poses per second */
    checks chk;
} bench_run;

/** Print the run as one JSON object (json) or as the table. */
void report(const bench_run *run, int json);

#endif
