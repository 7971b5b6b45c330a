/* garotor/mat4.c: 4x4 matrices, SE(3) in closed form, general expm and logm.
 * See mat4.h for what each function computes and the equations it cites. */
#include <garotor/mat4.h>

#include <float.h>
#include <math.h>
#include <string.h>

#define M(a, i, j) ((a).m[4 * (i) + (j)])

/* ---- small helpers --------------------------------------------------- */

static ga_vec3 v3(double x, double y, double z)
{
    ga_vec3 r = {x, y, z};
    return r;
}
static double dot3(ga_vec3 a, ga_vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static ga_vec3 cross3(ga_vec3 a, ga_vec3 b)
{
    return v3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
static ga_vec3 axpy3(double s, ga_vec3 x, ga_vec3 y) /* s x + y */
{
    return v3(s * x.x + y.x, s * x.y + y.y, s * x.z + y.z);
}
static double norm3(ga_vec3 a) { return hypot(hypot(a.x, a.y), a.z); }

/* No NaN or Inf in a. x - x is +0 for every finite x and NaN for NaN and
 * +-Inf, so the sum below is 0 exactly when all 16 entries are finite: one
 * test in place of sixteen, in four partial sums that can share vector lanes
 * (under -ffast-math this test, like isfinite() itself, cannot be relied on). */
static int mat4_isfinite(const ga_mat4 *a)
{
    double z[4] = {0.0, 0.0, 0.0, 0.0};
    for (int i = 0; i < 16; i += 4)
        for (int j = 0; j < 4; j++) z[j] += a->m[i + j] - a->m[i + j];
    return (z[0] + z[1]) + (z[2] + z[3]) == 0.0;
}

static ga_mat4 mat4_zero(void)
{
    ga_mat4 z;
    memset(&z, 0, sizeof z);
    return z;
}

/* y += c x */
static void mat4_acc(ga_mat4 *y, double c, const ga_mat4 *x)
{
    for (int i = 0; i < 16; i++) y->m[i] += c * x->m[i];
}

/* a + c I */
static ga_mat4 mat4_add_id(ga_mat4 a, double c)
{
    for (int i = 0; i < 4; i++) M(a, i, i) += c;
    return a;
}

ga_mat4 ga_mat4_identity(void) { return mat4_add_id(mat4_zero(), 1.0); }

ga_mat4 ga_mat4_mul(ga_mat4 a, ga_mat4 b)
{
    ga_mat4 c;
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            M(c, i, j) = M(a, i, 0) * M(b, 0, j) + M(a, i, 1) * M(b, 1, j) + M(a, i, 2) * M(b, 2, j) +
                         M(a, i, 3) * M(b, 3, j);
    return c;
}

double ga_mat4_norm1(ga_mat4 a)
{
    double best = 0.0;
    for (int j = 0; j < 4; j++) {
        double s = fabs(M(a, 0, j)) + fabs(M(a, 1, j)) + fabs(M(a, 2, j)) + fabs(M(a, 3, j));
        if (s > best || isnan(s))
            best = s; /* NaN in, NaN out */
    }
    return best;
}

/* a *= 2^e. For |e| <= 1000 the power is a normal double and the product
 * rounds exactly as ldexp does, without a call per entry. */
static void mat4_scale2(ga_mat4 *a, int e)
{
    if (e == 0)
        return;
    if (e >= -1000 && e <= 1000) {
        double f = ldexp(1.0, e);
        for (int i = 0; i < 16; i++) a->m[i] *= f;
    } else {
        for (int i = 0; i < 16; i++) a->m[i] = ldexp(a->m[i], e);
    }
}

/* ---- LU with partial pivoting ------------------------------------------
 * P A^ = L U with A^ = Dr A Dc: L (unit lower) below the diagonal of lu, U on
 * and above it; piv[k] is the row swapped with row k at step k; re, ce hold
 * the exponents of the power-of-2 (exact) scalings Dr, Dc. Used by the
 * inverse, the Pade solve of expm, and the roots and Pade solves of logm. */
typedef struct {
    ga_mat4 lu;
    int piv[4], re[4], ce[4];
} lu4;

/* Elimination with the pivot test |u_kk| > 4 eps max|A^_ij| (otherwise A^ is
 * within a few ulps, relative, of a singular matrix). With equilibrate, rows
 * then columns of A are first scaled so that each has its largest entry in
 * [1, 2). */
static int lu4_try(ga_mat4 a, lu4 *f, int equilibrate)
{
    for (int i = 0; i < 4; i++) f->re[i] = f->ce[i] = 0;
    for (int pass = 0; equilibrate && pass < 2; pass++) /* rows, then columns */
        for (int i = 0; i < 4; i++) {
            double mx = 0.0;
            for (int j = 0; j < 4; j++) mx = fmax(mx, fabs(pass ? M(a, j, i) : M(a, i, j)));
            if (!(mx > 0.0))
                return GA_ERR_SINGULAR;
            int e = ilogb(mx);
            for (int j = 0; j < 4; j++) {
                double *x = pass ? &M(a, j, i) : &M(a, i, j);
                *x = ldexp(*x, -e);
            }
            (pass ? f->ce : f->re)[i] = e;
        }
    double big = 0.0; /* max |a_ij| (a is finite here: no NaN to skip) */
    for (int i = 0; i < 16; i++) big = fabs(a.m[i]) > big ? fabs(a.m[i]) : big;
    for (int k = 0; k < 4; k++) {
        int p = k;
        for (int i = k + 1; i < 4; i++)
            if (fabs(M(a, i, k)) > fabs(M(a, p, k)))
                p = i;
        f->piv[k] = p;
        for (int j = 0; j < 4; j++) {
            double t = M(a, k, j);
            M(a, k, j) = M(a, p, j);
            M(a, p, j) = t;
        }
        if (!(fabs(M(a, k, k)) > 4.0 * DBL_EPSILON * big))
            return GA_ERR_SINGULAR;
        for (int i = k + 1; i < 4; i++) {
            double l = M(a, i, k) /= M(a, k, k);
            for (int j = k + 1; j < 4; j++) M(a, i, j) -= l * M(a, k, j);
        }
    }
    f->lu = a;
    return GA_OK;
}

/* A as given first: partial pivoting is not invariant under row scaling, and
 * equilibrating a well-scaled matrix can hurt (an affine [R, t; 0 1] whose
 * t_i differ by 2^10 would scale R's rows apart and lose 10 bits in R^{-1}).
 * Only when A looks singular is the equilibrated A^ tried: [R, t; 0 1] with
 * |t| = 1e16 has normwise condition |t|^2 but A^ is well conditioned; a
 * rank-deficient A fails both. */
static int lu4_factor(ga_mat4 a, lu4 *f) { return lu4_try(a, f, 0) == GA_OK ? GA_OK : lu4_try(a, f, 1); }

/* A^{-1} b = Dc A^^{-1} Dr b from the factors of A. */
static ga_mat4 lu4_solve(const lu4 *f, ga_mat4 b)
{
    /* the scalings are powers of 2, and 2^0 (A not equilibrated, the common
     * case) is skipped: ldexp is a call per entry */
    for (int i = 0; i < 4; i++)
        if (f->re[i])
            for (int j = 0; j < 4; j++) M(b, i, j) = ldexp(M(b, i, j), -f->re[i]);
    for (int k = 0; k < 4; k++)
        for (int j = 0; j < 4; j++) {
            double t = M(b, k, j);
            M(b, k, j) = M(b, f->piv[k], j);
            M(b, f->piv[k], j) = t;
        }
    for (int c = 0; c < 4; c++) {
        for (int i = 1; i < 4; i++)
            for (int j = 0; j < i; j++) M(b, i, c) -= M(f->lu, i, j) * M(b, j, c);
        for (int i = 3; i >= 0; i--) {
            for (int j = i + 1; j < 4; j++) M(b, i, c) -= M(f->lu, i, j) * M(b, j, c);
            M(b, i, c) /= M(f->lu, i, i);
        }
    }
    for (int i = 0; i < 4; i++)
        if (f->ce[i])
            for (int j = 0; j < 4; j++) M(b, i, j) = ldexp(M(b, i, j), -f->ce[i]);
    return b;
}

/* log |det A| from the factors (the scalings and the pivots). */
static double lu4_logabsdet(const lu4 *f)
{
    const double ln2 = 0.693147180559945309417232121458;
    double l = 0.0;
    for (int i = 0; i < 4; i++) l += log(fabs(M(f->lu, i, i))) + (f->re[i] + f->ce[i]) * ln2;
    return l;
}

int ga_mat4_inverse(ga_mat4 a, ga_mat4 *out)
{
    lu4 f;
    if (!mat4_isfinite(&a))
        return GA_ERR_NOTFINITE;
    if (lu4_factor(a, &f) != GA_OK)
        return GA_ERR_SINGULAR;
    ga_mat4 r = lu4_solve(&f, ga_mat4_identity());
    if (!mat4_isfinite(&r))
        return GA_ERR_SINGULAR; /* the inverse overflows */
    *out = r;
    return GA_OK;
}

/* ---- se(3): hat and vee ------------------------------------------------ */

ga_mat4 ga_twist_hat(ga_twist xi)
{
    ga_mat4 a = mat4_zero();
    M(a, 0, 1) = -xi.w.z;
    M(a, 0, 2) = xi.w.y;
    M(a, 0, 3) = xi.v.x;
    M(a, 1, 0) = xi.w.z;
    M(a, 1, 2) = -xi.w.x;
    M(a, 1, 3) = xi.v.y;
    M(a, 2, 0) = -xi.w.y;
    M(a, 2, 1) = xi.w.x;
    M(a, 2, 3) = xi.v.z;
    return a;
}

ga_twist ga_twist_vee(ga_mat4 a)
{
    ga_twist xi;
    /* halves first: the same result as (a21 - a12)/2 (scaling by 2 commutes
       with rounding), but no overflow for entries beyond DBL_MAX/2 */
    xi.w = v3(0.5 * M(a, 2, 1) - 0.5 * M(a, 1, 2), 0.5 * M(a, 0, 2) - 0.5 * M(a, 2, 0),
              0.5 * M(a, 1, 0) - 0.5 * M(a, 0, 1));
    xi.v = v3(M(a, 0, 3), M(a, 1, 3), M(a, 2, 3));
    return xi;
}

/* ---- SE(3) ----------------------------------------------------------- */

/* ga_se3_check through a pointer: ga_se3_log and the geodesic check the
 * matrix in place instead of copying its 128 bytes for each call. */
static inline int se3_check(const ga_mat4 *m, double tol)
{
    if (!mat4_isfinite(m))
        return GA_ERR_NOTFINITE;
    for (int i = 0; i < 3; i++)
        for (int j = i; j < 3; j++) { /* R^T R - I is symmetric */
            double g = M(*m, 0, i) * M(*m, 0, j) + M(*m, 1, i) * M(*m, 1, j) + M(*m, 2, i) * M(*m, 2, j) -
                       (i == j);
            if (!(fabs(g) <= tol))
                return GA_ERR_NOTRIGID; /* !(<=): a NaN tol rejects */
        }
    ga_vec3 c0 = v3(M(*m, 0, 0), M(*m, 1, 0), M(*m, 2, 0));
    ga_vec3 c1 = v3(M(*m, 0, 1), M(*m, 1, 1), M(*m, 2, 1));
    ga_vec3 c2 = v3(M(*m, 0, 2), M(*m, 1, 2), M(*m, 2, 2));
    if (!(dot3(c0, cross3(c1, c2)) > 0.0))
        return GA_ERR_NOTRIGID; /* a reflection */
    if (!(fabs(M(*m, 3, 0)) <= tol && fabs(M(*m, 3, 1)) <= tol && fabs(M(*m, 3, 2)) <= tol &&
          fabs(M(*m, 3, 3) - 1.0) <= tol))
        return GA_ERR_NOTRIGID;
    return GA_OK;
}

int ga_se3_check(ga_mat4 m, double tol) { return se3_check(&m, tol); }

ga_mat4 ga_se3_inverse(ga_mat4 m)
{
    ga_mat4 r = ga_mat4_identity();
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) M(r, i, j) = M(m, j, i);
    for (int i = 0; i < 3; i++)
        M(r, i, 3) = -(M(r, i, 0) * M(m, 0, 3) + M(r, i, 1) * M(m, 1, 3) + M(r, i, 2) * M(m, 2, 3));
    return r;
}

/* f_j(th) = sum_k (-1)^k th^2k / (2k+j)!, for j = 1, 2, 3:
 *   f_1 = sin th / th,  f_2 = (1 - cos th)/th^2,  f_3 = (th - sin th)/th^3,
 * the coefficients of expm(xi^) (Eberly eqs. 9, 19, 20). For th < 1 the
 * series is summed to k = 8 (these tables): the first omitted term,
 * th^18/(18+j)!, is below 1/19! < 1e-17 of f_j(0) = 1/j!. */
static const double sinc_series[3][9] = {
    {1.0, -1.0 / 6, 1.0 / 120, -1.0 / 5040, 1.0 / 362880, -1.0 / 39916800, 1.0 / 6227020800.0,
     -1.0 / 1307674368000.0, 1.0 / 355687428096000.0},
    {1.0 / 2, -1.0 / 24, 1.0 / 720, -1.0 / 40320, 1.0 / 3628800, -1.0 / 479001600, 1.0 / 87178291200.0,
     -1.0 / 20922789888000.0, 1.0 / 6402373705728000.0},
    {1.0 / 6, -1.0 / 120, 1.0 / 5040, -1.0 / 362880, 1.0 / 39916800, -1.0 / 6227020800.0,
     1.0 / 1307674368000.0, -1.0 / 355687428096000.0, 1.0 / 121645100408832000.0}};

ga_mat4 ga_se3_exp(ga_twist xi)
{
    ga_vec3 w = xi.w, v = xi.v;
    /* th = |w|: w.w overflows only for |w| > 1e154; then the scaled norm, so
     * that sin and cos still see the angle */
    double t2 = dot3(w, w), th = t2 <= DBL_MAX ? sqrt(t2) : norm3(w), a, b, c, co;
    if (th < 1.0) {
        /* the series, no trig call and no division; cos th = 1 - b th^2 (Rodrigues) */
        a = b = c = 0.0;
        for (int k = 8; k >= 0; k--) { /* Horner in th^2 */
            a = a * t2 + sinc_series[0][k];
            b = b * t2 + sinc_series[1][k];
            c = c * t2 + sinc_series[2][k];
        }
        co = 1.0 - b * t2;
    } else {
        /* the closed forms, from one sincos: no harmful cancellation for
         * th >= 1 (th - sin th loses at most log2(th / (th - sin th)) <= 2.7
         * bits, at th = 1), and where 1 - cos th would cancel (cos th > 1/2,
         * near th = 2 pi k) it is taken as sin^2 th / (1 + cos th) */
        double sn = sin(th);
        co = cos(th);
        a = sn / th;
        b = (co < 0.5 ? 1.0 - co : sn * sn / (1.0 + co)) / t2;
        c = (th - sn) / (t2 * th);
    }
    /* Eq. 9 with S^2 = w w^T - th^2 I and 1 - b th^2 = cos th (Rodrigues):
     * R = cos th I + a [w]x + b w w^T, its entries (b w_i) w_j written out.
     * Eq. 19-20: t = V v = v + b w x v + c w x (w x v). */
    double bx = b * w.x, by = b * w.y, bz = b * w.z;
    double ax = a * w.x, ay = a * w.y, az = a * w.z;
    ga_vec3 u = cross3(w, v);
    ga_vec3 t = axpy3(c, cross3(w, u), axpy3(b, u, v));
    ga_mat4 r = {{co + bx * w.x, bx * w.y - az, bx * w.z + ay, t.x, by * w.x + az, co + by * w.y,
                  by * w.z - ax, t.y, bz * w.x - ay, bz * w.y + ax, co + bz * w.z, t.z, 0.0, 0.0, 0.0, 1.0}};
    return r;
}

/* The principal log of a matrix already known to be rigid to GA_SE3_TOL. */
static inline ga_twist se3_log_core(const ga_mat4 *m)
{
    /* R = cos th I + sin th [n]x + (1 - cos th) n n^T for a unit axis n, so the
     * skew part gives s = sin th n and the trace c = cos th. */
    ga_vec3 s = v3(0.5 * (M(*m, 2, 1) - M(*m, 1, 2)), 0.5 * (M(*m, 0, 2) - M(*m, 2, 0)),
                   0.5 * (M(*m, 1, 0) - M(*m, 0, 1)));
    double c = 0.5 * (M(*m, 0, 0) + M(*m, 1, 1) + M(*m, 2, 2) - 1.0);
    /* sn = |s| <= 1 + tol: s.s cannot overflow, and for |s| >= 2^-450 it does
     * not underflow, so its plain sqrt is exact to rounding; below, the
     * scaled norm keeps a rotation of 1e-200 rad */
    double ss = dot3(s, s), sn = ss >= 0x1p-900 ? sqrt(ss) : norm3(s);
    double th = atan2(sn, c); /* in [0, pi]; accurate at both ends, unlike acos(c) */
    ga_twist xi;
    if (c >= 0.0) {
        /* th <= pi/2: eq. 11, w = (th / sin th) s, and th/|s| is well
         * conditioned here (both from atan2, no series needed). |s| = 0 with
         * c >= 0 is the identity rotation. */
        xi.w = sn > 0.0 ? axpy3(th / sn, s, v3(0, 0, 0)) : v3(0, 0, 0);
    } else {
        /* th in (pi/2, pi]: s = sin th n loses relative accuracy as th -> pi
         * (and vanishes at pi), but the symmetric part does not:
         * B = (R + R^T)/2 - c I = (1 - c) n n^T, 1 - c > 1. Eberly's th = pi
         * rule: normalise the column of B with the largest diagonal entry
         * (B_jj = (1 - c) n_j^2 >= (1 - c)/3), then take the sign of s. */
        int j = 0;
        for (int i = 1; i < 3; i++)
            if (M(*m, i, i) > M(*m, j, j))
                j = i;
        double col[3];
        for (int i = 0; i < 3; i++) col[i] = 0.5 * (M(*m, i, j) + M(*m, j, i)) - (i == j ? c : 0.0);
        ga_vec3 n = v3(col[0], col[1], col[2]);
        double k = th / sqrt(dot3(n, n)); /* |n| in [0.57, 2]: no over- or underflow */
        if (dot3(n, s) < 0.0)
            k = -k; /* at th = pi exactly s = 0 and either sign is right */
        xi.w = axpy3(k, n, v3(0, 0, 0));
    }
    /* Eq. 20: v = V^{-1} t = t - w x t / 2 + c2 w x (w x t),
     * c2 = (1 - (th/2) cot(th/2)) / th^2 = sum_n>=1 (-1)^(n+1) B_2n th^(2n-2) / (2n)!
     * (Bernoulli numbers). The closed form cancels as th -> 0, so for th < 1/2
     * the series is summed to n = 8 (next term < 2e-18 of the first). At
     * th <= pi, cot(th/2) >= 0 and V^{-1} is bounded. cot(th/2) needs no trig
     * call: with rho = |(sn, c)|, th/2 = atan2(sn, c)/2 has
     * cot(th/2) = (rho + c)/sn = sn/(rho - c), the first form for c >= 0 and
     * the second for c < 0, so that neither cancels (rho - c > rho for c < 0;
     * at th = pi, sn = 0 and cot = 0). */
    double c2;
    if (th < 0.5) {
        static const double cs[8] = {1.0 / 12,
                                     1.0 / 720,
                                     1.0 / 30240,
                                     1.0 / 1209600,
                                     1.0 / 47900160,
                                     691.0 / 1307674368000.0,
                                     1.0 / 74724249600.0,
                                     3617.0 / 10670622842880000.0};
        double t2 = th * th;
        c2 = 0.0;
        for (int i = 7; i >= 0; i--) c2 = c2 * t2 + cs[i];
    } else {
        double rho = sqrt(sn * sn + c * c);
        double cot = c >= 0.0 ? (rho + c) / sn : sn / (rho - c);
        c2 = (1.0 - 0.5 * th * cot) / (th * th);
    }
    ga_vec3 t = v3(M(*m, 0, 3), M(*m, 1, 3), M(*m, 2, 3));
    ga_vec3 u = cross3(xi.w, t);
    xi.v = axpy3(c2, cross3(xi.w, u), axpy3(-0.5, u, t));
    return xi;
}

int ga_se3_log(ga_mat4 m, ga_twist *out)
{
    int st = se3_check(&m, GA_SE3_TOL);
    if (st != GA_OK)
        return st;
    ga_twist xi = se3_log_core(&m);
    /* v = V^{-1} t overflows for a translation near DBL_MAX: report it, never
       return Inf or NaN (found by fuzz/fuzz_numeric;
       fuzz/regress/numeric/log-subnormal-rotation-translation replays it) */
    if (!(isfinite(xi.v.x) && isfinite(xi.v.y) && isfinite(xi.v.z)))
        return GA_ERR_DOMAIN;
    *out = xi;
    return GA_OK;
}

int ga_se3_geodesic(ga_mat4 h0, ga_mat4 h1, double t, ga_mat4 *out)
{
    int st = ga_se3_check(h0, GA_SE3_TOL);
    if (st == GA_OK)
        st = ga_se3_check(h1, GA_SE3_TOL);
    if (st == GA_OK && !isfinite(t))
        st = GA_ERR_NOTFINITE;
    if (st != GA_OK)
        return st;
    /* h1 h0^{-1} is rigid to about 2 GA_SE3_TOL, so it goes to the unchecked
     * log: re-checking it at GA_SE3_TOL could reject two valid inputs. */
    ga_mat4 rel = ga_mat4_mul(h1, ga_se3_inverse(h0));
    ga_twist xi = se3_log_core(&rel);
    xi.w = axpy3(t, xi.w, v3(0, 0, 0));
    xi.v = axpy3(t, xi.v, v3(0, 0, 0));
    ga_mat4 g = ga_mat4_mul(ga_se3_exp(xi), h0);
    /* a far extrapolation or a translation near DBL_MAX overflows: reported,
       never returned as Inf or NaN (found by fuzz/fuzz_numeric;
       fuzz/regress/numeric/geodesic-overflow replays it) */
    if (!mat4_isfinite(&g))
        return GA_ERR_DOMAIN;
    *out = g;
    return GA_OK;
}

ga_twist ga_se3_adjoint(ga_mat4 g, ga_twist xi)
{
    ga_vec3 rw = v3(M(g, 0, 0) * xi.w.x + M(g, 0, 1) * xi.w.y + M(g, 0, 2) * xi.w.z,
                    M(g, 1, 0) * xi.w.x + M(g, 1, 1) * xi.w.y + M(g, 1, 2) * xi.w.z,
                    M(g, 2, 0) * xi.w.x + M(g, 2, 1) * xi.w.y + M(g, 2, 2) * xi.w.z);
    ga_vec3 rv = v3(M(g, 0, 0) * xi.v.x + M(g, 0, 1) * xi.v.y + M(g, 0, 2) * xi.v.z,
                    M(g, 1, 0) * xi.v.x + M(g, 1, 1) * xi.v.y + M(g, 1, 2) * xi.v.z,
                    M(g, 2, 0) * xi.v.x + M(g, 2, 1) * xi.v.y + M(g, 2, 2) * xi.v.z);
    ga_twist r;
    r.w = rw;
    r.v = axpy3(1.0, cross3(v3(M(g, 0, 3), M(g, 1, 3), M(g, 2, 3)), rw), rv);
    return r;
}

/* ---- general exp: scaling and squaring (Higham 2005) ------------------- */

int ga_mat4_expm(ga_mat4 a, ga_mat4 *out)
{
    /* theta_m: the largest ||A||_1 for which r_m(A) = e^(A + E) with
     * ||E|| <= 2^-53 ||A|| (Higham 2005; checked against the backward-error
     * series log(e^-x r_m(x)) in exact rational arithmetic). b: the
     * coefficients of the Pade numerator p_m(x) = sum b_j x^j, scaled to
     * integers, with q_m(x) = p_m(-x). */
    static const double theta[5] = {1.495585217958292e-2, 2.539398330063230e-1, 9.504178996162932e-1,
                                    2.097847961257068e0, 5.371920351148152e0};
    static const int degree[5] = {3, 5, 7, 9, 13};
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

    if (!mat4_isfinite(&a))
        return GA_ERR_NOTFINITE;
    /* The norm of a/4 cannot overflow (4 entries of at most DBL_MAX/4 each). */
    ga_mat4 q = a;
    for (int i = 0; i < 16; i++) q.m[i] *= 0.25;
    double eta4 = ga_mat4_norm1(q);
    int idx = 0, s = 0;
    while (idx < 4 && !(eta4 <= 0.25 * theta[idx])) idx++;
    if (idx == 4 && eta4 > 0.25 * theta[4]) /* scale so that ||a/2^s||_1 <= theta_13 */
        s = (int)ceil(log2(eta4 / (0.25 * theta[4])));
    mat4_scale2(&a, -s);

    /* r_m = (V - U)^{-1} (V + U), U the odd and V the even part of p_m. */
    const double *b = coef[idx];
    int m = degree[idx];
    ga_mat4 id = ga_mat4_identity(), v = mat4_zero(), u0 = mat4_zero(); /* U = A U0 */
    ga_mat4 a2 = ga_mat4_mul(a, a);
    if (m < 13) {
        ga_mat4 p = id; /* p = A^(2k) */
        for (int k = 0; 2 * k < m; k++) {
            mat4_acc(&u0, b[2 * k + 1], &p);
            mat4_acc(&v, b[2 * k], &p);
            if (2 * k + 2 < m)
                p = ga_mat4_mul(p, a2);
        }
    } else { /* Higham's m = 13 scheme: 6 matrix products instead of 12 */
        ga_mat4 a4 = ga_mat4_mul(a2, a2), a6 = ga_mat4_mul(a4, a2), w = mat4_zero();
        mat4_acc(&w, b[13], &a6);
        mat4_acc(&w, b[11], &a4);
        mat4_acc(&w, b[9], &a2);
        u0 = ga_mat4_mul(a6, w);
        mat4_acc(&u0, b[7], &a6);
        mat4_acc(&u0, b[5], &a4);
        mat4_acc(&u0, b[3], &a2);
        mat4_acc(&u0, b[1], &id);
        w = mat4_zero();
        mat4_acc(&w, b[12], &a6);
        mat4_acc(&w, b[10], &a4);
        mat4_acc(&w, b[8], &a2);
        v = ga_mat4_mul(a6, w);
        mat4_acc(&v, b[6], &a6);
        mat4_acc(&v, b[4], &a4);
        mat4_acc(&v, b[2], &a2);
        mat4_acc(&v, b[0], &id);
    }
    ga_mat4 u = ga_mat4_mul(a, u0), den = v;
    mat4_acc(&den, -1.0, &u);
    lu4 f;
    /* q_m(A) is well conditioned for ||A||_1 <= theta_m (Higham 2005): this
     * failure is a guard, not an expected path. */
    if (lu4_factor(den, &f) != GA_OK)
        return GA_ERR_DOMAIN;
    /* X = r_m - I = 2 (V - U)^{-1} U: no cancellation for r_m near I. */
    ga_mat4 x = lu4_solve(&f, u);
    for (int i = 0; i < 16; i++) x.m[i] *= 2.0;

    /* Squaring. (I + X)^2 = I + (2X + X^2) keeps relative accuracy in X when
     * the result is near I; e.g. a rotation block R = I + O(1e-12) under a
     * translation 1e6 needs 18 squarings, and plain squaring would lose the
     * rounding of R's diagonal doubled 18 times (about 1e-11 relative in t).
     * Once a diagonal entry 1 + x of the result falls below 3/4 (contraction),
     * plain squaring is better: per step the X form rounds like
     * eps (2|x| + x^2) and the plain form like eps (1 + x)^2, which is smaller
     * for x < -1/4; near 0 the plain form keeps relative accuracy. */
    int plain = 0;
    for (int k = 0; k < s; k++) {
        if (!plain &&
            (M(x, 0, 0) < -0.25 || M(x, 1, 1) < -0.25 || M(x, 2, 2) < -0.25 || M(x, 3, 3) < -0.25)) {
            x = mat4_add_id(x, 1.0);
            plain = 1;
        }
        ga_mat4 x2 = ga_mat4_mul(x, x);
        if (!plain)
            mat4_acc(&x2, 2.0, &x);
        x = x2;
        if (!mat4_isfinite(&x))
            return GA_ERR_DOMAIN; /* overflow: stop before Inf - Inf */
    }
    if (!plain)
        x = mat4_add_id(x, 1.0);
    if (!mat4_isfinite(&x))
        return GA_ERR_DOMAIN;
    *out = x;
    return GA_OK;
}

/* ---- general log: inverse scaling and squaring ------------------------- */

/* One Newton step for X^2 = A from X: X += E with X E + E X = A - X^2, a
 * Sylvester equation, solved in its 16x16 Kronecker form by Gaussian
 * elimination with partial pivoting (unknown E_kj at index 4k + j). Its
 * matrix is nonsingular for a principal root (no mu_i + mu_j = 0). The step
 * is kept only if it lowers the residual ||A - X^2||_1, so an ill-conditioned
 * Sylvester system (a root near +-i, from a near half turn) cannot spoil X. */
static void sqrtm_newton(ga_mat4 a, ga_mat4 *x)
{
    double k[16][17] = {{0}};
    ga_mat4 x2 = ga_mat4_mul(*x, *x);
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            double *row = k[4 * i + j];
            for (int l = 0; l < 4; l++) {
                row[4 * l + j] += M(*x, i, l); /* (X E)_ij */
                row[4 * i + l] += M(*x, l, j); /* (E X)_ij */
            }
            row[16] = M(a, i, j) - M(x2, i, j);
        }
    for (int c = 0; c < 16; c++) {
        int p = c;
        for (int i = c + 1; i < 16; i++)
            if (fabs(k[i][c]) > fabs(k[p][c]))
                p = i;
        if (k[p][c] == 0.0)
            return; /* cannot happen for a principal root; keep X */
        for (int j = c; j < 17; j++) {
            double t = k[c][j];
            k[c][j] = k[p][j];
            k[p][j] = t;
        }
        for (int i = c + 1; i < 16; i++) {
            double l = k[i][c] / k[c][c];
            for (int j = c; j < 17; j++) k[i][j] -= l * k[c][j];
        }
    }
    double e[16];
    for (int i = 15; i >= 0; i--) {
        double acc = k[i][16];
        for (int j = i + 1; j < 16; j++) acc -= k[i][j] * e[j];
        e[i] = acc / k[i][i];
    }
    ga_mat4 r = *x, d0 = a, d1 = a;
    for (int i = 0; i < 16; i++) r.m[i] += e[i];
    ga_mat4 r2 = ga_mat4_mul(r, r);
    mat4_acc(&d0, -1.0, &x2);
    mat4_acc(&d1, -1.0, &r2);
    if (mat4_isfinite(&r) && ga_mat4_norm1(d1) < ga_mat4_norm1(d0))
        *x = r;
}

