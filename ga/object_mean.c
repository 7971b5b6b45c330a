/* garotor/object_mean.c: the weighted mean of conformal objects of one kind,
 * by direct averaging (Hadfield and Lasenby, "Direct linear interpolation of
 * geometric objects in conformal geometric algebra", Adv. Appl. Clifford
 * Algebras 29, 2019; clifford's average_objects): the weighted sum of the
 * objects, each normalised to |<X ~X>_0| = 1, projected back onto the blades
 * by the square root of a scalar plus 4-vector (Dorst and Valkenburg, "Square
 * root and logarithm of rotors in 3D conformal geometric algebra using polar
 * decomposition", 2011). See object.h for the definition and its properties.
 *
 * The sum is exact: every term is a double that does not depend on the order
 * of the objects, and the terms are added in a fixed-point accumulator (a
 * long integer of 32-bit digits, Kulisch's idea) and rounded once, so the
 * mean does not depend on that order, bit for bit. */
#include <garotor/object.h>

#include <math.h>
#include <stdint.h>

#include "internal/blade.h"
#include "internal/object.h"

#define U GAO_U

/* ---- the exact sum -------------------------------------------------------------
   x = M 2^(e - 53), M < 2^53 an integer, is added at bit e - 53 + ACC_BIAS >= 0
   (e >= -1073 for every non-zero double) of a signed number held in 32-bit
   digits, each an int64_t, so that 2^28 additions of at most 2^33 each fit
   before the carries must be propagated. 2^1024 times 2^64 terms needs
   1024 + 64 + ACC_BIAS bits: ACC_LIMBS digits hold them. */
#define ACC_BIAS 1138
#define ACC_LIMBS 74
#define ACC_MASK 0xffffffffu

typedef struct {
    int64_t d[ACC_LIMBS];
    uint32_t count; /* additions since the carries were last propagated */
} acc;

/* every digit but the last into [0, 2^32) */
static void acc_carry(acc *a)
{
    for (int i = 0; i + 1 < ACC_LIMBS; i++) {
        int64_t low = (int64_t)((uint64_t)a->d[i] & ACC_MASK);
        a->d[i + 1] += (a->d[i] - low) / 4294967296;
        a->d[i] = low;
    }
    a->count = 0;
}

static void acc_add(acc *a, double x)
{
    if (x == 0.0)
        return;
    int e;
    double m = frexp(fabs(x), &e);
    uint64_t M = (uint64_t)ldexp(m, 53);
    int p = e - 53 + ACC_BIAS, li = p >> 5, off = p & 31;
    uint64_t a0 = (M & ACC_MASK) << off, a1 = (M >> 32) << off;
    int64_t d0 = (int64_t)(a0 & ACC_MASK), d1 = (int64_t)((a0 >> 32) + (a1 & ACC_MASK)),
            d2 = (int64_t)(a1 >> 32);
    if (x < 0.0) {
        d0 = -d0;
        d1 = -d1;
        d2 = -d2;
    }
    a->d[li] += d0;
    a->d[li + 1] += d1;
    a->d[li + 2] += d2;
    if (++a->count >= (1u << 28))
        acc_carry(a);
}

/* the sum, rounded to a double once (ties by the conversion of a 64-bit
   integer, the bits below it kept as a sticky bit): a function of the exact
   sum alone */
static double acc_value(acc *a)
{
    acc_carry(a);
    double sign = 1.0;
    if (a->d[ACC_LIMBS - 1] < 0) {
        for (int i = 0; i < ACC_LIMBS; i++) a->d[i] = -a->d[i];
        acc_carry(a);
        sign = -1.0;
    }
    int h = ACC_LIMBS - 1;
    while (h >= 0 && a->d[h] == 0) h--;
    if (h < 0)
        return 0.0;
    uint64_t hi = (uint64_t)a->d[h], mid = h >= 1 ? (uint64_t)a->d[h - 1] : 0,
             lo = h >= 2 ? (uint64_t)a->d[h - 2] : 0;
    int lz = 0;
    while (!(hi & (0x80000000u >> lz))) lz++;
    uint64_t top = (hi << (32 + lz)) | (mid << lz), sticky = 0;
    if (lz > 0) {
        top |= lo >> (32 - lz);
        sticky = (lo & ((1ull << (32 - lz)) - 1)) != 0;
    } else
        sticky = lo != 0;
    for (int i = 0; i + 2 < h; i++) sticky |= a->d[i] != 0;
    return sign * ldexp((double)(top | sticky), 32 - lz + 32 * (h - 2) - ACC_BIAS);
}

