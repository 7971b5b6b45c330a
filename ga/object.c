/* garotor/object.c: classification and read-back of conformal objects,
 * projection, distance and angle (Dorst-Fontijne-Mann, "Geometric Algebra for
 * Computer Science", ch. 14-15); the rotors between two objects are in
 * object_between.c. See object.h for the conventions and the accuracy
 * statement. */
#include <garotor/object.h>

#include <garotor/conformal.h>
#include <garotor/versor.h>
#include <math.h>

#include "internal/eft.h"
#include "internal/object.h"
#include "internal/vec3.h"

#define U GAO_U

static int finite3(ga_vec3 a) { return isfinite(a.x) && isfinite(a.y) && isfinite(a.z); }
static double norm3(ga_vec3 a) { return sqrt(ga__v3_dot(a, a)); }
static ga_vec3 abs3(ga_vec3 a) { return ga__v3(fabs(a.x), fabs(a.y), fabs(a.z)); }

/* What a vanishing part (v.n of a dual vector, X ^ n of a blade) says about
   the kind: FLAT when it is exactly zero (the constructors of conformal.h and
   the meets of flats leave it so), ROUND when some coefficient is beyond its
   uncertainty e, UNSURE when every one is within it: that object is a flat
   and a round alike to the accuracy of its input (a unit sphere 1e8 from the
   origin, a plane moved by arithmetic that left rounding in e4 - e5). */
enum { FLAT, ROUND, UNSURE };
static int flat_kind(ga_mv part, ga_mv e)
{
    int zero = 1, within = 1;
    for (int i = 0; i < 32; i++) {
        if (part.c[i] != 0.0)
            zero = 0;
        if (fabs(part.c[i]) > e.c[i])
            within = 0;
    }
    return zero ? FLAT : within ? UNSURE : ROUND;
}

/* Whether a flat is at infinity: its weight (a plane's normal m, a line's
   direction u, a flat point's e45 part), of norm len, known to dw, s the
   largest coefficient. Strict: EMPTY where the weight is exactly 0 (the
   meets of parallel flats give it so: meet.c's weight_to_zero);
   GA_ERR_PRECISION where it is within its own uncertainty dw of 0 (a finite
   flat and one at infinity alike to the input's accuracy); else a finite
   flat however far (a line and a plane meeting 3e9 out: the flat point's
   bounds say how well). The rough reading (a local origin for the meet)
   calls a weight within GA_POINT_TOL of s empty. */
enum { FINITE = 1 };
static int at_infinity(double len, double dw, double s, int strict)
{
    if (!strict)
        return len <= GA_POINT_TOL * s ? GA_OBJECT_EMPTY : FINITE;
    if (len == 0.0)
        return GA_OBJECT_EMPTY;
    return dw < len ? FINITE : GA_ERR_PRECISION;
}

/* A dual vector v (sphere or plane), each coefficient known to e, into o with
   its bounds (first order, the factor f covering the second where the weight
   is known to 1/4 of itself or better). */
