/* ga/internal/se3.h (internal, not installed): the parts of the SE(3)
 * closed forms (se3.c) that the general logm also uses, for a rigid motion
 * turning by more than pi/2. Prefix ga__se3.
 */
#ifndef GA_INTERNAL_SE3_H
#define GA_INTERNAL_SE3_H

#include <garotor/types.h>

/* ga_se3_check through a pointer (no copy of the 128 bytes per call) */
int ga__se3_check(const ga_mat4 *m, double tol);
/* the principal log of a matrix already known to be rigid (Eberly) */
ga_twist ga__se3_log_core(const ga_mat4 *m);

#endif
