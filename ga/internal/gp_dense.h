/* ga/internal/gp_dense.h (internal, not installed): the dense products of
 * ga/mv_products.inc (written by gen/generate.py), and where their vector
 * forms are compiled.
 *
 * GA_DENSE_BLOCKS: gcc on x86-64 has mv_gp_blocks2, 4 and 8, the geometric
 * product in vectors of 2, 4 and 8 doubles (gcc's vector extensions), each
 * doing mv_gp_dense's operations in its order, so all give the same bits.
 * -Dc_args=-DGA_NO_TARGET_CLONES leaves them out (mv_gp_dense only).
 */
#ifndef GA_INTERNAL_GP_DENSE_H
#define GA_INTERNAL_GP_DENSE_H

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && !defined(GA_NO_TARGET_CLONES)
#define GA_DENSE_BLOCKS 1
#endif
#if defined(__GNUC__)
#define GA_DENSE_FN static inline __attribute__((always_inline)) /* into each target that uses it */
#else
#define GA_DENSE_FN static inline
#endif
#include "../mv_products.inc"

#endif
