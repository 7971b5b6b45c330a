/* tests/test_interp_stepping.c: a built path in use (interp/path.h): the
 * evaluators (Euler's error proportional to the step, exact stepping against
 * direct over 1e5..1e6 steps, the batch calls), keys appended one by one
 * against the path built at once, and bad input.
 * Seeded (interp_kit.h), so every run is the same.
 */
#include "interp_kit.h"

static tk_rng stream;
static tk_rng *const r = &stream; /* helpers take it as r */

/* ---- Euler: error proportional to the step -------------------------------------- */

static double euler_error(const ga_path *p, double h, int nsamp)
{
    ga_path_stepper se, sd;
    double a[16], b[16], e = 0;
    TK_OK(ga_path_stepper_init(p, GA_EVAL_EULER, h, (size_t)nsamp, p->t[0], p->t[p->n - 1], &se));
    TK_OK(ga_path_stepper_init(p, GA_EVAL_DIRECT, 0, (size_t)nsamp, p->t[0], p->t[p->n - 1], &sd));
    for (int k = 0; k < nsamp; ++k) {
        if (ga_path_stepper_next(&se, a) || ga_path_stepper_next(&sd, b))
            return NAN;
        e = fmax(e, mdiff(p->group->to_mat4(a), p->group->to_mat4(b)));
    }
    return e;
}

static void test_euler(void)
{
    stream = tk_rng_after(INTERP_SEED, 47546); /* after forms */
    keyset k;
    k.n = 4;
    for (int i = 0; i < 4; ++i) {
        k.t[i] = i;
        k.m[i] = rand_rigid(r, 0.5, 2.5, 3);
    }
    set_scale(&k);
    ga_scheme ss[2] = {GA_SCHEME_LIHAO3, GA_SCHEME_SMOOTH};
    const ga_group *gs[2] = {&ga_group_se3, &ga_group_cga};
    tk_check c_init = tk_begin("path init (Euler)", 0);
    tk_check c_slope = tk_begin("Euler error: log-log slope over 3 decades, |slope - 1|", 0.1);
    for (int si = 0; si < 2; ++si) {
        pathbuf b;
        int st = mkpath(&b, gs[si], ss[si], &k, NULL);
        tk_add_status(&c_init, st, GA_OK);
        if (st)
            continue;
        double lx[7], ly[7], sx = 0, sy = 0, sxx = 0, sxy = 0;
        tk_note("Euler (%s on %s): step -> max error:", ga_scheme_name(ss[si]), gs[si]->name);
        for (int j = 0; j < 7; ++j) {
            double h = pow(10.0, -1.0 - 0.5 * j);
            double e = euler_error(&b.p, h, 13);
            lx[j] = log10(h);
            ly[j] = log10(e);
            tk_note(" %.0e:%.2e", h, e);
            sx += lx[j];
            sy += ly[j];
            sxx += lx[j] * lx[j];
            sxy += lx[j] * ly[j];
        }
        double slope = (7 * sxy - sx * sy) / (7 * sxx - sx * sx);
        tk_note("\n    log-log slope over 3 decades (1e-1 .. 1e-4): %.3f  (want 1 +- 0.1)\n", slope);
        tk_add(&c_slope, fabs(slope - 1.0));
    }
    /* Euler on the screw is exact (constant body velocity): only rounding */
    pathbuf b;
    int st = mkpath(&b, &ga_group_se3, GA_SCHEME_SCREW, &k, NULL);
    tk_add_status(&c_init, st, GA_OK);
    tk_end(&c_init);
    tk_end(&c_slope);
    tk_check c_screw = tk_begin("Euler on screw (constant body velocity), step 1e-3, / scale", 1e-12);
    tk_add(&c_screw, st == GA_OK ? euler_error(&b.p, 1e-3, 13) / k.scale : INFINITY);
    tk_end(&c_screw);
}

/* ---- exact stepping vs direct over 10^6 steps ----------------------------------- */

