/* ga/internal/blade.h (internal, not installed): the basis blades of G(4,1)
 * as bit masks (bit k-1 for e_k, the canonical order of docs/conventions.md)
 * and the sign of a product of two of them. Prefix gabl_.
 */
#ifndef GA_INTERNAL_BLADE_H
#define GA_INTERNAL_BLADE_H

/* The canonical order of docs/conventions.md, as bit masks (grade first,
   then lexicographic): ga_blade_mask */
static const unsigned char gabl_mask[32] = {0x00, 0x01, 0x02, 0x04, 0x08, 0x10, 0x03, 0x05, 0x09, 0x11, 0x06,
                                            0x0a, 0x12, 0x0c, 0x14, 0x18, 0x07, 0x0b, 0x13, 0x0d, 0x15, 0x19,
                                            0x0e, 0x16, 0x1a, 0x1c, 0x0f, 0x17, 0x1b, 0x1d, 0x1e, 0x1f};

/* the index of each mask: the inverse of gabl_mask */
static const unsigned char gabl_index_of[32] = {0, 1, 2,  6,  3,  7,  10, 16, 4,  8,  11, 17, 13, 19, 22, 26,
                                                5, 9, 12, 18, 14, 20, 23, 27, 15, 21, 24, 28, 25, 29, 30, 31};

/* the number of vectors of a blade (mask < 32): a table, since without
   -mpopcnt __builtin_popcount is a call into libgcc */
static const unsigned char gabl_bits[32] = {0, 1, 1, 2, 1, 2, 2, 3, 1, 2, 2, 3, 2, 3, 3, 4,
                                            1, 2, 2, 3, 2, 3, 3, 4, 2, 3, 3, 4, 3, 4, 4, 5};
static inline int gabl_popcount5(unsigned m) { return gabl_bits[m & 31u]; }

/* Whether blade i is A e4 for a blade A without e4, e5: then A e5 is blade
   i + 1 in the canonical order (the pair A ^ n, A ^ nbar) */
static inline int gabl_pair_e4(int i) { return (gabl_mask[i] & 0x18u) == 0x8u; }

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
