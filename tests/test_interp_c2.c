/* tests/test_interp_c2.c: the C2 schemes and the decoupled ones (c2,
 * decoupled, decoupled-c2; interp/path.h): through the keys, cga = matrix,
 * the derivatives against finite differences, C1 and C2 at the keys, the
 * motions they reproduce, spacings over six decades, affine refused.
 * Seeded (interp_kit.h), so every run is the same.
 */
#include "interp_kit.h"

static tk_rng stream;
static tk_rng *const r = &stream; /* helpers take it as r */

/* The checks of one segment i of a rigid path p (cga) against pm (matrix) on
 * keys k: through the keys (c_key), cga = matrix (c_cm), velocity and
 * acceleration against central differences (c_v, c_a) at u = 0, 1/4, ..., 1. */
static void seg_checks(const ga_path *p, const ga_path *pm, const keyset *k, int i, tk_check *c_key,
                       tk_check *c_cm, tk_check *c_v, tk_check *c_a)
{
    double sc = k->scale, sc2 = sc * sc;
    tk_add(c_key, fmax(mdiff(at_seg(p, i, 0.0), k->m[i]), mdiff(at_seg(p, i, 1.0), k->m[i + 1])) / sc);
    for (int q = 0; q <= 4; ++q) {
        double u = 0.25 * q, v[6], a[6], vm[6], am[6], vf[6], af[6];
        TK_OK(ga_path_differentiate_segment(p, (size_t)i, u, GA_FRAME_BODY, v, a));
        TK_OK(ga_path_differentiate_segment(pm, (size_t)i, u, GA_FRAME_BODY, vm, am));
        tk_add(c_cm, fmax(mdiff(at_seg(p, i, u), at_seg(pm, i, u)) / sc,
                          fmax(vdiff(v, vm, 6) / sc, vdiff(a, am, 6) / sc2)));
        fd_central(p, i, u, 1e-5, vf);
        fd_accel(p, i, u, GA_FRAME_BODY, 1e-4, af);
        tk_add(c_v, vdiff(v, vf, 6) / fmax(sc, vnorm(v, 6)));
        tk_add(c_a, vdiff(a, af, 6) / fmax(sc2, vnorm(a, 6)));
    }
}

/* ---- decoupled, decoupled-c2 ------------------------------------------------- */

/* Rotation and translation apart (path.h DECOUPLED, DECOUPLED_C2). scipy is
 * the reference of tests/scipy_check.py; here: the keys, cga = matrix, the
 * analytic derivatives against differences, C1 and C2 at the keys, the
 * cases with a known answer, affine refused. */
