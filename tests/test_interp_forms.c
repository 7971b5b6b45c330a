/* tests/test_interp_forms.c: the schemes against closed forms and the
 * papers' equations: the screw path = Eberly's geodesic = Wareham-Lasenby's
 * rotor form = dual-quaternion ScLERP (Kavan et al. 2008), SLERP on
 * rotations; Wareham-Lasenby's quadratic, smooth's exactness, lihao3 on a
 * screw motion, Li-Hao's eqs. 16, 25 and 27; dexp of SE(3) against the
 * affine series and differences; affine = se3 on rigid keys.
 * Seeded (interp_kit.h), so every run is the same.
 */
#include "interp_kit.h"

static tk_rng stream;
static tk_rng *const r = &stream; /* helpers take it as r */

/* ---- screw = Eberly geodesic = W-L rotor form = dual-quaternion ScLERP; SLERP ---- */

typedef struct {
    double w, x, y, z;
} quat;
static quat qmul(quat a, quat b)
{
    quat r = {a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z, a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
              a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x, a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
    return r;
}
static quat qconj(quat a)
{
    quat r = {a.w, -a.x, -a.y, -a.z};
    return r;
}
static quat qadd(quat a, quat b)
{
    quat r = {a.w + b.w, a.x + b.x, a.y + b.y, a.z + b.z};
    return r;
}
static quat qscale(quat a, double s)
{
    quat r = {s * a.w, s * a.x, s * a.y, s * a.z};
    return r;
}

/* Shepperd's method, written here independently of rotor.c. */
static quat quat_of(ga_mat4 m)
{
    double r00 = m.m[0], r11 = m.m[5], r22 = m.m[10], tr = r00 + r11 + r22;
    quat q;
    if (tr >= r00 && tr >= r11 && tr >= r22) {
        double s = 2 * sqrt(1 + tr);
        q.w = s / 4;
        q.x = (m.m[9] - m.m[6]) / s;
        q.y = (m.m[2] - m.m[8]) / s;
        q.z = (m.m[4] - m.m[1]) / s;
    } else if (r00 >= r11 && r00 >= r22) {
        double s = 2 * sqrt(1 + r00 - r11 - r22);
        q.w = (m.m[9] - m.m[6]) / s;
        q.x = s / 4;
        q.y = (m.m[1] + m.m[4]) / s;
        q.z = (m.m[2] + m.m[8]) / s;
    } else if (r11 >= r22) {
        double s = 2 * sqrt(1 + r11 - r00 - r22);
        q.w = (m.m[2] - m.m[8]) / s;
        q.x = (m.m[1] + m.m[4]) / s;
        q.y = s / 4;
        q.z = (m.m[6] + m.m[9]) / s;
    } else {
        double s = 2 * sqrt(1 + r22 - r00 - r11);
        q.w = (m.m[4] - m.m[1]) / s;
        q.x = (m.m[2] + m.m[8]) / s;
        q.y = (m.m[6] + m.m[9]) / s;
        q.z = s / 4;
    }
    return q;
}
static ga_mat4 mat_of(quat q, ga_vec3 t)
{
    double w = q.w, x = q.x, y = q.y, z = q.z;
    /* clang-format off */
    ga_mat4 m = {{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y), t.x,
                  2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x), t.y,
                  2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y), t.z,
                  0, 0, 0, 1}};
    /* clang-format on */
    return m;
}

typedef struct {
    quat r, d;
} dquat;
static dquat dq_of(ga_mat4 m)
{
    dquat a;
    a.r = quat_of(m);
    quat t = {0, m.m[3], m.m[7], m.m[11]};
    a.d = qscale(qmul(t, a.r), 0.5);
    return a;
}
static dquat dq_mul(dquat a, dquat b)
{
    dquat c = {qmul(a.r, b.r), qadd(qmul(a.r, b.d), qmul(a.d, b.r))};
    return c;
}
static dquat dq_conj(dquat a)
{
    dquat c = {qconj(a.r), qconj(a.d)};
    return c;
}
static ga_mat4 dq_mat(dquat a)
{
    quat t = qscale(qmul(a.d, qconj(a.r)), 2.0);
    ga_vec3 tv = {t.x, t.y, t.z};
    return mat_of(a.r, tv);
}
/* a^u through the screw parameters: a = cos(th^/2) + sin(th^/2) l^, th^ = th + e d,
 * l^ = l + e m, m = (t x l + (t - d l) cot(th/2))/2 (Kavan et al. 2008). */
