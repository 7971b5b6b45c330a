/* fuzz/fuzz_numeric.c: libFuzzer target for the numeric API of ga/.
 *
 * The first byte picks an operation; the rest is read as doubles by
 * fuzz_reader.h (raw IEEE bit patterns, or one-byte tags for NaN, +-Inf,
 * subnormals, +-1e308, +-DBL_MAX, 0, pi, pi - 1e-9...). Every operation
 * asserts, besides "no crash and no sanitizer report":
 *
 *   - status:  NaN or Inf anywhere in the input of a status-returning
 *              function gives GA_ERR_NOTFINITE; every status is one types.h
 *              lists for that function; GA_OK never comes with a non-finite
 *              output (that would be a silent wrong answer).
 *   - group:   a rotor a function returns with GA_OK is on the group,
 *              ga_rotor_check(R, 1e-12) (R ~R = 1 to 1e-12); a rigid-motion
 *              matrix passes ga_se3_check(M, 1e-10).
 *   - valid:   inside the documented range of valid input the operation
 *              succeeds, its output is finite, and it inverts its partner
 *              (exp/log, bridge there and back) to the stated tolerance.
 *
 * "Valid" (the thresholds this target asserts against):
 *   VALID_MAX = 1e6   exp of a generator or twist whose components are at most
 *                     1e6 in size (rotations up to 1e6 rad, translations up
 *                     to 1e6); rotor or matrix coefficients up to 1e6 for the
 *                     bridge. Beyond, exp may lose every digit of the angle
 *                     (an angle of 1e20 rad is exact but meaningless) and, past
 *                     ~1e154, overflow to NaN: the value-returning functions
 *                     (ga_rotor_exp, ga_se3_exp) cannot say so, the group
 *                     interface (group.h) returns GA_ERR_DOMAIN (docs/errors.md).
 *   round trips       exp(log(R)) = +-R to 1e-10 max(1, |t|), far above the
 *                     measured 8 eps (the soak suite measures the real figure;
 *                     this is a net for gross failures, not a precision test).
 *   points            |x| <= 1e4 for F(x) and down (GA_POINT_TOL: a point
 *                     beyond ~4.5e4 reads as the point at infinity).
 *   expm              ||a||_1 <= 100: GA_OK and finite (e^100 ~ 3e43).
 *   logm round trip   logm(expm(X)) = X for ||X||_1 <= 1 (all eigenvalues
 *                     well inside the principal strip), to 1e-9; and
 *                     logm(1e-4 expm(X)) = X + log(1e-4) I likewise.
 *   logm diagonal     a positive diagonal has GA_OK and diag(log a_ii), to
 *                     1e-12 relative.
 *   mv exp/log        (op "mv", on the bivector part) exp of a bivector up
 *                     to 8 is a finite rotor; exp(log R) = R to 1e-12 |R|
 *                     where every rotation half-angle is at most 1.5 and
 *                     their sum at most 2.8 (the bound is derived at
 *                     mv_exp_log), to log's own 1e-9 elsewhere.
 *   join, meet_rel    (op "mv", on X and blades made of its doubles) a status
 *                     of object.h's list, finite results, and join(X, X) = X,
 *                     meet_rel(X, 2 X) = 2 X bit for bit.
 *   mv text           (op "mv") ga_mv_format then ga_mv_parse gives the same
 *                     doubles; the bytes after the op's doubles are parsed
 *                     as text: a status, and what it reads round-trips.
 */
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "fuzz_check.h"
#include "fuzz_reader.h"
#include <garotor/garotor.h>

#define VALID_MAX 1e6
#define RT_TOL 1e-10

static int rotor_finite(ga_rotor r) { return fz_all_finite(&r.s, 8); }
static double vnorm(ga_vec3 a) { return hypot(hypot(a.x, a.y), a.z); }
static int vfinite(ga_vec3 a) { return isfinite(a.x) && isfinite(a.y) && isfinite(a.z); }

/* max(1, |t|) of a rotor: the scale its P part is measured against. */
static double rotor_scale(ga_rotor r)
{
    ga_vec3 t = ga_rotor_to_translation(r);
    return fmax(1.0, vnorm(t));
}

/* The distance between a and +-b: q parts absolute, P parts relative to scale. */
static double rotor_dist_pm(ga_rotor a, ga_rotor b, double scale)
{
    double best = INFINITY;
    for (int sg = -1; sg <= 1; sg += 2) {
        const double *x = &a.s, *y = &b.s;
        double d = 0.0;
        for (int i = 0; i < 8; i++) d = fmax(d, fabs(x[i] - sg * y[i]) / (i < 4 ? 1.0 : scale));
        best = fmin(best, d);
    }
    return best;
}

static double mat_dist(ga_mat4 a, ga_mat4 b, double tscale)
{
    double d = 0.0;
    for (int i = 0; i < 16; i++) d = fmax(d, fabs(a.m[i] - b.m[i]) / ((i % 4 == 3 && i < 12) ? tscale : 1.0));
    return d;
}

static int is_status(int st)
{
    return st == GA_OK || st == GA_ERR_NOTFINITE || st == GA_ERR_SINGULAR || st == GA_ERR_NOTPOINT ||
           st == GA_ERR_NOTRIGID || st == GA_ERR_DOMAIN || st == GA_ERR_ARG || st == GA_ERR_NOTBLADE ||
           st == GA_ERR_IMAGINARY || st == GA_ERR_PRECISION;
}

/* ---- rotors --------------------------------------------------------------- */

/* Everything that takes an arbitrary rotor: check, normalize, both logs, the
 * screw, the matrix. */