static void test_decoupled(void)
{
    stream = tk_rng_after(INTERP_SEED, 8939); /* after paths' keys, c1 and accel */
    const ga_scheme ds[2] = {GA_SCHEME_DECOUPLED, GA_SCHEME_DECOUPLED_C2};
    tk_check c_key = tk_begin("decoupled: through the keys (eval_segment at u = 0, 1), / scale", 1e-14);
    tk_check c_cm = tk_begin("decoupled: cga = matrix (pose, velocity, acceleration), / scale^2", 1e-12);
    tk_check c_v = tk_begin("decoupled: velocity = central FD of the pose (step 1e-5), / scale", 1e-8);
    tk_check c_a = tk_begin("decoupled: acceleration = central FD of velocity (step 1e-4), / scale^2", 1e-6);
    tk_check c_c1 = tk_begin("decoupled-c2: velocity continuous at keys, / scale", 1e-13);
    tk_check c_c2 = tk_begin("decoupled-c2: acceleration continuous at keys, / scale^2", 1e-11);
    tk_check c_jump = tk_begin_least("decoupled: its acceleration jumps at keys (C1 only): largest jump",
                                     1e-3);
    for (int trial = 0; trial < 16; ++trial) {
        keyset k;
        random_keys(r, &k, 2 + trial % 7, trial % 5 == 3 ? 4 : 0);
        for (int si = 0; si < 2; ++si) {
            pathbuf b, bm;
            /* a workspace full of NaN: the build defines every slot it checks
               (unwritten slopes and scratch once failed it as GA_ERR_DOMAIN) */
            for (int j = 0; j < WORK; ++j) b.work[j] = bm.work[j] = NAN;
            int st = mkpath(&b, &ga_group_cga, ds[si], &k, NULL),
                stm = mkpath(&bm, &ga_group_se3, ds[si], &k, NULL);
            if (st || stm) { /* a failure to build counts as an error */
                tk_add(&c_key, NAN);
                continue;
            }
            double sc = k.scale, sc2 = sc * sc, jump = 0.0;
            for (int i = 0; i + 1 < k.n; ++i) {
                seg_checks(&b.p, &bm.p, &k, i, &c_key, &c_cm, &c_v, &c_a);
                if (i + 2 < k.n) { /* key i + 1: arriving against leaving */
                    double v0[6], a0[6], v1[6], a1[6];
                    TK_OK(ga_path_differentiate_segment(&b.p, (size_t)i, 1.0, GA_FRAME_BODY, v0, a0));
                    TK_OK(ga_path_differentiate_segment(&b.p, (size_t)(i + 1), 0.0, GA_FRAME_BODY, v1, a1));
                    if (si == 1) {
                        tk_add(&c_c1, vdiff(v0, v1, 6) / fmax(sc, vnorm(v0, 6)));
                        tk_add(&c_c2, vdiff(a0, a1, 6) / fmax(sc2, vnorm(a0, 6)));
                    } else {
                        jump = fmax(jump, vdiff(a0, a1, 6));
                    }
                }
            }
            if (si == 0 && k.n > 2)
                tk_add(&c_jump, jump);
        }
    }
    tk_end(&c_key);
    tk_end(&c_cm);
    tk_end(&c_v);
    tk_end(&c_a);
    tk_end(&c_c1);
    tk_end(&c_c2);
    tk_end(&c_jump);

    /* known answers: (1) pure rotations (no translation): decoupled is the
     * screw path (slerp = the screw of a rotation about the origin);
     * (2) keys rotating at a constant rate about one axis, positions on a
     * cubic in t: decoupled-c2 reproduces both (the chord rates all equal w,
     * which solves the C2 system; not-a-knot reproduces cubics) */
    tk_check c_sl = tk_begin("decoupled = screw on rotations about the origin", 1e-14);
    tk_check c_ex = tk_begin("decoupled-c2: constant-rate rotation + cubic position reproduced, / scale",
                             1e-13);
    for (int trial = 0; trial < 6; ++trial) {
        keyset k, kc;
        random_keys(r, &k, 3 + trial, 0);
        for (int i = 0; i < k.n; ++i) k.m[i].m[3] = k.m[i].m[7] = k.m[i].m[11] = 0.0;
        set_scale(&k);
        pathbuf b, bs;
        for (int gi = 0; gi < 2; ++gi) {
            const ga_group *g = gi ? &ga_group_se3 : &ga_group_cga;
            int st = mkpath(&b, g, GA_SCHEME_DECOUPLED, &k, NULL) | mkpath(&bs, g, GA_SCHEME_SCREW, &k, NULL);
            for (int j = 0; j <= 40; ++j) {
                double t = tgrid(&k, j, 40); /* the last exactly t_{n-1} */
                tk_add(&c_sl, st ? NAN : mdiff(at(&b.p, t), at(&bs.p, t)));
            }
        }
        kc.n = 3 + trial;
        random_times(r, &kc);
        ga_vec3 u = tk_unit(r), c[4] = {rvec(r, 2), rvec(r, 2), rvec(r, 1), rvec(r, 0.5)};
        double w = tk_range(r, 0.2, 1.0); /* w h < pi: every chord is the principal log */
        for (int i = 0; i < kc.n; ++i) {
            double t = kc.t[i];
            ga_vec3 pos = {c[0].x + t * (c[1].x + t * (c[2].x + t * c[3].x)),
                           c[0].y + t * (c[1].y + t * (c[2].y + t * c[3].y)),
                           c[0].z + t * (c[1].z + t * (c[2].z + t * c[3].z))};
            kc.m[i] = rigid(u, w * t, pos);
        }
        set_scale(&kc);
        for (int gi = 0; gi < 2; ++gi) {
            const ga_group *g = gi ? &ga_group_se3 : &ga_group_cga;
            int st = mkpath(&b, g, GA_SCHEME_DECOUPLED_C2, &kc, NULL);
            for (int j = 0; j <= 40; ++j) {
                double t = tgrid(&kc, j, 40);
                ga_vec3 pos = {c[0].x + t * (c[1].x + t * (c[2].x + t * c[3].x)),
                               c[0].y + t * (c[1].y + t * (c[2].y + t * c[3].y)),
                               c[0].z + t * (c[1].z + t * (c[2].z + t * c[3].z))};
                ga_mat4 m = at(&b.p, t), x = rigid(u, w * t, pos);
                if (kc.n < 4) /* the line and the parabola: the rotation only */
                    m.m[3] = m.m[7] = m.m[11] = x.m[3] = x.m[7] = x.m[11] = 0.0;
                tk_add(&c_ex, st ? NAN : mdiff(m, x) / kc.scale);
            }
        }
    }
    tk_end(&c_sl);
    tk_end(&c_ex);

    /* rotation and translation apart: rigid groups only */
    tk_check c_aff = tk_begin("decoupled on affine: workspace 0, GA_ERR_ARG", 0);
    keyset k;
    affine_keys(r, &k, 3);
    for (int si = 0; si < 2; ++si) {
        pathbuf b;
        tk_add_bool(&c_aff, ga_path_workspace_size(&ga_group_affine, ds[si], 3) == 0);
        tk_add_status(&c_aff, mkpath(&b, &ga_group_affine, ds[si], &k, NULL), GA_ERR_ARG);
        tk_add_bool(&c_aff, strcmp(ga_scheme_name(ds[si]), si ? "decoupled-c2" : "decoupled") == 0);
    }
    tk_end(&c_aff);
}

