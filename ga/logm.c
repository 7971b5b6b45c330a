/* ga/logm.c: the general 4x4 matrix logarithm ga_mat4_logm, by inverse
 * scaling and squaring on the real Schur form (Al-Mohy & Higham, "Improved
 * inverse scaling and squaring algorithms for the matrix logarithm", 2012). */
#include <garotor/mat4.h>

#include <float.h>
#include <math.h>
#include <string.h>

#include "internal/mat4.h"
#include "internal/schur.h"
#include "internal/se3.h"

#define M GA__M

/* A 2x2 block B with a complex pair a +- i w is a I + N with N = B - a I,
 * N^2 = -w^2 I (Cayley-Hamilton), so every function of B is f(B) =
 * Re f(a + iw) I + (Im f(a + iw) / w) N: a closed form, exact up to the
 * rounding of a, w and f, with no square root of a nearly singular matrix
 * even when a + iw is near -1 (a near half turn). */
static void blk2_parts(double t[4][4], int p, double *a, double *w, double nm[2][2])
{
    *a = 0.5 * (t[p][p] + t[p + 1][p + 1]);
    double hd = 0.5 * (t[p][p] - t[p + 1][p + 1]);
    /* w^2 = -(hd^2 + bc), scaled so that a tiny block does not underflow */
    double sc = fmax(fabs(hd), fmax(fabs(t[p][p + 1]), fabs(t[p + 1][p])));
    *w = 0.0;
    if (sc > 0.0) {
        double h = hd / sc, b = t[p][p + 1] / sc, c = t[p + 1][p] / sc;
        *w = sc * sqrt(fmax(-(h * h + b * c), 0.0));
    }
    nm[0][0] = hd;
    nm[0][1] = t[p][p + 1];
    nm[1][0] = t[p + 1][p];
    nm[1][1] = -hd;
}

/* log|z| for z = 1 + am1 + iw: the log1p form near |z| = 1, where
 * log(hypot) would lose the small part. */
static double log_abs(double am1, double w)
{
    if (fabs(am1) < 0.5 && fabs(w) < 0.5)
        return 0.5 * log1p(am1 * (2.0 + am1) + w * w);
    return log(hypot(1.0 + am1, w));
}

/* The principal square root of the upper quasi-triangular t (blocks as
 * listed) by the real block recurrence of Higham ("Computing real square
 * roots of a real matrix", 1987; Functions of Matrices, 2008, Alg. 6.7):
 * R_jj = sqrt(T_jj) (1x1, or the 2x2 closed form above), then for i < j
 * R_ii R_ij + R_ij R_jj = T_ij - sum_{i<k<j} R_ik R_kj, a Sylvester equation
 * of at most 4 unknowns, solved by elimination with partial pivoting. Its
 * matrix is nonsingular: principal roots have eigenvalues in the open right
 * half-plane, so no two sum to 0. */
