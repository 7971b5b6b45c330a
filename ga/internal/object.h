/* ga/internal/object.h (internal, not installed): what conformal.c, object.c,
 * object_between.c and meet.c share (and mv_algebra.c, whose inverse bounds its rounding by
 * gao_abs_gp). Prefix gao_.
 *
 * The accuracy model of object.h: every coefficient of an input is known to
 * GAO_KAPPA u times the largest coefficient of its class, the blades of one
 * grade with as many factors e4 or e5 (0, 1 or 2). A rotation about the
 * origin mixes the coefficients of a class and nothing else, so their
 * errors are of one size; a translation adds multiples of a lower class to a
 * higher one (an object far out has e4, e5 coefficients of the size of its
 * squared distance). gao_uncertainty gives those bounds, and the abs
 * products below carry them through a computation to first order.
 */
#ifndef GA_INTERNAL_OBJECT_H
#define GA_INTERNAL_OBJECT_H

#include <garotor/object.h>

#define GAO_U 1.1102230246251565e-16 /* u = 2^-53 */
#define GAO_KAPPA 1.0
/* ga_mv_meet's decision "special position": the inputs' coefficients are
   taken as known to GAO_MEET_KAPPA u of their class (the roundings of a
   construction of a few dozen operations) */
#define GAO_MEET_KAPPA 32.0
/* ga_mv_localize refuses a round whose move makes its world form's rounding
   more than this times the rounding of its local form */
#define GAO_LOCALIZE_LOSS 16.0

/* the largest |coefficient| of X off grade k */
double gao_off_grade(ga_mv X, int k);
/* X scaled by a power of two so that max |coefficient| is in [1/2, 1) (exact) */
ga_mv gao_unit_scaled(ga_mv X);

/* T_a X ~T_a, T_a = 1 + n a / 2 (Wareham-Lasenby §2.2): the exact sandwich,
   carried in double-double and rounded once per coefficient (up to a
   relative 2^-100 or so of the largest term), each grade that X has none
   of exactly 0. A flat (no part A ^ nbar) stays one exactly: the e4 and e5
   coefficients that must be equal are the roundings of one value. */
ga_mv gao_translate(ga_mv X, ga_vec3 a);
/* F(p0) ^ F(p1) ^ ... ^ F(p[np-1]) (^ n if with_n) built as
   T_p0 (F(0) ^ F(p1 - p0) ^ ...) ~T_p0, every step carried in double-double
   (the differences exact) and rounded once per coefficient: the blade of the
   points as given, each coefficient to about u of itself (and ~u^2 of its
   terms), however far out and however its terms cancel. */
ga_mv gao_build_about(const ga_vec3 *p, int np, int with_n);
/* a ^ b, each product exact and the sums double-double, rounded once: the
   exact outer product to a relative u of each coefficient (and ~u^2 of its
   terms) */
ga_mv gao_op_exact(ga_mv a, ga_mv b);
/* a b likewise: the exact geometric product to a relative u of each
   coefficient (and ~u^2 of its terms) */
ga_mv gao_gp_exact(ga_mv a, ga_mv b);
/* The magnitudes of T_a X ~T_a: the sandwich of |X| by |T_a| with every sign
   positive (a bound of what a perturbation of X becomes). */
ga_mv gao_abs_translate(ga_mv X, ga_vec3 a);
/* The parts A e4, A e5 (A without e4, e5) of X with coefficients p, q are
   A ^ ((p + q)/2 n + (p - q)/2 nbar): each pair rewritten as
   A ^ (kn (p + q)/2 n + kb (p - q)/2 nbar) (kb = 0 drops the nbar part, as
   a flat has none; kn = 1 / lambda, kb = lambda is x -> x / lambda). */
ga_mv gao_scale_n_nbar(ga_mv X, double kn, double kb);
/* Uncertainties in null coordinates: the slot of A e4 holds that of the
   coefficient of A ^ n, the slot of A e5 that of A ^ nbar (n = e4 + e5,
   nbar = e4 - e5). A translation is triangular there (n fixed, E -> E + n,
   nbar -> nbar + E + n), so the magnitudes of its action bound the moved
   uncertainty without the t^2 that independent e4, e5 parts would add to the
   weight. gao_unc_from_null scales the n parts by kn and the nbar parts by
   kb (x -> x / lambda: kn = 1 / lambda, kb = lambda) and gives the e4, e5
   parts each the sum. */
ga_mv gao_unc_to_null(ga_mv e);
ga_mv gao_unc_from_null(ga_mv e, double kn, double kb);
/* sum_j e_j |T_a b_j ~T_a| in null coordinates, b_j the null blades */
ga_mv gao_abs_translate_null(ga_mv e, ga_vec3 a);
/* sum |a_i| |b_j| over the products of blades i and j, at the index of their
   product: a bound of every term of a b, a ^ b, a _| b at that blade */
ga_mv gao_abs_gp(ga_mv a, ga_mv b);
/* |X| coefficient by coefficient */
ga_mv gao_abs(ga_mv X);
/* The uncertainty of X under the model above: kappa u times the largest
   |coefficient| of each blade's class. */
ga_mv gao_uncertainty(ga_mv X, double kappa);

/* The classification and read-back of object.c: strict = 0 reads a round
   too far out to promise anything roughly (a local origin for the meet). */
ga_status gao_classify(ga_mv X, int strict, ga_object *o);
/* ga_object_from_mv to GA_OBJECT_TOL (object.h): GA_ERR_PRECISION beyond it,
   GA_ERR_NOTBLADE for an empty object, GA_ERR_IMAGINARY for an imaginary
   round (the read-back of the functions that state no bound of their own:
   object.c, object_between.c); _pair: A's, then B's, the first failure. */
int gao_read_real(ga_mv O, ga_object *o);
int gao_read_real_pair(ga_mv A, ga_mv B, ga_object *a, ga_object *b);

#endif