/* ---- c2 --------------------------------------------------------------------------- */

/* One-sided second-order FD body acceleration from poses alone at (seg, u),
 * side sgn: y(s) = log(A^-1 A(t + s)) = v s + a s^2/2 + O(s^3) (the body
 * velocity ODE), so a ~ (-5 y(e) + 4 y(2e) - y(3e))/e^2, error O(e^2). */
static void fd_accel_pose(const ga_path *p, int seg, double u, int sgn, double eps, double *a)
{
    const ga_group *g = p->group;
    double m0[16], m[16], y[3][12], h = p->t[seg + 1] - p->t[seg];
    TK_OK(ga_path_eval_segment(p, (size_t)seg, u, m0));
    for (int j = 0; j < 3; ++j) {
        TK_OK(ga_path_eval_segment(p, (size_t)seg, u + sgn * (j + 1) * eps / h, m));
        body_log(g, m0, m, y[j]);
    }
    for (size_t i = 0; i < g->dim; ++i) a[i] = (-5 * y[0][i] + 4 * y[1][i] - y[2][i]) / (eps * eps);
}

/* C2 and DECOUPLED_C2 on spacings log-uniform in [1e-3, 1e3] (neighbours
 * up to 1e6 apart) next to rotations up to pi, where Newton's sweeps alone stall
 * (on these 300 sets of 3 to 8 keys, seeded, they failed on 3: the solver's
 * continuation, path.c c2_solve, builds them): every set builds, passes
 * through its keys, and is C1 and C2 at every key (analytic, relative). */
