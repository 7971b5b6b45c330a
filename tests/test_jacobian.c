/* tests/test_jacobian.c: the Lie-group Jacobians of jacobian.h.
 *
 *   exp         J_r and J_l against central differences of exp (seeded twists
 *               from 0 to beyond a half turn), and against their definition
 *               sum_k (-ad xi)^k / (k+1)! summed term by term; the identities
 *               J_l(xi) = J_r(-xi) = Ad(exp xi) J_r(xi), J J^-1 = I; the
 *               switch from series to closed form (th = 2) continuous
 *   group       compose, inverse, between, act, log, right and left, on rotors
 *               and matrices, against central differences on the group;
 *               rotors and matrices agree
 *   statuses    the refusals: angle >= 2 pi, NaN, a side that is neither,
 *               an element off the group
 */
#include "testkit.h"

typedef double m6[36];

static ga_twist tw(const double *x) { return (ga_twist){{x[0], x[1], x[2]}, {x[3], x[4], x[5]}}; }
static void tw_put(ga_twist t, double *x)
{
    x[0] = t.w.x, x[1] = t.w.y, x[2] = t.w.z, x[3] = t.v.x, x[4] = t.v.y, x[5] = t.v.z;
}

static ga_mat6 m6_mul(ga_mat6 a, ga_mat6 b)
{
    ga_mat6 c;
    for (int i = 0; i < 6; i++)
        for (int j = 0; j < 6; j++) {
            double s = 0;
            for (int k = 0; k < 6; k++) s += a.m[6 * i + k] * b.m[6 * k + j];
            c.m[6 * i + j] = s;
        }
    return c;
}

static double m6_maxabs(ga_mat6 a)
{
    double m = 0;
    for (int i = 0; i < 36; i++) m = tk_max(m, fabs(a.m[i]));
    return m;
}

static double m6_diff(ga_mat6 a, ga_mat6 b)
{
    double m = 0;
    for (int i = 0; i < 36; i++) m = tk_max(m, fabs(a.m[i] - b.m[i]));
    return m;
}

static ga_mat6 m6_eye(void)
{
    ga_mat6 e;
    memset(&e, 0, sizeof e);
    for (int i = 0; i < 6; i++) e.m[7 * i] = 1;
    return e;
}

/* log(a^-1 b) (right) or log(b a^-1) (left) as 6 numbers */
static void minus(ga_mat4 a, ga_mat4 b, ga_jac_side side, double *x)
{
    ga_twist t;
    ga_mat4 d = side == GA_JAC_RIGHT ? ga_mat4_mul(ga_se3_inverse(a), b) : ga_mat4_mul(b, ga_se3_inverse(a));
    TK_OK(ga_se3_log(d, &t));
    tw_put(t, x);
}

/* a exp(tau) (right) or exp(tau) a (left) */
static ga_mat4 plus(ga_mat4 a, const double *tau, ga_jac_side side)
{
    ga_mat4 e = ga_se3_exp(tw(tau));
    return side == GA_JAC_RIGHT ? ga_mat4_mul(a, e) : ga_mat4_mul(e, a);
}

static const double H = 1e-5;

/* ---- exp --------------------------------------------------------------------- */

/* the twists the sections draw: angle in [0, amax), |v| up to vmax, the
 * families near 0 and near pi among them */
static ga_twist draw(tk_rng *r, int i, double amax, double vmax)
{
    ga_vec3 u = tk_unit(r), d = tk_unit(r);
    double a;
    switch (i % 6) {
    case 0: a = 0; break;
    case 1: a = tk_loguni(r, 1e-12, 1e-3); break;
    case 2: a = TK_PI - tk_loguni(r, 1e-3, 1e-1); break;
    case 3: a = tk_range(r, 1.9, 2.1); break; /* about the series' switch */
    default: a = tk_range(r, 0, amax); break;
    }
    if (a >= amax)
        a = tk_range(r, 0, amax);
    double v = tk_uni(r) < 0.2 ? 0 : tk_range(r, 0, vmax);
    return (ga_twist){tk_scale(u, a), tk_scale(d, v)};
}

