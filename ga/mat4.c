/* garotor/mat4.c: 4x4 matrices, SE(3) in closed form, general expm and logm.
 * See mat4.h for what each function computes and the equations it cites. */
#include <garotor/mat4.h>

#include <float.h>
#include <math.h>
#include <string.h>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

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

ga_status ga_mat4_inverse(ga_mat4 a, ga_mat4 *out)
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
    /* clang-format off */
    M(a, 0, 1) = -xi.w.z; M(a, 0, 2) =  xi.w.y; M(a, 0, 3) = xi.v.x;
    M(a, 1, 0) =  xi.w.z; M(a, 1, 2) = -xi.w.x; M(a, 1, 3) = xi.v.y;
    M(a, 2, 0) = -xi.w.y; M(a, 2, 1) =  xi.w.x; M(a, 2, 3) = xi.v.z;
    /* clang-format on */
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

ga_status ga_se3_check(ga_mat4 m, double tol) { return se3_check(&m, tol); }

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

/* ga_se3_exp where w.w overflows (|w| beyond ~1.3e154), out of its hot path
   (tested before the series, it made se3_exp 8-10% slower in garotor-bench) */
#if defined(__GNUC__)
#define GA_COLD __attribute__((noinline, cold))
#else
#define GA_COLD
#endif
static GA_COLD ga_mat4 se3_exp_huge(ga_vec3 w, ga_vec3 v)
{
    /* th beyond ~1.3e154: b and c below lost th^2 (b = c = 0 left R =
     * cos th I + a [w]x, not a rotation, and c w x (w x v) gave NaN).
     * From the half angle h = |w/2| (th itself overflows from ~1.8e308),
     * as ga_rotor_exp: the unit axis n = (w/2)/h, sin th = 2 sin h cos h,
     * 1 - cos th = 2 sin^2 h, R = cos th I + sin th [n]x +
     * (1 - cos th) n n^T and t = (n.v) n + (sin th/th) v_perp +
     * ((1 - cos th)/th) n x v (v_perp = v - (n.v) n): Eberly's V v with
     * (th - sin th)/th^3 S^2 v written as -(1 - sin th/th) v_perp and
     * added to v without cancellation. The rotation is exact for the
     * double angle, which is known only to its ulp. */
    /* h as ga_rotor_exp takes phi (the sqrt of the dot product of w/2
     * 2^-600, times 2^600), bit for bit: an ulp of h is more than a
     * radian, so another rounding of the norm (hypot) turns by another
     * angle altogether */
    ga_vec3 w2 = v3(0x1p-601 * w.x, 0x1p-601 * w.y, 0x1p-601 * w.z);
    double ns = sqrt(dot3(w2, w2)), h = ns * 0x1p600;
    double sh = sin(h), ch = cos(h), sn = 2.0 * sh * ch, k = 2.0 * sh * sh;
    double tw = 2.0 * h; /* Inf beyond DBL_MAX: sn / tw = k / tw = 0, their limits */
    ga_vec3 n = v3(w2.x / ns, w2.y / ns, w2.z / ns);
    double co = ch * ch - sh * sh;
    double nv = dot3(n, v);
    ga_vec3 vpar = v3(nv * n.x, nv * n.y, nv * n.z), vperp = axpy3(-1.0, vpar, v);
    ga_vec3 tt = axpy3(k / tw, cross3(n, v), axpy3(sn / tw, vperp, vpar));
    double kx = k * n.x, ky = k * n.y, kz = k * n.z, sx = sn * n.x, sy = sn * n.y, sz = sn * n.z;
    /* clang-format off */
    ga_mat4 rr = {{co + kx * n.x, kx * n.y - sz, kx * n.z + sy, tt.x,
                   ky * n.x + sz, co + ky * n.y, ky * n.z - sx, tt.y,
                   kz * n.x - sy, kz * n.y + sx, co + kz * n.z, tt.z,
                   0.0, 0.0, 0.0, 1.0}};
    /* clang-format on */
    return rr;
}

