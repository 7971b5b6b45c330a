/* tests/test_interp_extrap.c: a path at times outside its range
 * (path.h, ga_path_extrap_*; interp/extrap.c), each mode against what the
 * header promises, computed here independently: before the first key and
 * after the last, the mode's closed form built from the keys with SE(3)'s
 * matrix functions (hold: the end key; extend: the end segment's formula,
 * written out for screw, lihao3 and bspline; constant velocity: E exp(d V)
 * with E the end key and V its end chord for the schemes whose end
 * velocity is that chord), the derivatives against those closed forms and
 * against finite differences in every frame; inside the range the path's
 * own bits; the refusals, one key, far times. Near-duplicate keys, merging
 * and the growth rule's words: tests/test_interp_keys.c. Seeded
 * (testkit.h), so every run is the same.
 */
#include "interp_kit.h"

static tk_rng stream;
static tk_rng *const r = &stream;

static const char *const frame_name[3] = {"body", "spatial", "world"};

/* ---- twists and SE(3) closed forms (matrices, mat4.h) --------------------- */

static ga_twist tw_lin(double a, ga_twist x, double b, ga_twist y)
{
    ga_twist z;
    z.w = (ga_vec3){a * x.w.x + b * y.w.x, a * x.w.y + b * y.w.y, a * x.w.z + b * y.w.z};
    z.v = (ga_vec3){a * x.v.x + b * y.v.x, a * x.v.y + b * y.v.y, a * x.v.z + b * y.v.z};
    return z;
}
static void tw_put(ga_twist x, double *d)
{
    d[0] = x.w.x, d[1] = x.w.y, d[2] = x.w.z, d[3] = x.v.x, d[4] = x.v.y, d[5] = x.v.z;
}
static ga_twist tw_get(const double *d) { return (ga_twist){{d[0], d[1], d[2]}, {d[3], d[4], d[5]}}; }

/* log(a^-1 b), the body displacement from a to b (NaN if the log fails) */
static ga_twist rel_log(ga_mat4 a, ga_mat4 b)
{
    ga_twist x;
    if (ga_se3_log(ga_mat4_mul(ga_se3_inverse(a), b), &x) != GA_OK)
        x = (ga_twist){{NAN, NAN, NAN}, {NAN, NAN, NAN}};
    return x;
}
static ga_mat4 exp_tw(double s, ga_twist x) { return ga_se3_exp(tw_lin(s, x, 0.0, x)); }

/* the chord s_i = log(A_i^-1 A_{i+1}) / h_i */
static ga_twist chord(const keyset *k, int i)
{
    ga_twist x = rel_log(k->m[i], k->m[i + 1]);
    return tw_lin(1.0 / (k->t[i + 1] - k->t[i]), x, 0.0, x);
}

/* lihao3's default velocity at key i (path.h) */
static ga_twist lihao3_vel(const keyset *k, int i)
{
    if (i == 0)
        return chord(k, 0);
    if (i == k->n - 1)
        return chord(k, k->n - 2);
    double h0 = k->t[i] - k->t[i - 1], h1 = k->t[i + 1] - k->t[i];
    return tw_lin(h1 / (h0 + h1), chord(k, i - 1), h0 / (h0 + h1), chord(k, i));
}

/* The segment the extension continues at t (before the range: the first,
 * after: the last) and its u, bspline's segments being [t_{s+1}, t_{s+2}]. */
static int end_segment(const keyset *k, ga_scheme s, double t, double *u)
{
    int off = s == GA_SCHEME_BSPLINE, last = s == GA_SCHEME_BSPLINE ? k->n - 4 : k->n - 2;
    int seg = t > k->t[k->n - 1 - off] ? last : 0;
    *u = (t - k->t[seg + off]) / (k->t[seg + off + 1] - k->t[seg + off]);
    return seg;
}

/* bspline's segment seg at u: A_s exp(b1 d1) exp(b2 d2) exp(b3 d3) */
static ga_mat4 bspline_at(const keyset *k, int seg, double u)
{
    double b[3] = {(5 + 3 * u - 3 * u * u + u * u * u) / 6, (1 + 3 * u + 3 * u * u - 2 * u * u * u) / 6,
                   u * u * u / 6};
    ga_mat4 m = k->m[seg];
    for (int j = 0; j < 3; ++j) m = ga_mat4_mul(m, exp_tw(b[j], rel_log(k->m[seg + j], k->m[seg + j + 1])));
    return m;
}

/* EXTEND's closed form at t outside the range: the end segment's formula
   continued (screw, lihao3 with default velocities, bspline) */
