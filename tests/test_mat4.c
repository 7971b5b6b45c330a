/* tests/test_mat4.c: the SE(3) closed forms against the general expm/logm,
 * round trips, half turns, affine matrices, and bad input.
 *
 * Every check prints one line (testkit.h): ok/FAIL, its name, the number of
 * cases, the worst measured error and the tolerance; the twist checks have
 * one line per family. The error measures:
 *   - matrix against matrix: max |entry difference| / max(1, |t|), t the
 *     reference's translation (rotation entries are O(1), translation
 *     entries O(|t|));
 *   - twist against twist: max |component difference| / max(1, |v|);
 *   - the affine round trip: ||expm(logm(A)) - A||_1 / ||A||_1.
 * Tolerances: 1e-13 for the SE(3) checks and 1e-12 for the affine round trip
 * are fixed accuracy targets, not derived bounds (the measured errors are
 * 1e-15..2e-14 and 5e-14).
 * Where the error depends on the problem the tolerance is computed from it:
 * logm near a half turn scales by the log's condition number th / sin th, the
 * inverse by eps cond(A), expm on contracting inputs by u ||A||_1 (each
 * explained at its check). The PRNG is testkit.h's splitmix64 with a fixed
 * seed, so every run is the same.
 */
#include "testkit.h"

#define N_TWISTS 100000 /* random and adversarial twists, across the families */
#define N_AFFINE 5000   /* random affine matrices for the expm/logm round trip */
#define N_FAMILIES 8

static const double PI = TK_PI;

static double trans_len(ga_mat4 m) { return sqrt(m.m[3] * m.m[3] + m.m[7] * m.m[7] + m.m[11] * m.m[11]); }

/* max |a - b| / max(1, |t_b|); NaN if an entry is NaN */
static double mat_err(ga_mat4 a, ga_mat4 b)
{
    double e = 0;
    for (int i = 0; i < 16; i++) {
        double d = fabs(a.m[i] - b.m[i]);
        if (isnan(d))
            return NAN;
        e = fmax(e, d);
    }
    return e / fmax(1.0, trans_len(b));
}

/* max |a - b| / max(1, |v_b|) */
static double twist_err(ga_twist a, ga_twist b)
{
    double d[6] = {a.w.x - b.w.x, a.w.y - b.w.y, a.w.z - b.w.z, a.v.x - b.v.x, a.v.y - b.v.y, a.v.z - b.v.z};
    double e = 0;
    for (int i = 0; i < 6; i++) {
        if (isnan(d[i]))
            return NAN;
        e = fmax(e, fabs(d[i]));
    }
    return e / fmax(1.0, tk_norm(b.v));
}

/* ---- twist families: testkit.h's, in this order ---------------------------- */
/* The first six have |w| < pi (their twists are principal logs). */
static const int family[N_FAMILIES] = {
    TK_SCREW,       TK_TINY_UNDER_LARGE, TK_ROT_SPREAD, TK_ROT_NEAR_PI_SPREAD,
    TK_TRANSLATION, TK_NEAR_IDENTITY,    TK_ROT_PI,     TK_BEYOND_PI};
#define HALF_TURN 6 /* index of TK_ROT_PI above */
#define BEYOND 7    /* index of TK_BEYOND_PI */

/* ---- affine matrices ---------------------------------------------------- */
/* A = [Q T Q^T, t; 0 1]: Q a random rotation, T upper (block) triangular with
 * either three positive eigenvalues or one positive eigenvalue and a complex
 * pair r e^{+-i phi}, |phi| < 0.95 pi, moduli log-uniform in 1e-3..1e3, and
 * shears up to 10 sqrt(d_i d_j) above the diagonal. Positive determinant and
 * no eigenvalue on the negative real axis, so the real principal log exists.
 * Kept only if cond_1(A) <= 1e6. */
static ga_mat4 random_affine(tk_rng *s, double *cond)
{
    for (;;) {
        double t[3][3] = {{0}}, d[3];
        for (int i = 0; i < 3; i++) d[i] = tk_loguni(s, 1e-3, 1e3);
        for (int i = 0; i < 3; i++) t[i][i] = d[i];
        if (tk_uni(s) < 0.5) { /* a rotation-scaling block in rows/cols 1,2 */
            double phi = tk_range(s, -0.95 * PI, 0.95 * PI);
            t[1][1] = d[1] * cos(phi);
            t[1][2] = -d[1] * sin(phi);
            t[2][1] = d[1] * sin(phi);
            t[2][2] = d[1] * cos(phi);
            d[2] = d[1];
        }
        double h = tk_loguni(s, 1e-3, 10.0);
        t[0][1] = h * sqrt(d[0] * d[1]) * tk_range(s, -1, 1);
        t[0][2] = h * sqrt(d[0] * d[2]) * tk_range(s, -1, 1);
        if (t[2][1] == 0)
            t[1][2] = h * sqrt(d[1] * d[2]) * tk_range(s, -1, 1);
        ga_vec3 qn = tk_unit(s);
        ga_twist q = {tk_scale(qn, tk_range(s, 0, PI)), {0, 0, 0}};
        ga_mat4 qm = ga_se3_exp(q), a = ga_mat4_identity();
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++) {
                double acc = 0;
                for (int k = 0; k < 3; k++)
                    for (int l = 0; l < 3; l++) acc += qm.m[4 * i + k] * t[k][l] * qm.m[4 * j + l];
                a.m[4 * i + j] = acc;
            }
        ga_vec3 tn = tk_unit(s), tr = tk_scale(tn, tk_loguni(s, 1e-3, 1e3));
        a.m[3] = tr.x;
        a.m[7] = tr.y;
        a.m[11] = tr.z;
        ga_mat4 inv;
        if (ga_mat4_inverse(a, &inv) != GA_OK)
            continue;
        *cond = ga_mat4_norm1(a) * ga_mat4_norm1(inv);
        if (*cond <= 1e6)
            return a;
    }
}

