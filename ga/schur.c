/* ga/schur.c: the real Schur form of a 3x3 or 4x4 matrix (Householder
 * reduction to Hessenberg form, Francis double-shift QR), as ga_mat4_logm
 * uses it (ga/internal/schur.h). */
#include <garotor/mat4.h>

#include <float.h>
#include <math.h>
#include <string.h>

#include "internal/eft.h"
#include "internal/mat4.h"
#include "internal/schur.h"

#define M GA__M

/* t <- P t P and q <- q P for the reflector P = I - beta v v^T acting on
 * rows and columns k..k+len-1 (t's leading n x n block) */
static void refl_apply(double t[4][4], double q[4][4], int n, int k, int len, const double v[3], double beta)
{
    for (int j = 0; j < n; j++) { /* rows k..k+len-1, from the left */
        double w = 0.0;
        for (int i = 0; i < len; i++) w += v[i] * t[k + i][j];
        w *= beta;
        for (int i = 0; i < len; i++) t[k + i][j] -= w * v[i];
    }
    for (int r = 0; r < n; r++) { /* columns k..k+len-1, from the right */
        double w = 0.0, wq = 0.0;
        for (int i = 0; i < len; i++) {
            w += t[r][k + i] * v[i];
            wq += q[r][k + i] * v[i];
        }
        w *= beta;
        wq *= beta;
        for (int i = 0; i < len; i++) {
            t[r][k + i] -= w * v[i];
            q[r][k + i] -= wq * v[i];
        }
    }
}

/* The reflector I - beta v v^T that maps x (len 2 or 3) to a multiple of e_1. */
static double refl_make(const double *x, int len, double v[3])
{
    double nrm = 0.0, mx = 0.0;
    for (int i = 0; i < len; i++) mx = fmax(mx, fabs(x[i]));
    if (!(mx > 0.0))
        return 0.0;
    for (int i = 0; i < len; i++) {
        v[i] = x[i] / mx;
        nrm += v[i] * v[i];
    }
    nrm = sqrt(nrm);
    v[0] += copysign(nrm, v[0]);
    /* v^T v to within one rounding (Dekker's exact squares and a
     * compensated sum), so that beta v^T v = 2 to about u and
     * I - beta v v^T is orthogonal to about 2u. Rounded plainly, v^T v is
     * off by several u, the Schur vectors of a few dozen reflectors lose
     * that many times more orthogonality, and Q log(T) Q^T carries it into
     * the log. */
    double hi = 0.0, lo = 0.0;
    for (int i = 0; i < len; i++) {
        double c = 134217729.0 * v[i], vh = c - (c - v[i]), vl = v[i] - vh;    /* v = vh + vl, 26 bits each */
        double p = v[i] * v[i], e = ((vh * vh - p) + 2.0 * vh * vl) + vl * vl; /* p + e = v_i^2 */
        double sum = hi + p, bv = sum - hi, err = (hi - (sum - bv)) + (p - bv); /* hi + p = sum + err */
        hi = sum;
        lo += err + e;
    }
    return 2.0 / (hi + lo);
}

/* Is the subdiagonal t[l][l-1] negligible? The test of Ahues & Tisseur
 * (1997), as LAPACK's dlahqr uses it: beyond |t21| <= eps (|t11| + |t22|) it
 * asks that setting t21 to 0 perturb the eigenvalues of the 2x2 window only
 * by rounding. So [-1 -s; s -1] with s = 1.2e-16 (a rotation one rounding
 * short of a half turn) stays a complex pair -1 +- is, whose log exists,
 * instead of being split into the eigenvalues -1, -1, which have none. */
static int schur_negligible(double t[4][4], int l)
{
    double h21 = fabs(t[l][l - 1]);
    if (h21 <= DBL_MIN)
        return 1;
    if (!(h21 <= DBL_EPSILON * (fabs(t[l - 1][l - 1]) + fabs(t[l][l]))))
        return 0;
    double h12 = fabs(t[l - 1][l]), d = fabs(t[l - 1][l - 1] - t[l][l]), h22 = fabs(t[l][l]);
    double ab = fmax(h21, h12), ba = fmin(h21, h12), aa = fmax(h22, d), bb = fmin(h22, d), s = aa + ab;
    return ba * (ab / s) <= fmax(DBL_MIN, DBL_EPSILON * (bb * (aa / s)));
}

/* The real Schur form of the leading n x n block of t (n = 3 or 4): t is
 * overwritten by Q^T t Q, upper quasi-triangular with 1x1 blocks (real
 * eigenvalues) and 2x2 blocks (complex pairs), and q by q Q. Householder
 * reduction to Hessenberg form, then Francis double-shift QR steps with
 * deflation (Golub & Van Loan, Matrix Computations, Alg. 7.4.2 and 7.5.1).
 * A 2x2 block with real eigenvalues is split by one rotation whose first
 * column is an eigenvector. GA_ERR_DOMAIN if QR does not converge (a guard:
 * 300 steps per deflation, LAPACK dlahqr's 30 max(10, n); a nearly
 * defective cluster, e^X - I for a nilpotent X, needed more than 30). */