static ga_mat4 extend_closed(const keyset *k, ga_scheme s, double t)
{
    double u;
    int i = end_segment(k, s, t, &u);
    if (s == GA_SCHEME_BSPLINE)
        return bspline_at(k, i, u);
    double h = k->t[i + 1] - k->t[i];
    ga_twist B = rel_log(k->m[i], k->m[i + 1]);
    if (s == GA_SCHEME_SCREW)
        return ga_mat4_mul(k->m[i], exp_tw(u, B));
    /* lihao3: B = h V_i, C = log(exp(-B) A_i^-1 A_{i+1}),
       D = h V_{i+1} - Ad_{(A_i^-1 A_{i+1})^-1} B - 2 C */
    ga_mat4 rel = ga_mat4_mul(ga_se3_inverse(k->m[i]), k->m[i + 1]);
    B = tw_lin(h, lihao3_vel(k, i), 0.0, B);
    ga_twist C;
    if (ga_se3_log(ga_mat4_mul(exp_tw(-1.0, B), rel), &C) != GA_OK)
        C = (ga_twist){{NAN, NAN, NAN}, {NAN, NAN, NAN}};
    ga_twist D = tw_lin(h, lihao3_vel(k, i + 1), -1.0, ga_se3_adjoint(ga_se3_inverse(rel), B));
    D = tw_lin(1.0, D, -2.0, C);
    return ga_mat4_mul(ga_mat4_mul(ga_mat4_mul(k->m[i], exp_tw(u, B)), exp_tw(u * u, C)),
                       exp_tw(u * u * u - u * u, D));
}

/* HOLD's closed form: the range's end pose (the end key; bspline's pose at
   t_1 or t_{n-2}) */
static ga_mat4 hold_closed(const keyset *k, ga_scheme s, double t)
{
    if (s == GA_SCHEME_BSPLINE)
        return t > k->t[k->n - 2] ? bspline_at(k, k->n - 4, 1.0) : bspline_at(k, 0, 0.0);
    return t > k->t[k->n - 1] ? k->m[k->n - 1] : k->m[0];
}

/* ---- keys and paths --------------------------------------------------------- */

/* n keys at random times (even for bspline), each the last moved by a
   rotation of 0.1..1.5 rad and a translation of up to 2: every relative log
   is far from a half turn. */
static void chain_keys(keyset *k, int n, int even)
{
    k->n = n;
    random_times(r, k);
    if (even) {
        double h = tk_range(r, 0.3, 2.0);
        for (int i = 1; i < n; ++i) k->t[i] = k->t[0] + h * i;
    }
    k->m[0] = rand_rigid(r, 0.0, PI, 3.0);
    for (int i = 1; i < n; ++i) {
        ga_mat4 d = rand_rigid(r, 0.1, 1.5, 2.0);
        k->m[i] = mmul(k->m[i - 1], d);
    }
    set_scale(k);
}

static void keys_for(ga_scheme s, int affine, keyset *k)
{
    int n = s == GA_SCHEME_QUADRATIC ? 3 : 5;
    if (affine) {
        affine_keys(r, k, n);
        if (s == GA_SCHEME_BSPLINE)
            for (int i = 1; i < n; ++i) k->t[i] = k->t[0] + 0.7 * i;
    } else
        chain_keys(k, n, s == GA_SCHEME_BSPLINE);
}

static ga_mat4 nan_mat(void)
{
    ga_mat4 z;
    for (int i = 0; i < 16; ++i) z.m[i] = NAN;
    return z;
}
/* the extrapolated pose at t as a matrix; NaN where the call fails */
static ga_mat4 xat(const ga_path_extrap *x, double t)
{
    double e[GA_GROUP_MAX_ELEM];
    return ga_path_extrap_eval(x, t, e) == GA_OK ? x->path->group->to_mat4(e) : nan_mat();
}
/* derivative of order o (1..3) at t in frame f, asked alone; NaN on failure */
static void xderiv(const ga_path_extrap *x, double t, ga_frame f, int o, double *d)
{
    if (ga_path_extrap_derivatives(x, t, f, o == 1 ? d : NULL, o == 2 ? d : NULL, o == 3 ? d : NULL))
        for (size_t i = 0; i < x->path->group->dim; ++i) d[i] = NAN;
}

/* The velocity in frame f from the extrapolated poses at t +- e (central
 * difference of the matrices): body vee(M^-1 M'), spatial vee(M' M^-1),
 * world (the angular part of spatial, then p'); affine: the 3x4 of those. */
