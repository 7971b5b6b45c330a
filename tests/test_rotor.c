/* tests/test_rotor.c: the compact rotor, exp and l(R), screws and the bridge,
 * checked against the full algebra (mv.h, conformal.h) and independent
 * references computed here (Taylor series with scaling and squaring, in double
 * through ga_mv_gp and in long double for 4x4 matrices; quaternion SLERP; the
 * helix of Wareham-Lasenby §4.1).
 *
 *   test_rotor [M]   runs M times the default counts (M = 100: 1e6 per family).
 *
 * Every error is measured, printed (worst per family) and compared with a
 * tolerance derived from the computation: EPS times the number of rounding
 * steps the formula takes, times the size of what is compared. Exits nonzero
 * on any failure.
 */
#include "testkit.h"

#include <stdlib.h>

#define N_CASES 10000 /* per family in the default run */
#define N_PATH 1000   /* samples along a path */
#define EPS DBL_EPSILON
#define PI TK_PI

static tk_rng rng = {0x9E3779B97F4A7C15u}; /* testkit.h: splitmix64 */
static long n_cases;                       /* per family: N_CASES times the scale argument */

/* ---- small vector helpers ------------------------------------------------ */
static ga_vec3 v3(double x, double y, double z)
{
    ga_vec3 r = {x, y, z};
    return r;
}
static ga_vec3 vadd(ga_vec3 a, ga_vec3 b) { return v3(a.x + b.x, a.y + b.y, a.z + b.z); }
static ga_vec3 vsub(ga_vec3 a, ga_vec3 b) { return v3(a.x - b.x, a.y - b.y, a.z - b.z); }
static ga_vec3 vscale(ga_vec3 a, double k) { return v3(k * a.x, k * a.y, k * a.z); }
static double vdot(ga_vec3 a, ga_vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static double vnorm(ga_vec3 a) { return sqrt(vdot(a, a)); }
static double vmaxabs(ga_vec3 a) { return tk_max(fabs(a.x), tk_max(fabs(a.y), fabs(a.z))); }
static ga_vec3 vcross(ga_vec3 a, ga_vec3 b)
{
    return v3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
/* Random vectors, each draw its own statement (C leaves the order of
 * evaluation of arguments and initializers unspecified): a unit direction,
 * then its length (len, k times uniform in [0, 1), log-uniform in [lo, hi)). */
static ga_vec3 rnd_vec(double len) { return vscale(tk_unit(&rng), len); }
static ga_vec3 rnd_vec_u(double k)
{
    ga_vec3 u = tk_unit(&rng);
    return vscale(u, k * tk_uni(&rng));
}
static ga_vec3 rnd_vec_logu(double lo, double hi)
{
    ga_vec3 u = tk_unit(&rng);
    return vscale(u, tk_loguni(&rng, lo, hi));
}
/* A unit vector perpendicular to the unit vector u. */
static ga_vec3 rnd_perp(ga_vec3 u)
{
    for (;;) {
        ga_vec3 v = tk_unit(&rng);
        ga_vec3 p = vsub(v, vscale(u, vdot(u, v)));
        double n = vnorm(p);
        if (n > 0.1)
            return vscale(p, 1.0 / n);
    }
}

/* ---- rotor, generator helpers ---------------------------------------- */
static double r_comp(ga_rotor r, int i)
{
    const double c[8] = {r.s, r.e12, r.e13, r.e23, r.e1n, r.e2n, r.e3n, r.e123n};
    return c[i];
}
static double rdiff(ga_rotor a, ga_rotor b)
{
    double d = 0.0;
    for (int i = 0; i < 8; i++) d = tk_max(d, fabs(r_comp(a, i) - r_comp(b, i)));
    return d;
}
static ga_rotor rneg(ga_rotor r)
{
    ga_rotor o = {-r.s, -r.e12, -r.e13, -r.e23, -r.e1n, -r.e2n, -r.e3n, -r.e123n};
    return o;
}
/* Distance up to sign (R and -R are the same motion). */
static double rdiff_pm(ga_rotor a, ga_rotor b) { return fmin(rdiff(a, b), rdiff(a, rneg(b))); }
static double rmaxabs(ga_rotor r) { return rdiff(r, rneg(r)) / 2.0; }
static ga_rotor rnd_rotor8(double scale)
{
    ga_rotor r;
    double *c = &r.s;
    for (int k = 0; k < 8; k++) c[k] = scale * tk_range(&rng, -1, 1);
    return r;
}
static double gdiff(ga_generator a, ga_generator b)
{
    return tk_max(tk_max(fabs(a.e12 - b.e12), tk_max(fabs(a.e13 - b.e13), fabs(a.e23 - b.e23))),
                  tk_max(fabs(a.e1n - b.e1n), tk_max(fabs(a.e2n - b.e2n), fabs(a.e3n - b.e3n))));
}
static ga_twist twist(ga_vec3 w, ga_vec3 v)
{
    ga_twist t = {w, v};
    return t;
}
static ga_generator gen(ga_vec3 w, ga_vec3 v) { return ga_twist_to_generator(twist(w, v)); }

/* ---- references ------------------------------------------------------------ */

/* exp(B) in the full algebra: Taylor series of ga_mv_gp with scaling and squaring.
 * Powers of B = beta I3 + c n grow like |beta|^k + k |beta|^(k-1) |c| (c n is
 * nilpotent), so the scaling is chosen by |beta| alone: |beta| / 2^k <= 1/8,
 * where 14 terms leave < 1e-20. *k_out = k (each squaring doubles the error).
 * The c n c n terms cancel inside ga_mv_gp's sums, which costs EPS |c|^2 in the
 * scalar part; so the series is summed for c / |c| and the n part scaled by |c|
 * afterwards (exp is affine in c: (c n) X (c n) = 0 for every even X). */
static ga_rotor mv_exp(ga_generator g, int *k_out)
{
    double nb = sqrt(g.e12 * g.e12 + g.e13 * g.e13 + g.e23 * g.e23);
    double nc = sqrt(g.e1n * g.e1n + g.e2n * g.e2n + g.e3n * g.e3n), kc = nc > 0 ? 1 / nc : 0;
    ga_generator gu = {g.e12, g.e13, g.e23, kc * g.e1n, kc * g.e2n, kc * g.e3n};
    int k = 0;
    while (nb > 0.125) nb *= 0.5, k++;
    ga_mv X = ga_mv_scale(ga_generator_to_mv(gu), ldexp(1.0, -k)), E = ga_mv_scalar(1.0), T = E;
    for (int j = 1; j <= 14; j++) {
        T = ga_mv_scale(ga_mv_gp(T, X), 1.0 / j);
        E = ga_mv_add(E, T);
    }
    for (int i = 0; i < k; i++) E = ga_mv_gp(E, E);
    *k_out = k;
    ga_rotor r;
    tk_add_bool(tk_get("full-algebra exp lies in the 8-component form"),
                ga_rotor_from_mv(E, 1e-6, &r) == GA_OK);
    ga_rotor raw = {E.c[GA_BLADE_SCALAR],   E.c[GA_BLADE_E12],       E.c[GA_BLADE_E13],
                    E.c[GA_BLADE_E23],      nc * E.c[GA_BLADE_E14],  nc * E.c[GA_BLADE_E24],
                    nc * E.c[GA_BLADE_E34], nc * E.c[GA_BLADE_E1234]};
    return raw;
}

/* expm(xi^) in long double: Taylor with scaling and squaring (scaled by |w|,
 * as above: the powers of xi^ are [[W^k, W^(k-1) v]; 0]). */
typedef long double ld;
static void mm_ld(const ld *a, const ld *b, ld *c)
{
    ld t[16];
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            ld s = 0;
            for (int k = 0; k < 4; k++) s += a[4 * i + k] * b[4 * k + j];
            t[4 * i + j] = s;
        }
    for (int i = 0; i < 16; i++) c[i] = t[i];
}
static ga_mat4 expm_ref(ga_twist xi)
{
    ld A[16] = {0,       -xi.w.z, xi.w.y, xi.v.x, xi.w.z, 0, -xi.w.x, xi.v.y,
                -xi.w.y, xi.w.x,  0,      xi.v.z, 0,      0, 0,       0};
    ld th = sqrtl((ld)xi.w.x * xi.w.x + (ld)xi.w.y * xi.w.y + (ld)xi.w.z * xi.w.z);
    int k = 0;
    while (th > 0.125L) th *= 0.5L, k++;
    for (int i = 0; i < 16; i++) A[i] = ldexpl(A[i], -k);
    ld E[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}, T[16];
    for (int i = 0; i < 16; i++) T[i] = E[i];
    for (int j = 1; j <= 20; j++) {
        mm_ld(T, A, T);
        for (int i = 0; i < 16; i++) T[i] /= j, E[i] += T[i];
    }
    for (int i = 0; i < k; i++) mm_ld(E, E, E);
    ga_mat4 m;
    for (int i = 0; i < 16; i++) m.m[i] = (double)E[i];
    return m;
}
static double mdiff(ga_mat4 a, ga_mat4 b)
{
    double d = 0.0;
    for (int i = 0; i < 16; i++) d = tk_max(d, fabs(a.m[i] - b.m[i]));
    return d;
}
static ga_mat4 mmul(ga_mat4 a, ga_mat4 b)
{
    ga_mat4 c;
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            double s = 0;
            for (int k = 0; k < 4; k++) s += a.m[4 * i + k] * b.m[4 * k + j];
            c.m[4 * i + j] = s;
        }
    return c;
}

