/* tests/test_interp_keys.c: the functions of path.h about the keys rather
 * than the path, each against what its header promises, computed here
 * independently: ga_times_min_gap and ga_times_gap_run (interp/near_dup.c)
 * at their edges and against a median and a run found by brute force;
 * ga_path_merge_keys against the mean time summed as documented, the
 * nearest whole nanosecond, and the mean pose of screws about one axis and
 * the barycentre equation; ga_path_growth_describe (interp/growth.c) on
 * paths that break the growth rule (lihao2's recurrence worked out by hand)
 * and one that does not, its ratio against C's "%.*g". Seeded (testkit.h),
 * so every run is the same.
 */
#include <locale.h>

#include "interp_kit.h"

static tk_rng stream;
static tk_rng *const r = &stream;

/* ---- near-duplicate keys ---------------------------------------------------- */

/* the median of n values, sorted here by insertion */
static double median_of(const double *v, size_t n)
{
    double s[64];
    for (size_t i = 0; i < n; ++i) {
        size_t j = i;
        for (; j > 0 && s[j - 1] > v[i]; --j) s[j] = s[j - 1];
        s[j] = v[i];
    }
    return n % 2 ? s[n / 2] : (s[n / 2 - 1] + s[n / 2]) / 2;
}

static void min_gap(void)
{
    double t[40], scratch[40], med = -1, gap = -1;
    tk_check c = tk_begin("min_gap: n = 0 and 1 -> median and gap 0", 0);
    t[0] = 3.5;
    tk_add_bool(&c, ga_times_min_gap(0, t, scratch, &med, &gap) == GA_OK && med == 0.0 && gap == 0.0);
    med = gap = -1;
    tk_add_bool(&c, ga_times_min_gap(1, t, scratch, &med, &gap) == GA_OK && med == 0.0 && gap == 0.0);
    tk_end(&c);
    c = tk_begin("min_gap: NULL times, scratch, median or gap -> GA_ERR_ARG (any n)", 0);
    for (size_t n = 0; n < 3; ++n) {
        tk_add_status(&c, ga_times_min_gap(n, NULL, scratch, &med, &gap), GA_ERR_ARG);
        tk_add_status(&c, ga_times_min_gap(n, t, NULL, &med, &gap), GA_ERR_ARG);
        tk_add_status(&c, ga_times_min_gap(n, t, scratch, NULL, &gap), GA_ERR_ARG);
        tk_add_status(&c, ga_times_min_gap(n, t, scratch, &med, NULL), GA_ERR_ARG);
    }
    tk_end(&c);
    /* hand-made: two keys; duplicates; an even and an odd count of spacings */
    struct {
        size_t n;
        double t[6], median;
    } hand[] = {
        {2, {1.0, 3.5}, 2.5},
        {3, {0, 1, 3}, 1.5},                    /* spacings 1, 2: the mean of the middle two */
        {4, {0, 0, 0, 1}, 0.0},                 /* exact duplicates: median 0, gap 0 */
        {4, {0, 1, 1, 2}, 1.0},                 /* 1, 0, 1 */
        {5, {0, 4, 5, 5, 9}, 2.5},              /* 4, 1, 0, 4: sorted 0 1 4 4 */
        {6, {10, 11, 11.5, 13.5, 14, 20}, 1.0}, /* 1, .5, 2, .5, 6: sorted .5 .5 1 2 6 */
    };
    c = tk_begin("min_gap: hand-made times: the median spacing, gap 1% of it", 0);
    for (size_t i = 0; i < TK_COUNT(hand); ++i) {
        int st = ga_times_min_gap(hand[i].n, hand[i].t, scratch, &med, &gap);
        tk_add_bool(&c,
                    st == GA_OK && med == hand[i].median && gap == GA_PATH_MIN_GAP_FRACTION * hand[i].median);
    }
    tk_end(&c);
    c = tk_begin("min_gap: random times: median of the spacings (sorted here), times unchanged", 0);
    for (int rep = 0; rep < 200; ++rep) {
        size_t n = 2 + tk_next(r) % 38;
        t[0] = tk_range(r, -1e3, 1e3);
        for (size_t i = 1; i < n; ++i) {
            double u = tk_uni(r);
            t[i] = t[i - 1] + (u < 0.2 ? 0.0 : u < 0.4 ? 1e-6 : tk_loguni(r, 1e-3, 10));
        }
        double sp[40], copy[40];
        for (size_t i = 1; i < n; ++i) sp[i - 1] = t[i] - t[i - 1];
        memcpy(copy, t, n * sizeof *t);
        double want = median_of(sp, n - 1);
        int st = ga_times_min_gap(n, t, scratch, &med, &gap);
        tk_add_bool(&c, st == GA_OK && med == want && gap == GA_PATH_MIN_GAP_FRACTION * want &&
                            !memcmp(copy, t, n * sizeof *t));
    }
    tk_end(&c);
    c = tk_begin("min_gap: a spacing not finite -> GA_ERR_NOTFINITE", 0);
    const double bad[][3] = {{0, NAN, 2}, {0, 1, INFINITY}, {-INFINITY, 0, 1}, {-DBL_MAX, DBL_MAX, DBL_MAX}};
    for (size_t i = 0; i < TK_COUNT(bad); ++i)
        tk_add_status(&c, ga_times_min_gap(3, bad[i], scratch, &med, &gap), GA_ERR_NOTFINITE);
    tk_end(&c);
    /* finite spacings whose median overflows (the mean of the two middle
       ones): an overflow, not GA_OK with an infinite median */
    const double big[] = {-DBL_MAX, -DBL_MAX / 4, DBL_MAX * 0.75};
    int st = ga_times_min_gap(3, big, scratch, &med, &gap);
    tk_expect(st == GA_ERR_DOMAIN || (st == GA_OK && isfinite(med) && isfinite(gap)),
              "min_gap: spacings 0.75 and 1 DBL_MAX: GA_OK only with a finite median");
}