static ga_mat4 mat(const double v[16])
{
    ga_mat4 m;
    memcpy(m.m, v, sizeof m.m);
    return m;
}

static ga_mat4 sentinel(void)
{
    ga_mat4 m;
    for (int i = 0; i < 16; i++) m.m[i] = 12345.0;
    return m;
}
static int is_sentinel(ga_mat4 m)
{
    for (int i = 0; i < 16; i++)
        if (m.m[i] != 12345.0)
            return 0;
    return 1;
}

/* Runs f on a and checks its status; that out was left untouched is one
 * check over all the calls. */
static void expect_fail(const char *name, int (*f)(ga_mat4, ga_mat4 *), ga_mat4 a, int want)
{
    ga_mat4 out = sentinel();
    tk_expect_status(name, f(a, &out), want);
    tk_add_bool(tk_get("failed calls leave their output untouched"), is_sentinel(out));
}

static const double eps = DBL_EPSILON;
static const uint64_t seed = 0x67617230746f72ull; /* "gar0tor" */

/* ---- 1. Eberly's closed-form exp against the general Pade expm ------- */
static void section_exp(void)
{
    /* Both are backward stable. For th in (pi, 3pi) the error is measured
     * against max(1, |v|, |t|): near th = 2pi, |t| = |V v| is far below |v|
     * (V across the axis is sin(th)/th ~ (2pi - th)/2pi), and the rounding of
     * th itself, EPS th, moves t by ~EPS |v| / 2pi: the exp of a twist is
     * known to EPS |v| there, not to EPS |t|. (Against max(1, |t|) this
     * family measured 2.1e-13 over 2e6 draws, 1.3e-13 over these; against
     * max(1, |v|, |t|), 2.9e-15.) Elsewhere |t| >= 2|v|/pi and the measure is
     * max(1, |t|). Measured ~1e-15. */
    {
        tk_check c[N_FAMILIES];
        for (int f = 0; f < N_FAMILIES; f++)
            c[f] = tk_beginf(1e-13, "se3_exp = expm(hat), / max(1,|t|%s): %s", f == BEYOND ? ",|v|" : "",
                             tk_family_name[family[f]]);
        tk_rng s = {seed};
        for (long i = 0; i < N_TWISTS; i++) {
            int fam = (int)(i % N_FAMILIES);
            ga_twist xi = tk_twist(&s, family[fam]);
            ga_mat4 e1 = ga_se3_exp(xi), e2;
            int st = ga_mat4_expm(ga_twist_hat(xi), &e2);
            double e = st == GA_OK ? mat_err(e2, e1) : INFINITY;
            if (fam == BEYOND) /* relative to max(1, |v|, |t|) */
                e *= fmax(1.0, trans_len(e1)) / fmax(fmax(1.0, tk_norm(xi.v)), trans_len(e1));
            tk_add(&c[fam], e);
        }
        for (int f = 0; f < N_FAMILIES; f++) tk_end(&c[f]);
    }
}

/* ---- 2. log(exp(xi)) = xi for angles < pi ----------------------------- */
static void section_log(void)
{
    tk_check c[6];
    for (int f = 0; f < 6; f++) /* the families with |w| < pi */
        c[f] = tk_beginf(1e-13, "se3_log(se3_exp(xi)) = xi: %s", tk_family_name[family[f]]);
    tk_rng s = {seed ^ 1};
    for (long i = 0; i < N_TWISTS; i++) {
        int fam = (int)(i % 6);
        ga_twist xi = tk_twist(&s, family[fam]), back;
        int st = ga_se3_log(ga_se3_exp(xi), &back);
        tk_add(&c[fam], st == GA_OK ? twist_err(back, xi) : INFINITY);
    }
    for (int f = 0; f < 6; f++) tk_end(&c[f]);
}

