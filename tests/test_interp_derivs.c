/* tests/test_interp_derivs.c: ga_path_derivatives (interp/path.h): the
 * velocity, acceleration and jerk of every scheme in the three frames
 * against finite differences (of the samples alone, and of the derivative
 * below), the closed form of the rigid groups against the affine group's
 * 4x4 jet, what may be left out bit for bit, constant keys exactly at rest;
 * and the C2 key velocities against a dense O(n^3) Newton solve of the C2
 * conditions written here from scratch (Van Loan's block exponentials for
 * the derivatives of exp). Seeded (interp_kit.h), so every run is the same.
 */
#include "interp_kit.h"

static tk_rng stream;
static tk_rng *const r = &stream; /* helpers take it as r */

static const char *const frame_name[3] = {"body", "spatial", "world"};

static double seg_len(const ga_path *p, int seg)
{
    double a, b;
    return ga_path_segment_range(p, (size_t)seg, &a, &b) == GA_OK ? b - a : NAN;
}

/* Keys for scheme s: bspline 6 at even times, quadratic 3, else 5. */
static void keys_for(ga_scheme s, int affine, keyset *k)
{
    int n = s == GA_SCHEME_QUADRATIC ? 3 : s == GA_SCHEME_BSPLINE ? 6 : 5;
    group_keys(r, affine, k, n, 0);
    if (s == GA_SCHEME_BSPLINE)
        for (int i = 1; i < n; ++i) k->t[i] = k->t[0] + 0.7 * i;
}

/* Derivative of order o (1 velocity, 2 acceleration, 3 jerk) in frame f at
 * (seg, u), asking for it alone; NaN where the call fails. */
static void deriv(const ga_path *p, int seg, double u, ga_frame f, int o, double *x)
{
    int st = ga_path_derivatives_segment(p, (size_t)seg, u, f, o == 1 ? x : NULL, o == 2 ? x : NULL,
                                         o == 3 ? x : NULL);
    if (st)
        for (size_t i = 0; i < p->group->dim; ++i) x[i] = NAN;
}

/* The velocity in frame f from three samples (central difference of the
 * 4x4 matrices, step e in t): body vee(M^-1 M'), spatial vee(M' M^-1),
 * world (the angular part of spatial, then p'). */
static void fd_pose_vel(const ga_path *p, int seg, double u, ga_frame f, double e, double *x)
{
    double h = seg_len(p, seg);
    ga_mat4 M = at_seg(p, seg, u), P = at_seg(p, seg, u + e / h), Q = at_seg(p, seg, u - e / h), D, Mi, X;
    for (int i = 0; i < 16; ++i) D.m[i] = (P.m[i] - Q.m[i]) / (2 * e);
    if (ga_mat4_inverse(M, &Mi) != GA_OK) {
        for (size_t i = 0; i < p->group->dim; ++i) x[i] = NAN;
        return;
    }
    X = f == GA_FRAME_BODY ? ga_mat4_mul(Mi, D) : ga_mat4_mul(D, Mi);
    if (!p->group->rigid) {
        for (int i = 0; i < 12; ++i) x[i] = X.m[i];
        return;
    }
    x[0] = 0.5 * (X.m[9] - X.m[6]);
    x[1] = 0.5 * (X.m[2] - X.m[8]);
    x[2] = 0.5 * (X.m[4] - X.m[1]);
    for (int i = 0; i < 3; ++i) x[3 + i] = f == GA_FRAME_WORLD ? D.m[4 * i + 3] : X.m[4 * i + 3];
}

/* Central difference (step e in t) of the analytic derivative of order o - 1. */
static void fd_deriv(const ga_path *p, int seg, double u, ga_frame f, int o, double e, double *x)
{
    double a[12], b[12], h = seg_len(p, seg);
    deriv(p, seg, u + e / h, f, o - 1, a);
    deriv(p, seg, u - e / h, f, o - 1, b);
    for (size_t i = 0; i < p->group->dim; ++i) x[i] = (a[i] - b[i]) / (2 * e);
}

/* From the samples alone: order 2 and 3 by central differences of the
 * sampled velocities (fd_pose_vel, step e) at u and u +- H. */