static void test_exact(void)
{
    keyset k;
    k.n = 4;
    k.t[0] = 0;
    for (int i = 1; i < 4; ++i) k.t[i] = k.t[i - 1] + tk_range(r, 0.5, 2);
    for (int i = 0; i < 4; ++i) k.m[i] = rand_rigid(r, 0.5, 3, 50);
    set_scale(&k);
    struct {
        ga_scheme s;
        const ga_group *g;
        long n;
    } runs[] = {
        {GA_SCHEME_LIHAO3, &ga_group_se3, 1000001},   {GA_SCHEME_LIHAO3, &ga_group_cga, 1000001},
        {GA_SCHEME_LIHAO2, &ga_group_cga, 200001},    {GA_SCHEME_SCREW, &ga_group_se3, 200001},
        {GA_SCHEME_LIHAO3, &ga_group_affine, 100001},
    };
    tk_note("exact stepping re-anchors every %d samples (GA_PATH_EXACT_REANCHOR)\n", GA_PATH_EXACT_REANCHOR);
    tk_check c_init = tk_begin("path init (exact stepping)", 0);
    tk_check c_exact = tk_begin("exact stepping vs direct over 1e5..1e6 steps, / scale", 1e-12);
    for (size_t q = 0; q < sizeof runs / sizeof runs[0]; ++q) {
        pathbuf b;
        keyset kk = k;
        if (runs[q].g == &ga_group_affine) { /* scaled and sheared keys at k's times */
            affine_keys(r, &kk, 4);
            memcpy(kk.t, k.t, sizeof k.t);
        }
        int st = mkpath(&b, runs[q].g, runs[q].s, &kk, NULL);
        tk_add_status(&c_init, st, GA_OK);
        if (st)
            continue;
        ga_path_stepper sx, sd;
        TK_OK(ga_path_stepper_init(&b.p, GA_EVAL_EXACT, 0, (size_t)runs[q].n, kk.t[0], kk.t[3], &sx));
        TK_OK(ga_path_stepper_init(&b.p, GA_EVAL_DIRECT, 0, (size_t)runs[q].n, kk.t[0], kk.t[3], &sd));
        double e = 0, a[16], c[16];
        clock_t c0 = clock();
        for (long j = 0; j < runs[q].n; ++j) {
            if (ga_path_stepper_next(&sx, a) || ga_path_stepper_next(&sd, c)) {
                e = NAN;
                break;
            }
            e = fmax(e, mdiff(runs[q].g->to_mat4(a), runs[q].g->to_mat4(c)));
        }
        e /= kk.scale;
        tk_note("     %-6s on %-6s over %ld steps: %.3g  (%.2f s both; cond %.3g)\n",
                ga_scheme_name(runs[q].s), runs[q].g->name, runs[q].n - 1, e,
                (double)(clock() - c0) / CLOCKS_PER_SEC, path_cond(&b.p));
        tk_add(&c_exact, e);
    }
    tk_end(&c_exact);
    /* batch call: N samples into a buffer, equal to direct */
    pathbuf b;
    int st = mkpath(&b, &ga_group_cga, GA_SCHEME_LIHAO3, &k, NULL);
    tk_add_status(&c_init, st, GA_OK);
    tk_end(&c_init);
    if (st)
        return;
    double buf[3][101 * 8];
    tk_check c_batch = tk_begin("batch uniform (exact) == batch at times (direct), / scale", 1e-12);
    TK_OK(ga_path_sample_uniform(&b.p, GA_EVAL_EXACT, 0, 101, k.t[0], k.t[3], buf[0]));
    double times[101];
    for (int j = 0; j < 101; ++j) times[j] = k.t[0] + (k.t[3] - k.t[0]) * j / 100.0;
    times[100] = k.t[3];
    TK_OK(ga_path_sample(&b.p, GA_EVAL_DIRECT, 0, 101, times, buf[1]));
    for (int j = 0; j < 101; ++j)
        tk_add(&c_batch,
               mdiff(ga_group_cga.to_mat4(buf[0] + 8 * j), ga_group_cga.to_mat4(buf[1] + 8 * j)) / k.scale);
    tk_end(&c_batch);
    tk_expect_status("batch euler at times", ga_path_sample(&b.p, GA_EVAL_EULER, 1e-3, 101, times, buf[2]),
                     GA_OK);
}

