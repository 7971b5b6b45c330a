/* tests/test_bspline.c: the uniform cumulative cubic B-spline (path.h
 * BSPLINE): its velocity and acceleration against finite differences, C2 at
 * the knots, cga = matrix, a motion on one screw reproduced, exact stepping
 * and Euler, local support, the time range and the checks of even spacing.
 */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "testkit.h"

/* the one stream every section draws from, in order (helpers take it as r) */
static tk_rng stream = {20261201u};
static tk_rng *const r = &stream;

#define MAXK 12
#define WORK 4096

typedef struct {
    int n;
    double t[MAXK];
    ga_mat4 m[MAXK];
} keyset;

typedef struct {
    ga_path p;
    double work[WORK];
} pathbuf;

static int mkpath(pathbuf *b, const ga_group *g, ga_scheme s, const keyset *k)
{
    return ga_path_init_mat4(g, s, (size_t)k->n, k->t, k->m, NULL, b->work, sizeof b->work, &b->p);
}

static ga_vec3 rvec(tk_rng *r, double s)
{
    ga_vec3 v;
    v.x = tk_range(r, -s, s);
    v.y = tk_range(r, -s, s);
    v.z = tk_range(r, -s, s);
    return v;
}

/* n keys at t0 + i h: each a random step (rotation up to 1.5 rad, translation
 * up to 1) from the one before; affine: exp of a random 3x4 step. */
static void random_keys(tk_rng *r, const ga_group *g, keyset *k, int n, double t0, double h)
{
    k->n = n;
    ga_mat4 m = ga_mat4_identity();
    for (int i = 0; i < n; ++i) {
        k->t[i] = t0 + h * i;
        if (g == &ga_group_affine) {
            double x[12], e[16];
            for (int j = 0; j < 12; ++j) x[j] = tk_range(r, -0.3, 0.3) * (j % 4 == 3 ? 3 : 1);
            ga_group_affine.exp(x, e);
            m = ga_mat4_mul(m, ga_group_affine.to_mat4(e));
        } else {
            ga_twist xi = {rvec(r, 0.85), rvec(r, 1.0)};
            m = ga_mat4_mul(m, ga_se3_exp(xi));
        }
        k->m[i] = m;
    }
}

static double vdiff(const double *a, const double *b, size_t d)
{
    double e = 0.0;
    for (size_t i = 0; i < d; ++i) e = tk_max(e, fabs(a[i] - b[i]));
    return e;
}
static double vnorm(const double *a, size_t d)
{
    double e = 0.0;
    for (size_t i = 0; i < d; ++i) e = tk_max(e, fabs(a[i]));
    return e;
}
static double mdiff(ga_mat4 a, ga_mat4 b)
{
    double e = 0.0;
    for (int i = 0; i < 16; ++i) e = tk_max(e, fabs(a.m[i] - b.m[i]));
    return e;
}

/* The velocity scale of a path: the largest |d_i|/h (the d_i are in p->coef). */
static double vscale(const ga_path *p)
{
    double s = 0.0, t0, t1;
    for (size_t i = 0; i + 1 < p->n; ++i) s = fmax(s, vnorm(p->coef + i * p->group->dim, p->group->dim));
    TK_OK(ga_path_segment_range(p, 0, &t0, &t1));
    return fmax(s, 1.0) / (t1 - t0);
}

static ga_mat4 pose_at(const ga_path *p, double t)
{
    double e[16];
    if (ga_path_eval(p, t, e) != GA_OK) {
        ga_mat4 z;
        for (int i = 0; i < 16; ++i) z.m[i] = NAN;
        return z;
    }
    return p->group->to_mat4(e);
}

/* y = log(a^-1 b) through the group */
static void body_log(const ga_group *g, const void *a, const void *b, double *y)
{
    double ai[16], r[16];
    g->inverse(a, ai);
    g->compose(ai, b, r);
    if (g->log(r, y) != GA_OK)
        for (size_t i = 0; i < g->dim; ++i) y[i] = NAN;
}

/* Central differences on segment seg at u, step e in t: the body velocity from
 * the poses, the acceleration from the analytic velocity. */