/* ---- 3. half turns and beyond: the backward error ---------------------- */
static void section_half_turn(void)
{
    tk_check back = tk_begin("th = pi: |exp(log M) - M|", 1e-13);
    tk_check axis = tk_begin("th = pi: w = +-pi n", 1e-13);
    tk_check angle = tk_begin("th = pi: |w| = pi", 1e-13);
    tk_rng s = {seed ^ 2};
    for (long i = 0; i < N_TWISTS / 4; i++) {
        ga_twist xi = tk_twist(&s, family[HALF_TURN]), l;
        ga_mat4 m = ga_se3_exp(xi);
        if (i % 2) { /* an exactly symmetric R = 2 n n^T - I: skew part 0 */
            ga_vec3 u = tk_unit(&s);
            double uv[3] = {u.x, u.y, u.z};
            for (int r = 0; r < 3; r++)
                for (int c = 0; c < 3; c++) m.m[4 * r + c] = 2 * uv[r] * uv[c] - (r == c);
            xi.w = tk_scale(u, PI);
        }
        int st = ga_se3_log(m, &l);
        if (st != GA_OK) {
            tk_add(&back, INFINITY);
            continue;
        }
        tk_add(&back, mat_err(ga_se3_exp(l), m));
        /* either sign of the axis: the angle is pi and w = +-xi.w */
        double dp = 0, dm = 0;
        double a[3] = {l.w.x, l.w.y, l.w.z}, b[3] = {xi.w.x, xi.w.y, xi.w.z};
        for (int k = 0; k < 3; k++) {
            dp = fmax(dp, fabs(a[k] - b[k]));
            dm = fmax(dm, fabs(a[k] + b[k]));
        }
        tk_add(&axis, isnan(tk_norm(l.w)) ? NAN : fmin(dp, dm));
        tk_add(&angle, fabs(tk_norm(l.w) - PI));
    }
    tk_end(&back);
    tk_end(&axis);
    tk_end(&angle);
    tk_check back7 = tk_begin("th in (pi, 3pi): |exp(log M) - M|", 1e-13);
    tk_check over = tk_begin("th in (pi, 3pi): principal, |w| - pi <= 0", 4 * eps);
    for (long i = 0; i < N_TWISTS / 4; i++) {
        ga_twist xi = tk_twist(&s, family[BEYOND]), l;
        ga_mat4 m = ga_se3_exp(xi);
        if (ga_se3_log(m, &l) != GA_OK) {
            tk_add(&back7, INFINITY);
            continue;
        }
        tk_add(&back7, mat_err(ga_se3_exp(l), m));
        tk_add(&over, tk_norm(l.w) - PI);
    }
    tk_end(&back7);
    tk_end(&over);
}

/* ---- 4. logm against se3_log on rigid inputs -------------------------- */
static void section_logm(void)
{
    /* The general log knows nothing of orthogonality, so near a half turn its
     * error is bounded by its condition number th / sin th (the divided
     * difference of log over the eigenvalues e^{+-i th}) times eps: the
     * tolerance is 1e-13 times that. A rigid motion turning by more than
     * pi/2 takes the closed form inside logm (mat4.h), so GA_ERR_DOMAIN can
     * only come at a skew part of exactly 0; it is still accepted only when
     * pi - th <= 1e-10 max(1, |t|), and the count is printed. */
    {
        tk_check c[6];
        for (int f = 0; f < 6; f++)
            c[f] = tk_beginf(1.0, "logm = hat(se3_log), / (1e-13 th/sin th): %s", tk_family_name[family[f]]);
        tk_check wrel = tk_begin("logm: w relative to |w|, th in 1e-12..1", 1e-13);
        tk_check status = tk_begin("se3_log status", 0);
        double domain_max = 0;
        tk_rng s = {seed ^ 3};
        long domain = 0;
        for (long i = 0; i < N_TWISTS; i++) {
            int fam = (int)(i % 6);
            ga_twist xi = tk_twist(&s, family[fam]), l1;
            ga_mat4 m = ga_se3_exp(xi), l2;
            int st1 = ga_se3_log(m, &l1);
            tk_add_status(&status, st1, GA_OK);
            if (st1 != GA_OK)
                continue;
            int st = ga_mat4_logm(m, &l2);
            double th = tk_norm(l1.w);
            double cond = th > 0 ? th / sin(th) : 1.0;
            double margin = (PI - th) / fmax(1.0, trans_len(m));
            if (st == GA_ERR_DOMAIN && margin <= 1e-10) {
                domain++;
                domain_max = fmax(domain_max, margin);
                continue;
            }
            tk_add(&c[fam], st == GA_OK ? mat_err(l2, ga_twist_hat(l1)) / (1e-13 * cond) : INFINITY);
            if ((fam == 1 || fam == 2) && st == GA_OK) { /* w relative to itself */
                ga_twist l3 = ga_twist_vee(l2);
                ga_vec3 dw = {l3.w.x - l1.w.x, l3.w.y - l1.w.y, l3.w.z - l1.w.z};
                tk_add(&wrel, tk_norm(dw) / tk_norm(l1.w));
            }
        }
        for (int f = 0; f < 6; f++) tk_end(&c[f]);
        tk_end(&status);
        tk_note("     GA_ERR_DOMAIN within rounding of pi: %ld cases, (pi - th)/max(1,|t|) <= %.2e\n", domain,
                domain_max);
        /* Tiny rotations under large translations: logm's w keeps relative
         * accuracy, not only accuracy relative to |v| (the rotation block of
         * each root and solve never mixes with the translation column, and
         * vee reads the skew part). 1e-13 relative to |w| itself. */
        tk_end(&wrel);
    }
}

