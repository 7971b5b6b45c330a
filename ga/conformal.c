/* garotor/conformal.c: points, spheres, planes, lines and circles of the
 * conformal model (Wareham-Lasenby §1, §2.2), built by outer products and read
 * back with a status. See conformal.h for the conventions. */
#include <garotor/conformal.h>

#include <math.h>

#include "internal/eft.h"
#include "internal/object.h"
#include "internal/vec3.h"

ga_mv ga_mv_n(void) { return ga_mv_vector(0, 0, 0, 1, 1); }
ga_mv ga_mv_nbar(void) { return ga_mv_vector(0, 0, 0, 1, -1); }
ga_mv ga_mv_e4(void) { return ga_mv_blade(GA_BLADE_E4); }
ga_mv ga_mv_e5(void) { return ga_mv_blade(GA_BLADE_E5); }
ga_mv ga_mv_i3(void) { return ga_mv_blade(GA_BLADE_E123); }
ga_mv ga_mv_i5(void) { return ga_mv_blade(GA_BLADE_E12345); }
ga_mv ga_vec3_to_mv(ga_vec3 x) { return ga_mv_vector(x.x, x.y, x.z, 0, 0); }

/* Every object is homogeneous (X and k X are the same object), so the
   read-backs work on gao_unit_scaled(X): without it, squares of coefficients
   beyond ~1e154 overflowed (a dual plane 1e200 (m + d n) read back a zero
   normal with GA_OK) and below ~1e-154 underflowed (found by
   fuzz/fuzz_numeric; fuzz/regress/numeric/plane-params-huge-coefficients
   replays it). */

/* (x^2 n + 2 lambda x - lambda^2 nbar) / (2 lambda^2), coefficient by coefficient:
   e_i: x_i / lambda; e4: (x^2 - lambda^2) / (2 lambda^2); e5: (x^2 + lambda^2) / (2 lambda^2). */
static ga_mv point_up(ga_vec3 x, double lambda)
{
    ga_vec3 y = ga__v3_div(x, lambda);
    double y2 = ga__v3_dot(y, y);
    return ga_mv_vector(y.x, y.y, y.z, 0.5 * (y2 - 1.0), 0.5 * (y2 + 1.0));
}

ga_status ga_point_up_scaled(ga_vec3 x, double lambda, ga_mv *out)
{
    if (!out)
        return GA_ERR_ARG;
    if (!isfinite(lambda) || !isfinite(x.x) || !isfinite(x.y) || !isfinite(x.z))
        return GA_ERR_NOTFINITE;
    if (!(lambda > 0.0))
        return GA_ERR_ARG;
    ga_mv X = point_up(x, lambda);
    if (!ga_mv_isfinite(X))
        return GA_ERR_DOMAIN;
    *out = X;
    return GA_OK;
}

ga_mv ga_point_up(ga_vec3 x) { return point_up(x, 1.0); }

/* The down-projection (see conformal.h): X = w F(x). Writes w and y = x / lambda. */
static int down_unit(ga_mv X, double *w_out, ga_vec3 *y_out)
{
    if (!ga_mv_isfinite(X))
        return GA_ERR_NOTFINITE;
    X = gao_unit_scaled(X);
    double s = ga_mv_maxabs(X);
    if (s == 0.0 || gao_off_grade(X, 1) > GA_POINT_TOL * s)
        return GA_ERR_NOTPOINT;
    ga_vec3 e = ga__v3_of_mv(X);
    double x4 = X.c[GA_BLADE_E4], x5 = X.c[GA_BLADE_E5];
    double xn = x4 - x5; /* X.n */
    if (!(fabs(xn) > GA_POINT_TOL * s) || x5 == 0.0)
        return GA_ERR_NOTPOINT;
    /* w = -X.n + X.X / (2 X5): cancellation-free, and -X.n itself when X is null */
    double w = (ga__v3_dot(e, e) + xn * xn) / (2.0 * x5);
    ga_vec3 y = ga__v3_div(e, w);
    /* X must be w F(y) to the tolerance; this is X.X = 0 (see conformal.h) */
    double y2 = ga__v3_dot(y, y);
    if (fabs(x4 - 0.5 * w * (y2 - 1.0)) > GA_POINT_TOL * s ||
        fabs(x5 - 0.5 * w * (y2 + 1.0)) > GA_POINT_TOL * s)
        return GA_ERR_NOTPOINT;
    *w_out = w;
    *y_out = y;
    return GA_OK;
}