/* Hamilton quaternion product and the plain dual-quaternion product. */
static ga_quat qmul(ga_quat a, ga_quat b)
{
    ga_quat r = {a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z, a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
                 a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x,
                 a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
    return r;
}
static ga_quat qadd(ga_quat a, ga_quat b)
{
    ga_quat r = {a.w + b.w, a.x + b.x, a.y + b.y, a.z + b.z};
    return r;
}
static double qdiff(ga_quat a, ga_quat b)
{
    return tk_max(tk_max(fabs(a.w - b.w), fabs(a.x - b.x)), tk_max(fabs(a.y - b.y), fabs(a.z - b.z)));
}
static double qdiff_pm(ga_quat a, ga_quat b)
{
    ga_quat nb = {-b.w, -b.x, -b.y, -b.z};
    return fmin(qdiff(a, b), qdiff(a, nb));
}
static ga_dualquat dqmul(ga_dualquat a, ga_dualquat b)
{
    ga_dualquat r = {qmul(a.real, b.real), qadd(qmul(a.real, b.dual), qmul(a.dual, b.real))};
    return r;
}

/* ---- the checks ------------------------------------------------------------ */

static void check_product(void)
{
    long n = n_cases;
    tk_note("compact product, reverse, conversion (full algebra as reference)\n");
    tk_check w_mul = tk_begin("ga_rotor_mul vs ga_mv_gp, / (max|a| max|b|)", 32 * EPS);
    tk_check w_rev = tk_begin("ga_rotor_reverse vs ga_mv_reverse (exact)", 0.0);
    tk_check w_out = tk_begin("ga_mv_gp of two rotor forms: outside the 8 components", 32 * EPS);
    tk_check w_conv = tk_begin("to_mv -> from_mv round trip (with projection)", 8 * EPS);
    for (long i = 0; i < n; i++) {
        ga_rotor a = rnd_rotor8(tk_loguni(&rng, 1e-3, 1e3)), b = rnd_rotor8(tk_loguni(&rng, 1e-3, 1e3));
        ga_mv full = ga_mv_gp(ga_rotor_to_mv(a), ga_rotor_to_mv(b));
        ga_rotor c = ga_rotor_mul(a, b);
        double scale = rmaxabs(a) * rmaxabs(b);
        /* each coefficient: 8 products summed (compact) vs up to 16 (full) */
        tk_add(&w_mul, tk_mv_maxabs(ga_mv_sub(full, ga_rotor_to_mv(c))) / scale);
        ga_mv rest = full; /* closure: nothing outside the 8-component form */
        rest.c[GA_BLADE_E14] -= rest.c[GA_BLADE_E15], rest.c[GA_BLADE_E24] -= rest.c[GA_BLADE_E25];
        rest.c[GA_BLADE_E34] -= rest.c[GA_BLADE_E35], rest.c[GA_BLADE_E1234] -= rest.c[GA_BLADE_E1235];
        const int in[8] = {GA_BLADE_SCALAR, GA_BLADE_E12, GA_BLADE_E13, GA_BLADE_E23,
                           GA_BLADE_E15,    GA_BLADE_E25, GA_BLADE_E35, GA_BLADE_E1235};
        for (int k = 0; k < 8; k++) rest.c[in[k]] = 0;
        tk_add(&w_out, tk_mv_maxabs(rest) / scale);
        tk_add(&w_rev, tk_mv_maxabs(ga_mv_sub(ga_mv_reverse(ga_rotor_to_mv(a)),
                                              ga_rotor_to_mv(ga_rotor_reverse(a)))));
        ga_vec3 gw = rnd_vec_u(3), gv = rnd_vec_logu(1e-3, 1e3);
        ga_generator g = gen(gw, gv);
        ga_rotor r = ga_rotor_exp(g), back;
        int st = ga_rotor_from_mv(ga_rotor_to_mv(r), 1e-9, &back);
        tk_add(&w_conv, st == GA_OK ? rdiff(back, r) / fmax(1, rmaxabs(r)) : INFINITY);
    }
    tk_end(&w_mul);
    tk_end(&w_out);
    tk_end(&w_rev);
    tk_end(&w_conv);
}

static void check_action(void)
{
    long n = n_cases;
    tk_note("action on points and objects (full sandwich R F(x) ~R as reference)\n");
    tk_check w_pt = tk_begin("apply vs down(R F(x) ~R), / ((1+|t|)^2 (1+|x|^2))", 64 * EPS);
    tk_check w_null = tk_begin("R F(x) ~R = F(apply(R, x))", 64 * EPS);
    tk_check w_n = tk_begin("R n ~R = n (Thm 8), exp's rotors", 32 * EPS);
    tk_check w_rr = tk_begin("R ~R = 1 (Thm 7), exp's rotors", 32 * EPS);
    tk_check w_comp = tk_begin("apply(R2 R1, x) = apply(R2, apply(R1, x))", 64 * EPS);
    for (long i = 0; i < n; i++) {
        double tl = tk_loguni(&rng, 1e-3, 1e2), xl = tk_loguni(&rng, 1e-3, 1e2);
        ga_vec3 gw = rnd_vec_u(4), gv = rnd_vec(tl);
        ga_generator g = gen(gw, gv);
        ga_rotor r = ga_rotor_exp(g);
        ga_vec3 x = vscale(tk_unit(&rng), xl), y = ga_rotor_apply(r, x), yf;
        ga_mv X = ga_rotor_apply_mv(r, ga_point_up(x));
        int st = ga_point_down(X, &yf);
        /* the sandwich multiplies coefficients of size (1 + |t|)^2 (1 + |x|^2):
           its rounding, relative to that, is a few dozen EPS */
        double scale = (1 + tl) * (1 + tl) * (1 + xl * xl);
        tk_add(&w_pt, st == GA_OK ? vmaxabs(vsub(y, yf)) / scale : INFINITY);
        tk_add(&w_null, tk_mv_maxabs(ga_mv_sub(X, ga_point_up(y))) / scale);
        ga_mv Rm = ga_rotor_to_mv(r);
        tk_add(&w_n,
               tk_mv_maxabs(ga_mv_sub(ga_rotor_apply_mv(r, ga_mv_n()), ga_mv_n())) / ((1 + tl) * (1 + tl)));
        tk_add(&w_rr, tk_mv_maxabs(ga_mv_sub(ga_mv_gp(Rm, ga_mv_reverse(Rm)), ga_mv_scalar(1))) /
                          ((1 + tl) * (1 + tl)));
        /* R2 R1 means R1 first */
        ga_vec3 w2 = rnd_vec_u(3), v2 = rnd_vec_u(10);
        ga_rotor r2 = ga_rotor_exp(gen(w2, v2));
        ga_vec3 z1 = ga_rotor_apply(ga_rotor_mul(r2, r), x), z2 = ga_rotor_apply(r2, y);
        tk_add(&w_comp, vmaxabs(vsub(z1, z2)) / (1 + tl + xl + 10));
    }
    tk_end(&w_pt);
    tk_end(&w_null);
    tk_end(&w_n);
    tk_end(&w_rr);
    tk_end(&w_comp);
    /* the contract's orientation: exp(B(xi)) with w = theta e3 turns e1 towards e2 */
    ga_vec3 e1r = ga_rotor_apply(ga_rotor_exp(gen(v3(0, 0, 0.3), v3(0, 0, 0))), v3(1, 0, 0));
    tk_add_bool(tk_get("w = 0.3 e3 rotates e1 to (cos 0.3, sin 0.3, 0)"),
                fabs(e1r.x - cos(0.3)) < 4 * EPS && fabs(e1r.y - sin(0.3)) < 4 * EPS && e1r.z == 0);
    ga_vec3 tr = ga_rotor_apply(ga_rotor_exp(gen(v3(0, 0, 0), v3(1, 2, 3))), v3(1, 1, 1));
    tk_add_bool(tk_get("v = (1,2,3) translates by (1,2,3)"), tr.x == 2 && tr.y == 3 && tr.z == 4);
    ga_vec3 ta = ga_rotor_apply(ga_rotor_translation(v3(1, -2, 5)), v3(0, 0, 0)), tf;
    TK_OK(ga_point_down(ga_rotor_apply_mv(ga_rotor_translation(v3(1, -2, 5)), ga_point_up(v3(0, 0, 0))),
                        &tf));
    tk_add_bool(tk_get("T_a = 1 + n a/2 translates by +a (W-L §2.2)"),
                ta.x == 1 && ta.y == -2 && ta.z == 5 &&
                    fabs(tf.x - 1) + fabs(tf.y + 2) + fabs(tf.z - 5) < 16 * EPS);
    ga_vec3 rr = ga_rotor_apply(ga_rotor_rotation(v3(0, 0, 2), PI / 2), v3(1, 0, 0));
    tk_add_bool(tk_get("ga_rotor_rotation is right-handed"),
                fabs(rr.x) < 4 * EPS && fabs(rr.y - 1) < 4 * EPS);
    tk_end_named();
}

/* exp of the closed form vs the full-algebra Taylor series. */
static void check_exp_series(void)
{
    long n = n_cases;
    tk_note("closed-form exp (Thm 3) vs Taylor series of ga_mv_gp with scaling and squaring\n");
    tk_check worst = tk_begin("|exp - series| / (max(1,|c|) (2^k + 1))", 32 * EPS);
    tk_check wr = tk_begin("closed-form exp is on the group to 16 EPS (0 = yes)", 0.0);
    for (long i = 0; i < n; i++) {
        double tl = tk_loguni(&rng, 1e-6, 1e3);
        double th = i % 3 == 0 ? tk_loguni(&rng, 1e-12, 1e-1) : 20 * tk_uni(&rng);
        ga_vec3 gw = rnd_vec(th), gv = rnd_vec(tl);
        ga_generator g = gen(gw, gv);
        int k;
        ga_rotor ref = mv_exp(g, &k), r = ga_rotor_exp(g);
        /* the series is exact to 1e-20; each of the k squarings doubles the
           error and adds ~16 EPS: bound 32 EPS (2^k + 1) of max(1, |c|) */
        double e = rdiff(r, ref) / fmax(1, tl) / (ldexp(1.0, k) + 1);
        tk_add(&worst, e);
        /* and Thm 7/8 for the closed form at these sizes */
        tk_add(&wr, fabs(ga_rotor_check(r, 16 * EPS) == GA_OK ? 0.0 : 1.0));
    }
    tk_end(&worst);
    tk_end(&wr);
    tk_end_named();
}

/* The other generator of a half turn: axis -u, same motion (v_par - v_perp). */
static ga_generator half_turn_alt(ga_vec3 w, ga_vec3 v)
{
    ga_vec3 u = vscale(w, 1.0 / vnorm(w)), vpar = vscale(u, vdot(u, v));
    return gen(vscale(w, -1), vsub(vpar, vsub(v, vpar)));
}

/* exp/log round trips over the twist families of testkit.h whose twists are
 * principal logs (all but the rotations beyond a half turn), and over rotors
 * just off the group (tk_drift of general screws). */
#define DRIFTED TK_TWIST_FAMILIES
static void check_exp_log(void)
{
    long n = n_cases;
    tk_note("exp(l(R)) = R and l(exp(B)) = B, error / max(1, |v|, |t|)\n");
    for (int f = 0; f <= DRIFTED; f++) {
        if (f == TK_BEYOND_PI)
            continue;
        int drifted = f == DRIFTED;
        tk_check w_el = tk_begin("   exp(l(R)) = R", 8 * EPS);
        tk_check w_le = tk_begin("   l(exp(B)) = B", 8 * EPS);
        tk_check w_lit = tk_begin("   exp(l_literal(R)) = R", 8 * EPS);
        tk_check w_litneg = tk_begin("   exp(l_literal(-R)) = -R (no sign flip), * sin(phi)", 8 * EPS);
        tk_check w_rot = tk_begin("   rotation part |w_log - w| / |w| (full relative accuracy)", 8 * EPS);
        double w_drift = 0;
        long cases = f == TK_IDENTITY ? 1 : n;
        for (long i = 0; i < cases; i++) {
            ga_twist xi = tk_twist(&rng, drifted ? TK_SCREW : f);
            ga_vec3 w = xi.w, v = xi.v, t;
            ga_generator B = gen(w, v), L;
            ga_rotor R = ga_rotor_exp(B), Rin = R;
            t = ga_rotor_to_translation(R);
            double scale = fmax(1, fmax(vnorm(v), vnorm(t)));
            if (drifted) { /* every coefficient moved by ~1e-12 relative */
                Rin = tk_drift(&rng, R);
                ga_rotor P;
                tk_add_bool(tk_get("normalize a drifted rotor"), ga_rotor_normalize(Rin, &P) == GA_OK);
                w_drift = fmax(w_drift, rdiff(P, R) / scale);
                R = P; /* exp(l(R)) must give back the projection */
            }
            int st = ga_rotor_log(Rin, &L);
            if (st != GA_OK) {
                tk_add(&w_el, INFINITY);
                continue;
            }
            tk_add(&w_el, rdiff_pm(ga_rotor_exp(L), R) / scale);
            if (!drifted) {
                double le = gdiff(L, B);
                if (f == TK_ROT_PI)
                    le = fmin(le, gdiff(L, half_turn_alt(w, v)));
                tk_add(&w_le, le / fmax(1, vnorm(v)));
            }
            /* the literal log inverts exp without a sign flip, also on -R, whose
               angle is 2 pi - theta: there sin(phi) = |<q>_2| is small, phi is
               known to EPS absolutely, so P_perp = sinc(phi) c_perp to EPS / sin(phi) */
            st = ga_rotor_log_literal(R, &L);
            tk_add(&w_lit, st == GA_OK ? rdiff(ga_rotor_exp(L), R) / scale : INFINITY);
            ga_rotor Rn = rneg(R);
            double sphi = fmin(1, sqrt(R.e12 * R.e12 + R.e13 * R.e13 + R.e23 * R.e23));
            st = ga_rotor_log_literal(Rn, &L);
            tk_add(&w_litneg, st == GA_OK ? rdiff(ga_rotor_exp(L), Rn) / scale * sphi : INFINITY);
            if (f == TK_TINY_UNDER_LARGE) { /* the rotation itself, relative to its own size */
                TK_OK(ga_rotor_log(R, &L));
                ga_twist xl = ga_generator_to_twist(L);
                tk_add(&w_rot, vnorm(vsub(xl.w, w)) / vnorm(w));
            }
        }
        if (drifted)
            tk_note(" %s, drifted by ~1e-12 (R ~R = 1 + ~1e-12) (%ld)\n", tk_family_name[TK_SCREW], cases);
        else
            tk_note(" %s (%ld)\n", tk_family_name[f], cases);
        /* exp and log each take O(10) roundings of quantities of size 1 or |t| */
        tk_end(&w_el);
        if (!drifted)
            tk_end(&w_le);
        tk_end(&w_lit);
        tk_end(&w_litneg);
        if (f == TK_TINY_UNDER_LARGE)
            tk_end(&w_rot);
        if (drifted) {
            tk_end_named();
            tk_note("     (projection moved the rotor by %.2e of max(1,|t|): the drift itself)\n", w_drift);
        }
    }
    /* the literal log past a half turn: l_literal(exp(B)) = B for angles in (pi, 2 pi - 1/2);
       c_perp is divided by sinc(phi) >= sinc(pi - 1/4) = 0.079, amplifying errors ~13x */
    tk_check w_lit = tk_begin("   l_literal(exp(B)) = B", 8 * 13 * EPS);
    for (long i = 0; i < n; i++) {
        ga_vec3 wu = tk_unit(&rng), w = vscale(wu, PI + (PI - 0.5) * tk_uni(&rng)),
                v = rnd_vec_logu(1e-3, 1e3);
        ga_generator B = gen(w, v), L;
        int st = ga_rotor_log_literal(ga_rotor_exp(B), &L);
        tk_add(&w_lit, st == GA_OK ? gdiff(L, B) / fmax(1, vnorm(v)) : INFINITY);
    }
    tk_note(" literal log, angles pi..2pi-1/2 (%ld)\n", n);
    tk_end(&w_lit);
    /* the full turn: q = -1 */
    ga_generator L;
    ga_rotor m1 = rneg(ga_rotor_translation(v3(0, 0, 2)));
    int st = ga_rotor_log_literal(m1, &L);
    tk_expect(st == GA_OK && rdiff(ga_rotor_exp(L), m1) < 8 * EPS, "literal log of -T_a (a turn of 2 pi)");
    st = ga_rotor_log(m1, &L);
    tk_expect(st == GA_OK && gdiff(L, gen(v3(0, 0, 0), v3(0, 0, 2))) == 0, "principal log of -T_a is a");
    /* near a full turn a screw's translation along its axis must not leak:
       p_perp is perpendicular to the axis only to rounding of |p|, and the
       literal log divides it by sin(phi) ~ pi - phi (2.4e-12 at 1e-4 before
       that rounding was taken out again along the axis) */
    tk_check w_full = tk_begin("   exp(l_literal(R)) = R, screws turning 2 pi - 2d, d in [1e-12, 0.3]",
                               8 * EPS);
    for (long i = 0; i < n; i++) {
        double d = tk_loguni(&rng, 1e-12, 0.3), shift = tk_range(&rng, -3, 3);
        ga_screw sc = {2 * (PI - d), tk_unit(&rng), vscale(tk_unit(&rng), tk_uni(&rng)), 0, shift};
        ga_rotor R = ga_rotor_from_screw(sc);
        /* the axis b = sin(phi) u as a product rounds it: to u absolutely,
           u / d relative, which tilts it off p (as in ga_mv_log's rigid frame) */
        R.e12 += tk_range(&rng, -EPS, EPS), R.e13 += tk_range(&rng, -EPS, EPS),
            R.e23 += tk_range(&rng, -EPS, EPS);
        st = ga_rotor_log_literal(R, &L);
        tk_add(&w_full, st == GA_OK ? rdiff(ga_rotor_exp(L), R) / fmax(1, fabs(shift)) : INFINITY);
    }
    tk_end(&w_full);
    /* the rotor that showed it: ga_mv_log's rigid frame of -exp(tE + N),
       pi - phi = 1e-4, p nearly along the axis (|p_perp| = 1.1e-5): exp of
       the literal log missed it by 2.4e-12 */
    ga_rotor rf = {-0.99999999500000003,   -2.6274830373048919e-05, -4.8660830899980295e-05,
                   8.3317205856422663e-05, -0.41710544675477335,    -0.24360720913890299,
                   0.13154961530410189,    5.0062633659095169e-05};
    tk_check w_rf = tk_begin("   exp(l_literal(R)) = R, the rotor near 2 pi from ga_mv_log's rigid frame",
                             8 * EPS);
    st = ga_rotor_log_literal(rf, &L);
    tk_add(&w_rf, st == GA_OK ? rdiff(ga_rotor_exp(L), rf) : INFINITY);
    tk_end(&w_rf);
}

static void check_matrix(void)
{
    long n = n_cases;
    tk_note("matrices: exp(B(xi)) vs long-double expm(xi^); rotor <-> matrix\n");
    tk_check w_exp = tk_begin("|mat(exp(B(xi))) - expm(xi^)| / max(1,|v|,|t|)", 1e-13);
    tk_check w_rmr = tk_begin("rotor -> matrix -> rotor (up to sign)", 8 * EPS);
    tk_check w_mrm = tk_begin("matrix -> rotor -> matrix", 16 * EPS);
    tk_check w_app = tk_begin("matrix action = ga_rotor_apply", 8 * EPS);
    tk_check w_mul = tk_begin("mat(R2 R1) = mat(R2) mat(R1)", 16 * EPS);
    for (long i = 0; i < n; i++) {
        int kind = i % 4;
        double th = kind == 0 ? tk_loguni(&rng, 1e-12, 1e-3)
                  : kind == 1 ? PI - tk_loguni(&rng, 1e-12, 1e-3)
                  : kind == 2 ? PI
                              : 3 * PI * tk_uni(&rng);
        double tl = tk_loguni(&rng, 1e-6, 1e3);
        ga_vec3 xw = rnd_vec(th), xv = rnd_vec(tl);
        ga_twist xi = twist(xw, xv);
        ga_rotor r = ga_rotor_exp(ga_twist_to_generator(xi)), back;
        ga_mat4 M = ga_rotor_to_mat4(r), E = expm_ref(xi);
        /* near a turn of 2 pi the motion's translation can be far below |v|, but
           sinc(theta/2) c_perp still carries the rounding of theta/2, EPS |v|:
           errors are measured against max(1, |v|, |t|) as for exp and log */
        double scale = fmax(fmax(1, tl), vmaxabs(v3(M.m[3], M.m[7], M.m[11])));
        tk_add(&w_exp, mdiff(M, E) / scale);
        int st = ga_rotor_from_mat4(M, &back);
        tk_add(&w_rmr, st == GA_OK ? rdiff_pm(back, r) / scale : INFINITY);
        tk_add(&w_mrm, st == GA_OK ? mdiff(ga_rotor_to_mat4(back), M) / scale : INFINITY);
        ga_vec3 x = rnd_vec_u(10), y = ga_rotor_apply(r, x);
        ga_vec3 ym = v3(M.m[0] * x.x + M.m[1] * x.y + M.m[2] * x.z + M.m[3],
                        M.m[4] * x.x + M.m[5] * x.y + M.m[6] * x.z + M.m[7],
                        M.m[8] * x.x + M.m[9] * x.y + M.m[10] * x.z + M.m[11]);
        tk_add(&w_app, vmaxabs(vsub(y, ym)) / (scale + 10));
        ga_vec3 w2 = rnd_vec_u(3), v2 = rnd_vec(tl);
        ga_rotor r2 = ga_rotor_exp(gen(w2, v2));
        tk_add(&w_mul,
               mdiff(ga_rotor_to_mat4(ga_rotor_mul(r2, r)), mmul(ga_rotor_to_mat4(r2), M)) / (2 * scale));
    }
    tk_end(&w_exp);
    tk_end(&w_rmr);
    tk_end(&w_mrm);
    tk_end(&w_app);
    tk_end(&w_mul);
    /* half turns by Shepperd: each coordinate axis and diagonals, exactly */
    const ga_vec3 axes[] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {0, 1, -1}, {1, 1, 1}};
    tk_check w_half = tk_begin("half turns about axes and diagonals, rotor -> matrix -> rotor", 8 * EPS);
    for (int a = 0; a < 6; a++) {
        ga_rotor r = ga_rotor_rotation(axes[a], PI), back;
        int st = ga_rotor_from_mat4(ga_rotor_to_mat4(r), &back);
        tk_add(&w_half, st == GA_OK ? rdiff_pm(back, r) : INFINITY);
    }
    tk_end(&w_half);
}