/* ---- 5. the general exp and log on affine matrices --------------------- */
static void section_affine(void)
{
    tk_check rt = tk_begin("expm(logm(A)) = A, affine: ||.||_1 / ||A||_1", 1e-12);
    tk_check inv = tk_begin("mat4_inverse: ||A A^-1 - I||_1 / (eps cond A)", 16.0);
    tk_check status = tk_begin("affine logm, expm, inverse: status", 0);
    double maxcond = 0;
    tk_rng s = {seed ^ 4};
    long hard = 0;
    for (long i = 0; i < N_AFFINE; i++) {
        double cond;
        ga_mat4 a = random_affine(&s, &cond), l, b, ai;
        maxcond = fmax(maxcond, cond);
        hard += cond > 1e5;
        int st = ga_mat4_logm(a, &l);
        if (st == GA_OK)
            st = ga_mat4_expm(l, &b);
        tk_add_status(&status, st, GA_OK);
        if (st != GA_OK) {
            tk_add(&rt, INFINITY);
            continue;
        }
        for (int k = 0; k < 16; k++) b.m[k] -= a.m[k];
        tk_add(&rt, ga_mat4_norm1(b) / ga_mat4_norm1(a));
        /* the inverse: residual ||A A^-1 - I||_1 <= c n eps cond(A) for
         * Gaussian elimination with partial pivoting; measured as a
         * multiple of eps cond(A) */
        tk_add_status(&status, ga_mat4_inverse(a, &ai), GA_OK);
        ga_mat4 r = ga_mat4_mul(a, ai);
        for (int k = 0; k < 4; k++) r.m[5 * k] -= 1.0;
        tk_add(&inv, ga_mat4_norm1(r) / (eps * cond));
    }
    tk_note("     condition numbers up to %.3e (%ld above 1e5)\n", maxcond, hard);
    tk_end(&rt);
    tk_end(&inv);
    tk_end(&status);
}

