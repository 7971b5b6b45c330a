/* tests/test_jacobian_affine.c: the Jacobians of the affine group
 * (jacobian.h, "the affine group").
 *
 *   exp         J_r and J_l against central differences of expm with one
 *               Richardson step, on seeded algebra elements: scalings, shears,
 *               general [A, b], the same scaled up to norm 20, and twists;
 *               J_l(X) = J_r(-X) bit for bit, J_l = Ad(expm X) J_r,
 *               J J^-1 = I; on se(3) the rigid J_r, J_r^-1 (embedded)
 *   group       compose, inverse, between, act, log, right and left, against
 *               central differences on the group (expm/logm), on general
 *               elements and near-singular ones (det down to 1e-3)
 *   statuses    the refusals: NaN, det < 0, det = 0, a last row off,
 *               J singular (eigenvalues 2 pi i apart), a side that is neither
 */
#include "testkit.h"

#define N 12

static ga_mat4 hat12(const double *x)
{
    ga_mat4 a;
    memcpy(a.m, x, 12 * sizeof(double));
    a.m[12] = a.m[13] = a.m[14] = a.m[15] = 0.0;
    return a;
}

static ga_mat4 expm(ga_mat4 x)
{
    ga_mat4 e;
    TK_OK(ga_mat4_expm(x, &e));
    e.m[12] = e.m[13] = e.m[14] = 0.0;
    e.m[15] = 1.0;
    return e;
}

static ga_mat4 inv4(ga_mat4 a)
{
    ga_mat4 r;
    TK_OK(ga_mat4_inverse(a, &r));
    r.m[12] = r.m[13] = r.m[14] = 0.0;
    r.m[15] = 1.0;
    return r;
}

static void mul12(const ga_mat12 *a, const ga_mat12 *b, ga_mat12 *o)
{
    for (int i = 0; i < N; i++)
        for (int j = 0; j < N; j++) {
            double s = 0;
            for (int k = 0; k < N; k++) s += a->m[N * i + k] * b->m[N * k + j];
            o->m[N * i + j] = s;
        }
}

static double maxabs(const double *a, int n)
{
    double m = 0;
    for (int i = 0; i < n; i++) m = tk_max(m, fabs(a[i]));
    return m;
}

static double diff(const double *a, const double *b, int n)
{
    double m = 0;
    for (int i = 0; i < n; i++) m = tk_max(m, fabs(a[i] - b[i]));
    return m;
}

/* the elements the exp section draws: scalings, shears, general [A, b] (the
 * testkit's families), the same scaled to norms up to 20, and twists */
static ga_mat4 draw(tk_rng *r, int i)
{
    int fam[3] = {TK_SCALING, TK_SHEAR, TK_AFFINE};
    if (i % 5 == 4) { /* a twist, its translation cut to |v| <= 20 */
        ga_twist t = tk_twist(r, (i / 5) % TK_TWIST_FAMILIES);
        double v = tk_norm(t.v);
        if (v > 20)
            t.v = tk_scale(t.v, 20 / v);
        return ga_twist_hat(t);
    }
    ga_mat4 x = tk_algebra(r, fam[i % 3]);
    for (int k = 12; k < 16; k++) x.m[k] = 0.0;
    double n = ga_mat4_norm1(x);
    if (i % 5 == 3 && n > 0) { /* large: 1-norm 5..20 */
        double s = tk_range(r, 5, 20) / n;
        for (int k = 0; k < 12; k++) x.m[k] *= s;
    } else if (n > 4) { /* the testkit's translations reach 1e3: norm <= 4 */
        for (int k = 0; k < 12; k++) x.m[k] *= 4 / n;
    }
    return x;
}

/* D(h) = vee(pre (expm(X + h E) - expm(X - h E)) post)/(2h) */
static void cdiff(ga_mat4 x, int k, double h, ga_mat4 pre, ga_mat4 post, double *d)
{
    ga_mat4 xp = x, xm = x;
    xp.m[k] += h;
    xm.m[k] -= h;
    ga_mat4 ep = expm(xp), em = expm(xm), g;
    for (int i = 0; i < 16; i++) g.m[i] = (ep.m[i] - em.m[i]) / (2 * h);
    g = ga_mat4_mul(ga_mat4_mul(pre, g), post);
    memcpy(d, g.m, 12 * sizeof(double));
}