static void qt_sqrt(double t[4][4], const int *bs, const int *bz, int nb, double r[4][4])
{
    memset(r, 0, 16 * sizeof(double));
    for (int j = 0; j < nb; j++) {
        int pj = bs[j], qj = bz[j];
        if (qj == 1)
            r[pj][pj] = sqrt(t[pj][pj]);
        else {
            double a, w, nm[2][2], al, c;
            blk2_parts(t, pj, &a, &w, nm);
            double rho = hypot(a, w);
            if (a >= 0.0) {
                al = sqrt(0.5 * (rho + a));
                c = 0.5 / al;
            } else { /* sqrt(a + iw) = al + i be with be = sqrt((rho - a)/2) */
                double be = sqrt(0.5 * (rho - a));
                al = w / (2.0 * be);
                c = be / w;
            }
            for (int u = 0; u < 2; u++)
                for (int v = 0; v < 2; v++) r[pj + u][pj + v] = (u == v ? al : 0.0) + c * nm[u][v];
        }
        for (int i = j - 1; i >= 0; i--) {
            int pi = bs[i], qi = bz[i], nu = qi * qj;
            double k[4][5] = {{0}};
            for (int u = 0; u < qi; u++)
                for (int v = 0; v < qj; v++) {
                    int row = u * qj + v;
                    double rhs = t[pi + u][pj + v];
                    for (int x = pi + qi; x < pj; x++) rhs -= r[pi + u][x] * r[x][pj + v];
                    k[row][nu] = rhs;
                    for (int w = 0; w < qi; w++) k[row][w * qj + v] += r[pi + u][pi + w]; /* R_ii X */
                    for (int w = 0; w < qj; w++) k[row][u * qj + w] += r[pj + w][pj + v]; /* X R_jj */
                }
            for (int c = 0; c < nu; c++) {
                int p = c;
                for (int i2 = c + 1; i2 < nu; i2++)
                    if (fabs(k[i2][c]) > fabs(k[p][c]))
                        p = i2;
                for (int j2 = 0; j2 <= nu; j2++) {
                    double tmp = k[c][j2];
                    k[c][j2] = k[p][j2];
                    k[p][j2] = tmp;
                }
                for (int i2 = c + 1; i2 < nu; i2++) {
                    double l = k[i2][c] / k[c][c];
                    for (int j2 = c; j2 <= nu; j2++) k[i2][j2] -= l * k[c][j2];
                }
            }
            double e[4];
            for (int i2 = nu - 1; i2 >= 0; i2--) {
                double acc = k[i2][nu];
                for (int j2 = i2 + 1; j2 < nu; j2++) acc -= k[i2][j2] * e[j2];
                e[i2] = acc / k[i2][i2];
            }
            for (int u = 0; u < qi; u++)
                for (int v = 0; v < qj; v++) r[pi + u][pj + v] = e[u * qj + v];
        }
    }
}

static ga_mat4 mat4_of(double t[4][4])
{
    ga_mat4 a;
    memcpy(a.m, t, sizeof a.m);
    return a;
}
/* t (log y - log x)/(y - x) for eigenvalues x, y > 0 given with their logs
 * lx, ly and their difference d = y - x (each from the form, T or T - I,
 * that holds them accurately), without cancellation: for close x and y the
 * divided difference is 2 atanh(z)/(y - x), z = (y - x)/(y + x) (Higham,
 * Functions of Matrices, 2008, eq. 11.28, with no unwinding term for real
 * positive x, y). t is multiplied in before the division: the divided
 * difference alone overflows for subnormal eigenvalues (1/x for x = 1e-312). */
static double log_divdiff(double t, double x, double y, double lx, double ly, double d)
{
    if (t == 0.0)
        return 0.0;
    if (d == 0.0)
        return t / x;
    if (x < 0.5 * y || y < 0.5 * x)
        return t * (ly - lx) / d;
    double z = d / (x + y);
    if (fabs(z) < 0x1p-26) /* atanh z = z (1 + z^2/3 + ...): 2 atanh(z)/d = 2/(x + y) to rounding,
                               and z and d may be subnormal, with few bits */
        return 2.0 * t / (x + y);
    return t * (2.0 * atanh(z)) / d;
}

/* The sign of det A from Gaussian elimination with partial pivoting run to
 * the end (no pivot test) on A with its rows scaled by powers of two to a
 * largest entry in [1, 2) (the sign is unchanged): -1, 0 (a zero row or
 * pivot) or 1. */
static int lu4_det_sign(ga_mat4 a)
{
    int sign = 1;
    for (int i = 0; i < 4; i++) {
        double mr = 0.0;
        for (int j = 0; j < 4; j++) mr = fmax(mr, fabs(M(a, i, j)));
        if (!(mr > 0.0))
            return 0;
        int e = ilogb(mr);
        for (int j = 0; j < 4; j++) M(a, i, j) = ldexp(M(a, i, j), -e);
    }
    for (int k = 0; k < 4; k++) {
        int p = k;
        for (int i = k + 1; i < 4; i++)
            if (fabs(M(a, i, k)) > fabs(M(a, p, k)))
                p = i;
        if (p != k) {
            sign = -sign;
            for (int j = 0; j < 4; j++) {
                double t = M(a, k, j);
                M(a, k, j) = M(a, p, j);
                M(a, p, j) = t;
            }
        }
        if (M(a, k, k) == 0.0)
            return 0;
        sign = M(a, k, k) < 0.0 ? -sign : sign;
        for (int i = k + 1; i < 4; i++) {
            double l = M(a, i, k) / M(a, k, k);
            for (int j = k + 1; j < 4; j++) M(a, i, j) -= l * M(a, k, j);
        }
    }
    return sign;
}