static int read_dual(ga_mv v, ga_mv e, int strict, ga_object *o)
{
    double s = ga_mv_maxabs(v), w = v.c[GA_BLADE_E5] - v.c[GA_BLADE_E4];
    double e4 = e.c[GA_BLADE_E4], e5 = e.c[GA_BLADE_E5];
    ga_vec3 m = ga__v3_of_mv(v), em = ga__v3_of_mv(e);
    ga_mv wpart = ga_mv_zero(), we = ga_mv_zero();
    wpart.c[GA_BLADE_E5] = w;
    double dw = e4 + e5 + U * fabs(w); /* w's uncertainty, and its rounding */
    we.c[GA_BLADE_E5] = dw;
    int kind = flat_kind(wpart, we);
    if (kind == UNSURE) {
        if (strict)
            return GA_ERR_PRECISION;
        kind = fabs(w) <= 64.0 * U * s ? FLAT : ROUND; /* a rough reading */
    }
    if (kind == FLAT) { /* v.n = 0: a plane w (m + d n) */
        double len = norm3(m), dm = norm3(em);
        int at_inf = at_infinity(len, dm, s, strict);
        if (at_inf < 0)
            return at_inf;
        if (at_inf == GA_OBJECT_EMPTY) {
            o->kind = GA_OBJECT_EMPTY; /* n: the plane at infinity */
            return GA_OK;
        }
        double d = 0.5 * (v.c[GA_BLADE_E4] + v.c[GA_BLADE_E5]) / len;
        o->kind = GA_OBJECT_PLANE;
        o->direction = ga__v3_scale(m, 1.0 / len);
        o->centre = ga__v3_scale(o->direction, d);
        o->angle_err = dm / len + 4.0 * U;
        o->err = (0.5 * (e4 + e5) + fabs(d) * dm) / len + fabs(d) * o->angle_err + 4.0 * U * fabs(d);
        return GA_OK;
    }
    if (strict && !(dw <= 0.25 * fabs(w)))
        return GA_ERR_PRECISION; /* the weight is not known to 1/4 of itself */
    double q = fmin(dw / fabs(w), 0.5), f = 1.0 / ((1.0 - q) * (1.0 - q));
    /* w (F(c) - (r^2/2) n): c = <v>_E / w, r^2 = |c|^2 - (v4 + v5) / w (conformal.h) */
    ga_vec3 c = ga__v3_scale(m, 1.0 / w), ac = abs3(c);
    double P = (v.c[GA_BLADE_E4] + v.c[GA_BLADE_E5]) / w, cc = ga__v3_dot(c, c);
    ga_vec3 dc = ga__v3_add(ga__v3_scale(ga__v3_add(em, ga__v3_scale(ac, dw)), 1.0 / fabs(w)),
                            ga__v3_scale(ac, 2.0 * U));
    double dP = (e4 + e5 + fabs(P) * dw) / fabs(w) + 3.0 * U * fabs(P);
    o->kind = GA_OBJECT_SPHERE;
    o->centre = c;
    o->r2 = cc - P;
    o->err = f * norm3(dc);
    o->r2_err = f * (2.0 * ga__v3_dot(ac, dc) + dP) + 6.0 * U * (cc + fabs(P));
    return GA_OK;
}

/* sum |a_i| |b_i|: a bound of <a ~b>_0's terms */
static double abs_dot(ga_mv a, ga_mv b)
{
    double s = 0.0;
    for (int i = 0; i < 32; i++) s += fabs(a.c[i]) * fabs(b.c[i]);
    return s;
}

/* The carrier flat F = X ^ n of a round or flat blade X (grade 2 or 3), and
   its uncertainty from X's (e) and from its own rounding. */
static ga_mv carrier_flat(ga_mv X, ga_mv e, ga_mv *eF)
{
    ga_mv n = ga_mv_n();
    *eF = ga_mv_add(gao_abs_gp(e, n), ga_mv_scale(gao_abs_gp(gao_abs(X), n), U));
    return ga_mv_op(X, n);
}

/* A line w (u e45 + (p ^ u) ^ n) whose weight |u| is below GA_POINT_TOL of
   its moment (more than 1e9 from the origin), where ga_line_params, which
   takes that for no direction, does not read it: the same formulas, the
   unit direction and p = u x (p x u); NOTBLADE where the moment (b23, -b13,
   b12) has a part along u beyond GA_POINT_TOL of X (no line has one). */
static int far_line(ga_mv X, ga_vec3 u, double s, ga_vec3 *direction, ga_vec3 *closest)
{
    double w = norm3(u);
    u = ga__v3_scale(u, 1.0 / w);
    ga_vec3 M = ga__v3(0.5 * (X.c[GA_BLADE_E234] + X.c[GA_BLADE_E235]),
                       -0.5 * (X.c[GA_BLADE_E134] + X.c[GA_BLADE_E135]),
                       0.5 * (X.c[GA_BLADE_E124] + X.c[GA_BLADE_E125]));
    if (!(fabs(ga__v3_dot(M, u)) <= GA_POINT_TOL * s))
        return GA_ERR_NOTBLADE;
    *direction = u;
    *closest = ga__v3_cross(u, ga__v3_scale(M, 1.0 / w));
    return GA_OK;
}