/* The principal square root of a by the Denman-Beavers iteration with
 * determinantal scaling (Higham, Functions of Matrices, 2008, ch. 6):
 *   Y_{k+1} = (mu Y_k + mu^-1 Z_k^{-1}) / 2,   Y_0 = A,
 *   Z_{k+1} = (mu Z_k + mu^-1 Y_k^{-1}) / 2,   Z_0 = I,
 *   mu = |det(Y_k) det(Z_k)|^(-1/8),
 * with Y_k -> A^(1/2) and Z_k -> A^(-1/2). The coupled form, not the cheaper
 * product form M_{k+1} = (I + (M_k + M_k^{-1})/2)/2: for an eigenvalue
 * e^(i(pi - d)) (a rotation near a half turn) the product form builds
 * M_1 = (I + (A + A^{-1})/2)/2 with an eigenvalue d^2/4 by cancellation and
 * loses eps/d^2, while Y_1 = (A + I)/2 and Z_1 = (I + A^{-1})/2 lose only
 * eps/d, which is the conditioning of the square root itself.
 * Convergence: M_k = Y_k Z_k obeys M_{k+1} - I = (M_k - I)^2 M_k^{-1} / 4
 * exactly (unscaled), and Y_k = A^(1/2) M_k^(1/2). So once M_k - I is below
 * 1e-8 (about sqrt(eps)) one more step leaves M at rounding level and the
 * iteration stops there; scaling, which speeds up the early steps, is
 * switched off below 1e-2 to keep that quadratic convergence. "Below" is
 * measured entrywise against |Y_k| |Z_k|, the scale at which Y_k Z_k rounds:
 * with a translation t the product rounds at eps |t| in its last column, so
 * a normwise test could never pass once |t| > 1e8. The iterates
 * use inverses of Y_k and Z_k, which for an ill-conditioned A (cond 1e6)
 * leave a residual ||Y^2 - A|| near 1e-13 ||A||; one Newton step at the end
 * brings it to rounding level (measured: the affine expm(logm(A)) round trip
 * goes from 8e-13 to 4e-14).
 * With an eigenvalue on the closed negative real axis the iteration meets a
 * singular Y_k or Z_k or never converges (for a real negative eigenvalue the
 * scalar iterates stay real and cannot approach its imaginary root):
 * GA_ERR_DOMAIN either way. */