static void test_c2_uneven(void)
{
    tk_rng r = {5};
    const ga_scheme sc[2] = {GA_SCHEME_DECOUPLED_C2, GA_SCHEME_C2};
    tk_check c_init = tk_begin("c2, decoupled-c2: spacings in [1e-3, 1e3], angles up to pi: build", 0);
    tk_check c_key = tk_begin("... through the keys, / (1 + |p|)", 1e-13);
    tk_check c_c1 = tk_begin("... velocity continuous at keys, / (rate scale (1 + |w| h))", 4e-15);
    tk_check c_c2 = tk_begin("... acceleration continuous at keys, / (its scale (1 + |w| h))", 4e-15);
    for (int set = 0; set < 300; ++set) {
        keyset k;
        k.n = 3 + (int)(tk_next(&r) % (MAXK - 2));
        k.t[0] = 0.0;
        for (int i = 0; i < k.n; ++i) {
            if (i)
                k.t[i] = k.t[i - 1] + tk_loguni(&r, 1e-3, 1e3 * (1 + 1e-12));
            ga_vec3 u = tk_unit(&r);
            ga_twist x = {tk_scale(u, tk_range(&r, 0, TK_PI)), {0, 0, 0}};
            k.m[i] = ga_se3_exp(x);
            k.m[i].m[3] = tk_range(&r, -1, 1);
            k.m[i].m[7] = tk_range(&r, -1, 1);
            k.m[i].m[11] = tk_range(&r, -1, 1);
        }
        for (int q = 0; q < 2; ++q) {
            pathbuf b;
            int st = mkpath(&b, &ga_group_se3, sc[q], &k, NULL);
            tk_add_status(&c_init, st, GA_OK);
            if (st)
                continue;
            for (int i = 0; i < k.n; ++i) {
                ga_mat4 m = at(&b.p, k.t[i]);
                double e = 0, big = 1;
                for (int j = 0; j < 16; ++j) {
                    e = fmax(e, fabs(m.m[j] - k.m[i].m[j]));
                    big = fmax(big, fabs(k.m[i].m[j]));
                }
                tk_add(&c_key, e / big);
            }
            /* the scales the rounding is relative to: the largest rate |w|
               (the solver converges relative to it), at each key the two
               segments' chord rates |theta|/h and |theta|/h^2, and |w|^2 for
               the acceleration (N is quadratic in the rate) */
            double wbig = 1.0, th[MAXK];
            for (int i = 0; i < k.n; ++i) {
                double v[6], a[6];
                TK_OK(ga_path_differentiate_segment(&b.p, (size_t)(i + 1 < k.n ? i : i - 1),
                                                    i + 1 < k.n ? 0.0 : 1.0, GA_FRAME_BODY, v, a));
                wbig = fmax(wbig, vnorm(v, 6));
                ga_twist x;
                if (i + 1 < k.n && ga_se3_log(ga_mat4_mul(ga_se3_inverse(k.m[i]), k.m[i + 1]), &x) == GA_OK)
                    th[i] = sqrt(x.w.x * x.w.x + x.w.y * x.w.y + x.w.z * x.w.z + x.v.x * x.v.x +
                                 x.v.y * x.v.y + x.v.z * x.v.z);
            }
            for (int i = 0; i + 2 < k.n; ++i) {
                double v0[6], a0[6], v1[6], a1[6], hl = k.t[i + 1] - k.t[i], hr = k.t[i + 2] - k.t[i + 1];
                TK_OK(ga_path_differentiate_segment(&b.p, (size_t)i, 1.0, GA_FRAME_BODY, v0, a0));
                TK_OK(ga_path_differentiate_segment(&b.p, (size_t)i + 1, 0.0, GA_FRAME_BODY, v1, a1));
                double sv = fmax(wbig, fmax(th[i] / hl, th[i + 1] / hr));
                double sa = fmax(fmax(wbig / hl, wbig / hr), fmax(th[i] / (hl * hl), th[i + 1] / (hr * hr)));
                sa = fmax(sa, wbig * wbig);
                /* the cubic x(tau) = a tau + b tau^2 + c tau^3 reaches theta at
                   tau = h through terms of size |w| h: x(h), and so J_r(x(h))
                   and the velocity there, carry an error of eps |w| h */
                double grow = 1.0 + wbig * fmax(hl, hr);
                tk_add(&c_c1, vdiff(v0, v1, 6) / (sv * grow));
                tk_add(&c_c2, vdiff(a0, a1, 6) / (sa * grow));
            }
        }
    }
    tk_end(&c_init);
    tk_end(&c_key);
    tk_end(&c_c1);
    tk_end(&c_c2);
}

/* C2 (path.h): through the keys, cga = matrix, analytic derivatives against
 * differences, C1 and C2 at the keys (analytic, and the FD acceleration gap
 * falling with the step, where lihao3's stays), keys on one screw motion
 * reproduced, affine refused. */
