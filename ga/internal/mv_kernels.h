/* ga/internal/mv_kernels.h (internal, not installed): the geometric product
 * by the sparse kernels of ga/mv_kernels.c (generated into ga/mv_kernels.inc),
 * for mv_algebra.c's inverse and versor.c's sandwich. Prefix gak_.
 */
#ifndef GA_INTERNAL_MV_KERNELS_H
#define GA_INTERNAL_MV_KERNELS_H

/* The grades of x that have a coefficient other than 0 (a NaN counts): bit k
   for grade k. */
unsigned gak_grades(const double *x);

/* r = a b (32 coefficients each; r may not be a or b), with the kernels of
   the grades a and b have: a of one parity times b of one grade or one
   parity, or the converse; the dense product where both have both
   parities. The terms a kernel leaves out are products with a zero
   coefficient, and each component sums the others in ga_mv_gp's order, so
   for finite a and b the result is ga_mv_gp's, bit for bit, but the sign of
   a zero. */
void gak_gp(const double *a, const double *b, double *r);

#endif