static dquat dq_pow(dquat a, double u)
{
    double sv = sqrt(a.r.x * a.r.x + a.r.y * a.r.y + a.r.z * a.r.z);
    double th = 2 * atan2(sv, a.r.w);
    ga_vec3 l = {a.r.x / sv, a.r.y / sv, a.r.z / sv};
    quat tq = qscale(qmul(a.d, qconj(a.r)), 2.0);
    ga_vec3 t = {tq.x, tq.y, tq.z};
    double dd = t.x * l.x + t.y * l.y + t.z * l.z, ct = cos(th / 2) / sin(th / 2);
    ga_vec3 m = {0.5 * ((t.y * l.z - t.z * l.y) + (t.x - dd * l.x) * ct),
                 0.5 * ((t.z * l.x - t.x * l.z) + (t.y - dd * l.y) * ct),
                 0.5 * ((t.x * l.y - t.y * l.x) + (t.z - dd * l.z) * ct)};
    double c = cos(u * th / 2), s = sin(u * th / 2), hd = u * dd / 2;
    dquat r;
    r.r.w = c;
    r.r.x = s * l.x;
    r.r.y = s * l.y;
    r.r.z = s * l.z;
    r.d.w = -hd * s;
    r.d.x = hd * c * l.x + s * m.x;
    r.d.y = hd * c * l.y + s * m.y;
    r.d.z = hd * c * l.z + s * m.z;
    return r;
}
static ga_mat4 sclerp(ga_mat4 a, ga_mat4 b, double u)
{
    dquat da = dq_of(a), rel = dq_mul(dq_conj(da), dq_of(b));
    if (rel.r.w < 0) {
        rel.r = qscale(rel.r, -1);
        rel.d = qscale(rel.d, -1);
    }
    return dq_mat(dq_mul(da, dq_pow(rel, u)));
}

static void test_screw(void)
{
    stream = tk_rng_after(INTERP_SEED, 34872); /* after paths' growth and cga_se3 */
    tk_check c_init = tk_begin("screw path init", 0);
    tk_check e_geo = tk_begin("screw == ga_se3_geodesic (Eberly eq. 21)", 1e-13);
    tk_check e_wl = tk_begin("screw == W-L exp(u l(R1 ~R0)) R0 on rotors (Ad-invariance)", 1e-13);
    tk_check e_dq = tk_begin("screw == dual-quaternion ScLERP", 1e-12);
    tk_check e_slerp = tk_begin("screw on pure rotations == quaternion SLERP", 1e-13);
    tk_check e_four = tk_begin("screw on rotors == A_i ga_rotor_exp(u B_i), u in [-1, 2], / scale", 1e-14);
    for (int trial = 0; trial < 100; ++trial) {
        keyset k;
        random_keys(r, &k, 2 + trial % 5, 0);
        pathbuf a, b;
        int s1 = mkpath(&a, &ga_group_se3, GA_SCHEME_SCREW, &k, NULL);
        int s2 = mkpath(&b, &ga_group_cga, GA_SCHEME_SCREW, &k, NULL);
        tk_add_status(&c_init, s1 ? s1 : s2, GA_OK);
        if (s1 || s2)
            continue;
        for (int i = 0; i + 1 < k.n; ++i) {
            /* W-L §3.1 with rotors: R(u) = exp(u l(R_{i+1} ~R_i)) R_i */
            const ga_group *g = &ga_group_cga;
            double ri[8], ri1[8], rinv[8], rel[8], x[6];
            g->from_mat4(k.m[i], ri);
            g->from_mat4(k.m[i + 1], ri1);
            g->inverse(ri, rinv);
            g->compose(ri1, rinv, rel);
            g->log(rel, x);
            for (int q = 0; q <= 10; ++q) {
                double u = q / 10.0;
                ga_mat4 geo;
                TK_OK(ga_se3_geodesic(k.m[i], k.m[i + 1], u, &geo));
                ga_mat4 ps = at_seg(&a.p, i, u), pc = at_seg(&b.p, i, u);
                tk_add(&e_geo, mdiff(ps, geo) / k.scale);
                double xu[6], e[8], wl[8];
                for (int j = 0; j < 6; ++j) xu[j] = u * x[j];
                g->exp(xu, e);
                g->compose(e, ri, wl);
                tk_add(&e_wl, mdiff(pc, g->to_mat4(wl)) / k.scale);
                tk_add(&e_dq, mdiff(ps, sclerp(k.m[i], k.m[i + 1], u)) / k.scale);
            }
            /* the sampler's sum of four fixed rotors (path.c, screw_at) against
               the product of the key and the exp of its scaled twist, also past
               the segment's ends, where u phi reaches each branch of the exp */
            const double *key = b.p.key + (size_t)i * b.p.key_stride, *xi = b.p.coef + 6 * i;
            for (int q = -20; q <= 40; ++q) {
                double u = q / 20.0, got[8];
                ga_rotor ki, want;
                memcpy(&ki, key, sizeof ki);
                ga_twist tw = {{u * xi[0], u * xi[1], u * xi[2]}, {u * xi[3], u * xi[4], u * xi[5]}};
                want = ga_rotor_mul(ki, ga_rotor_exp(ga_twist_to_generator(tw)));
                tk_add_status(&c_init, ga_path_eval_segment(&b.p, (size_t)i, u, got), GA_OK);
                tk_add(&e_four, mdiff(g->to_mat4(got), ga_rotor_to_mat4(want)) / k.scale);
            }
        }
        /* pure rotations: quaternion SLERP */
        keyset rk = k;
        for (int i = 0; i < rk.n; ++i) rk.m[i].m[3] = rk.m[i].m[7] = rk.m[i].m[11] = 0;
        pathbuf c;
        if (mkpath(&c, &ga_group_cga, GA_SCHEME_SCREW, &rk, NULL))
            continue;
        for (int i = 0; i + 1 < rk.n; ++i) {
            quat q0 = quat_of(rk.m[i]), q1 = quat_of(rk.m[i + 1]);
            double dot = q0.w * q1.w + q0.x * q1.x + q0.y * q1.y + q0.z * q1.z;
            if (dot < 0) {
                q1 = qscale(q1, -1);
                dot = -dot;
            }
            double phi = acos(fmin(1.0, dot));
            for (int q = 0; q <= 10; ++q) {
                double u = q / 10.0;
                quat s = phi < 1e-8 ? q0
                                    : qadd(qscale(q0, sin((1 - u) * phi) / sin(phi)),
                                           qscale(q1, sin(u * phi) / sin(phi)));
                ga_vec3 z = {0, 0, 0};
                tk_add(&e_slerp, mdiff(at_seg(&c.p, i, u), mat_of(s, z)));
            }
        }
    }
    tk_end(&c_init);
    tk_end(&e_geo);
    tk_end(&e_wl);
    tk_end(&e_dq);
    tk_end(&e_slerp);
    tk_end(&e_four);
}

