/* tests/soak_c2_keys.c: the figures of docs/schemes.md ("At a glance" and
 * c2's table) on the five keys of docs/figures/schemes.keys (argument: that
 * file), one row per scheme (quadratic on the first three keys; bspline, and
 * lihao3-even beside it, at the even times 0, 1, 2, 3, 4): through the keys
 * (largest matrix-entry difference between each segment's ends and its keys;
 * bspline: between A(t_i) and A_i for the keys in its range, also printed
 * one by one), the velocity and acceleration jumps (body frame, per unit t)
 * between the segments meeting at each interior key (bspline: knot),
 * invariance under a change of world frame (G A_i against G A(t)) and of body
 * frame (A_i H against A(t) H) over 201 samples of the path's range, the
 * largest body velocity and acceleration entries and cga against matrix over
 * 2001 samples; then decoupled's positions against screw's. With a second
 * argument, a pose file (t x y z qx qy qz qw a line, quaternions normalised:
 * tests/tum_like.awk's), the growth ratios (ga_path_measure_growth) of
 * lihao2, lihao3 and c2 on it. A measurement (exit status 0 unless a file
 * cannot be read): the soak suite runs it so that it keeps building and
 * running, and tests/doc_figures_check.py checks the tables of
 * docs/schemes.md against what it prints. */
#include <stdio.h>
#include <stdlib.h>

#include "testkit.h"

#define N 5

static ga_mat4 pose(const double *x)
{
    ga_quat q = {x[6], x[3], x[4], x[5]};
    ga_vec3 p = {x[0], x[1], x[2]};
    return ga_rotor_to_mat4(ga_rotor_from_quat(q, p));
}
static ga_mat4 motion(double deg, ga_vec3 axis, ga_vec3 t)
{
    double s = sqrt(axis.x * axis.x + axis.y * axis.y + axis.z * axis.z), th = deg * TK_PI / 180;
    ga_twist x = {{axis.x / s * th, axis.y / s * th, axis.z / s * th}, {0, 0, 0}};
    ga_mat4 m = ga_se3_exp(x);
    m.m[3] = t.x, m.m[7] = t.y, m.m[11] = t.z;
    return m;
}
static double md(ga_mat4 a, ga_mat4 b)
{
    double e = 0;
    for (int i = 0; i < 16; ++i) e = tk_max(e, fabs(a.m[i] - b.m[i]));
    return e;
}
static double vd(const double *a, const double *b)
{
    double e = 0;
    for (int i = 0; i < 6; ++i) e = tk_max(e, fabs(a[i] - b[i]));
    return e;
}