static void section_exp(void)
{
    tk_rng r = {20261203};
    tk_check fr = tk_begin("J_r: central differences of expm (Richardson), / max(1, |J_r|)", 1e-8);
    tk_check fl = tk_begin("J_l: central differences of expm (Richardson), / max(1, |J_l|)", 1e-8);
    tk_check sym = tk_begin("J_l(X) = J_r(-X), bit for bit", 0);
    tk_check ad = tk_begin("J_l(X) = Ad(expm X) J_r(X), / max(1, |J|) |Ad|", 1e-13);
    tk_check inv = tk_begin("J_r J_r^-1 = J_l J_l^-1 = I, / max(1, |J|) |J^-1|", 1e-13);
    tk_check se3 = tk_begin("on se(3): J_r = the rigid one (embedded), / max(1, |J_r|)", 1e-13);
    tk_check se3i = tk_begin("on se(3), |w| < pi - 0.1: J_r^-1 = the rigid one, / max(1, |J_r^-1|)", 1e-13);
    int n = 400, nsing = 0;
    for (int i = 0; i < n; i++) {
        ga_mat4 x = draw(&r, i), mx = x;
        for (int k = 0; k < 12; k++) mx.m[k] = -x.m[k];
        ga_mat12 jr, jl, jrm, jri, jli, p;
        TK_OK(ga_affine_jr(x, &jr));
        TK_OK(ga_affine_jl(x, &jl));
        TK_OK(ga_affine_jr(mx, &jrm));
        tk_add(&sym, memcmp(jl.m, jrm.m, sizeof jl.m) != 0);
        ga_mat4 e = expm(x), ei = inv4(e), id = ga_mat4_identity();
        double sr = tk_max(1.0, maxabs(jr.m, N * N)), sl = tk_max(1.0, maxabs(jl.m, N * N));
        double h = 1e-3 / tk_max(1.0, ga_mat4_norm1(x));
        for (int k = 0; k < 12; k++) {
            double d1[12], d2[12], g1[12], g2[12];
            cdiff(x, k, h, ei, id, d1);
            cdiff(x, k, h / 2, ei, id, d2);
            cdiff(x, k, h, id, ei, g1);
            cdiff(x, k, h / 2, id, ei, g2);
            for (int q = 0; q < 12; q++) {
                tk_add(&fr, fabs((4 * d2[q] - d1[q]) / 3 - jr.m[N * q + k]) / sr);
                tk_add(&fl, fabs((4 * g2[q] - g1[q]) / 3 - jl.m[N * q + k]) / sl);
            }
        }
        ga_mat12 A;
        TK_OK(ga_affine_adjoint_matrix(e, &A));
        mul12(&A, &jr, &p);
        tk_add(&ad, diff(p.m, jl.m, N * N) / (sl * maxabs(A.m, N * N)));
        /* a twist's ad has the eigenvalues +-2i|w| on the linear part (gl(3)
           holds more than so(3)): J is singular at |w| = pi; those are left out */
        int twist = i % 5 == 4, far = !twist || tk_norm(ga_twist_vee(x).w) < TK_PI - 0.1;
        int s1 = ga_affine_jr_inverse(x, &jri), s2 = ga_affine_jl_inverse(x, &jli);
        if (!far) {
            s1 = s2 = -100;
        } else if (s1 == GA_OK && s2 == GA_OK) {
            ga_mat12 eye;
            memset(&eye, 0, sizeof eye);
            for (int k = 0; k < N; k++) eye.m[(N + 1) * k] = 1.0;
            mul12(&jr, &jri, &p);
            tk_add(&inv, diff(p.m, eye.m, N * N) / (sr * maxabs(jri.m, N * N)));
            mul12(&jl, &jli, &p);
            tk_add(&inv, diff(p.m, eye.m, N * N) / (sl * maxabs(jli.m, N * N)));
        } else {
            /* the large ones (norm 5..20) may have eigenvalues 2 pi i k apart
               to within the pivot's threshold: GA_ERR_SINGULAR is right there;
               elsewhere a refusal is a failure */
            tk_add(&inv, i % 5 == 3 && s1 == GA_ERR_SINGULAR && s2 == GA_ERR_SINGULAR ? 0.0 : 1.0);
            nsing += i % 5 == 3;
        }
        if (twist) { /* the rigid J_r and J_r^-1 on hat(e_k) */
            ga_twist xi = ga_twist_vee(x);
            ga_mat6 j6 = ga_twist_jr(xi), j6i;
            int has_inv = far && ga_twist_jr_inverse(xi, &j6i) == GA_OK;
            for (int k = 0; k < 6; k++) {
                double ek[6] = {0};
                ek[k] = 1.0;
                ga_mat4 hk = ga_twist_hat((ga_twist){{ek[0], ek[1], ek[2]}, {ek[3], ek[4], ek[5]}});
                double a[12] = {0}, b[12] = {0};
                for (int q = 0; q < 12; q++)
                    for (int c = 0; c < 12; c++) {
                        a[q] += jr.m[N * q + c] * hk.m[c];
                        b[q] += jri.m[N * q + c] * hk.m[c];
                    }
                double c6[6], ci6[6];
                for (int q = 0; q < 6; q++) c6[q] = j6.m[6 * q + k], ci6[q] = j6i.m[6 * q + k];
                ga_mat4 want = ga_twist_hat((ga_twist){{c6[0], c6[1], c6[2]}, {c6[3], c6[4], c6[5]}}),
                        wanti = ga_twist_hat((ga_twist){{ci6[0], ci6[1], ci6[2]}, {ci6[3], ci6[4], ci6[5]}});
                tk_add(&se3, diff(a, want.m, 12) / sr);
                if (has_inv)
                    tk_add(&se3i, diff(b, wanti.m, 12) / tk_max(1.0, maxabs(jri.m, N * N)));
            }
        }
    }
    tk_end(&fr);
    tk_end(&fl);
    tk_end(&sym);
    tk_end(&ad);
    tk_note("J^-1: %d of the %d large draws refused as singular\n", nsing, n / 5);
    tk_end(&inv);
    tk_end(&se3);
    tk_end(&se3i);
}