/* ga_times_gap_run by brute force: the largest j >= i whose spacings i..j-1
   are all below gap */
static size_t run_ref(size_t n, const double *t, double gap, size_t i)
{
    if (i >= n)
        return i;
    size_t best = i;
    for (size_t j = i; j < n; ++j) {
        int all = 1;
        for (size_t k = i; k < j; ++k) all &= t[k + 1] - t[k] < gap;
        if (all)
            best = j;
    }
    return best;
}

static void gap_run(void)
{
    const double whole[] = {0, 1e-3, 2e-3, 3e-3}, start[] = {0, 1e-3, 1, 2, 3},
                 end[] = {0, 1, 2, 2.001, 2.002}, mid[] = {0, 1, 1.001, 1.002, 2, 3},
                 dyad[] = {0, 0.25, 0.5, 0.75}, dup[] = {1, 1, 1, 2}, back[] = {0, -1, -2};
    struct {
        size_t n;
        const double *t;
        double gap;
        size_t i, want;
        const char *what;
    } cases[] = {
        {4, whole, 0.01, 0, 3, "the whole array one run"},
        {4, whole, 0.01, 2, 3, "from inside the run to its end"},
        {5, start, 0.01, 0, 1, "a run at the start"},
        {5, start, 0.01, 1, 1, "its last key: no run"},
        {5, start, 0.01, 2, 2, "after it: none"},
        {5, end, 0.01, 2, 4, "a run at the end"},
        {5, end, 0.01, 4, 4, "the last key"},
        {6, mid, 0.01, 1, 3, "a run in the middle"},
        {6, mid, 0.01, 0, 0, "the key before it"},
        {4, dyad, 0.25, 0, 0, "spacing exactly the gap: not below"},
        {4, dyad, 0x1.0000000000001p-2, 0, 3, "gap one ulp above the spacing"},
        {4, dup, 0.0, 0, 0, "exact duplicates, gap 0: not below"},
        {4, dup, 1e-300, 0, 2, "exact duplicates, gap 1e-300"},
        {4, dup, NAN, 0, 0, "a NaN gap: no run"},
        {4, whole, -1.0, 0, 0, "a negative gap: no run"},
        {0, whole, 1.0, 0, 0, "n = 0"},
        {1, whole, 1.0, 0, 0, "n = 1"},
        {4, whole, 1.0, 4, 4, "i = n"},
        {4, whole, 1.0, 9, 9, "i > n"},
        {4, NULL, 1.0, 2, 2, "times NULL"},
        {3, back, 0.01, 0, 2, "backward steps: spacings below the gap, as defined"},
    };
    tk_check c = tk_begin("gap_run: hand-made runs and edges", 0);
    for (size_t k = 0; k < TK_COUNT(cases); ++k) {
        size_t got = ga_times_gap_run(cases[k].n, cases[k].t, cases[k].gap, cases[k].i);
        if (got != cases[k].want)
            tk_note("     gap_run: %s: %zu, wanted %zu\n", cases[k].what, got, cases[k].want);
        tk_add_bool(&c, got == cases[k].want);
    }
    tk_end(&c);
    c = tk_begin("gap_run: random clustered times, every start, against brute force", 0);
    for (int rep = 0; rep < 100; ++rep) {
        /* times on a grid of 2^-10, the gap 10 steps of it: spacings of
           exactly the gap come up, and every difference is exact */
        double t[30], q = 0x1p-10, gap = 10 * q;
        size_t n = 1 + tk_next(r) % 30;
        t[0] = q * (double)(tk_next(r) % 8192) - 4.0;
        for (size_t i = 1; i < n; ++i) {
            double u = tk_uni(r);
            t[i] = t[i - 1] + q * (double)(u < 0.5 ? tk_next(r) % 21 : 100 + tk_next(r) % 900);
        }
        for (size_t i = 0; i <= n; ++i)
            tk_add_bool(&c, ga_times_gap_run(n, t, gap, i) == run_ref(n, t, gap, i));
    }
    tk_end(&c);
}