int main(int argc, char **argv)
{
    FILE *f = argc > 1 ? fopen(argv[1], "r") : NULL;
    double t[N], x[7];
    ga_mat4 k[N], kg[N], kh[N];
    char line[256];
    int n = 0;
    while (f && n < N && fgets(line, sizeof line, f))
        if (line[0] != '#' && sscanf(line, "%lf %lf %lf %lf %lf %lf %lf %lf", &t[n], &x[0], &x[1], &x[2],
                                     &x[3], &x[4], &x[5], &x[6]) == 8)
            k[n] = pose(x), ++n;
    if (n != N) {
        fprintf(stderr, "soak_c2_keys: need the %d keys of docs/figures/schemes.keys\n", N);
        return 1;
    }
    ga_mat4 G = motion(70, (ga_vec3){1, 2, 3}, (ga_vec3){3, -2, 1}),
            H = motion(50, (ga_vec3){2, -1, 0.5}, (ga_vec3){-1, 0.5, 2});
    for (int i = 0; i < N; ++i) kg[i] = ga_mat4_mul(G, k[i]), kh[i] = ga_mat4_mul(k[i], H);
    printf("%-13s %-9s %-9s %-9s %-9s %-9s %-7s %-7s %s\n", "scheme", "keys", "v jump", "a jump", "world",
           "body", "max v", "max a", "cga-matrix");
    /* every scheme on the five keys; quadratic on the first three; bspline
     * (and lihao3-even beside it) at the even times 0, 1, 2, 3, 4 */
    static const double even[N] = {0, 1, 2, 3, 4};
    const struct {
        ga_scheme s;
        const char *name;
        int n;
        const double *t;
    } row[] = {{GA_SCHEME_SCREW, "screw", N, t},
               {GA_SCHEME_BIVECTOR, "bivector", N, t},
               {GA_SCHEME_QUADRATIC, "quadratic", 3, t},
               {GA_SCHEME_SMOOTH, "smooth", N, t},
               {GA_SCHEME_LIHAO2, "lihao2", N, t},
               {GA_SCHEME_LIHAO3, "lihao3", N, t},
               {GA_SCHEME_BSPLINE, "bspline", N, even},
               {GA_SCHEME_C2, "c2", N, t},
               {GA_SCHEME_DECOUPLED_C2, "decoupled-c2", N, t},
               {GA_SCHEME_LIHAO3, "lihao3-even", N, even}};
    static double w[4][8192];
    double boff[N] = {0};
    for (size_t s = 0; s < sizeof row / sizeof row[0]; ++s) {
        ga_path p, pg, ph, pc;
        const int n = row[s].n;
        const double *ts = row[s].t;
        if (ga_path_init_mat4(&ga_group_se3, row[s].s, n, ts, k, NULL, w[0], sizeof w[0], &p) ||
            ga_path_init_mat4(&ga_group_se3, row[s].s, n, ts, kg, NULL, w[1], sizeof w[1], &pg) ||
            ga_path_init_mat4(&ga_group_se3, row[s].s, n, ts, kh, NULL, w[2], sizeof w[2], &ph) ||
            ga_path_init_mat4(&ga_group_cga, row[s].s, n, ts, k, NULL, w[3], sizeof w[3], &pc)) {
            printf("%s: cannot build\n", row[s].name);
            continue;
        }
        double keys = 0, vj = 0, aj = 0, wo = 0, bo = 0, vmax = 0, amax = 0, cm = 0, t0, t1;
        ga_mat4 a, b, c;
        const size_t ns = ga_path_segments(&p);
        TK_OK(ga_path_range(&p, &t0, &t1));
        if (row[s].s == GA_SCHEME_BSPLINE) {
            /* not through its keys: how far from those in its range */
            for (int i = 1; i + 1 < n; ++i) {
                TK_OK(ga_path_eval(&p, ts[i], &a));
                boff[i] = md(a, k[i]);
                keys = tk_max(keys, boff[i]);
            }
        } else {
            for (size_t i = 0; i < ns; ++i) {
                TK_OK(ga_path_eval_segment(&p, i, 0.0, &a));
                TK_OK(ga_path_eval_segment(&p, i, 1.0, &b));
                keys = tk_max(keys, tk_max(md(a, k[i]), md(b, k[i + 1])));
            }
        }
        for (size_t i = 0; i + 1 < ns; ++i) {
            /* the two sides of the joint between segments i and i + 1 */
            double v0[6], a0[6], v1[6], a1[6];
            TK_OK(ga_path_differentiate_segment(&p, i, 1.0, GA_FRAME_BODY, v0, a0));
            TK_OK(ga_path_differentiate_segment(&p, i + 1, 0.0, GA_FRAME_BODY, v1, a1));
            vj = tk_max(vj, vd(v0, v1));
            aj = tk_max(aj, vd(a0, a1));
        }
        for (int j = 0; j <= 200; ++j) {
            double tj = j == 200 ? t1 : t0 + (t1 - t0) * j / 200;
            TK_OK(ga_path_eval(&p, tj, &a));
            TK_OK(ga_path_eval(&pg, tj, &b));
            TK_OK(ga_path_eval(&ph, tj, &c));
            wo = tk_max(wo, md(b, ga_mat4_mul(G, a)));
            bo = tk_max(bo, md(c, ga_mat4_mul(a, H)));
        }
        for (int j = 0; j <= 2000; ++j) {
            double tj = j == 2000 ? t1 : t0 + (t1 - t0) * j / 2000, v[6], ac[6];
            ga_rotor r;
            TK_OK(ga_path_eval(&p, tj, &a));
            TK_OK(ga_path_eval(&pc, tj, &r));
            cm = tk_max(cm, md(a, ga_rotor_to_mat4(r)));
            TK_OK(ga_path_differentiate(&p, tj, GA_FRAME_BODY, v, ac));
            for (int q = 0; q < 6; ++q) vmax = tk_max(vmax, fabs(v[q])), amax = tk_max(amax, fabs(ac[q]));
        }
        printf("%-13s %-9.2g %-9.2g %-9.2g %-9.2g %-9.2g %-7.3g %-7.3g %.2g\n", row[s].name, keys, vj, aj, wo,
               bo, vmax, amax, cm);
    }
    printf("bspline: from its keys at t = 1, 2, 3 by %.2g, %.2g, %.2g\n", boff[1], boff[2], boff[3]);
    {
        /* decoupled's straight chords against screw's helices: the largest
         * difference of a position coordinate over 2001 samples */
        ga_path ps, pd;
        double dp = 0;
        if (ga_path_init_mat4(&ga_group_se3, GA_SCHEME_SCREW, N, t, k, NULL, w[0], sizeof w[0], &ps) ||
            ga_path_init_mat4(&ga_group_se3, GA_SCHEME_DECOUPLED, N, t, k, NULL, w[1], sizeof w[1], &pd))
            printf("decoupled: cannot build\n");
        else {
            for (int j = 0; j <= 2000; ++j) {
                double tj = j == 2000 ? t[N - 1] : t[0] + (t[N - 1] - t[0]) * j / 2000;
                ga_mat4 a, b;
                TK_OK(ga_path_eval(&ps, tj, &a));
                TK_OK(ga_path_eval(&pd, tj, &b));
                for (int q = 3; q < 12; q += 4) dp = tk_max(dp, fabs(a.m[q] - b.m[q]));
            }
            printf("decoupled: positions from screw's by up to %.3g\n", dp);
        }
    }
    fclose(f);
    if (argc < 3)
        return 0;
    /* the growth rule on a pose file */
    FILE *g = fopen(argv[2], "r");
    size_t cap = 0, m = 0;
    double *tt = NULL, y[8];
    ga_mat4 *kk = NULL;
    while (g && fscanf(g, "%lf %lf %lf %lf %lf %lf %lf %lf", &y[0], &y[1], &y[2], &y[3], &y[4], &y[5], &y[6],
                       &y[7]) == 8) {
        if (m == cap) {
            cap = cap ? 2 * cap : 256;
            double *nt = realloc(tt, cap * sizeof *tt);
            ga_mat4 *nk = realloc(kk, cap * sizeof *kk);
            if (!nt || !nk)
                return free(nt ? nt : tt), free(nk ? nk : kk), 1;
            tt = nt, kk = nk;
        }
        double nq = sqrt(y[4] * y[4] + y[5] * y[5] + y[6] * y[6] + y[7] * y[7]);
        for (int i = 4; i < 8; ++i) y[i] /= nq;
        tt[m] = y[0];
        kk[m++] = pose(y + 1);
    }
    if (g)
        fclose(g);
    if (m < 3) {
        fprintf(stderr, "soak_c2_keys: %s: need 3 or more poses\n", argv[2]);
        return free(tt), free(kk), 1;
    }
    double t0 = tt[0];
    for (size_t i = 0; i < m; ++i) tt[i] -= t0;
    size_t wb = ga_path_workspace_size(&ga_group_se3, GA_SCHEME_C2, m);
    void *wk = malloc(wb);
    const ga_scheme gs[3] = {GA_SCHEME_LIHAO2, GA_SCHEME_LIHAO3, GA_SCHEME_C2};
    for (int s = 0; wk && s < 3; ++s) {
        ga_path p;
        ga_path_growth gr;
        int st = ga_path_init_mat4(&ga_group_se3, gs[s], m, tt, kk, NULL, wk, wb, &p);
        if (st == GA_OK)
            st = ga_path_measure_growth(&p, &gr);
        if (st == GA_OK)
            printf("%s: %zu keys: largest ratio %.3g at key %zu, first past %g: %s%zu\n",
                   ga_scheme_name(gs[s]), m, gr.ratio, gr.key, GA_PATH_GROWTH_MAX,
                   gr.first < m ? "key " : "none, ", gr.first);
        else
            printf("%s: %s\n", ga_scheme_name(gs[s]), ga_status_string(st));
    }
    free(wk);
    free(tt);
    free(kk);
    return 0;
}
