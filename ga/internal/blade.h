/* ga/internal/blade.h (internal, not installed): the basis blades of G(4,1)
 * as bit masks (bit k-1 for e_k, the canonical order of docs/conventions.md)
 * and the sign of a product of two of them. Prefix gabl_.
 */
#ifndef GA_INTERNAL_BLADE_H
#define GA_INTERNAL_BLADE_H

/* the index of each mask: the inverse of ga_blade_mask */
static const unsigned char gabl_index_of[32] = {0, 1, 2,  6,  3,  7,  10, 16, 4,  8,  11, 17, 13, 19, 22, 26,
                                                5, 9, 12, 18, 14, 20, 23, 27, 15, 21, 24, 28, 25, 29, 30, 31};

static inline int gabl_popcount5(unsigned m)
{
    int k = 0;
    for (; m; m &= m - 1) k++;
    return k;
}

/* The sign of the product of blades a and b (as masks): the parity of the
   transpositions that sort the vectors of a before those of b, times
   e5 e5 = -1 (e1..e4 square to +1). */
static inline double gabl_sign(unsigned a, unsigned b)
{
    int swaps = 0;
    for (unsigned x = a >> 1; x; x >>= 1) swaps += gabl_popcount5(x & b);
    if ((a & b) & 0x10)
        swaps++;
    return (swaps & 1) ? -1.0 : 1.0;
}

#endif