/* ---- 6. identities and closed forms ----------------------------------- */
static void section_identities(void)
{
    tk_rng s = {seed ^ 5};
    tk_check hv = tk_begin("vee(hat(xi)) = xi", 0.0);
    tk_check check = tk_begin("se3_exp output passes se3_check(., GA_SE3_TOL and 1e-14)", 0);
    tk_check sinv = tk_begin("se3_inverse = mat4_inverse on rigid", 1e-13);
    tk_check geo = tk_begin("geodesic: F(0) = h0, F(1) = h1, / max(1,|t0|,|t1|)", 1e-13);
    tk_check mid = tk_begin("geodesic: (F(1/2) h0^-1)^2 = h1 h0^-1, same scale", 1e-13);
    tk_check adj = tk_begin("adjoint: exp(Ad_g xi) = g exp(xi) g^-1, / max(1,|t_g|)", 1e-13);
    long n = N_TWISTS / 4;
    for (long i = 0; i < n; i++) {
        ga_twist a = tk_twist(&s, family[i % 6]), b = tk_twist(&s, family[i % 6]);
        ga_twist c = tk_twist(&s, family[(i + 3) % 6]), v = ga_twist_vee(ga_twist_hat(a));
        tk_add(&hv, twist_err(v, a));
        ga_mat4 h0 = ga_se3_exp(a), h1 = ga_se3_exp(b), g = ga_se3_exp(c), f, gi;
        tk_add_bool(&check, ga_se3_check(h0, GA_SE3_TOL) == GA_OK && ga_se3_check(h1, 1e-14) == GA_OK);
        TK_OK(ga_mat4_inverse(g, &gi));
        tk_add(&sinv, mat_err(ga_se3_inverse(g), gi));
        /* geodesic: F(0) = h0, F(1) = h1, and F(1/2) h0^-1 squared = h1 h0^-1.
         * h1 h0^-1 and its product with h0 round at the scale of both
         * translations, so errors are relative to max(1, |t0|, |t1|). */
        double sc = fmax(1.0, fmax(trans_len(h0), trans_len(h1)));
        TK_OK(ga_se3_geodesic(h0, h1, 0.0, &f));
        tk_add(&geo, mat_err(f, h0) * fmax(1.0, trans_len(h0)) / sc);
        TK_OK(ga_se3_geodesic(h0, h1, 1.0, &f));
        tk_add(&geo, mat_err(f, h1) * fmax(1.0, trans_len(h1)) / sc);
        TK_OK(ga_se3_geodesic(h0, h1, 0.5, &f));
        ga_mat4 half = ga_mat4_mul(f, ga_se3_inverse(h0)), dd = ga_mat4_mul(h1, ga_se3_inverse(h0));
        tk_add(&mid, mat_err(ga_mat4_mul(half, half), dd) * fmax(1.0, trans_len(dd)) / sc);
        /* adjoint: exp(Ad_g xi) = g exp(xi) g^-1 */
        ga_mat4 lhs = ga_se3_exp(ga_se3_adjoint(g, a));
        ga_mat4 rhs = ga_mat4_mul(ga_mat4_mul(g, h0), ga_se3_inverse(g));
        tk_add(&adj, mat_err(lhs, rhs) / fmax(1.0, tk_norm(c.v)));
    }
    tk_end(&hv);
    tk_end(&check);
    tk_end(&sinv);
    tk_end(&geo);
    tk_end(&mid);
    tk_end(&adj);

    /* expm closed forms: a diagonal (the contracting squarings), a Jordan
     * block, and a nilpotent N (N^2 = 0) whose 1-norm overflows, for which
     * exp = I + N. Error bound per entry: r_m(x) at x = -th (th =
     * ||A/2^s||_1 <= theta_13 = 5.37) is summed with cancellation
     * e^th, so its relative error is about u e^th; the 2^s = ||A||_1 / th
     * squarings multiply that exponent error, giving
     * u ||A||_1 e^th / th <= 40 u ||A||_1. */
    const double u = 0.5 * eps;
    double d[4] = {-50, -20, 1, 3};
    tk_check c;
    int st;
    ga_mat4 a = mat((double[16]){-50, 0, 0, 0, 0, -20, 0, 0, 0, 0, 1, 0, 0, 0, 0, 3}), r;
    c = tk_begin("expm(diag(-50,-20,1,3)) per entry, relative", 40 * u * 50);
    st = ga_mat4_expm(a, &r);
    for (int k = 0; k < 4; k++) tk_add(&c, st == GA_OK ? fabs(r.m[5 * k] - exp(d[k])) / exp(d[k]) : INFINITY);
    tk_end(&c);
    ga_mat4 j = mat((double[16]){-30, 1, 0, 0, 0, -30, 1, 0, 0, 0, -30, 0, 0, 0, 0, 0});
    c = tk_begin("expm(Jordan block at -30) per entry, relative", 40 * u * 31);
    st = ga_mat4_expm(j, &r);
    double ej = exp(-30.0), want[16] = {ej, ej, ej / 2, 0, 0, ej, ej, 0, 0, 0, ej, 0, 0, 0, 0, 1};
    for (int k = 0; k < 16; k++)
        tk_add(&c, st == GA_OK ? fabs(r.m[k] - want[k]) / (want[k] != 0 ? want[k] : 1) : INFINITY);
    tk_end(&c);
    ga_mat4 nil = mat((double[16]){0, 0, 0, DBL_MAX, 0, 0, 0, DBL_MAX, 0, 0, 0, -DBL_MAX, 0, 0, 0, 0});
    c = tk_begin("expm(N), N^2 = 0, ||N||_1 = inf: I + N, relative", 4 * eps);
    st = ga_mat4_expm(nil, &r);
    for (int k = 0; k < 16; k++) {
        double w = nil.m[k] + (k % 5 == 0);
        tk_add(&c, st == GA_OK ? fabs(r.m[k] - w) / fmax(1.0, fabs(w)) : INFINITY);
    }
    tk_end(&c);
    ga_mat4 ln;
    c = tk_begin("logm(I) = 0", 0.0);
    tk_add(&c, ga_mat4_logm(ga_mat4_identity(), &ln) == GA_OK ? ga_mat4_norm1(ln) : INFINITY);
    tk_end(&c);
    ga_mat4 sc = mat((double[16]){1e-3, 0, 0, 5, 0, 1e3, 0, -2, 0, 0, 2, 1e3, 0, 0, 0, 1});
    c = tk_begin("logm(diag scales) diagonal = log, relative", 1e-13);
    st = ga_mat4_logm(sc, &ln);
    const double want_log[3] = {log(1e-3), log(1e3), log(2.0)};
    for (int k = 0; k < 3; k++)
        tk_add(&c, st == GA_OK ? fabs(ln.m[5 * k] - want_log[k]) / fabs(want_log[k]) : INFINITY);
    tk_end(&c);
    /* small parts under large ones: a scaling of 1 + 1e-10 under a
     * translation of 1e6, compared with log1p of the stored entry */
    ga_mat4 tiny = mat((double[16]){1 + 1e-10, 3e-9, 0, 1e6, 0, 1 - 2e-10, 0, -5e5, 0, 0, 1 + 3e-10, 2e5, 0,
                                    0, 0, 1});
    c = tk_begin("logm(I + 1e-10 D, t = 1e6) diagonal, relative", 1e-13);
    st = ga_mat4_logm(tiny, &ln);
    for (int k = 0; k < 3; k++)
        tk_add(&c, st == GA_OK ? fabs(ln.m[5 * k] - log1p(tiny.m[5 * k] - 1)) / fabs(log1p(tiny.m[5 * k] - 1))
                               : INFINITY);
    tk_end(&c);
    /* se3_exp(pi e3) has eigenvalues -1 +- 1.2e-16 i (sin(pi) in double):
     * one rounding off the axis, so a principal log exists; logm finds it
     * (the singular-looking (A + I)/2 is regular after equilibration) and
     * it is se3_log's answer. */
    ga_twist half = {{0, 0, PI}, {1, 2, 3}}, lh;
    ga_mat4 mh = ga_se3_exp(half);
    TK_OK(ga_se3_log(mh, &lh));
    c = tk_begin("logm(se3_exp(pi e3)) = hat(se3_log(.))", 1e-13);
    tk_add(&c, ga_mat4_logm(mh, &ln) == GA_OK ? mat_err(ln, ga_twist_hat(lh)) : INFINITY);
    tk_end(&c);
    /* badly scaled but regular: |t| = 1e16 (normwise condition 1e32) */
    ga_twist far = {{0.3, -0.2, 0.1}, {1e16, -3e15, 2e14}};
    ga_mat4 mf = ga_se3_exp(far), mi;
    c = tk_begin("mat4_inverse(rigid, |t| = 1e16) = se3_inverse", 1e-13);
    tk_add(&c, ga_mat4_inverse(mf, &mi) == GA_OK ? mat_err(mi, ga_se3_inverse(mf)) : INFINITY);
    tk_end(&c);
    ga_twist lf;
    TK_OK(ga_se3_log(mf, &lf));
    c = tk_begin("logm(rigid, |t| = 1e16) = hat(se3_log(.))", 1e-13);
    tk_add(&c, ga_mat4_logm(mf, &ln) == GA_OK ? mat_err(ln, ga_twist_hat(lf)) : INFINITY);
    tk_end(&c);
    /* a sweep of translations 1 .. 1e18 (the root count grows to 60) */
    c = tk_begin("logm(rigid, |t| = 1 .. 1e18) = hat(se3_log(.))", 1e-13);
    for (int k = 0; k <= 18; k++) {
        ga_twist sw = {{0.7, -0.4, 1.1}, {pow(10, k), -0.3 * pow(10, k), 2.0}};
        ga_mat4 ms = ga_se3_exp(sw);
        TK_OK(ga_se3_log(ms, &lf));
        tk_add(&c, ga_mat4_logm(ms, &ln) == GA_OK ? mat_err(ln, ga_twist_hat(lf)) : INFINITY);
    }
    tk_end(&c);
    ga_mat4 dd = mat((double[16]){1e-20, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1e20, 0, 0, 0, 0, 1});
    c = tk_begin("mat4_inverse(diag(1e-20, 1, 1e20, 1))", eps);
    st = ga_mat4_inverse(dd, &mi);
    tk_add(&c, st == GA_OK ? fabs(mi.m[0] * 1e-20 - 1) : INFINITY);
    tk_add(&c, st == GA_OK ? fabs(mi.m[10] * 1e20 - 1) : INFINITY);
    tk_end(&c);
}

