/* bench/cases_path.c: the path cases of garotor-bench beside the sampling
 * loops of cases.c: the C2 build for 2000 and 1e5 keys (linear: the second
 * about 50 times the first), and for every scheme one pose (ga_path_eval)
 * against one acceleration (ga_path_acceleration) at the same times, on
 * rotors (docs/benchmarks.md, "Paths: the C2 build and the acceleration").
 */
#include <math.h>
#include <stdlib.h>

#include "bench.h"

/* ---- the C2 build ------------------------------------------------------------ */

/* Keys of a smooth motion with jittered times: a turn about a wandering axis
 * and a position on a Lissajous curve, key i at t = 0.1 i + 0.02 u_i. */
#define C2_MAX_KEYS 100000
static double c2_times[C2_MAX_KEYS];
static ga_rotor c2_keys[C2_MAX_KEYS];
static void *c2_work;
static size_t c2_work_bytes;

static int c2_setup(void)
{
    if (c2_work)
        return GA_OK;
    uint64_t x = 88172645463325252ull; /* xorshift64, fixed: the same keys every run */
    for (size_t i = 0; i < C2_MAX_KEYS; i++) {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        double s = 0.1 * (double)i, c = cos(0.3 * s), n = sin(0.3 * s);
        c2_times[i] = s + 0.02 * (double)(x >> 11) * 0x1p-53;
        ga_quat q = {c, n * 0.6, n * 0.8 * cos(s), n * 0.8 * sin(s)};
        ga_vec3 p = {sin(s), cos(0.7 * s), 0.1 * s};
        c2_keys[i] = ga_rotor_from_quat(q, p);
    }
    c2_work_bytes = ga_path_workspace_size(&ga_group_cga, GA_SCHEME_C2, C2_MAX_KEYS);
    c2_work = malloc(c2_work_bytes);
    return c2_work ? GA_OK : GA_ERR_ARG;
}

/* One call: a c2 path through the first *ctx keys, built; at least
 * C2_MAX_KEYS / *ctx calls a batch (returned as done), so that a batch of
 * either size builds 1e5 keys: the two sizes' batches take the same time and,
 * interleaved, see the same load (a batch of 2000 keys after the three of 1e5
 * were over measured another second of the shared machine). */
size_t run_c2_build(const void *ctx, size_t n)
{
    size_t keys = *(const size_t *)ctx, least = C2_MAX_KEYS / keys;
    int st = c2_setup();
    ga_path p;
    if (n < least)
        n = least;
    for (size_t k = 0; k < n && st == GA_OK; k++)
        st = ga_path_init(&ga_group_cga, GA_SCHEME_C2, keys, c2_times, c2_keys, NULL, c2_work, c2_work_bytes,
                          &p);
    status_or |= st;
    sink = st == GA_OK ? p.vel[6] : 0.0;
    return n;
}

/* ---- one pose against one acceleration, every scheme --------------------------- */

static ga_path acc_paths[GA_SCHEME_COUNT];
static double acc_work[GA_SCHEME_COUNT][4096];
static double acc_t[RING];
static ga_rotor acc_out[RING];
static double acc_a[RING][6];

static int acc_setup(void)
{
    static int done;
    if (done)
        return GA_OK;
    double times[N_KEYS];
    for (int i = 0; i < N_KEYS; i++) times[i] = i;
    int st = c2_setup();
    for (int s = 0; s < GA_SCHEME_COUNT && st == GA_OK; s++) {
        size_t n = s == GA_SCHEME_QUADRATIC ? 3 : N_KEYS; /* 8 keys of the c2 motion, 10 steps apart */
        ga_rotor k[N_KEYS];
        for (size_t i = 0; i < n; i++) k[i] = c2_keys[10 * i];
        st = ga_path_init(&ga_group_cga, (ga_scheme)s, n, times, k, NULL, acc_work[s], sizeof acc_work[s],
                          &acc_paths[s]);
    }
    for (int j = 0; j < RING; j++) acc_t[j] = (double)j * (1.0 / RING); /* a fraction of the range */
    done = st == GA_OK;
    return st;
}

static double acc_time(const ga_path *p, int j)
{
    double t0, t1;
    if (ga_path_range(p, &t0, &t1) != GA_OK)
        return NAN;
    return t0 + (t1 - t0) * acc_t[j];
}

/* ctx: the scheme; calls cycle through RING times over the path's range */
size_t run_eval(const void *ctx, size_t n)
{
    int st = acc_setup();
    const ga_path *p = &acc_paths[*(const int *)ctx];
    double t[RING];
    for (int j = 0; j < RING; j++) t[j] = acc_time(p, j);
    for (size_t k = 0; k < n && st == GA_OK; k++) st = ga_path_eval(p, t[k & MASK], &acc_out[k & MASK]);
    status_or |= st;
    sink = acc_out[0].s;
    return n;
}
size_t run_accel(const void *ctx, size_t n)
{
    int st = acc_setup();
    const ga_path *p = &acc_paths[*(const int *)ctx];
    double t[RING];
    for (int j = 0; j < RING; j++) t[j] = acc_time(p, j);
    for (size_t k = 0; k < n && st == GA_OK; k++) st = ga_path_acceleration(p, t[k & MASK], acc_a[k & MASK]);
    status_or |= st;
    sink = acc_a[0][0];
    return n;
}

/* ---- the contexts of cases.c's table --------------------------------------------- */

const size_t path_keys_2000 = 2000, path_keys_1e5 = C2_MAX_KEYS;
const int path_scheme[GA_SCHEME_COUNT] = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9};

int bench_cpu_clock(const bench *b) { return b->run == run_c2_build; }

int bench_max_batches(const bench *b) { return b->run == run_c2_build ? 3 : 0; }