/* ---- scheme identities: W-L quadratic, smooth exactness, lihao3 screw, eq. 27 ---- */

static void test_identities(void)
{
    /* W-L §3.2 at times -1, 0, 1: B'_l = ((B3 + B1)/2 - B2) l^2 + (B3 - B1)/2 l + B2 */
    tk_check c_init = tk_begin("path init (identities)", 0);
    tk_check e_wl = tk_begin("quadratic == W-L §3.2 formula at times -1, 0, 1", 1e-13);
    tk_check e_sq = tk_begin("smooth with 3 keys == quadratic", 1e-13);
    tk_check e_exact = tk_begin("smooth reproduces exp(quadratic twist) at any times", 1e-13);
    tk_check e_l3 = tk_begin("lihao3 (default velocities) reproduces a screw motion", 1e-13);
    tk_check e_l3v = tk_begin("lihao3 (default velocities): the screw motion's velocity", 1e-12);
    tk_check e16 = tk_begin("Li-Hao eq. 16 (e^-B): e^B e^C = A_i^-1 A_i+1", 1e-13);
    tk_check e27 = tk_begin_least("Li-Hao eq. 27 as printed (e^+B) misses the key by > 1e-2", 1e-2);
    tk_check e25 = tk_begin("Li-Hao eq. 25 (dM/du at u = 1) = central FD", 1e-8);
    for (int trial = 0; trial < 40; ++trial) {
        keyset k;
        random_keys(r, &k, 3, 0);
        k.t[0] = -1;
        k.t[1] = 0;
        k.t[2] = 1;
        const ga_group *g = trial % 2 ? &ga_group_cga : &ga_group_se3;
        pathbuf q, sm;
        int s1 = mkpath(&q, g, GA_SCHEME_QUADRATIC, &k, NULL),
            s2 = mkpath(&sm, g, GA_SCHEME_SMOOTH, &k, NULL);
        tk_add_status(&c_init, s1 ? s1 : s2, GA_OK);
        if (s1 || s2)
            continue;
        const double *B1 = q.p.gen, *B2 = B1 + 6, *B3 = B2 + 6;
        for (int j = 0; j <= 20; ++j) {
            double l = -1 + j / 10.0, x[6], e[16];
            for (int c = 0; c < 6; ++c)
                x[c] = ((B3[c] + B1[c]) / 2 - B2[c]) * l * l + (B3[c] - B1[c]) / 2 * l + B2[c];
            g->exp(x, e);
            tk_add(&e_wl, mdiff(at(&q.p, l), g->to_mat4(e)) / path_scale(&q.p, &k));
            tk_add(&e_sq, mdiff(at(&q.p, l), at(&sm.p, l)) / path_scale(&q.p, &k));
        }
    }
    /* smooth reproduces exp(Q(t)) for a quadratic Q in twist space (small angles,
     * so the principal logs are the Q(t_i) themselves) at any times */
    for (int trial = 0; trial < 40; ++trial) {
        double c0[6], c1[6], c2[6];
        for (int j = 0; j < 6; ++j) {
            c0[j] = tk_range(r, -0.5, 0.5);
            c1[j] = tk_range(r, -0.3, 0.3);
            c2[j] = tk_range(r, -0.05, 0.05);
        }
        keyset k;
        k.n = 4 + trial % 4;
        random_times(r, &k);
        double mid = 0.5 * (k.t[0] + k.t[k.n - 1]);
        for (int i = 0; i < k.n; ++i) {
            double s = (k.t[i] - mid) / (k.t[k.n - 1] - k.t[0]) * 2, x[6];
            for (int j = 0; j < 6; ++j) x[j] = c0[j] + c1[j] * s + c2[j] * s * s;
            k.m[i] = ga_se3_exp((ga_twist){{x[0], x[1], x[2]}, {x[3], x[4], x[5]}});
        }
        set_scale(&k);
        pathbuf sm;
        int st = mkpath(&sm, &ga_group_se3, GA_SCHEME_SMOOTH, &k, NULL);
        tk_add_status(&c_init, st, GA_OK);
        if (st)
            continue;
        for (int j = 0; j <= 50; ++j) {
            double t = tgrid(&k, j, 50);
            double s = (t - mid) / (k.t[k.n - 1] - k.t[0]) * 2, x[6];
            for (int c = 0; c < 6; ++c) x[c] = c0[c] + c1[c] * s + c2[c] * s * s;
            ga_mat4 ref = ga_se3_exp((ga_twist){{x[0], x[1], x[2]}, {x[3], x[4], x[5]}});
            tk_add(&e_exact, mdiff(at(&sm.p, t), ref) / k.scale);
        }
    }
    /* lihao3 with the default velocities reproduces a screw motion A0 exp(t V) */
    for (int trial = 0; trial < 40; ++trial) {
        ga_twist V;
        V.w = tk_unit(r);
        V.v = rvec(r, 1);
        ga_mat4 A0 = rand_rigid(r, 0, 3, 3);
        keyset k;
        k.n = 3 + trial % 5;
        random_times(r, &k);
        for (int i = 0; i < k.n; ++i) {
            double s = 0.4 * (k.t[i] - k.t[0]);
            ga_twist x = {{s * V.w.x, s * V.w.y, s * V.w.z}, {s * V.v.x, s * V.v.y, s * V.v.z}};
            k.m[i] = mmul(A0, ga_se3_exp(x));
        }
        set_scale(&k);
        const ga_group *g = trial % 2 ? &ga_group_cga : &ga_group_se3;
        pathbuf b;
        int st = mkpath(&b, g, GA_SCHEME_LIHAO3, &k, NULL);
        tk_add_status(&c_init, st, GA_OK);
        if (st)
            continue;
        for (int j = 0; j <= 30; ++j) {
            double t = tgrid(&k, j, 30), s = 0.4 * (t - k.t[0]);
            ga_twist x = {{s * V.w.x, s * V.w.y, s * V.w.z}, {s * V.v.x, s * V.v.y, s * V.v.z}};
            tk_add(&e_l3, mdiff(at(&b.p, t), mmul(A0, ga_se3_exp(x))) / k.scale);
            double v[6],
                vr[6] = {0.4 * V.w.x, 0.4 * V.w.y, 0.4 * V.w.z, 0.4 * V.v.x, 0.4 * V.v.y, 0.4 * V.v.z};
            vel_at(&b.p, t, v);
            tk_add(&e_l3v, vdiff(v, vr, 6));
        }
    }
    /* Li-Hao eq. 27 as printed, C = log(e^{+B} A_i^-1 A_{i+1}), misses the next
     * key; eq. 16's e^{-B} hits it. Eq. 25 (dM/du at u = 1) against FD. */
    for (int trial = 0; trial < 20; ++trial) {
        ga_mat4 A = rand_rigid(r, 0, 2, 2), Bm = rand_rigid(r, 0, 2, 2);
        ga_mat4 rel = mmul(ga_se3_inverse(A), Bm);
        ga_twist B = rand_twist(r, 0.5, 0.5), mB = {{-B.w.x, -B.w.y, -B.w.z}, {-B.v.x, -B.v.y, -B.v.z}};
        ga_twist C16, C27, D = rand_twist(r, 0.5, 0.5);
        TK_OK(ga_se3_log(mmul(ga_se3_exp(mB), rel), &C16));
        TK_OK(ga_se3_log(mmul(ga_se3_exp(B), rel), &C27));
        tk_add(&e16, mdiff(mmul(ga_se3_exp(B), ga_se3_exp(C16)), rel));
        tk_add(&e27, mdiff(mmul(ga_se3_exp(B), ga_se3_exp(C27)), rel));
        /* eq. 25: M'(1) = B^ rel + 2 rel C^ + rel D^ for M = e^{uB} e^{u^2 C} e^{(u^3-u^2) D} */
        ga_mat4 lhs = mmul(ga_twist_hat(B), rel), r2 = mmul(rel, ga_twist_hat(C16)),
                r3 = mmul(rel, ga_twist_hat(D));
        for (int i = 0; i < 16; ++i) lhs.m[i] += 2 * r2.m[i] + r3.m[i];
        double hs = 1e-5;
        ga_mat4 Mp, Mm;
        for (int sgn = -1; sgn <= 1; sgn += 2) {
            double u = 1 + sgn * hs, pb = u, pc = u * u, pd = u * u * u - u * u;
            ga_twist xb = {{pb * B.w.x, pb * B.w.y, pb * B.w.z}, {pb * B.v.x, pb * B.v.y, pb * B.v.z}};
            ga_twist xc = {{pc * C16.w.x, pc * C16.w.y, pc * C16.w.z},
                           {pc * C16.v.x, pc * C16.v.y, pc * C16.v.z}};
            ga_twist xd = {{pd * D.w.x, pd * D.w.y, pd * D.w.z}, {pd * D.v.x, pd * D.v.y, pd * D.v.z}};
            ga_mat4 M = mmul(mmul(ga_se3_exp(xb), ga_se3_exp(xc)), ga_se3_exp(xd));
            if (sgn < 0)
                Mm = M;
            else
                Mp = M;
        }
        for (int i = 0; i < 16; ++i) tk_add(&e25, fabs((Mp.m[i] - Mm.m[i]) / (2 * hs) - lhs.m[i]));
    }
    tk_end(&c_init);
    tk_end(&e_wl);
    tk_end(&e_sq);
    tk_end(&e_exact);
    tk_end(&e_l3);
    tk_end(&e_l3v);
    tk_end(&e16);
    tk_end(&e27);
    tk_end(&e25);
}