/* ---- 7. bad input: the right status, output untouched, no crash ------- */
static void section_bad_input(void)
{
    ga_mat4 id = ga_mat4_identity(), m;
    ga_twist tw, t0 = {{1, 2, 3}, {4, 5, 6}};
    m = id;
    m.m[6] = NAN;
    expect_fail("mat4_inverse(NaN)", ga_mat4_inverse, m, GA_ERR_NOTFINITE);
    expect_fail("mat4_expm(NaN)", ga_mat4_expm, m, GA_ERR_NOTFINITE);
    expect_fail("mat4_logm(NaN)", ga_mat4_logm, m, GA_ERR_NOTFINITE);
    m = id;
    m.m[3] = INFINITY;
    expect_fail("mat4_expm(Inf)", ga_mat4_expm, m, GA_ERR_NOTFINITE);
    expect_fail("mat4_logm(Inf)", ga_mat4_logm, m, GA_ERR_NOTFINITE);
    tw = t0;
    tk_expect_status("se3_log(Inf)", ga_se3_log(m, &tw), GA_ERR_NOTFINITE);
    tk_expect_status("se3_check(Inf)", ga_se3_check(m, 1e-9), GA_ERR_NOTFINITE);
    m = id;
    m.m[0] = NAN;
    tk_expect_status("se3_log(NaN)", ga_se3_log(m, &tw), GA_ERR_NOTFINITE);
    m = id;
    m.m[0] = m.m[5] = m.m[10] = 1.001;
    tk_expect_status("se3_log(scaled R)", ga_se3_log(m, &tw), GA_ERR_NOTRIGID);
    m = id;
    m.m[1] = 1e-6;
    tk_expect_status("se3_log(sheared R)", ga_se3_log(m, &tw), GA_ERR_NOTRIGID);
    m = id;
    m.m[0] = -1;
    tk_expect_status("se3_log(reflection)", ga_se3_log(m, &tw), GA_ERR_NOTRIGID);
    m = id;
    m.m[12] = 0.5;
    tk_expect_status("se3_log(last row 0.5 0 0 1)", ga_se3_log(m, &tw), GA_ERR_NOTRIGID);
    m = id;
    m.m[15] = 2;
    tk_expect_status("se3_log(last row 0 0 0 2)", ga_se3_log(m, &tw), GA_ERR_NOTRIGID);
    tk_expect(tw.w.x == 1 && tw.v.z == 6, "se3_log: a failed call leaves its output untouched");
    m = ga_se3_exp(t0);
    m.m[0] += 1e-12; /* slightly off: accepted */
    tk_expect_status("se3_log(R off by 1e-12)", ga_se3_log(m, &tw), GA_OK);
    m.m[0] += 1e-8; /* far off */
    tk_expect_status("se3_log(R off by 1e-8)", ga_se3_log(m, &tw), GA_ERR_NOTRIGID);
    tk_expect_status("se3_check(I, NaN tol)", ga_se3_check(id, NAN), GA_ERR_NOTRIGID);

    m = id;
    for (int k = 0; k < 4; k++) m.m[5 * k] = 1000;
    expect_fail("mat4_expm(1000 I) overflows", ga_mat4_expm, m, GA_ERR_DOMAIN);
    for (int k = 0; k < 4; k++) m.m[5 * k] = -1000;
    ga_mat4 r;
    tk_expect(ga_mat4_expm(m, &r) == GA_OK && ga_mat4_norm1(r) == 0, "mat4_expm(-1000 I) underflows to 0");
    m = id;
    m.m[0] = DBL_MAX;
    m.m[4] = DBL_MAX;
    expect_fail("mat4_expm(entries DBL_MAX)", ga_mat4_expm, m, GA_ERR_DOMAIN);

    expect_fail("mat4_logm(half turn diag(1,-1,-1,1))", ga_mat4_logm,
                mat((double[16]){1, 0, 0, 0, 0, -1, 0, 0, 0, 0, -1, 0, 0, 0, 0, 1}), GA_ERR_DOMAIN);
    expect_fail("mat4_logm(diag(-2,-3,1,1)), det > 0", ga_mat4_logm,
                mat((double[16]){-2, 0, 0, 0, 0, -3, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}), GA_ERR_DOMAIN);
    expect_fail("mat4_logm(-I)", ga_mat4_logm,
                mat((double[16]){-1, 0, 0, 0, 0, -1, 0, 0, 0, 0, -1, 0, 0, 0, 0, -1}), GA_ERR_DOMAIN);
    expect_fail("mat4_logm(Jordan block at -1)", ga_mat4_logm,
                mat((double[16]){-1, 1, 0, 0, 0, -1, 0, 0, 0, 0, 2, 0, 0, 0, 0, 1}), GA_ERR_DOMAIN);
    expect_fail("mat4_logm(det < 0: a negative eigenvalue)", ga_mat4_logm,
                mat((double[16]){2, 1, 0, 3, 1, -0.5, 1, 0, 0, 0.2, 1, 0, 0, 0, 0, 1}), GA_ERR_DOMAIN);
    ga_mat4 sing = mat((double[16]){1, 2, 3, 0, 2, 4, 6, 0, 1, 1, 1, 0, 0, 0, 0, 1});
    expect_fail("mat4_logm(rank 3)", ga_mat4_logm, sing, GA_ERR_SINGULAR);
    expect_fail("mat4_inverse(rank 3)", ga_mat4_inverse, sing, GA_ERR_SINGULAR);
    m = id;
    m.m[10] = 0;
    expect_fail("mat4_logm(diag(1,1,0,1))", ga_mat4_logm, m, GA_ERR_SINGULAR);
    expect_fail("mat4_inverse(0)", ga_mat4_inverse, mat((double[16]){0}), GA_ERR_SINGULAR);

    ga_mat4 g = sentinel();
    tk_expect_status("se3_geodesic(t = NaN)", ga_se3_geodesic(id, id, NAN, &g), GA_ERR_NOTFINITE);
    m = id;
    m.m[0] = 2;
    tk_expect_status("se3_geodesic(h1 not rigid)", ga_se3_geodesic(id, m, 0.5, &g), GA_ERR_NOTRIGID);
    m = id;
    m.m[7] = NAN;
    tk_expect_status("se3_geodesic(h0 NaN)", ga_se3_geodesic(m, id, 0.5, &g), GA_ERR_NOTFINITE);
    tk_expect(is_sentinel(g), "se3_geodesic: a failed call leaves its output untouched");
}