static int schur_real(double t[4][4], double q[4][4], int n)
{
    for (int k = 0; k + 2 < n; k++) { /* Hessenberg */
        double x[3] = {t[k + 1][k], t[k + 2][k], k + 3 < n ? t[k + 3][k] : 0.0}, v[3];
        int len = n - k - 1;
        double beta = refl_make(x, len, v);
        if (beta > 0.0)
            refl_apply(t, q, n, k + 1, len, v, beta);
        for (int i = k + 2; i < n; i++) t[i][k] = 0.0;
    }
    /* After 10 steps without deflation, a subdiagonal entry within
     * eps ||T||_max is taken as 0 too: a normwise backward-stable perturbation.
     * A strongly graded window (an entry 1 beside entries near 1e-298, whose
     * eigenvalues near 1e-149 have squares that underflow) otherwise gives a
     * shift column of 0 and no progress. */
    double tmax = 0.0;
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++) tmax = fmax(tmax, fabs(t[i][j]));
    int hi = n - 1, iter = 0;
    while (hi > 0) {
        int l = hi;
        for (; l > 0; l--)
            if (schur_negligible(t, l) || (iter >= 10 && fabs(t[l][l - 1]) <= DBL_EPSILON * tmax)) {
                t[l][l - 1] = 0.0;
                break;
            }
        if (l == hi) {
            hi--;
            iter = 0;
            continue;
        }
        if (l == hi - 1) { /* a 2x2 block: keep a complex pair, split a real one */
            int p = l;
            double a = t[p][p], b = t[p][p + 1], c = t[p + 1][p], d = t[p + 1][p + 1];
            double hd = 0.5 * (a - d), disc = hd * hd + b * c;
            if (disc >= 0.0) {
                double v0 = hd + copysign(sqrt(disc), hd), v1 = c, r = hypot(v0, v1);
                double x[2] = {v0 / r, v1 / r}, v[3];
                /* the reflector with first column (x0, x1) up to sign */
                double beta = refl_make(x, 2, v);
                if (beta > 0.0)
                    refl_apply(t, q, n, p, 2, v, beta);
                t[p + 1][p] = 0.0;
            }
            hi -= 2;
            iter = 0;
            continue;
        }
        if (++iter > 300) /* no convergence: the guard above */
            return GA_ERR_DOMAIN;
        /* The first column of (H - s1 I)(H - s2 I), s1 + s2 = s, s1 s2 = p,
         * from the active window divided by its largest entry g: only its
         * direction matters, and unscaled, a window of entries near 1e-298
         * (eigenvalues of A - I that small) would square to 0 and the
         * iteration would stall. */
        int m = hi;
        double g = 0.0;
        for (int i = l; i <= hi; i++)
            for (int j = i > l ? i - 1 : l; j <= hi; j++) g = fmax(g, fabs(t[i][j]));
        double ig = 1.0 / g; /* g > 0: t[l+1][l] was not negligible */
        double w00 = t[l][l] * ig, w01 = t[l][l + 1] * ig, w10 = t[l + 1][l] * ig, w11 = t[l + 1][l + 1] * ig,
               w21 = t[l + 2][l + 1] * ig, a = t[m - 1][m - 1] * ig, b = t[m - 1][m] * ig,
               c = t[m][m - 1] * ig, d = t[m][m] * ig;
        /* with the shifts the eigenvalues of [a b; c d], the column in
         * differences, (w00 - a)(w00 - d) - bc + w01 w10 and
         * w10 ((w00 - a) + (w11 - d)), which do not cancel when the
         * eigenvalues are clustered (EISPACK hqr): the expanded
         * w00^2 - (a + d) w00 + ad - bc + w01 w10 would lose the relative
         * accuracy of the step for a near-multiple of I (1e-4 I plus 1e-9
         * entries did not converge in 30 steps) */
        double x[3] = {(w00 - a) * (w00 - d) - b * c + w01 * w10, w10 * ((w00 - a) + (w11 - d)), w10 * w21};
        if (iter % 10 == 0) { /* an exceptional shift breaks a cycle */
            double e = fabs(c) + fabs(t[m - 1][m - 2] * ig), s = 1.5 * e, p = e * e;
            x[0] = w00 * w00 + w01 * w10 - s * w00 + p;
            x[1] = w10 * (w00 + w11 - s);
        }
        for (int k = l; k < hi - 1; k++) {
            double v[3], beta = refl_make(x, 3, v);
            if (beta > 0.0)
                refl_apply(t, q, n, k, 3, v, beta);
            if (k > l)
                t[k + 1][k - 1] = t[k + 2][k - 1] = 0.0;
            x[0] = t[k + 1][k];
            x[1] = t[k + 2][k];
            x[2] = k + 3 <= hi ? t[k + 3][k] : 0.0;
        }
        double v[3], beta = refl_make(x, 2, v);
        if (beta > 0.0)
            refl_apply(t, q, n, hi - 1, 2, v, beta);
        if (hi - 2 >= l)
            t[hi][hi - 2] = 0.0;
    }
    return GA_OK;
}

