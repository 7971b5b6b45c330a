/* ga/expm.c: the general 4x4 matrix exponential ga_mat4_expm, by scaling and
 * squaring with Pade approximants (Al-Mohy & Higham, "A new scaling and
 * squaring algorithm for the matrix exponential", 2009). */
#include <garotor/mat4.h>

#include <float.h>
#include <math.h>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "internal/eft.h"
#include "internal/mat4.h"

#define M GA__M

/* The product a*b of two matrices whose last rows are (0 0 0 a33) and
 * (0 0 0 b33): a homogeneous generator [B v; 0 0], I, and every polynomial
 * in them, which the product is again:
 *   [Ba va; 0 a33] [Bb vb; 0 b33] = [Ba Bb, Ba vb + b33 va; 0 a33 b33],
 * 40 multiplications instead of 64. */
static inline ga_mat4 mat4_mul_ut(const ga_mat4 *a, const ga_mat4 *b)
{
    /* row i of c as a combination of b's rows:
     * c_ij = (a_i0 b_0j + a_i1 b_1j) + a_i2 b_2j, and c_i3 plus a_i3 b_33 */
    ga_mat4 c;
#if defined(__SSE2__)
    /* the same operations in the same order, two entries per instruction
     * (gcc's own vectorisation of the loop below shuffles more than it
     * computes once inlined into ga_mat4_expm); adding -0.0 is exact */
    const double *bm = b->m;
    __m128d b0l = _mm_loadu_pd(bm), b0h = _mm_loadu_pd(bm + 2), b1l = _mm_loadu_pd(bm + 4),
            b1h = _mm_loadu_pd(bm + 6), b2l = _mm_loadu_pd(bm + 8), b2h = _mm_loadu_pd(bm + 10);
    for (int i = 0; i < 3; i++) {
        __m128d x0 = _mm_set1_pd(M(*a, i, 0)), x1 = _mm_set1_pd(M(*a, i, 1)), x2 = _mm_set1_pd(M(*a, i, 2));
        __m128d lo = _mm_add_pd(_mm_add_pd(_mm_mul_pd(x0, b0l), _mm_mul_pd(x1, b1l)), _mm_mul_pd(x2, b2l));
        __m128d hi = _mm_add_pd(_mm_add_pd(_mm_mul_pd(x0, b0h), _mm_mul_pd(x1, b1h)), _mm_mul_pd(x2, b2h));
        hi = _mm_add_pd(hi, _mm_set_pd(M(*a, i, 3) * M(*b, 3, 3), -0.0));
        _mm_storeu_pd(&M(c, i, 0), lo);
        _mm_storeu_pd(&M(c, i, 2), hi);
    }
#else
    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 4; j++)
            M(c, i, j) = M(*a, i, 0) * M(*b, 0, j) + M(*a, i, 1) * M(*b, 1, j) + M(*a, i, 2) * M(*b, 2, j);
        M(c, i, 3) += M(*a, i, 3) * M(*b, 3, 3);
    }
#endif
    M(c, 3, 0) = M(c, 3, 1) = M(c, 3, 2) = 0.0;
    M(c, 3, 3) = M(*a, 3, 3) * M(*b, 3, 3);
    return c;
}

static inline ga_mat4 mat4_mul_any(const ga_mat4 *a, const ga_mat4 *b, int h)
{
    return h ? mat4_mul_ut(a, b) : ga_mat4_mul(*a, *b);
}

/* ||a||_1 of a finite a (no NaN to propagate), the column sums as one vector
 * expression */
static double norm1_finite(const ga_mat4 *a)
{
    double s[4];
    for (int j = 0; j < 4; j++)
        s[j] = fabs(M(*a, 0, j)) + fabs(M(*a, 1, j)) + fabs(M(*a, 2, j)) + fabs(M(*a, 3, j));
    double s01 = s[0] > s[1] ? s[0] : s[1], s23 = s[2] > s[3] ? s[2] : s[3];
    return s01 > s23 ? s01 : s23;
}