ga_status ga_point_down_scaled(ga_mv X, double lambda, ga_vec3 *out)
{
    if (!out)
        return GA_ERR_ARG;
    if (!isfinite(lambda))
        return GA_ERR_NOTFINITE;
    if (!(lambda > 0.0))
        return GA_ERR_ARG;
    double w;
    ga_vec3 y;
    int st = down_unit(X, &w, &y);
    if (st != GA_OK)
        return st;
    /* a large lambda can overflow the point (found by fuzz/fuzz_numeric:
       fuzz/regress/numeric/down-scaled-overflow) */
    ga_vec3 x = ga__v3_scale(y, lambda);
    if (!isfinite(x.x) || !isfinite(x.y) || !isfinite(x.z))
        return GA_ERR_DOMAIN;
    *out = x;
    return GA_OK;
}

ga_status ga_point_down(ga_mv X, ga_vec3 *out) { return ga_point_down_scaled(X, 1.0, out); }

/* ---- objects ---------------------------------------------------------------- */

/* Each object is built about its first point a and then translated to it:
   F(a) ^ F(b) ^ ... = T_a (F(0) ^ F(b - a) ^ ...) ~T_a, as T_a F(x) ~T_a = F(x + a),
   every step carried in double-double and rounded once (gao_build_about).
   Wedged directly, the coefficients (|x|^2 -+ 1)/2 of far points cancelled
   (the plane z = 1e5 read back d = 99999.928); built about a in double, the
   local rounding (u of the local size) came out to u |a| of a plane through
   points 1e6 out that passes near the origin, beyond the rounding of its own
   coefficients (a line lying in such a plane met it in a flat point). This
   way the object is as accurate as its storage (object.h), and a flat comes
   out with its e4 and e5 parts equal. */
ga_mv ga_pointpair_from_points(ga_vec3 a, ga_vec3 b) { return gao_build_about((ga_vec3[]){a, b}, 2, 0); }
ga_mv ga_circle_from_points(ga_vec3 a, ga_vec3 b, ga_vec3 c)
{
    return gao_build_about((ga_vec3[]){a, b, c}, 3, 0);
}
ga_mv ga_line_from_points(ga_vec3 a, ga_vec3 b) { return gao_build_about((ga_vec3[]){a, b}, 2, 1); }
ga_mv ga_sphere_from_points(ga_vec3 a, ga_vec3 b, ga_vec3 c, ga_vec3 d)
{
    return gao_build_about((ga_vec3[]){a, b, c, d}, 4, 0);
}
ga_mv ga_plane_from_points(ga_vec3 a, ga_vec3 b, ga_vec3 c)
{
    return gao_build_about((ga_vec3[]){a, b, c}, 3, 1);
}

/* F(c) - (r^2/2) n: e4 = (|c|^2 - r^2 - 1) / 2, e5 = (|c|^2 - r^2 + 1) / 2,
   from |c|^2 - r^2 carried in double-double: e5 rounded once and e4 = e5 - 1
   exactly where that is exact (|e5| < 2^53), so that the weight e5 - e4 is
   1 exactly; beyond, each rounded once. Rounded term by term, |c|^2 / 2
   lost u |c|^2 / 2 before r^2 cancelled it: a sphere through (or near) the
   origin 1e8 out had its weight wrong by about 1 (read back within the
   bounds of the sphere as stored, not of the sphere meant); e4 and e5 each
   rounded on their own leave the weight off by ~u |e5|, which the meet of
   two nearly concentric spheres magnifies (their circle 2e-9 off at 100). */