/* ---- samples at times in any order ------------------------------------------------ */

/* ga_path_sample locates its times in blocks (interp/step.c: the segment of
 * the time before tried first, the others searched side by side): its
 * samples are ga_path_eval's bit for bit whatever the order of the times,
 * sorted, shuffled, repeated, at the knots and the range's ends, on every
 * scheme and on a group of rotors and one of matrices, across several blocks
 * (SAMPLE_BLOCK 64); a time outside the range (or NaN) gives
 * ga_path_locate's status with the samples before it written. */
enum { ORDER_KEYS = 37, ORDER_N = 300 };
static double order_work[1 << 15];

static int sample_matches(const ga_path *p, size_t n, const double *times, const unsigned char *got)
{
    size_t es = p->group->elem_size;
    unsigned char want[16 * sizeof(double)];
    for (size_t j = 0; j < n; ++j)
        if (ga_path_eval(p, times[j], want) != GA_OK || memcmp(want, got + j * es, es) != 0)
            return 0;
    return 1;
}

static void test_order(void)
{
    stream = tk_rng_after(INTERP_SEED, 0x5a3030);
    const ga_group *gs[2] = {&ga_group_cga, &ga_group_affine};
    static double T[ORDER_N], S[ORDER_N], B[ORDER_N];
    static unsigned char out[ORDER_N * 16 * sizeof(double)];
    ga_mat4 keys[ORDER_KEYS];
    double kt[ORDER_KEYS];
    tk_check c_init = tk_begin("order: paths built (schemes defined on the group)", 0);
    tk_check c_shuf = tk_begin("order: shuffled, repeated, knots, ends == ga_path_eval, bit for bit", 0);
    tk_check c_sort = tk_begin("order: the same times sorted == ga_path_eval, bit for bit", 0);
    tk_check c_bad =
        tk_begin("order: a time outside (above, below, NaN) -> GA_ERR_ARG, samples before written", 0);
    tk_check c_one = tk_begin("order: one key: its time -> the key, another -> GA_ERR_ARG", 0);
    for (int i = 0; i < ORDER_KEYS; ++i) {
        keys[i] = rand_rigid(r, 0.1, 2.0, 2.0);
        kt[i] = i == 0 ? 1.25 : kt[i - 1] + tk_range(r, 0.2, 1.8);
    }
    for (int gi = 0; gi < 2; ++gi)
        for (int si = 0; si < GA_SCHEME_COUNT; ++si) {
            ga_scheme sc = (ga_scheme)si;
            double t[ORDER_KEYS];
            for (int i = 0; i < ORDER_KEYS; ++i) t[i] = sc == GA_SCHEME_BSPLINE ? 1.25 + 0.5 * i : kt[i];
            size_t nkeys = sc == GA_SCHEME_QUADRATIC ? 3 : ORDER_KEYS; /* QUADRATIC: exactly 3 */
            size_t ws = ga_path_workspace_size(gs[gi], sc, nkeys);
            if (ws == 0 || ws > sizeof order_work)
                continue;
            ga_path p;
            int st = ga_path_init_mat4(gs[gi], sc, nkeys, t, keys, NULL, order_work, ws, &p);
            tk_add_status(&c_init, st, GA_OK);
            if (st)
                continue;
            double t0, t1;
            TK_OK(ga_path_range(&p, &t0, &t1));
            size_t nk = 0; /* the knots and the ends, then times inside, then repeats */
            for (size_t i = 0; i < nkeys; ++i)
                if (t[i] >= t0 && t[i] <= t1)
                    T[nk++] = t[i];
            T[nk++] = t0;
            T[nk++] = t1;
            T[nk++] = nextafter(t1, 0.0);
            T[nk++] = nextafter(t0, INFINITY);
            for (size_t j = nk; j < ORDER_N; ++j) {
                if (j % 5 == 0) {
                    size_t from = (size_t)(tk_uni(r) * (double)j);
                    T[j] = T[from];
                } else
                    T[j] = tk_range(r, t0, t1);
            }
            for (size_t j = ORDER_N - 1; j > 0; --j) { /* shuffle */
                size_t q = (size_t)(tk_uni(r) * (double)(j + 1));
                double x = T[j];
                T[j] = T[q];
                T[q] = x;
            }
            memcpy(S, T, sizeof T); /* sorted by insertion: 300 times */
            for (size_t j = 1; j < ORDER_N; ++j)
                for (size_t q = j; q > 0 && S[q - 1] > S[q]; --q) {
                    double x = S[q];
                    S[q] = S[q - 1];
                    S[q - 1] = x;
                }
            st = ga_path_sample(&p, GA_EVAL_DIRECT, 0, ORDER_N, T, out);
            tk_add_bool(&c_shuf, st == GA_OK && sample_matches(&p, ORDER_N, T, out));
            st = ga_path_sample(&p, GA_EVAL_DIRECT, 0, ORDER_N, S, out);
            tk_add_bool(&c_sort, st == GA_OK && sample_matches(&p, ORDER_N, S, out));
            st = ga_path_sample(&p, GA_EVAL_EXACT, 0, ORDER_N, T, out); /* at times EXACT is DIRECT */
            tk_add_bool(&c_shuf, st == GA_OK && sample_matches(&p, ORDER_N, T, out));
            const double bad[3] = {nextafter(t1, INFINITY), t0 - 1.0, NAN};
            const size_t where[3] = {
                150, 63, 64}; /* inside a later block, the first block's last, the second's first */
            for (int b = 0; b < 3; ++b) {
                memcpy(B, S, sizeof S);
                B[where[b]] = bad[b];
                memset(out, 0, sizeof out);
                st = ga_path_sample(&p, GA_EVAL_DIRECT, 0, ORDER_N, B, out);
                tk_add_bool(&c_bad, st == GA_ERR_ARG && sample_matches(&p, where[b], B, out));
                memcpy(B, T, sizeof T);
                B[where[b]] = bad[b];
                st = ga_path_sample(&p, GA_EVAL_EULER, 1e-2, ORDER_N, B, out);
                tk_add_bool(&c_bad, st == GA_ERR_ARG);
            }
        }
    /* one key: the constant path */
    ga_path p1;
    TK_OK(ga_path_init_mat4(&ga_group_cga, GA_SCHEME_SCREW, 1, kt, keys, NULL, order_work, sizeof order_work,
                            &p1));
    for (size_t j = 0; j < 40; ++j) T[j] = kt[0];
    tk_add_bool(&c_one, ga_path_sample(&p1, GA_EVAL_DIRECT, 0, 40, T, out) == GA_OK &&
                            sample_matches(&p1, 40, T, out));
    T[35] = kt[0] + 1.0;
    tk_add_bool(&c_one, ga_path_sample(&p1, GA_EVAL_DIRECT, 0, 40, T, out) == GA_ERR_ARG);
    tk_end(&c_init);
    tk_end(&c_shuf);
    tk_end(&c_sort);
    tk_end(&c_bad);
    tk_end(&c_one);
}

