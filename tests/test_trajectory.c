/* tests/test_trajectory.c: trajectories compared and fitted (trajectory.h).
 *
 *   associate   against a brute-force search (every pair's |difference|,
 *               the lowest index of the least): which side is the short
 *               one (evo: the estimate unless the reference has fewer),
 *               ties, max_diff 0 and beyond
 *   align       a known Sim(3) / SE(3) motion of seeded positions recovered;
 *               with noise, the result is a minimum: no rotation, translation
 *               or scale nudge lowers the cost; collinear positions and
 *               n < 3 refused (GA_ERR_DOMAIN)
 *   errors      APE and RPE against their definitions written with
 *               ga_se3_log (angle = |w|), the pair count against an
 *               enumeration, the statistics against sums done here and
 *               sorted by insertion
 *   tum         pose_from_tum and pose_to_tum round trip; the sign kept
 *               continuous; the 1e-9 and 1e-3 rules
 *   fit         keys drawn from a known spline: the fit reproduces them; noisy
 *               keys: the error against the true spline falls as keys are
 *               added (about 1/sqrt(keys)); statuses of bad input
 */
#include <garotor/trajectory.h>

#include "testkit.h"

static ga_mat4 rand_pose(tk_rng *r, double amax, double tmax)
{
    ga_vec3 u = tk_unit(r), d = tk_unit(r);
    return ga_se3_exp((ga_twist){tk_scale(u, tk_range(r, 0, amax)), tk_scale(d, tk_range(r, 0, tmax))});
}

static double dist3(ga_mat4 a, ga_mat4 b)
{
    double s = 0;
    for (int k = 0; k < 3; k++) s += (a.m[4 * k + 3] - b.m[4 * k + 3]) * (a.m[4 * k + 3] - b.m[4 * k + 3]);
    return sqrt(s);
}

static double log_angle(ga_mat4 m)
{
    ga_twist x;
    if (ga_se3_log(m, &x) != GA_OK)
        return NAN;
    return tk_norm(x.w);
}

static double mat_diff(ga_mat4 a, ga_mat4 b)
{
    double m = 0;
    for (int k = 0; k < 16; k++) m = tk_max(m, fabs(a.m[k] - b.m[k]));
    return m;
}

/* ---- associate ------------------------------------------------------------- */

