/* ga/jacobian_affine.c: the Jacobians of the affine group, homogeneous 4x4
 * matrices with det > 0 (jacobian.h, "the affine group").
 *
 * An algebra element X (last row zero) has the coordinates x[4i + j] =
 * X[i][j], i < 3. With Y's last row zero as well, (XY)_ij = sum_{k<3} X_ik Y_kj
 * and (YX)_ij = sum_{l<3} Y_il X_lj, so
 *   ad(X)[4i+j][4k+l] = [j = l] X_ik - [i = k, l < 3] X_lj,
 *   Ad(A)[4i+j][4k+l] = A_ik (A^-1)_lj            (A Y A^-1, k < 3).
 * J_r(X) = phi(-ad X), J_l(X) = phi(ad X), phi(z) = (e^z - 1)/z = sum_k
 * z^k/(k+1)!: Z = +-ad(X)/2^s with ||Z||_1 <= 1/2, phi(Z) by Horner (18
 * terms: the first left out is below 0.5^18/19! < 4e-23), e^Z = I + Z phi(Z),
 * then s doublings phi(2Z) = phi(Z)(e^Z + I)/2, e^{2Z} = (e^Z)^2 (Higham,
 * Functions of Matrices, 10.7.4; the phi functions of exponential
 * integrators). J_r(X) E is expm(-X) times the Frechet derivative of expm at
 * X in E (Higham 2008, 10.2), J_l(X) E that derivative times expm(-X).
 */
#include <garotor/jacobian.h>
#include <garotor/mat4.h>

#include <math.h>
#include <string.h>

#define N 12

static void m12_mul(const ga_mat12 *a, const ga_mat12 *b, ga_mat12 *o)
{
    ga_mat12 c;
    for (int i = 0; i < N; i++) {
        double r[N] = {0};
        for (int k = 0; k < N; k++) {
            double s = a->m[N * i + k];
            if (s == 0.0)
                continue; /* ad and Ad are sparse; a zero adds nothing */
            for (int j = 0; j < N; j++) r[j] += s * b->m[N * k + j];
        }
        memcpy(c.m + N * i, r, sizeof r);
    }
    *o = c;
}

static double m12_norm1(const ga_mat12 *a)
{
    double n = 0.0;
    for (int j = 0; j < N; j++) {
        double s = 0.0;
        for (int i = 0; i < N; i++) s += fabs(a->m[N * i + j]);
        n = fmax(n, s);
    }
    return n;
}

static int m12_finite(const ga_mat12 *a)
{
    double z = 0.0;
    for (int i = 0; i < N * N; i++) z += a->m[i] - a->m[i];
    return z == 0.0;
}

static int m4_finite(ga_mat4 a)
{
    for (int i = 0; i < 16; i++)
        if (!isfinite(a.m[i]))
            return 0;
    return 1;
}

ga_mat12 ga_affine_ad(ga_mat4 x)
{
    ga_mat12 o;
    memset(&o, 0, sizeof o);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 4; j++)
            for (int k = 0; k < 3; k++)
                for (int l = 0; l < 4; l++) {
                    double v = 0.0;
                    if (j == l)
                        v += x.m[4 * i + k];
                    if (i == k && l < 3)
                        v -= x.m[4 * l + j];
                    o.m[N * (4 * i + j) + 4 * k + l] = v;
                }
    return o;
}

/* phi(sgn ad X) */
static ga_status jac(ga_mat4 x, double sgn, ga_mat12 *out)
{
    if (!out)
        return GA_ERR_ARG;
    if (!m4_finite(x))
        return GA_ERR_NOTFINITE;
    ga_mat12 z = ga_affine_ad(x);
    double nrm = m12_norm1(&z);
    int s = 0;
    if (nrm > 0.5) {
        frexp(nrm, &s);
        s += 1; /* nrm = f 2^e, f in [1/2, 1): nrm 2^-(e+1) < 1/2 */
    }
    double sc = sgn * ldexp(1.0, -s);
    for (int i = 0; i < N * N; i++) z.m[i] *= sc;
    /* Horner: phi = I + Z/2 (I + Z/3 (I + ... (I + Z/19))) */
    ga_mat12 p, t;
    memset(&p, 0, sizeof p);
    for (int i = 0; i < N; i++) p.m[(N + 1) * i] = 1.0;
    for (int k = 19; k >= 2; k--) {
        m12_mul(&z, &p, &t);
        for (int i = 0; i < N * N; i++) p.m[i] = t.m[i] / k;
        for (int i = 0; i < N; i++) p.m[(N + 1) * i] += 1.0;
    }
    ga_mat12 e; /* e^Z = I + Z phi(Z) */
    m12_mul(&z, &p, &e);
    for (int i = 0; i < N; i++) e.m[(N + 1) * i] += 1.0;
    for (int r = 0; r < s; r++) {
        ga_mat12 h = e;
        for (int i = 0; i < N; i++) h.m[(N + 1) * i] += 1.0;
        m12_mul(&p, &h, &t);
        for (int i = 0; i < N * N; i++) p.m[i] = 0.5 * t.m[i];
        if (r + 1 < s)
            m12_mul(&e, &e, &e);
        if (!m12_finite(&p))
            return GA_ERR_DOMAIN;
    }
    if (!m12_finite(&p))
        return GA_ERR_DOMAIN;
    *out = p;
    return GA_OK;
}