ga_mv ga_sphere_dual(ga_vec3 centre, double radius)
{
    ga__eft_dd q = ga__eft_dd_prod(centre.x, centre.x);
    q = ga__eft_dd_add(q, ga__eft_dd_prod(centre.y, centre.y));
    q = ga__eft_dd_add(q, ga__eft_dd_prod(centre.z, centre.z));
    q = ga__eft_dd_add(q, ga__eft_dd_neg(ga__eft_dd_prod(radius, radius)));
    ga__eft_dd m = ga__eft_dd_add(q, ga__eft_dd_sum(-1.0, 0.0)),
               p = ga__eft_dd_add(q, ga__eft_dd_sum(1.0, 0.0));
    if (!isfinite(m.hi) || !isfinite(p.hi)) { /* a square overflowed: as rounded term by term */
        ga_mv s = ga_point_up(centre);
        double h = 0.5 * radius * radius;
        s.c[GA_BLADE_E4] -= h;
        s.c[GA_BLADE_E5] -= h;
        return s;
    }
    double e5 = 0.5 * p.hi, e4 = fabs(e5) < 0x1p53 ? e5 - 1.0 : 0.5 * m.hi;
    return ga_mv_vector(centre.x, centre.y, centre.z, e4, e5);
}

ga_mv ga_plane_dual(ga_vec3 m, double d) { return ga_mv_vector(m.x, m.y, m.z, d, d); }

/* How far X is from being a multiple k Y (k > 0 if positive), relative to X:
   max |X - k Y| / max |X| with k the least-squares scale. 1 or more means "not". */
static double misfit(ga_mv X, ga_mv Y, int positive)
{
    double xy = 0.0, yy = 0.0;
    for (int i = 0; i < 32; i++) {
        xy += X.c[i] * Y.c[i];
        yy += Y.c[i] * Y.c[i];
    }
    double sx = ga_mv_maxabs(X);
    if (!(yy > 0.0) || sx == 0.0 || (positive && !(xy > 0.0)))
        return 1.0;
    return ga_mv_maxabs(ga_mv_sub(X, ga_mv_scale(Y, xy / yy))) / sx;
}

/* The vector of a dual object: X itself if a vector, X I if a 4-vector (the
   undual, whose sign makes ga_plane_from_points(a,b,c) read back (b-a) x (c-a)). */
static int dual_vector(ga_mv X, ga_mv *v)
{
    if (!ga_mv_isfinite(X))
        return GA_ERR_NOTFINITE;
    X = gao_unit_scaled(X);
    double s = ga_mv_maxabs(X);
    if (s == 0.0)
        return GA_ERR_NOTBLADE;
    if (gao_off_grade(X, 1) <= GA_POINT_TOL * s)
        *v = ga_mv_grade(X, 1);
    else if (gao_off_grade(X, 4) <= GA_POINT_TOL * s)
        *v = ga_mv_grade(ga_mv_undual(X), 1);
    else
        return GA_ERR_NOTBLADE;
    return GA_OK;
}

/* Centre and squared radius of a dual sphere s = w (F(c) - (r^2/2) n):
   w = -s.n, c = <s>_E / w, r^2 = |c|^2 - (s4 + s5) / w. */
static int dual_sphere_params(ga_mv s, ga_vec3 *centre, double *radius)
{
    double sc = ga_mv_maxabs(s);
    double w = s.c[GA_BLADE_E5] - s.c[GA_BLADE_E4];
    if (!(fabs(w) > GA_POINT_TOL * sc))
        return GA_ERR_NOTBLADE; /* a plane (or the point at infinity) */
    ga_vec3 c = ga__v3_of_mv(s);
    c = ga__v3_div(c, w);
    double r2 = ga__v3_dot(c, c) - (s.c[GA_BLADE_E4] + s.c[GA_BLADE_E5]) / w;
    /* r^2 is a difference of terms up to 2 sc / |w|: negative beyond that is imaginary */
    if (r2 < -GA_POINT_TOL * 2.0 * sc / fabs(w))
        return GA_ERR_IMAGINARY;
    *centre = c;
    *radius = sqrt(fmax(r2, 0.0));
    return GA_OK;
}