/* The real Schur form of A - sig I (its leading n x n block; t and q as for
 * schur_real, t then holding T - sig I), scaled by a power of 2 so that QR's
 * products neither underflow nor overflow: a rotation of 1e-300 rad has
 * A - I of 1e-300. Not an upper triangular t, which is its own Schur form:
 * scaling down rounds subnormal entries (a diagonal 2e-322 beside 2 would
 * lose a bit). */
int ga__schur_shifted(const ga_mat4 *a, int n, double sig, double t[4][4], double qm[4][4])
{
    memcpy(t, a->m, 16 * sizeof(double));
    memset(qm, 0, 16 * sizeof(double));
    for (int i = 0; i < 4; i++) {
        qm[i][i] = 1.0;
        t[i][i] -= sig;
    }
    int es = 0, tri = 1;
    double mx = 0.0;
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++) {
            mx = fmax(mx, fabs(t[i][j]));
            tri &= i <= j || t[i][j] == 0.0;
        }
    if (mx > 0.0 && !tri) {
        es = ilogb(mx);
        for (int i = 0; i < n; i++)
            for (int j = 0; j < n; j++) t[i][j] = ldexp(t[i][j], -es);
    }
    if (schur_real(t, qm, n) != GA_OK)
        return GA_ERR_DOMAIN;
    for (int i = 0; es && i < n; i++)
        for (int j = 0; j < n; j++) t[i][j] = ldexp(t[i][j], es);
    return GA_OK;
}

/* Q brought back to orthogonal by one Newton-Schulz step
 * Q <- Q - Q (Q^T Q - I) / 2, and T recomputed from it as
 * Q^T (A - sig I) Q on and above the block diagonal. The rounding of a
 * few dozen reflector updates leaves Q^T Q - I and the residual
 * Q T Q^T - (A - sig I) at many u, which Q log(T) Q^T carries into the
 * log; after this step both are a few u. The recomputed T is kept only
 * where it keeps every
 * real eigenvalue's sign and every 2x2 block complex, so that the
 * domain decision of ga_mat4_logm sees the QR's eigenvalue structure. The
 * products (A - sig I) Q and Q^T ((A - sig I) Q) are summed by dot2,
 * the first kept as an unevaluated sum bq + bql: T then carries one
 * rounding per entry instead of one per product and addition. */
void ga__schur_refine(const ga_mat4 *a, int n, double sig, double t[4][4], double qm[4][4])
{
    double qe[4][4], qn[4][4], bq[4][4], bql[4][4], tn[4][4];
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++) {
            double acc = 0.0;
            for (int r = 0; r < n; r++) acc += qm[r][i] * qm[r][j];
            qe[i][j] = acc - (i == j);
        }
    memcpy(qn, qm, sizeof qn);
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++) {
            double acc = 0.0;
            for (int r = 0; r < n; r++) acc += qm[i][r] * qe[r][j];
            qn[i][j] = qm[i][j] - 0.5 * acc;
        }
    /* (A - sig I) Q, scaled up by a power of 2 when small (tiny entries
     * stay normal; undone below, exactly); never down, which would
     * round a subnormal entry beside large ones. Large entries whose products overflow
     * keep the QR's T (keep below). */
    double bm[4][4], bmax = 0.0;
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++) {
            bm[i][j] = M(*a, i, j) - (i == j ? sig : 0.0);
            bmax = fmax(bmax, fabs(bm[i][j]));
        }
    int es = bmax > 0.0 && bmax < 1.0 ? ilogb(bmax) : 0;
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++) {
            ga__eft_dot2 acc = {0.0, 0.0};
            for (int r = 0; r < n; r++) ga__eft_dot2_add(&acc, ldexp(bm[i][r], -es), qn[r][j]);
            bq[i][j] = acc.s + acc.c;
            bql[i][j] = acc.c - (bq[i][j] - acc.s);
        }
    memcpy(tn, t, sizeof tn);
    int keep = 1;
    for (int i = 0; i < n; i++)
        for (int j = i > 0 && t[i][i - 1] != 0.0 ? i - 1 : i; j < n; j++) {
            ga__eft_dot2 acc = {0.0, 0.0};
            for (int r = 0; r < n; r++) {
                ga__eft_dot2_add(&acc, qn[r][i], bq[r][j]);
                acc.c += qn[r][i] * bql[r][j];
            }
            tn[i][j] = ldexp(acc.s + acc.c, es);
        }
    for (int i = 0; i < n && keep; i++) {
        if (i + 1 < n && t[i + 1][i] != 0.0) {
            double h0 = 0.5 * (tn[i][i] - tn[i + 1][i + 1]);
            keep = tn[i + 1][i] != 0.0 && h0 * h0 + tn[i][i + 1] * tn[i + 1][i] < 0.0;
            i++;
        } else
            keep = (sig + tn[i][i] > 0.0) == (sig + t[i][i] > 0.0) && (sig + tn[i][i] != 0.0);
    }
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++) keep &= isfinite(tn[i][j]);
    if (keep) {
        memcpy(t, tn, sizeof tn);
        memcpy(qm, qn, sizeof qn);
    }
}
