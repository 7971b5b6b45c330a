/* bench/garotor-bench.c: where garotor stands against 4x4 matrices, dual
 * quaternions and Eigen, in one process run.
 *
 *   garotor-bench            a plain text table
 *   garotor-bench --json     one JSON object: {"ns": {...}, "err": {...}, ...}
 *   garotor-bench --quick    fewer and shorter batches (a smoke test)
 *   garotor-bench --only K,K only these keys (for a profiler; no throughput)
 *
 * Exit status 1 where the inputs cannot be built, a timed call returned a
 * status other than GA_OK, or a meet did not read back as its kind (the
 * default suite runs it once so: bench/meson.build, bench-smoke).
 *
 * Method. Every figure is the median, over repeated timed batches, of the
 * nanoseconds per call (clock_gettime(CLOCK_MONOTONIC) around a batch, divided
 * by the calls in it; the c2 builds on CLOCK_PROCESS_CPUTIME_ID: bench.h,
 * bench_cpu_clock). Each benchmark is first calibrated so that one batch
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
 *
 * This file: the options and the run. The others: bench.h (what they share),
 * inputs.c, floors.h, cases.c (the timed loops and the table), harness.c,
 * checks.c, report.c (the targets and the output).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"

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
    for (size_t i = 0; i < n_benches; i++) {
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
        for (size_t i = 0; i < n_benches; i++)
            if (benches[i].ns && (!bench_max_batches(&benches[i]) || r < bench_max_batches(&benches[i])))
                benches[i].ns[r] = time_batch(&benches[i]);
    for (size_t i = 0; i < n_benches; i++) {
        bench *b = &benches[i];
        if (!b->ns) {
            b->median = b->p25 = b->p75 = NAN;
            continue;
        }
        int cap = bench_max_batches(b), nb = cap && cap < n_batches ? cap : n_batches;
        qsort(b->ns, (size_t)nb, sizeof(double), cmp_double);
        b->median = quantile(b->ns, nb, 0.5);
        b->p25 = quantile(b->ns, nb, 0.25);
        b->p75 = quantile(b->ns, nb, 0.75);
    }

    /* batch sampling throughput, N = 1e6 poses into a caller buffer */
    double pps_direct = NAN, pps_exact = NAN;
    void *big = malloc((size_t)BATCH_POSES * sizeof(ga_rotor));
    if (big && !only) {
        pps_direct = batch_poses_per_s(GA_EVAL_DIRECT, batch_reps, big);
        pps_exact = batch_poses_per_s(GA_EVAL_EXACT, batch_reps, big);
    }
    free(big);

    bench_run run = {
        .n_batches = n_batches,
        .quick = quick,
        .batch_ns = batch_ns,
        .seed = seed,
        .euler_max = euler_max,
        .exact_max = exact_max,
        .euler_max_se3 = euler_max_se3,
        .exact_max_se3 = exact_max_se3,
        .euler_max_l3 = euler_max_l3,
        .exact_max_l3 = exact_max_l3,
        .euler_max_l3_se3 = euler_max_l3_se3,
        .exact_max_l3_se3 = exact_max_l3_se3,
        .pps_direct = pps_direct,
        .pps_exact = pps_exact,
        .chk = chk,
    };
    report(&run, json);
    /* a status other than GA_OK from a timed call, or a meet pair not read
       back as its kind: the figures time a failure, not the operation */
    return status_or != GA_OK || chk.meet_bad ? 1 : 0;
}
