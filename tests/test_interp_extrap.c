/* tests/test_interp_extrap.c: the functions of path.h around a path rather
 * than on it, each against what its header promises, computed here
 * independently: ga_path_extrap_* (interp/extrap.c) in every mode before the
 * first key and after the last against the mode's closed form built from the
 * keys with SE(3)'s matrix functions (hold: the end key; extend: the end
 * segment's formula, written out for screw, lihao3 and bspline; constant
 * velocity: E exp(d V) with E the end key and V its end chord for the
 * schemes whose end velocity is that chord), their derivatives against
 * those closed forms and against finite differences, inside the range the
 * path's own bits, and the refusals; ga_times_min_gap and ga_times_gap_run
 * (interp/near_dup.c) at their edges and against a brute force;
 * ga_path_merge_keys against the mean time summed as documented and the
 * barycentre of the poses; ga_path_growth_describe (interp/growth.c) on
 * paths that break the growth rule and one that does not, its ratio against
 * C's "%.*g". Seeded (testkit.h), so every run is the same.
 */
#include <locale.h>

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
        ga_twist mean = {{0, 0, 0}, {0, 0, 0}};
        for (size_t i = 0; i < m; ++i) {
            double a = tk_range(r, -0.6, 0.6);
            ga_twist xi = {tk_scale(u, a), tk_scale(u, a * pitch)};
            keys[i] = ga_mat4_mul(ga_mat4_mul(L, ga_se3_exp(xi)), Li);
            times[i] = (double)i;
            mean = tw_lin(1.0, mean, 1.0 / (double)m, xi);
        }
        ga_mat4 want = ga_mat4_mul(ga_mat4_mul(L, ga_se3_exp(mean)), Li);
        if (ga_path_merge_keys(m, times, keys, 0, &t, &key) != GA_OK)
            key = nan_mat();
        tk_add(&pc, mdiff(key, want) / fmax(1.0, tnorm(want)));
        /* random poses near each other */
        ga_mat4 c0 = rand_rigid(r, 0, PI, 5);
        for (size_t i = 0; i < m; ++i) {
            ga_mat4 d = rand_rigid(r, 0, 0.8, 0.5);
            keys[i] = ga_mat4_mul(c0, d);
        }
        if (ga_path_merge_keys(m, times, keys, 0, &t, &key) != GA_OK)
            key = nan_mat();
        ga_twist sum = {{0, 0, 0}, {0, 0, 0}};
        for (size_t i = 0; i < m; ++i) sum = tw_lin(1.0, sum, 1.0, rel_log(key, keys[i]));
        double s6[6];
        tw_put(sum, s6);
        tk_add(&bc, vnorm(s6, 6) / fmax(1.0, tnorm(c0)));
        ga_mat4 rev[GA_PATH_MERGE_MAX], key2;
        for (size_t i = 0; i < m; ++i) rev[i] = keys[m - 1 - i];
        if (ga_path_merge_keys(m, times, rev, 0, &t, &key2) != GA_OK)
            key2 = nan_mat();
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
        kb.m[i] = exp_tw((double)i, X);
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

static void seed(void) { stream = (tk_rng){tk_seed(20261203u)}; }

static const tk_section sections[] = {
    {"seed", seed, TK_SETUP},           {"names", names, 0},
    {"paths", extrap_paths, TK_STREAM}, {"edges", extrap_edges, TK_STREAM},
    {"min_gap", min_gap, TK_STREAM},    {"gap_run", gap_run, TK_STREAM},
    {"merge", merge, TK_STREAM},        {"growth", growth_words, 0},
    {"time", tk_cpu_time, 0},
};

int main(int argc, char **argv)
{
    return tk_main(argc, argv, "test_interp_extrap", sections, TK_COUNT(sections));
}