ga_status ga_affine_jr(ga_mat4 x, ga_mat12 *out) { return jac(x, -1.0, out); }
ga_status ga_affine_jl(ga_mat4 x, ga_mat12 *out) { return jac(x, 1.0, out); }

/* out = a^-1 by Gauss-Jordan elimination with partial pivoting;
 * GA_ERR_SINGULAR for a pivot at or below 1e-14 of the largest entry */
static ga_status m12_inverse(const ga_mat12 *a, ga_mat12 *out)
{
    double w[N][2 * N], big = 0.0;
    for (int i = 0; i < N; i++)
        for (int j = 0; j < N; j++) {
            w[i][j] = a->m[N * i + j];
            w[i][N + j] = i == j;
            big = fmax(big, fabs(w[i][j]));
        }
    for (int c = 0; c < N; c++) {
        int piv = c;
        for (int i = c + 1; i < N; i++)
            if (fabs(w[i][c]) > fabs(w[piv][c]))
                piv = i;
        if (!(fabs(w[piv][c]) > 1e-14 * big))
            return GA_ERR_SINGULAR;
        if (piv != c)
            for (int j = 0; j < 2 * N; j++) {
                double t = w[c][j];
                w[c][j] = w[piv][j];
                w[piv][j] = t;
            }
        double d = w[c][c];
        for (int j = 0; j < 2 * N; j++) w[c][j] /= d;
        for (int i = 0; i < N; i++) {
            double f = w[i][c];
            if (i == c || f == 0.0)
                continue;
            for (int j = 0; j < 2 * N; j++) w[i][j] -= f * w[c][j];
        }
    }
    ga_mat12 r;
    for (int i = 0; i < N; i++)
        for (int j = 0; j < N; j++) r.m[N * i + j] = w[i][N + j];
    if (!m12_finite(&r))
        return GA_ERR_DOMAIN;
    *out = r;
    return GA_OK;
}

static ga_status jac_inverse(ga_mat4 x, double sgn, ga_mat12 *out)
{
    ga_mat12 j;
    ga_status st = jac(x, sgn, out ? &j : NULL);
    return st == GA_OK ? m12_inverse(&j, out) : st;
}

ga_status ga_affine_jr_inverse(ga_mat4 x, ga_mat12 *out) { return jac_inverse(x, -1.0, out); }
ga_status ga_affine_jl_inverse(ga_mat4 x, ga_mat12 *out) { return jac_inverse(x, 1.0, out); }

/* ---- the group ------------------------------------------------------------------ */

static int side_ok(ga_jac_side side) { return side == GA_JAC_RIGHT || side == GA_JAC_LEFT; }

/* an element of the group, its last row set to 0 0 0 1, and its inverse
 * (group_affine.c's from_mat4 rules) */
static ga_status affine_in(ga_mat4 m, ga_mat4 *out, ga_mat4 *inv)
{
    if (!m4_finite(m))
        return GA_ERR_NOTFINITE;
    if (fabs(m.m[12]) > 1e-12 || fabs(m.m[13]) > 1e-12 || fabs(m.m[14]) > 1e-12 ||
        fabs(m.m[15] - 1.0) > 1e-12)
        return GA_ERR_DOMAIN;
    double det = m.m[0] * (m.m[5] * m.m[10] - m.m[6] * m.m[9]) -
                 m.m[1] * (m.m[4] * m.m[10] - m.m[6] * m.m[8]) + m.m[2] * (m.m[4] * m.m[9] - m.m[5] * m.m[8]);
    if (det < 0.0)
        return GA_ERR_DOMAIN;
    m.m[12] = m.m[13] = m.m[14] = 0.0;
    m.m[15] = 1.0;
    ga_mat4 r;
    ga_status st = ga_mat4_inverse(m, &r);
    if (st != GA_OK)
        return st;
    r.m[12] = r.m[13] = r.m[14] = 0.0;
    r.m[15] = 1.0;
    *out = m;
    *inv = r;
    return GA_OK;
}

/* Ad(A) from A and A^-1 */
static ga_mat12 adj(ga_mat4 a, ga_mat4 ai)
{
    ga_mat12 o;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 4; j++)
            for (int k = 0; k < 3; k++)
                for (int l = 0; l < 4; l++)
                    o.m[N * (4 * i + j) + 4 * k + l] = a.m[4 * i + k] * ai.m[4 * l + j];
    return o;
}