/* A flat blade X of grade k (2: flat point, 3: line), known to e, into o. */
static int read_flat(ga_mv X, ga_mv e, int k, double s, int strict, ga_object *o)
{
    if (k == 3) { /* w (u e45 + (p ^ u) ^ n), or a line at infinity */
        ga_vec3 u = ga__v3(X.c[GA_BLADE_E145], X.c[GA_BLADE_E245], X.c[GA_BLADE_E345]);
        ga_vec3 eu = ga__v3(e.c[GA_BLADE_E145], e.c[GA_BLADE_E245], e.c[GA_BLADE_E345]);
        int at_inf = at_infinity(norm3(u), norm3(eu), s, strict);
        if (at_inf < 0)
            return at_inf;
        if (at_inf == GA_OBJECT_EMPTY) {
            o->kind = GA_OBJECT_EMPTY;
            return GA_OK;
        }
        o->kind = GA_OBJECT_LINE;
        if (norm3(u) > GA_POINT_TOL * s) {
            if (ga_line_params(X, &o->direction, &o->centre) != GA_OK)
                return GA_ERR_NOTBLADE;
        } else if (far_line(X, u, s, &o->direction, &o->centre) != GA_OK)
            return GA_ERR_NOTBLADE;
        /* the moment's coefficients e_ij4, e_ij5 over the weight |u| */
        double eb = sqrt(e.c[GA_BLADE_E124] * e.c[GA_BLADE_E124] + e.c[GA_BLADE_E134] * e.c[GA_BLADE_E134] +
                         e.c[GA_BLADE_E234] * e.c[GA_BLADE_E234]),
               w = norm3(u), p = norm3(o->centre);
        o->angle_err = norm3(eu) / w + 4.0 * U;
        o->err = eb / w + p * o->angle_err + 8.0 * U * p;
        return GA_OK;
    }
    /* w (F(p) ^ n) = w (p ^ n - e45): e_i4 = e_i5 = w p_i, e45 = -w */
    double w = -X.c[GA_BLADE_E45], dw = e.c[GA_BLADE_E45];
    ga_vec3 p = ga__v3(X.c[GA_BLADE_E14], X.c[GA_BLADE_E24], X.c[GA_BLADE_E34]);
    ga_vec3 ep = ga__v3(e.c[GA_BLADE_E14], e.c[GA_BLADE_E24], e.c[GA_BLADE_E34]);
    int at_inf = at_infinity(fabs(w), dw, s, strict);
    if (at_inf < 0)
        return at_inf;
    if (at_inf == GA_OBJECT_EMPTY) {
        o->kind = GA_OBJECT_EMPTY; /* a direction ^ n: at infinity */
        o->direction = p;
        return GA_OK;
    }
    if (!(dw <= 0.25 * fabs(w)))
        return GA_ERR_PRECISION;
    o->kind = GA_OBJECT_FLATPOINT;
    o->centre = ga__v3_scale(p, 1.0 / w);
    double f = 1.0 / (1.0 - dw / fabs(w));
    o->err = f * (norm3(ep) + norm3(o->centre) * dw) / fabs(w) + 2.0 * U * norm3(o->centre);
    return GA_OK;
}

/* A round blade X of grade k (2: point pair, 3: circle), known to e, with
   its carrier flat F known to eF: the carrier sphere sigma = X F^-1 =
   X ~F / <F ~F>_0 (conformal.c's carrier), read as a dual vector. What of
   sigma is not a vector is rounding or X is not quite a blade: up to
   GA_POINT_TOL of sigma it is taken into sigma's uncertainty, beyond it X
   is no round. */