/* ---- dexp: closed form vs the affine series vs finite differences -------------- */

static void test_dexp(void)
{
    tk_check e_aff = tk_begin("dexp: SE(3) closed form = affine series, / max(1,|x|)", 1e-12);
    tk_check e_fd = tk_begin("dexp: SE(3) closed form = central FD of log, / max(1,|x|)", 1e-7);
    for (int trial = 0; trial < 200; ++trial) {
        double x[6], y[6], j1[6], j2[12], xa[12], ya[12];
        ga_vec3 u = tk_unit(r);
        double th = trial % 5 == 0 ? pow(10.0, tk_range(r, -12, -1))
                  : trial % 5 == 1 ? PI - pow(10.0, tk_range(r, -12, -1))
                  : trial % 5 == 2 ? tk_range(r, 0.9, 1.1)
                                   : tk_range(r, 0, 8);
        x[0] = th * u.x;
        x[1] = th * u.y;
        x[2] = th * u.z;
        for (int i = 3; i < 6; ++i) x[i] = tk_range(r, -3, 3);
        for (int i = 0; i < 6; ++i) y[i] = tk_range(r, -1, 1);
        ga_group_se3.dexp(x, y, j1);
        /* the same twists as affine algebra elements (top rows of the hat) */
        ga_mat4 hx = ga_twist_hat((ga_twist){{x[0], x[1], x[2]}, {x[3], x[4], x[5]}});
        ga_mat4 hy = ga_twist_hat((ga_twist){{y[0], y[1], y[2]}, {y[3], y[4], y[5]}});
        memcpy(xa, hx.m, sizeof xa);
        memcpy(ya, hy.m, sizeof ya);
        ga_group_affine.dexp(xa, ya, j2);
        ga_mat4 hj = ga_twist_hat((ga_twist){{j1[0], j1[1], j1[2]}, {j1[3], j1[4], j1[5]}});
        double e = vdiff(hj.m, j2, 12);
        tk_add(&e_aff, e / fmax(1, vnorm(x, 6)));
        /* FD: log(exp(x)^-1 exp(x + s y))/s, central */
        double hs = 1e-6, xp[6], xm[6], ex[16], ep[16], em[16], yp[6], ym[6];
        for (int i = 0; i < 6; ++i) {
            xp[i] = x[i] + hs * y[i];
            xm[i] = x[i] - hs * y[i];
        }
        ga_group_se3.exp(x, ex);
        ga_group_se3.exp(xp, ep);
        ga_group_se3.exp(xm, em);
        body_log(&ga_group_se3, ex, ep, yp);
        body_log(&ga_group_se3, ex, em, ym);
        double fd[6];
        for (int i = 0; i < 6; ++i) fd[i] = (yp[i] - ym[i]) / (2 * hs);
        tk_add(&e_fd, vdiff(fd, j1, 6) / fmax(1, vnorm(x, 6)));
    }
    tk_end(&e_aff);
    tk_end(&e_fd);
}