/* ---- the Pade step -------------------------------------------------------- */

/* [8/8] Pade approximant of log(1 + x) in partial fractions: 8-point
 * Gauss-Legendre on log(I + X) = int_0^1 X (I + t X)^{-1} dt (Higham 2001).
 * It is used once alpha_p(X) = max(||X^p||^(1/p), ||X^(p+1)||^(1/(p+1)))
 * is at most theta_8 = 0.3666532675959788 for p = 3 or p = 4, which
 * bounds its backward error by u = 2^-53 (Al-Mohy & Higham 2012, Table
 * 2.1 and Thm. 2.2 with p(p - 1) <= 2m + 1 = 17). */
static const double node[8] = {1.98550717512318842e-02, 1.01666761293186636e-01, 2.37233795041835505e-01,
                               4.08282678752175110e-01, 5.91717321247824946e-01, 7.62766204958164495e-01,
                               8.98333238706813364e-01, 9.80144928248768088e-01};
static const double weight[8] = {5.06142681451881293e-02, 1.11190517226687241e-01, 1.56853322938943635e-01,
                                 1.81341891689180995e-01, 1.81341891689180995e-01, 1.56853322938943635e-01,
                                 1.11190517226687241e-01, 5.06142681451881293e-02};
static const double theta8 = 0.3666532675959788;

/* The [8/8] Pade approximant of log(I + X) as its partial fractions,
 * sum_j weight_j (I + node_j X)^{-1} X. GA_ERR_DOMAIN if a factor is
 * singular (a guard: rho(t X) < 0.37). */
static int logm_pade8(const ga_mat4 *x, ga_mat4 *lout)
{
    ga__mat4_lu f;
    ga_mat4 l = ga__mat4_zero();
    for (int j = 0; j < 8; j++) {
        ga_mat4 d = *x;
        for (int i = 0; i < 16; i++) d.m[i] *= node[j];
        if (ga__mat4_lu_factor(ga__mat4_add_id(d, 1.0), &f) != GA_OK)
            return GA_ERR_DOMAIN;
        ga_mat4 term = ga__mat4_lu_solve(&f, *x);
        ga__mat4_acc(&l, weight[j], &term);
    }
    *lout = l;
    return GA_OK;
}

/* ---- the steps of ga_mat4_logm ------------------------------------------ */

/* log A when neither Schur form converged (e.g. 1e-4 e^X: a cluster of
 * three eigenvalues at 1e-4 coupled by entries of 1e-15 in a
 * cycle, beside entries of 1e-302 and subnormals).
 * A fallback without a Schur form: inverse scaling and squaring
 * on A itself, square roots by the Denman-Beavers iteration
 * (Higham, "Functions of Matrices", 6.15), then the Pade step on
 * X = A^(1/2^k) - I once ||X||_1 <= theta_8, log A = 2^k log(I + X).
 * X is carried as X <- (Y + I)^{-1} X, not formed by
 * subtraction, whose absolute error of a few eps made the result
 * accurate only to about 2^k eps ||log A||; the domain (no
 * eigenvalue on the closed negative axis) shows as a failing
 * iteration. */