static void fd_seg(const ga_path *p, size_t seg, double u, double e, double *v, double *a)
{
    const ga_group *g = p->group;
    double ta, tb, A[16], P[16], M[16], yp[12], ym[12], vp[12], vm[12];
    TK_OK(ga_path_segment_range(p, seg, &ta, &tb));
    double du = e / (tb - ta);
    TK_OK(ga_path_eval_segment(p, seg, u, A));
    TK_OK(ga_path_eval_segment(p, seg, u + du, P));
    TK_OK(ga_path_eval_segment(p, seg, u - du, M));
    body_log(g, A, P, yp);
    body_log(g, A, M, ym);
    TK_OK(ga_path_differentiate_segment(p, seg, u + du, GA_FRAME_BODY, vp, NULL));
    TK_OK(ga_path_differentiate_segment(p, seg, u - du, GA_FRAME_BODY, vm, NULL));
    for (size_t i = 0; i < g->dim; ++i) {
        v[i] = (yp[i] - ym[i]) / (2 * e);
        a[i] = (vp[i] - vm[i]) / (2 * e);
    }
}

static const ga_group *const groups[3] = {&ga_group_cga, &ga_group_se3, &ga_group_affine};

/* ---- 1. derivatives against finite differences, both frames ---------------------- */

static void test_derivatives(void)
{
    /* central differences of step e err by e^2/6 times the third derivative,
     * plus eps/e rounding: at e = 1e-4 about 1e-8 of the scale; halving e
     * must cut the error about 4x (>= 3x) unless at the floor 1e-9 */
    tk_check c_v = tk_begin("velocity = central FD of the poses, / vscale (step 1e-4)", 1e-7);
    tk_check c_a = tk_begin("acceleration = central FD of the velocity, / vscale^2 (step 1e-4)", 1e-7);
    tk_check c_fall = tk_begin("FD errors fall >= 3x when the step halves (or <= 1e-9)", 0);
    tk_check c_sp = tk_begin("spatial = Ad_A body (velocity and acceleration), / vscale^2", 1e-13);
    tk_check c_api = tk_begin("velocity/acceleration(_segment) = differentiate (same numbers)", 0);
    for (int trial = 0; trial < 9; ++trial) {
        const ga_group *g = groups[trial % 3];
        size_t d = g->dim;
        keyset k;
        random_keys(r, g, &k, 5 + trial % 3, tk_range(r, -3, 3), tk_range(r, 0.3, 2.0));
        pathbuf b;
        if (mkpath(&b, g, GA_SCHEME_BSPLINE, &k) != GA_OK) {
            tk_add(&c_v, INFINITY);
            continue;
        }
        double vs = vscale(&b.p), vs2 = vs * vs;
        for (size_t s = 0; s < ga_path_segments(&b.p); ++s)
            for (int q = 0; q < 4; ++q) {
                double u = 0.05 + 0.3 * q, v[12], a[12], vf[12], af[12], vf2[12], af2[12];
                TK_OK(ga_path_differentiate_segment(&b.p, s, u, GA_FRAME_BODY, v, a));
                fd_seg(&b.p, s, u, 1e-4, vf, af);
                fd_seg(&b.p, s, u, 5e-5, vf2, af2);
                double ev = vdiff(v, vf, d) / vs, ev2 = vdiff(v, vf2, d) / vs;
                double ea = vdiff(a, af, d) / vs2, ea2 = vdiff(a, af2, d) / vs2;
                tk_add(&c_v, ev);
                tk_add(&c_a, ea);
                tk_add_bool(&c_fall, (ev <= 1e-9 || ev >= 3 * ev2) && (ea <= 1e-9 || ea >= 3 * ea2));
                double m[16], vsp[12], asp[12], adv[12], ada[12], v1[12], a1[12], ta, tb;
                TK_OK(ga_path_eval_segment(&b.p, s, u, m));
                TK_OK(ga_path_differentiate_segment(&b.p, s, u, GA_FRAME_SPATIAL, vsp, asp));
                g->adjoint(m, v, adv);
                g->adjoint(m, a, ada);
                tk_add(&c_sp, fmax(vdiff(vsp, adv, d) / vs, vdiff(asp, ada, d) / vs2) /
                                  fmax(1.0, ga_mat4_norm1(g->to_mat4(m))));
                TK_OK(ga_path_velocity_segment(&b.p, s, u, v1));
                TK_OK(ga_path_acceleration_segment(&b.p, s, u, a1));
                tk_add_bool(&c_api, vdiff(v, v1, d) == 0.0 && vdiff(a, a1, d) == 0.0);
                TK_OK(ga_path_segment_range(&b.p, s, &ta, &tb));
                double t = ta + 0.5 * (tb - ta);
                TK_OK(ga_path_differentiate(&b.p, t, GA_FRAME_BODY, v, a));
                TK_OK(ga_path_velocity(&b.p, t, v1));
                TK_OK(ga_path_acceleration(&b.p, t, a1));
                tk_add_bool(&c_api, vdiff(v, v1, d) == 0.0 && vdiff(a, a1, d) == 0.0);
            }
    }
    tk_end(&c_v);
    tk_end(&c_a);
    tk_end(&c_fall);
    tk_end(&c_sp);
    tk_end(&c_api);
}

