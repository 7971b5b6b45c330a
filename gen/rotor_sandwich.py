"""gen/rotor_sandwich.py: ga/rotor_sandwich.inc, the sandwich of ga_rotor_apply_mv.

R X ~R for a compact rotor R (the components of section 4, gen/common.py) and
a full multivector X, every term written out from the blade products of
section 1: T = R X, then T ~R, each product over the 16 blades of R.
"""

from common import (ALG, HEADER, Poly, Vars, a_major, comment_block, compact_rotor,
                    dense_vars, emit_sum, popcount, rotor_basis)

PATH = 'ga/rotor_sandwich.inc'


# ---- 9. the sandwich R X ~R (ga/rotor_sandwich.inc) -------------------------

def generate():
    # the sandwich R X ~R of a compact rotor: T = R X, then T ~R, each with
    # R's 16 blades (e_i n = e_i4 + e_i5) instead of 32
    out, counts = [], {}
    basis = rotor_basis()
    vars_ = Vars()
    R = compact_rotor(basis, vars_, 'r')
    X = dense_vars(vars_, 'x')
    T = ALG.product(R, X)
    lines, mul, add = [], 0, 0
    for i, m in enumerate(ALG.masks):
        lines += emit_sum('double t%d' % i, T.get(m, Poly()), vars_.names, a_major)
        dm, da = T.get(m, Poly()).ops()
        mul, add = mul + dm, add + da
    vars2 = Vars()
    R2 = compact_rotor(basis, vars2, 'r')
    Tv = {m: vars2('t%d' % i) for i, m in enumerate(ALG.masks)}
    Rrev = {m: c * (-1 if popcount(m) % 4 in (2, 3) else 1) for m, c in R2.items()}
    S = ALG.product(Tv, Rrev)
    # the reverse of R is R with its grade-2 part negated: check against the rule
    assert all(popcount(m) in (0, 2, 4) for m in R2)
    for i, m in enumerate(ALG.masks):
        lines += emit_sum('out[%d]' % i, S.get(m, Poly()), vars2.names, a_major)
        dm, da = S.get(m, Poly()).ops()
        mul, add = mul + dm, add + da
    counts['rotor_apply_mv'] = (mul, add)
    out += ['', '/* out = R X ~R for a compact rotor r (R = q + P n) and a full multivector x:',
            ' * t = R x, then t ~R, each product over the 16 blades of R. %d multiplications,' % mul,
            ' * %d additions. */' % add,
            'static inline void rotor_sandwich_dense(ga_rotor r, const double *restrict x,',
            '                                        double *restrict out)', '{']
    out += lines + ['}']
    head = [HEADER, '',
            'The sandwich of ga_rotor_apply_mv (ga/rotor.c), R X ~R for a compact rotor',
            'and a full multivector, every term written out from the blade products of',
            'G(4,1) (section 1 of the script) and the compact components of section 4.',
            'Needs in scope: ga_rotor (rotor.h).']
    text = '\n'.join(comment_block(head) + out) + '\n'
    return text, counts