static void rotor_any(ga_rotor r)
{
    int fin = rotor_finite(r);
    int chk = ga_rotor_check(r, GA_ROTOR_DRIFT_MAX);
    ga_rotor nr;
    int nst = ga_rotor_normalize(r, &nr);
    ga_generator L, Ll;
    int lst = ga_rotor_log(r, &L), llst = ga_rotor_log_literal(r, &Ll);
    ga_screw sc;
    int sst = ga_rotor_to_screw(r, &sc);
    if (!fin) {
        FZ_CHECK(chk == GA_ERR_NOTFINITE && nst == GA_ERR_NOTFINITE && lst == GA_ERR_NOTFINITE &&
                     llst == GA_ERR_NOTFINITE && sst == GA_ERR_NOTFINITE,
                 "non-finite rotor: check %d normalize %d log %d literal %d screw %d", chk, nst, lst, llst,
                 sst);
        return;
    }
    FZ_CHECK(chk == GA_OK || chk == GA_ERR_NOTRIGID, "check status %d", chk);
    FZ_CHECK(nst == GA_OK || nst == GA_ERR_NOTRIGID || nst == GA_ERR_DOMAIN, "normalize status %d", nst);
    FZ_CHECK(lst == GA_OK || lst == GA_ERR_NOTRIGID || lst == GA_ERR_DOMAIN, "log status %d", lst);
    FZ_CHECK(llst == GA_OK || llst == GA_ERR_NOTRIGID || llst == GA_ERR_DOMAIN, "literal log status %d",
             llst);
    FZ_CHECK(sst == GA_OK || sst == GA_ERR_NOTRIGID || sst == GA_ERR_DOMAIN, "screw status %d", sst);
    /* log accepts exactly what the check at GA_ROTOR_DRIFT_MAX accepts */
    FZ_CHECK((lst == GA_ERR_NOTRIGID) == (chk == GA_ERR_NOTRIGID), "log %d but check %d", lst, chk);
    FZ_CHECK((llst == GA_ERR_NOTRIGID) == (chk == GA_ERR_NOTRIGID), "literal log %d but check %d", llst, chk);
    if (nst == GA_OK) {
        FZ_CHECK(rotor_finite(nr), "normalize: GA_OK with a non-finite rotor");
        FZ_CHECK(ga_rotor_check(nr, 1e-12) == GA_OK, "normalize: result off the group");
    }
    if (lst == GA_OK) {
        FZ_CHECK(fz_all_finite(&L.e12, 6), "log: GA_OK with a non-finite generator");
        ga_twist xi = ga_generator_to_twist(L);
        FZ_CHECK(vnorm(xi.w) <= 3.141592653589793 * (1 + 1e-15), "log: angle %.17g > pi", vnorm(xi.w));
        FZ_CHECK(nst == GA_OK || nst == GA_ERR_DOMAIN, "log ok but normalize %d", nst);
        if (nst == GA_OK && fz_maxabs(&r.s, 8) <= VALID_MAX) {
            ga_rotor e = ga_rotor_exp(L);
            double d = rotor_dist_pm(e, nr, rotor_scale(nr));
            FZ_CHECK(d <= RT_TOL, "exp(log(R)) = +-normalize(R): off by %.3g", d);
        }
    }
    if (llst == GA_OK)
        FZ_CHECK(fz_all_finite(&Ll.e12, 6), "literal log: GA_OK with a non-finite generator");
    if (sst == GA_OK) {
        FZ_CHECK(isfinite(sc.angle) && vfinite(sc.axis) && vfinite(sc.point) && isfinite(sc.shift) &&
                     !isnan(sc.pitch),
                 "screw: GA_OK with a non-finite field");
        FZ_CHECK(sc.angle >= 0 && sc.angle <= 3.141592653589793 * (1 + 1e-15), "screw angle %.17g", sc.angle);
        /* a rotation (or pure translation) below the normal range carries its
           axis in subnormal coefficients with only a few significant bits */
        if (sc.angle >= 1e-300 || (sc.angle == 0.0 && (sc.shift == 0.0 || sc.shift >= 1e-300)))
            FZ_CHECK(fabs(vnorm(sc.axis) - 1.0) <= 1e-14, "screw axis not unit: %.17g", vnorm(sc.axis));
    }
    if (ga_rotor_check(r, 1e-12) == GA_OK) {
        ga_mat4 m = ga_rotor_to_mat4(r);
        if (fz_all_finite(m.m, 16))
            FZ_CHECK(ga_se3_check(m, 1e-10) == GA_OK, "to_mat4 of a unit rotor is not rigid");
    }
}

/* exp of a generator, then back. */
static void op_exp_log(fz_reader *rd)
{
    double x[6];
    fz_doubles(rd, x, 6);
    ga_generator B = {x[0], x[1], x[2], x[3], x[4], x[5]};
    ga_rotor R = ga_rotor_exp(B);
    if (!fz_all_finite(x, 6)) {
        FZ_CHECK(!rotor_finite(R), "exp: NaN/Inf in, finite out");
        rotor_any(R);
        return;
    }
    if (fz_maxabs(x, 6) <= VALID_MAX) {
        FZ_CHECK(rotor_finite(R), "exp of a valid generator is not finite");
        FZ_CHECK(ga_rotor_check(R, 1e-12) == GA_OK, "exp of a valid generator is off the group");
        ga_generator L;
        FZ_CHECK(ga_rotor_log(R, &L) == GA_OK, "log of exp(B) fails");
        double d = rotor_dist_pm(ga_rotor_exp(L), R, rotor_scale(R));
        FZ_CHECK(d <= RT_TOL, "exp(log(exp(B))) = +-exp(B): off by %.3g", d);
        /* the matrix side agrees: expm(xi^) = to_mat4(exp(B(xi))) */
        ga_twist xi = ga_generator_to_twist(B);
        ga_mat4 M = ga_se3_exp(xi), MR = ga_rotor_to_mat4(R);
        double s = fmax(1.0, vnorm((ga_vec3){M.m[3], M.m[7], M.m[11]}));
        d = mat_dist(M, MR, s);
        FZ_CHECK(d <= 1e-9, "se3_exp and rotor exp differ by %.3g", d);
    }
    rotor_any(R);
}

/* A rotor drifted off the group by arbitrary amounts. */
static void op_rotor_drift(fz_reader *rd)
{
    double x[6], d[8];
    fz_doubles(rd, x, 6);
    fz_doubles(rd, d, 8);
    if (!fz_all_finite(x, 6))
        return;
    ga_rotor R = ga_rotor_exp((ga_generator){x[0], x[1], x[2], x[3], x[4], x[5]});
    double *c = &R.s;
    for (int i = 0; i < 8; i++) c[i] += d[i];
    rotor_any(R);
}

static void op_rotor_any(fz_reader *rd)
{
    ga_rotor r;
    fz_doubles(rd, &r.s, 8);
    rotor_any(r);
}

/* ---- matrices ------------------------------------------------------------- */