static int read_round(ga_mv X, ga_mv e, ga_mv F, ga_mv eF, int k, int strict, ga_object *o)
{
    ga_mv Fr = ga_mv_reverse(F), aX = gao_abs(X), aF = gao_abs(F);
    double f = ga_mv_sp(F, Fr), ef = 2.0 * abs_dot(aF, eF) + 8.0 * U * abs_dot(aF, aF);
    if (strict && !(ef <= 0.25 * fabs(f)))
        return GA_ERR_PRECISION;
    if (f == 0.0)
        return GA_ERR_NOTBLADE;
    ga_mv g = ga_mv_gp(X, Fr), sigma = ga_mv_scale(g, 1.0 / f);
    ga_mv eg = ga_mv_add(ga_mv_add(gao_abs_gp(e, aF), gao_abs_gp(aX, eF)),
                         ga_mv_scale(gao_abs_gp(aX, aF), 64.0 * U));
    ga_mv es = ga_mv_scale(ga_mv_add(eg, ga_mv_scale(gao_abs(sigma), ef)), 1.0 / (fabs(f) - ef));
    double off = gao_off_grade(sigma, 1), ss = ga_mv_maxabs(sigma);
    /* beyond GA_POINT_TOL of sigma and beyond what the uncertainty makes of
       it, X is no round (a rough reading takes sigma's vector part as it is) */
    if (strict && !(off <= GA_POINT_TOL * ss) && !(off <= 4.0 * ga_mv_maxabs(es)))
        return GA_ERR_NOTBLADE;
    for (int i = 0; i < 32; i++) es.c[i] += off;
    ga_object flat;
    int st = read_dual(ga_mv_grade(sigma, 1), ga_mv_grade(es, 1), strict, o);
    if (st != GA_OK)
        return st;
    if (o->kind != GA_OBJECT_SPHERE)
        return strict ? GA_ERR_PRECISION : GA_ERR_NOTBLADE;
    ga_mv ef2 = gao_uncertainty(F, GAO_KAPPA);
    for (int i = 0; i < 32; i++) ef2.c[i] = fmax(ef2.c[i], eF.c[i]);
    if ((st = k == 2 ? read_flat(F, ef2, 3, ga_mv_maxabs(F), strict, &flat)
                     : read_dual(ga_mv_grade(ga_mv_undual(F), 1), ga_mv_grade(ga_mv_undual(ef2), 1), 1,
                                 &flat)) != GA_OK)
        return st == GA_ERR_PRECISION && !strict ? GA_ERR_NOTBLADE : st;
    if (flat.kind != (k == 2 ? GA_OBJECT_LINE : GA_OBJECT_PLANE))
        return GA_ERR_NOTBLADE;
    o->kind = k == 2 ? GA_OBJECT_POINTPAIR : GA_OBJECT_CIRCLE;
    o->direction = flat.direction;
    o->angle_err = flat.angle_err;
    return GA_OK;
}

/* read_round about the round's own centre c0 (read roughly first): there
   its coefficients are of its own size, and X ~F has no cancellation of
   c0's square; X moved there exactly (gao_translate) with its uncertainty,
   and the centre moved back. */