static void section_associate(void)
{
    tk_rng r = {20261203};
    tk_check c = tk_begin("associate = brute force (nearest, lower index on a tie, kept within max_diff)", 0);
    tk_check side = tk_begin("the short side: the estimate unless the reference has fewer poses", 0);
    for (int trial = 0; trial < 400; trial++) {
        size_t nr = 1 + (size_t)(tk_uni(&r) * 40), ne = 1 + (size_t)(tk_uni(&r) * 40);
        if (trial % 7 == 0)
            ne = nr;
        double tr[40], te[40], step = trial % 3 == 0 ? 0.5 : tk_range(&r, 0.01, 1);
        double a = tk_range(&r, -1, 1), b = tk_range(&r, -1, 1);
        for (size_t i = 0; i < nr; i++) /* on a grid of 0.5 now and then: exact ties */
            a += trial % 3 == 0 ? 0.5 : step * tk_range(&r, 0.2, 1.8),
                tr[i] = trial % 3 == 0 ? a - fmod(a, 0.25) : a;
        for (size_t i = 0; i < ne; i++)
            b += trial % 3 == 0 ? 0.75 : step * tk_range(&r, 0.2, 1.8),
                te[i] = trial % 3 == 0 ? b - fmod(b, 0.25) : b;
        for (size_t i = 1; i < nr; i++)
            if (!(tr[i] > tr[i - 1]))
                tr[i] = tr[i - 1] + 0.25;
        for (size_t i = 1; i < ne; i++)
            if (!(te[i] > te[i - 1]))
                te[i] = te[i - 1] + 0.25;
        double md = trial % 5 == 0 ? 0.0 : tk_range(&r, 0, 0.6);
        size_t ir[40], ie[40], n = 99;
        TK_OK(ga_traj_associate(tr, nr, te, ne, md, ir, ie, &n));
        /* brute force */
        int est_long = ne > nr;
        const double *ts = est_long ? tr : te, *tl = est_long ? te : tr;
        size_t ns = est_long ? nr : ne, nl = est_long ? ne : nr, m = 0, bs[40], bl[40];
        for (size_t i = 0; i < ns; i++) {
            size_t best = 0;
            for (size_t j = 1; j < nl; j++)
                if (fabs(tl[j] - ts[i]) < fabs(tl[best] - ts[i]))
                    best = j;
            if (fabs(tl[best] - ts[i]) <= md)
                bs[m] = i, bl[m] = best, m++;
        }
        int same = n == m;
        for (size_t k = 0; same && k < m; k++) {
            size_t wr = est_long ? bs[k] : bl[k], we = est_long ? bl[k] : bs[k];
            same = ir[k] == wr && ie[k] == we;
        }
        tk_add_bool(&c, same);
    }
    /* max_diff huge: every pose of the short side is kept */
    double tr[3] = {0, 1, 2}, te[3] = {0.1, 1.1, 2.1}, te4[4] = {0, 0.5, 1, 1.5};
    size_t ir[4], ie[4], n;
    TK_OK(ga_traj_associate(tr, 3, te, 3, 1e9, ir, ie, &n));
    tk_add_bool(&side, n == 3 && ie[0] == 0 && ie[2] == 2 && ir[2] == 2);
    TK_OK(ga_traj_associate(tr, 3, te4, 4, 1e9, ir, ie, &n)); /* the estimate is longer: ref is short */
    tk_add_bool(&side,
                n == 3 && ir[0] == 0 && ir[1] == 1 && ir[2] == 2 && ie[0] == 0 && ie[1] == 2 && ie[2] == 3);
    tk_end(&c);
    tk_end(&side);
    tk_check st = tk_begin("associate: times not increasing GA_ERR_ARG, NaN GA_ERR_NOTFINITE, max_diff < 0",
                           0);
    double bad[3] = {0, 1, 1}, nan3[3] = {0, NAN, 2};
    tk_add_status(&st, ga_traj_associate(bad, 3, te, 3, 0.1, ir, ie, &n), GA_ERR_ARG);
    tk_add_status(&st, ga_traj_associate(tr, 3, nan3, 3, 0.1, ir, ie, &n), GA_ERR_NOTFINITE);
    tk_add_status(&st, ga_traj_associate(tr, 3, te, 3, -1, ir, ie, &n), GA_ERR_ARG);
    tk_add_status(&st, ga_traj_associate(tr, 0, te, 3, 1, ir, ie, &n), GA_ERR_ARG);
    tk_end(&st);
}

/* ---- align ------------------------------------------------------------------ */

static double align_cost(const ga_mat4 *ref, const ga_mat4 *est, size_t n, ga_mat4 T, double s)
{
    double c = 0;
    for (size_t i = 0; i < n; i++) {
        ga_mat4 e = est[i];
        for (int a = 0; a < 3; a++) e.m[4 * a + 3] *= s;
        e = ga_mat4_mul(T, e);
        c += dist3(e, ref[i]) * dist3(e, ref[i]);
    }
    return c;
}