static void mat_any(ga_mat4 m)
{
    int fin = fz_all_finite(m.m, 16);
    ga_rotor R;
    ga_twist xi;
    ga_mat4 inv;
    int rst = ga_rotor_from_mat4(m, &R), cst = ga_se3_check(m, GA_SE3_TOL);
    int lst = ga_se3_log(m, &xi), ist = ga_mat4_inverse(m, &inv);
    if (!fin) {
        FZ_CHECK(rst == GA_ERR_NOTFINITE && cst == GA_ERR_NOTFINITE && lst == GA_ERR_NOTFINITE &&
                     ist == GA_ERR_NOTFINITE,
                 "non-finite matrix: from_mat4 %d check %d log %d inverse %d", rst, cst, lst, ist);
        return;
    }
    FZ_CHECK(rst == GA_OK || rst == GA_ERR_NOTRIGID || rst == GA_ERR_DOMAIN, "from_mat4 status %d", rst);
    FZ_CHECK(lst == GA_OK || lst == GA_ERR_NOTRIGID || lst == GA_ERR_DOMAIN, "se3_log status %d", lst);
    FZ_CHECK(ist == GA_OK || ist == GA_ERR_SINGULAR, "inverse status %d", ist);
    if (ist == GA_OK)
        FZ_CHECK(fz_all_finite(inv.m, 16), "inverse: GA_OK with a non-finite matrix");
    if (rst == GA_OK) {
        FZ_CHECK(rotor_finite(R), "from_mat4: GA_OK with a non-finite rotor");
        FZ_CHECK(ga_rotor_check(R, 1e-12) == GA_OK, "from_mat4: rotor off the group");
        double ts = fmax(1.0, vnorm((ga_vec3){m.m[3], m.m[7], m.m[11]}));
        if (ts <= VALID_MAX) {
            double d = mat_dist(ga_rotor_to_mat4(R), m, ts);
            FZ_CHECK(d <= 1e-8, "to_mat4(from_mat4(M)) = M: off by %.3g", d);
        }
        rotor_any(R);
    }
    if (lst == GA_OK) {
        FZ_CHECK(fz_all_finite(&xi.w.x, 6), "se3_log: GA_OK with a non-finite twist");
        FZ_CHECK(vnorm(xi.w) <= 3.141592653589793 * (1 + 1e-15), "se3_log: angle %.17g > pi", vnorm(xi.w));
        double ts = fmax(1.0, vnorm((ga_vec3){m.m[3], m.m[7], m.m[11]}));
        if (ts <= VALID_MAX) {
            double d = mat_dist(ga_se3_exp(xi), m, ts);
            FZ_CHECK(d <= 1e-8, "se3_exp(se3_log(M)) = M: off by %.3g", d);
        }
    }
    if (cst == GA_OK) {
        ga_mat4 mi = ga_se3_inverse(m);
        double ts = fmax(1.0, vnorm((ga_vec3){m.m[3], m.m[7], m.m[11]}));
        if (ts <= VALID_MAX) {
            /* ga_se3_check accepts a last row off by GA_SE3_TOL, which
               se3_inverse (the inverse of the rigid motion M stands for)
               ignores: the product's last row is then off by that times |t|,
               so it is measured relative to ts as well
               (fuzz/regress/numeric/se3-inverse-drifted-last-row) */
            ga_mat4 p = ga_mat4_mul(m, mi), id = ga_mat4_identity();
            double d = 0.0;
            for (int i = 0; i < 16; i++)
                d = fmax(d, fabs(p.m[i] - id.m[i]) / (i % 4 == 3 || i >= 12 ? ts : 1.0));
            FZ_CHECK(d <= 1e-8, "M se3_inverse(M) = I: off by %.3g", d);
        }
    }
}

static void op_mat_any(fz_reader *rd)
{
    ga_mat4 m;
    fz_doubles(rd, m.m, 16);
    mat_any(m);
}

/* A rigid motion perturbed by arbitrary amounts (most of them tiny). */
static void op_mat_near(fz_reader *rd)
{
    double x[6], d[16];
    fz_doubles(rd, x, 6);
    fz_doubles(rd, d, 16);
    if (!fz_all_finite(x, 6))
        return;
    ga_mat4 m = ga_se3_exp((ga_twist){{x[0], x[1], x[2]}, {x[3], x[4], x[5]}});
    for (int i = 0; i < 16; i++) m.m[i] += d[i];
    mat_any(m);
}

/* exp and log on the matrix side, and the geodesic and adjoint. */
static void op_se3(fz_reader *rd)
{
    double x[6], y[6];
    fz_doubles(rd, x, 6);
    fz_doubles(rd, y, 6);
    double t = fz_double(rd);
    ga_twist xi = {{x[0], x[1], x[2]}, {x[3], x[4], x[5]}};
    ga_twist eta = {{y[0], y[1], y[2]}, {y[3], y[4], y[5]}};
    ga_mat4 M = ga_se3_exp(xi), N = ga_se3_exp(eta), G;
    int gst = ga_se3_geodesic(M, N, t, &G);
    FZ_CHECK(is_status(gst), "geodesic status %d", gst);
    if (gst == GA_OK)
        FZ_CHECK(fz_all_finite(G.m, 16), "geodesic: GA_OK with a non-finite matrix");
    if (!fz_all_finite(x, 6)) {
        FZ_CHECK(!fz_all_finite(M.m, 16), "se3_exp: NaN/Inf in, finite out");
        FZ_CHECK(gst == GA_ERR_NOTFINITE, "geodesic from a NaN matrix: status %d", gst);
        mat_any(M);
        return;
    }
    if (fz_maxabs(x, 6) <= VALID_MAX) {
        FZ_CHECK(fz_all_finite(M.m, 16), "se3_exp of a valid twist is not finite");
        FZ_CHECK(ga_se3_check(M, 1e-10) == GA_OK, "se3_exp of a valid twist is not rigid");
        ga_twist l;
        FZ_CHECK(ga_se3_log(M, &l) == GA_OK, "se3_log(se3_exp(xi)) fails");
        if (fz_all_finite(y, 6) && fz_maxabs(y, 6) <= VALID_MAX && isfinite(t) && fabs(t) <= 1e3)
            FZ_CHECK(gst == GA_OK, "geodesic between valid motions fails: %d", gst);
        ga_twist a = ga_se3_adjoint(M, eta);
        if (fz_all_finite(y, 6) && fz_maxabs(y, 6) <= VALID_MAX)
            FZ_CHECK(fz_all_finite(&a.w.x, 6), "adjoint of valid input not finite");
    }
    mat_any(M);
}

/* The general exp and log. */
static void op_expm_logm(fz_reader *rd)
{
    ga_mat4 a, e, l;
    fz_doubles(rd, a.m, 16);
    int fin = fz_all_finite(a.m, 16);
    int est = ga_mat4_expm(a, &e), lst = ga_mat4_logm(a, &l);
    if (!fin) {
        FZ_CHECK(est == GA_ERR_NOTFINITE && lst == GA_ERR_NOTFINITE, "non-finite: expm %d logm %d", est, lst);
        return;
    }
    FZ_CHECK(est == GA_OK || est == GA_ERR_DOMAIN, "expm status %d", est);
    FZ_CHECK(lst == GA_OK || lst == GA_ERR_SINGULAR || lst == GA_ERR_DOMAIN, "logm status %d", lst);
    if (est == GA_OK)
        FZ_CHECK(fz_all_finite(e.m, 16), "expm: GA_OK with a non-finite matrix");
    if (lst == GA_OK)
        FZ_CHECK(fz_all_finite(l.m, 16), "logm: GA_OK with a non-finite matrix");
    double n1 = ga_mat4_norm1(a);
    if (n1 <= 100)
        FZ_CHECK(est == GA_OK, "expm of ||a||_1 = %.3g fails: %d", n1, est);
    if (n1 <= 1 && est == GA_OK) {
        ga_mat4 back;
        int st = ga_mat4_logm(e, &back);
        FZ_CHECK(st == GA_OK, "logm(expm(X)), ||X||_1 = %.3g, fails: %d", n1, st);
        double d = mat_dist(back, a, 1.0);
        FZ_CHECK(d <= 1e-9, "logm(expm(X)) = X: off by %.3g", d);
        /* scaled: log(c e^X) = X + log(c) I, c = 1e-4 (eigenvalues near 0,
         * where a Schur form of A - I loses digits) */
        ga_mat4 sc = e;
        for (int i = 0; i < 16; i++) sc.m[i] *= 1e-4;
        st = ga_mat4_logm(sc, &back);
        FZ_CHECK(st == GA_OK, "logm(1e-4 expm(X)), ||X||_1 = %.3g, fails: %d", n1, st);
        for (int i = 0; i < 4; i++) back.m[5 * i] -= log(1e-4);
        d = mat_dist(back, a, 1.0);
        FZ_CHECK(d <= 1e-9, "logm(1e-4 expm(X)) = X + log(1e-4) I: off by %.3g", d);
    }
    /* a positive diagonal always has a log: diag(log a_ii) */
    int diag = 1;
    for (int i = 0; i < 16; i++) diag &= i % 5 == 0 ? a.m[i] > 0.0 : a.m[i] == 0.0;
    if (diag) {
        FZ_CHECK(lst == GA_OK, "logm of a positive diagonal fails: %d", lst);
        for (int i = 0; i < 4; i++) {
            double w = log(a.m[5 * i]);
            FZ_CHECK(fabs(l.m[5 * i] - w) <= 1e-12 * fmax(1.0, fabs(w)),
                     "logm of a diagonal: %.17g, not %.17g", l.m[5 * i], w);
        }
    }
}