/* max_ij |Y Z - I|_ij / S_ij, the residual of Denman-Beavers, with the scale
 * S_ij = max(D_ij, 1e-6 min(max_l D_il, max_l D_lj), DBL_MIN), D = |Y| |Z|.
 * D_ij is the scale at which (Y Z)_ij rounds when its terms carry the
 * entry's weight. An entry that should be exactly 0 but holds rounding noise
 * of its row and column (eps times max_l D_il, say) would read as a residual
 * near 1 against its own terms and stop convergence forever, and with it
 * keep the determinant scaling on (found by fuzz/fuzz_path: logm of
 * [1 0 0 0; 0 1 0 0; 0 -.98 .016 -.98; 0 0 0 1] was GA_ERR_DOMAIN; replayed by
 * fuzz/regress/path/affine-logm-db-stall): such entries are measured against
 * 1e-6 of the smaller of their row's and column's largest scale, which
 * leaves the noise near 1e-9. A translation column keeps its own scale (its
 * D_ij is the largest of its row). Below DBL_MIN products round absolutely,
 * to 2^-1074, so a relative residual need never fall below 1e-8 (found by
 * fuzz/fuzz_numeric: logm(expm(X)) was GA_ERR_DOMAIN for an X with one entry of
 * -8e-322; replayed by fuzz/regress/numeric/logm-subnormal-entry). */