/* ell(A, m) of Al-Mohy & Higham 2009 (eq. 5.3 and Alg. 5.1): the number of
 * extra squarings that bring the leading backward-error term
 * |c_{2m+1}| || |A|^{2m+1} ||_1 / ||A||_1 down to u = 2^-53, with
 * c_{2m+1} = (m!)^2 / ((2m)! (2m+1)!). || |A|^k ||_1 = max of e^T |A|^k
 * exactly (the paper estimates it), the vector rescaled by 2^-+500 (exact)
 * whenever it leaves [2^-500, 2^500], so that it can neither overflow nor
 * lose its largest entry to underflow. */
static int expm_ell(const ga_mat4 *a, double norm, int m, double log2c)
{
    if (!(norm > 0.0))
        return 0;
    double ab[16], v[4] = {1.0, 1.0, 1.0, 1.0}, mx = 1.0;
    int e = 0;
    for (int i = 0; i < 16; i++) ab[i] = fabs(a->m[i]);
    for (int k = 0; k < 2 * m + 1; k++) {
        double w[4];
        mx = 0.0;
        for (int j = 0; j < 4; j++) {
            w[j] = v[0] * ab[j] + v[1] * ab[4 + j] + v[2] * ab[8 + j] + v[3] * ab[12 + j];
            mx = w[j] > mx ? w[j] : mx;
        }
        if (!(mx > 0.0))
            return 0; /* |A| nilpotent: no truncation error at all */
        double f = mx > 0x1p500 ? 0x1p-500 : mx < 0x1p-500 ? 0x1p500 : 1.0;
        e += f > 1.0 ? -500 : f < 1.0 ? 500 : 0;
        mx *= f;
        for (int j = 0; j < 4; j++) v[j] = w[j] * f;
    }
    double l = ceil((log2c + log2(mx) + e - log2(norm) + 53.0) / (2 * m));
    return l > 0.0 ? (l < 64.0 ? (int)l : 64) : 0;
}

/* X = c D^{-1} U for D = V - U, when the last rows are D: (0 0 0 b_0) and
 * U: 0 (a homogeneous generator); c = 2 gives X = r_m - I, and U = (V + U
 * with its last column replaced by 2U's), c = 1 the top rows of r_m. D is block triangular, [D3 d; 0 b_0],
 * and D [X3 x; 0 0] = U gives D3 [X3 x] = [U3 u]: one 3x3 elimination with partial pivoting, four right-hand
 * sides; d and b_0 play no part. 0 if a pivot is at most 4 eps max |D3_ij| (a guard: the caller then takes
 * the 4x4 LU with its equilibrated retry). */
