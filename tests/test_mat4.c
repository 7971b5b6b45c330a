/* tests/test_mat4.c: the SE(3) closed forms against the general expm/logm,
 * round trips, half turns, affine matrices, and bad input (issue 4).
 *
 * Every check prints one line: ok/FAIL, its name, the number of cases, the
 * worst measured error and the tolerance; families are broken down above
 * their summary line. The error measures:
 *   - matrix against matrix: max |entry difference| / max(1, |t|), t the
 *     reference's translation (issue 4: "relative to max(1, |translation|)");
 *   - twist against twist: max |component difference| / max(1, |v|);
 *   - the affine round trip: ||expm(logm(A)) - A||_1 / ||A||_1.
 * Tolerances: 1e-13 for the SE(3) checks and 1e-12 for the affine round trip
 * are issue 4's targets (the measured errors are 1e-15..2e-14 and 5e-14).
 * Where the error depends on the problem the tolerance is computed from it:
 * logm near a half turn scales by the log's condition number th / sin th, the
 * inverse by eps cond(A), expm on contracting inputs by u ||A||_1 (each
 * explained at its check). The PRNG is splitmix64 with a fixed seed, so
 * every run is the same.
 */
#include "testkit.h"

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#define N_TWISTS 100000 /* random and adversarial twists, across the families */
#define N_AFFINE 5000  /* random affine matrices for the expm/logm round trip */
#define N_FAMILIES 8

static const double PI = 3.14159265358979323846;

/* ---- random draws: testkit.h (splitmix64) ---------------------------- */

/* ---- reporting ---------------------------------------------------------- */
static int failures;

static void report(const char *name, long n, double worst, double tol)
{
    int ok = worst <= tol; /* a NaN worst fails */
    printf("%-4s %-52s n=%-6ld worst %.3e  tol %.1e\n", ok ? "ok" : "FAIL", name, n, worst, tol);
    if (!ok) failures++;
}

static void expect(const char *name, int got, int want)
{
    int ok = got == want;
    printf("%-4s %-52s status %d (want %d)\n", ok ? "ok" : "FAIL", name, got, want);
    if (!ok) failures++;
}

static double trans_len(ga_mat4 m)
{
    return sqrt(m.m[3] * m.m[3] + m.m[7] * m.m[7] + m.m[11] * m.m[11]);
}

/* max |a - b| / max(1, |t_b|) */
static double mat_err(ga_mat4 a, ga_mat4 b)
{
    double e = 0;
    for (int i = 0; i < 16; i++) e = fmax(e, fabs(a.m[i] - b.m[i]));
    return e / fmax(1.0, trans_len(b));
}

/* max |a - b| / max(1, |v_b|) */
static double twist_err(ga_twist a, ga_twist b)
{
    double d[6] = {a.w.x - b.w.x, a.w.y - b.w.y, a.w.z - b.w.z,
                   a.v.x - b.v.x, a.v.y - b.v.y, a.v.z - b.v.z};
    double e = 0;
    for (int i = 0; i < 6; i++) e = fmax(e, fabs(d[i]));
    if (e != e) return NAN;
    return e / fmax(1.0, tk_norm(b.v));
}

/* ---- twist families (issue 4) ------------------------------------------- */
static const char *family_name[N_FAMILIES] = {
    "generic (th < pi)", "tiny rotation, large translation", "small rotation",
    "near half turn (pi - 1e-12..1e-1)", "pure translation", "identity / zero",
    "half turn, |w| = pi", "beyond a half turn (pi..3pi)"};