static void fd_pose_higher(const ga_path *p, int seg, double u, ga_frame f, int o, double e, double H,
                           double *x)
{
    double a[12], b[12], c[12], h = seg_len(p, seg);
    fd_pose_vel(p, seg, u + H / h, f, e, a);
    fd_pose_vel(p, seg, u - H / h, f, e, b);
    fd_pose_vel(p, seg, u, f, e, c);
    for (size_t i = 0; i < p->group->dim; ++i)
        x[i] = o == 2 ? (a[i] - b[i]) / (2 * H) : (a[i] - 2 * c[i] + b[i]) / (H * H);
}

/* ---- every scheme, every frame, against differences ---------------------------- */

static void test_frames(void)
{
    stream = tk_rng_after(INTERP_SEED, 31001);
    /* [order-1][frame]: against the difference of the analytic derivative one
       order below (step 1e-4), and against the samples alone (velocity: step
       1e-4; acceleration: steps 1e-5 and 1e-3; jerk: 1e-4 and 1e-2). The
       differences' truncation grows with the square of the rates, and
       lihao2's grow along the keys (to 2e5 here): its largest errors are
       1.8e-6, 1.6e-4, 9e-3 (a wrong term would be of order 1) */
    tk_check c_an[3][3], c_pose[3][3], c_arg = tk_begin("world frame on affine: GA_ERR_ARG", 0);
    for (int o = 0; o < 3; ++o)
        for (int f = 0; f < 3; ++f) {
            static const double tol_an[3] = {1e-7, 1e-5, 1e-5}, tol_pose[3] = {1e-5, 1e-3, 5e-2};
            static const char *const what[3] = {"velocity", "acceleration", "jerk"};
            c_an[o][f] = o == 0
                           ? tk_beginf(tol_an[o], "%s %s = central FD of the samples (step 1e-5), relative",
                                       frame_name[f], what[o])
                           : tk_beginf(tol_an[o], "%s %s = central FD of the %s (step 1e-4), relative",
                                       frame_name[f], what[o], what[o - 1]);
            c_pose[o][f] = tk_beginf(tol_pose[o], "%s %s = FD of the samples alone, relative", frame_name[f],
                                     what[o]);
        }
    for (int gi = 0; gi < 3; ++gi) {
        const ga_group *g = ga_group_nth((size_t)gi);
        for (int s = 0; s < GA_SCHEME_COUNT; ++s) {
            if (ga_path_workspace_size(g, (ga_scheme)s, 4) == 0)
                continue;
            for (int trial = 0; trial < 3; ++trial) {
                keyset k;
                pathbuf b;
                keys_for((ga_scheme)s, !g->rigid, &k);
                if (mkpath(&b, g, (ga_scheme)s, &k, NULL) != GA_OK)
                    continue; /* affine lihao2 may have no real log: test_schemes counts those */
                const ga_path *p = &b.p;
                int d = (int)g->dim, nseg = (int)ga_path_segments(p);
                for (int seg = 0; seg < nseg; ++seg)
                    for (int q = 0; q < 4; ++q) {
                        /* off u = 1/2, where smooth's quadratic pieces meet */
                        double u = 0.15 + 0.25 * q, x[12], y[12];
                        for (int f = 0; f < 3; ++f) {
                            if (f == GA_FRAME_WORLD && !g->rigid) {
                                tk_add_status(&c_arg,
                                              ga_path_derivatives_segment(p, (size_t)seg, u, GA_FRAME_WORLD,
                                                                          x, NULL, NULL),
                                              GA_ERR_ARG);
                                continue;
                            }
                            for (int o = 1; o <= 3; ++o) {
                                deriv(p, seg, u, (ga_frame)f, o, x);
                                double nx = fmax(1.0, vnorm(x, d));
                                if (o == 1)
                                    fd_pose_vel(p, seg, u, (ga_frame)f, 1e-5, y);
                                else
                                    fd_deriv(p, seg, u, (ga_frame)f, o, 1e-4, y);
                                tk_add(&c_an[o - 1][f], vdiff(x, y, d) / nx);
                                if (o == 1)
                                    fd_pose_vel(p, seg, u, (ga_frame)f, 1e-4, y);
                                else
                                    fd_pose_higher(p, seg, u, (ga_frame)f, o, o == 2 ? 1e-5 : 1e-4,
                                                   o == 2 ? 1e-3 : 1e-2, y);
                                tk_add(&c_pose[o - 1][f], vdiff(x, y, d) / nx);
                            }
                        }
                    }
            }
        }
    }
    for (int o = 0; o < 3; ++o)
        for (int f = 0; f < 3; ++f) tk_end(&c_an[o][f]);
    for (int o = 0; o < 3; ++o)
        for (int f = 0; f < 3; ++f) tk_end(&c_pose[o][f]);
    tk_end(&c_arg);
}