static void fd_pose_vel(const ga_path_extrap *x, double t, ga_frame f, double e, double *v)
{
    ga_mat4 M = xat(x, t), P = xat(x, t + e), Q = xat(x, t - e), D, Mi, X;
    for (int i = 0; i < 16; ++i) D.m[i] = (P.m[i] - Q.m[i]) / (2 * e);
    if (ga_mat4_inverse(M, &Mi) != GA_OK)
        Mi = nan_mat();
    X = f == GA_FRAME_BODY ? ga_mat4_mul(Mi, D) : ga_mat4_mul(D, Mi);
    if (!x->path->group->rigid) {
        for (int i = 0; i < 12; ++i) v[i] = X.m[i];
        return;
    }
    v[0] = 0.5 * (X.m[9] - X.m[6]);
    v[1] = 0.5 * (X.m[2] - X.m[8]);
    v[2] = 0.5 * (X.m[4] - X.m[1]);
    for (int i = 0; i < 3; ++i) v[3 + i] = f == GA_FRAME_WORLD ? D.m[4 * i + 3] : X.m[4 * i + 3];
}

/* the times outside the range a case samples: 0.05 to 1.5 times the end
   segment's length out, alternately before the start and after the end */
static void outside_times(const ga_path_extrap *x, double *ts, int n)
{
    size_t m = ga_path_segments(x->path);
    double a0, a1, b0, b1;
    TK_OK(ga_path_segment_range(x->path, 0, &a0, &a1));
    TK_OK(ga_path_segment_range(x->path, m - 1, &b0, &b1));
    for (int i = 0; i < n; ++i) {
        double d = tk_range(r, 0.05, 1.5);
        ts[i] = i % 2 ? x->r1 + d * (b1 - b0) : x->r0 - d * (a1 - a0);
    }
}

static double pose_tol(const keyset *k, ga_mat4 ref, double rel) { return rel * fmax(k->scale, tnorm(ref)); }

/* ---- sections -------------------------------------------------------------- */

static void names(void)
{
    tk_check c = tk_begin("extrap: the names and ga_extrap_by_name round trip", 0);
    static const char *const want[] = {"error", "hold", "extend", "constant-velocity"};
    for (int m = 0; m < 4; ++m) {
        ga_extrap e = (ga_extrap)7;
        tk_add_bool(&c, strcmp(ga_extrap_name((ga_extrap)m), want[m]) == 0);
        tk_add_bool(&c, ga_extrap_by_name(want[m], &e) == GA_OK && e == (ga_extrap)m);
    }
    tk_end(&c);
    ga_extrap e = GA_EXTRAP_HOLD;
    tk_check s = tk_begin("extrap: an unknown name -> GA_ERR_ARG", 0);
    tk_add_status(&s, ga_extrap_by_name("wrap", &e), GA_ERR_ARG);
    tk_add_status(&s, ga_extrap_by_name("Hold", &e), GA_ERR_ARG);
    tk_add_status(&s, ga_extrap_by_name("", &e), GA_ERR_ARG);
    tk_end(&s);
}

/* Every group, scheme and mode: inside the range the path's own bits (pose
 * and derivatives), outside the mode's closed form and its derivatives. */