/* ---- the mean --------------------------------------------------------------- */

/* the grade of a kind's form in the sum: the dual vector for spheres and
   planes, the direct blade for the rest */
static int kind_grade(int kind)
{
    switch (kind) {
    case GA_OBJECT_FLATPOINT:
    case GA_OBJECT_POINTPAIR: return 2;
    case GA_OBJECT_LINE:
    case GA_OBJECT_CIRCLE: return 3;
    default: return 1;
    }
}

/* X in its kind's form (grade g): a 4-blade sphere or plane as its dual
   vector; *off: the largest coefficient of the other grades dropped */
static ga_mv in_form(ga_mv X, int g, double *off)
{
    X = gao_unit_scaled(X); /* exact: no square below overflows */
    if (g == 1 && gao_off_grade(X, 1) > gao_off_grade(X, 4))
        X = ga_mv_undual(X);
    *off = gao_off_grade(X, g);
    return ga_mv_grade(X, g);
}

/* sum |a_i| |b_i| */
static double abs_dot(ga_mv a, ga_mv b)
{
    double s = 0.0;
    for (int i = 0; i < 32; i++) s += fabs(a.c[i]) * fabs(b.c[i]);
    return s;
}

/* the uncertainty e (of X) moved by a with X, in null coordinates (a
   translation is triangular there), and the rounding of the moved Y */
static ga_mv unc_moved(ga_mv e, ga_vec3 a, ga_mv Y)
{
    ga_mv r = gao_unc_from_null(gao_abs_translate_null(gao_unc_to_null(e), a), 1.0, 1.0);
    return ga_mv_add(r, ga_mv_scale(gao_abs(Y), U));
}

/* X about c0 in units of lam (x -> x / lam: n -> n / lam, nbar -> lam nbar),
   its uncertainty e with it (and the rounding of the scaling) */
static ga_mv to_units(ga_mv X, ga_mv *e, double lam)
{
    X = gao_scale_n_nbar(X, 1.0 / lam, lam);
    *e = ga_mv_add(gao_unc_from_null(gao_unc_to_null(*e), 1.0 / lam, lam), ga_mv_scale(gao_abs(X), 2.0 * U));
    return X;
}

/* |<X ~X>_0| (invariant under translations), taken about c, X's centre for
   a round: about the origin the e4 and e5 squares of a round far out cancel
   (|c|^4 / r^2 against 1); *dq: how far it can be off, X known to e */
static double norm2_about(ga_mv X, ga_mv e, ga_vec3 c, double *dq)
{
    ga_vec3 mc = {-c.x, -c.y, -c.z};
    ga_mv Y = gao_translate(X, mc), eY = unc_moved(e, mc, Y);
    *dq = 2.0 * abs_dot(Y, eY) + 40.0 * U * abs_dot(Y, Y);
    return fabs(ga_mv_sp(Y, ga_mv_reverse(Y)));
}

static double dist3(ga_vec3 a, ga_vec3 b)
{
    return sqrt((a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y) + (a.z - b.z) * (a.z - b.z));
}

/* The blade of the sum C (grade g), normalised to |<X ~X>_0| = 1. For the
   grades 2 and 3: C = k X, k = k0 + k4 a scalar plus a 4-vector that
   commutes with C and X a blade: sigma = +-C ~C = k^2 (+-X ~X = 1),
   k = sqrt(sigma) = (sigma + N) / sqrt(2 (s0 + N)), N = sqrt(s0^2 - Q^2)
   (Dorst and Valkenburg), and X = k^-1 C, a positive multiple of
   (s0 + N - Q) C, Q = <sigma>_4 (Q^2 a scalar). */