static int expm_solve3(const ga_mat4 *d, const ga_mat4 *u, double c, ga_mat4 *x)
{
    /* rows [D3_i | U_i], 7 entries each, permuted through pointers: the
     * pivot choices are selections, not branches or row copies */
    double rows[3][7], big = 0.0;
    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 3; j++) {
            rows[i][j] = M(*d, i, j);
            big = fabs(rows[i][j]) > big ? fabs(rows[i][j]) : big;
        }
        for (int j = 0; j < 4; j++) rows[i][3 + j] = M(*u, i, j);
    }
    double *r0 = rows[0], *r1 = rows[1], *r2 = rows[2], *t;
    /* column 0: the largest of three to the top, then of two */
    t = fabs(r1[0]) > fabs(r0[0]) ? r1 : r0;
    r1 = t == r1 ? r0 : r1;
    r0 = t;
    t = fabs(r2[0]) > fabs(r0[0]) ? r2 : r0;
    r2 = t == r2 ? r0 : r2;
    r0 = t;
    double tol = 4.0 * DBL_EPSILON * big;
    if (!(fabs(r0[0]) > tol))
        return 0;
    double f1 = r1[0] / r0[0], f2 = r2[0] / r0[0];
    for (int j = 1; j < 7; j++) {
        r1[j] -= f1 * r0[j];
        r2[j] -= f2 * r0[j];
    }
    t = fabs(r2[1]) > fabs(r1[1]) ? r2 : r1;
    r2 = t == r2 ? r1 : r2;
    r1 = t;
    if (!(fabs(r1[1]) > tol))
        return 0;
    double f = r2[1] / r1[1];
    for (int j = 2; j < 7; j++) r2[j] -= f * r1[j];
    if (!(fabs(r2[2]) > tol))
        return 0;
    for (int j = 0; j < 4; j++) {
        double x2 = r2[3 + j] / r2[2];
        double x1 = (r1[3 + j] - r1[2] * x2) / r1[1];
        double x0 = (r0[3 + j] - r0[1] * x1 - r0[2] * x2) / r0[0];
        M(*x, 0, j) = c * x0;
        M(*x, 1, j) = c * x1;
        M(*x, 2, j) = c * x2;
        M(*x, 3, j) = 0.0;
    }
    return 1;
}

/* The diagonal blocks of A when A is upper quasi-triangular with blocks of
 * size 1 and 2 (every entry below them 0): their starts and sizes, and the
 * count; 0 if A is not of that form. */
static int qt_blocks(const ga_mat4 *a, int bs[4], int bz[4])
{
    int nb = 0;
    for (int p = 0; p < 4;) {
        int z = (p < 3 && M(*a, p + 1, p) != 0.0) ? 2 : 1;
        for (int j = p; j < p + z; j++)
            for (int i = p + z; i < 4; i++)
                if (M(*a, i, j) != 0.0)
                    return 0;
        bs[nb] = p;
        bz[nb++] = z;
        p += z;
    }
    return nb;
}

/* sinh(x)/x */
static double sinch(double x) { return fabs(x) < 0x1p-26 ? 1.0 : sinh(x) / x; }

/* The diagonal blocks of exp(2^k A), and the superdiagonal entry between two
 * adjacent 1x1 blocks, written into x exactly (to rounding) instead of as
 * the squarings left them (Al-Mohy & Higham 2009, sec. 2 and Code Fragment
 * 2.1, which scipy applies to triangular input; the 2x2 blocks by the closed
 * form e^m (cosh mu I + sinch mu N), N = B - m I, mu^2 = -det N, the form
 * scipy uses for 2x2 input). plain: x holds exp; else exp - I. */