static void check_quat(void)
{
    long n = n_cases;
    tk_note("quaternions and dual quaternions\n");
    tk_check w_q = tk_begin("quat(rotation(u, th)) = (cos th/2, sin th/2 u)", 8 * EPS);
    tk_check w_rq = tk_begin("rotor -> (quat, t) -> rotor", 8 * EPS);
    tk_check w_dq = tk_begin("dual quat = (r, t r / 2) computed independently", 8 * EPS);
    tk_check w_dqr = tk_begin("rotor -> dual quat -> rotor (exact)", 0.0);
    tk_check w_dqm = tk_begin("dq(R2 R1) = dq(R2) dq(R1) (plain dual-quaternion product)", 16 * EPS);
    tk_check w_rod = tk_begin("its matrix = Rodrigues' formula", 16 * EPS);
    for (long i = 0; i < n; i++) {
        ga_vec3 u = tk_unit(&rng);
        double th = 2 * PI * tk_uni(&rng);
        ga_rotor rot = ga_rotor_rotation(u, th);
        ga_quat q = ga_rotor_to_quat(rot);
        ga_quat qe = {cos(th / 2), sin(th / 2) * u.x, sin(th / 2) * u.y, sin(th / 2) * u.z};
        tk_add(&w_q, qdiff(q, qe));
        /* its matrix vs Rodrigues: I + sin [u]x + (1 - cos) [u]x^2 */
        ga_mat4 M = ga_rotor_to_mat4(rot);
        double c = cos(th), s = sin(th), K[9] = {0, -u.z, u.y, u.z, 0, -u.x, -u.y, u.x, 0};
        for (int a = 0; a < 3; a++)
            for (int b = 0; b < 3; b++) {
                double k2 = 0;
                for (int m = 0; m < 3; m++) k2 += K[3 * a + m] * K[3 * m + b];
                tk_add(&w_rod, fabs(M.m[4 * a + b] - ((a == b) + s * K[3 * a + b] + (1 - c) * k2)));
            }
        ga_vec3 rw = rnd_vec_u(3), rv = rnd_vec_logu(1e-3, 1e3);
        ga_rotor r = ga_rotor_exp(gen(rw, rv));
        ga_vec3 t = ga_rotor_to_translation(r);
        ga_quat rq = ga_rotor_to_quat(r);
        double scale = fmax(1, vnorm(t));
        tk_add(&w_rq, rdiff(ga_rotor_from_quat(rq, t), r) / scale);
        ga_dualquat d = ga_rotor_to_dualquat(r);
        ga_quat tq = {0, t.x, t.y, t.z}, half = qmul(tq, rq);
        ga_quat dual = {half.w / 2, half.x / 2, half.y / 2, half.z / 2};
        tk_add(&w_dq, tk_max(qdiff(d.real, rq), qdiff(d.dual, dual)) / scale);
        tk_add(&w_dqr, rdiff(ga_rotor_from_dualquat(d), r));
        ga_vec3 w2 = rnd_vec_u(3), v2 = rnd_vec_logu(1e-3, 1e3);
        ga_rotor r2 = ga_rotor_exp(gen(w2, v2));
        ga_dualquat p = dqmul(ga_rotor_to_dualquat(r2), d), pr = ga_rotor_to_dualquat(ga_rotor_mul(r2, r));
        tk_add(&w_dqm, tk_max(qdiff(p.real, pr.real), qdiff(p.dual, pr.dual)) / (rmaxabs(r) * rmaxabs(r2)));
    }
    /* 4 roundings in the rotor, 2 in the reference; 1 - 2 (y^2 + z^2) and
       Rodrigues' 1 + (1 - c) k2 each round ~6 times quantities of size <= 2 */
    tk_end(&w_q);
    tk_end(&w_rod);
    tk_end(&w_rq);
    tk_end(&w_dq);
    tk_end(&w_dqr);
    tk_end(&w_dqm);
}