static double db_residual(const ga_mat4 *y, const ga_mat4 *z)
{
    double d[4][4], r[4][4], rowmax[4] = {0}, colmax[4] = {0}, worst = 0.0;
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            r[i][j] = -(double)(i == j);
            d[i][j] = 0.0;
            for (int k = 0; k < 4; k++) {
                r[i][j] += M(*y, i, k) * M(*z, k, j);
                d[i][j] += fabs(M(*y, i, k) * M(*z, k, j));
            }
            rowmax[i] = fmax(rowmax[i], d[i][j]);
            colmax[j] = fmax(colmax[j], d[i][j]);
        }
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            double s = fmax(fmax(d[i][j], 1e-6 * fmin(rowmax[i], colmax[j])), DBL_MIN);
            if (fabs(r[i][j]) > worst * s)
                worst = fabs(r[i][j]) / s;
        }
    return worst;
}

static int sqrtm_db(ga_mat4 a, ga_mat4 *root)
{
    ga_mat4 y = a, z = ga_mat4_identity(), id = ga_mat4_identity();
    for (int it = 0; it < 100; it++) {
        lu4 fy, fz;
        if (lu4_factor(y, &fy) != GA_OK || lu4_factor(z, &fz) != GA_OK)
            return GA_ERR_DOMAIN;
        ga_mat4 yinv = lu4_solve(&fy, id), zinv = lu4_solve(&fz, id);
        double res = db_residual(&y, &z), mu = 1.0;
        if (res > 1e-2) {
            mu = exp(-(lu4_logabsdet(&fy) + lu4_logabsdet(&fz)) / 8.0);
        }
        ga_mat4 yn = mat4_zero(), zn = mat4_zero();
        mat4_acc(&yn, 0.5 * mu, &y);
        mat4_acc(&yn, 0.5 / mu, &zinv);
        mat4_acc(&zn, 0.5 * mu, &z);
        mat4_acc(&zn, 0.5 / mu, &yinv);
        y = yn;
        z = zn;
        if (!mat4_isfinite(&y) || !mat4_isfinite(&z))
            return GA_ERR_DOMAIN;
        if (res <= 1e-8) {
            sqrtm_newton(a, &y);
            *root = y;
            return GA_OK;
        }
    }
    return GA_ERR_DOMAIN;
}