static void section_align(void)
{
    tk_rng r = {20261204};
    tk_check ex = tk_begin("align: a known Sim(3) motion recovered from exact positions (relative)", 1e-12);
    tk_check ex3 = tk_begin("align: a known SE(3) motion recovered (relative)", 1e-12);
    tk_check mn = tk_begin_least("align with noise: no nudge of R, t or s lowers the cost (relative rise)",
                                 -1e-13);
    enum { N = 60 };
    ga_mat4 ref[N], est[N];
    for (int trial = 0; trial < 60; trial++) {
        ga_mat4 G = rand_pose(&r, 3.0, 5.0);
        double s = trial % 2 ? tk_range(&r, 0.2, 4) : 1.0;
        double noise = trial < 30 ? 0 : 0.05;
        for (int i = 0; i < N; i++) {
            est[i] = rand_pose(&r, 3.0, 4.0);
            ga_mat4 e = est[i];
            for (int a = 0; a < 3; a++) e.m[4 * a + 3] *= s;
            ref[i] = ga_mat4_mul(G, e);
            for (int a = 0; a < 3; a++) ref[i].m[4 * a + 3] += noise * tk_range(&r, -1, 1);
        }
        ga_mat4 T;
        double got;
        TK_OK(ga_traj_align(ref, est, N, trial % 2, &T, &got));
        if (noise == 0) {
            double e = tk_max(mat_diff(T, G) / (1 + dist3(G, ga_mat4_identity())), fabs(got - s) / s);
            tk_add(trial % 2 ? &ex : &ex3, e);
            continue;
        }
        double c0 = align_cost(ref, est, N, T, got);
        for (int k = 0; k < 7; k++)
            for (int sg = -1; sg <= 1; sg += 2) {
                double d[6] = {0};
                double h = 1e-5 * sg, s2 = got;
                ga_mat4 T2 = T;
                if (k < 6) {
                    d[k] = h;
                    T2 = ga_mat4_mul(ga_se3_exp((ga_twist){{d[0], d[1], d[2]}, {d[3], d[4], d[5]}}), T);
                } else if (trial % 2) {
                    s2 = got * (1 + h);
                }
                tk_add(&mn, (align_cost(ref, est, N, T2, s2) - c0) / c0);
            }
    }
    tk_end(&ex);
    tk_end(&ex3);
    tk_end(&mn);
    tk_check st = tk_begin("align: collinear positions, n < 3, a still estimate for Sim(3): GA_ERR_DOMAIN",
                           0);
    for (int i = 0; i < 5; i++) {
        ref[i] = ga_se3_exp((ga_twist){{0, 0, 0}, {i, 2.0 * i, 0}});
        est[i] = ga_se3_exp((ga_twist){{0, 0, 0}, {0, i, 0}});
    }
    ga_mat4 T;
    double s;
    tk_add_status(&st, ga_traj_align(ref, est, 5, 0, &T, &s), GA_ERR_DOMAIN);
    tk_add_status(&st, ga_traj_align(ref, est, 2, 0, &T, &s), GA_ERR_DOMAIN);
    for (int i = 0; i < 5; i++) est[i] = ga_mat4_identity(), ref[i] = rand_pose(&r, 1, 1);
    tk_add_status(&st, ga_traj_align(ref, est, 5, 1, &T, &s), GA_ERR_DOMAIN);
    ref[1].m[3] = NAN;
    tk_add_status(&st, ga_traj_align(ref, est, 5, 0, &T, &s), GA_ERR_NOTFINITE);
    tk_end(&st);
}

/* ---- errors ----------------------------------------------------------------- */