static void test_c2(void)
{
    const ga_group *gs[2] = {&ga_group_cga, &ga_group_se3};
    tk_check c_init = tk_begin("c2: path init (random keys, spacings 0.2..3)", 0);
    tk_check c_key = tk_begin("c2: through the keys (eval_segment at u = 0, 1), / scale", 1e-14);
    tk_check c_cm = tk_begin("c2: cga = matrix (pose, velocity, acceleration), / scale^2", 1e-12);
    tk_check c_v = tk_begin("c2: velocity = central FD of the pose (step 1e-5), / scale", 1e-8);
    tk_check c_a = tk_begin("c2: acceleration = central FD of velocity (step 1e-4), / scale^2", 1e-6);
    tk_check c_c1 = tk_begin("c2: velocity continuous at keys (analytic), / scale", 1e-13);
    tk_check c_c2 = tk_begin("c2: acceleration continuous at keys (analytic), / scale^2", 1e-11);
    /* the one-sided FD accelerations from the two sides differ by the jump
       plus c h^2 (second-order differences): extrapolated from h = 1e-3 and
       2e-4, D = (25 d(2e-4) - d(1e-3)) / 24 is the jump to O(h^4) plus the
       rounding, about 4 eps / h^2 = 2.2e-8 of the scale at 2e-4 */
    tk_check c_gap = tk_begin("c2: FD acceleration jump from the poses, extrapolated to h = 0, / scale^2",
                              1e-6);
    tk_check c_fall = tk_begin("c2: that FD gap falls ~eps^2 (20x for 5x; or <= 1e-7)", 0);
    tk_check c_l3 = tk_begin_least("lihao3: its FD acceleration gap does not fall (C1 only): gap at 2e-4",
                                   1e-3);
    double worst[2] = {0, 0}, ratio = 1e300, l3[2] = {1e300, 1e300};
    for (int trial = 0; trial < 16; ++trial) {
        keyset k;
        random_keys(r, &k, 2 + trial % 7, trial % 5 == 3 ? 4 : 0);
        pathbuf b, bm, bl;
        int st = mkpath(&b, &ga_group_cga, GA_SCHEME_C2, &k, NULL),
            stm = mkpath(&bm, &ga_group_se3, GA_SCHEME_C2, &k, NULL),
            stl = mkpath(&bl, &ga_group_se3, GA_SCHEME_LIHAO3, &k, NULL);
        tk_add_status(&c_init, st, GA_OK);
        tk_add_status(&c_init, stm, GA_OK);
        if (st || stm || stl)
            continue;
        double sc = k.scale, sc2 = sc * sc;
        for (int i = 0; i + 1 < k.n; ++i) {
            seg_checks(&b.p, &bm.p, &k, i, &c_key, &c_cm, &c_v, &c_a);
            if (i + 2 < k.n) { /* key i + 1: arriving against leaving */
                double v0[6], a0[6], v1[6], a1[6];
                TK_OK(ga_path_differentiate_segment(&bm.p, (size_t)i, 1.0, GA_FRAME_BODY, v0, a0));
                TK_OK(ga_path_differentiate_segment(&bm.p, (size_t)(i + 1), 0.0, GA_FRAME_BODY, v1, a1));
                double as = fmax(sc2, vnorm(a0, 6));
                tk_add(&c_c1, vdiff(v0, v1, 6) / fmax(sc, vnorm(v0, 6)));
                tk_add(&c_c2, vdiff(a0, a1, 6) / as);
                /* from the poses alone: the one-sided FD accelerations from
                   both sides at steps 1e-3 and 2e-4 */
                double eps[2] = {1e-3, 2e-4}, gap[2], gl[2], d[2][6];
                for (int e = 0; e < 2; ++e) {
                    double fl[6], fr[6];
                    fd_accel_pose(&bm.p, i, 1.0, -1, eps[e], fl);
                    fd_accel_pose(&bm.p, i + 1, 0.0, +1, eps[e], fr);
                    for (int j = 0; j < 6; ++j) d[e][j] = fl[j] - fr[j];
                    gap[e] = vdiff(fl, fr, 6) / as;
                    worst[e] = fmax(worst[e], gap[e]);
                    fd_accel_pose(&bl.p, i, 1.0, -1, eps[e], fl);
                    fd_accel_pose(&bl.p, i + 1, 0.0, +1, eps[e], fr);
                    gl[e] = vdiff(fl, fr, 6);
                    l3[e] = fmin(l3[e], gl[e]);
                }
                double jump[6];
                for (int j = 0; j < 6; ++j) jump[j] = (25 * d[1][j] - d[0][j]) / 24;
                tk_add(&c_gap, vnorm(jump, 6) / as);
                tk_add_bool(&c_fall, gap[1] <= 1e-7 || gap[0] >= 20 * gap[1]);
                ratio = fmin(ratio, gap[1] > 1e-7 ? gap[0] / gap[1] : 25);
                tk_add(&c_l3, gl[1]);
            }
        }
    }
    tk_end(&c_init);
    tk_end(&c_key);
    tk_end(&c_cm);
    tk_end(&c_v);
    tk_end(&c_a);
    tk_end(&c_c1);
    tk_end(&c_c2);
    tk_end(&c_gap);
    tk_end(&c_fall);
    tk_note(
        "     c2 FD acceleration gap / scale^2, step 1e-3: %.3g   step 2e-4: %.3g  (smallest fall %.1fx)\n",
        worst[0], worst[1], ratio);
    tk_end(&c_l3);
    tk_note("     lihao3 FD acceleration gap, smallest at step 1e-3: %.3g   at 2e-4: %.3g\n", l3[0], l3[1]);

    /* keys on one screw motion exp(t xi) (|w| h < pi, so every relative log
       is t xi's): the constant velocity solves the C2 system, so c2 is that
       motion, its velocity xi and its acceleration 0 */
    tk_check c_sc = tk_begin("c2: keys on one screw motion reproduced, / scale", 1e-13);
    tk_check c_scv = tk_begin("c2: ... its velocity xi, acceleration 0, / scale^2", 1e-13);
    for (int trial = 0; trial < 8; ++trial) {
        keyset k;
        ga_twist xi = screw_keys(r, &k, 2 + trial % 7, 2.0);
        double x6[6] = {xi.w.x, xi.w.y, xi.w.z, xi.v.x, xi.v.y, xi.v.z};
        for (int gi = 0; gi < 2; ++gi) {
            pathbuf b;
            int st = mkpath(&b, gs[gi], GA_SCHEME_C2, &k, NULL);
            for (int j = 0; j <= 40; ++j) {
                double t = tgrid(&k, j, 40), v[6], a[6];
                ga_twist x = {tk_scale(xi.w, t), tk_scale(xi.v, t)};
                tk_add(&c_sc, st ? NAN : mdiff(at(&b.p, t), ga_se3_exp(x)) / k.scale);
                if (st || ga_path_differentiate(&b.p, t, GA_FRAME_BODY, v, a))
                    v[0] = NAN;
                tk_add(&c_scv, fmax(vdiff(v, x6, 6), vnorm(a, 6)) / (k.scale * k.scale));
            }
        }
    }
    tk_end(&c_sc);
    tk_end(&c_scv);

    /* screw motions: rigid groups only */
    tk_check c_aff = tk_begin("c2 on affine: workspace 0, GA_ERR_ARG; the name", 0);
    keyset k;
    affine_keys(r, &k, 3);
    pathbuf b;
    ga_scheme sc;
    tk_add_bool(&c_aff, ga_path_workspace_size(&ga_group_affine, GA_SCHEME_C2, 3) == 0);
    tk_add_status(&c_aff, mkpath(&b, &ga_group_affine, GA_SCHEME_C2, &k, NULL), GA_ERR_ARG);
    tk_add_bool(&c_aff, strcmp(ga_scheme_name(GA_SCHEME_C2), "c2") == 0 &&
                            ga_scheme_by_name("c2", &sc) == GA_OK && sc == GA_SCHEME_C2);
    tk_end(&c_aff);
}

static const tk_section sections[] = {
    {"decoupled", test_decoupled, TK_STREAM},
    {"c2", test_c2, 0},
    {"c2_uneven", test_c2_uneven, 0},
    {"time", tk_cpu_time, TK_SETUP},
};

int main(int argc, char **argv)
{
    return tk_main(argc, argv, "test_interp_c2", sections, TK_COUNT(sections));
}