int ga_mat4_logm(ga_mat4 a, ga_mat4 *out)
{
    /* [8/8] Pade approximant of log(1 + x) in partial fractions: 8-point
     * Gauss-Legendre on log(I + X) = int_0^1 X (I + t X)^{-1} dt (Higham 2001).
     * For ||X||_1 <= 0.325 its error is below 2^-53 |log(1 - ||X||_1)|
     * (Kenney-Laub bound: the worst case is x = -||X||). */
    static const double node[8] = {1.98550717512318842e-02, 1.01666761293186636e-01, 2.37233795041835505e-01,
                                   4.08282678752175110e-01, 5.91717321247824946e-01, 7.62766204958164495e-01,
                                   8.98333238706813364e-01, 9.80144928248768088e-01};
    static const double weight[8] = {
        5.06142681451881293e-02, 1.11190517226687241e-01, 1.56853322938943635e-01, 1.81341891689180995e-01,
        1.81341891689180995e-01, 1.56853322938943635e-01, 1.11190517226687241e-01, 5.06142681451881293e-02};
    const double theta8 = 0.325;

    if (!mat4_isfinite(&a))
        return GA_ERR_NOTFINITE;
    lu4 f;
    if (lu4_factor(a, &f) != GA_OK)
        return GA_ERR_SINGULAR; /* eigenvalue 0: no log */

    /* A_k = A^(1/2^k) and Z = A_k - I. Z is updated by the identity
     * A_k - I = (A_{k+1} + I)(A_{k+1} - I) (the factors commute) rather than
     * formed as A_{k+1} - I, which would round away small parts: a scaling
     * diag(1 + 1e-10, ...) under a translation of 1e6 needs 23 roots, after
     * which its diagonal in A_23 - I is near 1e-17, below the rounding of 1;
     * subtraction returns that scaling's log with 100% error, the update with
     * 1e-15 (tests/test_mat4.c). */
    ga_mat4 ak = a, z = mat4_add_id(a, -1.0);
    int k = 0;
    while (ga_mat4_norm1(z) > theta8) {
        ga_mat4 root;
        /* Each root about halves ||Z||_1 <= 4 DBL_MAX < 2^1026 (a translation
         * t needs log2(|t|/theta8) roots, 23 for 1e6), so 1100 roots always
         * suffice; not getting there means no principal root is converging. */
        if (k == 1100 || sqrtm_db(ak, &root) != GA_OK)
            return GA_ERR_DOMAIN;
        if (lu4_factor(mat4_add_id(root, 1.0), &f) != GA_OK)
            return GA_ERR_DOMAIN;
        z = lu4_solve(&f, z);
        ak = root;
        k++;
    }
    ga_mat4 l = mat4_zero();
    for (int j = 0; j < 8; j++) {
        ga_mat4 d = z;
        for (int i = 0; i < 16; i++) d.m[i] *= node[j];
        /* I + t Z, ||t Z|| < 1/3: well conditioned, cannot be singular */
        if (lu4_factor(mat4_add_id(d, 1.0), &f) != GA_OK)
            return GA_ERR_DOMAIN;
        ga_mat4 term = lu4_solve(&f, z);
        mat4_acc(&l, weight[j], &term);
    }
    mat4_scale2(&l, k);
    if (!mat4_isfinite(&l))
        return GA_ERR_DOMAIN;
    /* A posteriori check. Within rounding of the negative real axis (a
     * rounded half turn has eigenvalues -1 +- 1e-16 i) a square root can
     * settle on a non-principal branch, and the backward error of the whole
     * computation grows fast once the eigenvalues come closer to the axis
     * than ~1e-8 (tests/test_cross.c). Rather than return a confident wrong
     * answer, accept L only if exp(L) reproduces A to GA_LOGM_BACKWARD_TOL. */
    ga_mat4 back;
    if (ga_mat4_expm(l, &back) != GA_OK)
        return GA_ERR_DOMAIN;
    double err = 0.0;
    for (int i = 0; i < 16; i++) back.m[i] -= a.m[i];
    err = ga_mat4_norm1(back);
    if (!(err <= GA_LOGM_BACKWARD_TOL * ga_mat4_norm1(a)))
        return GA_ERR_DOMAIN;
    *out = l;
    return GA_OK;
}

