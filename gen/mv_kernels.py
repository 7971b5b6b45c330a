"""gen/mv_kernels.py: ga/mv_kernels.inc, the other products of ga/mv_kernels.c.

The dense products besides gp, op and lc (scalar, fat dot, Hestenes' inner,
regressive, commutator), every term written out from the blade products of
section 1 (gen/common.py); and the sparse kernels of the geometric product:
a of one parity (the even or the odd blades) times b of one grade, or of one
parity. Each component sums its terms in the order of the blade loop they
replace (a's blade, then b's: a_major), so where the loop's skipped terms
are zeros the result is the loop's, bit for bit (but the sign of a zero).
"""

from common import (ALG, Algebra, HEADER, Poly, Vars, a_major, comment_block, dense_vars, emit_sum,
                    popcount, wrap)

PATH = 'ga/mv_kernels.inc'

I_MASK = 31  # e12345


# ---- 13. the other dense products and the sparse kernels (ga/mv_kernels.inc) --

def _pairs_dot(hestenes):
    """The blade pairs of the fat dot (one blade's vectors all in the other's)
    and, with hestenes, without the scalar's pairs: ga/mv.c's dot_product."""
    def keep(ma, mb):
        if hestenes and (ma == 0 or mb == 0):
            return False
        return (ma & mb) == ma or (ma & mb) == mb
    return keep


def _product(A, B, keep):
    """The geometric product's terms for the pairs keep(ma, mb), in a_major order."""
    out = {}
    for ma in sorted(A, key=ALG.index.get):
        for mb in sorted(B, key=ALG.index.get):
            if not keep(ma, mb):
                continue
            s, m = ALG.blade_product(ma, mb)
            out[m] = out.get(m, 0) + s * (A[ma] * B[mb])
    return {m: c for m, c in out.items() if c != 0}


def _anticommute(ma, mb):
    """e_a e_b = -e_b e_a: the pairs that survive (a b - b a) / 2."""
    return ALG.blade_product(ma, mb)[0] == -ALG.blade_product(mb, ma)[0]


def _function(name, what, P, names, ret='void', out='r[%d]'):
    lines, mul, add = [], 0, 0
    for i, m in enumerate(ALG.masks):
        p = P.get(m, Poly())
        lines += emit_sum(out % i, p, names, a_major)
        dm, da = p.ops()
        mul, add = mul + dm, add + da
    head = ['', '/* r = %s: %d multiplications, %d additions. */' % (what, mul, add),
            'static %s %s(const double *restrict a, const double *restrict b, double *restrict r)'
            % (ret, name), '{']
    return head + lines + ['}'], (mul, add)


