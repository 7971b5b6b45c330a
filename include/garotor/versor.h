/* garotor/versor.h: versors of G(4,1) (products of vectors, even or odd),
 * their sandwich, and the conformal transformations as versors: reflections,
 * inversions, dilations, transversions.
 *
 * A versor V acts on any multivector X by V X^ V^-1, where X^ is X for even V
 * and the grade involution of X for odd V (Dorst-Fontijne-Mann, "Geometric
 * Algebra for Computer Science", 2007, §7.6): so a dual plane vector reflects
 * points in its plane, a dual sphere vector inverts them in its sphere.
 * exp, log and the split of any bivector and rotor (ga_mv_exp, ga_mv_log,
 * ga_mv_split, ga_mv_factor) are in mv.h, which this header includes.
 */
#ifndef GAROTOR_VERSOR_H
#define GAROTOR_VERSOR_H

#include "mv.h"
#include "types.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- versors ------------------------------------------------------------------- */

/** V X^ V^-1 (X^ = X for even V, the grade involution of X for odd V).
 *  V need not be a versor: any invertible V of one parity is applied (for
 *  a versor, the sandwich keeps grades and products; for other V it need
 *  not). GA_ERR_NOTFINITE on NaN/Inf; GA_ERR_ARG when V has both even and
 *  odd parts; GA_ERR_SINGULAR when V has no inverse (ga_mv_inverse). */
GA_API GA_NODISCARD ga_status ga_versor_apply(ga_mv V, ga_mv X, ga_mv *out);
/** ga_versor_apply of V on each of in[0], ..., in[n - 1] into out[0..n - 1]:
 *  V's checks and inverse once, then each sandwich; out[i] is, bit for bit,
 *  what ga_versor_apply(V, in[i], &out[i]) writes. out may be in (the same
 *  array); other overlaps are not allowed. GA_ERR_ARG where in or out is
 *  NULL, GA_ERR_NOTFINITE where V or any in[i] has a NaN or Inf, and V's
 *  statuses of ga_versor_apply; nothing is written on any error. */
GA_API GA_NODISCARD ga_status ga_versor_apply_many(ga_mv V, const ga_mv *in, size_t n, ga_mv *out);

/** Reflection in the plane n.x = d (n need not be unit): the dual plane
 *  vector n + d e_inf (odd). */
GA_API ga_mv ga_versor_reflection(ga_vec3 normal, double distance);
/** Inversion in the sphere of centre c and radius r: the dual sphere
 *  F(c) - r^2/2 n (odd); it maps x to c + r^2 (x - c)/|x - c|^2. */
GA_API ga_mv ga_versor_inversion(ga_vec3 centre, double radius);
/** Dilation about c by the factor s > 0: T_c exp(-ln(s)/2 e45) T_c^-1, which
 *  maps x to c + s (x - c). GA_ERR_ARG unless s > 0, GA_ERR_NOTFINITE. */
GA_API GA_NODISCARD ga_status ga_versor_dilation(ga_vec3 centre, double s, ga_mv *out);
/** Transversion 1 + nbar b/2 (b a Euclidean vector): the translation by -b
 *  conjugated by the inversion in the unit sphere (e4 n e4 = nbar), so it
 *  maps x to (x - |x|^2 b) / (1 - 2 b.x + |b|^2 |x|^2). */
GA_API ga_mv ga_versor_transversion(ga_vec3 b);
/** Rotation by angle about the unit axis through the origin, as a full
 *  multivector (ga_rotor_to_mv of ga_rotor_rotation). */
GA_API ga_mv ga_versor_rotation(ga_vec3 axis, double angle);
/** Translation by a, as a full multivector (ga_rotor_to_mv of
 *  ga_rotor_translation): 1 + n a/2. */
GA_API ga_mv ga_versor_translation(ga_vec3 a);

#ifdef __cplusplus
}
#endif
#endif
