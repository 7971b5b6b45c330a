/* ga/internal/schur.h (internal, not installed): the real Schur form of a
 * 3x3 or 4x4 matrix (schur.c), as ga_mat4_logm uses it. Prefix ga__schur.
 * Matrices are double[4][4], row-major like ga_mat4; only the leading
 * n x n block takes part.
 */
#ifndef GA_INTERNAL_SCHUR_H
#define GA_INTERNAL_SCHUR_H

#include <garotor/types.h>

/* The real Schur form A - sig I = Q T Q^T of the leading n x n block
 * (n = 3 or 4): t = T - sig I, upper quasi-triangular (1x1 blocks: real
 * eigenvalues, 2x2 blocks: complex pairs), qm = Q (the identity outside the
 * block). GA_ERR_DOMAIN if QR does not converge (a guard). */
int ga__schur_shifted(const ga_mat4 *a, int n, double sig, double t[4][4], double qm[4][4]);
/* Q and T refined in place by one Newton-Schulz step where that keeps the
 * eigenvalue structure (see schur.c) */
void ga__schur_refine(const ga_mat4 *a, int n, double sig, double t[4][4], double qm[4][4]);

#endif
