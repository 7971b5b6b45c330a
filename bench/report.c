/* bench/report.c: the report of garotor-bench: the speed targets (ratios of
 * two figures, some with a bound), the machine, and the output, as the text
 * table or as one JSON object (the keys of docs/conventions.md, "The
 * benchmark garotor-bench").
 */
#define _POSIX_C_SOURCE 200809L

#include <math.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "bench.h"

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
    {"motor_apply/mat4_apply", "motor_apply", "mat4_apply", 2.2, 0,
     "point action: rotor against an inline 4x4 matrix"},
    {"apply_many/mat4_apply", "apply_many", "mat4_apply", 1.1, 0,
     "1000 points under one rotor, per point, against an inline 4x4 on one point"},
    {"lc/gp_full", "lc", "gp_full", 1.0, 0, "left contraction against the geometric product"},
    {"dot/gp_full", "dot", "gp_full", 1.0, 0, "fat dot against the geometric product"},
    {"versor_apply/sandwich_hand", "versor_apply", "sandwich_hand", 1.2, 0,
     "ga_versor_apply against two ga_mv_gp by hand"},
    {"gp_rotor_vector/gp_full", "gp_rotor_vector", "gp_full", 0.25, 0,
     "a rotor times a vector (16 and 5 coefficients) against the dense product"},
    {"gp_full/gp_table", "gp_full", "gp_table", 0.3, 0, "dense product against a plain table-driven loop"},
    {"gp_full/motor_mul", "gp_full", "motor_mul", 8.0, 1,
     "what the compact form saves over the full algebra"},
    {"exp/se3_exp", "exp", "se3_exp", 0.7, 0, "rotor exp against Eberly's 4x4 exp"},
    {"log/se3_log", "log", "se3_log", 0.7, 0, "rotor log against Eberly's 4x4 log"},
    {"log/exp", "log", "exp", 1.3, 0, "rotor log against rotor exp"},
    {"sample_exact/sample_euler", "sample_exact", "sample_euler", 0.5, 0,
     "exact stepping against one Euler step, same poses"},
    {"sample_direct/exp", "sample_direct", "exp", 2.0, 0, "a closed-form screw pose against one exp"},
    {"sample_exact/motor_mul", "sample_exact", "motor_mul", 2.5, 0,
     "an exactly stepped screw pose against one product"},
    {"sample_decoupled/eigen_slerp_lerp", "sample_decoupled", "eigen_slerp_lerp", 1.0, 0,
     "a decoupled pose against Eigen's slerp + lerp, same keys and times"},
    {"se3_exp/eigen_expm", "se3_exp", "eigen_expm", 1.0, 0,
     "closed-form SE(3) exp against Eigen's general expm"},
    {"se3_log/eigen_logm", "se3_log", "eigen_logm", 1.0, 0,
     "closed-form SE(3) log against Eigen's general logm"},
    {"c2_build_1e5/c2_build_2000", "c2_build_1e5", "c2_build_2000", 60.0, 0,
     "c2 build linear in the keys: 50 times the keys"},
#define ACCEL_RATIO(name)                                                                                    \
    {                                                                                                        \
        "accel_" name "/eval_" name, "accel_" name, "eval_" name, 3.0, 0,                                    \
            "an acceleration against a pose, " name                                                          \
    }
    ACCEL_RATIO("screw"),
    ACCEL_RATIO("bivector"),
    ACCEL_RATIO("quadratic"),
    ACCEL_RATIO("smooth"),
    ACCEL_RATIO("lihao2"),
    ACCEL_RATIO("lihao3"),
    ACCEL_RATIO("decoupled"),
    ACCEL_RATIO("decoupled_c2"),
    ACCEL_RATIO("bspline"),
    ACCEL_RATIO("c2"),
#undef ACCEL_RATIO
    /* extras, no target */
    {"apply_many/mat4_loop", "apply_many", "mat4_loop", NAN, 0,
     "the rotor batch against an inline 4x4 loop over the same points"},
    {"mat4_apply_many/mat4_loop", "mat4_apply_many", "mat4_loop", NAN, 0,
     "the library's 4x4 batch against the inline loop"},
    {"motor_apply_loop/apply_many", "motor_apply_loop", "apply_many", NAN, 0,
     "ga_rotor_apply per point against the batch"},
    {"op/gp_full", "op", "gp_full", NAN, 0, "outer product against the geometric product"},
    {"ip/gp_full", "ip", "gp_full", NAN, 0, "Hestenes' inner product against the geometric product"},
    {"regressive/gp_full", "regressive", "gp_full", NAN, 0,
     "regressive product against the geometric product"},
    {"commutator/gp_full", "commutator", "gp_full", NAN, 0, "commutator against the geometric product"},
    {"gp_full/gp_full_ptr", "gp_full", "gp_full_ptr", NAN, 0,
     "geometric product: by value against by pointer"},
    {"lc/lc_ptr", "lc", "lc_ptr", NAN, 0, "left contraction: by value against by pointer"},
    {"op/op_ptr", "op", "op_ptr", NAN, 0, "outer product: by value against by pointer"},
    {"dot/dot_ptr", "dot", "dot_ptr", NAN, 0, "fat dot: by value against by pointer"},
    {"gp_rotor_vector_mv/gp_rotor_vector_ptr", "gp_rotor_vector_mv", "gp_rotor_vector_ptr", NAN, 0,
     "rotor times vector: by value against by pointer"},
    {"gp_rotor_vector_mv/gp_full", "gp_rotor_vector_mv", "gp_full", NAN, 0,
     "rotor times vector as ga_mv (by value) against the dense product"},
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
/* the meets: the decision "special position", the join and the
   read-back against the plain formula on the same pairs (no target:
   docs/benchmarks.md, "The meets of the object layer") */