/* ---- the group ---------------------------------------------------------------- */

enum { OP_COMPOSE, OP_INVERSE, OP_BETWEEN, OP_ACT, OP_LOG, OPS };
static const char *const op_name[OPS] = {"compose", "inverse", "between", "act", "log"};

/* log(a^-1 b) (right) or log(b a^-1) (left) as 12 numbers */
static void minus(ga_mat4 a, ga_mat4 b, ga_jac_side side, double *x)
{
    ga_mat4 d = side == GA_JAC_RIGHT ? ga_mat4_mul(inv4(a), b) : ga_mat4_mul(b, inv4(a)), l;
    TK_OK(ga_mat4_logm(d, &l));
    memcpy(x, l.m, 12 * sizeof(double));
}

static ga_mat4 plus(ga_mat4 a, const double *tau, ga_jac_side side)
{
    ga_mat4 e = expm(hat12(tau));
    return side == GA_JAC_RIGHT ? ga_mat4_mul(a, e) : ga_mat4_mul(e, a);
}

/* the value of op: an element (into *m, returns 0) or n numbers (into v) */
static int value(int op, ga_mat4 a, ga_mat4 b, ga_vec3 p, ga_mat4 *m, double *v)
{
    switch (op) {
    case OP_COMPOSE: *m = ga_mat4_mul(a, b); return 0;
    case OP_INVERSE: *m = inv4(a); return 0;
    case OP_BETWEEN: *m = ga_mat4_mul(inv4(a), b); return 0;
    case OP_ACT:
        for (int i = 0; i < 3; i++)
            v[i] = a.m[4 * i] * p.x + a.m[4 * i + 1] * p.y + a.m[4 * i + 2] * p.z + a.m[4 * i + 3];
        return 3;
    default: {
        ga_mat4 l;
        TK_OK(ga_mat4_logm(a, &l));
        memcpy(v, l.m, 12 * sizeof(double));
        return 12;
    }
    }
}