/* W-L §2.1: pure-rotation rotors interpolate as quaternion SLERP. */
static void check_slerp(void)
{
    long n = n_cases / 10;
    tk_note("pure rotations interpolate as quaternion SLERP (W-L §2.1)\n");
    tk_check worst = tk_begin("|exp(lam l(R2 ~R1)) R1 - slerp(q0, q1, lam)| sin(om)", 16 * EPS);
    for (long i = 0; i < n; i++) {
        ga_vec3 u1 = tk_unit(&rng);
        ga_rotor r1 = ga_rotor_rotation(u1, 2 * PI * tk_uni(&rng));
        ga_vec3 u2 = tk_unit(&rng);
        ga_rotor r2 = ga_rotor_mul(ga_rotor_rotation(u2, 0.01 + 3 * tk_uni(&rng)), r1);
        ga_quat q0 = ga_rotor_to_quat(r1), q1 = ga_rotor_to_quat(r2);
        double d = q0.w * q1.w + q0.x * q1.x + q0.y * q1.y + q0.z * q1.z;
        if (d < 0)
            q1.w = -q1.w, q1.x = -q1.x, q1.y = -q1.y, q1.z = -q1.z, d = -d;
        ga_quat df = {q1.w - q0.w, q1.x - q0.x, q1.y - q0.y, q1.z - q0.z};
        ga_quat sm = {q1.w + q0.w, q1.x + q0.x, q1.y + q0.y, q1.z + q0.z};
        double om = 2 * atan2(sqrt(df.w * df.w + df.x * df.x + df.y * df.y + df.z * df.z),
                              sqrt(sm.w * sm.w + sm.x * sm.x + sm.y * sm.y + sm.z * sm.z));
        ga_generator L;
        TK_OK(ga_rotor_log(ga_rotor_mul(r2, ga_rotor_reverse(r1)), &L));
        for (int k = 0; k <= 10; k++) {
            double lam = k / 10.0;
            double a = sin((1 - lam) * om) / sin(om), b = sin(lam * om) / sin(om);
            ga_quat qs = {a * q0.w + b * q1.w, a * q0.x + b * q1.x, a * q0.y + b * q1.y, a * q0.z + b * q1.z};
            ga_generator Ll = {lam * L.e12, lam * L.e13, lam * L.e23, 0, 0, 0};
            ga_rotor rl = ga_rotor_mul(ga_rotor_exp(Ll), r1);
            /* slerp's weights lose ~EPS / sin(om) */
            tk_add(&worst, qdiff_pm(ga_rotor_to_quat(rl), qs) * sin(om));
        }
    }
    tk_end(&worst);
}