static void expm_fix_blocks(ga_mat4 *x, const ga_mat4 *a, int k, int plain, const int *bs, const int *bz,
                            int nb)
{
    for (int b = 0; b < nb; b++) {
        int p = bs[b];
        if (bz[b] == 1) {
            double l = ldexp(M(*a, p, p), k);
            M(*x, p, p) = plain ? exp(l) : expm1(l);
            if (b + 1 < nb && bz[b + 1] == 1) {
                double l2 = ldexp(M(*a, p + 1, p + 1), k), t = ldexp(M(*a, p, p + 1), k);
                double f = t * exp(0.5 * (l + l2)) * sinch(0.5 * (l2 - l));
                if (isfinite(f))
                    M(*x, p, p + 1) = f;
            }
        } else {
            double b11 = ldexp(M(*a, p, p), k), b12 = ldexp(M(*a, p, p + 1), k),
                   b21 = ldexp(M(*a, p + 1, p), k), b22 = ldexp(M(*a, p + 1, p + 1), k);
            /* m = (b11 + b22)/2 + dm, hd = (b11 - b22)/2 + dhd and
             * q = hd^2 + b12 b21 + dq with their rounding errors carried
             * (two-sums, fma), and mu = sqrt(q) + dmu: each error enters
             * the result once, to first order, instead of being amplified */
            double m, dm, hd, dhd;
            ga__eft_two_sum(b11, b22, &m, &dm);
            ga__eft_two_sum(b11, -b22, &hd, &dhd);
            m *= 0.5;
            dm *= 0.5;
            hd *= 0.5;
            dhd *= 0.5;
            double p1 = hd * hd, p2 = b12 * b21, q, dq;
            ga__eft_two_sum(p1, p2, &q, &dq);
            dq += fma(hd, hd, -p1) + fma(b12, b21, -p2) + 2.0 * hd * dhd;
            double c, sc, cm1;
            if (q >= 0.0) {
                double mu = sqrt(q), h = sinh(0.5 * mu),
                       dmu = mu > 0.0 ? (fma(-mu, mu, q) + dq) / (2.0 * mu) : 0.0;
                double sh = sinh(mu);
                c = cosh(mu) + sh * dmu;
                cm1 = 2.0 * h * h + sh * dmu; /* cosh mu - 1 */
                sc = sinch(mu);
                if (mu >= 0x1p-26)
                    sc += (c - sc) / mu * dmu;
            } else {
                double nu = sqrt(-q), h = sin(0.5 * nu), dnu = (fma(-nu, nu, -q) - dq) / (2.0 * nu);
                double sn = sin(nu);
                c = cos(nu) - sn * dnu;
                cm1 = -2.0 * h * h - sn * dnu;
                sc = nu < 0x1p-26 ? 1.0 : sn / nu;
                if (nu >= 0x1p-26)
                    sc += (c - sc) / nu * dnu;
            }
            double em = exp(m), d = plain ? (em + em * dm) * c : (expm1(m) + em * dm) * c + cm1,
                   o = (em + em * dm) * sc;
            double e[2][2] = {{fma(o, hd, d) + o * dhd, o * b12}, {o * b21, fma(-o, hd, d) - o * dhd}};
            if (isfinite(e[0][0]) && isfinite(e[0][1]) && isfinite(e[1][0]) && isfinite(e[1][1]))
                for (int u = 0; u < 2; u++)
                    for (int v = 0; v < 2; v++) M(*x, p + u, p + v) = e[u][v];
        }
    }
}

/* ---- the Pade approximants and their bounds ------------------------------ */

/* theta_m: the largest alpha for which r_m(A) = e^(A + E) with
 * ||E|| <= 2^-53 ||A|| (Higham 2005, Table 2.3) for m <= 9, and
 * theta_13 = 4.25 of Al-Mohy & Higham 2009, Table 3.1 (and scipy), not
 * Higham 2005's 5.37: near 5.37 the rounding in evaluating r_13 and
 * solving with q_13 dominates the truncation error. b: the coefficients of the Pade numerator
 * p_m(x) = sum b_j x^j, scaled to integers, with q_m(x) = p_m(-x).
 * log2c: log2 of c_{2m+1} = (m!)^2 / ((2m)! (2m+1)!). */
static const double theta[5] = {1.495585217958292e-2, 2.539398330063230e-1, 9.504178996162932e-1,
                                2.097847961257068e0, 4.25};
static const double log2c[5] = {-16.621136113, -33.227772657, -51.994974307, -72.324718099, -116.447004252};
static const int degree[5] = {3, 5, 7, 9, 13};
/* theta_m^4 and theta_m^6: for m = 3, 5 eta = max(d4, d6); for m = 7, 9
 * eta_3 = max(d6, d8) with d8 <= d4 (below). ell_free: ||A||_1 below
 * which ell(A, m) is 0 whatever |A| is (|c_{2m+1}| ||A||_1^(2m) <= u).
 * t13_k: theta_13^k for k = 4, 6, 10. */
static const double theta4[4] = {5.003163045600666e-08, 4.158371815587934e-03, 0.8159403826875232,
                                 19.368502336532284};
