/* tests/test_rotor.c: the compact rotor, its product, its action on points,
 * exp and l(R), and its 4x4 matrix and the SE(3) closed forms, checked
 * against the full algebra (mv.h, conformal.h) and independent references
 * (rotor_kit.h). Quaternions, slerp and screws: test_rotor_screws.c.
 *
 *   test_rotor [M]   runs M times the default counts (M = 100: 1e6 per family).
 *
 * Exits nonzero on any failure.
 */
#include "rotor_kit.h"

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
    {"product", check_product, TK_STREAM},       {"action", check_action, TK_STREAM},
    {"exp_series", check_exp_series, TK_STREAM}, {"exp_log", check_exp_log, TK_STREAM},
    {"matrix", check_matrix, TK_STREAM},         {"se3", check_se3, 0},
};

/* the scale argument */
static void setup(const char *arg) { rotor_setup("test_rotor", arg); }

int main(int argc, char **argv)
{
    return tk_main_arg(argc, argv, "test_rotor", sections, TK_COUNT(sections), setup);
}