static ga_mat12 m12_identity(void)
{
    ga_mat12 o;
    memset(&o, 0, sizeof o);
    for (int i = 0; i < N; i++) o.m[(N + 1) * i] = 1.0;
    return o;
}

static ga_mat12 m12_neg(ga_mat12 a)
{
    for (int i = 0; i < N * N; i++) a.m[i] = -a.m[i];
    return a;
}

/* both arguments of a two-element Jacobian checked, with their inverses */
static ga_status affine_pair_in(ga_mat4 a, ga_mat4 b, ga_mat4 *ma, ga_mat4 *mai, ga_mat4 *mb, ga_mat4 *mbi)
{
    ga_status st = affine_in(a, ma, mai);
    return st == GA_OK ? affine_in(b, mb, mbi) : st;
}

ga_status ga_affine_adjoint_matrix(ga_mat4 a, ga_mat12 *out)
{
    if (!out)
        return GA_ERR_ARG;
    ga_mat4 m, mi;
    ga_status st = affine_in(a, &m, &mi);
    if (st == GA_OK)
        *out = adj(m, mi);
    return st;
}

ga_status ga_affine_jac_compose(ga_mat4 a, ga_mat4 b, ga_jac_side side, ga_mat12 *ja, ga_mat12 *jb)
{
    if (!ja || !jb || !side_ok(side))
        return GA_ERR_ARG;
    ga_mat4 ma, mai, mb, mbi;
    ga_status st = affine_pair_in(a, b, &ma, &mai, &mb, &mbi);
    if (st != GA_OK)
        return st;
    if (side == GA_JAC_RIGHT)
        *ja = adj(mbi, mb), *jb = m12_identity();
    else
        *ja = m12_identity(), *jb = adj(ma, mai);
    return GA_OK;
}

ga_status ga_affine_jac_inverse(ga_mat4 a, ga_jac_side side, ga_mat12 *j)
{
    if (!j || !side_ok(side))
        return GA_ERR_ARG;
    ga_mat4 m, mi;
    ga_status st = affine_in(a, &m, &mi);
    if (st == GA_OK)
        *j = m12_neg(side == GA_JAC_RIGHT ? adj(m, mi) : adj(mi, m));
    return st;
}

ga_status ga_affine_jac_between(ga_mat4 a, ga_mat4 b, ga_jac_side side, ga_mat12 *ja, ga_mat12 *jb)
{
    if (!ja || !jb || !side_ok(side))
        return GA_ERR_ARG;
    ga_mat4 ma, mai, mb, mbi;
    ga_status st = affine_pair_in(a, b, &ma, &mai, &mb, &mbi);
    if (st != GA_OK)
        return st;
    if (side == GA_JAC_RIGHT) { /* -Ad(B^-1 A), I */
        ga_mat4 c = ga_mat4_mul(mbi, ma), ci = ga_mat4_mul(mai, mb);
        *ja = m12_neg(adj(c, ci));
        *jb = m12_identity();
    } else { /* -Ad(A^-1), Ad(A^-1) */
        *jb = adj(mai, ma);
        *ja = m12_neg(*jb);
    }
    return GA_OK;
}

ga_status ga_affine_jac_act(ga_mat4 a, ga_vec3 p, ga_jac_side side, ga_mat3x12 *ja, ga_mat3 *jp)
{
    if (!ja || !jp || !side_ok(side))
        return GA_ERR_ARG;
    ga_mat4 m, mi;
    ga_status st = affine_in(a, &m, &mi);
    if (st == GA_OK && !(isfinite(p.x) && isfinite(p.y) && isfinite(p.z)))
        st = GA_ERR_NOTFINITE;
    if (st != GA_OK)
        return st;
    double pt[4] = {p.x, p.y, p.z, 1.0}, yt[4] = {0, 0, 0, 1.0};
    for (int i = 0; i < 3; i++)
        yt[i] = m.m[4 * i] * p.x + m.m[4 * i + 1] * p.y + m.m[4 * i + 2] * p.z + m.m[4 * i + 3];
    for (int i = 0; i < 3; i++) {
        for (int k = 0; k < 3; k++)
            for (int l = 0; l < 4; l++)
                ja->m[N * i + 4 * k + l] = side == GA_JAC_RIGHT ? m.m[4 * i + k] * pt[l] : (i == k) * yt[l];
        for (int k = 0; k < 3; k++) jp->m[3 * i + k] = m.m[4 * i + k];
    }
    return GA_OK;
}

ga_status ga_affine_jac_log(ga_mat4 a, ga_jac_side side, ga_mat12 *j)
{
    if (!j || !side_ok(side))
        return GA_ERR_ARG;
    ga_mat4 m, mi, l;
    ga_status st = affine_in(a, &m, &mi);
    if (st == GA_OK)
        st = ga_mat4_logm(m, &l);
    if (st != GA_OK)
        return st;
    return side == GA_JAC_RIGHT ? ga_affine_jr_inverse(l, j) : ga_affine_jl_inverse(l, j);
}