static const double theta6[4] = {1.1190950742656221e-11, 2.6815443116884287e-04, 0.7370342020997932,
                                 85.24012158171844};
static const double ell_free[5] = {0.014955873861517137, 0.2539783216046672, 0.9514583772676373,
                                   2.104672049828496, 5.427430678788747};
static const double t13_4 = 326.25390625, t13_6 = 5892.961181640625, t13_10 = 1922601.6048898697;
static const double b3[] = {120, 60, 12, 1};
static const double b5[] = {30240, 15120, 3360, 420, 30, 1};
static const double b7[] = {17297280, 8648640, 1995840, 277200, 25200, 1512, 56, 1};
static const double b9[] = {17643225600., 8821612800., 2075673600., 302702400., 30270240,
                            2162160,      110880,      3960,        90,         1};
static const double b13[] = {64764752532480000.,
                             32382376266240000.,
                             7771770303897600.,
                             1187353796428800.,
                             129060195264000.,
                             10559470521600.,
                             670442572800.,
                             33522128640.,
                             1323241920.,
                             40840800.,
                             960960,
                             16380,
                             182,
                             1};
static const double *const coef[5] = {b3, b5, b7, b9, b13};

/* The degree m (its index in degree[]) and the extra squarings, added to
 * *s, for A of 1-norm n1 with its powers a2, a4, a6, all four scaled by the
 * squarings (exact powers of 2). */
static int expm_degree(ga_mat4 *a, ga_mat4 *a2, ga_mat4 *a4, ga_mat4 *a6, int h, double n1, int *s)
{
    /* eta <= theta_m is tested as ||A^k|| <= theta_m^k (no roots). d8 and
     * d10 are not computed (two more products): the bounds
     * ||A^8|| <= ||A^4||^2 and ||A^10|| <= ||A^4|| ||A^6|| give d8 <= d4 and
     * d10 <= (||A^4|| ||A^6||)^(1/10), which can only choose more squarings
     * than the paper's estimates, never fewer. ell(A, m) is computed only
     * for m = 9: for m = 3, 5, 7 a candidate with ||A||_1 above ell_free
     * goes on to the next degree instead (its eta test then holds too),
     * because one more matrix product costs less than the 2m + 1 dependent
     * vector products of ell, and a larger m with the same s is as
     * accurate (its backward error is also below u). */
    double n4 = norm1_finite(a4), n6 = norm1_finite(a6);
    int idx = -1;
    for (int c = 0; c < 4 && idx < 0; c++) {
        if (n4 <= theta4[c] && n6 <= theta6[c] &&
            (n1 <= ell_free[c] || (c == 3 && expm_ell(a, n1, degree[c], log2c[c]) == 0)))
            idx = c;
    }
    if (idx < 0) {
        /* eta_5 = min(max(d6, d8), max(d8, d10)) <= theta_13 is first
         * tested without roots or products, with d8 <= d4 and
         * d10 <= (||A^4|| ||A^6||)^(1/10); only when that fails are d8 and
         * d10 computed exactly (||A^4 A^4||, ||A^4 A^6||: the paper's and
         * scipy's s, not one squaring more from the bounds) */
        int s1 = 0;
        if (!(n4 <= t13_4 && (n6 <= t13_6 || n4 * n6 <= t13_10))) {
            ga_mat4 a8 = mat4_mul_any(a4, a4, h), a10 = mat4_mul_any(a4, a6, h);
            double d6 = pow(n6, 1.0 / 6.0), d8 = pow(norm1_finite(&a8), 0.125),
                   d10 = pow(norm1_finite(&a10), 0.1);
            double eta5 = fmin(fmax(d6, d8), fmax(d8, d10));
            s1 = eta5 > theta[4] ? (int)ceil(log2(eta5 / theta[4])) : 0;
        }
        double ns = ldexp(n1, -s1); /* ||2^-s1 A||_1, exactly */
        if (!(ns <= ell_free[4])) {
            ga_mat4 as = *a;
            ga__mat4_scale2(&as, -s1);
            s1 += expm_ell(&as, ns, 13, log2c[4]);
        }
        idx = 4;
        if (s1 > 0) { /* scaled powers: exact powers of 2 */
            ga__mat4_scale2(a, -s1);
            ga__mat4_scale2(a2, -2 * s1);
            ga__mat4_scale2(a4, -4 * s1);
            ga__mat4_scale2(a6, -6 * s1);
        }
        *s += s1;
    }
    return idx;
}

