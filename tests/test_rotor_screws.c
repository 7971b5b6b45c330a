/* tests/test_rotor_screws.c: the compact rotor against quaternions and
 * dual quaternions, slerp, screw motions (the helix of Wareham-Lasenby §4.1,
 * the paper's forms, ga_rotor_to_screw and back), and bad input, checked
 * against independent references (rotor_kit.h).
 *
 *   test_rotor_screws [M]   runs M times the default counts, as test_rotor.
 *
 * Its stream starts where test_rotor's sections leave it at the default
 * scale (tk_rng_after: their draws), so that at M = 1 its inputs are those
 * they have always been; at another scale they are other draws of the same
 * stream. Exits nonzero on any failure.
 */
#include "rotor_kit.h"

/* the draws of test_rotor's sections at the default scale */
#define TEST_ROTOR_DRAWS 3259700u

/* ---- the checks ------------------------------------------------------------ */

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

static const tk_section sections[] = {
    {"quat", check_quat, TK_STREAM},     {"slerp", check_slerp, TK_STREAM},
    {"helix", check_helix, TK_STREAM},   {"paper_forms", check_paper_forms, TK_STREAM},
    {"screws", check_screws, TK_STREAM}, {"bad_input", check_bad_input, 0},
};

/* the scale argument; the stream */
static void setup(const char *arg)
{
    rng = tk_rng_after(ROTOR_SEED, TEST_ROTOR_DRAWS);
    rotor_setup("test_rotor_screws", arg);
}

int main(int argc, char **argv)
{
    return tk_main_arg(argc, argv, "test_rotor_screws", sections, TK_COUNT(sections), setup);
}