static void section_errors(void)
{
    tk_rng r = {20261205};
    enum { N = 50 };
    ga_mat4 ref[N], est[N];
    for (int i = 0; i < N; i++) {
        ref[i] = rand_pose(&r, 3.0, 4.0);
        est[i] = ga_mat4_mul(ref[i], rand_pose(&r, 0.3, 0.2));
    }
    double te[N], re[N];
    tk_check ape = tk_begin("APE: |t_est - t_ref| and the angle |w| of log(est^-1 ref) (rad, deg)", 1e-13);
    TK_OK(ga_traj_ape(ref, est, N, 1.0, te, re));
    for (int i = 0; i < N; i++) {
        tk_add(&ape, fabs(te[i] - dist3(est[i], ref[i])));
        tk_add(&ape, fabs(re[i] - log_angle(ga_mat4_mul(ga_se3_inverse(est[i]), ref[i]))));
    }
    TK_OK(ga_traj_ape(ref, est, N, 180 / TK_PI, te, re));
    for (int i = 0; i < N; i++)
        tk_add(&ape,
               fabs(re[i] - 180 / TK_PI * log_angle(ga_mat4_mul(ga_se3_inverse(est[i]), ref[i]))) / 180);
    tk_end(&ape);
    tk_check rpe = tk_begin("RPE: E = (Q_i^-1 Q_j)^-1 (P_i^-1 P_j) by log, every delta, both pairings",
                            1e-12);
    tk_check cnt = tk_begin("rpe_count = the pairs enumerated", 0);
    for (size_t delta = 1; delta <= N + 1; delta += 3)
        for (int all = 0; all < 2; all++) {
            size_t want = 0;
            for (size_t i = 0; i + delta < N; i += all ? 1 : delta) want++;
            size_t m = ga_traj_rpe_count(N, delta, all);
            tk_add_bool(&cnt, m == want);
            if (m == 0) {
                tk_add_status(&cnt, ga_traj_rpe(ref, est, N, delta, all, 1.0, te, re), GA_ERR_ARG);
                continue;
            }
            TK_OK(ga_traj_rpe(ref, est, N, delta, all, 1.0, te, re));
            size_t k = 0;
            for (size_t i = 0; i + delta < N; i += all ? 1 : delta, k++) {
                ga_mat4 q = ga_mat4_mul(ga_se3_inverse(ref[i]), ref[i + delta]);
                ga_mat4 p = ga_mat4_mul(ga_se3_inverse(est[i]), est[i + delta]);
                ga_mat4 e = ga_mat4_mul(ga_se3_inverse(q), p);
                tk_add(&rpe, fabs(te[k] - dist3(e, ga_mat4_identity())) / (1 + te[k]));
                tk_add(&rpe, fabs(re[k] - log_angle(e)));
            }
        }
    tk_add_bool(&cnt, ga_traj_rpe_count(N, 0, 0) == 0 && ga_traj_rpe_count(1, 1, 1) == 0 &&
                          ga_traj_rpe_count(7, 3, 0) == 2 && ga_traj_rpe_count(7, 3, 1) == 4);
    tk_end(&rpe);
    tk_end(&cnt);

    tk_check sts = tk_begin("statistics: the sums here, the median of the sorted copy, std population",
                            1e-15);
    for (int trial = 0; trial < 200; trial++) {
        size_t n = 1 + (size_t)(tk_uni(&r) * 30);
        double e[32], c[32], sum = 0, sse = 0;
        for (size_t i = 0; i < n; i++)
            e[i] = trial % 4 == 0 ? (double)(tk_next(&r) % 4) : tk_range(&r, 0, 10);
        memcpy(c, e, sizeof e);
        for (size_t i = 1; i < n; i++) /* insertion sort */
            for (size_t j = i; j > 0 && c[j - 1] > c[j]; j--) {
                double t = c[j];
                c[j] = c[j - 1];
                c[j - 1] = t;
            }
        for (size_t i = 0; i < n; i++) sum += e[i], sse += e[i] * e[i];
        double mean = sum / (double)n, var = 0;
        for (size_t i = 0; i < n; i++) var += (e[i] - mean) * (e[i] - mean);
        ga_traj_stats s;
        TK_OK(ga_traj_statistics(e, n, &s));
        double med = n % 2 ? c[n / 2] : (c[n / 2 - 1] + c[n / 2]) / 2;
        int sorted = memcmp(e, c, n * sizeof *e) == 0;
        tk_add_bool(&sts, sorted && s.min == c[0] && s.max == c[n - 1] && s.median == med);
        tk_add(&sts, fabs(s.mean - mean) + fabs(s.sse - sse) + fabs(s.rmse - sqrt(sse / (double)n)) +
                         fabs(s.std - sqrt(var / (double)n)));
    }
    double e3[4] = {3, 1, 2, 10};
    ga_traj_stats s;
    TK_OK(ga_traj_statistics(e3, 4, &s));
    tk_add_bool(&sts, s.median == 2.5 && s.mean == 4 && s.sse == 114 && s.min == 1 && s.max == 10);
    double en[2] = {1, NAN};
    tk_add_status(&sts, ga_traj_statistics(en, 2, &s), GA_ERR_NOTFINITE);
    tk_add_status(&sts, ga_traj_statistics(en, 0, &s), GA_ERR_ARG);
    tk_end(&sts);
}

/* ---- tum ------------------------------------------------------------------- */