static int read_round_local(ga_mv X, ga_mv e, ga_mv F, ga_mv eF, int k, int strict, ga_object *o)
{
    ga_object r0;
    if (read_round(X, e, F, eF, k, 0, &r0) != GA_OK || !finite3(r0.centre) || !isfinite(r0.r2))
        return read_round(X, e, F, eF, k, strict, o);
    /* about c0, in units of lambda, a power of two near the round's size
       (and at least 1, the unit of L): x -> (x - c0) / lambda, n -> n /
       lambda, nbar -> lambda nbar. There the round's parts are of one size,
       and its uncertainty, carried in null coordinates, keeps the weight
       apart from the n parts that the move to c0 makes large. */
    ga_vec3 c0 = r0.centre, mc0 = ga__v3_scale(c0, -1.0);
    double size = sqrt(fabs(r0.r2)), lam = size >= 1.0 && isfinite(size) ? ldexp(1.0, ilogb(size)) : 1.0;
    ga_mv Y = ga_mv_grade(gao_translate(X, mc0), k);
    /* X's uncertainty moved to c0, and the rounding of the move (u of each
       coefficient of Y), in null coordinates */
    ga_mv eN = gao_abs_translate_null(gao_unc_to_null(ga_mv_add(e, ga_mv_scale(gao_abs(X), 4.0 * U * U))),
                                      mc0);
    eN = ga_mv_add(eN, gao_unc_to_null(ga_mv_scale(gao_abs(Y), U)));
    Y = gao_scale_n_nbar(Y, 1.0 / lam, lam);
    /* to lambda's units, and the rounding of that */
    ga_mv eY = ga_mv_add(gao_unc_from_null(eN, 1.0 / lam, lam), ga_mv_scale(gao_abs(Y), 2.0 * U));
    /* scale both by a power of two (exactly), Y's largest coefficient ~ 1 */
    int ex;
    frexp(ga_mv_maxabs(Y), &ex);
    for (int i = 0; i < 32; i++) {
        Y.c[i] = ldexp(Y.c[i], -ex);
        eY.c[i] = ldexp(eY.c[i], -ex);
    }
    ga_mv eFY, FY = carrier_flat(Y, eY, &eFY);
    int st = read_round(Y, eY, FY, eFY, k, strict, o);
    if (st != GA_OK)
        return st;
    ga_vec3 cl = ga__v3_scale(o->centre, lam);
    o->centre = ga__v3_add(c0, cl);
    o->err = o->err * lam + U * (norm3(c0) + norm3(cl));
    o->r2 *= lam * lam;
    o->r2_err = o->r2_err * lam * lam + 2.0 * U * fabs(o->r2);
    return GA_OK;
}

/* strict = 0: the rough reading of a round too far out (a local origin for the meet) */
static int classify(ga_mv X, int strict, ga_object *o)
{
    if (!ga_mv_isfinite(X))
        return GA_ERR_NOTFINITE;
    if (ga_mv_maxabs(X) == 0.0)
        return GA_ERR_SINGULAR;
    X = gao_unit_scaled(X);
    double s = ga_mv_maxabs(X);
    int k = 1;
    while (k <= 4 && gao_off_grade(X, k) > GA_POINT_TOL * s) k++;
    if (k > 4)
        return GA_ERR_NOTBLADE;
    /* the parts of other grades are rounding (or X is no object): they
       are dropped, and added to the uncertainty of the rest */
    double off = gao_off_grade(X, k);
    X = ga_mv_grade(X, k);
    ga_object r = {GA_OBJECT_EMPTY, GA_REALITY_REAL, {0, 0, 0}, {0, 0, 0}, 0.0, 0.0, 0.0, 0.0};
    int st;
    if (k == 1 || k == 4) {
        ga_mv v = k == 1 ? X : ga_mv_grade(ga_mv_undual(X), 1), e = gao_uncertainty(v, GAO_KAPPA);
        for (int i = 0; i < 32; i++) e.c[i] += off;
        st = read_dual(v, ga_mv_grade(e, 1), strict, &r);
    } else {
        ga_mv e = gao_uncertainty(X, GAO_KAPPA), eF;
        for (int i = 0; i < 32; i++) e.c[i] += off;
        ga_mv F = carrier_flat(X, e, &eF);
        int kind = flat_kind(F, eF);
        if (kind == UNSURE && !strict)
            kind = ga_mv_maxabs(F) <= 64.0 * U * s ? FLAT : ROUND;
        if (kind == UNSURE)
            return GA_ERR_PRECISION;
        st = kind == FLAT ? read_flat(X, e, k, s, strict, &r) : read_round_local(X, e, F, eF, k, strict, &r);
    }
    if (st != GA_OK)
        return st;
    if (r.kind >= GA_OBJECT_POINTPAIR) {
        double L = fmax(1.0, norm3(r.centre) + sqrt(fabs(r.r2)));
        double band = fmax(GA_OBJECT_TANGENT_TOL * L * L, r.r2_err);
        r.reality = fabs(r.r2) <= band ? GA_REALITY_TANGENT
                  : r.r2 < 0.0         ? GA_REALITY_IMAGINARY
                                       : GA_REALITY_REAL;
    }
    if (!finite3(r.centre) || !isfinite(r.r2) || !isfinite(r.err) || !isfinite(r.r2_err))
        return GA_ERR_DOMAIN;
    *o = r;
    return GA_OK;
}