#define MEET_RATIO(key, pair, what)                                                                          \
    {                                                                                                        \
        key "_" pair "/meet_floor_" pair, key "_" pair, "meet_floor_" pair, NAN, 0, what ", " pair           \
    }
    MEET_RATIO("meet", "plane_plane", "ga_mv_meet against the dual-wedge formula"),
    MEET_RATIO("meet", "line_plane", "ga_mv_meet against the dual-wedge formula"),
    MEET_RATIO("meet", "sphere_sphere", "ga_mv_meet against the dual-wedge formula"),
    MEET_RATIO("meet", "plane_sphere", "ga_mv_meet against the dual-wedge formula"),
    MEET_RATIO("meet_rel", "plane_plane", "ga_mv_meet_rel against the dual-wedge formula"),
    MEET_RATIO("meet_rel", "line_plane", "ga_mv_meet_rel against the dual-wedge formula"),
    MEET_RATIO("meet_rel", "sphere_sphere", "ga_mv_meet_rel against the dual-wedge formula"),
    MEET_RATIO("meet_rel", "plane_sphere", "ga_mv_meet_rel against the dual-wedge formula"),
    MEET_RATIO("meet_read", "plane_plane", "the meet's read-back against the dual-wedge formula"),
    MEET_RATIO("meet_read", "line_plane", "the meet's read-back against the dual-wedge formula"),
    MEET_RATIO("meet_read", "sphere_sphere", "the meet's read-back against the dual-wedge formula"),
    MEET_RATIO("meet_read", "plane_sphere", "the meet's read-back against the dual-wedge formula"),
#undef MEET_RATIO
    {"meet_regressive/meet_floor_plane_plane", "meet_regressive", "meet_floor_plane_plane", NAN, 0,
     "the formula as ga_mv_regressive's one kernel against the floor"},
    {"meet_by_symbols/meet_floor_plane_plane", "meet_by_symbols", "meet_floor_plane_plane", NAN, 0,
     "the formula through ga_mv_dual, ga_mv_op, ga_mv_undual against the floor"},
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

/* ---- the output ---------------------------------------------------------------- */

void report(const bench_run *run, int json)
{
    const int n_batches = run->n_batches, quick = run->quick;
    const double batch_ns = run->batch_ns;
    const unsigned long long seed = run->seed;
    const double euler_max = run->euler_max, exact_max = run->exact_max;
    const double euler_max_se3 = run->euler_max_se3, exact_max_se3 = run->exact_max_se3;
    const double euler_max_l3 = run->euler_max_l3, exact_max_l3 = run->exact_max_l3;
    const double euler_max_l3_se3 = run->euler_max_l3_se3, exact_max_l3_se3 = run->exact_max_l3_se3;
    const double pps_direct = run->pps_direct, pps_exact = run->pps_exact;
    const checks chk = run->chk;

    char cpu[256];
    cpu_model(cpu, sizeof cpu);
    long ncpu = sysconf(_SC_NPROCESSORS_ONLN);
    const char *eigen_version = NULL;
#ifdef GAROTOR_BENCH_EIGEN
    eigen_version = garotor_eigen_version();
#endif

    if (json) {
        printf("{\n  \"ns\": {");
        for (size_t i = 0; i < n_benches; i++) {
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
        for (size_t i = 0; i < n_benches; i++) {
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
        printf(",\n    \"meet_vs_floor\": %.3e,\n    \"meet_rel_vs_meet\": %.3e,\n    \"meet_bad\": %d",
               chk.meet_vs_floor, chk.meet_rel_vs_meet, chk.meet_bad);
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
        return;
    }

    printf("garotor-bench: median ns per call over %d interleaved batches of ~%g ms;\n"
           "inputs: rings of %d seeded random values (seed %llu)%s\n\n",
           n_batches, batch_ns * 1e-6, RING, seed, quick ? "; --quick: not a measurement" : "");
    printf("%-26s %10s %14s  %s\n", "key", "ns/call", "p25..p75", "one call of");
    for (size_t i = 0; i < n_benches; i++) {
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
    printf("  meets (relative to the meet's largest coefficient): meet vs floor %.1e, meet_rel vs meet %.1e, "
           "pairs not read as their kind %d\n",
           chk.meet_vs_floor, chk.meet_rel_vs_meet, chk.meet_bad);
    printf("\nmachine: %s, %ld online CPUs; %s; build %s; Eigen %s\n", cpu, ncpu, compiler(),
           GAROTOR_BENCH_BUILD, eigen_version ? eigen_version : "absent");
    printf("checksum %.17g\n", (double)sink);
}