ga_mat4 ga_se3_exp(ga_twist xi)
{
    ga_vec3 w = xi.w, v = xi.v;
    /* th = |w| (w.w overflows only for |w| > 1e154: se3_exp_huge, tested in
     * the branch that calls sin and cos anyway, so the series stays a leaf) */
    double t2 = dot3(w, w), th = sqrt(t2), a, b, c, co;
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
        if (isinf(t2))
            return se3_exp_huge(w, v);
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
    /* clang-format off */
    ga_mat4 r = {{co + bx * w.x, bx * w.y - az, bx * w.z + ay, t.x,
                  by * w.x + az, co + by * w.y, by * w.z - ax, t.y,
                  bz * w.x - ay, bz * w.y + ax, co + bz * w.z, t.z,
                  0.0, 0.0, 0.0, 1.0}};
    /* clang-format on */
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

ga_status ga_se3_log(ga_mat4 m, ga_twist *out)
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

ga_status ga_se3_geodesic(ga_mat4 h0, ga_mat4 h1, double t, ga_mat4 *out)
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

/* ---- general exp: scaling and squaring (Al-Mohy & Higham 2009) --------- */

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

/* s + e = a + b exactly (Knuth's two-sum) */
static void two_sum(double a, double b, double *s, double *e)
{
    double t = a + b, bb = t - a;
    *s = t;
    *e = (a - (t - bb)) + (b - bb);
}

/* a sum of products s + c carried to about twice the working precision
 * (Ogita, Rump & Oishi 2005, Dot2): each product's rounding error by fma,
 * each addition's by two_sum, gathered in c */
typedef struct {
    double s, c;
} dot2;

static inline void dot2_add(dot2 *a, double x, double y)
{
    double p = x * y, s, e;
    two_sum(a->s, p, &s, &e);
    a->c += e + fma(x, y, -p);
    a->s = s;
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
             * the result once, to first order, instead of being amplified
             * (scipy's 2x2 [1.47 5.86; -1.28 3.40], exp through the angle
             * nu = 2.56: 4.5u without, 1.1u with) */
            double m, dm, hd, dhd;
            two_sum(b11, b22, &m, &dm);
            two_sum(b11, -b22, &hd, &dhd);
            m *= 0.5;
            dm *= 0.5;
            hd *= 0.5;
            dhd *= 0.5;
            double p1 = hd * hd, p2 = b12 * b21, q, dq;
            two_sum(p1, p2, &q, &dq);
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

ga_status ga_mat4_expm(ga_mat4 a, ga_mat4 *out)
{
    /* theta_m: the largest alpha for which r_m(A) = e^(A + E) with
     * ||E|| <= 2^-53 ||A|| (Higham 2005, Table 2.3) for m <= 9, and
     * theta_13 = 4.25 of Al-Mohy & Higham 2009, Table 3.1 (and scipy), not
     * Higham 2005's 5.37: near 5.37 the rounding in evaluating r_13 and
     * solving with q_13 dominates the truncation error (scipy's
     * test_burkardt_12 and three other dense 3x3 and 4x4 inputs lost 3 to 5
     * times scipy's accuracy with 5.37, one squaring fewer). b: the coefficients of the Pade numerator
     * p_m(x) = sum b_j x^j, scaled to integers, with q_m(x) = p_m(-x).
     * log2c: log2 of c_{2m+1} = (m!)^2 / ((2m)! (2m+1)!). */
    static const double theta[5] = {1.495585217958292e-2, 2.539398330063230e-1, 9.504178996162932e-1,
                                    2.097847961257068e0, 4.25};
    static const double log2c[5] = {-16.621136113, -33.227772657, -51.994974307, -72.324718099,
                                    -116.447004252};
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

    if (!mat4_isfinite(&a))
        return GA_ERR_NOTFINITE;
    /* A homogeneous generator (last row 0): every power and U have last row
     * 0, I and V have (0 0 0 c): all products are block triangular
     * (mat4_mul_ut), and the Pade solve is 3x3 (expm_solve3). */
    int h = M(a, 3, 0) == 0.0 && M(a, 3, 1) == 0.0 && M(a, 3, 2) == 0.0 && M(a, 3, 3) == 0.0;
    /* exp(A) = e^mu exp(A - mu I): with mu = trace(A)/4 > 0 where that
     * lowers ||A||_1 and ||A||_1 > 1 (Higham, Functions of Matrices, 2008,
     * sec. 10.7.3; below 1 no squaring is saved and e^mu only rounds:
     * 1u more on scipy's small 4x4). scipy's shifted test matrices B + cI, c = 2.3 to 5.8:
     * 2.0e-15 to 3.4e-15 unshifted (one or two more squarings of a
     * growing r_m) against 1.7e-16 to 2.4e-16. Not for mu < 0, where the
     * squarings of a contracting r_m lose nothing and e^mu alone would
     * round (scipy's matrices lost up to 3x); not for a homogeneous
     * generator, whose last row stays 0. */
    double mu = 0.0;
    if (!h) {
        mu = 0.25 * (M(a, 0, 0) + M(a, 1, 1) + M(a, 2, 2) + M(a, 3, 3));
        ga_mat4 b = mat4_add_id(a, -mu);
        if (mu > 0.0 && mat4_isfinite(&b) && norm1_finite(&a) > 1.0 && norm1_finite(&b) < norm1_finite(&a))
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
        mat4_scale2(&a, -s);
        n1 = norm1_finite(&a);
    }
    /* d_k = ||A^k||_1^(1/k) (exact norms: the powers are needed anyway), and
     * the choice of m and s of Al-Mohy & Higham 2009, Alg. 5.1: eta from the
     * d_k, which for a nonnormal A are much below ||A||_1 and avoid the
     * overscaling of Higham 2005 (Moler's badly scaled matrix), with ell()
     * guarding against a nonnormal |A| that makes the eta bound optimistic. */
    ga_mat4 a2 = mat4_mul_any(&a, &a, h), a4 = mat4_mul_any(&a2, &a2, h), a6 = mat4_mul_any(&a4, &a2, h);
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
    double n4 = norm1_finite(&a4), n6 = norm1_finite(&a6);
    int idx = -1;
    for (int c = 0; c < 4 && idx < 0; c++) {
        if (n4 <= theta4[c] && n6 <= theta6[c] &&
            (n1 <= ell_free[c] || (c == 3 && expm_ell(&a, n1, degree[c], log2c[c]) == 0)))
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
            ga_mat4 a8 = mat4_mul_any(&a4, &a4, h), a10 = mat4_mul_any(&a4, &a6, h);
            double d6 = pow(n6, 1.0 / 6.0), d8 = pow(norm1_finite(&a8), 0.125),
                   d10 = pow(norm1_finite(&a10), 0.1);
            double eta5 = fmin(fmax(d6, d8), fmax(d8, d10));
            s1 = eta5 > theta[4] ? (int)ceil(log2(eta5 / theta[4])) : 0;
        }
        double ns = ldexp(n1, -s1); /* ||2^-s1 A||_1, exactly */
        if (!(ns <= ell_free[4])) {
            ga_mat4 as = a;
            mat4_scale2(&as, -s1);
            s1 += expm_ell(&as, ns, 13, log2c[4]);
        }
        idx = 4;
        if (s1 > 0) { /* scaled powers: exact powers of 2 */
            mat4_scale2(&a, -s1);
            mat4_scale2(&a2, -2 * s1);
            mat4_scale2(&a4, -4 * s1);
            mat4_scale2(&a6, -6 * s1);
        }
        s += s1;
    }

    /* r_m = (V - U)^{-1} (V + U), U the odd and V the even part of p_m. */
    const double *b = coef[idx];
    int m = degree[idx];
    ga_mat4 id = ga_mat4_identity(), v, u0; /* U = A U0 */
    if (m < 13) {
        /* U0 = sum b_{2k+1} A^{2k}, V = sum b_{2k} A^{2k}, entry by entry in
         * one pass (A^8 only for m = 9; the missing powers are 0 terms) */
        ga_mat4 a8 = mat4_zero();
        if (m == 9)
            a8 = mat4_mul_any(&a4, &a4, h);
        double bb[10] = {0};
        for (int k = 0; k <= m; k++) bb[k] = b[k];
        for (int i = 0; i < 16; i++) {
            u0.m[i] = bb[1] * id.m[i] + bb[3] * a2.m[i] + bb[5] * a4.m[i] + bb[7] * a6.m[i] + bb[9] * a8.m[i];
            v.m[i] = bb[0] * id.m[i] + bb[2] * a2.m[i] + bb[4] * a4.m[i] + bb[6] * a6.m[i] + bb[8] * a8.m[i];
        }
    } else { /* Higham's m = 13 scheme: 6 matrix products instead of 12 */
        ga_mat4 w = mat4_zero();
        v = mat4_zero();
        u0 = mat4_zero();
        mat4_acc(&w, b[13], &a6);
        mat4_acc(&w, b[11], &a4);
        mat4_acc(&w, b[9], &a2);
        u0 = mat4_mul_any(&a6, &w, h);
        mat4_acc(&u0, b[7], &a6);
        mat4_acc(&u0, b[5], &a4);
        mat4_acc(&u0, b[3], &a2);
        mat4_acc(&u0, b[1], &id);
        w = mat4_zero();
        mat4_acc(&w, b[12], &a6);
        mat4_acc(&w, b[10], &a4);
        mat4_acc(&w, b[8], &a2);
        v = mat4_mul_any(&a6, &w, h);
        mat4_acc(&v, b[6], &a6);
        mat4_acc(&v, b[4], &a4);
        mat4_acc(&v, b[2], &a2);
        mat4_acc(&v, b[0], &id);
    }
    ga_mat4 u = mat4_mul_any(&a, &u0, h), den = v, x;
    mat4_acc(&den, -1.0, &u);
    /* X = r_m - I = 2 (V - U)^{-1} U: no cancellation for r_m near I. But
     * for a contracting r_m (a diagonal entry below 3/4, where the squaring
     * below goes plain at once) r_m itself, (V - U)^{-1} (V + U), as scipy
     * computes it: I + X rounds r_m's small entries to eps absolute
     * (scipy's test_burkardt_12, e^-1, e^-2, e^-20 through six squarings:
     * 2.8e-13 against 1.0e-14, scipy 7.1e-14). Predicted from the diagonal
     * of 2^-s A (one solve, not two, for most inputs), and checked on X. */
    int plain = a.m[0] < -0.25 || a.m[5] < -0.25 || a.m[10] < -0.25 || a.m[15] < -0.25;
    ga_mat4 rhs = u;
    double c = 2.0;
    for (int pass = 0; pass < 2; pass++) {
        if (plain) { /* D r = V + U; for h, r = [R t; 0 1] and D3 t = 2 u, t as in X */
            rhs = v;
            mat4_acc(&rhs, 1.0, &u);
            if (h)
                for (int i = 0; i < 3; i++) M(rhs, i, 3) = 2.0 * M(u, i, 3);
            c = 1.0;
        }
        if (!(h && expm_solve3(&den, &rhs, c, &x))) {
            lu4 f;
            /* q_m(A) is well conditioned for alpha <= theta_m (Higham
             * 2005): this failure is a guard, not an expected path. */
            if (lu4_factor(den, &f) != GA_OK)
                return GA_ERR_DOMAIN;
            x = lu4_solve(&f, rhs);
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

    /* Squaring. (I + X)^2 = I + (2X + X^2) keeps relative accuracy in X when
     * the result is near I; e.g. a rotation block R = I + O(1e-12) under a
     * translation 1e6 needs 18 squarings, and plain squaring would lose the
     * rounding of R's diagonal doubled 18 times (about 1e-11 relative in t).
     * Once a diagonal entry 1 + x of the result falls below 3/4 (contraction),
     * plain squaring is better: per step the X form rounds like
     * eps (2|x| + x^2) and the plain form like eps (1 + x)^2, which is smaller
     * for x < -1/4; near 0 the plain form keeps relative accuracy. With h the
     * last row is 0 in X and e_4^T in I + X: products stay block triangular. */
    int bs[4], bz[4], nb = qt_blocks(&a, bs, bz);
    if (nb)
        expm_fix_blocks(&x, &a, 0, plain, bs, bz, nb);
    for (int k = 0; k < s; k++) {
        if (!plain &&
            (M(x, 0, 0) < -0.25 || M(x, 1, 1) < -0.25 || M(x, 2, 2) < -0.25 || M(x, 3, 3) < -0.25)) {
            x = mat4_add_id(x, 1.0);
            plain = 1;
        }
        ga_mat4 x2 = mat4_mul_any(&x, &x, h);
        if (!plain)
            mat4_acc(&x2, 2.0, &x);
        x = x2;
        if (!mat4_isfinite(&x))
            return GA_ERR_DOMAIN; /* overflow: stop before Inf - Inf */
        if (nb)
            expm_fix_blocks(&x, &a, k + 1, plain, bs, bz, nb);
    }
    if (!plain) {
        x = mat4_add_id(x, 1.0);
        /* 1 + expm1(l) rounds e^l to eps absolute, not relative (e^-5.4 =
         * 0.0047 then carries 20 u): the blocks once more as exp itself */
        if (nb)
            expm_fix_blocks(&x, &a, s, 1, bs, bz, nb);
    }
    if (mu > 0.0) {
        double em = exp(mu);
        for (int i = 0; i < 16; i++) x.m[i] *= em;
    }
    if (!mat4_isfinite(&x))
        return GA_ERR_DOMAIN;
    *out = x;
    return GA_OK;
}

/* ---- general log: real Schur form, inverse scaling and squaring -------- */

/* The real Schur form of the leading n x n block of t (n = 3 or 4): t is
 * overwritten by Q^T t Q, upper quasi-triangular with 1x1 blocks (real
 * eigenvalues) and 2x2 blocks (complex pairs), and q by q Q. Householder
 * reduction to Hessenberg form, then Francis double-shift QR steps with
 * deflation (Golub & Van Loan, Matrix Computations, Alg. 7.4.2 and 7.5.1).
 * A 2x2 block with real eigenvalues is split by one rotation whose first
 * column is an eigenvector. GA_ERR_DOMAIN if QR does not converge (a guard:
 * 300 steps per deflation, LAPACK dlahqr's 30 max(10, n); a nearly
 * defective cluster, e^X - I for a nilpotent X, needed more than 30). */
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
     * I - beta v v^T is orthogonal to about 2u. Rounded plainly it was off
     * by up to 9.5u (measured over random x), and the Schur vectors of a
     * few dozen reflectors lost 10 to 20u of orthogonality, which
     * Q log(T) Q^T carries into the log: 4.8e-15 against 9.6e-16 on scipy's
     * near-identity 3x3 (its log has entries 1e-3; A - I is exact). */
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
     * shift column of 0 and no progress (found by fuzz/fuzz_numeric;
     * fuzz/regress/numeric/logm-expm-graded-tiny replays it). */
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
        if (++iter >
            300) /* found by fuzz/fuzz_numeric at 30; fuzz/regress/numeric/logm-expm-nilpotent-slow-qr */
            return GA_ERR_DOMAIN;
        /* The first column of (H - s1 I)(H - s2 I), s1 + s2 = s, s1 s2 = p,
         * from the active window divided by its largest entry g: only its
         * direction matters, and unscaled, a window of entries near 1e-298
         * (eigenvalues of A - I that small) would square to 0 and the
         * iteration would stall (found by fuzz/fuzz_numeric;
         * fuzz/regress/numeric/logm-expm-tiny-entries replays it). */
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

/* The real Schur form of A - sig I (its leading n x n block; t and q as for
 * schur_real, t then holding T - sig I), scaled by a power of 2 so that QR's
 * products neither underflow nor overflow: a rotation of 1e-300 rad has
 * A - I of 1e-300. Not an upper triangular t, which is its own Schur form:
 * scaling down rounds subnormal entries (a diagonal 2e-322 beside 2 lost a
 * bit; found by fuzz/fuzz_numeric, fuzz/regress/numeric/logm-diagonal-
 * subnormal). */
static int schur_shifted(const ga_mat4 *a, int n, double sig, double t[4][4], double qm[4][4])
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

/* t (log y - log x)/(y - x) for eigenvalues x, y > 0 given with their logs
 * lx, ly and their difference d = y - x (each from the form, T or T - I,
 * that holds them accurately), without cancellation: for close x and y the
 * divided difference is 2 atanh(z)/(y - x), z = (y - x)/(y + x) (Higham,
 * Functions of Matrices, 2008, eq. 11.28, with no unwinding term for real
 * positive x, y). t is multiplied in before the division: the divided
 * difference alone overflows for subnormal eigenvalues (1/x for x = 1e-312;
 * found by fuzz/fuzz_numeric, fuzz/regress/numeric/logm-diagonal-subnormal-pair). */
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

ga_status ga_mat4_logm(ga_mat4 a, ga_mat4 *out)
{
    /* [8/8] Pade approximant of log(1 + x) in partial fractions: 8-point
     * Gauss-Legendre on log(I + X) = int_0^1 X (I + t X)^{-1} dt (Higham 2001).
     * It is used once alpha_p(X) = max(||X^p||^(1/p), ||X^(p+1)||^(1/(p+1)))
     * is at most theta_8 = 0.3666532675959788 for p = 3 or p = 4, which
     * bounds its backward error by u = 2^-53 (Al-Mohy & Higham 2012, Table
     * 2.1 and Thm. 2.2 with p(p - 1) <= 2m + 1 = 17). */
    static const double node[8] = {1.98550717512318842e-02, 1.01666761293186636e-01, 2.37233795041835505e-01,
                                   4.08282678752175110e-01, 5.91717321247824946e-01, 7.62766204958164495e-01,
                                   8.98333238706813364e-01, 9.80144928248768088e-01};
    static const double weight[8] = {
        5.06142681451881293e-02, 1.11190517226687241e-01, 1.56853322938943635e-01, 1.81341891689180995e-01,
        1.81341891689180995e-01, 1.56853322938943635e-01, 1.11190517226687241e-01, 5.06142681451881293e-02};
    const double theta8 = 0.3666532675959788;

    if (!mat4_isfinite(&a))
        return GA_ERR_NOTFINITE;
    lu4 f;
    if (lu4_factor(a, &f) != GA_OK) {
        /* numerically singular. A negative determinant (the LU's, run to
         * the end) is an odd number of negative real eigenvalues (a complex
         * pair gives |l|^2 > 0): no real logarithm at all, GA_ERR_DOMAIN, as
         * for a well-conditioned A below; only det >= 0 is GA_ERR_SINGULAR
         * (an ill-conditioned block with eigenvalues 5.1e15, 38, -4.5, a
         * lihao2 factor on affine keys, met the pivot test first and was
         * GA_ERR_SINGULAR) */
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
        se3_check(&a, GA_MAT4_LOGM_RIGID_TOL) == GA_OK) {
        if (M(a, 2, 1) == M(a, 1, 2) && M(a, 0, 2) == M(a, 2, 0) && M(a, 1, 0) == M(a, 0, 1))
            return GA_ERR_DOMAIN;
        ga_twist xi = se3_log_core(&a);
        /* v = V^{-1} t overflows for a translation near DBL_MAX, as in
           ga_se3_log (found by fuzz/fuzz_numeric;
           fuzz/regress/numeric/logm-rigid-translation-overflow) */
        ga_mat4 l = ga_twist_hat(xi);
        if (!mat4_isfinite(&l))
            return GA_ERR_DOMAIN;
        *out = l;
        return GA_OK;
    }
    int n = h ? 3 : 4;
    double sig = 1.0; /* t holds T - sig I */
    if (schur_shifted(&a, n, 1.0, t, qm) != GA_OK) {
        /* the form of A - I did not converge (a guard: a cluster of
         * eigenvalues equal to rounding, 1e-4 (I + E) with E of 1e-10 and
         * below, once did not; found by fuzz/fuzz_numeric,
         * fuzz/regress/numeric/logm-scaled-expm-tiny-schur-fallback and
         * logm-scaled-expm-cluster-mean-shift): the form of A - sig I,
         * sig the mean of the diagonal, whose entries are the cluster's
         * spread, resolved after scaling */
        sig = 0.0;
        for (int i = 0; i < n; i++) sig += M(a, i, i) / n;
        if (schur_shifted(&a, n, sig, t, qm) != GA_OK) {
            /* Neither converged (the case seen: 1e-4 e^X, a cluster of
             * three eigenvalues at 1e-4 coupled by entries of 1e-15 in a
             * cycle, beside entries of 1e-302 and subnormals; found by
             * fuzz_numeric, fuzz/regress/numeric/logm-scaled-expm-qr-stall).
             * A fallback without a Schur form: inverse scaling and squaring
             * on A itself, square roots by the Denman-Beavers iteration
             * (Higham, "Functions of Matrices", 6.15), then the Pade step on
             * X = A^(1/2^k) - I once ||X||_1 <= theta_8, log A = 2^k log(I + X).
             * X is carried as X <- (Y + I)^{-1} X, not formed by
             * subtraction, whose absolute error of a few eps made the result
             * accurate only to about 2^k eps ||log A||; the domain (no
             * eigenvalue on the closed negative axis) shows as a failing
             * iteration. */
            ga_mat4 y = a, x = mat4_add_id(a, -1.0);
            int k = 0;
            for (; k < 64 && !(ga_mat4_norm1(x) <= theta8); k++) {
                ga_mat4 Y = y, Z = ga_mat4_identity();
                int it = 0;
                for (; it < 64; it++) {
                    lu4 fy, fz;
                    if (lu4_factor(Y, &fy) != GA_OK || lu4_factor(Z, &fz) != GA_OK)
                        return GA_ERR_DOMAIN;
                    ga_mat4 yi = lu4_solve(&fy, ga_mat4_identity()), zi = lu4_solve(&fz, ga_mat4_identity());
                    double change = 0.0, size = 0.0;
                    for (int e = 0; e < 16; e++) {
                        double yn = 0.5 * (Y.m[e] + zi.m[e]);
                        change = fmax(change, fabs(yn - Y.m[e]));
                        size = fmax(size, fabs(yn));
                        Y.m[e] = yn;
                        Z.m[e] = 0.5 * (Z.m[e] + yi.m[e]);
                    }
                    if (!mat4_isfinite(&Y) || !mat4_isfinite(&Z))
                        return GA_ERR_DOMAIN;
                    if (change <= 4 * DBL_EPSILON * size)
                        break;
                }
                if (it == 64)
                    return GA_ERR_DOMAIN;
                /* X <- (Y + I)^{-1} X, as Z in the Schur path: the root's
                 * A^(1/2^k) - I without the subtraction's absolute error */
                lu4 fr;
                if (lu4_factor(mat4_add_id(Y, 1.0), &fr) != GA_OK)
                    return GA_ERR_DOMAIN;
                x = lu4_solve(&fr, x);
                y = Y;
            }
            if (k == 64)
                return GA_ERR_DOMAIN;
            ga_mat4 l = mat4_zero();
            for (int j = 0; j < 8; j++) {
                ga_mat4 d = x;
                for (int i = 0; i < 16; i++) d.m[i] *= node[j];
                if (lu4_factor(mat4_add_id(d, 1.0), &f) != GA_OK)
                    return GA_ERR_DOMAIN; /* a guard: rho(t X) < 0.37 */
                ga_mat4 term = lu4_solve(&f, x);
                mat4_acc(&l, weight[j], &term);
            }
            mat4_scale2(&l, k);
            if (h)
                M(l, 3, 0) = M(l, 3, 1) = M(l, 3, 2) = M(l, 3, 3) = 0.0;
            if (!mat4_isfinite(&l))
                return GA_ERR_DOMAIN;
            *out = l;
            return GA_OK;
        }
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
            memcpy(ts, t, sizeof t);
            memcpy(qs, qm, sizeof qm);
            if (schur_shifted(&a, n, 0.0, t, qm) == GA_OK)
                sig = 0.0;
            else { /* a guard, as above: keep the form of A - I */
                memcpy(t, ts, sizeof t);
                memcpy(qm, qs, sizeof qm);
            }
        }
    }
    /* Q brought back to orthogonal by one Newton-Schulz step
     * Q <- Q - Q (Q^T Q - I) / 2, and T recomputed from it as
     * Q^T (A - sig I) Q on and above the block diagonal. The rounding of a
     * few dozen reflector updates leaves Q^T Q - I and the residual
     * Q T Q^T - (A - sig I) near 10 to 30u, which Q log(T) Q^T carries into
     * the log; after this step both are a few u (measured against the
     * 80-digit logs of scipy's 4x4 matrices: 15.6u to 2.5u, 10.8u to 1.8u,
     * 11.4u to 1.3u). The recomputed T is kept only where it keeps every
     * real eigenvalue's sign and every 2x2 block complex, so that the
     * domain decision below sees the QR's eigenvalue structure. The
     * products (A - sig I) Q and Q^T ((A - sig I) Q) are summed by dot2,
     * the first kept as an unevaluated sum bq + bql: T then carries one
     * rounding per entry instead of one per product and addition (scipy's
     * random 4x4 with eigenvalues 1.15, 0.54, -0.63 +- 1.23i, whose log
     * doubles the form's error: 8.1u to 6.1u, scipy's 6.9u). */
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
         * round a subnormal entry beside large ones (fuzz/regress/numeric/
         * logm-diagonal-subnormal). Large entries whose products overflow
         * keep the QR's T (keep below). */
        double bm[4][4], bmax = 0.0;
        for (int i = 0; i < n; i++)
            for (int j = 0; j < n; j++) {
                bm[i][j] = M(a, i, j) - (i == j ? sig : 0.0);
                bmax = fmax(bmax, fabs(bm[i][j]));
            }
        int es = bmax > 0.0 && bmax < 1.0 ? ilogb(bmax) : 0;
        for (int i = 0; i < n; i++)
            for (int j = 0; j < n; j++) {
                dot2 acc = {0.0, 0.0};
                for (int r = 0; r < n; r++) dot2_add(&acc, ldexp(bm[i][r], -es), qn[r][j]);
                bq[i][j] = acc.s + acc.c;
                bql[i][j] = acc.c - (bq[i][j] - acc.s);
            }
        memcpy(tn, t, sizeof tn);
        int keep = 1;
        for (int i = 0; i < n; i++)
            for (int j = i > 0 && t[i][i - 1] != 0.0 ? i - 1 : i; j < n; j++) {
                dot2 acc = {0.0, 0.0};
                for (int r = 0; r < n; r++) {
                    dot2_add(&acc, qn[r][i], bq[r][j]);
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
    const int shifted = sig == 1.0;
    if (h)
        for (int i = 0; i < 3; i++)
            t[i][3] = qm[0][i] * M(a, 0, 3) + qm[1][i] * M(a, 1, 3) + qm[2][i] * M(a, 2, 3);
    /* the eigenvalue 1 of A's last row when A is homogeneous, less sig */
    if (h)
        t[3][3] = 1.0 - sig;

    /* The blocks, and the domain decided from the eigenvalues: a real
     * eigenvalue <= 0 has no real principal log (0 is caught above as
     * singular); a complex pair always has one. lambda = sig + t_ii. */
    const double lam1 = sig;
    int bs[4], bz[4], nb = 0;
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

    /* Inverse scaling and squaring on T: T_k = T^(1/2^k) and Z = T_k - I,
     * carried as Z <- (T_{k+1} + I)^{-1} Z (the factors commute) rather than
     * formed by subtraction, which would round away small parts (a scaling
     * 1 + 1e-10 under a translation of 1e6; this is the accurate T_k - I of
     * Al-Mohy & Higham 2012, sec. 5, for the whole matrix). Square roots
     * are taken while the spectral radius of Z exceeds theta_8, then while
     * alpha_3(Z) and alpha_4(Z) both do. */
    double tk[4][4], z[4][4];
    memcpy(tk, t, sizeof t);
    memcpy(z, t, sizeof t);
    for (int i = 0; i < 4; i++) {
        tk[i][i] += lam1;      /* T */
        z[i][i] -= 1.0 - lam1; /* T - I */
    }
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
        if (lu4_factor(mat4_add_id(rp, 1.0), &f) != GA_OK)
            return GA_ERR_DOMAIN; /* a guard: R + I has eigenvalues with real part > 1 */
        ga_mat4 zn = lu4_solve(&f, mat4_of(z));
        memcpy(z, zn.m, sizeof z);
        memcpy(tk, r, sizeof r);
    }
    /* Z's blocks above the block diagonal are T_k's own (I has none
     * there), as the square-root recurrence gave them: carried through the
     * solves above they gather the rounding of each (the corner of the
     * peer matrix with eigenvalues 0.30-0.32 and off-diagonals 3e5:
     * 8.5u, against 0 from T_k). The diagonal blocks keep the carried
     * form, whose small parts subtraction would lose. */
    for (int b = 0; b < nb; b++)
        for (int b2 = b + 1; b2 < nb; b2++)
            for (int u = 0; u < bz[b]; u++)
                for (int v = 0; v < bz[b2]; v++) z[bs[b] + u][bs[b2] + v] = tk[bs[b] + u][bs[b2] + v];
    ga_mat4 zm = mat4_of(z), l = mat4_zero();
    for (int j = 0; j < 8; j++) {
        ga_mat4 d = zm;
        for (int i = 0; i < 16; i++) d.m[i] *= node[j];
        if (lu4_factor(mat4_add_id(d, 1.0), &f) != GA_OK)
            return GA_ERR_DOMAIN; /* a guard: rho(t Z) < 0.37 */
        ga_mat4 term = lu4_solve(&f, zm);
        mat4_acc(&l, weight[j], &term);
    }
    mat4_scale2(&l, k);

    /* The diagonal blocks of log T exactly from T's own (Al-Mohy & Higham
     * 2012, sec. 5: recomputing them removes the error of the roots and of
     * the Pade step where it matters most): log t_ii, or for a complex pair
     * a +- iw, log|.| I + (arg/w) N with arg = atan2(w, a) in (0, pi). The
     * superdiagonal entry between two adjacent real eigenvalues is t_ij
     * times their divided difference. */
    for (int b = 0; b < nb; b++) {
        int p = bs[b];
        if (bz[b] == 1) {
            double x = lam1 + t[p][p], lx = shifted ? log1p(t[p][p]) : log(x);
            M(l, p, p) = lx;
            if (b + 1 < nb && bz[b + 1] == 1) {
                double y = lam1 + t[p + 1][p + 1], ly = shifted ? log1p(t[p + 1][p + 1]) : log(y);
                M(l, p, p + 1) = log_divdiff(t[p][p + 1], x, y, lx, ly, t[p + 1][p + 1] - t[p][p]);
            }
        } else {
            double aa, w, nm[2][2];
            blk2_parts(t, p, &aa, &w, nm);
            double re = lam1 + aa, lr = shifted ? log_abs(aa, w) : log(hypot(re, w));
            double c = w > 0.0 ? atan2(w, re) / w : 1.0 / re;
            for (int u = 0; u < 2; u++)
                for (int v = 0; v < 2; v++) M(l, p + u, p + v) = (u == v ? lr : 0.0) + c * nm[u][v];
        }
    }
    if (h) /* the last row of log [B t; 0 1] is 0, exactly */
        M(l, 3, 0) = M(l, 3, 1) = M(l, 3, 2) = M(l, 3, 3) = 0.0;

    /* log A = Q log(T) Q^T */
    ga_mat4 q = mat4_of(qm), qt;
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) M(qt, i, j) = qm[j][i];
    l = ga_mat4_mul(ga_mat4_mul(q, l), qt);
    if (h)
        M(l, 3, 0) = M(l, 3, 1) = M(l, 3, 2) = M(l, 3, 3) = 0.0;
    if (!mat4_isfinite(&l))
        return GA_ERR_DOMAIN;
    *out = l;
    return GA_OK;
}

/* Nearest rotation: Higham's Newton iteration for the orthogonal polar factor,
 * X <- (X + X^-T)/2 (Higham, "Computing the polar decomposition", 1986), from
 * X_0 = R with ||R^T R - I|| <= 1e-3: the error e_k = ||X_k^T X_k - I|| obeys
 * e_{k+1} ~ e_k^2 / 4, so three steps reach rounding; the loop stops when a
 * step changes no entry by more than 4 ulp, at most 8 steps. */
ga_status ga_se3_normalize(ga_mat4 m, double tol, ga_mat4 *out)
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