static void extrap_paths(void)
{
    tk_check in_pose = tk_begin("extrap: inside the range, ga_path_eval's bits (every mode)", 0);
    tk_check in_der = tk_begin("extrap: inside the range, ga_path_derivatives' bits (every mode, frame)", 0);
    tk_check err_st = tk_begin("extrap: ERROR outside -> GA_ERR_ARG (pose and derivatives)", 0);
    tk_check hold_p = tk_begin("extrap: HOLD = the end key (bspline: the range's end pose), / scale", 0);
    tk_check hold_b = tk_begin("extrap: HOLD = ga_path_eval at the range's end, bit for bit", 0);
    tk_check hold_d = tk_begin("extrap: HOLD velocity, acceleration, jerk exactly 0 (every frame)", 0);
    tk_check ext_c = tk_begin("extrap: EXTEND = screw/lihao3/bspline end segment continued, / scale", 0);
    tk_check ext_s = tk_begin("extrap: EXTEND = ga_path_eval_segment at the end segment's u (status, bits)",
                              0);
    tk_check ext_d = tk_begin("extrap: EXTEND derivatives = ga_path_derivatives_segment's (status, bits)", 0);
    tk_check cv_c = tk_begin("extrap: CONSTANT_VELOCITY = E exp(d V), E key, V end chord, / scale", 0);
    tk_check cv_g = tk_begin("extrap: CONSTANT_VELOCITY = E exp(d V), E, V the path's at the end", 0);
    tk_check cv_v = tk_begin("extrap: CONSTANT_VELOCITY body velocity = V, bit for bit", 0);
    tk_check cv_s = tk_begin("extrap: CONSTANT_VELOCITY spatial velocity = Ad_E V", 0);
    tk_check cv_w = tk_begin("extrap: CONSTANT_VELOCITY world: R w, R v, R(w x v), R(w x (w x v))", 0);
    tk_check cv_0 = tk_begin("extrap: CONSTANT_VELOCITY body/spatial acceleration, jerk exactly 0", 0);
    tk_check nul = tk_begin("extrap: derivatives with outputs left NULL, the same bits", 0);
    int skipped = 0;
    tk_check fd[3][3];
    for (int f = 0; f < 3; ++f)
        for (int o = 0; o < 3; ++o)
            fd[f][o] = tk_beginf(0, "extrap: %s %s outside vs central differences", frame_name[f],
                                 o == 0   ? "velocity (poses)"
                                 : o == 1 ? "acceleration"
                                          : "jerk");
    for (size_t gi = 0; ga_group_nth(gi); ++gi) {
        const ga_group *g = ga_group_nth(gi);
        int affine = !g->rigid;
        for (int s = 0; s < GA_SCHEME_COUNT; ++s) {
            if (!ga_path_workspace_size(g, (ga_scheme)s, 5))
                continue;
            for (int rep = 0; rep < 3; ++rep) {
                keyset k;
                keys_for((ga_scheme)s, affine, &k);
                pathbuf pb;
                if (mkpath(&pb, g, (ga_scheme)s, &k, NULL) != GA_OK) {
                    tk_add_bool(&in_pose, 0);
                    continue;
                }
                const ga_path *p = &pb.p;
                size_t dim = g->dim;
                ga_path_extrap x[4];
                for (int m = 0; m < 4; ++m) TK_OK(ga_path_extrap_init(p, (ga_extrap)m, &x[m]));
                ga_path_growth gr;
                TK_OK(ga_path_measure_growth(p, &gr));
                int wild = gr.first < p->n;
                skipped += wild;
                /* inside: the ends, the keys, random times */
                double tin[12];
                int nin = 0;
                tin[nin++] = x[0].r0;
                tin[nin++] = x[0].r1;
                for (int i = 0; i < k.n; ++i)
                    if (k.t[i] >= x[0].r0 && k.t[i] <= x[0].r1)
                        tin[nin++] = k.t[i];
                while (nin < 12) tin[nin++] = tk_range(r, x[0].r0, x[0].r1);
                for (int m = 0; m < 4; ++m)
                    for (int i = 0; i < nin; ++i) {
                        double a[16], b[16];
                        int sa = ga_path_extrap_eval(&x[m], tin[i], a), sb = ga_path_eval(p, tin[i], b);
                        tk_add_bool(&in_pose, sa == GA_OK && sb == GA_OK && !memcmp(a, b, g->elem_size));
                        for (int f = 0; f < (affine ? 2 : 3); ++f) {
                            double d1[3][12], d2[3][12];
                            memset(d1, 0, sizeof d1);
                            memset(d2, 0, sizeof d2);
                            sa = ga_path_extrap_derivatives(&x[m], tin[i], (ga_frame)f, d1[0], d1[1], d1[2]);
                            sb = ga_path_derivatives(p, tin[i], (ga_frame)f, d2[0], d2[1], d2[2]);
                            tk_add_bool(&in_der, sa == GA_OK && sb == GA_OK && !memcmp(d1, d2, sizeof d1));
                        }
                    }
                double tout[8];
                outside_times(&x[0], tout, 8);
                for (int i = 0; i < 8; ++i) {
                    double t = tout[i], e[16], d[3][12];
                    int after = t > x[0].r1;
                    /* ERROR */
                    tk_add_status(&err_st, ga_path_extrap_eval(&x[0], t, e), GA_ERR_ARG);
                    tk_add_status(&err_st,
                                  ga_path_extrap_derivatives(&x[0], t, GA_FRAME_BODY, d[0], d[1], d[2]),
                                  GA_ERR_ARG);
                    /* HOLD */
                    ga_mat4 H = xat(&x[1], t);
                    if (!affine) {
                        ga_mat4 ref = hold_closed(&k, (ga_scheme)s, t);
                        tk_add_tol(&hold_p, mdiff(H, ref), pose_tol(&k, ref, 1e-13));
                    }
                    double end[16];
                    TK_OK(ga_path_eval(p, after ? x[0].r1 : x[0].r0, end));
                    tk_add_bool(&hold_b,
                                ga_path_extrap_eval(&x[1], t, e) == GA_OK && !memcmp(e, end, g->elem_size));
                    for (int f = 0; f < (affine ? 2 : 3); ++f) {
                        for (int q = 0; q < 3; ++q)
                            for (size_t c = 0; c < dim; ++c) d[q][c] = NAN;
                        int st = ga_path_extrap_derivatives(&x[1], t, (ga_frame)f, d[0], d[1], d[2]);
                        int zero = st == GA_OK;
                        for (int q = 0; q < 3; ++q)
                            for (size_t c = 0; c < dim; ++c) zero &= d[q][c] == 0.0;
                        tk_add_bool(&hold_d, zero);
                    }
                    /* EXTEND */
                    double u;
                    int seg = end_segment(&k, (ga_scheme)s, t, &u);
                    ga_mat4 X = xat(&x[2], t);
                    if (!affine &&
                        (s == GA_SCHEME_SCREW || s == GA_SCHEME_LIHAO3 || s == GA_SCHEME_BSPLINE)) {
                        ga_mat4 ref = extend_closed(&k, (ga_scheme)s, t);
                        tk_add_tol(&ext_c, mdiff(X, ref), pose_tol(&k, ref, 1e-12));
                    }
                    double es[16];
                    int sx = ga_path_extrap_eval(&x[2], t, e),
                        ss = ga_path_eval_segment(p, (size_t)seg, u, es);
                    tk_add_bool(&ext_s, sx == ss && (sx != GA_OK || !memcmp(e, es, g->elem_size)));
                    for (int f = 0; f < (affine ? 2 : 3); ++f) {
                        double d2[3][12];
                        memset(d, 0, sizeof d);
                        memset(d2, 0, sizeof d2);
                        sx = ga_path_extrap_derivatives(&x[2], t, (ga_frame)f, d[0], d[1], d[2]);
                        ss = ga_path_derivatives_segment(p, (size_t)seg, u, (ga_frame)f, d2[0], d2[1], d2[2]);
                        tk_add_bool(&ext_d, sx == ss && (sx != GA_OK || !memcmp(d, d2, sizeof d)));
                    }
                    /* CONSTANT_VELOCITY: E exp(d V) */
                    ga_mat4 C = xat(&x[3], t);
                    double dt = after ? t - x[0].r1 : t - x[0].r0, V[12], Ee[16];
                    TK_OK(ga_path_eval(p, after ? x[0].r1 : x[0].r0, Ee));
                    TK_OK(ga_path_differentiate(p, after ? x[0].r1 : x[0].r0, GA_FRAME_BODY, V, NULL));
                    ga_mat4 E = g->to_mat4(Ee), ref;
                    if (affine) {
                        ga_mat4 A;
                        memset(&A, 0, sizeof A);
                        for (int c = 0; c < 12; ++c) A.m[c] = dt * V[c];
                        if (ga_mat4_expm(A, &ref) != GA_OK)
                            ref = nan_mat();
                        ref = ga_mat4_mul(E, ref);
                        tk_add_tol(&cv_g, mdiff(C, ref), pose_tol(&k, ref, 1e-12) * ga_mat4_norm1(ref));
                    } else {
                        ref = ga_mat4_mul(E, exp_tw(dt, tw_get(V)));
                        tk_add_tol(&cv_g, mdiff(C, ref), pose_tol(&k, ref, 1e-13));
                        if (s == GA_SCHEME_SCREW || s == GA_SCHEME_LIHAO3 || s == GA_SCHEME_C2) {
                            /* their end velocity is the end chord (path.h) */
                            ga_twist Vk = chord(&k, after ? k.n - 2 : 0);
                            ga_mat4 Ek = after ? k.m[k.n - 1] : k.m[0];
                            ref = ga_mat4_mul(Ek, exp_tw(dt, Vk));
                            tk_add_tol(&cv_c, mdiff(C, ref), pose_tol(&k, ref, 1e-12));
                        }
                    }
                    double cv[3][12];
                    TK_OK(ga_path_extrap_derivatives(&x[3], t, GA_FRAME_BODY, cv[0], cv[1], cv[2]));
                    tk_add_bool(&cv_v, !memcmp(cv[0], V, dim * sizeof *V));
                    int zero = 1;
                    for (int q = 1; q < 3; ++q)
                        for (size_t c = 0; c < dim; ++c) zero &= cv[q][c] == 0.0;
                    TK_OK(ga_path_extrap_derivatives(&x[3], t, GA_FRAME_SPATIAL, cv[0], cv[1], cv[2]));
                    for (int q = 1; q < 3; ++q)
                        for (size_t c = 0; c < dim; ++c) zero &= cv[q][c] == 0.0;
                    tk_add_bool(&cv_0, zero);
                    if (!affine) {
                        ga_twist vb = tw_get(V), sp = ga_se3_adjoint(E, vb);
                        double spd[6];
                        tw_put(sp, spd);
                        tk_add_tol(&cv_s, vdiff(cv[0], spd, 6), 1e-13 * fmax(1.0, vnorm(spd, 6)));
                        /* world: R the rotation of the pose at t, E exp(d V) */
                        TK_OK(ga_path_extrap_derivatives(&x[3], t, GA_FRAME_WORLD, cv[0], cv[1], cv[2]));
                        ga_mat4 Mt = ga_mat4_mul(E, exp_tw(dt, vb));
                        double w[3] = {vb.w.x, vb.w.y, vb.w.z}, lin[3][3] = {{vb.v.x, vb.v.y, vb.v.z}};
                        for (int q = 1; q < 3; ++q) {
                            lin[q][0] = w[1] * lin[q - 1][2] - w[2] * lin[q - 1][1];
                            lin[q][1] = w[2] * lin[q - 1][0] - w[0] * lin[q - 1][2];
                            lin[q][2] = w[0] * lin[q - 1][1] - w[1] * lin[q - 1][0];
                        }
                        double want[3][6], mag = 1.0;
                        for (int q = 0; q < 3; ++q)
                            for (int a = 0; a < 3; ++a) {
                                const double *R = Mt.m + 4 * a;
                                want[q][a] = q == 0 ? R[0] * w[0] + R[1] * w[1] + R[2] * w[2] : 0.0;
                                want[q][3 + a] = R[0] * lin[q][0] + R[1] * lin[q][1] + R[2] * lin[q][2];
                                mag = fmax(mag, fmax(fabs(want[q][a]), fabs(want[q][3 + a])));
                            }
                        double err = 0;
                        for (int q = 0; q < 3; ++q) err = tk_max(err, vdiff(cv[q], want[q], 6));
                        tk_add_tol(&cv_w, err, 1e-13 * mag);
                    }
                    /* every mode, every frame: the derivatives against central
                       differences, and the NULL outputs; not on a path that
                       breaks the growth rule (lihao2 on affine keys), whose
                       continued formulas reach 1e20 within a segment */
                    if (wild)
                        continue;
                    for (int m = 1; m < 4; ++m)
                        for (int f = 0; f < (affine ? 2 : 3); ++f) {
                            double an[3][12], num[3][12], h = 1e-5 * fmax(1.0, fabs(t));
                            TK_OK(ga_path_extrap_derivatives(&x[m], t, (ga_frame)f, an[0], an[1], an[2]));
                            fd_pose_vel(&x[m], t, (ga_frame)f, h, num[0]);
                            for (int o = 2; o <= 3; ++o) {
                                double pp[12], pm[12];
                                xderiv(&x[m], t + h, (ga_frame)f, o - 1, pp);
                                xderiv(&x[m], t - h, (ga_frame)f, o - 1, pm);
                                for (size_t c = 0; c < dim; ++c) num[o - 1][c] = (pp[c] - pm[c]) / (2 * h);
                            }
                            double mag = fmax(k.scale, tnorm(xat(&x[m], t)));
                            for (int o = 0; o < 3; ++o) mag = fmax(mag, vnorm(an[o], (int)dim));
                            for (int o = 0; o < 3; ++o) {
                                tk_add_tol(&fd[f][o], vdiff(an[o], num[o], (int)dim), 1e-6 * mag);
                            }
                            for (int o = 1; o <= 3; ++o) {
                                double one[12];
                                xderiv(&x[m], t, (ga_frame)f, o, one);
                                tk_add_bool(&nul, !memcmp(one, an[o - 1], dim * sizeof *one));
                            }
                        }
                }
            }
        }
    }
    tk_check *all[] = {&in_pose, &in_der, &err_st, &hold_p, &hold_b, &hold_d, &ext_c, &ext_s,
                       &ext_d,   &cv_c,   &cv_g,   &cv_v,   &cv_s,   &cv_w,   &cv_0,  &nul};
    for (size_t i = 0; i < TK_COUNT(all); ++i) tk_end(all[i]);
    tk_note("     (paths past the growth rule, left out of the finite differences: %d)\n", skipped);
    for (int f = 0; f < 3; ++f)
        for (int o = 0; o < 3; ++o) tk_end(&fd[f][o]);
}