/* W-L §4.1: the path of exp(lam B) from the origin is the helix r_lam. */
static void check_helix(void)
{
    tk_note("the helix of W-L §4.1 (Fig. 7: t_par = 4a + 6b, psi = 9 pi, |t_perp| = 1)\n");
    tk_check w_fix = tk_begin("r_lam with -lam t_perp (T_a = 1 + n a/2 of §2.2)", 64 * EPS * 8);
    tk_check w_printed = tk_begin("r_lam as printed (+lam t_perp) misses by 2 lam |t_perp|: |miss - 2 lam|",
                                  64 * EPS * 8);
    tk_check w_axis = tk_begin("screw axis passes through alpha/psi (a sin b1 + b cos b1)", 64 * EPS * 8);
    tk_check w_miss = tk_begin_least("r_lam as printed misses the path at lam = 1 by at least 1", 1.0);
    for (int trial = 0; trial < 20; trial++) {
        ga_vec3 a = v3(1, 0, 0), b = v3(0, 1, 0);
        if (trial > 0)
            a = tk_unit(&rng), b = rnd_perp(a);
        ga_vec3 tperp = vcross(a, b); /* unit, out of the plane */
        double psi = 9 * PI, ta = 4, tb = 6;
        ga_vec3 t = vadd(vadd(vscale(a, ta), vscale(b, tb)), tperp);
        /* B = (psi/2) P + t n/2 with P = ab = a ^ b: (e12, e13, e23) of a ^ b, c = t/2 */
        ga_generator B = {psi / 2 * (a.x * b.y - a.y * b.x),
                          psi / 2 * (a.x * b.z - a.z * b.x),
                          psi / 2 * (a.y * b.z - a.z * b.y),
                          t.x / 2,
                          t.y / 2,
                          t.z / 2};
        double alpha = hypot(ta, tb), b1 = atan2(-tb, ta); /* cos b1 = ta/alpha, sin b1 = -tb/alpha */
        ga_vec3 centre = vscale(vadd(vscale(a, sin(b1)), vscale(b, cos(b1))), alpha / psi);
        for (int k = 0; k <= N_PATH; k++) {
            double lam = (double)k / N_PATH;
            ga_generator Bl = {lam * B.e12, lam * B.e13, lam * B.e23, lam * B.e1n, lam * B.e2n, lam * B.e3n};
            ga_rotor R = ga_rotor_exp(Bl);
            ga_vec3 r = ga_rotor_apply(R, v3(0, 0, 0));
            ga_vec3 circ = vadd(vscale(vadd(vscale(a, sin(lam * psi + b1)), vscale(b, cos(lam * psi + b1))),
                                       -alpha / psi),
                                centre);
            /* the printed formula is the path moved by +2 lam t_perp, exactly in
               exact arithmetic: its miss is 2 lam |t_perp| = 2 lam (so 2 at
               lam = 1), to the rounding of the path itself */
            double miss = vnorm(vsub(r, vadd(circ, vscale(tperp, lam))));
            tk_add(&w_printed, fabs(miss - 2 * lam));
            if (k == N_PATH)
                tk_add(&w_miss, miss);
            tk_add(&w_fix, vnorm(vsub(r, vsub(circ, vscale(tperp, lam)))));
            ga_screw s;
            if (fmod(lam * psi, 2 * PI) > 0.1 && fmod(lam * psi, 2 * PI) < 2 * PI - 0.1 &&
                ga_rotor_to_screw(R, &s) == GA_OK) /* the screw axis passes through the centre */
                tk_add(&w_axis, vnorm(vcross(vsub(centre, s.point), s.axis)));
        }
    }
    /* a path point is a few dozen roundings of quantities of size |t| = 7.3 */
    tk_end(&w_printed);
    tk_end(&w_miss);
    tk_end(&w_fix);
    tk_end(&w_axis);
}