/* ---- keys near the group: ga_se3_normalize, ga_quat_normalize --------- */
static void section_normalize(void)
{
    /* A rigid motion with every entry of its 3x3 block moved by up to 1e-4
     * (max |R^T R - I| then below 1e-3) comes back as R' with R'^T R' = I to
     * rounding and R'^T M symmetric (R' the orthogonal polar factor of M, the
     * nearest rotation); 2e-3 off is refused. */
    {
        tk_check c_orth = tk_begin("se3_normalize: R^T R = I (entries off by 1e-4 in)", 4 * eps);
        tk_check c_pol = tk_begin("se3_normalize: R^T M symmetric (the polar factor)", 8 * eps);
        tk_check c_far = tk_begin("se3_normalize / quat_normalize: 1e-3 off or more refused, less taken", 0);
        tk_rng s = {seed + 7};
        for (int i = 0; i < 2000; i++) {
            ga_mat4 m = ga_se3_exp(tk_twist(&s, 0)), r;
            for (int a = 0; a < 3; a++)
                for (int b = 0; b < 3; b++) m.m[4 * a + b] += tk_range(&s, -1e-4, 1e-4);
            int st = ga_se3_normalize(m, GA_SE3_NORMALIZE_TOL, &r);
            tk_add_status(&c_far, st, GA_OK);
            double e = 0, p = 0;
            for (int a = 0; a < 3; a++)
                for (int b = 0; b < 3; b++) {
                    double g = 0, h = 0, k = 0;
                    for (int q = 0; q < 3; q++) {
                        g += r.m[4 * q + a] * r.m[4 * q + b];
                        h += r.m[4 * q + a] * m.m[4 * q + b];
                        k += r.m[4 * q + b] * m.m[4 * q + a];
                    }
                    e = fmax(e, fabs(g - (a == b)));
                    p = fmax(p, fabs(h - k));
                }
            tk_add(&c_orth, e);
            tk_add(&c_pol, p);
            ga_mat4 far = m;
            far.m[0] += 2e-3;
            tk_add_status(&c_far, ga_se3_normalize(far, GA_SE3_NORMALIZE_TOL, &r), GA_ERR_NOTRIGID);
            double dq = tk_range(&s, -1e-3, 1e-3), n2 = (1 + dq) / 2;
            ga_quat q = {n2, n2, n2, n2}, u;
            tk_add_status(&c_far, ga_quat_normalize(q, GA_SE3_NORMALIZE_TOL, &u), GA_OK);
            q.w = q.x = q.y = q.z = (1 + 1.5e-3) / 2;
            tk_add_status(&c_far, ga_quat_normalize(q, GA_SE3_NORMALIZE_TOL, &u), GA_ERR_NOTRIGID);
        }
        tk_end(&c_orth);
        tk_end(&c_pol);
        tk_end(&c_far);
    }
}