/* ---- appending keys ------------------------------------------------------------ */

/* The path grown key by key by ga_path_append equals the path built from all
 * the keys at once, bit for bit (pose, velocity and acceleration at sample
 * times and at the keys), for every scheme that can append, on every group;
 * errors leave the path untouched. */
static int same_bits(const ga_path *a, const ga_path *b, const keyset *k, int N)
{
    for (int j = 0; j <= N + k->n - 1; ++j)
        if (!tk_path_same_at(a, b, j <= N ? tgrid(k, j, N) : k->t[j - N - 1]))
            return 0;
    return 1;
}

static void test_append(void)
{
    const ga_group *groups[3] = {&ga_group_cga, &ga_group_se3, &ga_group_affine};
    tk_check c_same = tk_begin("appended key by key = built at once, bit for bit", 0);
    tk_check c_cap = tk_begin("cap: the keys the workspace holds; no room: GA_ERR_ARG, path unchanged", 0);
    tk_check c_err = tk_begin("append errors: status, and the path unchanged", 0);
    tk_check c_no = tk_begin("schemes that cannot append: GA_ERR_ARG, cap = n, path unchanged", 0);
    static pathbuf all, grown;
    for (int gi = 0; gi < 3; ++gi) {
        const ga_group *g = groups[gi];
        for (int s = 0; s < GA_SCHEME_COUNT; ++s) {
            size_t need = ga_path_workspace_size(g, (ga_scheme)s, 8);
            if (need == 0)
                continue; /* not defined on g */
            for (int rep = 0; rep < 4; ++rep) {
                keyset k;
                group_keys(r, !g->rigid, &k, 8, rep);
                double v0[12];
                for (int i = 0; i < 12; ++i) v0[i] = tk_range(r, -1, 1);
                const double *vel = s == GA_SCHEME_LIHAO2 && rep % 2 ? v0 : NULL;
                size_t start = (size_t)rep % 3 + 1; /* 1, 2 or 3 keys, then appends */
                if (s == GA_SCHEME_BSPLINE) {       /* evenly spaced, and 4 keys or more to begin */
                    for (int i = 1; i < 8; ++i) k.t[i] = k.t[0] + 0.75 * i;
                    start += 3;
                }
                if (!ga_scheme_can_append((ga_scheme)s)) {
                    start = 3; /* every scheme takes 3 keys */
                    int st = ga_path_init_mat4(g, (ga_scheme)s, start, k.t, k.m, NULL, grown.work, need,
                                               &grown.p);
                    tk_add_status(&c_no, st, GA_OK);
                    if (st)
                        continue;
                    ga_path before = grown.p;
                    tk_add_status(&c_no, ga_path_append_mat4(&grown.p, k.t[start], k.m[start]), GA_ERR_ARG);
                    tk_add_bool(&c_no, grown.p.cap == start && !memcmp(&before, &grown.p, sizeof before));
                    continue;
                }
                int sa = ga_path_init_mat4(g, (ga_scheme)s, 8, k.t, k.m, vel, all.work, need, &all.p);
                int sg = ga_path_init_mat4(g, (ga_scheme)s, start, k.t, k.m, vel, grown.work, need, &grown.p);
                if (s == GA_SCHEME_LIHAO2 && !g->rigid && sa != GA_OK && sg == GA_OK) {
                    /* the recurrence grew until a logm or an inverse failed (see
                       test_keys in test_interp_paths.c): growing the path fails the same way */
                    int st = GA_OK;
                    for (size_t i = start; i < 8 && st == GA_OK; ++i)
                        st = ga_path_append_mat4(&grown.p, k.t[i], k.m[i]);
                    tk_add_status(&c_same, st, sa);
                    continue;
                }
                tk_add_status(&c_same, sa, GA_OK);
                tk_add_status(&c_same, sg, GA_OK);
                if (sa || sg)
                    continue;
                tk_add_bool(&c_cap, grown.p.cap == 8 && all.p.cap == 8);
                for (size_t i = start; i < 8; ++i) {
                    ga_path before = grown.p;
                    /* errors first: each must leave the path as it was */
                    ga_mat4 bad = k.m[i];
                    bad.m[5] = INFINITY;
                    tk_add_status(&c_err, ga_path_append_mat4(&grown.p, k.t[i - 1], k.m[i]), GA_ERR_ARG);
                    tk_add_status(&c_err, ga_path_append_mat4(&grown.p, NAN, k.m[i]), GA_ERR_NOTFINITE);
                    tk_add_status(&c_err, ga_path_append_mat4(&grown.p, k.t[i], bad), GA_ERR_NOTFINITE);
                    tk_add_status(&c_err, ga_path_append(NULL, k.t[i], &k.m[i]), GA_ERR_ARG);
                    if (s == GA_SCHEME_BSPLINE) /* off the even grid */
                        tk_add_status(&c_err, ga_path_append_mat4(&grown.p, k.t[i] + 1e-6, k.m[i]),
                                      GA_ERR_ARG);
                    tk_add_bool(&c_err, !memcmp(&before, &grown.p, sizeof before) &&
                                            same_bits(&before, &grown.p, &k, 8));
                    tk_add_status(&c_same, ga_path_append_mat4(&grown.p, k.t[i], k.m[i]), GA_OK);
                }
                tk_add_bool(&c_same, grown.p.n == 8 && same_bits(&all.p, &grown.p, &k, 40));
                ga_path before = grown.p;
                tk_add_status(&c_cap, ga_path_append_mat4(&grown.p, k.t[7] + 1, k.m[0]), GA_ERR_ARG);
                tk_add_bool(&c_cap, !memcmp(&before, &grown.p, sizeof before));
            }
        }
    }
    tk_end(&c_same);
    tk_end(&c_cap);
    tk_end(&c_err);
    tk_end(&c_no);
}

