/* ga/se3.c: SE(3) in closed form (Eberly, "Rotation representations and
 * performance issues"): the rigidity check, inverse, exp and log, the
 * geodesic, the adjoint and the nearest rigid motion. See mat4.h for what
 * each function computes and the equations it cites. */
#include <garotor/mat4.h>

#include <float.h>
#include <math.h>

#include "internal/mat4.h"
#include "internal/se3.h"
#include "internal/series.h"
#include "internal/vec3.h"

#define M GA__M

/* The series for small angles are rows of ga/internal/series.h:
 *   f_1 = sin th / th,  f_2 = (1 - cos th)/th^2,  f_3 = (th - sin th)/th^3,
 * the coefficients of expm(xi^) (Eberly eqs. 9, 19, 20), summed to k = 8 for
 * th < 1 (the first omitted term, th^18/(18+j)!, is below 1/19! < 1e-17 of
 * f_j(0) = 1/j!), and c2 = (1 - (th/2) cot(th/2)) / th^2, the coefficient of
 * V^-1 in the log (Eberly eq. 20), by its Bernoulli series for th < 1/2. */

/* ga_se3_check through a pointer: ga_se3_log and the geodesic check the
 * matrix in place instead of copying its 128 bytes for each call. */
static inline int se3_check(const ga_mat4 *m, double tol)
{
    if (!ga__mat4_isfinite(m))
        return GA_ERR_NOTFINITE;
    for (int i = 0; i < 3; i++)
        for (int j = i; j < 3; j++) { /* R^T R - I is symmetric */
            double g = M(*m, 0, i) * M(*m, 0, j) + M(*m, 1, i) * M(*m, 1, j) + M(*m, 2, i) * M(*m, 2, j) -
                       (i == j);
            if (!(fabs(g) <= tol))
                return GA_ERR_NOTRIGID; /* !(<=): a NaN tol rejects */
        }
    ga_vec3 c0 = ga__v3(M(*m, 0, 0), M(*m, 1, 0), M(*m, 2, 0));
    ga_vec3 c1 = ga__v3(M(*m, 0, 1), M(*m, 1, 1), M(*m, 2, 1));
    ga_vec3 c2 = ga__v3(M(*m, 0, 2), M(*m, 1, 2), M(*m, 2, 2));
    if (!(ga__v3_dot(c0, ga__v3_cross(c1, c2)) > 0.0))
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

/* ga_se3_exp where w.w overflows (|w| beyond ~1.3e154), out of its hot path
   (tested before the series, it slowed the common case) */
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
    ga_vec3 w2 = ga__v3(0x1p-601 * w.x, 0x1p-601 * w.y, 0x1p-601 * w.z);
    double ns = sqrt(ga__v3_dot(w2, w2)), h = ns * 0x1p600;
    double sh = sin(h), ch = cos(h), sn = 2.0 * sh * ch, k = 2.0 * sh * sh;
    double tw = 2.0 * h; /* Inf beyond DBL_MAX: sn / tw = k / tw = 0, their limits */
    ga_vec3 n = ga__v3(w2.x / ns, w2.y / ns, w2.z / ns);
    double co = ch * ch - sh * sh;
    double nv = ga__v3_dot(n, v);
    ga_vec3 vpar = ga__v3(nv * n.x, nv * n.y, nv * n.z), vperp = ga__v3_axpy(-1.0, vpar, v);
    ga_vec3 tt = ga__v3_axpy(k / tw, ga__v3_cross(n, v), ga__v3_axpy(sn / tw, vperp, vpar));
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
    double t2 = ga__v3_dot(w, w), th = sqrt(t2), a, b, c, co;
    if (th < 1.0) {
        /* the series, no trig call and no division; cos th = 1 - b th^2 (Rodrigues) */
        a = ga__series(GA__SERIES_F1, 9, t2);
        b = ga__series(GA__SERIES_F2, 9, t2);
        c = ga__series(GA__SERIES_F3, 9, t2);
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
    ga_vec3 u = ga__v3_cross(w, v);
    ga_vec3 t = ga__v3_axpy(c, ga__v3_cross(w, u), ga__v3_axpy(b, u, v));
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
    ga_vec3 s = ga__v3(0.5 * (M(*m, 2, 1) - M(*m, 1, 2)), 0.5 * (M(*m, 0, 2) - M(*m, 2, 0)),
                       0.5 * (M(*m, 1, 0) - M(*m, 0, 1)));
    double c = 0.5 * (M(*m, 0, 0) + M(*m, 1, 1) + M(*m, 2, 2) - 1.0);
    /* sn = |s| <= 1 + tol: s.s cannot overflow, and for |s| >= 2^-450 it does
     * not underflow, so its plain sqrt is exact to rounding; below, the
     * scaled norm keeps a rotation of 1e-200 rad */
    double ss = ga__v3_dot(s, s), sn = ss >= 0x1p-900 ? sqrt(ss) : ga__v3_norm(s);
    double th = atan2(sn, c); /* in [0, pi]; accurate at both ends, unlike acos(c) */
    ga_twist xi;
    if (c >= 0.0) {
        /* th <= pi/2: eq. 11, w = (th / sin th) s, and th/|s| is well
         * conditioned here (both from atan2, no series needed). |s| = 0 with
         * c >= 0 is the identity rotation. */
        xi.w = sn > 0.0 ? ga__v3_axpy(th / sn, s, ga__v3(0, 0, 0)) : ga__v3(0, 0, 0);
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
        ga_vec3 n = ga__v3(col[0], col[1], col[2]);
        double k = th / sqrt(ga__v3_dot(n, n)); /* |n| in [0.57, 2]: no over- or underflow */
        if (ga__v3_dot(n, s) < 0.0)
            k = -k; /* at th = pi exactly s = 0 and either sign is right */
        xi.w = ga__v3_axpy(k, n, ga__v3(0, 0, 0));
    }
    /* Eq. 20: v = V^{-1} t = t - w x t / 2 + c2 w x (w x t),
     * c2 = (1 - (th/2) cot(th/2)) / th^2. The closed form cancels as th -> 0,
     * so for th < 1/2 its series is summed. At
     * th <= pi, cot(th/2) >= 0 and V^{-1} is bounded. cot(th/2) needs no trig
     * call: with rho = |(sn, c)|, th/2 = atan2(sn, c)/2 has
     * cot(th/2) = (rho + c)/sn = sn/(rho - c), the first form for c >= 0 and
     * the second for c < 0, so that neither cancels (rho - c > rho for c < 0;
     * at th = pi, sn = 0 and cot = 0). */
    double c2;
    if (th < 0.5) {
        /* the Bernoulli series of c2 (row COT of series.h) to th^14: the
           next term is below 2e-18 of the first */
        c2 = ga__series(GA__SERIES_COT, 8, th * th);
    } else {
        double rho = sqrt(sn * sn + c * c);
        double cot = c >= 0.0 ? (rho + c) / sn : sn / (rho - c);
        c2 = (1.0 - 0.5 * th * cot) / (th * th);
    }
    ga_vec3 t = ga__v3(M(*m, 0, 3), M(*m, 1, 3), M(*m, 2, 3));
    ga_vec3 u = ga__v3_cross(xi.w, t);
    xi.v = ga__v3_axpy(c2, ga__v3_cross(xi.w, u), ga__v3_axpy(-0.5, u, t));
    return xi;
}

/* for ga_mat4_logm's rigid branch (ga/internal/se3.h); the calls here keep
 * the inline forms */
int ga__se3_check(const ga_mat4 *m, double tol) { return se3_check(m, tol); }
ga_twist ga__se3_log_core(const ga_mat4 *m) { return se3_log_core(m); }

ga_status ga_se3_log(ga_mat4 m, ga_twist *out)
{
    if (!out)
        return GA_ERR_ARG;
    int st = se3_check(&m, GA_SE3_TOL);
    if (st != GA_OK)
        return st;
    ga_twist xi = se3_log_core(&m);
    /* v = V^{-1} t overflows for a translation near DBL_MAX: report it, never
       return Inf or NaN */
    if (!(isfinite(xi.v.x) && isfinite(xi.v.y) && isfinite(xi.v.z)))
        return GA_ERR_DOMAIN;
    *out = xi;
    return GA_OK;
}

ga_status ga_se3_geodesic(ga_mat4 h0, ga_mat4 h1, double t, ga_mat4 *out)
{
    if (!out)
        return GA_ERR_ARG;
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
    xi.w = ga__v3_axpy(t, xi.w, ga__v3(0, 0, 0));
    xi.v = ga__v3_axpy(t, xi.v, ga__v3(0, 0, 0));
    ga_mat4 g = ga_mat4_mul(ga_se3_exp(xi), h0);
    /* a far extrapolation or a translation near DBL_MAX overflows: reported,
       never returned as Inf or NaN */
    if (!ga__mat4_isfinite(&g))
        return GA_ERR_DOMAIN;
    *out = g;
    return GA_OK;
}

ga_twist ga_se3_adjoint(ga_mat4 g, ga_twist xi)
{
    ga_vec3 rw = ga__v3(M(g, 0, 0) * xi.w.x + M(g, 0, 1) * xi.w.y + M(g, 0, 2) * xi.w.z,
                        M(g, 1, 0) * xi.w.x + M(g, 1, 1) * xi.w.y + M(g, 1, 2) * xi.w.z,
                        M(g, 2, 0) * xi.w.x + M(g, 2, 1) * xi.w.y + M(g, 2, 2) * xi.w.z);
    ga_vec3 rv = ga__v3(M(g, 0, 0) * xi.v.x + M(g, 0, 1) * xi.v.y + M(g, 0, 2) * xi.v.z,
                        M(g, 1, 0) * xi.v.x + M(g, 1, 1) * xi.v.y + M(g, 1, 2) * xi.v.z,
                        M(g, 2, 0) * xi.v.x + M(g, 2, 1) * xi.v.y + M(g, 2, 2) * xi.v.z);
    ga_twist r;
    r.w = rw;
    r.v = ga__v3_axpy(1.0, ga__v3_cross(ga__v3(M(g, 0, 3), M(g, 1, 3), M(g, 2, 3)), rw), rv);
    return r;
}

/* Nearest rotation: Higham's Newton iteration for the orthogonal polar factor,
 * X <- (X + X^-T)/2 (Higham, "Computing the polar decomposition", 1986), from
 * X_0 = R with ||R^T R - I|| <= 1e-3: the error e_k = ||X_k^T X_k - I|| obeys
 * e_{k+1} ~ e_k^2 / 4, so three steps reach rounding; the loop stops when a
 * step changes no entry by more than 4 ulp, at most 8 steps. */
ga_status ga_se3_normalize(ga_mat4 m, double tol, ga_mat4 *out)
{
    if (!out)
        return GA_ERR_ARG;
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