/* ---- 2. C2 at the knots ------------------------------------------------------------ */

static void test_c2(void)
{
    /* at a knot the two segments' formulas give the same pose, velocity and
     * acceleration (up to rounding); measured from outside: the jump of the
     * acceleration over [t_k - e, t_k + e] shrinks like e (the third
     * derivative jumps, so the jump is about 2e |a'|), while on lihao3
     * (C1) it stays at the scheme's jump */
    tk_check c_pose = tk_begin("knots: pose of segment s at u=1 = of s+1 at u=0, / scale", 1e-14);
    tk_check c_vel = tk_begin("knots: velocity s at u=1 = s+1 at u=0, / vscale", 1e-14);
    tk_check c_acc = tk_begin("knots: acceleration s at u=1 = s+1 at u=0, / vscale^2", 1e-13);
    tk_check c_shr = tk_begin("knots: |a(t+e) - a(t-e)| / vscale^2 at e = 1e-6", 1e-5);
    tk_check c_lin = tk_begin("knots: that jump halves with e (ratio in [1.8, 2.2], e = 1e-3 .. 1e-6)", 0);
    tk_check c_c1 = tk_begin_least("lihao3 on the same keys: acceleration jump at e = 1e-6, / vscale^2",
                                   1e-3);
    for (int trial = 0; trial < 9; ++trial) {
        const ga_group *g = groups[trial % 3];
        size_t d = g->dim;
        keyset k;
        random_keys(r, g, &k, 7, tk_range(r, -3, 3), tk_range(r, 0.3, 2.0));
        pathbuf b, l;
        if (mkpath(&b, g, GA_SCHEME_BSPLINE, &k) != GA_OK) {
            tk_add(&c_pose, INFINITY);
            continue;
        }
        double vs = vscale(&b.p), vs2 = vs * vs, sc = 1.0;
        for (int i = 0; i < k.n; ++i) sc = fmax(sc, ga_mat4_norm1(k.m[i]));
        int lst = g == &ga_group_affine ? -1 : mkpath(&l, g, GA_SCHEME_LIHAO3, &k);
        for (size_t s = 0; s + 1 < ga_path_segments(&b.p); ++s) {
            double e0[16], e1[16], v0[12], a0[12], v1[12], a1[12], ta, tk;
            TK_OK(ga_path_eval_segment(&b.p, s, 1.0, e0));
            TK_OK(ga_path_eval_segment(&b.p, s + 1, 0.0, e1));
            tk_add(&c_pose, mdiff(g->to_mat4(e0), g->to_mat4(e1)) / sc);
            TK_OK(ga_path_differentiate_segment(&b.p, s, 1.0, GA_FRAME_BODY, v0, a0));
            TK_OK(ga_path_differentiate_segment(&b.p, s + 1, 0.0, GA_FRAME_BODY, v1, a1));
            tk_add(&c_vel, vdiff(v0, v1, d) / vs);
            tk_add(&c_acc, vdiff(a0, a1, d) / vs2);
            TK_OK(ga_path_segment_range(&b.p, s, &ta, &tk));
            double prev = NAN;
            for (double e = 1e-3; e > 0.9e-6; e /= 2) {
                double ap[12], am[12];
                TK_OK(ga_path_acceleration(&b.p, tk + e, ap));
                TK_OK(ga_path_acceleration(&b.p, tk - e, am));
                double j = vdiff(ap, am, d) / vs2;
                if (!isnan(prev))
                    tk_add_bool(&c_lin, prev / j >= 1.8 && prev / j <= 2.2);
                prev = j;
            }
            double ap[12], am[12];
            TK_OK(ga_path_acceleration(&b.p, tk + 1e-6, ap));
            TK_OK(ga_path_acceleration(&b.p, tk - 1e-6, am));
            tk_add(&c_shr, vdiff(ap, am, d) / vs2);
            if (lst == GA_OK) {
                TK_OK(ga_path_acceleration(&l.p, tk + 1e-6, ap));
                TK_OK(ga_path_acceleration(&l.p, tk - 1e-6, am));
                tk_add(&c_c1, vdiff(ap, am, d) / vs2);
            }
        }
    }
    tk_end(&c_pose);
    tk_end(&c_vel);
    tk_end(&c_acc);
    tk_end(&c_shr);
    tk_end(&c_lin);
    tk_end(&c_c1);
}