/* Definition 4, Lemmas 5 and 6 and Thm 9 as the paper states them, in the full algebra. */
static void check_paper_forms(void)
{
    long n = n_cases;
    tk_note("W-L Def. 4, Lemmas 5-6, Thm 9 as printed, in the full algebra\n");
    tk_check w_l5 = tk_begin("Lemma 5: exp(B) = [1 + sinc t_par n/2 ~tau] tau", 16 * EPS);
    tk_check w_l6 = tk_begin("Lemma 6: that rotor translates by -sinc t_par (cos - sin P)", 16 * EPS);
    tk_check w_t9 = tk_begin("Thm 9 (acos form) = ga_rotor_log_literal, * sin|ab|", 64 * EPS);
    tk_check w_tau = tk_begin("ga_rotor_twist = tau(psi, P, a) of Def. 4", 8 * EPS);
    ga_mv nn = ga_mv_n(), e4 = ga_mv_e4();
    for (long i = 0; i < n / 10; i++) {
        ga_vec3 u = tk_unit(&rng), a = rnd_perp(u), b = vcross(u, a); /* P = ab, axis u */
        double psi = 0.5 + (2 * PI - 1) * tk_uni(&rng), h = psi / 2;
        double ka = 10 * tk_range(&rng, -1, 1), kb = 10 * tk_range(&rng, -1, 1),
               ku = 10 * tk_range(&rng, -1, 1);
        ga_vec3 tpar = vadd(vscale(a, ka), vscale(b, kb)), tperp = vscale(u, ku);
        ga_vec3 t = vadd(tpar, tperp);
        ga_generator plane = {a.x * b.y - a.y * b.x, a.x * b.z - a.z * b.x, a.y * b.z - a.z * b.y, 0, 0, 0};
        ga_generator B = {h * plane.e12, h * plane.e13, h * plane.e23, t.x / 2, t.y / 2, t.z / 2};
        ga_mv R = ga_rotor_to_mv(ga_rotor_exp(B));
        ga_mv P = ga_generator_to_mv(plane);
        /* Def. 4: tau = [cos + sin P][1 + n a/2], built here in the full algebra */
        ga_mv rot = ga_mv_add(ga_mv_scalar(cos(h)), ga_mv_scale(P, sin(h)));
        ga_mv tau = ga_mv_gp(rot,
                             ga_mv_add(ga_mv_scalar(1),
                                       ga_mv_scale(ga_mv_gp(nn, ga_vec3_to_mv(vscale(tperp, -1))), 0.5)));
        tk_add(&w_tau,
               tk_mv_maxabs(ga_mv_sub(ga_rotor_to_mv(ga_rotor_twist(psi, plane, vscale(tperp, -1))), tau)) /
                   10);
        /* Lemma 5: exp(B) = [1 + sinc(psi/2) t_par n/2 ~tau] tau */
        double sinc = sin(h) / h;
        ga_mv tpn = ga_mv_gp(ga_vec3_to_mv(tpar), nn);
        ga_mv L = ga_mv_add(ga_mv_scalar(1), ga_mv_scale(ga_mv_gp(tpn, ga_mv_reverse(tau)), sinc / 2));
        tk_add(&w_l5, tk_mv_maxabs(ga_mv_sub(ga_mv_gp(L, tau), R)) / 100);
        /* Lemma 6: L translates by t'_par = -sinc t_par (cos - sin P) */
        ga_mv tp = ga_mv_scale(
            ga_mv_gp(ga_vec3_to_mv(tpar), ga_mv_sub(ga_mv_scalar(cos(h)), ga_mv_scale(P, sin(h)))), -sinc);
        ga_rotor Lr;
        ga_vec3 moved = {NAN, NAN, NAN};
        if (ga_rotor_from_mv(L, 1e-12, &Lr) == GA_OK) /* a rotor, and a pure translation */
            moved = ga_rotor_apply(Lr, v3(0, 0, 0));
        tk_add(&w_l6, tk_max(fabs(Lr.s - 1), tk_max(fabs(Lr.e12), tk_max(fabs(Lr.e13), fabs(Lr.e23)))));
        tk_add(&w_l6, vmaxabs(vsub(moved, v3(tp.c[GA_BLADE_E1], tp.c[GA_BLADE_E2], tp.c[GA_BLADE_E3]))) / 10);
        /* Thm 9 (literal, |ab| = acos <R>_0 in (0, pi)): ab = (<R>_2 n).e / sinc,
           c_perp n = -ab <R>_4 / (|ab|^2 sinc), c_par n = -ab <ab <R>_2>_2 / (|ab|^2 sinc) */
        double nab = acos(R.c[GA_BLADE_SCALAR]), sn = sin(nab) / nab;
        ga_mv R2 = ga_mv_grade(R, 2), R4 = ga_mv_grade(R, 4);
        ga_mv ab = ga_mv_scale(ga_mv_grade(ga_mv_gp(ga_mv_gp(R2, nn), e4), 2), 1 / sn);
        ga_mv cperp = ga_mv_scale(ga_mv_gp(ab, R4), -1 / (nab * nab * sn));
        ga_mv cpar = ga_mv_scale(ga_mv_gp(ab, ga_mv_grade(ga_mv_gp(ab, R2), 2)), -1 / (nab * nab * sn));
        ga_mv ell = ga_mv_add(ab, ga_mv_add(cperp, cpar));
        ga_generator lit;
        TK_OK(ga_rotor_log_literal(ga_rotor_exp(B), &lit));
        /* acos near its ends loses ~EPS/sin: compare relative to 1/sin(nab) */
        tk_add(&w_t9, tk_mv_maxabs(ga_mv_sub(ell, ga_generator_to_mv(lit))) / 10 * sin(nab));
    }
    tk_end(&w_tau);
    tk_end(&w_l5);
    tk_end(&w_l6);
    tk_end(&w_t9);
}