/* the Jacobian of op w.r.t. argument arg into J (rows x cols, cols 12 or 3) */
static void jacobian(int op, int arg, ga_mat4 a, ga_mat4 b, ga_vec3 p, ga_jac_side side, double *J)
{
    ga_mat12 j1, j2;
    ga_mat3x12 ja;
    ga_mat3 jp;
    switch (op) {
    case OP_COMPOSE:
        TK_OK(ga_affine_jac_compose(a, b, side, &j1, &j2));
        memcpy(J, arg ? j2.m : j1.m, sizeof j1.m);
        break;
    case OP_INVERSE:
        TK_OK(ga_affine_jac_inverse(a, side, &j1));
        memcpy(J, j1.m, sizeof j1.m);
        break;
    case OP_BETWEEN:
        TK_OK(ga_affine_jac_between(a, b, side, &j1, &j2));
        memcpy(J, arg ? j2.m : j1.m, sizeof j1.m);
        break;
    case OP_ACT:
        TK_OK(ga_affine_jac_act(a, p, side, &ja, &jp));
        if (arg)
            memcpy(J, jp.m, sizeof jp.m);
        else
            memcpy(J, ja.m, sizeof ja.m);
        break;
    default:
        TK_OK(ga_affine_jac_log(a, side, &j1));
        memcpy(J, j1.m, sizeof j1.m);
        break;
    }
}

/* an element: expm of a drawn algebra element of norm <= 2; near-singular
 * (every third): its linear part times diag(1, 1, d), d down to 1e-3 */
static ga_mat4 element(tk_rng *r, int i)
{
    int fam[3] = {TK_SCALING, TK_SHEAR, TK_AFFINE};
    ga_mat4 x = tk_algebra(r, fam[i % 3]);
    for (int k = 12; k < 16; k++) x.m[k] = 0.0;
    double n = ga_mat4_norm1(x);
    if (n > 2)
        for (int k = 0; k < 12; k++) x.m[k] *= 2 / n;
    ga_mat4 e = expm(x);
    if (i % 3 == 2) {
        double d = tk_loguni(r, 1e-3, 1e-1);
        for (int k = 0; k < 3; k++) e.m[4 * k + 2] *= d;
    }
    return e;
}

static void section_group(void)
{
    tk_rng r = {20261204};
    tk_check c[OPS][2];
    for (int op = 0; op < OPS; op++)
        for (int s = 0; s < 2; s++)
            c[op][s] = tk_beginf(1e-6, "%s, %s: central differences on the group, / max(1, |J|)", op_name[op],
                                 s ? "left" : "right");
    const double H = 1e-6;
    for (int i = 0; i < 60; i++) {
        ga_mat4 a = element(&r, i), b = element(&r, i + 1);
        ga_vec3 p = tk_scale(tk_unit(&r), tk_range(&r, 0, 3));
        for (int op = 0; op < OPS; op++)
            for (int s = 0; s < 2; s++) {
                ga_jac_side side = s ? GA_JAC_LEFT : GA_JAC_RIGHT;
                if (op == OP_LOG && i % 3 == 2)
                    continue; /* logm of the near-singular: eigenvalues near 0 */
                int nargs = op == OP_INVERSE || op == OP_LOG ? 1 : 2;
                for (int arg = 0; arg < nargs; arg++) {
                    double J[N * N], v0[12], vp[12], vm[12];
                    ga_mat4 m0, mp, mm;
                    jacobian(op, arg, a, b, p, side, J);
                    int rows = value(op, a, b, p, &m0, v0);
                    int cols = op == OP_ACT && arg ? 3 : 12, nr = rows ? rows : 12;
                    double scale = tk_max(1.0, maxabs(J, nr * cols));
                    for (int k = 0; k < cols; k++) {
                        double tp[12] = {0}, tm[12] = {0}, d[12];
                        tp[k] = H;
                        tm[k] = -H;
                        ga_mat4 ap = a, am = a, bp = b, bm = b;
                        ga_vec3 pp = p, pm = p;
                        if (op == OP_ACT && arg) {
                            double *q = k == 0 ? &pp.x : k == 1 ? &pp.y : &pp.z;
                            double *qm = k == 0 ? &pm.x : k == 1 ? &pm.y : &pm.z;
                            *q += H;
                            *qm -= H;
                        } else if (arg) {
                            bp = plus(b, tp, side);
                            bm = plus(b, tm, side);
                        } else {
                            ap = plus(a, tp, side);
                            am = plus(a, tm, side);
                        }
                        value(op, ap, bp, pp, &mp, vp);
                        value(op, am, bm, pm, &mm, vm);
                        if (rows == 0) { /* (f(+) (-) f(-)) on the output's side */
                            double dp[12], dm[12];
                            minus(m0, mp, side, dp);
                            minus(m0, mm, side, dm);
                            for (int q = 0; q < 12; q++) d[q] = (dp[q] - dm[q]) / (2 * H);
                        } else {
                            for (int q = 0; q < rows; q++) d[q] = (vp[q] - vm[q]) / (2 * H);
                        }
                        for (int q = 0; q < nr; q++) tk_add(&c[op][s], fabs(d[q] - J[cols * q + k]) / scale);
                    }
                }
            }
    }
    for (int op = 0; op < OPS; op++)
        for (int s = 0; s < 2; s++) tk_end(&c[op][s]);
}