/* ---- the bridge ------------------------------------------------------------- */

static void op_bridge(fz_reader *rd)
{
    double q4[4], t3[3], r8[8];
    fz_doubles(rd, q4, 4);
    fz_doubles(rd, t3, 3);
    fz_doubles(rd, r8, 8);
    /* dual quaternions: an exact relabelling, there and back, any bits */
    ga_rotor r;
    memcpy(&r.s, r8, sizeof r8);
    ga_rotor back = ga_rotor_from_dualquat(ga_rotor_to_dualquat(r));
    FZ_CHECK(memcmp(&back, &r, sizeof r) == 0, "from_dualquat(to_dualquat(R)) != R");
    /* quaternion and translation to a rotor and back */
    if (!fz_all_finite(q4, 4) || !fz_all_finite(t3, 3))
        return;
    /* scale to [1/2, 1) by a power of 2 first: normalising subnormal
       components directly would leave a norm off by their rounding */
    double qm = fz_maxabs(q4, 4);
    if (!(qm > 0))
        return;
    int qe;
    frexp(qm, &qe);
    for (int i = 0; i < 4; i++) q4[i] = ldexp(q4[i], -qe);
    double qn = hypot(hypot(q4[0], q4[1]), hypot(q4[2], q4[3]));
    if (!(qn > 0) || !isfinite(qn))
        return;
    ga_quat q = {q4[0] / qn, q4[1] / qn, q4[2] / qn, q4[3] / qn};
    ga_vec3 t = {t3[0], t3[1], t3[2]};
    ga_rotor R = ga_rotor_from_quat(q, t);
    if (fz_maxabs(t3, 3) > VALID_MAX)
        return;
    FZ_CHECK(ga_rotor_check(R, 1e-12) == GA_OK, "from_quat of a unit quaternion is off the group");
    ga_vec3 t2 = ga_rotor_to_translation(R);
    ga_quat qb = ga_rotor_to_quat(R);
    FZ_CHECK(qb.w == q.w && qb.x == q.x && qb.y == q.y && qb.z == q.z, "quaternion not kept");
    double s = fmax(1.0, vnorm(t));
    double d = vnorm((ga_vec3){t2.x - t.x, t2.y - t.y, t2.z - t.z}) / s;
    FZ_CHECK(d <= 1e-14, "translation not kept: off by %.3g", d);
    ga_rotor R2;
    int st = ga_rotor_from_mat4(ga_rotor_to_mat4(R), &R2);
    FZ_CHECK(st == GA_OK, "from_mat4(to_mat4(R)) fails: %d", st);
    d = rotor_dist_pm(R2, R, s);
    FZ_CHECK(d <= 1e-13, "from_mat4(to_mat4(R)) = +-R: off by %.3g", d);
    ga_vec3 x = ga_rotor_apply(R, t);
    FZ_CHECK(vfinite(x), "apply of a valid rotor to a valid point is not finite");
}

/* ---- screws ----------------------------------------------------------------- */

static void op_screw(fz_reader *rd)
{
    double x[9];
    fz_doubles(rd, x, 9);
    ga_screw s = {x[0], {x[1], x[2], x[3]}, {x[4], x[5], x[6]}, x[7], x[8]};
    ga_rotor R = ga_rotor_from_screw(s);
    if (fz_all_finite(x, 8) && fz_maxabs(x, 8) <= VALID_MAX) {
        FZ_CHECK(rotor_finite(R), "from_screw of a valid screw is not finite");
        FZ_CHECK(ga_rotor_check(R, 1e-12) == GA_OK, "from_screw: off the group");
        ga_screw s2;
        int st = ga_rotor_to_screw(R, &s2);
        FZ_CHECK(st == GA_OK || st == GA_ERR_DOMAIN, "screw_from_rotor status %d", st);
        if (st == GA_OK) {
            double d = rotor_dist_pm(ga_rotor_from_screw(s2), R, rotor_scale(R));
            FZ_CHECK(d <= RT_TOL, "from_screw(screw_from_rotor(R)) = +-R: off by %.3g", d);
        }
    }
    rotor_any(R);
}

/* ---- the conformal model ---------------------------------------------------- */

/* ga_mv_join and ga_mv_meet_rel of A and B: a status of object.h's list
   (NaN/Inf anywhere first), finite results with GA_OK, and where B is A or
   2 A (the same subspace, decided alike to the bit: scaling by 2 is exact
   through every step) the join A and the meet B as given. */
static void join_pair(ga_mv A, ga_mv B, int same)
{
    int fin = fz_all_finite(A.c, 32) && fz_all_finite(B.c, 32);
    ga_mv J, M;
    int js = ga_mv_join(A, B, &J), ms = ga_mv_meet_rel(A, B, &M);
    FZ_CHECK(fin ? (js == GA_OK || js == GA_ERR_SINGULAR || js == GA_ERR_NOTBLADE || js == GA_ERR_DOMAIN)
                 : js == GA_ERR_NOTFINITE,
             "join status %d", js);
    FZ_CHECK(fin ? (ms == GA_OK || ms == GA_ERR_SINGULAR || ms == GA_ERR_NOTBLADE || ms == GA_ERR_DOMAIN)
                 : ms == GA_ERR_NOTFINITE,
             "meet_rel status %d", ms);
    if (js == GA_OK)
        FZ_CHECK(fz_all_finite(J.c, 32), "join: GA_OK with a non-finite result");
    if (ms == GA_OK)
        FZ_CHECK(fz_all_finite(M.c, 32), "meet_rel: GA_OK with a non-finite result");
    if (same && js == GA_OK)
        FZ_CHECK(!memcmp(&J, &A, sizeof J), "join of A and %s is not A", same == 1 ? "A" : "2 A");
    if (same && ms == GA_OK)
        FZ_CHECK(!memcmp(&M, &B, sizeof M), "meet_rel of A and %s is not the second",
                 same == 1 ? "A" : "2 A");
}

/* The join and meet of X with itself and 2 X, and of blades made of X's
   doubles: vectors v1 (X's), v2 (e12..e25), v3 (e34..e45), the 4-vector q
   (X's): v1 ^ v2 with v2 ^ v3 (sharing v2), v1 with v1 ^ v2 (held), v1 ^ v2
   with q. */