/* The refusals, one key, and the far times. */
static void extrap_edges(void)
{
    keyset k;
    chain_keys(&k, 4, 0);
    pathbuf pb;
    TK_OK(mkpath(&pb, &ga_group_cga, GA_SCHEME_LIHAO3, &k, NULL));
    ga_path_extrap x, keep;
    double e[16], d[3][12];
    tk_check c = tk_begin("extrap: init with a bad mode -> GA_ERR_ARG", 0);
    tk_add_status(&c, ga_path_extrap_init(&pb.p, (ga_extrap)4, &x), GA_ERR_ARG);
    tk_add_status(&c, ga_path_extrap_init(&pb.p, (ga_extrap)-1, &x), GA_ERR_ARG);
    tk_end(&c);
    c = tk_begin("extrap: a NaN time -> GA_ERR_ARG (every mode, pose and derivatives)", 0);
    for (int m = 0; m < 4; ++m) {
        TK_OK(ga_path_extrap_init(&pb.p, (ga_extrap)m, &x));
        tk_add_status(&c, ga_path_extrap_eval(&x, NAN, e), GA_ERR_ARG);
        tk_add_status(&c, ga_path_extrap_eval(&x, -NAN, e), GA_ERR_ARG);
        for (int f = 0; f < 3; ++f)
            tk_add_status(&c, ga_path_extrap_derivatives(&x, NAN, (ga_frame)f, d[0], d[1], d[2]), GA_ERR_ARG);
    }
    tk_end(&c);
    c = tk_begin("extrap: a bad frame -> GA_ERR_ARG (inside and outside, every mode)", 0);
    for (int m = 0; m < 4; ++m) {
        TK_OK(ga_path_extrap_init(&pb.p, (ga_extrap)m, &x));
        tk_add_status(&c, ga_path_extrap_derivatives(&x, x.r1 + 1, (ga_frame)3, d[0], d[1], d[2]),
                      GA_ERR_ARG);
        tk_add_status(&c, ga_path_extrap_derivatives(&x, x.r0, (ga_frame)3, d[0], d[1], d[2]), GA_ERR_ARG);
    }
    tk_end(&c);
    /* affine: no world frame */
    keyset ka;
    affine_keys(r, &ka, 4);
    pathbuf pa;
    TK_OK(mkpath(&pa, &ga_group_affine, GA_SCHEME_SCREW, &ka, NULL));
    c = tk_begin("extrap: GA_FRAME_WORLD on affine -> GA_ERR_ARG (inside and outside, every mode)", 0);
    for (int m = 0; m < 4; ++m) {
        TK_OK(ga_path_extrap_init(&pa.p, (ga_extrap)m, &x));
        tk_add_status(&c, ga_path_extrap_derivatives(&x, x.r1 + 1, GA_FRAME_WORLD, d[0], NULL, NULL),
                      GA_ERR_ARG);
        tk_add_status(&c, ga_path_extrap_derivatives(&x, x.r0 - 1, GA_FRAME_WORLD, NULL, d[1], NULL),
                      GA_ERR_ARG);
        tk_add_status(&c, ga_path_extrap_derivatives(&x, x.r0, GA_FRAME_WORLD, NULL, NULL, d[2]), GA_ERR_ARG);
    }
    tk_end(&c);
    /* init reads the range and, for CONSTANT_VELOCITY, the ends' poses and
       body velocities */
    TK_OK(ga_path_extrap_init(&pb.p, GA_EXTRAP_CONSTANT_VELOCITY, &x));
    double r0, r1, pe[2][16], ve[2][12];
    TK_OK(ga_path_range(&pb.p, &r0, &r1));
    for (int i = 0; i < 2; ++i) {
        TK_OK(ga_path_eval(&pb.p, i ? r1 : r0, pe[i]));
        TK_OK(ga_path_differentiate(&pb.p, i ? r1 : r0, GA_FRAME_BODY, ve[i], NULL));
    }
    tk_expect(x.path == &pb.p && x.mode == GA_EXTRAP_CONSTANT_VELOCITY && x.r0 == r0 && x.r1 == r1 &&
                  !memcmp(x.pose[0], pe[0], sizeof(ga_rotor)) &&
                  !memcmp(x.pose[1], pe[1], sizeof(ga_rotor)) &&
                  !memcmp(x.vel[0], ve[0], 6 * sizeof(double)) &&
                  !memcmp(x.vel[1], ve[1], 6 * sizeof(double)),
              "extrap: init holds the path, mode, range, end poses and velocities");
    /* far out: GA_OK comes with finite output, else an overflow status */
    c = tk_begin("extrap: far times: GA_OK and finite, or GA_ERR_DOMAIN/NOTFINITE", 0);
    tk_check hold_far = tk_begin("extrap: HOLD at +-1e300 = the end pose, bit for bit", 0);
    for (int m = 1; m < 4; ++m) {
        TK_OK(ga_path_extrap_init(&pb.p, (ga_extrap)m, &x));
        const double far[] = {1e300, -1e300, 1e308, -DBL_MAX, 1e30};
        for (size_t i = 0; i < TK_COUNT(far); ++i) {
            int st = ga_path_extrap_eval(&x, far[i], e);
            int fin = 1;
            for (int q = 0; q < 8; ++q) fin &= isfinite(e[q]);
            tk_add_bool(&c, (st == GA_OK && fin) || st == GA_ERR_DOMAIN || st == GA_ERR_NOTFINITE);
            st = ga_path_extrap_derivatives(&x, far[i], GA_FRAME_WORLD, d[0], d[1], d[2]);
            fin = 1;
            for (int q = 0; q < 3; ++q)
                for (int j = 0; j < 6; ++j) fin &= isfinite(d[q][j]);
            tk_add_bool(&c, (st == GA_OK && fin) || st == GA_ERR_DOMAIN || st == GA_ERR_NOTFINITE);
            if (m == GA_EXTRAP_HOLD && fabs(far[i]) == 1e300)
                tk_add_bool(&hold_far, ga_path_extrap_eval(&x, far[i], e) == GA_OK &&
                                           !memcmp(e, pe[far[i] > 0], sizeof(ga_rotor)));
        }
    }
    tk_end(&c);
    tk_end(&hold_far);
    /* one key: every mode but ERROR holds it, at rest */
    c = tk_begin("extrap: one key: HOLD, EXTEND, CONSTANT_VELOCITY give it, at rest", 0);
    tk_check c1 = tk_begin("extrap: one key: ERROR away from t_0 -> GA_ERR_ARG", 0);
    for (size_t gi = 0; ga_group_nth(gi); ++gi) {
        const ga_group *g = ga_group_nth(gi);
        for (int s = 0; s < GA_SCHEME_COUNT; ++s) {
            if (!ga_path_workspace_size(g, (ga_scheme)s, 1))
                continue;
            keyset k1;
            if (g->rigid)
                chain_keys(&k1, 1, 0);
            else
                affine_keys(r, &k1, 1);
            pathbuf p1;
            if (mkpath(&p1, g, (ga_scheme)s, &k1, NULL) != GA_OK) {
                tk_add_bool(&c, 0);
                continue;
            }
            double key[16];
            TK_OK(ga_path_eval(&p1.p, k1.t[0], key));
            for (int m = 0; m < 4; ++m) {
                TK_OK(ga_path_extrap_init(&p1.p, (ga_extrap)m, &x));
                for (int side = -1; side <= 1; side += 2) {
                    double t = k1.t[0] + side * tk_range(r, 0.1, 5.0);
                    int st = ga_path_extrap_eval(&x, t, e);
                    if (m == GA_EXTRAP_ERROR) {
                        tk_add_status(&c1, st, GA_ERR_ARG);
                        continue;
                    }
                    int ok = st == GA_OK && !memcmp(e, key, g->elem_size);
                    for (int f = 0; f < (g->rigid ? 3 : 2); ++f) {
                        for (int q = 0; q < 3; ++q)
                            for (int j = 0; j < 12; ++j) d[q][j] = NAN;
                        ok &= ga_path_extrap_derivatives(&x, t, (ga_frame)f, d[0], d[1], d[2]) == GA_OK;
                        for (int q = 0; q < 3; ++q)
                            for (size_t j = 0; j < g->dim; ++j) ok &= d[q][j] == 0.0;
                    }
                    tk_add_bool(&c, ok);
                }
            }
        }
    }
    tk_end(&c);
    tk_end(&c1);
    /* x is valid while the path is unchanged: init after an append sees the new end */
    keyset k3;
    chain_keys(&k3, 3, 0);
    double buf[WORK];
    ga_path p3;
    TK_OK(ga_path_init_mat4(&ga_group_se3, GA_SCHEME_SCREW, 2, k3.t, k3.m, NULL, buf, sizeof buf, &p3));
    TK_OK(ga_path_extrap_init(&p3, GA_EXTRAP_HOLD, &keep));
    TK_OK(ga_path_append_mat4(&p3, k3.t[2], k3.m[2]));
    TK_OK(ga_path_extrap_init(&p3, GA_EXTRAP_HOLD, &x));
    tk_expect(keep.r1 == k3.t[1] && x.r1 == k3.t[2] &&
                  mdiff(xat(&x, k3.t[2] + 1), k3.m[2]) <= 1e-13 * k3.scale,
              "extrap: init after ga_path_append holds the new end");
}

static void seed(void) { stream = (tk_rng){tk_seed(20261203u)}; }

static const tk_section sections[] = {
    {"seed", seed, TK_SETUP},           {"names", names, 0},      {"paths", extrap_paths, TK_STREAM},
    {"edges", extrap_edges, TK_STREAM}, {"time", tk_cpu_time, 0},
};

int main(int argc, char **argv)
{
    return tk_main(argc, argv, "test_interp_extrap", sections, TK_COUNT(sections));
}