/* ---- the rigid closed form against the affine group's 4x4 jet --------------------- */

/* Keys turning by less than 1 rad from the identity and from each other: the
 * principal logs of cga and affine are the same twist, and the branch rule of
 * cga never takes the other branch, so each scheme defines the same path on
 * both groups. */
static void test_closed_form(void)
{
    stream = tk_rng_after(INTERP_SEED, 32003);
    tk_check c_a = tk_begin("cga (closed form) = affine (4x4 jet): acceleration, relative", 1e-11);
    tk_check c_j = tk_begin("cga (closed form) = affine (4x4 jet): jerk, relative", 1e-10);
    const ga_scheme sch[] = {GA_SCHEME_SCREW,  GA_SCHEME_BIVECTOR, GA_SCHEME_QUADRATIC, GA_SCHEME_SMOOTH,
                             GA_SCHEME_LIHAO2, GA_SCHEME_LIHAO3,   GA_SCHEME_BSPLINE};
    for (size_t si = 0; si < TK_COUNT(sch); ++si)
        for (int trial = 0; trial < 6; ++trial) {
            keyset k;
            int n = sch[si] == GA_SCHEME_QUADRATIC ? 3 : sch[si] == GA_SCHEME_BSPLINE ? 6 : 5;
            k.n = n;
            for (int i = 0; i < n; ++i) {
                k.t[i] = sch[si] == GA_SCHEME_BSPLINE ? 0.6 * i
                                                      : (i ? k.t[i - 1] + tk_range(r, 0.3, 1.5) : 0.0);
                k.m[i] = rigid(tk_unit(r), tk_range(r, 0.0, 0.45), rvec(r, 3));
            }
            set_scale(&k);
            pathbuf bc, ba;
            if (mkpath(&bc, &ga_group_cga, sch[si], &k, NULL) != GA_OK ||
                mkpath(&ba, &ga_group_affine, sch[si], &k, NULL) != GA_OK) {
                tk_add(&c_a, NAN);
                continue;
            }
            for (int seg = 0; seg < (int)ga_path_segments(&bc.p); ++seg)
                for (int q = 0; q <= 4; ++q) {
                    double u = 0.25 * q, ac[6], jc[6], aa[12], ja[12];
                    TK_OK(ga_path_derivatives_segment(&bc.p, (size_t)seg, u, GA_FRAME_BODY, NULL, ac, jc));
                    TK_OK(ga_path_derivatives_segment(&ba.p, (size_t)seg, u, GA_FRAME_BODY, NULL, aa, ja));
                    ga_mat4 ha = ga_group_cga.hat(ac), hj = ga_group_cga.hat(jc);
                    double ea = 0, ej = 0, na = 1, nj = 1;
                    for (int i = 0; i < 12; ++i) {
                        ea = fmax(ea, fabs(ha.m[i] - aa[i]));
                        ej = fmax(ej, fabs(hj.m[i] - ja[i]));
                        na = fmax(na, fabs(aa[i]));
                        nj = fmax(nj, fabs(ja[i]));
                    }
                    tk_add(&c_a, ea / na);
                    tk_add(&c_j, ej / nj);
                }
        }
    tk_end(&c_a);
    tk_end(&c_j);
}

/* ---- what may be left out, bit for bit; constant keys ------------------------------ */

static int same(const double *a, const double *b, size_t d) { return memcmp(a, b, d * sizeof(double)) == 0; }