/* r_m = (V - U)^{-1} (V + U), U the odd and V the even part of p_m: U and
 * V of degree[idx] from A and its powers. */
static void expm_pade(int idx, const ga_mat4 *a, const ga_mat4 *a2, const ga_mat4 *a4, const ga_mat4 *a6,
                      int h, ga_mat4 *uout, ga_mat4 *vout)
{
    const double *b = coef[idx];
    int m = degree[idx];
    ga_mat4 id = ga_mat4_identity(), v, u0; /* U = A U0 */
    if (m < 13) {
        /* U0 = sum b_{2k+1} A^{2k}, V = sum b_{2k} A^{2k}, entry by entry in
         * one pass (A^8 only for m = 9; the missing powers are 0 terms) */
        ga_mat4 a8 = ga__mat4_zero();
        if (m == 9)
            a8 = mat4_mul_any(a4, a4, h);
        double bb[10] = {0};
        for (int k = 0; k <= m; k++) bb[k] = b[k];
        for (int i = 0; i < 16; i++) {
            u0.m[i] = bb[1] * id.m[i] + bb[3] * a2->m[i] + bb[5] * a4->m[i] + bb[7] * a6->m[i] +
                      bb[9] * a8.m[i];
            v.m[i] = bb[0] * id.m[i] + bb[2] * a2->m[i] + bb[4] * a4->m[i] + bb[6] * a6->m[i] +
                     bb[8] * a8.m[i];
        }
    } else { /* Higham's m = 13 scheme: 6 matrix products instead of 12 */
        ga_mat4 w = ga__mat4_zero();
        v = ga__mat4_zero();
        u0 = ga__mat4_zero();
        ga__mat4_acc(&w, b[13], a6);
        ga__mat4_acc(&w, b[11], a4);
        ga__mat4_acc(&w, b[9], a2);
        u0 = mat4_mul_any(a6, &w, h);
        ga__mat4_acc(&u0, b[7], a6);
        ga__mat4_acc(&u0, b[5], a4);
        ga__mat4_acc(&u0, b[3], a2);
        ga__mat4_acc(&u0, b[1], &id);
        w = ga__mat4_zero();
        ga__mat4_acc(&w, b[12], a6);
        ga__mat4_acc(&w, b[10], a4);
        ga__mat4_acc(&w, b[8], a2);
        v = mat4_mul_any(a6, &w, h);
        ga__mat4_acc(&v, b[6], a6);
        ga__mat4_acc(&v, b[4], a4);
        ga__mat4_acc(&v, b[2], a2);
        ga__mat4_acc(&v, b[0], &id);
    }
    *uout = mat4_mul_any(a, &u0, h);
    *vout = v;
}

/* X = r_m - I, or r_m itself (*plain), from U and V. GA_ERR_DOMAIN if
 * V - U is singular (a guard). */