static void check_screws(void)
{
    long n = n_cases;
    tk_note("screws (Chasles): screw -> rotor -> screw, and the screw's own meaning\n");
    tk_check w_rt = tk_begin("screw round trip (angle, axis, point, shift, pitch)", 64 * EPS);
    tk_check w_mean = tk_begin("R moves axis points by shift along the axis", 64 * EPS);
    for (long i = 0; i < n; i++) {
        int kind = i % 4;
        ga_screw s = {0, {0, 0, 1}, {0, 0, 0}, 0, 0}, o;
        s.angle = PI * tk_uni(&rng);
        s.axis = tk_unit(&rng);
        s.shift = 100 * tk_range(&rng, -1, 1);
        if (kind == 0) /* pure translation */
            s.angle = 0, s.shift = tk_loguni(&rng, 1e-6, 1e3), s.pitch = INFINITY;
        else {
            s.point = vscale(rnd_perp(s.axis), tk_loguni(&rng, 1e-6, 1e2));
            if (kind == 1) /* pure rotation */
                s.shift = 0;
            s.pitch = s.shift / s.angle;
        }
        ga_rotor r = ga_rotor_from_screw(s);
        double scale = fmax(1, fmax(vnorm(s.point), fabs(s.shift)));
        if (ga_rotor_to_screw(r, &o) != GA_OK) {
            tk_add(&w_rt, INFINITY);
            continue;
        }
        /* the axis point is (u x v) / angle with v = point x w + shift u: the
           rotor's rounding EPS |v| becomes EPS (|point| + |shift| / angle) there */
        double e = tk_max(fabs(o.angle - s.angle), vmaxabs(vsub(o.axis, s.axis)));
        e = tk_max(e, fabs(o.shift - s.shift) / scale);
        if (kind != 0)
            e = tk_max(e, vmaxabs(vsub(o.point, s.point)) / (1 + vnorm(s.point) + fabs(s.shift) / s.angle));
        if (kind == 0)
            e = tk_max(e, isinf(o.pitch) && o.pitch > 0 ? 0 : 1);
        else
            e = tk_max(e, fabs(o.pitch - s.pitch) / fmax(1, fabs(s.pitch)) * s.angle / scale);
        tk_add(&w_rt, e);
        /* meaning: points on the axis move along it by shift; the angle is the rotation's */
        ga_vec3 p = vadd(o.point, vscale(o.axis, 3 * tk_range(&rng, -1, 1)));
        ga_vec3 m = vsub(ga_rotor_apply(r, p), vadd(p, vscale(o.axis, o.shift)));
        tk_add(&w_mean, vmaxabs(m) / scale);
    }
    tk_end(&w_rt);
    tk_end(&w_mean);
    ga_screw id;
    int st = ga_rotor_to_screw(ga_rotor_identity(), &id);
    tk_add_bool(tk_get("identity screw: all zero, axis (0, 0, 1)"),
                st == GA_OK && id.angle == 0 && id.axis.z == 1 && id.axis.x == 0 && id.shift == 0 &&
                    id.pitch == 0 && id.point.x == 0);
    tk_add_bool(tk_get("identity screw -> identity rotor"),
                rdiff(ga_rotor_from_screw(id), ga_rotor_identity()) == 0);
    tk_end_named();
}