static void mv_join(const ga_mv *X)
{
    join_pair(*X, *X, 1);
    ga_mv X2 = ga_mv_scale(*X, 2.0);
    if (fz_all_finite(X2.c, 32))
        join_pair(*X, X2, 2);
    const double *c = X->c;
    ga_mv v1 = ga_mv_grade(*X, 1), v2 = ga_mv_vector(c[6], c[7], c[8], c[9], c[10]),
          v3 = ga_mv_vector(c[11], c[12], c[13], c[14], c[15]), q = ga_mv_grade(*X, 4);
    ga_mv A = ga_mv_op(v1, v2);
    join_pair(A, ga_mv_op(v2, v3), 0);
    join_pair(v1, A, 0);
    join_pair(A, q, 0);
}

static void mv_any(const ga_mv *X, double lambda)
{
    mv_join(X);
    int fin = fz_all_finite(X->c, 32);
    ga_vec3 a, b, c;
    double r, d;
    int st;
    st = ga_point_down(*X, &a);
    FZ_CHECK(fin ? (st == GA_OK || st == GA_ERR_NOTPOINT) : st == GA_ERR_NOTFINITE, "down status %d", st);
    if (st == GA_OK)
        FZ_CHECK(vfinite(a), "down: GA_OK with a non-finite point");
    st = ga_point_down_scaled(*X, lambda, &a);
    FZ_CHECK(is_status(st), "down_scaled status %d", st);
    /* both NaN/Inf and lambda <= 0: either status is right */
    if (!fin || !isfinite(lambda))
        FZ_CHECK(st == GA_ERR_NOTFINITE || (st == GA_ERR_ARG && lambda <= 0),
                 "down_scaled of NaN/Inf, lambda %.17g: %d", lambda, st);
    else if (!(lambda > 0))
        FZ_CHECK(st == GA_ERR_ARG, "down_scaled, lambda %.17g: %d", lambda, st);
    if (st == GA_OK)
        FZ_CHECK(vfinite(a), "down_scaled: GA_OK with a non-finite point");
    st = ga_sphere_params(*X, &a, &r);
    FZ_CHECK(fin ? (st == GA_OK || st == GA_ERR_NOTBLADE || st == GA_ERR_IMAGINARY) : st == GA_ERR_NOTFINITE,
             "sphere %d", st);
    if (st == GA_OK)
        FZ_CHECK(vfinite(a) && isfinite(r) && r >= 0, "sphere: GA_OK with bad output");
    st = ga_plane_params(*X, &a, &d);
    FZ_CHECK(fin ? (st == GA_OK || st == GA_ERR_NOTBLADE) : st == GA_ERR_NOTFINITE, "plane %d", st);
    if (st == GA_OK)
        FZ_CHECK(vfinite(a) && isfinite(d) && fabs(vnorm(a) - 1) <= 1e-12, "plane: GA_OK with bad output");
    st = ga_line_params(*X, &a, &b);
    FZ_CHECK(fin ? (st == GA_OK || st == GA_ERR_NOTBLADE) : st == GA_ERR_NOTFINITE, "line %d", st);
    if (st == GA_OK)
        FZ_CHECK(vfinite(a) && vfinite(b) && fabs(vnorm(a) - 1) <= 1e-12, "line: GA_OK with bad output");
    st = ga_pointpair_points(*X, &a, &b);
    FZ_CHECK(fin ? (st == GA_OK || st == GA_ERR_NOTBLADE || st == GA_ERR_IMAGINARY) : st == GA_ERR_NOTFINITE,
             "pair %d", st);
    if (st == GA_OK)
        FZ_CHECK(vfinite(a) && vfinite(b), "point pair: GA_OK with bad output");
    ga_object ob; /* object.h: a kind and finite parameters, or a status */
    st = ga_object_from_mv(*X, &ob);
    FZ_CHECK(fin ? (st == GA_OK || st == GA_ERR_SINGULAR || st == GA_ERR_NOTBLADE || st == GA_ERR_PRECISION ||
                    st == GA_ERR_DOMAIN)
                 : st == GA_ERR_NOTFINITE,
             "object %d", st);
    if (st == GA_OK)
        FZ_CHECK(vfinite(ob.centre) && vfinite(ob.direction) && isfinite(ob.r2) &&
                     ob.kind >= GA_OBJECT_EMPTY && ob.kind <= GA_OBJECT_SPHERE && ob.err >= 0 &&
                     isfinite(ob.err) && ob.r2_err >= 0 && isfinite(ob.r2_err) && ob.angle_err >= 0 &&
                     isfinite(ob.angle_err),
                 "object: GA_OK with bad output or bounds");

    st = ga_circle_params(*X, &a, &r, &c);
    FZ_CHECK(fin ? (st == GA_OK || st == GA_ERR_NOTBLADE || st == GA_ERR_IMAGINARY) : st == GA_ERR_NOTFINITE,
             "circle %d", st);
    if (st == GA_OK)
        FZ_CHECK(vfinite(a) && isfinite(r) && vfinite(c), "circle: GA_OK with bad output");
    /* the local-origin functions (object.h): statuses, finite outputs, and
       the same kind, reality and direction as ga_object_from_mv reads */
    ga_vec3 og = {lambda, -0.5 * lambda, 0.25 * lambda};
    ga_object ob2;
    st = ga_object_from_mv_about(*X, og, lambda, &ob2);
    /* lambda (and the origin made of it) is checked first: NaN/Inf in it
       is GA_ERR_NOTFINITE, lambda <= 0 GA_ERR_ARG whatever X holds */
    int lam_ok = isfinite(lambda) && lambda > 0;
    FZ_CHECK(!isfinite(lambda) ? st == GA_ERR_NOTFINITE
             : !lam_ok         ? st == GA_ERR_ARG
             : !fin            ? st == GA_ERR_NOTFINITE
                               : (st == GA_OK || st == GA_ERR_SINGULAR || st == GA_ERR_NOTBLADE ||
                       st == GA_ERR_PRECISION || st == GA_ERR_DOMAIN),
             "object_about, lambda %.17g: %d", lambda, st);
    if (st == GA_OK) {
        FZ_CHECK(vfinite(ob2.centre) && vfinite(ob2.direction) && isfinite(ob2.r2) &&
                     ob2.kind >= GA_OBJECT_EMPTY && ob2.kind <= GA_OBJECT_SPHERE,
                 "object_about: GA_OK with bad output");
        ga_object ob1;
        if (ga_object_from_mv(*X, &ob1) == GA_OK)
            FZ_CHECK(ob1.kind == ob2.kind && ob1.direction.x == ob2.direction.x &&
                         ob1.direction.y == ob2.direction.y && ob1.direction.z == ob2.direction.z,
                     "object_about: kind %d or direction differs from object_from_mv's (kind %d)", ob2.kind,
                     ob1.kind);
    }
    ga_mv Y;
    st = ga_mv_localize(*X, og, lambda, &Y);
    FZ_CHECK(!fin || !isfinite(lambda) ? st == GA_ERR_NOTFINITE
             : !lam_ok                 ? st == GA_ERR_ARG
                                       : (st == GA_OK || st == GA_ERR_DOMAIN || st == GA_ERR_PRECISION),
             "localize, lambda %.17g: %d", lambda, st);
    if (st == GA_OK)
        FZ_CHECK(fz_all_finite(Y.c, 32), "localize: GA_OK with a non-finite result");
    ga_vec3 og2;
    st = ga_rotor_apply_about(ga_rotor_rotation((ga_vec3){0.6, 0, 0.8}, lambda), og, *X, &og2, &Y);
    FZ_CHECK(is_status(st), "apply_about %d", st);
    if (st == GA_OK) {
        FZ_CHECK(vfinite(og2) && fz_all_finite(Y.c, 32), "apply_about: GA_OK with a non-finite result");
        ga_object ob1;
        if (ga_object_from_mv(*X, &ob1) == GA_OK && ga_object_from_mv(Y, &ob2) == GA_OK &&
            ob1.kind >= GA_OBJECT_POINTPAIR)
            FZ_CHECK(ob2.kind == ob1.kind, "apply_about: a round of kind %d became kind %d", ob1.kind,
                     ob2.kind);
    }
    ga_mv inv;
    st = ga_mv_inverse(*X, &inv);
    FZ_CHECK(fin ? (st == GA_OK || st == GA_ERR_SINGULAR) : st == GA_ERR_NOTFINITE, "inverse %d", st);
    if (st == GA_OK)
        FZ_CHECK(fz_all_finite(inv.c, 32), "mv inverse: GA_OK with a non-finite result");
    /* the algebra of mv.h: statuses of their lists, and finite results with GA_OK */
    ga_mv pr, pw;
    st = ga_mv_project(*X, ga_mv_grade(*X, 2), &pr);
    FZ_CHECK(fin ? (st == GA_OK || st == GA_ERR_SINGULAR || st == GA_ERR_DOMAIN) : st == GA_ERR_NOTFINITE,
             "project %d", st);
    if (st == GA_OK)
        FZ_CHECK(fz_all_finite(pr.c, 32), "project: GA_OK with a non-finite result");
    st = ga_mv_reject(*X, ga_mv_grade(*X, 1), &pr);
    FZ_CHECK(fin ? (st == GA_OK || st == GA_ERR_SINGULAR || st == GA_ERR_DOMAIN) : st == GA_ERR_NOTFINITE,
             "reject %d", st);
    if (st == GA_OK)
        FZ_CHECK(fz_all_finite(pr.c, 32), "reject: GA_OK with a non-finite result");
    st = ga_mv_sqrt(*X, &pw);
    if (st == GA_OK)
        FZ_CHECK(fz_all_finite(pw.c, 32), "sqrt: GA_OK with a non-finite result");
    else
        FZ_CHECK(st < 0, "sqrt %d", st);
    ga_rotor R;
    st = ga_rotor_from_mv(*X, 1e-9, &R);
    FZ_CHECK(fin ? (st == GA_OK || st == GA_ERR_NOTRIGID || st == GA_ERR_DOMAIN) : st == GA_ERR_NOTFINITE,
             "from_mv %d", st);
    if (st == GA_OK)
        FZ_CHECK(rotor_finite(R) && ga_rotor_check(R, 1e-12) == GA_OK, "from_mv: GA_OK with a bad rotor");
}