static void section_exp(void)
{
    tk_rng r = {20261202};
    tk_check fr = tk_begin("J_r: central differences of exp(xi + d) = exp(xi) exp(J_r d)", 1e-9);
    tk_check fl = tk_begin("J_l: central differences of exp(xi + d) = exp(J_l d) exp(xi)", 1e-9);
    tk_check ser = tk_begin("J_r = sum (-ad xi)^k/(k+1)!, 80 terms (|xi| <= 5)", 4e-15);
    tk_check sym = tk_begin("J_l(xi) = J_r(-xi), bit for bit", 0);
    tk_check ad = tk_begin("J_l(xi) = Ad(exp xi) J_r(xi)", 4e-15);
    tk_check inv = tk_begin("J_r J_r^-1 = J_l J_l^-1 = I (angle < 2 pi - 0.1)", 1e-14);
    tk_check sta = tk_begin("J^-1: GA_OK below 2 pi", 0);
    int n = 3000;
    for (int i = 0; i < n; i++) {
        ga_twist xi = draw(&r, i, 2 * TK_PI - 0.1, 3.0);
        double x[6], th = tk_norm(xi.w);
        tw_put(xi, x);
        ga_mat6 jr = ga_twist_jr(xi), jl = ga_twist_jl(xi);
        double scale = tk_max(1.0, m6_maxabs(jr));
        ga_mat4 e0 = ga_se3_exp(xi);
        for (int k = 0; k < 6; k++) {
            double xp[6], xm[6], dp[6], dm[6], gp[6], gm[6];
            memcpy(xp, x, sizeof x), memcpy(xm, x, sizeof x);
            xp[k] += H, xm[k] -= H;
            ga_mat4 ep = ga_se3_exp(tw(xp)), em = ga_se3_exp(tw(xm));
            minus(e0, ep, GA_JAC_RIGHT, dp), minus(e0, em, GA_JAC_RIGHT, dm);
            minus(e0, ep, GA_JAC_LEFT, gp), minus(e0, em, GA_JAC_LEFT, gm);
            for (int i2 = 0; i2 < 6; i2++) {
                tk_add(&fr, fabs((dp[i2] - dm[i2]) / (2 * H) - jr.m[6 * i2 + k]) / scale);
                tk_add(&fl, fabs((gp[i2] - gm[i2]) / (2 * H) - jl.m[6 * i2 + k]) / scale);
            }
        }
        if (tk_norm(xi.w) + tk_norm(xi.v) <= 5.0) {
            /* the definition, summed: term_k = (-ad)^k / (k+1)! */
            ga_mat6 a = ga_twist_ad(xi), term = m6_eye(), sum = m6_eye();
            for (int i2 = 0; i2 < 36; i2++) a.m[i2] = -a.m[i2];
            for (int k = 1; k < 80; k++) {
                term = m6_mul(term, a);
                for (int i2 = 0; i2 < 36; i2++) term.m[i2] /= (double)(k + 1);
                for (int i2 = 0; i2 < 36; i2++) sum.m[i2] += term.m[i2];
            }
            tk_add(&ser, m6_diff(sum, jr) / scale);
        }
        ga_twist mx = {{-xi.w.x, -xi.w.y, -xi.w.z}, {-xi.v.x, -xi.v.y, -xi.v.z}};
        tk_add(&sym, m6_diff(ga_twist_jr(mx), jl));
        tk_add(&ad,
               m6_diff(m6_mul(ga_se3_adjoint_matrix(e0), jr), jl) / (scale * tk_max(1.0, tk_norm(xi.v))));
        ga_mat6 jri, jli;
        int s1 = ga_twist_jr_inverse(xi, &jri), s2 = ga_twist_jl_inverse(xi, &jli);
        tk_add_status(&sta, s1, GA_OK);
        tk_add_status(&sta, s2, GA_OK);
        if (s1 == GA_OK && s2 == GA_OK) {
            double c = scale * m6_maxabs(jri) * (th > 6 ? 100 : 1);
            tk_add(&inv, m6_diff(m6_mul(jr, jri), m6_eye()) / c);
            tk_add(&inv, m6_diff(m6_mul(jl, jli), m6_eye()) / c);
        }
    }
    tk_end(&fr);
    tk_end(&fl);
    tk_end(&ser);
    tk_end(&sym);
    tk_end(&ad);
    tk_end(&inv);
    tk_end(&sta);

    /* continuity where the series give way to the closed forms (th = 2) */
    tk_check sw = tk_begin("J_r, J_r^-1 across th = 2 (series | closed form): jump / step <= 10", 10);
    for (int i = 0; i < 200; i++) {
        ga_vec3 u = tk_unit(&r), d = tk_scale(tk_unit(&r), tk_range(&r, 0, 3));
        double below = nextafter(2.0, 0), above = 2.0;
        ga_twist a = {tk_scale(u, below), d}, b = {tk_scale(u, above), d};
        ga_mat6 ia, ib;
        TK_OK(ga_twist_jr_inverse(a, &ia));
        TK_OK(ga_twist_jr_inverse(b, &ib));
        double ulp = 2.0 * DBL_EPSILON * tk_max(1.0, m6_maxabs(ga_twist_jr(b)));
        /* the true change over one step of th is about one ulp of 2 */
        tk_add(&sw, m6_diff(ga_twist_jr(a), ga_twist_jr(b)) / ulp);
        tk_add(&sw, m6_diff(ia, ib) / (2.0 * DBL_EPSILON * tk_max(1.0, m6_maxabs(ib))));
    }
    tk_end(&sw);
}