static void section_tum(void)
{
    tk_rng r = {20261206};
    tk_check rt = tk_begin("pose_to_tum(pose_from_tum(row)) = row (q up to sign)", 4e-16 * 8);
    tk_check sg = tk_begin("pose_to_tum: q . prev >= 0", 0);
    ga_quat prev = {1, 0, 0, 0};
    for (int i = 0; i < 500; i++) {
        ga_vec3 u = tk_unit(&r);
        double a = tk_range(&r, 0, TK_PI), s = sin(a / 2);
        double row[7] = {
            tk_range(&r, -5, 5), tk_range(&r, -5, 5), tk_range(&r, -5, 5), s * u.x, s * u.y, s * u.z,
            cos(a / 2)};
        ga_mat4 m;
        TK_OK(ga_traj_pose_from_tum(row, 0, &m));
        double back[7];
        ga_quat before = prev;
        TK_OK(ga_traj_pose_to_tum(m, &prev, back));
        double sign = back[6] * row[6] + back[3] * row[3] + back[4] * row[4] + back[5] * row[5] < 0 ? -1 : 1;
        for (int k = 0; k < 7; k++) tk_add(&rt, fabs(back[k] - (k >= 3 ? sign : 1) * row[k]));
        tk_add_bool(&sg,
                    back[6] * before.w + back[3] * before.x + back[4] * before.y + back[5] * before.z >= 0);
    }
    tk_end(&rt);
    tk_end(&sg);
    tk_check st =
        tk_begin("pose_from_tum: |q| 1 + 2e-9 refused, accepted and normalised with normalize; 2e-3 "
                 "refused by both; NaN",
                 0);
    double row[7] = {1, 2, 3, 0, 0, 0, 1 + 2e-9};
    ga_mat4 m;
    tk_add_status(&st, ga_traj_pose_from_tum(row, 0, &m), GA_ERR_NOTRIGID);
    tk_add_status(&st, ga_traj_pose_from_tum(row, 1, &m), GA_OK);
    tk_add_bool(&st, m.m[0] == 1 && m.m[3] == 1 && m.m[11] == 3);
    row[6] = 1 + 2e-3;
    tk_add_status(&st, ga_traj_pose_from_tum(row, 1, &m), GA_ERR_NOTRIGID);
    row[6] = NAN;
    tk_add_status(&st, ga_traj_pose_from_tum(row, 1, &m), GA_ERR_NOTFINITE);
    tk_end(&st);
}

/* ---- fit -------------------------------------------------------------------- */

static double work[1 << 17];

/* the mean translation and angle error of the fitted spline against the true
 * one at 200 times over the keys' span */
static double fit_error(const ga_mat4 *ctl, size_t nc, const ga_mat4 *truth, size_t nt, double h, double span)
{
    double e = 0;
    for (int i = 0; i < 200; i++) {
        double t = span * (i + 0.5) / 200;
        ga_mat4 a, b;
        TK_OK(ga_traj_bspline_pose(ctl, nc, h, t, &a));
        TK_OK(ga_traj_bspline_pose(truth, nt, h, t, &b));
        ga_mat4 d = ga_mat4_mul(ga_se3_inverse(a), b);
        e += dist3(d, ga_mat4_identity()) + ga_traj_angle(d);
    }
    return e / 200;
}

