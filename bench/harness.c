/* bench/harness.c: the timing harness of garotor-bench: a batch timed on
 * the monotonic clock (the c2 builds: the CPU clock), the calibration of a batch to its target duration,
 * the quantiles of the batches, the keys --only selects, and the throughput
 * of one large sampling call.
 */
#define _POSIX_C_SOURCE 200809L

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "bench.h"

double now_ns(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e9 + (double)ts.tv_nsec;
}

/* b's clock: the monotonic one, or the process's CPU time (bench_cpu_clock) */
static double clock_ns(const bench *b)
{
    if (!bench_cpu_clock(b))
        return now_ns();
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec * 1e9 + (double)ts.tv_nsec;
}

/* ns per call of one batch of b */
double time_batch(bench *b)
{
    double t0 = clock_ns(b);
    size_t done = b->run(b->ctx, b->calls);
    double t1 = clock_ns(b);
    return (t1 - t0) / (double)done;
}

/* Grow the batch until it takes about target_ns. Each size is timed three
 * times and the fastest counts, so that one preempted trial cannot stop the
 * growth early (a batch of a few calls would then time the clock). */
void calibrate(bench *b, double target_ns)
{
    b->calls = 1;
    for (int it = 0; it < 60; it++) {
        double el = INFINITY;
        for (int trial = 0; trial < 3; trial++) {
            double t0 = clock_ns(b);
            size_t done = b->run(b->ctx, b->calls);
            double t = clock_ns(b) - t0;
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

int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* the q-quantile (0..1) of a sorted array, linearly interpolated */
double quantile(const double *s, int n, double q)
{
    double pos = q * (n - 1);
    int i = (int)pos;
    if (i >= n - 1)
        return s[n - 1];
    return s[i] + (pos - i) * (s[i + 1] - s[i]);
}

static bench *find(const char *key)
{
    for (size_t i = 0; i < n_benches; i++)
        if (strcmp(benches[i].key, key) == 0)
            return &benches[i];
    return NULL;
}

double ns_of(const char *key)
{
    bench *b = find(key);
    return b && b->ns ? b->median : NAN;
}

/* --only KEY,KEY,...: is key in the list (NULL: every key)? */
int selected(const char *only, const char *key)
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

/* Batch sampling throughput: BATCH_POSES poses of a screw path on rotors
 * into a caller buffer, one ga_path_sample_uniform call; median of reps. */
double batch_poses_per_s(ga_eval ev, int reps, void *buf)
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