static ga_twist random_twist(tk_rng *s, int fam)
{
    ga_twist xi;
    ga_vec3 n = tk_unit(s);
    double th = 0, vl = tk_loguni(s, 1e-3, 1e6);
    switch (fam) {
    case 0: th = tk_range(s, 0, PI); vl = tk_loguni(s, 1e-3, 1e3); break;
    case 1: th = tk_loguni(s, 1e-12, 1e-6); vl = tk_loguni(s, 1.0, 1e6); break;
    case 2: th = tk_loguni(s, 1e-6, 1.0); break;
    case 3: th = PI - (tk_uni(s) < 0.2 ? 1e-9 : tk_loguni(s, 1e-12, 1e-1)); break;
    case 4: th = 0; vl = tk_loguni(s, 1e-6, 1e6); break;
    case 5: th = 0; vl = tk_uni(s) < 0.5 ? 0.0 : tk_loguni(s, 1e-300, 1e-12);
            if (tk_uni(s) < 0.5) th = tk_loguni(s, 1e-300, 1e-12);
            break;
    case 6: th = PI; break;
    default: th = tk_range(s, PI, 3 * PI); break;
    }
    if (fam == 6 && tk_uni(s) < 0.3) { /* along a coordinate axis */
        ga_vec3 e[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
        n = e[tk_next(s) % 3];
    }
    xi.w = tk_scale(n, th);
    xi.v = tk_scale(tk_unit(s), vl);
    return xi;
}

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
            t[1][1] = d[1] * cos(phi); t[1][2] = -d[1] * sin(phi);
            t[2][1] = d[1] * sin(phi); t[2][2] = d[1] * cos(phi);
            d[2] = d[1];
        }
        double h = tk_loguni(s, 1e-3, 10.0);
        t[0][1] = h * sqrt(d[0] * d[1]) * tk_range(s, -1, 1);
        t[0][2] = h * sqrt(d[0] * d[2]) * tk_range(s, -1, 1);
        if (t[2][1] == 0) t[1][2] = h * sqrt(d[1] * d[2]) * tk_range(s, -1, 1);
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
        a.m[3] = tr.x; a.m[7] = tr.y; a.m[11] = tr.z;
        ga_mat4 inv;
        if (ga_mat4_inverse(a, &inv) != GA_OK) continue;
        *cond = ga_mat4_norm1(a) * ga_mat4_norm1(inv);
        if (*cond <= 1e6) return a;
    }
}

static ga_mat4 mat(const double v[16]) { ga_mat4 m; memcpy(m.m, v, sizeof m.m); return m; }

static ga_mat4 sentinel(void)
{
    ga_mat4 m;
    for (int i = 0; i < 16; i++) m.m[i] = 12345.0;
    return m;
}
static int is_sentinel(ga_mat4 m)
{
    for (int i = 0; i < 16; i++)
        if (m.m[i] != 12345.0) return 0;
    return 1;
}

/* Runs f on a and checks both the status and that out was left untouched. */
static void expect_fail(const char *name, int (*f)(ga_mat4, ga_mat4 *), ga_mat4 a, int want)
{
    ga_mat4 out = sentinel();
    int st = f(a, &out), touched = !is_sentinel(out), ok = st == want && !touched;
    printf("%-4s %-52s status %d (want %d)%s\n", ok ? "ok" : "FAIL", name, st, want,
           touched ? ", output written" : "");
    if (!ok) failures++;
}