int gao_classify(ga_mv X, int strict, ga_object *o) { return classify(X, strict, o); }

ga_status ga_object_from_mv(ga_mv X, ga_object *out) { return out ? classify(X, 1, out) : GA_ERR_ARG; }

ga_status ga_object_from_mv_about(ga_mv X, ga_vec3 origin, double lambda, ga_object *out)
{
    if (!out)
        return GA_ERR_ARG;
    if (!finite3(origin) || !isfinite(lambda))
        return GA_ERR_NOTFINITE;
    if (!(lambda > 0.0))
        return GA_ERR_ARG;
    ga_object o;
    int st = classify(X, 1, &o);
    if (st != GA_OK)
        return st;
    ga_vec3 c = ga__v3_scale(o.centre, lambda);
    switch (o.kind) {
    case GA_OBJECT_EMPTY: break;
    case GA_OBJECT_PLANE: /* m.(x - origin) = lambda d: m.x = lambda d + m.origin */
        o.centre = ga__v3_scale(o.direction, ga__v3_dot(c, o.direction) + ga__v3_dot(o.direction, origin));
        break;
    case GA_OBJECT_LINE: { /* the point of the line closest to the world's origin */
        ga_vec3 q = ga__v3_add(c, origin);
        o.centre = ga__v3_sub(q, ga__v3_scale(o.direction, ga__v3_dot(q, o.direction)));
        break;
    }
    default: o.centre = ga__v3_add(c, origin); /* rounds and flat points */
    }
    o.r2 *= lambda * lambda;
    o.r2_err = o.r2_err * lambda * lambda + 2.0 * U * fabs(o.r2);
    o.err = o.err * lambda + 4.0 * U * (norm3(o.centre) + norm3(origin));
    if (!finite3(o.centre) || !isfinite(o.r2))
        return GA_ERR_DOMAIN;
    *out = o;
    return GA_OK;
}

/* The object of O, refusing what has no nearest point, and what is not
   known to GA_OBJECT_TOL (the functions below state no bound of their own). */
int gao_read_real(ga_mv O, ga_object *o)
{
    int st = classify(O, 1, o);
    if (st != GA_OK)
        return st;
    double L = fmax(1.0, norm3(o->centre) + sqrt(fabs(o->r2)));
    if (o->err > GA_OBJECT_TOL * L || o->r2_err > GA_OBJECT_TOL * L * L)
        return GA_ERR_PRECISION;
    if (o->kind == GA_OBJECT_EMPTY)
        return GA_ERR_NOTBLADE;
    if (o->reality == GA_REALITY_IMAGINARY)
        return GA_ERR_IMAGINARY;
    return GA_OK;
}

/* Both objects of a two-object query, the first failure's status. */
int gao_read_real_pair(ga_mv A, ga_mv B, ga_object *a, ga_object *b)
{
    int st = gao_read_real(A, a);
    return st == GA_OK ? gao_read_real(B, b) : st;
}