/* exp and log of the general algebra (mv.h), on B = the bivector part of
 * X, and log on X itself.
 *
 * Bounds. ga_mv_exp writes each coefficient of R = exp(B) as a short sum of
 * products of the coefficients of B, B^2 and B B^2 with the closed-form
 * functions of the parts' squares l1, l2 (ga/mv_exp.c), every term at most
 * |R| = max |coefficient| in size, so that R is within a few dozen roundings,
 * k u |R| with k ~ 60 (u = 1.1e-16; measured 1.4e-14 |R|, docs/versors.md).
 * On the principal domain kept here (every elliptic half-angle t_i <= 1.5,
 * t1 + t2 <= 2.8, |B| <= 8) log is the inverse of exp with condition number
 * below 1 / sinc(1.5) ~ 1.5 times 1 / (pi - t1 - t2) <= 3 (the conjugate
 * point of Spin(4), docs/versors.md), so log's own few dozen roundings and
 * R's, carried through log and back through exp, leave exp(log R) within
 * about 60 u (1 + 3 * 1.5) |R| ~ 4e-14 |R| of R. 1e-12 |R| is 25 times that:
 * a net for lost digits, not a precision test (tests/test_versor.c is).
 * Outside that domain log's contract is only its own check: GA_OK means
 * exp(log R) = R to 1e-9 relative (versor.h), which is asserted as such. */
#define MV_LOG_TOL 1e-12

static ga_mv mv_sub(ga_mv a, ga_mv b)
{
    for (int i = 0; i < 32; i++) a.c[i] -= b.c[i];
    return a;
}
static ga_mv mv_biv(ga_mv X)
{
    ga_mv B = ga_mv_zero();
    for (int i = GA_BLADE_E12; i <= GA_BLADE_E45; i++) B.c[i] = X.c[i];
    return B;
}

/* The largest elliptic half-angle of B and the sum of both (0 for
   hyperbolic and null parts): l1, l2 the roots of l^2 - s l + qq/4 as in
   ga/internal/bivector_fns.h, an elliptic part l < 0 of half-angle sqrt(-l). */
static void mv_angles(ga_mv B, double *tmax, double *tsum)
{
    ga_mv b2 = ga_mv_gp(B, B), q = ga_mv_grade(b2, 4);
    double sq = b2.c[0], qq = ga_mv_sp(q, q), d = fmax(sq * sq - qq, 0.0);
    double l1 = 0.5 * (sq + copysign(sqrt(d), sq)), l2 = l1 != 0.0 ? 0.25 * qq / l1 : 0.0;
    double t1 = l1 < 0 ? sqrt(-l1) : 0.0, t2 = l2 < 0 ? sqrt(-l2) : 0.0;
    *tmax = fmax(t1, t2);
    *tsum = t1 + t2;
}