static int expm_rm(const ga_mat4 *a, const ga_mat4 *u, const ga_mat4 *v, int h, ga_mat4 *xout, int *plainout)
{
    ga_mat4 den = *v, x;
    ga__mat4_acc(&den, -1.0, u);
    /* X = r_m - I = 2 (V - U)^{-1} U: no cancellation for r_m near I. But
     * for a contracting r_m (a diagonal entry below 3/4, where the squaring
     * below goes plain at once) r_m itself, (V - U)^{-1} (V + U), as scipy
     * computes it: I + X rounds r_m's small entries to eps absolute, and
     * the squarings amplify that. Predicted from the diagonal
     * of 2^-s A (one solve, not two, for most inputs), and checked on X. */
    int plain = a->m[0] < -0.25 || a->m[5] < -0.25 || a->m[10] < -0.25 || a->m[15] < -0.25;
    ga_mat4 rhs = *u;
    double c = 2.0;
    for (int pass = 0; pass < 2; pass++) {
        if (plain) { /* D r = V + U; for h, r = [R t; 0 1] and D3 t = 2 u, t as in X */
            rhs = *v;
            ga__mat4_acc(&rhs, 1.0, u);
            if (h)
                for (int i = 0; i < 3; i++) M(rhs, i, 3) = 2.0 * M(*u, i, 3);
            c = 1.0;
        }
        if (!(h && expm_solve3(&den, &rhs, c, &x))) {
            ga__mat4_lu f;
            /* q_m(A) is well conditioned for alpha <= theta_m (Higham
             * 2005): this failure is a guard, not an expected path. */
            if (ga__mat4_lu_factor(den, &f) != GA_OK)
                return GA_ERR_DOMAIN;
            x = ga__mat4_lu_solve(&f, rhs);
            for (int i = 0; i < 16; i++) x.m[i] *= c;
        }
        if (h) {
            M(x, 3, 0) = M(x, 3, 1) = M(x, 3, 2) = 0.0;
            M(x, 3, 3) = plain ? 1.0 : 0.0;
        }
        if (plain || !(M(x, 0, 0) < -0.25 || M(x, 1, 1) < -0.25 || M(x, 2, 2) < -0.25 || M(x, 3, 3) < -0.25))
            break;
        plain = 1;
    }
    *xout = x;
    *plainout = plain;
    return GA_OK;
}

/* The s squarings of I + X (of X itself when plain): (I + X)^2 = I + (2X + X^2) keeps relative accuracy in X
 * when the result is near I; e.g. a rotation block R = I + O(1e-12) under a translation 1e6 needs 18
 * squarings, and plain squaring would lose the rounding of R's diagonal doubled 18 times (about 1e-11
 * relative in t). Once a diagonal entry 1 + x of the result falls below 3/4 (contraction), plain squaring is
 * better: per step the X form rounds like eps (2|x| + x^2) and the plain form like eps (1 + x)^2, which is
 * smaller for x < -1/4; near 0 the plain form keeps relative accuracy. With h the last row is 0 in X and
 * e_4^T in I + X: products stay block triangular. */
static int expm_square(ga_mat4 *xio, const ga_mat4 *a, int s, int h, int plain)
{
    ga_mat4 x = *xio;
    int bs[4], bz[4], nb = qt_blocks(a, bs, bz);
    if (nb)
        expm_fix_blocks(&x, a, 0, plain, bs, bz, nb);
    for (int k = 0; k < s; k++) {
        if (!plain &&
            (M(x, 0, 0) < -0.25 || M(x, 1, 1) < -0.25 || M(x, 2, 2) < -0.25 || M(x, 3, 3) < -0.25)) {
            x = ga__mat4_add_id(x, 1.0);
            plain = 1;
        }
        ga_mat4 x2 = mat4_mul_any(&x, &x, h);
        if (!plain)
            ga__mat4_acc(&x2, 2.0, &x);
        x = x2;
        if (!ga__mat4_isfinite(&x))
            return GA_ERR_DOMAIN; /* overflow: stop before Inf - Inf */
        if (nb)
            expm_fix_blocks(&x, a, k + 1, plain, bs, bz, nb);
    }
    if (!plain) {
        x = ga__mat4_add_id(x, 1.0);
        /* 1 + expm1(l) rounds e^l to eps absolute, not relative (e^-5.4 =
         * 0.0047 then carries 20 u): the blocks once more as exp itself */
        if (nb)
            expm_fix_blocks(&x, a, s, 1, bs, bz, nb);
    }
    *xio = x;
    return GA_OK;
}