static void test_bits(void)
{
    stream = tk_rng_after(INTERP_SEED, 33007);
    tk_check c_v = tk_begin("velocity alone = ga_path_velocity (body), bit for bit", 0);
    tk_check c_d = tk_begin("(v, a) = ga_path_differentiate, in every frame, bit for bit", 0);
    tk_check c_j = tk_begin("(v, a) the same with the jerk asked too, bit for bit", 0);
    tk_check c_z = tk_begin("constant keys: velocity, acceleration, jerk exactly 0 (every frame)", 0);
    for (int gi = 0; gi < 3; ++gi) {
        const ga_group *g = ga_group_nth((size_t)gi);
        size_t d = g->dim;
        for (int s = 0; s < GA_SCHEME_COUNT; ++s) {
            if (ga_path_workspace_size(g, (ga_scheme)s, 4) == 0)
                continue;
            keyset k;
            pathbuf b;
            keys_for((ga_scheme)s, !g->rigid, &k);
            if (mkpath(&b, g, (ga_scheme)s, &k, NULL) == GA_OK) {
                const ga_path *p = &b.p;
                double t0, t1;
                TK_OK(ga_path_range(p, &t0, &t1));
                for (int q = 0; q <= 8; ++q) {
                    double t = q == 8 ? t1 : t0 + (t1 - t0) * q / 8.0, v0[12], v1[12], a1[12], v2[12], a2[12],
                           j2[12];
                    tk_add_bool(&c_v, ga_path_derivatives(p, t, GA_FRAME_BODY, v0, NULL, NULL) == GA_OK &&
                                          ga_path_velocity(p, t, v1) == GA_OK && same(v0, v1, d));
                    for (int f = 0; f < (g->rigid ? 3 : 2); ++f) {
                        int ok = ga_path_differentiate(p, t, (ga_frame)f, v1, a1) == GA_OK &&
                                 ga_path_derivatives(p, t, (ga_frame)f, v2, a2, NULL) == GA_OK;
                        tk_add_bool(&c_d, ok && same(v1, v2, d) && same(a1, a2, d));
                        ok = ga_path_derivatives(p, t, (ga_frame)f, v2, a2, j2) == GA_OK;
                        tk_add_bool(&c_j, ok && same(v1, v2, d) && same(a1, a2, d));
                    }
                }
            }
            /* every key the same pose */
            for (int i = 1; i < k.n; ++i) k.m[i] = k.m[0];
            int st = mkpath(&b, g, (ga_scheme)s, &k, NULL);
            if (st != GA_OK) {
                tk_add_bool(&c_z, 0);
                tk_note("     constant keys: %s on %s: %s\n", ga_scheme_name((ga_scheme)s), g->name,
                        ga_status_string(st));
                continue;
            }
            double t0, t1;
            TK_OK(ga_path_range(&b.p, &t0, &t1));
            for (int q = 0; q <= 4; ++q)
                for (int f = 0; f < (g->rigid ? 3 : 2); ++f) {
                    double v[12], a[12], j[12], z = 0.0;
                    int st = ga_path_derivatives(&b.p, q == 4 ? t1 : t0 + (t1 - t0) * q / 4.0, (ga_frame)f, v,
                                                 a, j);
                    for (size_t i = 0; i < d; ++i) z = fmax(z, fabs(v[i]) + fabs(a[i]) + fabs(j[i]));
                    tk_add_bool(&c_z, st == GA_OK && z == 0.0);
                    if (st != GA_OK || z != 0.0)
                        tk_note("     constant keys: %s on %s, %s frame: %g (%s)\n",
                                ga_scheme_name((ga_scheme)s), g->name, frame_name[f], z,
                                ga_status_string(st));
                }
        }
    }
    tk_end(&c_v);
    tk_end(&c_d);
    tk_end(&c_j);
    tk_end(&c_z);
}

/* ---- c2: the key velocities against a dense Newton solve ------------------------ */