/* Nearest point of a round of centre c and radius r in the direction d from c. */
static int onto_round(ga_vec3 c, double r, ga_vec3 d, ga_vec3 *out)
{
    double len = sqrt(ga__v3_dot(d, d));
    if (!(len > 0.0))
        return r > 0.0 ? GA_ERR_DOMAIN : (*out = c, GA_OK);
    *out = ga__v3_add(c, ga__v3_scale(d, r / len));
    return GA_OK;
}

ga_status ga_point_project(ga_vec3 x, ga_mv O, ga_vec3 *out)
{
    if (!out)
        return GA_ERR_ARG;
    ga_object o;
    int st = gao_read_real(O, &o);
    if (st != GA_OK)
        return st;
    ga_vec3 c = o.centre, u = o.direction, y = ga__v3_sub(x, c);
    double r = sqrt(fmax(o.r2, 0.0));
    switch (o.kind) {
    case GA_OBJECT_FLATPOINT: *out = c; return GA_OK;
    case GA_OBJECT_PLANE:
        *out = ga__v3_sub(x, ga__v3_scale(u, ga__v3_dot(u, y)));
        return GA_OK; /* x - (m.x - d) m */
    case GA_OBJECT_LINE:
        *out = ga__v3_add(c, ga__v3_scale(u, ga__v3_dot(u, y)));
        return GA_OK;                                       /* p + ((x - p).u) u */
    case GA_OBJECT_SPHERE: return onto_round(c, r, y, out); /* c + r (x - c)/|x - c| */
    case GA_OBJECT_CIRCLE: return onto_round(c, r, ga__v3_sub(y, ga__v3_scale(u, ga__v3_dot(u, y))), out);
    default: /* the pair c -+ r u: the nearer one */
        *out = ga__v3_add(c, ga__v3_scale(u, ga__v3_dot(u, y) >= 0.0 ? r : -r));
        return GA_OK;
    }
}

ga_status ga_point_reject(ga_vec3 x, ga_mv O, ga_vec3 *out)
{
    if (!out)
        return GA_ERR_ARG;
    ga_vec3 p;
    int st = ga_point_project(x, O, &p);
    if (st == GA_OK)
        *out = ga__v3_sub(x, p);
    return st;
}

ga_status ga_point_distance(ga_vec3 x, ga_mv O, double *out)
{
    if (!out)
        return GA_ERR_ARG;
    ga_vec3 d;
    int st = ga_point_reject(x, O, &d);
    if (st == GA_OK)
        *out = sqrt(ga__v3_dot(d, d));
    return st;
}

/* The angle in [0, pi/2] between two lines of directions a and b:
   atan2(|a ^ b|, |a . b|), the sine from the wedge (cross product) and the
   cosine from the inner product, accurate near 0 and near pi/2 alike (acos of
   the cosine alone loses half the digits near 0). */
static double line_angle(ga_vec3 a, ga_vec3 b)
{
    ga_vec3 x = ga__v3_cross(a, b);
    return atan2(sqrt(ga__v3_dot(x, x)), fabs(ga__v3_dot(a, b)));
}

/* a . b in double-double, for the distances of round_angle below */
static ga__eft_dd dd_dot3(ga_vec3 a, ga_vec3 b)
{
    return ga__eft_dd_add(ga__eft_dd_add(ga__eft_dd_prod(a.x, b.x), ga__eft_dd_prod(a.y, b.y)),
                          ga__eft_dd_prod(a.z, b.z));
}

/* The angle between a sphere (centre c, squared radius r2) and a plane (unit
   normal m through q), or two spheres, as atan2(sine, cosine) of the normals
   where they cross: the norm of the wedge of the normalised dual vectors and
   their inner product, written out Euclidean. With p = m.(c - q) the distance
   of the centre from the plane, cos = |p| / r and sin = sqrt(r^2 - p^2) / r; for
   two spheres, with X = r1^2 + r2^2 - |c1 - c2|^2, cos = |X| / (2 r1 r2) and
   sin = sqrt(4 r1^2 r2^2 - X^2) / (2 r1 r2) (the triangle of the radii and the
   centres' distance). The differences of squares are taken in double-double,
   so that the sine keeps its digits where the objects nearly touch or nearly
   coincide. GA_ERR_DOMAIN where the sine's square is negative: no crossing. */