/* ---- 3. cga = matrix ----------------------------------------------------------------- */

static void test_cga_matrix(void)
{
    tk_check c_p = tk_begin("cga = matrix: poses, / scale", 1e-12);
    tk_check c_v = tk_begin("cga = matrix: body velocity, / vscale", 1e-12);
    tk_check c_a = tk_begin("cga = matrix: body acceleration, / vscale^2", 1e-12);
    tk_check c_s = tk_begin("cga = matrix: spatial velocity and acceleration, / (scale vscale^2)", 1e-12);
    for (int trial = 0; trial < 10; ++trial) {
        keyset k;
        random_keys(r, &ga_group_se3, &k, 4 + trial % 5, tk_range(r, -5, 5), tk_range(r, 0.1, 3.0));
        pathbuf bc, bm;
        if (mkpath(&bc, &ga_group_cga, GA_SCHEME_BSPLINE, &k) ||
            mkpath(&bm, &ga_group_se3, GA_SCHEME_BSPLINE, &k)) {
            tk_add(&c_p, INFINITY);
            continue;
        }
        double vs = vscale(&bm.p), vs2 = vs * vs, sc = 1.0, t0, t1;
        for (int i = 0; i < k.n; ++i) sc = fmax(sc, ga_mat4_norm1(k.m[i]));
        TK_OK(ga_path_range(&bm.p, &t0, &t1));
        for (int j = 0; j <= 40; ++j) {
            double t = j == 40 ? t1 : t0 + (t1 - t0) * j / 40.0, vc[6], ac[6], vm[6], am[6];
            tk_add(&c_p, mdiff(pose_at(&bc.p, t), pose_at(&bm.p, t)) / sc);
            TK_OK(ga_path_differentiate(&bc.p, t, GA_FRAME_BODY, vc, ac));
            TK_OK(ga_path_differentiate(&bm.p, t, GA_FRAME_BODY, vm, am));
            tk_add(&c_v, vdiff(vc, vm, 6) / vs);
            tk_add(&c_a, vdiff(ac, am, 6) / vs2);
            TK_OK(ga_path_differentiate(&bc.p, t, GA_FRAME_SPATIAL, vc, ac));
            TK_OK(ga_path_differentiate(&bm.p, t, GA_FRAME_SPATIAL, vm, am));
            tk_add(&c_s, fmax(vdiff(vc, vm, 6) / vs, vdiff(ac, am, 6) / vs2) / sc);
        }
    }
    tk_end(&c_p);
    tk_end(&c_v);
    tk_end(&c_a);
    tk_end(&c_s);
}

/* ---- 4. keys on one screw motion -------------------------------------------------------- */