/* exp of an m x m matrix (m <= 12) by scaling, 24 Taylor terms and squaring. */
static void dense_expm(int m, const double *a, double *o)
{
    double s[144], t[144], u[144], nrm = 0.0;
    int q = 0;
    for (int i = 0; i < m; ++i) {
        double row = 0.0;
        for (int j = 0; j < m; ++j) row += fabs(a[m * i + j]);
        nrm = fmax(nrm, row);
    }
    while (nrm > 0.25) {
        nrm *= 0.5;
        ++q;
    }
    for (int i = 0; i < m * m; ++i) s[i] = ldexp(a[i], -q);
    for (int i = 0; i < m * m; ++i) o[i] = (i % (m + 1) == 0);
    for (int k = 24; k >= 1; --k) { /* o = I + s o / k */
        for (int i = 0; i < m; ++i)
            for (int j = 0; j < m; ++j) {
                double x = 0.0;
                for (int l = 0; l < m; ++l) x += s[m * i + l] * o[m * l + j];
                t[m * i + j] = x / k + (i == j);
            }
        memcpy(o, t, (size_t)(m * m) * sizeof(double));
    }
    for (; q > 0; --q) {
        for (int i = 0; i < m; ++i)
            for (int j = 0; j < m; ++j) {
                double x = 0.0;
                for (int l = 0; l < m; ++l) x += o[m * i + l] * o[m * l + j];
                u[m * i + j] = x;
            }
        memcpy(o, u, (size_t)(m * m) * sizeof(double));
    }
}

/* The 4x4 block (bi, bj) of an m x m matrix, m = 4 nb. */
static ga_mat4 block(const double *x, int nb, int bi, int bj)
{
    ga_mat4 b;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) b.m[4 * i + j] = x[(4 * nb) * (4 * bi + i) + 4 * bj + j];
    return b;
}

/* G = exp(X), G1 = d/dt exp(X + t Y), G2 = d^2/dt^2 exp(X + t Y) at t = 0, by
 * Van Loan: exp of [[X, Y, 0], [0, X, Y], [0, 0, X]] holds G, G1 and G2/2. */
static void vanloan(const double *x, const double *y, ga_mat4 *G, ga_mat4 *G1, ga_mat4 *G2)
{
    ga_mat4 X = ga_twist_hat((ga_twist){{x[0], x[1], x[2]}, {x[3], x[4], x[5]}}),
            Y = ga_twist_hat((ga_twist){{y[0], y[1], y[2]}, {y[3], y[4], y[5]}});
    double a[144] = {0}, e[144];
    for (int b = 0; b < 3; ++b)
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j) {
                a[12 * (4 * b + i) + 4 * b + j] = X.m[4 * i + j];
                if (b < 2)
                    a[12 * (4 * b + i) + 4 * (b + 1) + j] = Y.m[4 * i + j];
            }
    dense_expm(12, a, e);
    *G = block(e, 3, 0, 0);
    *G1 = block(e, 3, 0, 1);
    *G2 = block(e, 3, 0, 2);
    for (int i = 0; i < 16; ++i) G2->m[i] *= 2.0;
}

static void vee6(ga_mat4 X, double *o)
{
    o[0] = 0.5 * (X.m[9] - X.m[6]);
    o[1] = 0.5 * (X.m[2] - X.m[8]);
    o[2] = 0.5 * (X.m[4] - X.m[1]);
    o[3] = X.m[3];
    o[4] = X.m[7];
    o[5] = X.m[11];
}

/* J_r(th) y = vee(G^-1 G1) and N(th, y) = vee(G^-1 G2 - (G^-1 G1)^2) with Y = y. */
static void jr_n(const double *th, const double *y, double *jy, double *n)
{
    ga_mat4 G, G1, G2, Gi;
    vanloan(th, y, &G, &G1, &G2);
    Gi = ga_se3_inverse(G);
    ga_mat4 V = ga_mat4_mul(Gi, G1), P = ga_mat4_mul(Gi, G2), V2 = ga_mat4_mul(V, V);
    if (jy)
        vee6(V, jy);
    if (n) {
        for (int i = 0; i < 16; ++i) P.m[i] -= V2.m[i];
        vee6(P, n);
    }
}