/* ---- affine vs se3 on rigid keys; affine paths through scaled/sheared keys ---- */

static void test_affine(void)
{
    tk_check c_init = tk_begin("affine/se3 path init", 0);
    tk_check c = tk_begin("affine == se3 on rigid keys (screw, lihao2, lihao3), / scale", 1e-11);
    long domain = 0;
    for (int trial = 0; trial < 30; ++trial) {
        keyset k;
        k.n = 3 + trial % 4;
        random_times(r, &k);
        for (int i = 0; i < k.n; ++i) k.m[i] = rand_rigid(r, 0, 2.5, 4);
        set_scale(&k);
        ga_scheme ss[3] = {GA_SCHEME_SCREW, GA_SCHEME_LIHAO2, GA_SCHEME_LIHAO3};
        for (int si = 0; si < 3; ++si) {
            pathbuf a, b;
            int s1 = mkpath(&a, &ga_group_affine, ss[si], &k, NULL),
                s2 = mkpath(&b, &ga_group_se3, ss[si], &k, NULL);
            if (s1 == GA_ERR_DOMAIN) { /* a relative motion near a half turn: no real logm */
                ++domain;
                continue;
            }
            tk_add_status(&c_init, s1 ? s1 : s2, GA_OK);
            if (s1 || s2)
                continue;
            for (int j = 0; j <= 20; ++j) {
                double t = tgrid(&k, j, 20);
                tk_add(&c, mdiff(at(&a.p, t), at(&b.p, t)) / k.scale);
            }
        }
    }
    tk_end(&c_init);
    tk_end(&c);
    if (domain)
        tk_note("     (%ld affine paths GA_ERR_DOMAIN: a relative motion near a half turn)\n", domain);
    /* det and last-row checks */
    ga_mat4 bad = ga_mat4_identity(), m;
    bad.m[0] = -1;
    tk_expect(ga_group_affine.from_mat4(bad, &m) != GA_OK, "affine rejects det < 0");
    bad = ga_mat4_identity();
    bad.m[12] = 1e-6;
    tk_expect(ga_group_affine.from_mat4(bad, &m) != GA_OK, "affine rejects a last row 1e-6 0 0 1");
}

static const tk_section sections[] = {
    {"screw", test_screw, TK_STREAM}, {"identities", test_identities, TK_STREAM},
    {"dexp", test_dexp, TK_STREAM},   {"affine", test_affine, 0},
    {"time", tk_cpu_time, TK_SETUP},
};

int main(int argc, char **argv)
{
    return tk_main(argc, argv, "test_interp_forms", sections, TK_COUNT(sections));
}