def gen_dense():
    out, counts = [], {}
    # the scalar product <a b>_0: each blade with itself, in blade order
    vars_ = Vars()
    A, B = dense_vars(vars_, 'a'), dense_vars(vars_, 'b')
    S = _product(A, B, lambda ma, mb: ma == mb).get(0, Poly())
    mul, add = S.ops()
    counts['mv_sp'] = (mul, add)
    out += ['', '/* <a b>_0: %d multiplications, %d additions. */' % (mul, add),
            'static double mv_sp_dense(const double *restrict a, const double *restrict b)', '{']
    out += emit_sum('double s', S, vars_.names, a_major) + ['    return s;', '}']
    for name, hestenes, what in (('dot', 0, 'the fat dot a . b'),
                                 ('ip', 1, "Hestenes' inner product a . b")):
        vars_ = Vars()
        A, B = dense_vars(vars_, 'a'), dense_vars(vars_, 'b')
        P = _product(A, B, _pairs_dot(hestenes))
        lines, c = _function('mv_%s_dense' % name, what, P, vars_.names)
        out += lines
        counts['mv_%s' % name] = c
    # the regressive product undual(dual(a) ^ dual(b)), dual(x) = x I^-1 = -x I:
    # the variables declared in the order of the blades of dual(a), dual(b), so
    # that a_major sums in the order of ga_mv_op's loop on the duals
    vars_ = Vars()
    I = {I_MASK: 1}
    DA, DB = {}, {}
    for D, cname in ((DA, 'a'), (DB, 'b')):
        for m in ALG.masks:
            # dual(x) at blade m is -sign * x at blade j, where e_j I = sign e_m
            j = m ^ I_MASK
            s, mm = ALG.blade_product(j, I_MASK)
            assert mm == m
            D[m] = -s * vars_('%s[%d]' % (cname, ALG.index[j]))
    W = ALG.product(DA, DB, Algebra.OP)
    P = ALG.product(W, I)
    lines, c = _function('mv_regressive_dense', 'the regressive product a & b', P, vars_.names)
    out += lines
    counts['mv_regressive'] = c
    # the commutator (a b - b a) / 2: the anticommuting pairs of blades i < j
    # (i = j commutes), each as s_ij (a_i b_j - a_j b_i) since s_ji = -s_ij,
    # in the order of (i, j): swapping a and b negates every difference
    # exactly, so a x b = -(b x a) and a x a = 0 hold bit for bit
    terms = {}
    for i, mi in enumerate(ALG.masks):
        for j, mj in enumerate(ALG.masks):
            if j <= i or not _anticommute(mi, mj):
                continue
            s, m = ALG.blade_product(mi, mj)
            terms.setdefault(m, []).append((s, i, j))
    lines, mul, add = [], 0, 0
    for k, m in enumerate(ALG.masks):
        pieces = []
        for s, i, j in terms.get(m, []):
            t = '(a[%d] * b[%d] - a[%d] * b[%d])' % (i, j, j, i)
            pieces.append(('-' if s < 0 else '') + t if not pieces else ('- ' if s < 0 else '+ ') + t)
        mul, add = mul + 2 * len(pieces), add + 2 * len(pieces) - 1 if pieces else add
        lines += wrap('r[%d]' % k, ' '.join(pieces) if pieces else '0.0')
    counts['mv_commutator'] = (mul, add)
    out += ['', '/* r = the commutator product (a b - b a) / 2: %d multiplications, %d additions. */'
            % (mul, add),
            'static void mv_commutator_dense(const double *restrict a, const double *restrict b,',
            '                                double *restrict r)', '{']
    out += lines + ['}']
    return out, counts


PARITY = (('e', 0), ('o', 1))


def _sparse_vars(vars_, cname, keep):
    return {m: vars_('%s[%d]' % (cname, i)) for i, m in enumerate(ALG.masks) if keep(m)}