static int logm_denman_beavers(ga_mat4 a, int h, ga_mat4 *out)
{
    ga_mat4 y = a, x = ga__mat4_add_id(a, -1.0);
    int k = 0;
    for (; k < 64 && !(ga_mat4_norm1(x) <= theta8); k++) {
        ga_mat4 Y = y, Z = ga_mat4_identity();
        int it = 0;
        for (; it < 64; it++) {
            ga__mat4_lu fy, fz;
            if (ga__mat4_lu_factor(Y, &fy) != GA_OK || ga__mat4_lu_factor(Z, &fz) != GA_OK)
                return GA_ERR_DOMAIN;
            ga_mat4 yi = ga__mat4_lu_solve(&fy, ga_mat4_identity()),
                    zi = ga__mat4_lu_solve(&fz, ga_mat4_identity());
            double change = 0.0, size = 0.0;
            for (int e = 0; e < 16; e++) {
                double yn = 0.5 * (Y.m[e] + zi.m[e]);
                change = fmax(change, fabs(yn - Y.m[e]));
                size = fmax(size, fabs(yn));
                Y.m[e] = yn;
                Z.m[e] = 0.5 * (Z.m[e] + yi.m[e]);
            }
            if (!ga__mat4_isfinite(&Y) || !ga__mat4_isfinite(&Z))
                return GA_ERR_DOMAIN;
            if (change <= 4 * DBL_EPSILON * size)
                break;
        }
        if (it == 64)
            return GA_ERR_DOMAIN;
        /* X <- (Y + I)^{-1} X, as Z in the Schur path: the root's
         * A^(1/2^k) - I without the subtraction's absolute error */
        ga__mat4_lu fr;
        if (ga__mat4_lu_factor(ga__mat4_add_id(Y, 1.0), &fr) != GA_OK)
            return GA_ERR_DOMAIN;
        x = ga__mat4_lu_solve(&fr, x);
        y = Y;
    }
    if (k == 64)
        return GA_ERR_DOMAIN;
    ga_mat4 l;
    if (logm_pade8(&x, &l) != GA_OK)
        return GA_ERR_DOMAIN;
    ga__mat4_scale2(&l, k);
    if (h)
        M(l, 3, 0) = M(l, 3, 1) = M(l, 3, 2) = M(l, 3, 3) = 0.0;
    if (!ga__mat4_isfinite(&l))
        return GA_ERR_DOMAIN;
    *out = l;
    return GA_OK;
}

/* The real Schur form of A - sig I (t = T - sig I, qm = Q; see below in
 * ga_mat4_logm): sig = 1 first, then 0 where an eigenvalue is small, or the
 * mean of the diagonal where the form of A - I does not converge.
 * GA_ERR_DOMAIN if neither converges. */
static int logm_schur(const ga_mat4 *a, int n, double t[4][4], double qm[4][4], double *sigout)
{
    double sig = 1.0;
    if (ga__schur_shifted(a, n, 1.0, t, qm) != GA_OK) {
        /* the form of A - I did not converge (a guard: a cluster of
         * eigenvalues equal to rounding, such as 1e-4 (I + E) with E of
         * 1e-10 and below): the form of A - sig I,
         * sig the mean of the diagonal, whose entries are the cluster's
         * spread, resolved after scaling */
        sig = 0.0;
        for (int i = 0; i < n; i++) sig += M(*a, i, i) / n;
        if (ga__schur_shifted(a, n, sig, t, qm) != GA_OK)
            return GA_ERR_DOMAIN;
    } else {
        /* the smallest |lambda| (squared), lambda = 1 + t_ii, or for a 2x2
         * block det(I + T_jj) */
        double small = INFINITY;
        for (int i = 0; i < n; i++) {
            if (i + 1 < n && t[i + 1][i] != 0.0) {
                double d = (1.0 + t[i][i]) * (1.0 + t[i + 1][i + 1]) - t[i][i + 1] * t[i + 1][i];
                small = fmin(small, fabs(d));
                i++;
            } else
                small = fmin(small, (1.0 + t[i][i]) * (1.0 + t[i][i]));
        }
        if (small < 0.25) {
            double ts[4][4], qs[4][4];
            memcpy(ts, t, sizeof ts);
            memcpy(qs, qm, sizeof qs);
            if (ga__schur_shifted(a, n, 0.0, t, qm) == GA_OK)
                sig = 0.0;
            else { /* a guard, as above: keep the form of A - I */
                memcpy(t, ts, sizeof ts);
                memcpy(qm, qs, sizeof qs);
            }
        }
    }
    *sigout = sig;
    return GA_OK;
}