static void check_bad_input(void)
{
    tk_note("bad input gives the right status, outputs untouched\n");
    ga_rotor good = ga_rotor_exp(gen(v3(0.3, -1, 2), v3(5, 6, -7))), out = {9, 9, 9, 9, 9, 9, 9, 9};
    ga_generator g = {9, 9, 9, 9, 9, 9};
    for (int k = 0; k < 8; k++) {
        ga_rotor bad = good;
        (&bad.s)[k] = (k & 1) ? NAN : -INFINITY;
        tk_add_bool(tk_get("log of NaN/Inf: GA_ERR_NOTFINITE"), ga_rotor_log(bad, &g) == GA_ERR_NOTFINITE);
        tk_add_bool(tk_get("literal log of NaN/Inf"), ga_rotor_log_literal(bad, &g) == GA_ERR_NOTFINITE);
        tk_add_bool(tk_get("check of NaN/Inf"), ga_rotor_check(bad, 1) == GA_ERR_NOTFINITE);
        tk_add_bool(tk_get("normalize of NaN/Inf"), ga_rotor_normalize(bad, &out) == GA_ERR_NOTFINITE);
        ga_screw s;
        tk_add_bool(tk_get("screw of NaN/Inf"), ga_rotor_to_screw(bad, &s) == GA_ERR_NOTFINITE);
        bad = good; /* far off: 1e-5 > GA_ROTOR_DRIFT_MAX */
        (&bad.s)[k] += 1e-5 * (k < 4 ? 1 : 12);
        tk_add_bool(tk_get("log of a rotor 1e-5 off: GA_ERR_NOTRIGID"),
                    ga_rotor_log(bad, &g) == GA_ERR_NOTRIGID);
        tk_add_bool(tk_get("check of a far-off rotor"),
                    ga_rotor_check(bad, GA_ROTOR_DRIFT_MAX) == GA_ERR_NOTRIGID);
        bad = good; /* 1e-12 off: accepted */
        (&bad.s)[k] += 1e-12 * (k < 4 ? 1 : 12);
        tk_add_bool(tk_get("log of a rotor 1e-12 off: accepted"), ga_rotor_log(bad, &g) == GA_OK);
    }
    tk_add_bool(tk_get("log wrote its output"), g.e12 != 9);
    ga_generator g2 = {9, 9, 9, 9, 9, 9};
    ga_rotor far = good;
    far.s *= 2;
    tk_add_bool(tk_get("failed log leaves output untouched"),
                ga_rotor_log(far, &g2) == GA_ERR_NOTRIGID && g2.e12 == 9 && g2.e3n == 9);
    ga_rotor zero = {0, 0, 0, 0, 1, 2, 3, 4};
    tk_add_bool(tk_get("normalize of q = 0: GA_ERR_NOTRIGID"),
                ga_rotor_normalize(zero, &out) == GA_ERR_NOTRIGID && out.s == 9);
    ga_rotor scaled = {3 * good.s,   3 * good.e12, 3 * good.e13, 3 * good.e23,
                       3 * good.e1n, 3 * good.e2n, 3 * good.e3n, 3 * good.e123n};
    tk_add_bool(tk_get("normalize(3 R) = R"),
                ga_rotor_normalize(scaled, &out) == GA_OK && rdiff(out, good) < 16 * EPS * 10);
    /* multivectors that are not rotors */
    ga_rotor r;
    ga_mv m = ga_rotor_to_mv(good);
    m.c[GA_BLADE_E1] = 1e-3;
    tk_add_bool(tk_get("from_mv with a vector part"), ga_rotor_from_mv(m, 1e-9, &r) == GA_ERR_NOTRIGID);
    m = ga_rotor_to_mv(good);
    m.c[GA_BLADE_E14] += 1e-3;
    tk_add_bool(tk_get("from_mv with e14 != e15"), ga_rotor_from_mv(m, 1e-9, &r) == GA_ERR_NOTRIGID);
    m = ga_rotor_to_mv(good);
    m.c[GA_BLADE_E45] = 0.5;
    tk_add_bool(tk_get("from_mv of a dilation-like part"), ga_rotor_from_mv(m, 1e-9, &r) == GA_ERR_NOTRIGID);
    m = ga_rotor_to_mv(good);
    m.c[GA_BLADE_E1234] += 1e-3, m.c[GA_BLADE_E1235] += 1e-3;
    tk_add_bool(tk_get("from_mv off the group (<P~q>_3 != 0)"),
                ga_rotor_from_mv(m, 1e-9, &r) == GA_ERR_NOTRIGID);
    m.c[GA_BLADE_E12345] = NAN;
    tk_add_bool(tk_get("from_mv of NaN"), ga_rotor_from_mv(m, 1e-9, &r) == GA_ERR_NOTFINITE);
    /* matrices */
    ga_mat4 M = ga_rotor_to_mat4(good), B;
    tk_add_bool(tk_get("from_mat4 of a rigid motion"),
                ga_rotor_from_mat4(M, &r) == GA_OK && rdiff_pm(r, good) < 64 * EPS);
    B = M, B.m[0] *= 1 + 1e-8;
    tk_add_bool(tk_get("from_mat4: not orthonormal (1e-8)"), ga_rotor_from_mat4(B, &r) == GA_ERR_NOTRIGID);
    B = M, B.m[0] += 1e-11;
    tk_add_bool(tk_get("from_mat4: orthonormal to 1e-11 accepted"), ga_rotor_from_mat4(B, &r) == GA_OK);
    B = M, B.m[1] += 0.1;
    tk_add_bool(tk_get("from_mat4: shear"), ga_rotor_from_mat4(B, &r) == GA_ERR_NOTRIGID);
    B = M;
    for (int j = 0; j < 3; j++) B.m[j] = -B.m[j];
    tk_add_bool(tk_get("from_mat4: a reflection (det -1)"), ga_rotor_from_mat4(B, &r) == GA_ERR_NOTRIGID);
    B = M, B.m[12] = 0.1;
    tk_add_bool(tk_get("from_mat4: last row not 0 0 0 1"), ga_rotor_from_mat4(B, &r) == GA_ERR_NOTRIGID);
    B = M, B.m[15] = 2;
    tk_add_bool(tk_get("from_mat4: last row 0 0 0 2"), ga_rotor_from_mat4(B, &r) == GA_ERR_NOTRIGID);
    B = M, B.m[7] = NAN;
    tk_add_bool(tk_get("from_mat4: NaN"), ga_rotor_from_mat4(B, &r) == GA_ERR_NOTFINITE);
    B = M, B.m[5] = INFINITY;
    tk_add_bool(tk_get("from_mat4: Inf"), ga_rotor_from_mat4(B, &r) == GA_ERR_NOTFINITE);
    ga_screw s;
    ga_rotor nearlyflat = ga_rotor_exp(gen(v3(1e-300, 0, 0), v3(0, 1e10, 0)));
    tk_add_bool(tk_get("screw with its axis beyond DBL_MAX: GA_ERR_DOMAIN"),
                ga_rotor_to_screw(nearlyflat, &s) == GA_ERR_DOMAIN);
    tk_end_named();
}

/* Cross-representation: the SE(3) closed forms of mat4.h (Eberly) agree. */
static void check_se3(void)
{
    long n = n_cases;
    tk_note("cross-check with the matrix group (mat4.h: ga_se3_exp, ga_se3_log)\n");
    tk_check w_exp = tk_begin("mat(exp(B(xi))) = ga_se3_exp(xi)", 32 * EPS);
    tk_check w_log = tk_begin("twist(l(R)) = ga_se3_log(mat(R)), angles < pi", 32 * EPS);
    tk_check w_ref = tk_begin("ga_se3_exp(xi) = long-double expm(xi^)", 16 * EPS);
    for (long i = 0; i < n; i++) {
        int kind = i % 4;
        double th = kind == 0 ? tk_loguni(&rng, 1e-12, 1e-3)
                  : kind == 1 ? PI - tk_loguni(&rng, 1e-9, 1e-3)
                  : kind == 2 ? tk_loguni(&rng, 1e-3, PI - 1e-3)
                              : 0;
        double tl = tk_loguni(&rng, 1e-6, 1e3);
        ga_vec3 xw = rnd_vec(th), xv = rnd_vec(tl);
        ga_twist xi = twist(xw, xv), xl;
        ga_rotor r = ga_rotor_exp(ga_twist_to_generator(xi));
        ga_mat4 M = ga_rotor_to_mat4(r), S = ga_se3_exp(xi);
        double scale = fmax(1, tl);
        tk_add(&w_exp, mdiff(M, S) / scale);
        tk_add(&w_ref, mdiff(S, expm_ref(xi)) / scale);
        ga_generator L;
        int st = ga_rotor_log(r, &L), sm = ga_se3_log(M, &xl);
        ga_twist xr = ga_generator_to_twist(L);
        tk_add(&w_log, st == GA_OK && sm == GA_OK
                           ? tk_max(vmaxabs(vsub(xr.w, xl.w)), vmaxabs(vsub(xr.v, xl.v))) / scale
                           : INFINITY);
    }
    /* each side is a closed form of a few dozen roundings of size max(1, |v|);
       against the long-double series (exact to ~1e-19 here, then rounded to
       double) only one side rounds: half of that */
    tk_end(&w_exp);
    tk_end(&w_ref);
    tk_end(&w_log);
}

static const tk_section sections[] = {
    {"product", check_product, TK_STREAM},
    {"action", check_action, TK_STREAM},
    {"exp_series", check_exp_series, TK_STREAM},
    {"exp_log", check_exp_log, TK_STREAM},
    {"matrix", check_matrix, TK_STREAM},
    {"se3", check_se3, TK_STREAM},
    {"quat", check_quat, TK_STREAM},
    {"slerp", check_slerp, TK_STREAM},
    {"helix", check_helix, TK_STREAM},
    {"paper_forms", check_paper_forms, TK_STREAM},
    {"screws", check_screws, TK_STREAM},
    {"bad_input", check_bad_input, 0},
};

/* the scale argument */
static void setup(const char *arg)
{
    long mult = arg ? atol(arg) : 1;
    n_cases = N_CASES * (mult > 0 ? mult : 1);
    tk_note("test_rotor: %ld cases per family\n", n_cases);
}

int main(int argc, char **argv)
{
    return tk_main_arg(argc, argv, "test_rotor", sections, TK_COUNT(sections), setup);
}