static void mv_exp_log(const ga_mv *X)
{
    ga_mv B = mv_biv(*X), R = ga_mv_exp(*X), L;
    int bfin = fz_all_finite(B.c, 32);
    /* NaN in, NaN out; exp reads the bivector part only */
    if (!bfin)
        FZ_CHECK(!fz_all_finite(R.c, 32), "mv_exp: NaN/Inf in, finite out");
    /* finite in: never NaN out (a hyperbolic part beyond ~710 overflows to
       +-Inf, as exp does; it gave inf * 0 = NaN) */
    for (int i = 0; bfin && i < 32; i++)
        FZ_CHECK(!isnan(R.c[i]), "mv_exp: finite in, NaN out (coefficient %d)", i);
    FZ_CHECK(ga_mv_maxabs(mv_sub(R, ga_mv_exp(B))) == 0.0, "mv_exp reads more than the bivector part");
    /* log of anything: GA_OK, GA_ERR_DOMAIN, or NOTFINITE exactly for NaN/Inf */
    int st = ga_mv_log(*X, &L);
    FZ_CHECK(fz_all_finite(X->c, 32) ? (st == GA_OK || st == GA_ERR_DOMAIN) : st == GA_ERR_NOTFINITE,
             "mv_log status %d", st);
    if (st == GA_OK) {
        FZ_CHECK(fz_all_finite(L.c, 32), "mv_log: GA_OK with a non-finite result");
        FZ_CHECK(ga_mv_maxabs(mv_sub(L, mv_biv(L))) == 0.0, "mv_log: not a bivector");
        /* versor.h: to 1e-9, or 64 u size^2 where that is larger (exp of a
           log of size |L| is known no better), size = min(|X|, |L|) + 4, up
           to 1e-6 */
        double mx = ga_mv_maxabs(*X), d = ga_mv_maxabs(mv_sub(ga_mv_exp(L), *X)) / fmax(1.0, mx);
        double sz = fmin(mx, ga_mv_maxabs(L)) + 4.0,
               lim = fmin(1e-6, fmax(1e-9, 64.0 * DBL_EPSILON * sz * sz));
        FZ_CHECK(d <= lim, "mv_log: GA_OK but exp(log X) misses X by %.3g (|X| %.3g, |log X| %.3g)", d, mx,
                 ga_mv_maxabs(L));
    }
    if (bfin) {
        /* a bivector of the Euclidean 4-space e1234 has only elliptic parts:
           its exp is bounded and on the group at any size (beyond ~1e77 its
           square overflows: ga/mv_exp.c's exp_huge_*) */
        ga_mv E = ga_mv_zero();
        static const int e1234[] = {GA_BLADE_E12, GA_BLADE_E13, GA_BLADE_E14,
                                    GA_BLADE_E23, GA_BLADE_E24, GA_BLADE_E34};
        for (int i = 0; i < 6; i++) E.c[e1234[i]] = B.c[e1234[i]];
        ga_mv RE = ga_mv_exp(E), re;
        FZ_CHECK(fz_all_finite(RE.c, 32) && ga_mv_maxabs(RE) <= 1.0 + 1e-12,
                 "mv_exp of an e1234 bivector (max %.3g): not finite or above 1", ga_mv_maxabs(E));
        re = ga_mv_gp(RE, ga_mv_reverse(RE));
        re.c[0] -= 1.0;
        FZ_CHECK(ga_mv_maxabs(re) <= 1e-12, "mv_exp of an e1234 bivector (max %.3g): R ~R - 1 = %.3g",
                 ga_mv_maxabs(E), ga_mv_maxabs(re));
    }
    /* split: NOTFINITE exactly for NaN/Inf in the bivector part; else two
       finite parts summing to B (to rounding of the 4-space they span) */
    ga_mv B1, B2, F1, F2;
    st = ga_mv_split(*X, &B1, &B2);
    FZ_CHECK(bfin ? (st == GA_OK || st == GA_ERR_DOMAIN) : st == GA_ERR_NOTFINITE, "mv_split status %d", st);
    if (st == GA_OK) {
        FZ_CHECK(fz_all_finite(B1.c, 32) && fz_all_finite(B2.c, 32), "mv_split: GA_OK with non-finite parts");
        /* (B1 - B) + B2, quartered for a B above 1 (near DBL_MAX the parts
           and their sums may round past it), exact below (subnormals) */
        double d = 0.0, k = ga_mv_maxabs(B) > 1.0 ? 0.25 : 1.0;
        for (int i = 0; i < 32; i++) d = fmax(d, fabs((k * B1.c[i] - k * B.c[i]) + k * B2.c[i]));
        d /= k * ga_mv_maxabs(B);
        /* to 1e-11, or to the spacing of subnormals where B's parts are
           scaled back below DBL_MIN */
        FZ_CHECK(!(ga_mv_maxabs(B) > 0) || d <= 1e-11 + 0x1p-1068 / ga_mv_maxabs(B),
                 "mv_split: B1 + B2 misses B (max %.3g) by %.3g", ga_mv_maxabs(B), d);
    }
    /* factor: ga_mv_log's status, or split's */
    st = ga_mv_factor(*X, &F1, &F2);
    FZ_CHECK(is_status(st) && (st == GA_OK || st == GA_ERR_DOMAIN || st == GA_ERR_NOTFINITE),
             "mv_factor status %d", st);
    if (!bfin || ga_mv_maxabs(B) > 8.0)
        return;
    /* exp of a finite bivector up to 8 is finite and a rotor: even, R ~R = 1 */
    double sc = fmax(1.0, ga_mv_maxabs(R));
    FZ_CHECK(fz_all_finite(R.c, 32), "mv_exp of a bivector up to 8 is not finite");
    for (int g = 1; g <= 5; g += 2)
        FZ_CHECK(ga_mv_maxabs(ga_mv_grade(R, g)) == 0.0, "mv_exp: odd grade %d", g);
    ga_mv rr = ga_mv_gp(R, ga_mv_reverse(R));
    rr.c[0] -= 1.0;
    FZ_CHECK(ga_mv_maxabs(rr) <= 1e-12 * sc * sc, "mv_exp: R ~R - 1 = %.3g (|R| = %.3g)", ga_mv_maxabs(rr),
             sc);
    /* every exp(B) has a log; within the principal domain exp(log R) = R to
       MV_LOG_TOL, elsewhere (when log finds one) to its own 1e-9 */
    double tmax, tsum;
    mv_angles(B, &tmax, &tsum);
    st = ga_mv_log(R, &L);
    int principal = tmax <= 1.5 && tsum <= 2.8;
    if (principal)
        FZ_CHECK(st == GA_OK, "mv_log(exp(B)), half-angles %.17g (sum %.17g): status %d", tmax, tsum, st);
    if (st == GA_OK) {
        double d = ga_mv_maxabs(mv_sub(ga_mv_exp(L), R)) / sc;
        FZ_CHECK(d <= (principal ? MV_LOG_TOL : 1e-9),
                 "exp(log R) = R, half-angles %.3g (sum %.3g): off by %.3g", tmax, tsum, d);
    }
}

/* Text: X written and read back to the same doubles (a -0 reads as 0), or
   GA_ERR_NOTFINITE for NaN/Inf; then the rest of the input read as text:
   GA_OK, GA_ERR_ARG or GA_ERR_NOTFINITE, and what it reads writes and reads
   back the same. */
static void mv_text(const ga_mv *X, const uint8_t *rest, size_t nrest)
{
    char buf[GA_MV_TEXT_MAX], text[1024];
    size_t len = 0;
    ga_mv Y;
    int st = ga_mv_format(*X, buf, sizeof buf, &len);
    if (!fz_all_finite(X->c, 32)) {
        FZ_CHECK(st == GA_ERR_NOTFINITE, "mv_format of NaN/Inf: %d", st);
    } else {
        FZ_CHECK(st == GA_OK && len == strlen(buf), "mv_format: %d", st);
        st = ga_mv_parse(buf, &Y);
        FZ_CHECK(st == GA_OK, "mv_parse(mv_format(X)): %d on '%s'", st, buf);
        for (int i = 0; i < 32; i++)
            FZ_CHECK(Y.c[i] == X->c[i], "mv_parse(mv_format(X)): coefficient %d %.17g, not %.17g", i, Y.c[i],
                     X->c[i]);
    }
    size_t n = nrest < sizeof text - 1 ? nrest : sizeof text - 1;
    memcpy(text, rest, n);
    text[n] = '\0';
    st = ga_mv_parse(text, &Y);
    FZ_CHECK(st == GA_OK || st == GA_ERR_ARG || st == GA_ERR_NOTFINITE, "mv_parse status %d", st);
    if (st == GA_OK) {
        FZ_CHECK(fz_all_finite(Y.c, 32), "mv_parse: GA_OK with a non-finite coefficient");
        ga_mv Z;
        if (ga_mv_format(Y, buf, sizeof buf, &len) == GA_OK && ga_mv_parse(buf, &Z) == GA_OK)
            for (int i = 0; i < 32; i++) FZ_CHECK(Z.c[i] == Y.c[i], "mv text round trip, coefficient %d", i);
        else
            FZ_CHECK(0, "mv_parse read a text that does not write and read back");
    }
}