/* The blocks, and the domain decided from the eigenvalues: a real
 * eigenvalue <= 0 has no real principal log (0 is caught above as
 * singular); a complex pair always has one. lambda = sig + t_ii. */
static int logm_blocks(double t[4][4], double lam1, int bs[4], int bz[4], int *nbout)
{
    int nb = 0;
    for (int i = 0; i < 4; i += bz[nb - 1]) {
        bs[nb] = i;
        bz[nb] = (i < 3 && t[i + 1][i] != 0.0) ? 2 : 1;
        if (bz[nb] == 1 && !(lam1 + t[i][i] > 0.0))
            return lam1 + t[i][i] == 0.0 ? GA_ERR_SINGULAR : GA_ERR_DOMAIN;
        if (bz[nb] == 2) {
            /* a complex pair re +- iw whose imaginary part is within the
             * rounding of the Schur form (GA_MAT4_LOGM_AXIS_TOL |lambda|)
             * of the negative real axis: the sign of w, and with it the
             * log's, is not determined by the data */
            double am, w, nm[2][2];
            blk2_parts(t, i, &am, &w, nm);
            double re = lam1 + am;
            if (re < 0.0 && w <= GA_MAT4_LOGM_AXIS_TOL * hypot(re, w))
                return GA_ERR_DOMAIN;
        }
        nb++;
    }
    *nbout = nb;
    return GA_OK;
}

/* Inverse scaling and squaring on T: T_k = T^(1/2^k) and Z = T_k - I,
 * carried as Z <- (T_{k+1} + I)^{-1} Z (the factors commute) rather than
 * formed by subtraction, which would round away small parts (a scaling
 * 1 + 1e-10 under a translation of 1e6; this is the accurate T_k - I of
 * Al-Mohy & Higham 2012, sec. 5, for the whole matrix). Square roots
 * are taken while the spectral radius of Z exceeds theta_8, then while
 * alpha_3(Z) and alpha_4(Z) both do. Z = T_k - I and k into *zout, *kout. */
static int logm_roots(double t[4][4], double lam1, const int *bs, const int *bz, int nb, ga_mat4 *zout,
                      int *kout)
{
    double tk[4][4], z[4][4];
    memcpy(tk, t, sizeof tk);
    memcpy(z, t, sizeof z);
    for (int i = 0; i < 4; i++) {
        tk[i][i] += lam1;      /* T */
        z[i][i] -= 1.0 - lam1; /* T - I */
    }
    ga__mat4_lu f;
    int k = 0;
    for (;; k++) {
        double rho = 0.0;
        for (int b = 0; b < nb; b++) {
            int p = bs[b];
            rho = fmax(rho, bz[b] == 1 ? fabs(z[p][p])
                                       : sqrt(fabs(z[p][p] * z[p + 1][p + 1] - z[p][p + 1] * z[p + 1][p])));
        }
        if (rho <= theta8) {
            ga_mat4 zm = mat4_of(z);
            if (ga_mat4_norm1(zm) <= theta8)
                break;
            ga_mat4 z2 = ga_mat4_mul(zm, zm), z3 = ga_mat4_mul(z2, zm), z4 = ga_mat4_mul(z2, z2),
                    z5 = ga_mat4_mul(z4, zm);
            double d3 = cbrt(ga_mat4_norm1(z3)), d4 = pow(ga_mat4_norm1(z4), 0.25),
                   d5 = pow(ga_mat4_norm1(z5), 0.2);
            if (fmin(fmax(d3, d4), fmax(d4, d5)) <= theta8)
                break;
        }
        /* Each root at least halves the argument of a complex eigenvalue
         * and the log of a real one; with ||log T|| <= 4 * 1100 ... the
         * count is bounded by the exponent range: 1100 roots always do. */
        if (k == 1100)
            return GA_ERR_DOMAIN;
        double r[4][4];
        qt_sqrt(tk, bs, bz, nb, r);
        ga_mat4 rp = mat4_of(r);
        if (ga__mat4_lu_factor(ga__mat4_add_id(rp, 1.0), &f) != GA_OK)
            return GA_ERR_DOMAIN; /* a guard: R + I has eigenvalues with real part > 1 */
        ga_mat4 zn = ga__mat4_lu_solve(&f, mat4_of(z));
        memcpy(z, zn.m, sizeof z);
        memcpy(tk, r, sizeof r);
    }
    /* Z's blocks above the block diagonal are T_k's own (I has none
     * there), as the square-root recurrence gave them: carried through the
     * solves above they gather the rounding of each. The diagonal blocks keep the carried
     * form, whose small parts subtraction would lose. */
    for (int b = 0; b < nb; b++)
        for (int b2 = b + 1; b2 < nb; b2++)
            for (int u = 0; u < bz[b]; u++)
                for (int v = 0; v < bz[b2]; v++) z[bs[b] + u][bs[b2] + v] = tk[bs[b] + u][bs[b2] + v];
    *zout = mat4_of(z);
    *kout = k;
    return GA_OK;
}

