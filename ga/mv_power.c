/* garotor/mv_power.c: square roots and real powers of rotors of G(4,1)
 * through their principal logarithm, and the weighted mean of rigid-motion
 * rotors (the exponential barycentre of Pennec and Arsigny).
 *
 * R^t = exp(t log R) with the log of ga_mv_log (mv_log.c) and the exp of
 * ga_mv_exp (mv_exp.c): every power of R is a function of the one bivector
 * B = log R, so R^s R^t = R^(s+t) and (R^t)^-1 = R^-t hold to the rounding
 * of exp, and sqrt(R) = R^(1/2) is the root whose elliptic angles are halved
 * (the principal square root: the one of the principal log).
 */
#include <garotor/mv.h>
#include <garotor/rotor.h>

#include <float.h>
#include <math.h>

ga_status ga_mv_pow(ga_mv R, double t, ga_mv *out)
{
    if (!out)
        return GA_ERR_ARG;
    if (!isfinite(t))
        return GA_ERR_NOTFINITE;
    ga_mv B;
    ga_status st = ga_mv_log(R, &B);
    if (st != GA_OK)
        return st;
    ga_mv r = ga_mv_exp(ga_mv_scale(B, t));
    if (!ga_mv_isfinite(r))
        return GA_ERR_DOMAIN; /* t B overflows, or its boost does */
    *out = r;
    return GA_OK;
}

ga_status ga_mv_sqrt(ga_mv R, ga_mv *out)
{
    if (!out)
        return GA_ERR_ARG;
    return ga_mv_pow(R, 0.5, out);
}

/* ---- the mean of rigid motions ---------------------------------------------------
   M solves sum_i w_i log(M^-1 R_i) = 0 (the exponential barycentre; Pennec &
   Arsigny, "Exponential barycenters of the canonical Cartan connection and
   invariant means on Lie groups", 2013). The fixed-point iteration
       M <- M exp(sum_i w_i log(M^-1 R_i))
   starts at the rotor of largest weight. The equation is invariant under
   M -> L M, R_i -> L R_i and M -> M L, R_i -> R_i L (log(L^-1 X L) =
   L^-1 log(X) L), so is the mean. */

/* the largest coefficient of a generator's rotation part and of its
   translation part */
static double rot_max(ga_generator b) { return fmax(fabs(b.e12), fmax(fabs(b.e13), fabs(b.e23))); }
static double tra_max(ga_generator b) { return fmax(fabs(b.e1n), fmax(fabs(b.e2n), fabs(b.e3n))); }
/* the largest coefficient of a rotor's n part (half its translation) */
static double n_max(ga_rotor r)
{
    return fmax(fmax(fabs(r.e1n), fabs(r.e2n)), fmax(fabs(r.e3n), fabs(r.e123n)));
}

ga_status ga_rotor_mean(const ga_rotor *R, const double *w, size_t n, ga_rotor *out)
{
    if (!R || !w || !out)
        return GA_ERR_ARG;
    if (n == 0)
        return GA_ERR_ARG;
    double wsum = 0.0;
    size_t first = 0;
    for (size_t i = 0; i < n; i++) {
        const double *c = &R[i].s;
        for (int k = 0; k < 8; k++)
            if (!isfinite(c[k]))
                return GA_ERR_NOTFINITE;
        if (!isfinite(w[i]))
            return GA_ERR_NOTFINITE;
        if (!(w[i] >= 0.0))
            return GA_ERR_ARG;
        wsum += w[i];
        if (w[i] > w[first])
            first = i;
    }
    if (!(wsum > 0.0) || !isfinite(wsum))
        return GA_ERR_ARG;
    /* every rotor on the group (as ga_rotor_log takes it): projected */
    ga_rotor M;
    ga_status st = ga_rotor_normalize(R[first], &M);
    if (st != GA_OK)
        return st;
    /* the size of the translations, which the products M^-1 R_i round at */
    double tra0 = 1.0;
    for (size_t i = 0; i < n; i++)
        if (w[i] != 0.0)
            tra0 = fmax(tra0, n_max(R[i]));
    for (int it = 0; it < GA_ROTOR_MEAN_ITER; it++) {
        ga_generator step = {0, 0, 0, 0, 0, 0};
        double rot = 1.0, tra = fmax(tra0, n_max(M)); /* the sizes of the two parts, at least 1 */
        ga_rotor Mi = ga_rotor_reverse(M);
        for (size_t i = 0; i < n; i++) {
            if (w[i] == 0.0)
                continue;
            ga_generator b;
            if ((st = ga_rotor_log(ga_rotor_mul(Mi, R[i]), &b)) != GA_OK)
                return st;
            double k = w[i] / wsum;
            step.e12 += k * b.e12;
            step.e13 += k * b.e13;
            step.e23 += k * b.e23;
            step.e1n += k * b.e1n;
            step.e2n += k * b.e2n;
            step.e3n += k * b.e3n;
            rot = fmax(rot, rot_max(b));
            tra = fmax(tra, tra_max(b));
        }
        ga_rotor next;
        if ((st = ga_rotor_normalize(ga_rotor_mul(M, ga_rotor_exp(step)), &next)) != GA_OK)
            return st;
        M = next;
        /* converged: the step is the rounding of the sum of the logs */
        if (rot_max(step) <= GA_ROTOR_MEAN_TOL * DBL_EPSILON * rot &&
            tra_max(step) <= GA_ROTOR_MEAN_TOL * DBL_EPSILON * tra) {
            *out = M;
            return GA_OK;
        }
    }
    return GA_ERR_DOMAIN;
}