/* J_r(th)^-1 y: the 6 x 6 J_r by columns, then Gauss-Jordan */
static void jr_inv(const double *th, const double *y, double *o)
{
    double J[36], b[6];
    for (int c = 0; c < 6; ++c) {
        double e[6] = {0}, col[6];
        e[c] = 1.0;
        jr_n(th, e, col, NULL);
        for (int i = 0; i < 6; ++i) J[6 * i + c] = col[i];
    }
    memcpy(b, y, sizeof b);
    for (int c = 0; c < 6; ++c) {
        int pv = c;
        for (int i = c + 1; i < 6; ++i)
            if (fabs(J[6 * i + c]) > fabs(J[6 * pv + c]))
                pv = i;
        for (int j = 0; j < 6; ++j) {
            double t = J[6 * c + j];
            J[6 * c + j] = J[6 * pv + j];
            J[6 * pv + j] = t;
        }
        double t = b[c];
        b[c] = b[pv];
        b[pv] = t;
        for (int i = 0; i < 6; ++i) {
            if (i == c)
                continue;
            double f = J[6 * i + c] / J[6 * c + c];
            for (int j = 0; j < 6; ++j) J[6 * i + j] -= f * J[6 * c + j];
            b[i] -= f * b[c];
        }
    }
    for (int i = 0; i < 6; ++i) o[i] = b[i] / J[6 * i + i];
}

/* The C2 residual: for each interior key k, the body acceleration at the end
 * of segment k - 1 minus that at the start of segment k, the segments the
 * cubics x with x(0) = 0, x(h) = th, x'(0) = w_i, J_r(th) x'(h) = w_{i+1}
 * (path.h C2): x''(0) = (6 th - 4 h w_i - 2 h e)/h^2, x''(h) = (-6 th +
 * 2 h w_i + 4 h e)/h^2, e = J_r(th)^-1 w_{i+1}; the acceleration at x = 0 is
 * x''(0), at x = th J_r(th) x''(h) + N(th, e). W: the n key velocities. */
static void c2_residual(int n, const double *t, const double (*th)[6], const double *W, double *F)
{
    for (int k = 1; k + 1 < n; ++k) {
        double hl = t[k] - t[k - 1], hr = t[k + 1] - t[k], e[6], xl[6], jl[6], nl[6], el[6], xr[6];
        jr_inv(th[k - 1], W + 6 * k, el);
        jr_inv(th[k], W + 6 * (k + 1), e);
        for (int i = 0; i < 6; ++i) {
            xl[i] = (-6 * th[k - 1][i] + 2 * hl * W[6 * (k - 1) + i] + 4 * hl * el[i]) / (hl * hl);
            xr[i] = (6 * th[k][i] - 4 * hr * W[6 * k + i] - 2 * hr * e[i]) / (hr * hr);
        }
        jr_n(th[k - 1], xl, jl, NULL);
        jr_n(th[k - 1], el, NULL, nl);
        for (int i = 0; i < 6; ++i) F[6 * (k - 1) + i] = jl[i] + nl[i] - xr[i];
    }
}

/* Dense Newton on the 6 (n - 2) interior velocities: the Jacobian by central
 * differences, each step by Gaussian elimination with partial pivoting on the
 * whole matrix (O(n^3)); returns the last step's size relative to |W|. */
static double c2_dense(int n, const double *t, const double (*th)[6], double *W)
{
    enum { MU = 6 * (MAXK - 2) };
    int m = 6 * (n - 2);
    double F[MU], Fp[MU], Fm[MU], A[MU * (MU + 1)], step = INFINITY, prev = INFINITY;
    /* until the step is below 1e-16, or stalls at rounding level (below
       1e-13 and no longer halving: more sweeps only repeat the rounding) */
    for (int it = 0; it < 40 && step > 1e-16 && !(step < 1e-13 && step > 0.5 * prev); ++it) {
        prev = step;
        double big = 0.0;
        for (int i = 0; i < 6 * n; ++i) big = fmax(big, fabs(W[i]));
        c2_residual(n, t, th, W, F);
        for (int c = 0; c < m; ++c) {
            double *w = W + 6 + c, keep = *w, e = 1e-6 * fmax(1.0, big);
            *w = keep + e;
            c2_residual(n, t, th, W, Fp);
            *w = keep - e;
            c2_residual(n, t, th, W, Fm);
            *w = keep;
            for (int i = 0; i < m; ++i) A[(m + 1) * i + c] = (Fp[i] - Fm[i]) / (2 * e);
        }
        for (int i = 0; i < m; ++i) A[(m + 1) * i + m] = -F[i];
        for (int c = 0; c < m; ++c) {
            int pv = c;
            for (int i = c + 1; i < m; ++i)
                if (fabs(A[(m + 1) * i + c]) > fabs(A[(m + 1) * pv + c]))
                    pv = i;
            for (int j = 0; j <= m; ++j) {
                double x = A[(m + 1) * c + j];
                A[(m + 1) * c + j] = A[(m + 1) * pv + j];
                A[(m + 1) * pv + j] = x;
            }
            for (int i = c + 1; i < m; ++i) {
                double f = A[(m + 1) * i + c] / A[(m + 1) * c + c];
                for (int j = c; j <= m; ++j) A[(m + 1) * i + j] -= f * A[(m + 1) * c + j];
            }
        }
        double dx[MU];
        step = 0.0;
        for (int i = m - 1; i >= 0; --i) {
            double s = A[(m + 1) * i + m];
            for (int j = i + 1; j < m; ++j) s -= A[(m + 1) * i + j] * dx[j];
            dx[i] = s / A[(m + 1) * i + i];
        }
        for (int i = 0; i < m; ++i) {
            W[6 + i] += dx[i];
            step = fmax(step, fabs(dx[i]) / fmax(1.0, big));
        }
    }
    return step;
}