static void section_fit(void)
{
    tk_rng r = {20261207};
    const double h = 0.5, span = 4.0;
    size_t nc;
    TK_OK(ga_traj_fit_count(span, h, &nc));
    tk_expect(nc == 11, "fit_count(4, 0.5) = 8 intervals + 3 = 11 controls");
    ga_mat4 truth[11], ctl[11];
    truth[0] = rand_pose(&r, 1, 1);
    for (size_t j = 1; j < nc; j++) truth[j] = ga_mat4_mul(truth[j - 1], rand_pose(&r, 0.3, 0.4));
    enum { MAXK = 1600 };
    static double t[MAXK], res[2 * MAXK];
    static ga_mat4 z[MAXK], f[MAXK];
    size_t ws = ga_traj_fit_workspace_size(nc);
    tk_expect(ws > 0 && ws <= sizeof work, "the workspace of 11 controls fits the test's buffer");
    /* exact keys at uneven times */
    tk_check ex = tk_begin("fit of exact keys on uneven stamps: every residual (m, rad)", 1e-9);
    size_t n = 60;
    for (size_t k = 0; k < n; k++)
        t[k] = k == 0 ? 0 : k == n - 1 ? span : span * (k + tk_range(&r, -0.4, 0.4)) / (n - 1);
    for (size_t k = 0; k < n; k++) TK_OK(ga_traj_bspline_pose(truth, nc, h, t[k], &z[k]));
    TK_OK(ga_traj_fit_bspline(t, z, n, h, 0, work, ws, ctl, nc));
    TK_OK(ga_traj_fit_residuals(t, z, n, ctl, nc, h, f, res));
    for (size_t k = 0; k < 2 * n; k++) tk_add(&ex, res[k]);
    tk_add(&ex, fit_error(ctl, nc, truth, nc, h, span));
    tk_end(&ex);
    /* noisy keys: 100, 400, 1600 */
    double err[3];
    for (int level = 0; level < 3; level++) {
        n = (size_t)100 << (2 * level);
        tk_rng rn = {777};
        for (size_t k = 0; k < n; k++) {
            t[k] = span * (k + (k && k < n - 1 ? tk_range(&rn, -0.3, 0.3) : 0)) / (double)(n - 1);
            ga_mat4 p;
            TK_OK(ga_traj_bspline_pose(truth, nc, h, t[k], &p));
            ga_vec3 u = tk_unit(&rn), d = tk_unit(&rn);
            z[k] = ga_mat4_mul(p, ga_se3_exp((ga_twist){tk_scale(u, 0.02 * tk_uni(&rn)),
                                                        tk_scale(d, 0.02 * tk_uni(&rn))}));
        }
        TK_OK(ga_traj_fit_bspline(t, z, n, h, 0, work, ws, ctl, nc));
        err[level] = fit_error(ctl, nc, truth, nc, h, span);
        tk_note("noisy keys (0.02 m, rad): %zu keys, mean error of the fit against the truth %.3g\n", n,
                err[level]);
    }
    tk_check fall = tk_begin_least("noise: 4x the keys lowers the error by a factor >= 1.5 (theory: 2)", 1.5);
    tk_add(&fall, err[0] / err[1]);
    tk_add(&fall, err[1] / err[2]);
    tk_end(&fall);
    tk_check st = tk_begin("fit: statuses (small or misaligned workspace, times, n < 4, NaN, count)", 0);
    tk_add_status(&st, ga_traj_fit_bspline(t, z, 100, h, 0, work, ws - 1, ctl, nc), GA_ERR_ARG);
    tk_add_status(&st, ga_traj_fit_bspline(t, z, 100, h, 0, (char *)work + 1, ws, ctl, nc), GA_ERR_ARG);
    tk_add_status(&st, ga_traj_fit_bspline(t, z, 3, h, 0, work, ws, ctl, nc), GA_ERR_ARG);
    tk_add_status(&st, ga_traj_fit_bspline(t, z, 100, h, -1, work, ws, ctl, nc), GA_ERR_ARG);
    double keep = t[5];
    t[5] = t[4];
    tk_add_status(&st, ga_traj_fit_bspline(t, z, 100, h, 0, work, ws, ctl, nc), GA_ERR_ARG);
    t[5] = NAN;
    tk_add_status(&st, ga_traj_fit_bspline(t, z, 100, h, 0, work, ws, ctl, nc), GA_ERR_NOTFINITE);
    t[5] = keep;
    tk_add_status(&st, ga_traj_fit_count(2e6, 1, &nc), GA_ERR_DOMAIN);
    tk_add_status(&st, ga_traj_fit_count(1, 0, &nc), GA_ERR_ARG);
    tk_add_bool(&st, ga_traj_fit_workspace_size(3) == 0 && ga_traj_fit_workspace_size(SIZE_MAX / 2) == 0);
    TK_OK(ga_traj_fit_count(0, 1, &nc));
    tk_add_bool(&st, nc == 4);
    tk_end(&st);
}

static const tk_section sections[] = {
    {"associate", section_associate, 0},
    {"align", section_align, 0},
    {"errors", section_errors, 0},
    {"tum", section_tum, 0},
    {"fit", section_fit, 0},
};

int main(int argc, char **argv)
{
    return tk_main(argc, argv, "test_trajectory", sections, TK_COUNT(sections));
}