/* The diagonal blocks of log T exactly from T's own (Al-Mohy & Higham
 * 2012, sec. 5: recomputing them removes the error of the roots and of
 * the Pade step where it matters most): log t_ii, or for a complex pair
 * a +- iw, log|.| I + (arg/w) N with arg = atan2(w, a) in (0, pi). The
 * superdiagonal entry between two adjacent real eigenvalues is t_ij
 * times their divided difference. */
static void logm_fix_blocks(ga_mat4 *l, double t[4][4], double lam1, int shifted, const int *bs,
                            const int *bz, int nb)
{
    for (int b = 0; b < nb; b++) {
        int p = bs[b];
        if (bz[b] == 1) {
            double x = lam1 + t[p][p], lx = shifted ? log1p(t[p][p]) : log(x);
            M(*l, p, p) = lx;
            if (b + 1 < nb && bz[b + 1] == 1) {
                double y = lam1 + t[p + 1][p + 1], ly = shifted ? log1p(t[p + 1][p + 1]) : log(y);
                M(*l, p, p + 1) = log_divdiff(t[p][p + 1], x, y, lx, ly, t[p + 1][p + 1] - t[p][p]);
            }
        } else {
            double aa, w, nm[2][2];
            blk2_parts(t, p, &aa, &w, nm);
            double re = lam1 + aa, lr = shifted ? log_abs(aa, w) : log(hypot(re, w));
            double c = w > 0.0 ? atan2(w, re) / w : 1.0 / re;
            for (int u = 0; u < 2; u++)
                for (int v = 0; v < 2; v++) M(*l, p + u, p + v) = (u == v ? lr : 0.0) + c * nm[u][v];
        }
    }
}