ga_status ga_mat4_expm(ga_mat4 a, ga_mat4 *out)
{
    if (!out)
        return GA_ERR_ARG;
    if (!ga__mat4_isfinite(&a))
        return GA_ERR_NOTFINITE;
    /* A homogeneous generator (last row 0): every power and U have last row
     * 0, I and V have (0 0 0 c): all products are block triangular
     * (mat4_mul_ut), and the Pade solve is 3x3 (expm_solve3). */
    int h = M(a, 3, 0) == 0.0 && M(a, 3, 1) == 0.0 && M(a, 3, 2) == 0.0 && M(a, 3, 3) == 0.0;
    /* exp(A) = e^mu exp(A - mu I): with mu = trace(A)/4 > 0 where that
     * lowers ||A||_1 and ||A||_1 > 1 (Higham, Functions of Matrices, 2008,
     * sec. 10.7.3; below 1 no squaring is saved and e^mu only rounds):
     * unshifted, a growing r_m needs one or two more squarings, each of
     * which rounds. Not for mu < 0, where the squarings of a contracting
     * r_m lose nothing and e^mu alone would round; not for a homogeneous
     * generator, whose last row stays 0. */
    double mu = 0.0;
    if (!h) {
        mu = 0.25 * (M(a, 0, 0) + M(a, 1, 1) + M(a, 2, 2) + M(a, 3, 3));
        ga_mat4 b = ga__mat4_add_id(a, -mu);
        if (mu > 0.0 && ga__mat4_isfinite(&b) && norm1_finite(&a) > 1.0 &&
            norm1_finite(&b) < norm1_finite(&a))
            a = b;
        else
            mu = 0.0;
    }
    /* Past ||A||_1 = 2^60 the powers below could overflow: scale by an exact
     * power of 2 first (at least that many squarings are needed anyway). Its
     * exponent comes from the norm of A/4, which cannot overflow (4 entries
     * of at most DBL_MAX/4 each) where ||A||_1 can. */
    double n1 = norm1_finite(&a); /* Inf if the sum overflows */
    int s = 0;
    if (!(n1 <= 0x1p60)) {
        ga_mat4 q = a;
        for (int i = 0; i < 16; i++) q.m[i] *= 0.25;
        s = ilogb(norm1_finite(&q)) - 58 + 2;
        ga__mat4_scale2(&a, -s);
        n1 = norm1_finite(&a);
    }
    /* d_k = ||A^k||_1^(1/k) (exact norms: the powers are needed anyway), and
     * the choice of m and s of Al-Mohy & Higham 2009, Alg. 5.1: eta from the
     * d_k, which for a nonnormal A are much below ||A||_1 and avoid the
     * overscaling of Higham 2005 (Moler's badly scaled matrix), with ell()
     * guarding against a nonnormal |A| that makes the eta bound optimistic. */
    ga_mat4 a2 = mat4_mul_any(&a, &a, h), a4 = mat4_mul_any(&a2, &a2, h), a6 = mat4_mul_any(&a4, &a2, h);
    int idx = expm_degree(&a, &a2, &a4, &a6, h, n1, &s);
    ga_mat4 u, v, x;
    expm_pade(idx, &a, &a2, &a4, &a6, h, &u, &v);
    int plain;
    if (expm_rm(&a, &u, &v, h, &x, &plain) != GA_OK || expm_square(&x, &a, s, h, plain) != GA_OK)
        return GA_ERR_DOMAIN;
    if (mu > 0.0) {
        double em = exp(mu);
        for (int i = 0; i < 16; i++) x.m[i] *= em;
    }
    if (!ga__mat4_isfinite(&x))
        return GA_ERR_DOMAIN;
    *out = x;
    return GA_OK;
}