ga_status ga_sphere_params(ga_mv S, ga_vec3 *centre, double *radius)
{
    if (!centre || !radius)
        return GA_ERR_ARG;
    ga_mv s;
    int st = dual_vector(S, &s);
    return st != GA_OK ? st : dual_sphere_params(s, centre, radius);
}

/* Normal and distance of a dual plane p = w (m + d n), w > 0. */
static int dual_plane_params(ga_mv p, ga_vec3 *normal, double *distance)
{
    double sc = ga_mv_maxabs(p);
    ga_vec3 m = ga__v3_of_mv(p);
    double len = sqrt(ga__v3_dot(m, m));
    if (fabs(p.c[GA_BLADE_E4] - p.c[GA_BLADE_E5]) > GA_POINT_TOL * sc || !(len > GA_POINT_TOL * sc))
        return GA_ERR_NOTBLADE; /* a sphere (p.n != 0), or n: the plane at infinity */
    *normal = ga__v3_div(m, len);
    *distance = 0.5 * (p.c[GA_BLADE_E4] + p.c[GA_BLADE_E5]) / len;
    return GA_OK;
}

ga_status ga_plane_params(ga_mv P, ga_vec3 *normal, double *distance)
{
    if (!normal || !distance)
        return GA_ERR_ARG;
    ga_mv p;
    int st = dual_vector(P, &p);
    return st != GA_OK ? st : dual_plane_params(p, normal, distance);
}

/* The line u e45 + (p ^ u) ^ n (|u| = 1, p.u = 0). */
static ga_mv line_of(ga_vec3 u, ga_vec3 p)
{
    ga_mv L = ga_mv_op(ga_mv_op(ga_vec3_to_mv(p), ga_vec3_to_mv(u)), ga_mv_n());
    L.c[GA_BLADE_E145] += u.x;
    L.c[GA_BLADE_E245] += u.y;
    L.c[GA_BLADE_E345] += u.z;
    return L;
}

ga_status ga_line_params(ga_mv L, ga_vec3 *direction, ga_vec3 *closest)
{
    if (!direction || !closest)
        return GA_ERR_ARG;
    if (!ga_mv_isfinite(L))
        return GA_ERR_NOTFINITE;
    L = gao_unit_scaled(L);
    double s = ga_mv_maxabs(L);
    if (s == 0.0 || gao_off_grade(L, 3) > GA_POINT_TOL * s)
        return GA_ERR_NOTBLADE;
    /* L = w (u e45 + B ^ n), B = p ^ u: u from the e_i45, B from the e_ij4 and e_ij5 */
    ga_vec3 u = ga__v3(L.c[GA_BLADE_E145], L.c[GA_BLADE_E245], L.c[GA_BLADE_E345]);
    double w = sqrt(ga__v3_dot(u, u));
    if (!(w > GA_POINT_TOL * s))
        return GA_ERR_NOTBLADE; /* no direction: not a line */
    u = ga__v3_div(u, w);
    double b12 = 0.5 * (L.c[GA_BLADE_E124] + L.c[GA_BLADE_E125]) / w;
    double b13 = 0.5 * (L.c[GA_BLADE_E134] + L.c[GA_BLADE_E135]) / w;
    double b23 = 0.5 * (L.c[GA_BLADE_E234] + L.c[GA_BLADE_E235]) / w;
    /* B = p ^ u is the 3D moment p x u = (b23, -b13, b12); p = u x (p x u) */
    ga_vec3 p = ga__v3_cross(u, ga__v3(b23, -b13, b12));
    /* everything else (e123, e_ij4 != e_ij5, B not containing u) is the misfit */
    if (misfit(L, line_of(u, p), 1) > GA_POINT_TOL)
        return GA_ERR_NOTBLADE;
    *direction = u;
    *closest = p;
    return GA_OK;
}