def gen_sparse():
    out, counts = [], {}
    # a of one parity times b of one grade k
    for pname, par in PARITY:
        for k in range(6):
            vars_ = Vars()
            A = _sparse_vars(vars_, 'a', lambda m: popcount(m) % 2 == par)
            B = _sparse_vars(vars_, 'b', lambda m: popcount(m) == k)
            P = ALG.product(A, B)
            what = 'a b, a %s (its other blades not read), b of grade %d' % (
                'even' if par == 0 else 'odd', k)
            lines, c = _function('mv_gp_%sg%d' % (pname, k), what, P, vars_.names)
            out += lines
            counts['mv_gp_%sg%d' % (pname, k)] = c
    # a of one parity times b of one parity
    for pname, par in PARITY:
        for qname, qar in PARITY:
            vars_ = Vars()
            A = _sparse_vars(vars_, 'a', lambda m: popcount(m) % 2 == par)
            B = _sparse_vars(vars_, 'b', lambda m: popcount(m) % 2 == qar)
            P = ALG.product(A, B)
            what = 'a b, a %s, b %s (their other blades not read)' % (
                'even' if par == 0 else 'odd', 'even' if qar == 0 else 'odd')
            lines, c = _function('mv_gp_%s%s' % (pname, qname), what, P, vars_.names)
            out += lines
            counts['mv_gp_%s%s' % (pname, qname)] = c
    # a b for a and b of one parity, both even or both odd: its scalar and
    # grade-4 coefficients alone (r[0], r[26..30]; the others not written).
    # a ~a has no other grade but grade 2's rounding (it is its own reverse),
    # which ga/mv_algebra.c's versor inverse does not need
    for pname, par in PARITY:
        vars_ = Vars()
        A = _sparse_vars(vars_, 'a', lambda m: popcount(m) % 2 == par)
        B = _sparse_vars(vars_, 'b', lambda m: popcount(m) % 2 == par)
        P = ALG.product(A, B)
        lines, mul, add = [], 0, 0
        for i, m in enumerate(ALG.masks):
            if popcount(m) not in (0, 4):
                continue
            p = P.get(m, Poly())
            lines += emit_sum('r[%d]' % i, p, vars_.names, a_major)
            dm, da = p.ops()
            mul, add = mul + dm, add + da
        name = 'mv_gp_%s%s_g04' % (pname, pname)
        counts[name] = (mul, add)
        out += ['', '/* r[0], r[26..30] = the scalar and grade-4 coefficients of a b, a and b %s (their' % (
                    'even' if par == 0 else 'odd'),
                '   other blades not read; r\'s other coefficients not written): %d multiplications,' % mul,
                '   %d additions (mv_gp_%s%s\'s sums). */' % (add, pname, pname),
                'static void %s(const double *restrict a, const double *restrict b, double *restrict r)' % name,
                '{'] + lines + ['}']
    # an even multivector times a vector on their coefficients alone (the
    # public ga_mv_gp_even_vector_sparse): e[j] the j-th even blade, v[j] the
    # j-th vector, o[j] the j-th odd blade of the result, in the canonical
    # order; the variables declared in mv_gp_eg1's order, so the same sums
    vars_ = Vars()
    ev = [m for m in ALG.masks if popcount(m) % 2 == 0]
    od = [m for m in ALG.masks if popcount(m) % 2 == 1]
    A = {m: vars_('e[%d]' % j) for j, m in enumerate(ev)}
    B = {m: vars_('v[%d]' % j) for j, m in enumerate(m for m in ALG.masks if popcount(m) == 1)}
    P = ALG.product(A, B)
    assert all(popcount(m) % 2 == 1 for m in P)
    lines, mul, add = [], 0, 0
    for j, m in enumerate(od):
        p = P.get(m, Poly())
        lines += emit_sum('o[%d]' % j, p, vars_.names, a_major)
        dm, da = p.ops()
        mul, add = mul + dm, add + da
    counts['mv_gp_eg1_sparse'] = (mul, add)
    out += ['', '/* o = the odd coefficients of e v, e the 16 even coefficients of a multivector, v the',
            '   5 of a vector: %d multiplications, %d additions (mv_gp_eg1\'s sums). */' % (mul, add),
            'static void mv_gp_eg1_sparse(const double *restrict e, const double *restrict v, double *restrict o)',
            '{'] + lines + ['}']
    # vector times vector
    vars_ = Vars()
    A = _sparse_vars(vars_, 'a', lambda m: popcount(m) == 1)
    B = _sparse_vars(vars_, 'b', lambda m: popcount(m) == 1)
    P = ALG.product(A, B)
    lines, c = _function('mv_gp_g1g1', 'a b of the vector parts of a and b', P, vars_.names)
    out += lines
    counts['mv_gp_g1g1'] = c
    return out, counts


def generate():
    dense, c1 = gen_dense()
    sparse, c2 = gen_sparse()
    counts = dict(c1)
    counts.update(c2)
    head = [HEADER, '',
            'The products of ga/mv_kernels.c, every term written out from the blade',
            'products of G(4,1) (section 1 of the script): the scalar product, the fat',
            "dot, Hestenes' inner product, the regressive and the commutator product of",
            'two general multivectors, and the sparse kernels of the geometric product',
            '(a of one parity times b of one grade or of one parity; a vector times a',
            'vector). Each component sums its terms in the order of the blade loop:',
            'a\'s blade, then b\'s. Every r[0..31] is written (0.0 where no term falls).']
    text = '\n'.join(comment_block(head) + dense + sparse) + '\n'
    return text, counts