static void test_screw(void)
{
    /* A_i = A_0 exp(i X): every d_i = X, and b_1 + b_2 + b_3 = 1 + u, so
     * A(t) = A_0 exp(((t - t_0)/h) X) on all of [t_1, t_{n-2}]: the keys
     * inside the range are hit, the velocity is X/h, the acceleration 0 */
    tk_check c_p = tk_begin("one screw: A(t) = A_0 exp((t - t_0)/h X), / scale", 1e-13);
    tk_check c_v = tk_begin("one screw: body velocity = X/h, / |X/h|", 1e-13);
    tk_check c_a = tk_begin("one screw: acceleration = 0, / |X/h|^2", 1e-13);
    for (int trial = 0; trial < 8; ++trial) {
        const ga_group *g = groups[trial % 2];
        keyset k;
        ga_twist xi = {rvec(r, 1.0), rvec(r, 1.5)};
        ga_mat4 a0 = ga_se3_exp((ga_twist){rvec(r, 1.5), rvec(r, 3.0)});
        double h = tk_range(r, 0.2, 2.0), x[6] = {xi.w.x, xi.w.y, xi.w.z, xi.v.x, xi.v.y, xi.v.z};
        random_keys(r, g, &k, 6, tk_range(r, -2, 2), h);
        for (int i = 0; i < k.n; ++i)
            k.m[i] = ga_mat4_mul(a0, ga_se3_exp((ga_twist){tk_scale(xi.w, i), tk_scale(xi.v, i)}));
        pathbuf b;
        if (mkpath(&b, g, GA_SCHEME_BSPLINE, &k) != GA_OK) {
            tk_add(&c_p, INFINITY);
            continue;
        }
        double sc = 1.0, xs = vnorm(x, 6) / h, t0, t1;
        for (int i = 0; i < k.n; ++i) sc = fmax(sc, ga_mat4_norm1(k.m[i]));
        TK_OK(ga_path_range(&b.p, &t0, &t1));
        for (int j = 0; j <= 30; ++j) {
            double t = j == 30 ? t1 : t0 + (t1 - t0) * j / 30.0, s = (t - k.t[0]) / h, v[6], a[6];
            ga_mat4 want = ga_mat4_mul(a0, ga_se3_exp((ga_twist){tk_scale(xi.w, s), tk_scale(xi.v, s)}));
            tk_add(&c_p, mdiff(pose_at(&b.p, t), want) / sc);
            TK_OK(ga_path_differentiate(&b.p, t, GA_FRAME_BODY, v, a));
            double xh[6];
            for (int i = 0; i < 6; ++i) xh[i] = x[i] / h;
            tk_add(&c_v, vdiff(v, xh, 6) / xs);
            tk_add(&c_a, vnorm(a, 6) / (xs * xs));
        }
    }
    tk_end(&c_p);
    tk_end(&c_v);
    tk_end(&c_a);
}

/* ---- 5. evaluators; local support ------------------------------------------------------- */