static ga_status project(ga_mv C, int g, ga_mv *X)
{
    if (g == 2 || g == 3) {
        ga_mv sigma = ga_mv_gp(C, ga_mv_reverse(C));
        if (sigma.c[0] < 0.0)
            sigma = ga_mv_scale(sigma, -1.0);
        double s0 = sigma.c[0];
        ga_mv Q = ga_mv_grade(sigma, 4);
        double q2 = ga_mv_sp(Q, Q), N2 = s0 * s0 - q2;
        if (!(s0 > 0.0) || !(N2 > 0.0))
            return GA_ERR_DOMAIN; /* no blade k^-1 C: the sum is no multiple of an object */
        ga_mv K = ga_mv_scale(Q, -1.0);
        K.c[0] = s0 + sqrt(N2);
        C = ga_mv_grade(ga_mv_gp(K, C), g);
    }
    double q = fabs(ga_mv_sp(C, ga_mv_reverse(C)));
    if (!(q > 0.0) || !isfinite(q))
        return GA_ERR_DOMAIN;
    *X = ga_mv_scale(C, 1.0 / sqrt(q));
    return GA_OK;
}

/* L = max(1, |c| + sqrt|r^2|) of object.h */
static double scene(const ga_object *o)
{
    return fmax(1.0, sqrt(o->centre.x * o->centre.x + o->centre.y * o->centre.y + o->centre.z * o->centre.z) +
                         sqrt(fabs(o->r2)));
}

/* the centre about which a round is normalised and projected (0 for flats) */
static ga_vec3 local_centre(const ga_object *o)
{
    ga_vec3 z = {0, 0, 0};
    return o->kind >= GA_OBJECT_POINTPAIR ? o->centre : z;
}