static int round_angle(const ga_object *a, const ga_object *b, double *out)
{
    ga__eft_dd x, n;
    int e;
    /* every length scaled by 2^-e (exactly) to about 1, so that no square
       overflows or underflows: the angle does not depend on the scale */
    if (a->kind == GA_OBJECT_SPHERE && b->kind == GA_OBJECT_SPHERE) {
        ga__eft_dd d[3] = {ga__eft_dd_sum(a->centre.x, -b->centre.x),
                           ga__eft_dd_sum(a->centre.y, -b->centre.y),
                           ga__eft_dd_sum(a->centre.z, -b->centre.z)};
        frexp(fmax(fmax(fmax(fabs(d[0].hi), fabs(d[1].hi)), fabs(d[2].hi)), sqrt(fmax(a->r2, b->r2))), &e);
        ga__eft_dd D = {0.0, 0.0};
        for (int i = 0; i < 3; i++) {
            ga__eft_dd di = ga__eft_dd_ldexp(d[i], -e);
            D = ga__eft_dd_add(D, ga__eft_dd_mul(di, di));
        }
        double r1 = ldexp(a->r2, -2 * e), r2 = ldexp(b->r2, -2 * e);
        x = ga__eft_dd_add(ga__eft_dd_sum(r1, r2), ga__eft_dd_neg(D));
        n = ga__eft_dd_add(ga__eft_dd_prod(4.0 * r1, r2), ga__eft_dd_neg(ga__eft_dd_mul(x, x)));
    } else {
        const ga_object *sp = a->kind == GA_OBJECT_SPHERE ? a : b, *pl = a->kind == GA_OBJECT_SPHERE ? b : a;
        x = ga__eft_dd_add(dd_dot3(pl->direction, sp->centre),
                           ga__eft_dd_neg(dd_dot3(pl->direction, pl->centre)));
        frexp(fmax(fabs(x.hi), sqrt(sp->r2)), &e);
        x = ga__eft_dd_ldexp(x, -e);
        n = ga__eft_dd_add((ga__eft_dd){ldexp(sp->r2, -2 * e), 0.0}, ga__eft_dd_neg(ga__eft_dd_mul(x, x)));
    }
    if (!(n.hi >= 0.0))
        return GA_ERR_DOMAIN; /* they do not cross */
    *out = atan2(sqrt(n.hi), fabs(x.hi));
    return GA_OK;
}

ga_status ga_object_angle(ga_mv A, ga_mv B, double *out)
{
    if (!out)
        return GA_ERR_ARG;
    ga_object a, b;
    int st = gao_read_real_pair(A, B, &a, &b);
    if (st != GA_OK)
        return st;
    int fa = a.kind == GA_OBJECT_PLANE || a.kind == GA_OBJECT_LINE;
    int fb = b.kind == GA_OBJECT_PLANE || b.kind == GA_OBJECT_LINE;
    if (fa && fb) {
        ga_vec3 u = a.direction, v = b.direction, x = ga__v3_cross(u, v);
        /* a line and a plane: the complement of the angle of direction and
           normal, atan2(|u . v|, |u ^ v|) with no subtraction from pi/2 */
        *out = a.kind == b.kind ? line_angle(u, v) : atan2(fabs(ga__v3_dot(u, v)), sqrt(ga__v3_dot(x, x)));
        return GA_OK;
    }
    if ((a.kind == GA_OBJECT_SPHERE || a.kind == GA_OBJECT_PLANE) &&
        (b.kind == GA_OBJECT_SPHERE || b.kind == GA_OBJECT_PLANE))
        return round_angle(&a, &b, out);
    return GA_ERR_NOTBLADE;
}