/* Nearest rotation: Higham's Newton iteration for the orthogonal polar factor,
 * X <- (X + X^-T)/2 (Higham, "Computing the polar decomposition", 1986), from
 * X_0 = R with ||R^T R - I|| <= 1e-3: the error e_k = ||X_k^T X_k - I|| obeys
 * e_{k+1} ~ e_k^2 / 4, so three steps reach rounding; the loop stops when a
 * step changes no entry by more than 4 ulp, at most 8 steps. */
int ga_se3_normalize(ga_mat4 m, double tol, ga_mat4 *out)
{
    if (!(tol >= 0.0 && tol <= GA_SE3_NORMALIZE_TOL))
        return GA_ERR_ARG;
    int st = se3_check(&m, tol);
    if (st != GA_OK)
        return st;
    double x[3][3];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) x[i][j] = M(m, i, j);
    for (int it = 0; it < 8; it++) {
        /* X^-T = cof(X) / det X */
        double c[3][3];
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++) {
                int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
                c[i][j] = x[i1][j1] * x[i2][j2] - x[i1][j2] * x[i2][j1];
            }
        double det = x[0][0] * c[0][0] + x[0][1] * c[0][1] + x[0][2] * c[0][2], change = 0.0;
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++) {
                double nx = 0.5 * (x[i][j] + c[i][j] / det);
                change = fmax(change, fabs(nx - x[i][j]));
                x[i][j] = nx;
            }
        if (change <= 4 * DBL_EPSILON)
            break;
    }
    ga_mat4 r = m;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) M(r, i, j) = x[i][j];
    M(r, 3, 0) = M(r, 3, 1) = M(r, 3, 2) = 0.0;
    M(r, 3, 3) = 1.0;
    *out = r;
    return GA_OK;
}
