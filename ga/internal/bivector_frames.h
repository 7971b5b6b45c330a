/* ga/internal/bivector_frames.h (internal, not installed): the frames in
 * which the parts of a bivector or rotor of G(4,1) come out exact, shared by
 * exp (ga/mv_exp.c), log (ga/mv_log.c) and split (ga/mv_split.c); defined in
 * ga/bivector_frames.c, which explains them. Prefix gabf_.
 */
#ifndef GA_INTERNAL_BIVECTOR_FRAMES_H
#define GA_INTERNAL_BIVECTOR_FRAMES_H

#include <garotor/mv.h>

/* ---- a null part: the frame in which it is rigid ------------------------------- */

/* The 5x5 matrix of x -> x _| b, whose kernel is b's null vector */
void gabf_contraction_matrix(ga_mv b, double M[5][5]);

/* A rotor V of the Euclidean 4-space e1..e4 that takes the null vector n of
   M (its metric normal, candidate 0, or from M^2, candidate 1) to the point
   at infinity: V b ~V is rigid where b's parts fix n. 0 where M gives no n. */
int gabf_rigid_frame(double M[5][5], int cand, ga_mv *V);

/* V X ~V */
ga_mv gabf_sandwich(ga_mv V, ga_mv X);

/* ---- two rotations: the ideals of Spin(4) -------------------------------------- */

/* An orthonormal basis U[0..2] of the bivectors of the ideal of P = (1 +- J)/2
   in the 4-space of the unit 4-vector J (<Ui Uj>_0 = -1/2 for i = j, else 0) */
void gabf_ideal_basis(ga_mv J, ga_mv P, ga_mv U[3]);

#endif