static void test_eval(void)
{
    tk_check c_ex = tk_begin("exact stepping = direct (2000 samples), / scale", 1e-12);
    tk_check c_eu = tk_begin("Euler error halves with the step (ratio in [1.6, 2.4])", 0);
    tk_check c_eu0 = tk_begin("Euler at step 1/256: error / scale", 1e-2);
    tk_check c_loc = tk_begin("one key more: the common range unchanged (bit for bit)", 0);
    for (int trial = 0; trial < 6; ++trial) {
        const ga_group *g = groups[trial % 3];
        keyset k;
        random_keys(r, g, &k, 7, tk_range(r, -2, 2), tk_range(r, 0.2, 2.0));
        pathbuf b, b2;
        if (mkpath(&b, g, GA_SCHEME_BSPLINE, &k) != GA_OK) {
            tk_add(&c_ex, INFINITY);
            continue;
        }
        double sc = 1.0, t0, t1;
        for (int i = 0; i < k.n; ++i) sc = fmax(sc, ga_mat4_norm1(k.m[i]));
        TK_OK(ga_path_range(&b.p, &t0, &t1));
        enum { NS = 2000 };
        static double ex[NS * 16], di[NS * 16];
        size_t es = g->elem_size / sizeof(double);
        int st = ga_path_sample_uniform(&b.p, GA_EVAL_EXACT, 1.0, NS, t0, t1, ex);
        st = st ? st : ga_path_sample_uniform(&b.p, GA_EVAL_DIRECT, 1.0, NS, t0, t1, di);
        double worst = st ? INFINITY : 0.0;
        for (size_t j = 0; !st && j < NS; ++j)
            worst = tk_max(worst, mdiff(g->to_mat4(ex + j * es), g->to_mat4(di + j * es)) / sc);
        tk_add(&c_ex, worst);
        double prev = NAN;
        for (double step = 1.0 / 64; step >= 1.0 / 512; step /= 2) {
            enum { NE = 61 };
            static double eu[NE * 16], dr[NE * 16];
            TK_OK(ga_path_sample_uniform(&b.p, GA_EVAL_EULER, step, NE, t0, t1, eu));
            TK_OK(ga_path_sample_uniform(&b.p, GA_EVAL_DIRECT, 1.0, NE, t0, t1, dr));
            double e = 0.0;
            for (size_t j = 0; j < NE; ++j)
                e = tk_max(e, mdiff(g->to_mat4(eu + j * es), g->to_mat4(dr + j * es)) / sc);
            if (!isnan(prev))
                tk_add_bool(&c_eu, prev / e >= 1.6 && prev / e <= 2.4);
            if (step == 1.0 / 256)
                tk_add(&c_eu0, e);
            prev = e;
        }
        /* local support: the path of the first 6 keys equals the first 7's
           on the 6's range */
        keyset k6 = k;
        k6.n = 6;
        if (mkpath(&b2, g, GA_SCHEME_BSPLINE, &k6) != GA_OK) {
            tk_add_bool(&c_loc, 0);
            continue;
        }
        double s0, s1;
        TK_OK(ga_path_range(&b2.p, &s0, &s1));
        for (int j = 0; j < 20; ++j) { /* s1 itself: a segment end here, a start there */
            double t = s0 + (s1 - s0) * j / 20.0, e1[16], e2[16], v1[12], v2[12], a1[12], a2[12];
            TK_OK(ga_path_eval(&b.p, t, e1));
            TK_OK(ga_path_eval(&b2.p, t, e2));
            TK_OK(ga_path_differentiate(&b.p, t, GA_FRAME_SPATIAL, v1, a1));
            TK_OK(ga_path_differentiate(&b2.p, t, GA_FRAME_SPATIAL, v2, a2));
            tk_add_bool(&c_loc, memcmp(e1, e2, g->elem_size) == 0 && memcmp(v1, v2, g->dim * 8) == 0 &&
                                    memcmp(a1, a2, g->dim * 8) == 0);
        }
    }
    tk_end(&c_ex);
    tk_end(&c_eu);
    tk_end(&c_eu0);
    tk_end(&c_loc);
}

/* ---- 6. range, spacing, errors ------------------------------------------------------------ */

