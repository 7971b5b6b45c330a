"""gen/rotor_mul.py: include/garotor/rotor_mul.h, the compact rotor product.

ga_rotor_mul_inline is a public static inline function (rotor_inline.h
includes it; ga_rotor_mul in ga/rotor.c calls it; clang-format is off in it):
the product of two compact rigid-motion rotors. Each of the 8 compact
components is a multivector (1, e1 e2, ..., e1 n, e1 e2 e3 n with n = e4 + e5,
as products of vectors: section 4 of gen/common.py); two general compact
rotors are multiplied symbolically (sections 1 and 2) and the product is
asserted to close on the 8 components.
"""

from fractions import Fraction

from common import (ALG, HEADER, Poly, Vars, comment_block, compact_rotor, emit_sum,
                    mv_add, mv_scale, rotor_basis, b_major)

PATH = 'include/garotor/rotor_mul.h'


# ---- 6. the compact rotor product (include/garotor/rotor_mul.h) -------------

def decompose(M, basis):
    """M's coefficients on the compact components; asserts that M is in their
    span (the product closes)."""
    coef, rest = [], dict(M)
    for field, m in basis:
        lead = min(m, key=ALG.index.get)  # a blade no other component has
        assert all(lead not in m2 for f2, m2 in basis if f2 != field)
        c = rest.get(lead, Poly()) * Fraction(1, m[lead])
        coef.append((field, c))
        rest = mv_add(rest, mv_scale(m, -c))
    assert not rest, 'the product leaves the compact components: ' + \
        ', '.join(ALG.name(m) for m in sorted(rest, key=ALG.index.get))
    return coef


def generate():
    basis = rotor_basis()
    vars_ = Vars()
    A = compact_rotor(basis, vars_, 'a')
    B = compact_rotor(basis, vars_, 'b')
    prod = decompose(ALG.product(A, B), basis)
    lines, mul, add = [], 0, 0
    for field, p in prod:
        # b_major, not mv.c's a_major: the same sums, rounded in another order,
        # but what gcc 12 -O3 makes of them (it vectorizes pairs of adjacent
        # components) ran in about 0.87x the time of the hand-written order
        # this replaced, and a_major in about 1.2x (motor_mul against
        # dualquat_mul in garotor-bench, x86-64).
        lines += emit_sum('r.%s' % field, p, vars_.names, b_major)
        m, s = p.ops()
        mul, add = mul + m, add + s
    head = [HEADER, '',
            'ga_rotor_mul_inline (include it through <garotor/rotor_inline.h>; ga_rotor_mul',
            'calls it): r = a b for compact rigid-motion',
            'rotors R = q + P n (include/garotor/rotor.h), from the geometric product',
            'of G(4,1) (e1..e4 square to +1, e5 to -1, n = e4 + e5): each component of',
            'the product of the two general 8-component multivectors, its terms in',
            'the order of b\'s components, then a\'s. The script asserts that the',
            'product has no other components. %d multiplications, %d additions.' % (mul, add)]
    body = ['/* clang-format off */', '#ifndef GAROTOR_ROTOR_MUL_H', '#define GAROTOR_ROTOR_MUL_H', '',
            '#include "rotor.h"', '',
            '/** ga_rotor_mul: the product a b (b first, then a) of compact rotors. */',
            'static inline ga_rotor ga_rotor_mul_inline(ga_rotor a, ga_rotor b)', '{',
            '    ga_rotor r;'] + lines + ['    return r;', '}', '', '#endif',
                                          '/* clang-format on */']
    text = '\n'.join(comment_block(head) + body) + '\n'
    return text, {'rotor_mul': (mul, add)}