static void test_c2_dense(void)
{
    stream = tk_rng_after(INTERP_SEED, 34019);
    tk_check c_w = tk_begin("c2 key velocities = dense Newton (O(n^3)), / max(1, |W|)", 1e-11);
    tk_check c_r = tk_begin("... the dense solve's residual at the path's velocities, / max(1, |W|)", 1e-10);
    for (int trial = 0; trial < 12; ++trial) {
        keyset k;
        int n = 3 + trial % (MAXK - 2);
        k.n = n;
        for (int i = 0; i < n; ++i) {
            k.t[i] = i ? k.t[i - 1] + tk_range(r, 0.3, 2.0) : tk_range(r, -1, 1);
            k.m[i] = rigid(tk_unit(r), tk_range(r, 0.0, 2.5), rvec(r, 3));
        }
        set_scale(&k);
        pathbuf b;
        if (mkpath(&b, &ga_group_se3, GA_SCHEME_C2, &k, NULL) != GA_OK) {
            tk_add(&c_w, NAN);
            continue;
        }
        double th[MAXK][6], W[6 * MAXK], F[6 * MAXK], big = 1.0;
        for (int i = 0; i + 1 < n; ++i) {
            ga_twist x;
            ga_mat4 rel = ga_mat4_mul(ga_se3_inverse(k.m[i]), k.m[i + 1]);
            TK_OK(ga_se3_log(rel, &x));
            double v[6] = {x.w.x, x.w.y, x.w.z, x.v.x, x.v.y, x.v.z};
            memcpy(th[i], v, sizeof v);
        }
        /* the ends (path.h): the screw velocities of the end segments; the
           interior from the chords' average */
        for (int i = 0; i < n; ++i) {
            int j = i + 1 < n ? i : i - 1;
            for (int c = 0; c < 6; ++c) W[6 * i + c] = th[j][c] / (k.t[j + 1] - k.t[j]);
        }
        double step = c2_dense(n, k.t, (const double(*)[6])th, W);
        double err = step > 1e-12 ? NAN : 0.0;
        for (int i = 0; i < 6 * n; ++i) big = fmax(big, fabs(W[i]));
        for (int i = 0; i < 6 * n; ++i) err = fmax(err, fabs(W[i] - b.p.vel[i]) / big);
        tk_add(&c_w, err);
        c2_residual(n, k.t, (const double(*)[6])th, b.p.vel, F);
        tk_add(&c_r, vnorm(F, 6 * (n - 2)) / big);
    }
    tk_end(&c_w);
    tk_end(&c_r);
}

static const tk_section sections[] = {
    {"frames", test_frames, 0},
    {"closed-form", test_closed_form, 0},
    {"bits", test_bits, 0},
    {"c2-dense", test_c2_dense, 0},
};

int main(int argc, char **argv)
{
    return tk_main(argc, argv, "test_interp_derivs", sections, TK_COUNT(sections));
}