/* ---- group ------------------------------------------------------------------- */

enum { OP_COMPOSE, OP_INVERSE, OP_BETWEEN, OP_ACT, OP_LOG, OPS };
static const char *const op_name[OPS] = {"compose", "inverse", "between", "act", "log"};

/* the value of op at (a, b, p): a group element (into *m) or a vector of n
 * numbers (into v) */
static int value(int op, ga_mat4 a, ga_mat4 b, ga_vec3 p, ga_mat4 *m, double *v)
{
    switch (op) {
    case OP_COMPOSE: *m = ga_mat4_mul(a, b); return 0;
    case OP_INVERSE: *m = ga_se3_inverse(a); return 0;
    case OP_BETWEEN: *m = ga_mat4_mul(ga_se3_inverse(a), b); return 0;
    case OP_ACT:
        for (int i = 0; i < 3; i++)
            v[i] = a.m[4 * i] * p.x + a.m[4 * i + 1] * p.y + a.m[4 * i + 2] * p.z + a.m[4 * i + 3];
        return 3;
    default: {
        ga_twist t;
        TK_OK(ga_se3_log(a, &t));
        tw_put(t, v);
        return 6;
    }
    }
}

/* the Jacobian of op w.r.t. argument arg (0: a, 1: b or the point) as rows x
 * cols into J, through the rotor (rot) or the matrix functions */
static int jacobian(int op, int arg, int rot, ga_mat4 a, ga_mat4 b, ga_vec3 p, ga_jac_side side, double *J)
{
    ga_rotor ra, rb;
    TK_OK(ga_rotor_from_mat4(a, &ra));
    TK_OK(ga_rotor_from_mat4(b, &rb));
    ga_mat6 j1, j2;
    ga_mat36 ja;
    ga_mat3 jp;
    int st;
    switch (op) {
    case OP_COMPOSE:
        st = rot ? ga_rotor_jac_compose(ra, rb, side, &j1, &j2) : ga_se3_jac_compose(a, b, side, &j1, &j2);
        memcpy(J, arg ? j2.m : j1.m, sizeof j1.m);
        break;
    case OP_INVERSE:
        st = rot ? ga_rotor_jac_inverse(ra, side, &j1) : ga_se3_jac_inverse(a, side, &j1);
        memcpy(J, j1.m, sizeof j1.m);
        break;
    case OP_BETWEEN:
        st = rot ? ga_rotor_jac_between(ra, rb, side, &j1, &j2) : ga_se3_jac_between(a, b, side, &j1, &j2);
        memcpy(J, arg ? j2.m : j1.m, sizeof j1.m);
        break;
    case OP_ACT:
        st = rot ? ga_rotor_jac_act(ra, p, side, &ja, &jp) : ga_se3_jac_act(a, p, side, &ja, &jp);
        if (arg)
            memcpy(J, jp.m, sizeof jp.m);
        else
            memcpy(J, ja.m, sizeof ja.m);
        break;
    default:
        st = rot ? ga_rotor_jac_log(ra, side, &j1) : ga_se3_jac_log(a, side, &j1);
        memcpy(J, j1.m, sizeof j1.m);
        break;
    }
    TK_OK(st);
    return st;
}

static void section_group(void)
{
    tk_rng r = {8172026};
    for (int op = 0; op < OPS; op++)
        for (int sd = 0; sd < 2; sd++) {
            ga_jac_side side = sd ? GA_JAC_LEFT : GA_JAC_RIGHT;
            int nargs = op == OP_INVERSE || op == OP_LOG ? 1 : 2;
            tk_check fd = tk_beginf(1e-9, "%s, %s: central differences (rotor and matrix)", op_name[op],
                                    sd ? "left" : "right");
            tk_check agree = tk_beginf(1e-14, "%s, %s: rotor = matrix", op_name[op], sd ? "left" : "right");
            for (int i = 0; i < 400; i++) {
                /* log: keep clear of the half turn, where the principal log jumps */
                double amax = op == OP_LOG ? TK_PI - 1e-3 : TK_PI;
                ga_mat4 a = ga_se3_exp(draw(&r, i, amax, 3.0)), b = ga_se3_exp(draw(&r, i + 3, TK_PI, 3.0));
                ga_vec3 p = tk_scale(tk_unit(&r), tk_range(&r, 0, 3));
                ga_mat4 f0;
                double v0[6];
                int nv = value(op, a, b, p, &f0, v0);
                int rows = nv ? nv : 6;
                for (int arg = 0; arg < nargs; arg++) {
                    double Jm[36], Jr[36];
                    jacobian(op, arg, 0, a, b, p, side, Jm);
                    jacobian(op, arg, 1, a, b, p, side, Jr);
                    int cols = op == OP_ACT && arg == 1 ? 3 : 6;
                    double scale = 1.0;
                    for (int i2 = 0; i2 < rows * cols; i2++) scale = tk_max(scale, fabs(Jm[i2]));
                    for (int i2 = 0; i2 < rows * cols; i2++) tk_add(&agree, fabs(Jm[i2] - Jr[i2]) / scale);
                    for (int k = 0; k < cols; k++) {
                        double dp[6], dm[6];
                        for (int sg = 0; sg < 2; sg++) {
                            double *out = sg ? dm : dp, tau[6] = {0};
                            ga_mat4 a2 = a, b2 = b, f;
                            ga_vec3 p2 = p;
                            double h = sg ? -H : H;
                            if (op == OP_ACT && arg == 1)
                                (&p2.x)[k] += h;
                            else {
                                tau[k] = h;
                                if (arg)
                                    b2 = plus(b, tau, side);
                                else
                                    a2 = plus(a, tau, side);
                            }
                            double v[6];
                            if (value(op, a2, b2, p2, &f, v))
                                for (int i2 = 0; i2 < rows; i2++) out[i2] = v[i2] - v0[i2];
                            else
                                minus(f0, f, side, out);
                        }
                        for (int i2 = 0; i2 < rows; i2++)
                            tk_add(&fd, fabs((dp[i2] - dm[i2]) / (2 * H) - Jm[cols * i2 + k]) / scale);
                    }
                }
            }
            tk_end(&fd);
            tk_end(&agree);
        }
}