static void op_mv_any(fz_reader *rd)
{
    ga_mv X;
    fz_doubles(rd, X.c, 32);
    mv_any(&X, fz_double(rd));
    mv_exp_log(&X);
    mv_text(&X, rd->p + (rd->k < rd->n ? rd->k : rd->n), rd->k < rd->n ? rd->n - rd->k : 0);
}

/* Objects built from points, read back; points up and down. */
static void op_points(fz_reader *rd)
{
    double x[12];
    fz_doubles(rd, x, 12);
    double lambda = fz_double(rd), rad = fz_double(rd);
    uint8_t which = fz_byte(rd);
    ga_vec3 p[4] = {{x[0], x[1], x[2]}, {x[3], x[4], x[5]}, {x[6], x[7], x[8]}, {x[9], x[10], x[11]}};
    for (int i = 0; i < 4; i++) {
        ga_vec3 y;
        int st = ga_point_down(ga_point_up(p[i]), &y);
        if (!vfinite(p[i])) {
            FZ_CHECK(st == GA_ERR_NOTFINITE, "down(F(NaN)): %d", st);
            continue;
        }
        double s = fmax(1.0, vnorm(p[i]));
        if (s <= 1e4) {
            FZ_CHECK(st == GA_OK, "down(F(x)), |x| = %.3g: %d", s, st);
            double d = vnorm((ga_vec3){y.x - p[i].x, y.y - p[i].y, y.z - p[i].z}) / s;
            FZ_CHECK(d <= 1e-13, "down(F(x)) = x: off by %.3g", d);
        }
        if (isfinite(lambda) && lambda >= 1e-6 && lambda <= 1e6 && vnorm(p[i]) <= 1e4 * lambda) {
            ga_mv Xs;
            st = ga_point_up_scaled(p[i], lambda, &Xs);
            FZ_CHECK(st == GA_OK, "up_scaled(x), |x| = %.3g, lambda %.3g: %d", vnorm(p[i]), lambda, st);
            st = ga_point_down_scaled(Xs, lambda, &y);
            FZ_CHECK(st == GA_OK, "down_scaled(F(x)), |x| = %.3g, lambda %.3g: %d", vnorm(p[i]), lambda, st);
            double d = vnorm((ga_vec3){y.x - p[i].x, y.y - p[i].y, y.z - p[i].z}) / fmax(lambda, vnorm(p[i]));
            FZ_CHECK(d <= 1e-13, "down_scaled(F(x)) = x: off by %.3g", d);
        }
    }
    ga_mv X;
    switch (which % 8) {
    case 0: X = ga_pointpair_from_points(p[0], p[1]); break;
    case 1: X = ga_circle_from_points(p[0], p[1], p[2]); break;
    case 2: X = ga_line_from_points(p[0], p[1]); break;
    case 3: X = ga_sphere_from_points(p[0], p[1], p[2], p[3]); break;
    case 4: X = ga_plane_from_points(p[0], p[1], p[2]); break;
    case 5: X = ga_sphere_dual(p[0], rad); break;
    case 6: X = ga_plane_dual(p[0], rad); break;
    default:
        if (ga_point_up_scaled(p[0], lambda, &X) != GA_OK)
            X = ga_point_up(p[0]);
        break;
    }
    mv_any(&X, lambda);
    if (which % 8 == 5 && vfinite(p[0]) && isfinite(rad) && vnorm(p[0]) <= 1e3 && fabs(rad) >= 1e-3 &&
        fabs(rad) <= 1e3) {
        ga_vec3 c;
        double r;
        int st = ga_sphere_params(X, &c, &r);
        FZ_CHECK(st == GA_OK, "sphere_params(dual_sphere(c, r)) fails: %d", st);
        double s = fmax(1.0, fmax(vnorm(p[0]), fabs(rad)));
        double d = fmax(vnorm((ga_vec3){c.x - p[0].x, c.y - p[0].y, c.z - p[0].z}), fabs(r - fabs(rad)));
        FZ_CHECK(d <= 1e-12 * s * s, "dual sphere read back off by %.3g (scene %.3g)", d, s);
    }
    /* a dual sphere held about the origin p[1] at the length lam, a power of
       two near its radius (object.h): where the origin is near the sphere
       (within 8 radii: c - o is then within 8 u L of exact), it reads back
       to 1e-12 of L = max(1, |c| + |r|) at any distance, never refused */
    double rr = fabs(rad), q = vnorm((ga_vec3){p[0].x - p[1].x, p[0].y - p[1].y, p[0].z - p[1].z});
    if (which % 8 == 5 && vfinite(p[0]) && vfinite(p[1]) && isfinite(rad) && rr >= 1e-100 && rr <= 1e100 &&
        vnorm(p[0]) <= 1e100 && vnorm(p[1]) <= 1e100 && q <= 8 * rr) {
        double lam = ldexp(1.0, ilogb(rr)), L = fmax(1.0, vnorm(p[0]) + rr);
        ga_vec3 cl = {(p[0].x - p[1].x) / lam, (p[0].y - p[1].y) / lam, (p[0].z - p[1].z) / lam};
        ga_object ob;
        int st = ga_object_from_mv_about(ga_sphere_dual(cl, rad / lam), p[1], lam, &ob);
        FZ_CHECK(st == GA_OK, "object_about(dual sphere about a near origin): %d", st);
        if (st == GA_OK) {
            double d = vnorm((ga_vec3){ob.centre.x - p[0].x, ob.centre.y - p[0].y, ob.centre.z - p[0].z}) / L;
            d = fmax(d, fabs(ob.r2 - rr * rr) / (L * L));
            FZ_CHECK(ob.kind == GA_OBJECT_SPHERE && d <= 1e-12,
                     "dual sphere about a near origin: kind %d, off by %.3g (L %.3g)", ob.kind, d, L);
        }
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_reader rd = fz_begin(data, size);
    switch (fz_byte(&rd) % 11) {
    case 0: op_exp_log(&rd); break;
    case 1: op_rotor_any(&rd); break;
    case 2: op_rotor_drift(&rd); break;
    case 3: op_mat_any(&rd); break;
    case 4: op_mat_near(&rd); break;
    case 5: op_se3(&rd); break;
    case 6: op_expm_logm(&rd); break;
    case 7: op_bridge(&rd); break;
    case 8: op_screw(&rd); break;
    case 9: op_mv_any(&rd); break;
    default: op_points(&rd); break;
    }
    return 0;
}