ga_status ga_mat4_logm(ga_mat4 a, ga_mat4 *out)
{
    if (!out)
        return GA_ERR_ARG;
    if (!ga__mat4_isfinite(&a))
        return GA_ERR_NOTFINITE;
    ga__mat4_lu f;
    if (ga__mat4_lu_factor(a, &f) != GA_OK) {
        /* numerically singular. A negative determinant (the LU's, run to
         * the end) is an odd number of negative real eigenvalues (a complex
         * pair gives |l|^2 > 0): no real logarithm at all, GA_ERR_DOMAIN, as
         * for a well-conditioned A below; only det >= 0 is GA_ERR_SINGULAR
         * (an ill-conditioned A with a negative eigenvalue can fail the
         * pivot test before its Schur form is seen) */
        return lu4_det_sign(a) < 0 ? GA_ERR_DOMAIN : GA_ERR_SINGULAR;
    }

    /* The real Schur form A = Q T Q^T (Al-Mohy & Higham 2012, Alg. 4.1 works
     * on the Schur factor; real arithmetic as in Al-Mohy, Higham & Relton
     * 2013). A homogeneous A = [B t; 0 1] is already block triangular: only
     * B is reduced, B = Q3 T3 Q3^T, and T = [T3 Q3^T t; 0 1], Q = diag(Q3, 1).
     * The form is first computed of A - I (same Q, T - I): its backward
     * error is relative to ||A - I||, so a motion near the identity (a
     * rotation of 1e-12 rad) keeps relative accuracy in its log, which a
     * Schur form of A itself (error eps ||A||, absolute) would not. That
     * shift loses the eigenvalues near 0 instead (1e-100 - 1 rounds to -1;
     * an eigenvalue 1e-4 keeps only 12 digits), so when one has modulus
     * below 1/2 the form is recomputed of A itself, whose error is then no
     * larger (||A|| <= 3 ||A - I|| once rho(A - I) >= 1/2). t holds
     * T - sig I: sig = 1 (shifted), 0, or (a fallback) the mean of the
     * diagonal. */
    double t[4][4], qm[4][4];
    int h = M(a, 3, 0) == 0.0 && M(a, 3, 1) == 0.0 && M(a, 3, 2) == 0.0 && M(a, 3, 3) == 1.0;
    /* A rigid motion, orthonormal to rounding (GA_MAT4_LOGM_RIGID_TOL),
     * turning by more than pi/2: Eberly's closed form (ga_se3_log). Its
     * result is the exact log of a rigid motion within that rounding of a,
     * so it is as backward stable as the general method, and it keeps full
     * accuracy up to the half turn, where the general log of a nearly
     * orthogonal matrix is conditioned like 1/(pi - th) (a complex pair
     * near -1). At th = pi exactly (a skew part of 0) there is no principal
     * log: GA_ERR_DOMAIN. */
    if (h && 0.5 * (M(a, 0, 0) + M(a, 1, 1) + M(a, 2, 2) - 1.0) < 0.0 &&
        ga__se3_check(&a, GA_MAT4_LOGM_RIGID_TOL) == GA_OK) {
        if (M(a, 2, 1) == M(a, 1, 2) && M(a, 0, 2) == M(a, 2, 0) && M(a, 1, 0) == M(a, 0, 1))
            return GA_ERR_DOMAIN;
        ga_twist xi = ga__se3_log_core(&a);
        /* v = V^{-1} t overflows for a translation near DBL_MAX, as in
           ga_se3_log */
        ga_mat4 l = ga_twist_hat(xi);
        if (!ga__mat4_isfinite(&l))
            return GA_ERR_DOMAIN;
        *out = l;
        return GA_OK;
    }
    int n = h ? 3 : 4;
    double sig; /* t holds T - sig I */
    if (logm_schur(&a, n, t, qm, &sig) != GA_OK)
        return logm_denman_beavers(a, h, out);
    /* Q and T with less of the QR's rounding, which log(T) would carry */
    ga__schur_refine(&a, n, sig, t, qm);
    const int shifted = sig == 1.0;
    if (h)
        for (int i = 0; i < 3; i++)
            t[i][3] = qm[0][i] * M(a, 0, 3) + qm[1][i] * M(a, 1, 3) + qm[2][i] * M(a, 2, 3);
    /* the eigenvalue 1 of A's last row when A is homogeneous, less sig */
    if (h)
        t[3][3] = 1.0 - sig;

    const double lam1 = sig;
    int bs[4], bz[4], nb;
    int st = logm_blocks(t, lam1, bs, bz, &nb);
    if (st != GA_OK)
        return st;
    ga_mat4 zm, l;
    int k;
    if (logm_roots(t, lam1, bs, bz, nb, &zm, &k) != GA_OK || logm_pade8(&zm, &l) != GA_OK)
        return GA_ERR_DOMAIN;
    ga__mat4_scale2(&l, k);
    logm_fix_blocks(&l, t, lam1, shifted, bs, bz, nb);
    if (h) /* the last row of log [B t; 0 1] is 0, exactly */
        M(l, 3, 0) = M(l, 3, 1) = M(l, 3, 2) = M(l, 3, 3) = 0.0;

    /* log A = Q log(T) Q^T */
    ga_mat4 q = mat4_of(qm), qt;
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) M(qt, i, j) = qm[j][i];
    l = ga_mat4_mul(ga_mat4_mul(q, l), qt);
    if (h)
        M(l, 3, 0) = M(l, 3, 1) = M(l, 3, 2) = M(l, 3, 3) = 0.0;
    if (!ga__mat4_isfinite(&l))
        return GA_ERR_DOMAIN;
    *out = l;
    return GA_OK;
}