/* The carrier of a round X (point pair, circle): the dual sphere with its centre
   and radius, <X (X ^ n)^-1>_1 (X* = sigma ^ flats through the centre, each
   orthogonal to sigma, so the flats cancel against X ^ n). */
static int carrier(ga_mv X, ga_mv flat, ga_vec3 *centre, double *radius)
{
    ga_mv inv;
    if (ga_mv_inverse(flat, &inv) != GA_OK)
        return GA_ERR_NOTBLADE;
    ga_mv sigma = ga_mv_gp(X, inv);
    double s = ga_mv_maxabs(sigma);
    if (s == 0.0 || gao_off_grade(sigma, 1) > GA_POINT_TOL * s)
        return GA_ERR_NOTBLADE;
    return dual_sphere_params(ga_mv_grade(sigma, 1), centre, radius);
}

ga_status ga_pointpair_points(ga_mv PP, ga_vec3 *a, ga_vec3 *b)
{
    if (!a || !b)
        return GA_ERR_ARG;
    if (!ga_mv_isfinite(PP))
        return GA_ERR_NOTFINITE;
    PP = gao_unit_scaled(PP);
    double s = ga_mv_maxabs(PP);
    if (s == 0.0 || gao_off_grade(PP, 2) > GA_POINT_TOL * s)
        return GA_ERR_NOTBLADE;
    ga_mv L = ga_mv_op(PP, ga_mv_n());
    ga_vec3 u, p, c;
    double r;
    if (ga_line_params(L, &u, &p) != GA_OK)
        return GA_ERR_NOTBLADE;
    int st = carrier(PP, L, &c, &r);
    if (st != GA_OK)
        return st; /* GA_ERR_IMAGINARY for an imaginary pair */
    ga_vec3 pa = ga__v3_sub(c, ga__v3_scale(u, r));
    ga_vec3 pb = ga__v3_add(c, ga__v3_scale(u, r));
    if (!(r > 0.0) || misfit(PP, ga_pointpair_from_points(pa, pb), 1) > GA_POINT_TOL)
        return GA_ERR_NOTBLADE;
    *a = pa;
    *b = pb;
    return GA_OK;
}

ga_status ga_circle_params(ga_mv C, ga_vec3 *centre, double *radius, ga_vec3 *normal)
{
    if (!centre || !radius || !normal)
        return GA_ERR_ARG;
    if (!ga_mv_isfinite(C))
        return GA_ERR_NOTFINITE;
    C = gao_unit_scaled(C);
    double s = ga_mv_maxabs(C);
    if (s == 0.0 || gao_off_grade(C, 3) > GA_POINT_TOL * s)
        return GA_ERR_NOTBLADE;
    ga_mv P = ga_mv_op(C, ga_mv_n());
    ga_vec3 m, c;
    double d, r;
    if (ga_plane_params(P, &m, &d) != GA_OK)
        return GA_ERR_NOTBLADE;
    int st = carrier(C, P, &c, &r);
    if (st != GA_OK)
        return st; /* GA_ERR_IMAGINARY for an imaginary circle */
    /* C is dual to sigma ^ pi, the carrier sphere and the plane through its centre */
    ga_mv rebuilt = ga_mv_undual(ga_mv_op(ga_sphere_dual(c, r), ga_plane_dual(m, ga__v3_dot(m, c))));
    if (misfit(C, rebuilt, 0) > GA_POINT_TOL)
        return GA_ERR_NOTBLADE;
    *centre = c;
    *radius = r;
    *normal = m;
    return GA_OK;
}