/* ---- statuses ------------------------------------------------------------------ */

static void section_statuses(void)
{
    ga_mat6 j, j2;
    ga_mat36 ja;
    ga_mat3 jp;
    ga_twist at2pi = {{2 * TK_PI, 0, 0}, {1, 0, 0}}, below = {{0, 6.2, 0}, {0, 0, 1}};
    tk_expect_status("J_r^-1 at |w| = 2 pi: GA_ERR_DOMAIN", ga_twist_jr_inverse(at2pi, &j), GA_ERR_DOMAIN);
    tk_expect_status("J_l^-1 at |w| = 7: GA_ERR_DOMAIN",
                     ga_twist_jl_inverse((ga_twist){{7, 0, 0}, {0, 0, 0}}, &j), GA_ERR_DOMAIN);
    tk_expect_status("J_r^-1 at |w| = 6.2: GA_OK", ga_twist_jr_inverse(below, &j), GA_OK);
    tk_expect_status("J_r^-1 of NaN: GA_ERR_NOTFINITE",
                     ga_twist_jr_inverse((ga_twist){{NAN, 0, 0}, {0, 0, 0}}, &j), GA_ERR_NOTFINITE);
    ga_mat4 m = ga_se3_exp(below), bad = m;
    ga_rotor rr = ga_rotor_exp(ga_twist_to_generator(below)), rbad = rr;
    bad.m[0] += 1e-6;
    rbad.s += 1e-5;
    tk_expect_status("a side that is neither: GA_ERR_ARG", ga_se3_jac_inverse(m, (ga_jac_side)7, &j),
                     GA_ERR_ARG);
    tk_expect_status("rotor side 2: GA_ERR_ARG", ga_rotor_jac_log(rr, (ga_jac_side)2, &j), GA_ERR_ARG);
    tk_expect_status("matrix off SE(3) by 1e-6: GA_ERR_NOTRIGID",
                     ga_se3_jac_compose(m, bad, GA_JAC_RIGHT, &j, &j2), GA_ERR_NOTRIGID);
    tk_expect_status("rotor off the group by 1e-5: GA_ERR_NOTRIGID",
                     ga_rotor_jac_between(rr, rbad, GA_JAC_LEFT, &j, &j2), GA_ERR_NOTRIGID);
    tk_expect_status("act on a NaN point: GA_ERR_NOTFINITE",
                     ga_se3_jac_act(m, (ga_vec3){NAN, 0, 0}, GA_JAC_RIGHT, &ja, &jp), GA_ERR_NOTFINITE);
    tk_expect_status("rotor act on an infinite point: GA_ERR_NOTFINITE",
                     ga_rotor_jac_act(rr, (ga_vec3){0, INFINITY, 0}, GA_JAC_LEFT, &ja, &jp),
                     GA_ERR_NOTFINITE);
    bad = m;
    bad.m[5] = NAN;
    tk_expect_status("log of a NaN matrix: GA_ERR_NOTFINITE", ga_se3_jac_log(bad, GA_JAC_RIGHT, &j),
                     GA_ERR_NOTFINITE);
}

static const tk_section sections[] = {
    {"exp", section_exp, 0},
    {"group", section_group, 0},
    {"statuses", section_statuses, 0},
};

int main(int argc, char **argv) { return tk_main(argc, argv, "test_jacobian", sections, TK_COUNT(sections)); }