/* ---- bad input ---------------------------------------------------------------- */

static void test_errors(void)
{
    keyset k;
    k.n = 4;
    for (int i = 0; i < 4; ++i) {
        k.t[i] = i;
        k.m[i] = ga_mat4_identity();
        k.m[i].m[3] = i;
    }
    pathbuf b;
    int st;
    st = ga_path_init_mat4(&ga_group_se3, GA_SCHEME_SCREW, 0, k.t, k.m, NULL, b.work, sizeof b.work, &b.p);
    tk_expect_status("screw with 0 keys -> GA_ERR_ARG", st, GA_ERR_ARG);
    st = ga_path_init_mat4(&ga_group_cga, GA_SCHEME_SMOOTH, 2, k.t, k.m, NULL, b.work, sizeof b.work, &b.p);
    tk_expect_status("smooth with 2 keys -> GA_ERR_ARG", st, GA_ERR_ARG);
    st = ga_path_init_mat4(&ga_group_cga, GA_SCHEME_QUADRATIC, 4, k.t, k.m, NULL, b.work, sizeof b.work,
                           &b.p);
    tk_expect_status("quadratic with 4 keys -> GA_ERR_ARG", st, GA_ERR_ARG);
    st = ga_path_init_mat4(&ga_group_cga, GA_SCHEME_LIHAO3, 0, k.t, k.m, NULL, b.work, sizeof b.work, &b.p);
    tk_expect_status("lihao3 with 0 keys -> GA_ERR_ARG", st, GA_ERR_ARG);
    double t2[4] = {0, 1, 1, 2}, t3[4] = {0, 2, 1, 3}, t4[4] = {0, NAN, 1, 3};
    st = ga_path_init_mat4(&ga_group_cga, GA_SCHEME_LIHAO2, 4, t2, k.m, NULL, b.work, sizeof b.work, &b.p);
    tk_expect_status("equal times -> GA_ERR_ARG", st, GA_ERR_ARG);
    st = ga_path_init_mat4(&ga_group_se3, GA_SCHEME_BIVECTOR, 4, t3, k.m, NULL, b.work, sizeof b.work, &b.p);
    tk_expect_status("decreasing times -> GA_ERR_ARG", st, GA_ERR_ARG);
    st = ga_path_init_mat4(&ga_group_se3, GA_SCHEME_BIVECTOR, 4, t4, k.m, NULL, b.work, sizeof b.work, &b.p);
    tk_expect_status("NaN time -> GA_ERR_NOTFINITE", st, GA_ERR_NOTFINITE);
    st = ga_path_init_mat4(&ga_group_se3, GA_SCHEME_LIHAO3, 4, k.t, k.m, NULL, b.work,
                           ga_path_workspace_size(&ga_group_se3, GA_SCHEME_LIHAO3, 4) - 8, &b.p);
    tk_expect_status("small workspace -> GA_ERR_ARG", st, GA_ERR_ARG);
    st = ga_path_init_mat4(&ga_group_se3, GA_SCHEME_LIHAO3, 4, k.t, k.m, NULL, b.work,
                           ga_path_workspace_size(&ga_group_se3, GA_SCHEME_LIHAO3, 4), &b.p);
    tk_expect_status("exact workspace size suffices", st, GA_OK);
    double out[16];
    tk_expect_status("t after the last key -> GA_ERR_ARG", ga_path_eval(&b.p, 3.5, out), GA_ERR_ARG);
    tk_expect_status("t NaN -> GA_ERR_ARG", ga_path_eval(&b.p, NAN, out), GA_ERR_ARG);
    ga_path_stepper s;
    tk_expect_status("Euler step 0 -> GA_ERR_ARG",
                     ga_path_stepper_init(&b.p, GA_EVAL_EULER, 0.0, 10, 0, 3, &s), GA_ERR_ARG);
    tk_expect(ga_path_stepper_init(&b.p, GA_EVAL_EXACT, 0, 1, 1.5, 1.5, &s) == GA_OK &&
                  ga_path_stepper_next(&s, out) == GA_OK && ga_path_stepper_next(&s, out) == GA_ERR_ARG,
              "one-sample stepper, then GA_ERR_ARG");
    tk_expect_status("t0 > t1 -> GA_ERR_ARG", ga_path_stepper_init(&b.p, GA_EVAL_DIRECT, 0, 5, 2, 1, &s),
                     GA_ERR_ARG);
    tk_expect_status("t0 before keys -> GA_ERR_ARG",
                     ga_path_stepper_init(&b.p, GA_EVAL_DIRECT, 0, 5, -1, 1, &s), GA_ERR_ARG);
    double nanv[4 * 6];
    for (int i = 0; i < 24; ++i) nanv[i] = NAN;
    st = ga_path_init_mat4(&ga_group_se3, GA_SCHEME_LIHAO3, 4, k.t, k.m, nanv, b.work, sizeof b.work, &b.p);
    tk_expect_status("NaN velocity -> GA_ERR_NOTFINITE", st, GA_ERR_NOTFINITE);
    ga_mat4 nr[4];
    memcpy(nr, k.m, sizeof nr);
    nr[2].m[0] = 1.1;
    st = ga_path_init_mat4(&ga_group_cga, GA_SCHEME_SCREW, 4, k.t, nr, NULL, b.work, sizeof b.work, &b.p);
    tk_expect_status("non-rigid key on cga -> GA_ERR_NOTRIGID", st, GA_ERR_NOTRIGID);
    st = ga_path_init_mat4(&ga_group_se3, GA_SCHEME_SCREW, 4, k.t, nr, NULL, b.work, sizeof b.work, &b.p);
    tk_expect_status("non-rigid key on se3 -> GA_ERR_NOTRIGID", st, GA_ERR_NOTRIGID);
    st = ga_path_init_mat4(&ga_group_affine, GA_SCHEME_SCREW, 4, k.t, nr, NULL, b.work, sizeof b.work, &b.p);
    tk_expect_status("scaled key on affine -> ok", st, GA_OK);
    ga_scheme sc;
    tk_expect(ga_scheme_by_name("smooth", &sc) == GA_OK && sc == GA_SCHEME_SMOOTH, "scheme by name");
    tk_expect(ga_scheme_by_name("nope", &sc) == GA_ERR_ARG, "unknown scheme -> GA_ERR_ARG");
    tk_expect(ga_group_by_name("matrix") == &ga_group_se3 && ga_group_by_name("x") == NULL, "group by name");
}

static const tk_section sections[] = {
    {"euler", test_euler, TK_STREAM}, {"exact", test_exact, TK_STREAM}, {"order", test_order, 0},
    {"append", test_append, 0},       {"errors", test_errors, 0},       {"time", tk_cpu_time, TK_SETUP},
};

int main(int argc, char **argv)
{
    return tk_main(argc, argv, "test_interp_stepping", sections, TK_COUNT(sections));
}