static ga_status mean(const ga_mv *A, const double *w, size_t n, ga_mv *out, ga_object *obj)
{
    if (n == 0)
        return GA_ERR_ARG;
    /* NaN or Inf anywhere first, then the weights, then the objects */
    double wmax = 0.0;
    for (size_t i = 0; i < n; i++)
        if (!ga_mv_isfinite(A[i]) || (w && !isfinite(w[i])))
            return GA_ERR_NOTFINITE;
    for (size_t i = 0; i < n; i++) {
        double wi = w ? w[i] : 1.0;
        if (!(wi >= 0.0))
            return GA_ERR_ARG;
        wmax = fmax(wmax, wi);
    }
    if (!(wmax > 0.0))
        return GA_ERR_ARG;
    int kind = -1, all4 = 1;
    for (size_t i = 0; i < n; i++) {
        ga_object o;
        int st = ga_object_from_mv(A[i], &o);
        if (st != GA_OK)
            return st;
        if (kind >= 0 && o.kind != kind)
            return GA_ERR_ARG;
        kind = o.kind;
        if (kind == GA_OBJECT_EMPTY)
            return GA_ERR_NOTBLADE;
        if (kind >= GA_OBJECT_POINTPAIR && o.reality == GA_REALITY_TANGENT)
            return GA_ERR_DOMAIN; /* |<X ~X>_0| = 0: no normalisation */
        ga_mv s = gao_unit_scaled(A[i]);
        all4 &= gao_off_grade(s, 4) < gao_off_grade(s, 1); /* a 4-blade sphere or plane */
    }
    int g = kind_grade(kind);
    /* the weights scaled by a power of two (exactly) to at most 1 */
    int ew;
    frexp(wmax, &ew);
    /* the blades of grade g */
    ga_mv gmask = ga_mv_zero();
    for (int j = 0; j < 32; j++) gmask.c[j] = 1.0;
    gmask = ga_mv_grade(gmask, g);
    int idx[10], m = 0;
    for (int j = 0; j < 32; j++)
        if (gmask.c[j] != 0.0)
            idx[m++] = j;
    /* A round far out has coefficients of the size of its squared distance
       about the origin, and the terms would round there: every object is
       moved (exactly, rounded once: gao_translate) to c0, the a-weighted mean
       of the rounds' centres (a_i = w_i / |X_i|: the sphere's own centre),
       summed, normalised and projected there, and moved back. c0 is a
       function of exact sums, so that the mean still does not depend on the
       order. Flats are summed about the origin (c0 = 0), where they keep
       their lengths anyway (object.h). */
    acc sum[10] = {{{0}, 0}}, esum[10] = {{{0}, 0}}, csum[5] = {{{0}, 0}};
    ga_vec3 c0 = {0, 0, 0};
    double lam = 1.0; /* rounds: a power of two near their mean radius */
    ga_mv C = ga_mv_zero(), eC = ga_mv_zero();
    ga_mv S = ga_mv_zero();
    for (int pass = kind >= GA_OBJECT_POINTPAIR ? 0 : 1; pass < 3; pass++) {
        double tmax = 0.0; /* the largest |term|, for the cancellation below */
        for (size_t i = 0; i < n; i++) {
            double wi = ldexp(w ? w[i] : 1.0, -ew);
            if (wi == 0.0)
                continue;
            ga_object o;
            if (ga_object_from_mv(A[i], &o) != GA_OK)
                return GA_ERR_DOMAIN; /* read in the first pass: not reached */
            /* X and its uncertainty (object.h's model: its rounding, and
               the parts of other grades dropped) */
            double off, dq;
            ga_mv X = in_form(A[i], g, &off), eX = gao_uncertainty(X, GAO_KAPPA);
            for (int j = 0; j < 32; j++) eX.c[j] += off;
            ga_vec3 ci = local_centre(&o);
            double q = norm2_about(X, eX, ci, &dq);
            if (!(q > 0.0) || !isfinite(q))
                return GA_ERR_DOMAIN;
            if (pass == 0) {
                double ai = wi / sqrt(q);
                acc_add(&csum[0], ai * ci.x);
                acc_add(&csum[1], ai * ci.y);
                acc_add(&csum[2], ai * ci.z);
                acc_add(&csum[3], ai);
                acc_add(&csum[4], ai * sqrt(fabs(o.r2)));
                continue;
            }
            /* the term, its uncertainty carried with it: the input's and
               the roundings of the scaling and of the move */
            double f = wi / sqrt(q), rel = dq / (2.0 * q) + 4.0 * U;
            X = ga_mv_scale(X, f);
            eX = ga_mv_add(ga_mv_scale(eX, f), ga_mv_scale(gao_abs(X), U));
            if (kind >= GA_OBJECT_POINTPAIR) {
                ga_vec3 mc0 = {-c0.x, -c0.y, -c0.z};
                X = gao_translate(X, mc0);
                eX = unc_moved(eX, mc0, X);
                X = to_units(X, &eX, lam);
            }
            if (pass == 2) {
                /* the scale f is known to rel of itself: a multiple of the
                   term, of which only the part off the sum S moves the mean
                   (S ~ X mu, mu by least squares on the coefficients) */
                double xs = 0.0, ss = 0.0;
                for (int j = 0; j < m; j++) {
                    xs += X.c[idx[j]] * S.c[idx[j]];
                    ss += S.c[idx[j]] * S.c[idx[j]];
                }
                double mu = xs / ss;
                for (int j = 0; j < m; j++)
                    acc_add(&esum[j],
                            rel * (fabs(X.c[idx[j]] - mu * S.c[idx[j]]) + 4.0 * U * fabs(X.c[idx[j]])));
                continue;
            }
            for (int j = 0; j < m; j++) {
                double t = X.c[idx[j]];
                tmax = fmax(tmax, fabs(t));
                acc_add(&sum[j], t);
                acc_add(&esum[j], eX.c[idx[j]]);
            }
        }
        if (pass == 0) {
            double sa = acc_value(&csum[3]);
            c0 = (ga_vec3){acc_value(&csum[0]) / sa, acc_value(&csum[1]) / sa, acc_value(&csum[2]) / sa};
            if (!(isfinite(c0.x) && isfinite(c0.y) && isfinite(c0.z)))
                return GA_ERR_DOMAIN;
            double rbar = acc_value(&csum[4]) / sa;
            if (rbar > 0.0 && isfinite(rbar))
                lam = ldexp(1.0, ilogb(fmin(fmax(rbar, 0x1p-40), 0x1p40)));
            continue;
        }
        if (pass == 1) {
            /* the objects cancel (a plane and its reverse) to the rounding of the terms */
            double smax = 0.0;
            for (int j = 0; j < m; j++) {
                S.c[idx[j]] = acc_value(&sum[j]);
                smax = fmax(smax, fabs(S.c[idx[j]]));
            }
            if (!(smax > 16.0 * U * tmax))
                return GA_ERR_SINGULAR;
            continue;
        }
        double smax = ga_mv_maxabs(S);
        for (int j = 0; j < m; j++)
            eC.c[idx[j]] = acc_value(&esum[j]) * (1.0 + 4.0 * U) + U * fabs(S.c[idx[j]]);
        int es;
        frexp(smax, &es);
        C = gao_unit_scaled(S);
        for (int j = 0; j < 32; j++) eC.c[j] = ldexp(eC.c[j], -es);
    }
    ga_mv X;
    int pst = project(C, g, &X);
    if (pst != GA_OK)
        return pst;
    /* what the mean is known to from its inputs, to first order: the
       read-back's change with each coefficient of C (by differences),
       times that coefficient's uncertainty, summed */
    ga_object p, pj;
    if (ga_object_from_mv(X, &p) != GA_OK || p.kind != kind)
        return GA_ERR_PRECISION;
    double de = 0.0, dr = 0.0, da = 0.0, h = 0x1p-26 * ga_mv_maxabs(C);
    for (int j = 0; j < m; j++) {
        ga_mv Cj = C, Xj;
        int i = idx[j];
        double e = eC.c[i];
        Cj.c[i] += h;
        if (kind < GA_OBJECT_POINTPAIR && gabl_pair_e4(i)) {
            /* a flat's e4 and e5 parts are one value (its n part): moved together */
            Cj.c[i + 1] += h;
            e = fmax(e, eC.c[i + 1]);
        } else if (kind < GA_OBJECT_POINTPAIR &&
                   ((i > 0 && gabl_pair_e4(i - 1)) || (g > 1 && !(gabl_mask[i] & 0x18u))))
            continue; /* nor has it parts without e4, e5 */
        if (project(Cj, g, &Xj) != GA_OK || ga_object_from_mv(Xj, &pj) != GA_OK || pj.kind != kind)
            return GA_ERR_PRECISION;
        double f = e / h;
        de += f * dist3(pj.centre, p.centre);
        dr += f * fabs(pj.r2 - p.r2);
        da += f * dist3(pj.direction, p.direction);
    }
    /* twice that (the differences and the second order), and the read-back's own */
    p.err = lam * (p.err + 2.0 * de);
    p.r2_err = lam * lam * (p.r2_err + 2.0 * dr);
    p.angle_err += 2.0 * da;
    C = X;
    if (kind >= GA_OBJECT_POINTPAIR)
        C = ga_mv_grade(gao_translate(gao_scale_n_nbar(C, lam, 1.0 / lam), c0), g);
    if (g == 1 && all4)
        C = ga_mv_dual(C);
    if (!ga_mv_isfinite(C))
        return GA_ERR_DOMAIN;
    /* the mean must be an object of the inputs' kind */
    ga_object o;
    int st = ga_object_from_mv(C, &o);
    if (st != GA_OK)
        return st;
    if (o.kind != kind)
        return GA_ERR_DOMAIN;
    /* the bounds: out's read-back's (the rounding of out) and what the
       mean is known to from its inputs */
    o.err += p.err;
    o.r2_err += p.r2_err;
    o.angle_err += p.angle_err;
    if (o.kind >= GA_OBJECT_POINTPAIR) {
        double L = scene(&o), band = fmax(GA_OBJECT_TANGENT_TOL * L * L, o.r2_err);
        o.reality = fabs(o.r2) <= band ? GA_REALITY_TANGENT
                  : o.r2 < 0.0         ? GA_REALITY_IMAGINARY
                                       : GA_REALITY_REAL;
    }
    if (obj)
        *obj = o;
    *out = C;
    return GA_OK;
}

ga_status ga_object_mean(const ga_mv *A, const double *w, size_t n, ga_mv *out)
{
    if (!A || !out)
        return GA_ERR_ARG;
    return mean(A, w, n, out, NULL);
}

ga_status ga_object_mean_read(const ga_mv *A, const double *w, size_t n, ga_mv *out, ga_object *obj)
{
    if (!A || !out || !obj)
        return GA_ERR_ARG;
    return mean(A, w, n, out, obj);
}