int main(void)
{
    const double eps = DBL_EPSILON;
    uint64_t seed = 0x67617230746f72ull; /* "gar0tor" */

    /* ---- 1. Eberly's closed-form exp against the general Pade expm ------- */
    /* Both are backward stable; for th in (pi, 3pi) the measure is harsher,
     * since |t| = |V v| can be far below |v| near th = 2pi, yet it stays under
     * 1e-13 (measured ~1e-14 there, ~1e-15 elsewhere). */
    {
        double worst[N_FAMILIES] = {0}, all = 0;
        tk_rng s = {seed};
        for (long i = 0; i < N_TWISTS; i++) {
            int fam = (int)(i % N_FAMILIES);
            ga_twist xi = random_twist(&s, fam);
            ga_mat4 e1 = ga_se3_exp(xi), e2;
            int st = ga_mat4_expm(ga_twist_hat(xi), &e2);
            double e = st == GA_OK ? mat_err(e2, e1) : INFINITY;
            worst[fam] = fmax(worst[fam], e);
            all = fmax(all, e);
        }
        for (int f = 0; f < N_FAMILIES; f++)
            printf("       %-44s worst %.3e\n", family_name[f], worst[f]);
        report("se3_exp(xi) = expm(hat(xi))", N_TWISTS, all, 1e-13);
    }

    /* ---- 2. log(exp(xi)) = xi for angles < pi ----------------------------- */
    {
        double worst[6] = {0}, all = 0;
        tk_rng s = {seed ^ 1};
        for (long i = 0; i < N_TWISTS; i++) {
            int fam = (int)(i % 6); /* the families with |w| < pi */
            ga_twist xi = random_twist(&s, fam), back;
            int st = ga_se3_log(ga_se3_exp(xi), &back);
            double e = st == GA_OK ? twist_err(back, xi) : INFINITY;
            worst[fam] = fmax(worst[fam], e);
            all = fmax(all, e);
        }
        for (int f = 0; f < 6; f++) printf("       %-44s worst %.3e\n", family_name[f], worst[f]);
        report("se3_log(se3_exp(xi)) = xi, |w| < pi", N_TWISTS, all, 1e-13);
    }

    /* ---- 3. half turns and beyond: the backward error ---------------------- */
    {
        double back = 0, axis = 0, angle = 0;
        tk_rng s = {seed ^ 2};
        long n = 0;
        for (long i = 0; i < N_TWISTS / 4; i++, n++) {
            ga_twist xi = random_twist(&s, 6), l;
            ga_mat4 m = ga_se3_exp(xi);
            if (i % 2) { /* an exactly symmetric R = 2 n n^T - I: skew part 0 */
                ga_vec3 u = tk_unit(&s);
                double uv[3] = {u.x, u.y, u.z};
                for (int r = 0; r < 3; r++)
                    for (int c = 0; c < 3; c++) m.m[4 * r + c] = 2 * uv[r] * uv[c] - (r == c);
                xi.w = tk_scale(u, PI);
            }
            int st = ga_se3_log(m, &l);
            if (st != GA_OK) { back = INFINITY; continue; }
            back = fmax(back, mat_err(ga_se3_exp(l), m));
            /* either sign of the axis: the angle is pi and w = +-xi.w */
            double dp = 0, dm = 0;
            double a[3] = {l.w.x, l.w.y, l.w.z}, b[3] = {xi.w.x, xi.w.y, xi.w.z};
            for (int k = 0; k < 3; k++) { dp = fmax(dp, fabs(a[k] - b[k])); dm = fmax(dm, fabs(a[k] + b[k])); }
            axis = fmax(axis, fmin(dp, dm));
            angle = fmax(angle, fabs(tk_norm(l.w) - PI));
        }
        report("th = pi: |exp(log M) - M|", n, back, 1e-13);
        report("th = pi: w = +-pi n", n, axis, 1e-13);
        report("th = pi: |w| = pi", n, angle, 1e-13);
        double back7 = 0, over = 0;
        for (long i = 0; i < N_TWISTS / 4; i++) {
            ga_twist xi = random_twist(&s, 7), l;
            ga_mat4 m = ga_se3_exp(xi);
            if (ga_se3_log(m, &l) != GA_OK) { back7 = INFINITY; continue; }
            back7 = fmax(back7, mat_err(ga_se3_exp(l), m));
            over = fmax(over, tk_norm(l.w) - PI);
        }
        report("th in (pi, 3pi): |exp(log M) - M|", N_TWISTS / 4, back7, 1e-13);
        report("th in (pi, 3pi): principal, |w| - pi <= 0", N_TWISTS / 4, over, 4 * eps);
    }

    /* ---- 4. logm against se3_log on rigid inputs -------------------------- */
    /* The general log knows nothing of orthogonality, so near a half turn its
     * error is bounded by its condition number th / sin th (the divided
     * difference of log over the eigenvalues e^{+-i th}) times eps: the
     * tolerance is 1e-13 times that. Near th = pi logm verifies its result
     * (backward error <= GA_LOGM_BACKWARD_TOL) and otherwise says GA_ERR_DOMAIN;
     * that answer is accepted only when pi - th <= 1e-10 max(1, |t|), the
     * band mat4.h documents (measured: it starts near 1e-11 rad). */
    {
        double worst[6] = {0}, all = 0, domain_max = 0, wrel = 0;
        tk_rng s = {seed ^ 3};
        long domain = 0, nw = 0;
        for (long i = 0; i < N_TWISTS; i++) {
            int fam = (int)(i % 6);
            ga_twist xi = random_twist(&s, fam), l1;
            ga_mat4 m = ga_se3_exp(xi), l2;
            if (ga_se3_log(m, &l1) != GA_OK) { all = INFINITY; continue; }
            int st = ga_mat4_logm(m, &l2);
            double th = tk_norm(l1.w), e;
            double cond = th > 0 ? th / sin(th) : 1.0;
            double margin = (PI - th) / fmax(1.0, trans_len(m));
            if (st == GA_ERR_DOMAIN && margin <= 1e-10) {
                domain++;
                domain_max = fmax(domain_max, margin);
                continue;
            }
            e = st == GA_OK ? mat_err(l2, ga_twist_hat(l1)) / (1e-13 * cond) : INFINITY;
            worst[fam] = fmax(worst[fam], e);
            all = fmax(all, e);
            if ((fam == 1 || fam == 2) && st == GA_OK) { /* w relative to itself */
                ga_twist l3 = ga_twist_vee(l2);
                ga_vec3 dw = {l3.w.x - l1.w.x, l3.w.y - l1.w.y, l3.w.z - l1.w.z};
                wrel = fmax(wrel, tk_norm(dw) / tk_norm(l1.w));
                nw++;
            }
        }
        for (int f = 0; f < 6; f++)
            printf("       %-44s worst %.3e x 1e-13 th/sin th\n", family_name[f], worst[f]);
        printf("       GA_ERR_DOMAIN within rounding of pi: %ld cases, (pi - th)/max(1,|t|) <= %.2e\n",
               domain, domain_max);
        report("logm(M) = hat(se3_log(M)), / (1e-13 th/sin th)", N_TWISTS, all, 1.0);
        /* Tiny rotations under large translations: logm's w keeps relative
         * accuracy, not only accuracy relative to |v| (the rotation block of
         * each root and solve never mixes with the translation column, and
         * vee reads the skew part). 1e-13 relative to |w| itself. */
        report("logm: w relative to |w|, th in 1e-12..1", nw, wrel, 1e-13);
    }

    /* ---- 5. the general exp and log on affine matrices --------------------- */
    {
        double worst = 0, maxcond = 0, inv = 0;
        tk_rng s = {seed ^ 4};
        long bad = 0, hard = 0;
        for (long i = 0; i < N_AFFINE; i++) {
            double cond;
            ga_mat4 a = random_affine(&s, &cond), l, b, ai;
            maxcond = fmax(maxcond, cond);
            hard += cond > 1e5;
            int st = ga_mat4_logm(a, &l);
            if (st == GA_OK) st = ga_mat4_expm(l, &b);
            if (st != GA_OK) { bad++; continue; }
            for (int k = 0; k < 16; k++) b.m[k] -= a.m[k];
            worst = fmax(worst, ga_mat4_norm1(b) / ga_mat4_norm1(a));
            /* the inverse: residual ||A A^-1 - I||_1 <= c n eps cond(A) for
             * Gaussian elimination with partial pivoting; measured as a
             * multiple of eps cond(A) */
            ga_mat4_inverse(a, &ai);
            ga_mat4 r = ga_mat4_mul(a, ai);
            for (int k = 0; k < 4; k++) r.m[5 * k] -= 1.0;
            inv = fmax(inv, ga_mat4_norm1(r) / (eps * cond));
        }
        printf("       condition numbers up to %.3e (%ld above 1e5); %ld without a log\n",
               maxcond, hard, bad);
        report("expm(logm(A)) = A, affine: ||.||_1 / ||A||_1", N_AFFINE, bad ? INFINITY : worst, 1e-12);
        report("mat4_inverse: ||A A^-1 - I||_1 / (eps cond A)", N_AFFINE, inv, 16.0);
    }

    /* ---- 6. identities and closed forms ----------------------------------- */
    {
        tk_rng s = {seed ^ 5};
        double hv = 0, sinv = 0, geo = 0, mid = 0, adj = 0, check = 0;
        long n = N_TWISTS / 4;
        for (long i = 0; i < n; i++) {
            ga_twist a = random_twist(&s, (int)(i % 6)), b = random_twist(&s, (int)(i % 6));
            ga_twist c = random_twist(&s, (int)((i + 3) % 6)), v = ga_twist_vee(ga_twist_hat(a));
            hv = fmax(hv, twist_err(v, a));
            ga_mat4 h0 = ga_se3_exp(a), h1 = ga_se3_exp(b), g = ga_se3_exp(c), f, gi;
            if (ga_se3_check(h0, GA_SE3_TOL) != GA_OK || ga_se3_check(h1, 1e-14) != GA_OK) check = INFINITY;
            ga_mat4_inverse(g, &gi);
            sinv = fmax(sinv, mat_err(ga_se3_inverse(g), gi));
            /* geodesic: F(0) = h0, F(1) = h1, and F(1/2) h0^-1 squared = h1 h0^-1.
             * h1 h0^-1 and its product with h0 round at the scale of both
             * translations, so errors are relative to max(1, |t0|, |t1|). */
            double sc = fmax(1.0, fmax(trans_len(h0), trans_len(h1)));
            ga_se3_geodesic(h0, h1, 0.0, &f);
            geo = fmax(geo, mat_err(f, h0) * fmax(1.0, trans_len(h0)) / sc);
            ga_se3_geodesic(h0, h1, 1.0, &f);
            geo = fmax(geo, mat_err(f, h1) * fmax(1.0, trans_len(h1)) / sc);
            ga_se3_geodesic(h0, h1, 0.5, &f);
            ga_mat4 half = ga_mat4_mul(f, ga_se3_inverse(h0)), dd = ga_mat4_mul(h1, ga_se3_inverse(h0));
            mid = fmax(mid, mat_err(ga_mat4_mul(half, half), dd) * fmax(1.0, trans_len(dd)) / sc);
            /* adjoint: exp(Ad_g xi) = g exp(xi) g^-1 */
            ga_mat4 lhs = ga_se3_exp(ga_se3_adjoint(g, a));
            ga_mat4 rhs = ga_mat4_mul(ga_mat4_mul(g, h0), ga_se3_inverse(g));
            adj = fmax(adj, mat_err(lhs, rhs) / fmax(1.0, tk_norm(c.v)));
        }
        report("vee(hat(xi)) = xi", n, hv, 0.0);
        report("se3_exp output passes se3_check(., 1e-14)", n, check, 0.0);
        report("se3_inverse = mat4_inverse on rigid", n, sinv, 1e-13);
        report("geodesic: F(0) = h0, F(1) = h1, / max(1,|t0|,|t1|)", n, geo, 1e-13);
        report("geodesic: (F(1/2) h0^-1)^2 = h1 h0^-1, same scale", n, mid, 1e-13);
        report("adjoint: exp(Ad_g xi) = g exp(xi) g^-1, / max(1,|t_g|)", n, adj, 1e-13);

        /* expm closed forms: a diagonal (the contracting squarings), a Jordan
         * block, and a nilpotent N (N^2 = 0) whose 1-norm overflows, for which
         * exp = I + N. Error bound per entry: r_m(x) at x = -th (th =
         * ||A/2^s||_1 <= theta_13 = 5.37) is summed with cancellation
         * e^th, so its relative error is about u e^th; the 2^s = ||A||_1 / th
         * squarings multiply that exponent error, giving
         * u ||A||_1 e^th / th <= 40 u ||A||_1. */
        const double u = 0.5 * eps;
        double d[4] = {-50, -20, 1, 3}, e = 0;
        ga_mat4 a = mat((double[16]){-50, 0, 0, 0, 0, -20, 0, 0, 0, 0, 1, 0, 0, 0, 0, 3}), r;
        ga_mat4_expm(a, &r);
        for (int k = 0; k < 4; k++) e = fmax(e, fabs(r.m[5 * k] - exp(d[k])) / exp(d[k]));
        report("expm(diag(-50,-20,1,3)) per entry, relative", 4, e, 40 * u * 50);
        ga_mat4 j = mat((double[16]){-30, 1, 0, 0, 0, -30, 1, 0, 0, 0, -30, 0, 0, 0, 0, 0});
        ga_mat4_expm(j, &r);
        double ej = exp(-30.0), want[16] = {ej, ej, ej / 2, 0, 0, ej, ej, 0, 0, 0, ej, 0, 0, 0, 0, 1};
        e = 0;
        for (int k = 0; k < 16; k++) e = fmax(e, fabs(r.m[k] - want[k]) / (want[k] != 0 ? want[k] : 1));
        report("expm(Jordan block at -30) per entry, relative", 16, e, 40 * u * 31);
        ga_mat4 nil = mat((double[16]){0, 0, 0, DBL_MAX, 0, 0, 0, DBL_MAX, 0, 0, 0, -DBL_MAX, 0, 0, 0, 0});
        e = ga_mat4_expm(nil, &r) == GA_OK ? 0 : INFINITY;
        for (int k = 0; k < 16; k++) {
            double w = nil.m[k] + (k % 5 == 0);
            e = fmax(e, fabs(r.m[k] - w) / fmax(1.0, fabs(w)));
        }
        report("expm(N), N^2 = 0, ||N||_1 = inf: I + N, relative", 16, e, 4 * eps);
        ga_mat4 ln;
        e = ga_mat4_logm(ga_mat4_identity(), &ln) == GA_OK ? ga_mat4_norm1(ln) : INFINITY;
        report("logm(I) = 0", 1, e, 0.0);
        ga_mat4 sc = mat((double[16]){1e-3, 0, 0, 5, 0, 1e3, 0, -2, 0, 0, 2, 1e3, 0, 0, 0, 1});
        ga_mat4_logm(sc, &ln);
        e = fmax(fabs(ln.m[0] - log(1e-3)) / fabs(log(1e-3)), fabs(ln.m[5] - log(1e3)) / log(1e3));
        e = fmax(e, fabs(ln.m[10] - log(2.0)) / log(2.0));
        report("logm(diag scales) diagonal = log, relative", 3, e, 1e-13);
        /* small parts under large ones: a scaling of 1 + 1e-10 under a
         * translation of 1e6, compared with log1p of the stored entry */
        ga_mat4 tiny = mat((double[16]){1 + 1e-10, 3e-9, 0, 1e6, 0, 1 - 2e-10, 0, -5e5,
                                        0, 0, 1 + 3e-10, 2e5, 0, 0, 0, 1});
        e = ga_mat4_logm(tiny, &ln) == GA_OK ? 0 : INFINITY;
        for (int k = 0; k < 3; k++)
            e = fmax(e, fabs(ln.m[5 * k] - log1p(tiny.m[5 * k] - 1)) / fabs(log1p(tiny.m[5 * k] - 1)));
        report("logm(I + 1e-10 D, t = 1e6) diagonal, relative", 3, e, 1e-13);
        /* se3_exp(pi e3) has eigenvalues -1 +- 1.2e-16 i (sin(pi) in double):
         * one rounding off the axis, so a principal log exists; logm finds it
         * (the singular-looking (A + I)/2 is regular after equilibration) and
         * it is se3_log's answer. */
        ga_twist half = {{0, 0, PI}, {1, 2, 3}}, lh;
        ga_mat4 mh = ga_se3_exp(half);
        ga_se3_log(mh, &lh);
        e = ga_mat4_logm(mh, &ln) == GA_OK ? mat_err(ln, ga_twist_hat(lh)) : INFINITY;
        report("logm(se3_exp(pi e3)) = hat(se3_log(.))", 1, e, 1e-13);
        /* badly scaled but regular: |t| = 1e16 (normwise condition 1e32) */
        ga_twist far = {{0.3, -0.2, 0.1}, {1e16, -3e15, 2e14}};
        ga_mat4 mf = ga_se3_exp(far), mi;
        e = ga_mat4_inverse(mf, &mi) == GA_OK ? mat_err(mi, ga_se3_inverse(mf)) : INFINITY;
        report("mat4_inverse(rigid, |t| = 1e16) = se3_inverse", 1, e, 1e-13);
        ga_twist lf;
        ga_se3_log(mf, &lf);
        e = ga_mat4_logm(mf, &ln) == GA_OK ? mat_err(ln, ga_twist_hat(lf)) : INFINITY;
        report("logm(rigid, |t| = 1e16) = hat(se3_log(.))", 1, e, 1e-13);
        /* a sweep of translations 1 .. 1e18 (the root count grows to 60) */
        e = 0;
        for (int k = 0; k <= 18; k++) {
            ga_twist sw = {{0.7, -0.4, 1.1}, {pow(10, k), -0.3 * pow(10, k), 2.0}};
            ga_mat4 ms = ga_se3_exp(sw);
            ga_se3_log(ms, &lf);
            e = fmax(e, ga_mat4_logm(ms, &ln) == GA_OK ? mat_err(ln, ga_twist_hat(lf)) : INFINITY);
        }
        report("logm(rigid, |t| = 1 .. 1e18) = hat(se3_log(.))", 19, e, 1e-13);
        ga_mat4 dd = mat((double[16]){1e-20, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1e20, 0, 0, 0, 0, 1});
        e = ga_mat4_inverse(dd, &mi) == GA_OK ? fmax(fabs(mi.m[0] * 1e-20 - 1), fabs(mi.m[10] * 1e20 - 1)) : INFINITY;
        report("mat4_inverse(diag(1e-20, 1, 1e20, 1))", 1, e, eps);
    }

    /* ---- 7. bad input: the right status, output untouched, no crash ------- */
    {
        ga_mat4 id = ga_mat4_identity(), m;
        ga_twist tw, t0 = {{1, 2, 3}, {4, 5, 6}};
        m = id; m.m[6] = NAN;
        expect_fail("mat4_inverse(NaN)", ga_mat4_inverse, m, GA_ERR_NOTFINITE);
        expect_fail("mat4_expm(NaN)", ga_mat4_expm, m, GA_ERR_NOTFINITE);
        expect_fail("mat4_logm(NaN)", ga_mat4_logm, m, GA_ERR_NOTFINITE);
        m = id; m.m[3] = INFINITY;
        expect_fail("mat4_expm(Inf)", ga_mat4_expm, m, GA_ERR_NOTFINITE);
        expect_fail("mat4_logm(Inf)", ga_mat4_logm, m, GA_ERR_NOTFINITE);
        tw = t0;
        expect("se3_log(Inf)", ga_se3_log(m, &tw), GA_ERR_NOTFINITE);
        expect("se3_check(Inf)", ga_se3_check(m, 1e-9), GA_ERR_NOTFINITE);
        m = id; m.m[0] = NAN;
        expect("se3_log(NaN)", ga_se3_log(m, &tw), GA_ERR_NOTFINITE);
        m = id; m.m[0] = m.m[5] = m.m[10] = 1.001;
        expect("se3_log(scaled R)", ga_se3_log(m, &tw), GA_ERR_NOTRIGID);
        m = id; m.m[1] = 1e-6;
        expect("se3_log(sheared R)", ga_se3_log(m, &tw), GA_ERR_NOTRIGID);
        m = id; m.m[0] = -1;
        expect("se3_log(reflection)", ga_se3_log(m, &tw), GA_ERR_NOTRIGID);
        m = id; m.m[12] = 0.5;
        expect("se3_log(last row 0.5 0 0 1)", ga_se3_log(m, &tw), GA_ERR_NOTRIGID);
        m = id; m.m[15] = 2;
        expect("se3_log(last row 0 0 0 2)", ga_se3_log(m, &tw), GA_ERR_NOTRIGID);
        expect("... output untouched", tw.w.x == 1 && tw.v.z == 6, 1);
        m = ga_se3_exp(t0); m.m[0] += 1e-12; /* slightly off: accepted */
        expect("se3_log(R off by 1e-12)", ga_se3_log(m, &tw), GA_OK);
        m.m[0] += 1e-8; /* far off */
        expect("se3_log(R off by 1e-8)", ga_se3_log(m, &tw), GA_ERR_NOTRIGID);
        expect("se3_check(I, NaN tol)", ga_se3_check(id, NAN), GA_ERR_NOTRIGID);

        m = id;
        for (int k = 0; k < 4; k++) m.m[5 * k] = 1000;
        expect_fail("mat4_expm(1000 I) overflows", ga_mat4_expm, m, GA_ERR_DOMAIN);
        for (int k = 0; k < 4; k++) m.m[5 * k] = -1000;
        ga_mat4 r;
        expect("mat4_expm(-1000 I) underflows to 0", ga_mat4_expm(m, &r) == GA_OK && ga_mat4_norm1(r) == 0, 1);
        m = id; m.m[0] = DBL_MAX; m.m[4] = DBL_MAX;
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
        m = id; m.m[10] = 0;
        expect_fail("mat4_logm(diag(1,1,0,1))", ga_mat4_logm, m, GA_ERR_SINGULAR);
        expect_fail("mat4_inverse(0)", ga_mat4_inverse, mat((double[16]){0}), GA_ERR_SINGULAR);

        ga_mat4 g = sentinel();
        expect("se3_geodesic(t = NaN)", ga_se3_geodesic(id, id, NAN, &g), GA_ERR_NOTFINITE);
        m = id; m.m[0] = 2;
        expect("se3_geodesic(h1 not rigid)", ga_se3_geodesic(id, m, 0.5, &g), GA_ERR_NOTRIGID);
        m = id; m.m[7] = NAN;
        expect("se3_geodesic(h0 NaN)", ga_se3_geodesic(m, id, 0.5, &g), GA_ERR_NOTFINITE);
        expect("... output untouched", is_sentinel(g), 1);
    }

    printf("%s: %d failure(s)\n", failures ? "FAIL" : "ok", failures);
    return failures != 0;
}