/* ---- merging keys ------------------------------------------------------------ */

/* the whole number nearest x where there is one (|x - floor x| != 1/2) */
static int nearest_whole(double x, double *w)
{
    double f = floor(x), d = x - f; /* exact */
    if (d == 0.5)
        return 0;
    *w = d < 0.5 ? f : f + 1;
    return 1;
}

static void merge(void)
{
    double t = -7, times[GA_PATH_MERGE_MAX + 1];
    ga_mat4 key = ga_mat4_identity(), keys[GA_PATH_MERGE_MAX + 1];
    for (int i = 0; i <= GA_PATH_MERGE_MAX; ++i) {
        times[i] = i;
        keys[i] = ga_mat4_identity();
    }
    tk_check c = tk_begin("merge: m = 0, m > GA_PATH_MERGE_MAX, NULL -> GA_ERR_ARG", 0);
    tk_add_status(&c, ga_path_merge_keys(0, times, keys, 0, &t, &key), GA_ERR_ARG);
    tk_add_status(&c, ga_path_merge_keys(GA_PATH_MERGE_MAX + 1, times, keys, 0, &t, &key), GA_ERR_ARG);
    tk_add_status(&c, ga_path_merge_keys(2, NULL, keys, 0, &t, &key), GA_ERR_ARG);
    tk_add_status(&c, ga_path_merge_keys(2, times, NULL, 0, &t, &key), GA_ERR_ARG);
    tk_add_status(&c, ga_path_merge_keys(2, times, keys, 0, NULL, &key), GA_ERR_ARG);
    tk_add_status(&c, ga_path_merge_keys(2, times, keys, 0, &t, NULL), GA_ERR_ARG);
    tk_end(&c);
    tk_expect(ga_path_merge_keys(GA_PATH_MERGE_MAX, times, keys, 0, &t, &key) == GA_OK &&
                  t == (GA_PATH_MERGE_MAX - 1) / 2.0 && mdiff(key, ga_mat4_identity()) == 0.0,
              "merge: GA_PATH_MERGE_MAX identities at 0..63: identity at 31.5");

    /* the time: each divided by m, added in order, bit for bit; ns: the
       nearest whole number to it times 1e9 */
    tk_check tc = tk_begin("merge: *t = sum of times[k] / m in order, bit for bit", 0);
    tk_check nc = tk_begin("merge: ns: *t = the whole number nearest the mean * 1e9", 0);
    tk_check mc = tk_begin("merge: one key: itself (pose to rounding), its time", 0);
    for (int rep = 0; rep < 100; ++rep) {
        size_t m = 1 + tk_next(r) % 8;
        double base = tk_uni(r) < 0.5 ? tk_range(r, -10, 10) : tk_range(r, 1e3, 1e7);
        for (size_t i = 0; i < m; ++i) {
            times[i] = base + tk_range(r, 0, 1e-4);
            keys[i] = rand_rigid(r, 0, 0.5, 2.0);
        }
        double want = 0.0, w;
        for (size_t i = 0; i < m; ++i) want += times[i] / (double)m;
        tk_add_bool(&tc, ga_path_merge_keys(m, times, keys, 0, &t, &key) == GA_OK && t == want);
        if (m == 1)
            tk_add_bool(&mc, t == times[0] && mdiff(key, keys[0]) <= 1e-14 * fmax(1, tnorm(keys[0])));
        if (nearest_whole(want * 1e9, &w))
            tk_add_bool(&nc, ga_path_merge_keys(m, times, keys, 1, &t, &key) == GA_OK && t == w);
    }
    /* where floor(x + 0.5) is not the nearest: odd x between 2^52 and 2^53,
       and the double just below 1/2 */
    int found = 0;
    for (double x = 0x1p52 / 1e9 * 1.7; found < 4; x = nextafter(x, 1e300)) {
        double y = x * 1e9, w;
        if (fmod(y, 2.0) == 1.0 && nearest_whole(y, &w)) {
            tk_add_bool(&nc, ga_path_merge_keys(1, &x, keys, 1, &t, &key) == GA_OK && t == w);
            found++;
        }
    }
    for (double x = 0.5e-9, s = 0; s < 64; s++, x = nextafter(x, 0)) {
        double y = x * 1e9, w;
        if (y == nextafter(0.5, 0) && nearest_whole(y, &w))
            tk_add_bool(&nc, ga_path_merge_keys(1, &x, keys, 1, &t, &key) == GA_OK && t == w);
    }
    tk_end(&tc);
    tk_end(&nc);
    tk_end(&mc);

    /* the pose: screws about one axis commute, so their mean is exp of the
       mean twist; moved by L on both sides (L R L^-1), its mean moves alike */
    tk_check pc = tk_begin("merge: screws about one axis: L exp(mean twist) L^-1, / scale", 1e-13);
    tk_check bc = tk_begin("merge: random poses: sum log(M^-1 R_k) = 0 (the barycentre)", 1e-12);
    tk_check oc = tk_begin("merge: the mean pose independent of the keys' order", 1e-13);
    for (int rep = 0; rep < 50; ++rep) {
        size_t m = 2 + tk_next(r) % 7;
        ga_vec3 u = tk_unit(r);
        double pitch = tk_range(r, -2, 2);
        ga_mat4 L = rand_rigid(r, 0, PI, 3), Li = ga_se3_inverse(L);
        double abar = 0.0; /* the twists a (u, pitch u): their mean is abar's */
        for (size_t i = 0; i < m; ++i) {
            double a = tk_range(r, -0.6, 0.6);
            ga_twist xi = {tk_scale(u, a), tk_scale(u, a * pitch)};
            keys[i] = ga_mat4_mul(ga_mat4_mul(L, ga_se3_exp(xi)), Li);
            times[i] = (double)i;
            abar += a / (double)m;
        }
        ga_twist mean = {tk_scale(u, abar), tk_scale(u, abar * pitch)};
        ga_mat4 want = ga_mat4_mul(ga_mat4_mul(L, ga_se3_exp(mean)), Li);
        if (ga_path_merge_keys(m, times, keys, 0, &t, &key) != GA_OK)
            key.m[0] = NAN;
        tk_add(&pc, mdiff(key, want) / fmax(1.0, tnorm(want)));
        /* random poses near each other */
        ga_mat4 c0 = rand_rigid(r, 0, PI, 5);
        for (size_t i = 0; i < m; ++i) {
            ga_mat4 d = rand_rigid(r, 0, 0.8, 0.5);
            keys[i] = ga_mat4_mul(c0, d);
        }
        if (ga_path_merge_keys(m, times, keys, 0, &t, &key) != GA_OK)
            key.m[0] = NAN;
        double s6[6] = {0, 0, 0, 0, 0, 0};
        for (size_t i = 0; i < m; ++i) {
            ga_twist x;
            if (ga_se3_log(ga_mat4_mul(ga_se3_inverse(key), keys[i]), &x) != GA_OK)
                x.w.x = NAN;
            const double c6[6] = {x.w.x, x.w.y, x.w.z, x.v.x, x.v.y, x.v.z};
            for (int j = 0; j < 6; ++j) s6[j] += c6[j];
        }
        tk_add(&bc, vnorm(s6, 6) / fmax(1.0, tnorm(c0)));
        ga_mat4 rev[GA_PATH_MERGE_MAX], key2;
        for (size_t i = 0; i < m; ++i) rev[i] = keys[m - 1 - i];
        if (ga_path_merge_keys(m, times, rev, 0, &t, &key2) != GA_OK)
            key2.m[0] = NAN;
        tk_add(&oc, mdiff(key, key2) / fmax(1.0, tnorm(key)));
    }
    tk_end(&pc);
    tk_end(&bc);
    tk_end(&oc);

    /* refusals: a key that is no rigid motion passes ga_rotor_from_mat4's
       status on; times not finite, or a mean in ns that overflows */
    c = tk_begin("merge: a key that is no rigid motion -> its ga_rotor_from_mat4 status", 0);
    for (int kind = 0; kind < 3; ++kind) {
        ga_rotor rr;
        keys[0] = ga_mat4_identity();
        keys[1] = rand_rigid(r, 0, 1, 1);
        if (kind == 0)
            keys[1].m[0] *= 1.5;
        else if (kind == 1)
            keys[1].m[5] = NAN;
        else
            keys[1].m[12] = 0.5;
        int want = ga_rotor_from_mat4(keys[1], &rr);
        tk_add_bool(&c, want != GA_OK);
        tk_add_status(&c, ga_path_merge_keys(2, times, keys, 0, &t, &key), want);
    }
    tk_end(&c);
    keys[0] = keys[1] = ga_mat4_identity();
    c = tk_begin("merge: a time not finite -> GA_ERR_NOTFINITE", 0);
    const double badt[][2] = {{0, NAN}, {INFINITY, 1}, {-INFINITY, INFINITY}};
    for (size_t i = 0; i < TK_COUNT(badt); ++i)
        for (int ns = 0; ns < 2; ++ns)
            tk_add_status(&c, ga_path_merge_keys(2, badt[i], keys, ns, &t, &key), GA_ERR_NOTFINITE);
    tk_end(&c);
    const double huge[2] = {1e300, 1e300};
    tk_expect_status("merge: ns of a mean of 1e300 s overflows -> GA_ERR_DOMAIN",
                     ga_path_merge_keys(2, huge, keys, 1, &t, &key), GA_ERR_DOMAIN);
}