/* ---- statuses ------------------------------------------------------------------ */

static void section_statuses(void)
{
    ga_mat12 j, j2;
    ga_mat3x12 ja;
    ga_mat3 jp;
    ga_mat4 id = ga_mat4_identity(), bad = id, x = ga_twist_hat((ga_twist){{0, 0, 2 * TK_PI}, {1, 0, 0}});
    tk_expect_status("J_r^-1 with eigenvalues 2 pi i apart: GA_ERR_SINGULAR", ga_affine_jr_inverse(x, &j),
                     GA_ERR_SINGULAR);
    tk_expect_status("J_l^-1 the same: GA_ERR_SINGULAR", ga_affine_jl_inverse(x, &j), GA_ERR_SINGULAR);
    x.m[0] = NAN;
    tk_expect_status("J_r of NaN: GA_ERR_NOTFINITE", ga_affine_jr(x, &j), GA_ERR_NOTFINITE);
    memset(&x, 0, sizeof x);
    x.m[0] = 400.0;
    x.m[5] = -400.0; /* ad has the eigenvalue 800: phi(800) overflows */
    tk_expect_status("J_r overflowing (eigenvalues +-400): GA_ERR_DOMAIN", ga_affine_jr(x, &j),
                     GA_ERR_DOMAIN);
    tk_expect_status("a side that is neither: GA_ERR_ARG", ga_affine_jac_inverse(id, (ga_jac_side)7, &j),
                     GA_ERR_ARG);
    bad.m[0] = -1.0;
    tk_expect_status("det < 0: GA_ERR_DOMAIN", ga_affine_jac_compose(id, bad, GA_JAC_RIGHT, &j, &j2),
                     GA_ERR_DOMAIN);
    bad.m[0] = 0.0;
    tk_expect_status("det = 0: GA_ERR_SINGULAR", ga_affine_jac_between(bad, id, GA_JAC_LEFT, &j, &j2),
                     GA_ERR_SINGULAR);
    bad = id;
    bad.m[13] = 1e-9;
    tk_expect_status("last row off by 1e-9: GA_ERR_DOMAIN", ga_affine_jac_log(bad, GA_JAC_RIGHT, &j),
                     GA_ERR_DOMAIN);
    tk_expect_status("act on a NaN point: GA_ERR_NOTFINITE",
                     ga_affine_jac_act(id, (ga_vec3){NAN, 0, 0}, GA_JAC_RIGHT, &ja, &jp), GA_ERR_NOTFINITE);
    bad = id;
    bad.m[5] = INFINITY;
    tk_expect_status("Ad of an infinite matrix: GA_ERR_NOTFINITE", ga_affine_adjoint_matrix(bad, &j),
                     GA_ERR_NOTFINITE);
    bad = id;
    bad.m[0] = -2.0;
    bad.m[5] = -0.5; /* negative real eigenvalues: no real log */
    tk_expect_status("log at eigenvalues -2, -0.5: GA_ERR_DOMAIN", ga_affine_jac_log(bad, GA_JAC_LEFT, &j),
                     GA_ERR_DOMAIN);
}

static const tk_section sections[] = {
    {"exp", section_exp, 0},
    {"group", section_group, 0},
    {"statuses", section_statuses, 0},
};

int main(int argc, char **argv)
{
    return tk_main(argc, argv, "test_jacobian_affine", sections, TK_COUNT(sections));
}