/* ---- logm: no real log however ill-conditioned -------------------------- */
static void section_logm_no_real(void)
{
    /* det < 0 is a negative real eigenvalue: GA_ERR_DOMAIN, also where the
       LU's pivot test calls A singular first (it said GA_ERR_SINGULAR; a
       lihao2 factor on affine keys had eigenvalues 5.1e15, 38, -4.5). Exact
       cases: the block [a a; a a-d] (a = 1e16, 2^60, 3e17; d = 2, 4, 6 ulps
       of a, about 4 eps a) has det -a d exactly, eigenvalues near 2a and
       -d/2, and its second pivot -d fails the test (15 of the 18 did;
       equilibration cannot help: both rows have the same scale); in a
       homogeneous matrix with a
       translation, or beside a 2x2 rotation. d = 0 (rank 1 block) stays
       GA_ERR_SINGULAR */
    {
        static const double as[3] = {1e16, 0x1p60, 3e17};
        tk_check dom = tk_begin("logm of [a a; a a-d] blocks, det -a d < 0, d 2..6 ulps of a: GA_ERR_DOMAIN",
                                0);
        tk_check sng = tk_begin("logm of [a a; a a] blocks (det 0): GA_ERR_SINGULAR", 0);
        for (int ai = 0; ai < 3; ai++)
            for (int k = 0; k <= 3; k++)
                for (int form = 0; form < 2; form++) {
                    double a = as[ai], d = k * 2.0 * ldexp(DBL_EPSILON, ilogb(a)); /* k ulps */
                    ga_mat4 m = ga_mat4_identity(), out;
                    m.m[0] = m.m[1] = m.m[4] = a;
                    m.m[5] = a - d;
                    if (form == 0)
                        m.m[3] = 3.0, m.m[7] = -2.0, m.m[11] = 0.5;
                    else /* beside a rotation by 0.3 in axes 2, 3 */
                        m.m[10] = m.m[15] = cos(0.3), m.m[11] = -sin(0.3), m.m[14] = sin(0.3);
                    if (k == 0)
                        tk_add_status(&sng, ga_mat4_logm(m, &out), GA_ERR_SINGULAR);
                    else
                        tk_add_status(&dom, ga_mat4_logm(m, &out), GA_ERR_DOMAIN);
                }
        tk_end(&dom);
        tk_end(&sng);
    }
}

/* ---- angles whose square overflows (|w| from 1e154 to 1e308) -------------- */
static void section_overflow(void)
{
    /* se3_exp of such a twist lost the n n^T term with th^2 (cos th I +
       sin th [n]x, no rotation) and gave NaN with a translation; rotor_exp
       gave NaN. Both give the rotation by the double angle: se3_exp passes
       se3_check and agrees with the rotor's matrix to 1e-13 / max(1, |t|) (both take the angle from the same
       rounding of the norm), and the translation along the axis is v's, to 1e-13 |v| */
    {
        tk_rng s = {0x5e3b16}; /* its own stream */
        tk_check rig = tk_begin("se3_exp of an angle 1e154..1e308: passes se3_check(GA_SE3_TOL)", 0);
        tk_check agr = tk_begin("se3_exp = rotor_to_mat4(rotor_exp) there, / max(1,|t|)", 1e-13);
        tk_check axi = tk_begin("its translation along the axis is v's, / |v|", 1e-13);
        for (long i = 0; i < 2000; i++) {
            ga_vec3 u = tk_unit(&s), d = tk_unit(&s);
            double th = tk_loguni(&s, 1e154, 1e308), vs = i % 2 ? tk_loguni(&s, 1e-3, 1e300) : 0.0;
            ga_twist xi = {tk_scale(u, th), tk_scale(d, vs)};
            ga_mat4 m = ga_se3_exp(xi);
            ga_mat4 r = ga_rotor_to_mat4(ga_rotor_exp(ga_twist_to_generator(xi)));
            tk_add_status(&rig, ga_se3_check(m, GA_SE3_TOL), GA_OK);
            tk_add(&agr, mat_err(m, r));
            double along = m.m[3] * u.x + m.m[7] * u.y + m.m[11] * u.z,
                   want = vs * (d.x * u.x + d.y * u.y + d.z * u.z);
            tk_add(&axi, vs > 0 ? fabs(along - want) / vs : 0.0);
        }
        tk_end(&rig);
        tk_end(&agr);
        tk_end(&axi);
    }
}

static const tk_section sections[] = {
    {"exp", section_exp, 0},
    {"log", section_log, 0},
    {"half_turn", section_half_turn, 0},
    {"logm", section_logm, 0},
    {"affine", section_affine, 0},
    {"identities", section_identities, 0},
    {"bad_input", section_bad_input, 0},
    {"normalize", section_normalize, 0},
    {"logm_no_real", section_logm_no_real, 0},
    {"overflow", section_overflow, 0},
};

int main(int argc, char **argv) { return tk_main(argc, argv, "test_mat4", sections, TK_COUNT(sections)); }