static void test_errors(void)
{
    keyset k;
    pathbuf b;
    random_keys(r, &ga_group_se3, &k, 6, 10.0, 0.5);
    tk_expect(ga_scheme_min_keys(GA_SCHEME_BSPLINE) == 4, "bspline: at least 4 keys");
    ga_scheme s;
    tk_expect(ga_scheme_by_name("bspline", &s) == GA_OK && s == GA_SCHEME_BSPLINE &&
                  strcmp(ga_scheme_name(GA_SCHEME_BSPLINE), "bspline") == 0,
              "bspline: its name");
    for (int n = 2; n <= 3; ++n) {
        keyset kk = k;
        kk.n = n;
        tk_expect_status("bspline: 2 or 3 keys -> GA_ERR_ARG",
                         mkpath(&b, &ga_group_cga, GA_SCHEME_BSPLINE, &kk), GA_ERR_ARG);
    }
    tk_expect_status("bspline: 6 even keys -> ok", mkpath(&b, &ga_group_cga, GA_SCHEME_BSPLINE, &k), GA_OK);
    double t0 = 0, t1 = 0, e[16], v[6];
    TK_OK(ga_path_range(&b.p, &t0, &t1));
    tk_expect(t0 == k.t[1] && t1 == k.t[4] && ga_path_segments(&b.p) == 3,
              "bspline: range [t_1, t_{n-2}], n-3 segments");
    tk_expect_status("bspline: eval before t_1 -> GA_ERR_ARG", ga_path_eval(&b.p, k.t[1] - 1e-9, e),
                     GA_ERR_ARG);
    tk_expect_status("bspline: eval after t_{n-2} -> GA_ERR_ARG", ga_path_eval(&b.p, k.t[4] + 1e-9, e),
                     GA_ERR_ARG);
    tk_expect_status("bspline: velocity at t_0 -> GA_ERR_ARG", ga_path_velocity(&b.p, k.t[0], v), GA_ERR_ARG);
    tk_expect_status("bspline: eval at t_{n-2} -> ok", ga_path_eval(&b.p, k.t[4], e), GA_OK);
    tk_expect_status("bspline: segment n-3 -> GA_ERR_ARG", ga_path_eval_segment(&b.p, 3, 0.5, e), GA_ERR_ARG);
    tk_expect_status("bspline: segment 2 extrapolated to u = 1.5 -> ok",
                     ga_path_eval_segment(&b.p, 2, 1.5, e), GA_OK);
    double sm[3 * 8];
    tk_expect_status("bspline: samples from t_0 -> GA_ERR_ARG",
                     ga_path_sample_uniform(&b.p, GA_EVAL_DIRECT, 1.0, 3, k.t[0], k.t[4], sm), GA_ERR_ARG);
    /* approximating: the knot's pose is no key */
    TK_OK(ga_path_eval(&b.p, k.t[2], e));
    tk_expect(mdiff(ga_group_cga.to_mat4(e), k.m[2]) > 1e-3, "bspline: the key is not hit at its time");
    /* uneven times */
    keyset ku = k;
    ku.t[3] += 2e-9 * 0.5;
    tk_expect(ga_times_uneven(6, ku.t) == 3, "uneven: key 3 off by 2e-9 h is named");
    tk_expect_status("uneven: GA_ERR_ARG", mkpath(&b, &ga_group_cga, GA_SCHEME_BSPLINE, &ku), GA_ERR_ARG);
    ku = k;
    ku.t[3] += 0.5e-9 * 0.5;
    tk_expect(ga_times_uneven(6, ku.t) == 0, "uneven: key 3 off by 0.5e-9 h passes");
    ku = k;
    ku.t[5] += 0.1; /* the last key moves the grid: key 1 is the first off it */
    tk_expect(ga_times_uneven(6, ku.t) == 1, "uneven: the last key off: key 1 named");
    ku = k;
    ku.t[2] = NAN;
    tk_expect(ga_times_uneven(6, ku.t) == 2, "uneven: NaN is off");
    /* epoch times: 1.3e9 + i 0.01 as doubles are even to their rounding only */
    static double ep[2000];
    double worst = 0.0;
    for (int i = 0; i < 2000; ++i) ep[i] = 1305031102.1758 + 0.01 * i;
    for (int i = 0; i < 2000; ++i)
        worst = fmax(worst, fabs(ep[i] - (ep[0] + (ep[1999] - ep[0]) * i / 1999.0)));
    tk_expect(worst > 1e-9 * 0.01, "epoch: the doubles are uneven by more than 1e-9 of the spacing");
    tk_expect(ga_times_uneven(2000, ep) == 0, "epoch: 2000 keys at 1.3e9 + 0.01 i pass");
    ep[700] += 1e-5;
    tk_expect(ga_times_uneven(2000, ep) == 700, "epoch: one key off by 1e-3 of the spacing is named");
    /* one key: the constant path */
    keyset k1 = k;
    k1.n = 1;
    tk_expect_status("bspline: one key -> ok", mkpath(&b, &ga_group_se3, GA_SCHEME_BSPLINE, &k1), GA_OK);
    tk_expect_status("bspline: one key, eval at t_0", ga_path_eval(&b.p, k.t[0], e), GA_OK);
    tk_expect(mdiff(ga_group_se3.to_mat4(e), k.m[0]) == 0.0, "bspline: one key: the key");
    tk_expect(ga_path_workspace_size(&ga_group_cga, GA_SCHEME_BSPLINE, 6) > 0, "bspline: workspace size");
}

static const tk_section sections[] = {
    {"derivatives", test_derivatives, TK_STREAM},
    {"c2", test_c2, TK_STREAM},
    {"cga_matrix", test_cga_matrix, TK_STREAM},
    {"screw", test_screw, TK_STREAM},
    {"eval", test_eval, TK_STREAM},
    {"errors", test_errors, TK_STREAM},
    {"time", tk_cpu_time, TK_SETUP},
};

int main(int argc, char **argv) { return tk_main(argc, argv, "test_bspline", sections, TK_COUNT(sections)); }