/* ---- the growth rule's words ------------------------------------------------ */

/* x as "%.*g" writes it in the C locale, with 3 digits or as many as show it
   past GA_PATH_GROWTH_MAX */
static void g_ref(double x, char *buf)
{
    for (int dig = 3; dig <= 17; ++dig) {
        snprintf(buf, 32, "%.*g", dig, x);
        if (strtod(buf, NULL) > GA_PATH_GROWTH_MAX)
            return;
    }
}

static void growth_words(void)
{
    /* lihao2 on translations along x at unit spacing: in 1D the recurrence is
       V_{i+1} = 2 s_i - V_i; chords 1, 0.1, 1, 0.1, 1, 0.1 from V_0 = s_0 give
       V = 1, 1, -0.8, 2.8, -2.6, 4.6, -4.4: the first key past 3 is key 5
       (4.6), carried there by segment 4-5, the largest key 5 too */
    const double x[] = {0, 1, 1.1, 2.1, 2.2, 3.2, 3.3};
    keyset k;
    k.n = 7;
    for (int i = 0; i < 7; ++i) {
        k.t[i] = i;
        k.m[i] = ga_mat4_identity();
        k.m[i].m[3] = x[i];
    }
    set_scale(&k);
    ga_path_growth gr;
    ga_path_growth_words w;
    memset(&w, 0, sizeof w);
    pathbuf pb;
    TK_OK(mkpath(&pb, &ga_group_se3, GA_SCHEME_LIHAO2, &k, NULL));
    TK_OK(ga_path_measure_growth(&pb.p, &gr));
    int st = ga_path_growth_describe(&pb.p, &gr, &w);
    char want[32];
    g_ref(gr.ratio, want);
    tk_expect(gr.first == 5 && fabs(gr.ratio - 4.6) < 1e-12, "growth: lihao2 zigzag: first key 5, ratio 4.6");
    tk_expect(st == GA_OK && w.a == 4 && w.b == 5 && strcmp(w.ratio, "4.6") == 0 &&
                  strcmp(w.ratio, want) == 0,
              "growth: lihao2 zigzag: segment 4-5, ratio \"4.6\"");
    tk_expect(st == GA_OK && w.advice && strstr(w.advice, "lihao3") && !strstr(w.advice, "near-duplicate"),
              "growth: lihao2: the advice names another scheme");
    /* key 0: a given v0 of 5 times the chord */
    double v0[6] = {0, 0, 0, 5 * x[1], 0, 0};
    TK_OK(mkpath(&pb, &ga_group_se3, GA_SCHEME_LIHAO2, &k, v0));
    TK_OK(ga_path_measure_growth(&pb.p, &gr));
    st = ga_path_growth_describe(&pb.p, &gr, &w);
    tk_expect(gr.first == 0 && st == GA_OK && w.a == 0 && w.b == 1,
              "growth: lihao2 with v0 5 times the chord: key 0, segment 0-1");
    /* chords that underflow: translations of 1e-320 a second under a given
       velocity of 1: the ratio 1/1e-320 is infinite, key 0 past the rule,
       and described ("%g": "inf") */
    keyset ks;
    ks.n = 3;
    for (int i = 0; i < 3; ++i) {
        ks.t[i] = i;
        ks.m[i] = ga_mat4_identity();
        ks.m[i].m[3] = i * 1e-320;
    }
    set_scale(&ks);
    double v1[6] = {0, 0, 0, 1, 0, 0};
    TK_OK(mkpath(&pb, &ga_group_se3, GA_SCHEME_LIHAO2, &ks, v1));
    TK_OK(ga_path_measure_growth(&pb.p, &gr));
    st = ga_path_growth_describe(&pb.p, &gr, &w);
    g_ref(gr.ratio, want);
    tk_expect(isinf(gr.ratio) && gr.first == 0 && st == GA_OK && w.a == 0 && w.b == 1 &&
                  strcmp(w.ratio, want) == 0 && strcmp(want, "inf") == 0,
              "growth: chords of 1e-320: ratio inf, key 0, described as \"inf\"");
    /* a screw path keeps the rule: nothing to describe */
    TK_OK(mkpath(&pb, &ga_group_se3, GA_SCHEME_SCREW, &k, NULL));
    TK_OK(ga_path_measure_growth(&pb.p, &gr));
    tk_expect(gr.first == pb.p.n && gr.ratio <= 1.0 + 1e-12, "growth: screw on the same keys keeps the rule");
    tk_expect_status("growth: describe where no key is past the rule -> GA_ERR_ARG",
                     ga_path_growth_describe(&pb.p, &gr, &w), GA_ERR_ARG);
    /* bspline (range [t_1, t_{n-2}]): keys on one screw motion exp(i X) at
       unit spacing make a path of velocity X at every time, every chord X:
       ratio 1, at a key of its range */
    keyset kb;
    ga_twist X = rand_twist(r, 0.5, 2.0);
    kb.n = 6;
    for (int i = 0; i < 6; ++i) {
        kb.t[i] = i;
        kb.m[i] = ga_se3_exp((ga_twist){tk_scale(X.w, i), tk_scale(X.v, i)});
    }
    set_scale(&kb);
    for (size_t gi = 0; gi < 2; ++gi) {
        st = mkpath(&pb, ga_group_nth(gi), GA_SCHEME_BSPLINE, &kb, NULL);
        if (st == GA_OK)
            st = ga_path_measure_growth(&pb.p, &gr);
        tk_expect(st == GA_OK && fabs(gr.ratio - 1.0) < 1e-12 && gr.key >= 1 && gr.key <= 4 && gr.first == 6,
                  gi ? "growth: bspline (matrix) on one screw motion: ratio 1 at a key of its range"
                     : "growth: bspline (cga) on one screw motion: ratio 1 at a key of its range");
    }
    TK_OK(mkpath(&pb, &ga_group_se3, GA_SCHEME_SCREW, &k, NULL));
    /* the others' advice: near-duplicates; a ratio and first given here */
    tk_check c = tk_begin("growth: the ratio as \"%.*g\" (3 digits, or enough to show > 3)", 0);
    tk_check a = tk_begin("growth: a, b = first - 1, first; advice: lihao2 a scheme, others near-dups", 0);
    const double ratios[] = {
        3.0004,  0x1.8000000000001p1, 3.1,        3.14159, 4.6, 9.995, 99.95, 999.5, 12345.6, 1e20, 1e300,
        3.00049, 123456789,           3e-5 * 1e6, 1e5};
    for (size_t i = 0; i < TK_COUNT(ratios); ++i) {
        ga_path_growth g2 = {ratios[i], 3, 1 + i % 6};
        char ref[32];
        g_ref(ratios[i], ref);
        st = ga_path_growth_describe(&pb.p, &g2, &w);
        if (st != GA_OK || strcmp(w.ratio, ref))
            tk_note("     growth: %.17g: \"%s\", wanted \"%s\"\n", ratios[i], st == GA_OK ? w.ratio : "-",
                    ref);
        tk_add_bool(&c,
                    st == GA_OK && strcmp(w.ratio, ref) == 0 && strtod(w.ratio, NULL) > GA_PATH_GROWTH_MAX);
        tk_add_bool(&a, st == GA_OK && w.a == g2.first - 1 && w.b == g2.first && w.advice &&
                            strstr(w.advice, "near-duplicate"));
    }
    /* the advice of every scheme: lihao2 another scheme, the others
       near-duplicates */
    for (int sc = 0; sc < GA_SCHEME_COUNT; ++sc) {
        keyset ke = k;
        ke.n = sc == GA_SCHEME_QUADRATIC ? 3 : 7;
        pathbuf pe;
        ga_path_growth g2 = {5.0, 4, 1};
        st = mkpath(&pe, &ga_group_se3, (ga_scheme)sc, &ke, NULL);
        if (st == GA_OK)
            st = ga_path_growth_describe(&pe.p, &g2, &w);
        tk_add_bool(&a, st == GA_OK && w.a == 0 && w.b == 1 && w.advice &&
                            (sc == GA_SCHEME_LIHAO2
                                 ? strstr(w.advice, "lihao3") && !strstr(w.advice, "near-duplicate")
                                 : strstr(w.advice, "near-duplicate") != NULL));
    }
    /* under a locale whose decimal point is a comma, the same text */
    const char *loc = setlocale(LC_NUMERIC, "de_DE.UTF-8");
    if (!loc)
        loc = setlocale(LC_NUMERIC, "fr_FR.UTF-8");
    if (loc) {
        ga_path_growth g2 = {3.14159, 3, 2};
        tk_add_bool(&c, ga_path_growth_describe(&pb.p, &g2, &w) == GA_OK && strcmp(w.ratio, "3.14") == 0);
        setlocale(LC_NUMERIC, "C");
    } else
        tk_note("     (no de_DE or fr_FR locale: the decimal comma is not tried)\n");
    tk_end(&c);
    tk_end(&a);
    c = tk_begin("growth: describe refuses NULL, first >= n, a NaN ratio", 0);
    ga_path_growth g3 = {4.0, 1, 2};
    tk_add_status(&c, ga_path_growth_describe(NULL, &g3, &w), GA_ERR_ARG);
    tk_add_status(&c, ga_path_growth_describe(&pb.p, NULL, &w), GA_ERR_ARG);
    tk_add_status(&c, ga_path_growth_describe(&pb.p, &g3, NULL), GA_ERR_ARG);
    g3.first = pb.p.n;
    tk_add_status(&c, ga_path_growth_describe(&pb.p, &g3, &w), GA_ERR_ARG);
    g3.first = pb.p.n + 5;
    tk_add_status(&c, ga_path_growth_describe(&pb.p, &g3, &w), GA_ERR_ARG);
    g3.first = 1;
    g3.ratio = NAN;
    tk_add_status(&c, ga_path_growth_describe(&pb.p, &g3, &w), GA_ERR_ARG);
    tk_end(&c);
}

static void seed(void) { stream = (tk_rng){tk_seed(20261204u)}; }

static const tk_section sections[] = {
    {"seed", seed, TK_SETUP},    {"min_gap", min_gap, TK_STREAM},     {"gap_run", gap_run, TK_STREAM},
    {"merge", merge, TK_STREAM}, {"growth", growth_words, TK_STREAM}, {"time", tk_cpu_time, 0},
};

int main(int argc, char **argv)
{
    return tk_main(argc, argv, "test_interp_keys", sections, TK_COUNT(sections));
}
