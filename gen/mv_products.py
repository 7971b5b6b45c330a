"""gen/mv_products.py: ga/mv_products.inc, the dense products of ga/mv.c.

gp, op and lc of two general multivectors (ga_mv_gp, ga_mv_op, ga_mv_lc),
every term written out from the blade products of section 1 (gen/common.py),
each component summing its terms in the order of the blade loop they replace;
and, for gcc, the geometric product again in vectors of 2, 4 or 8 doubles
(gen_gp_blocks), the same operations in the same order.
"""

from common import (ALG, Algebra, HEADER, Poly, Vars, a_major, comment_block, dense_vars, emit_sum,
                    popcount)

PATH = 'ga/mv_products.inc'


# ---- 8. the dense products (ga/mv_products.inc) -----------------------------

# gp, op and lc of two general multivectors, every term written out: each
# component is the sum of its blade pairs in the order of ga/mv.c's loop
# (a_major: a's blade, then b's), so the rounding is that of the loop, term
# for term. What differs from the loop: the sum starts at its first term, not
# at +0.0 (only the sign of a zero result can differ), and no term is skipped
# where a coefficient of a is zero (a zero term added to a sum leaves it
# unchanged, so finite inputs give the same numbers; an Inf in b beside a zero
# in a now gives NaN where the loop skipped it: NaN in, NaN out still holds).
DENSE = [('gp', Algebra.GP, 'the geometric product a b'),
         ('op', Algebra.OP, 'the outer product a ^ b'),
         ('lc', Algebra.LC, 'the left contraction a _| b')]


def generate():
    out, counts = [], {}
    for name, kind, what in DENSE:
        vars_ = Vars()
        A, B = dense_vars(vars_, 'a'), dense_vars(vars_, 'b')
        P = ALG.product(A, B, kind)
        lines, mul, add = [], 0, 0
        for i, m in enumerate(ALG.masks):
            lines += emit_sum('r[%d]' % i, P.get(m, Poly()), vars_.names, a_major)
            dm, da = P.get(m, Poly()).ops()
            mul, add = mul + dm, add + da
        counts['mv_%s' % name] = (mul, add)
        out += ['', '/* r = %s: %d multiplications, %d additions. */' % (what, mul, add),
                'GA_DENSE_FN void mv_%s_dense(const double *restrict a, const double *restrict b,'
                % name,
                '                             double *restrict r)', '{']
        out += lines + ['}']
    out += gen_gp_blocks()
    out += gen_more_blocks()
    head = [HEADER, '',
            'The dense products of ga/mv.c (ga_mv_gp, ga_mv_op, ga_mv_lc), every term',
            'written out from the blade products of G(4,1) (section 1 of the script).',
            'Each component sums its terms in the order of the blade loop they replace:',
            'a\'s blade, then b\'s. Needs GA_DENSE_FN defined (static inline, or more).',
            'With GA_DENSE_BLOCKS defined (gcc only: vector extensions, __builtin_shuffle),',
            'also mv_gp_blocks2, 4 and 8: the same geometric product in vectors of 2, 4',
            'or 8 doubles, the same operations in the same order (see gen_gp_blocks).']
    text = '\n'.join(comment_block(head) + out) + '\n'
    return text, counts


# The geometric product again, in vectors of W = 2, 4 or 8 doubles (gcc's
# vector extensions; ga/mv.c compiles each for the instruction set of its
# width and picks one at load time). Indexed by blade mask, the product is
# r[i] = sum over a's blades m of sign(m, i ^ m) a[m] b[i ^ m]: for a fixed m,
# the b's of W consecutive results (an aligned block) are one aligned block of
# b, at block (block ^ m / W), with its lanes permuted by lane ^ (m % W), so
# each (m, block) is a shuffle, a sign flip (xor of the sign bits, exact), a
# product with a[m] and a sum. b is first copied into mask order and the result
# copied back into the blade order of ga_mv. The terms of each component are
# added in the order of a's blades, left to right, as mv_gp_dense adds them,
# and (+-x) a = +-(x a) exactly, so the result is mv_gp_dense's, bit for bit
# (but the sign of a NaN).
def gen_gp_blocks():
    masks = ALG.masks
    out = ['', '#ifdef GA_DENSE_BLOCKS',
           '#define MV_NEG (-0x7fffffffffffffffLL - 1) /* the sign bit */',
           '/* the sign bit of sign(m, i ^ m): row k for m the mask of a\'s blade k,',
           '   column i the result\'s mask */',
           'static const long long mv_gp_sign_bits[32][32] = {']
    rows = []
    for ma in masks:
        bits = ['MV_NEG' if ALG.blade_product(ma, i ^ ma)[0] < 0 else '0' for i in range(32)]
        for chunk in range(0, 32, 8):
            rows.append(', '.join(bits[chunk:chunk + 8]))
    body = []
    for k in range(32):
        body.append('    {' + ',\n     '.join(rows[4 * k:4 * k + 4]) + '}')
    out += [',\n'.join(body), '};']
    for W in (2, 4, 8):
        nb = 32 // W
        vd, vi = 'mv_v%dd' % W, 'mv_v%di' % W
        out += ['', 'typedef double %s __attribute__((vector_size(%d)));' % (vd, 8 * W),
                'typedef long long %s __attribute__((vector_size(%d)));' % (vi, 8 * W), '',
                '/* r = the geometric product a b in %d vectors of %d doubles. */' % (nb, W),
                'GA_DENSE_FN void mv_gp_blocks%d(const double *restrict a, const double *restrict b,' % W,
                '                               double *restrict r)', '{',
                '    double bf[32], rf[32];',
                '    %s bm[%d], acc[%d], t;' % (vd, nb, nb),
                '    %s sg;' % vi]
        out += ['    bf[%d] = b[%d];' % (m, i) for i, m in enumerate(masks)]
        out += ['    __builtin_memcpy(bm, bf, sizeof bm);']
        out += ['    acc[%d] = a[0] * bm[%d];' % (q, q) for q in range(nb)]
        for k, ma in enumerate(masks):
            if k == 0:
                continue
            x, hi = ma % W, ma // W
            for q in range(nb):
                src = 'bm[%d]' % (q ^ hi)
                if x:
                    out += ['    t = __builtin_shuffle(%s, (%s){%s});' % (
                        src, vi, ', '.join(str(lane ^ x) for lane in range(W)))]
                    src = 't'
                out += ['    __builtin_memcpy(&sg, &mv_gp_sign_bits[%d][%d], sizeof sg);' % (k, W * q),
                        '    acc[%d] += a[%d] * (%s)((%s)%s ^ sg);' % (q, k, vd, vi, src)]
        out += ['    __builtin_memcpy(rf, acc, sizeof rf);']
        out += ['    r[%d] = rf[%d];' % (i, m) for i, m in enumerate(masks)]
        out += ['}']
    out += ['#endif']
    return out


# More products in the vectors of gen_gp_blocks, for ga/mv.c and
# ga/mv_kernels.c (section 8, continued):
#   - mv_gpe_blocksW, mv_gpo_blocksW: the geometric product for a of one
#     parity, the terms of a's even (odd) blades only, with the sign bits of
#     gen_gp_blocks; where a's other blades are 0 the terms left out are
#     zeros, so for finite b the result is mv_gp_dense's but the sign of a
#     zero;
#   - mv_dot_blocksW: the fat dot, each (m, block) a product with a factor
#     table, sign(m, i ^ m) for the pairs the dot keeps and 0 for the others
#     (x * +-1 is exact, x * 0 a zero), the (m, block) with no pair kept left
#     out: the terms of mv_dot_dense in its order, plus zeros. For finite a and
#     b its numbers, but the sign of a zero (an Inf in b beside a pair not
#     kept gives a NaN where the loop left the pair out).
# Each block's sum starts at its first term, as the straight-line code's.
def _dot_keeps(ma, mb):
    return (ma & mb) == ma or (ma & mb) == mb


# b into mask order, and the result back into blade order, as whole vectors:
# each block of W masks gathers its lanes from the blocks of b (blade order)
# that hold them, by two-source shuffles (an exact move of doubles, so the
# numbers are those of the scalar copy). Written for the dot only: with the
# copy through bf[] gcc builds each permuted b (lane ^ x) from 8 scalar loads,
# with the vectors it is one shuffle (docs/benchmarks.md, "Round three").
def _gather(W, dst, src, order, lines):
    """dst[q] lane l = src element order[W q + l] (src blocks of W)."""
    vi = 'mv_v%di' % W
    for q in range(32 // W):
        want = [order[W * q + l] for l in range(W)]
        blocks = sorted(set(e // W for e in want))
        if len(blocks) == 1:
            lines.append('    %s[%d] = __builtin_shuffle(%s[%d], (%s){%s});' % (
                dst, q, src, blocks[0], vi, ', '.join(str(e % W) for e in want)))
            continue
        b0, b1 = blocks[0], blocks[1]
        idx = [(e % W if e // W == b0 else W + e % W) if e // W in (b0, b1) else 0 for e in want]
        lines.append('    %s[%d] = __builtin_shuffle(%s[%d], %s[%d], (%s){%s});' % (
            dst, q, src, b0, src, b1, vi, ', '.join(map(str, idx))))
        for bx in blocks[2:]:
            idx = [W + e % W if e // W == bx else l for l, e in enumerate(want)]
            lines.append('    %s[%d] = __builtin_shuffle(%s[%d], %s[%d], (%s){%s});' % (
                dst, q, dst, q, src, bx, vi, ', '.join(map(str, idx))))


def gen_more_blocks():
    masks = ALG.masks
    out = ['', '#ifdef GA_DENSE_BLOCKS',
           '/* the factor of each pair of the fat dot: sign(m, i ^ m) where one blade is in',
           '   the other, else 0; row k for a\'s blade k, column i the result\'s mask */',
           'static const double mv_dot_factor[32][32] = {']
    rows = []
    for ma in masks:
        f = []
        for i in range(32):
            mb = i ^ ma
            f.append(('%d' % ALG.blade_product(ma, mb)[0]) if _dot_keeps(ma, mb) else '0')
        rows.append('    {' + ', '.join(f) + '}')
    out += [',\n'.join(rows), '};']
    for W in (2, 4, 8):
        nb = 32 // W
        vd, vi = 'mv_v%dd' % W, 'mv_v%di' % W
        for name, ks, dot in (('gpe', [k for k, m in enumerate(masks) if popcount(m) % 2 == 0], False),
                              ('gpo', [k for k, m in enumerate(masks) if popcount(m) % 2 == 1], False),
                              ('dot', list(range(32)), True)):
            what = {'gpe': 'the geometric product a b for a even (its odd blades not read)',
                    'gpo': 'the geometric product a b for a odd (its even blades not read)',
                    'dot': 'the fat dot a . b'}[name]
            out += ['', '/* r = %s in %d vectors of %d doubles. */' % (what, nb, W),
                    'GA_DENSE_FN void mv_%s_blocks%d(const double *restrict a, const double *restrict b,'
                    % (name, W),
                    '                               double *restrict r)', '{']
            if dot:
                out += ['    %s bv[%d], bm[%d], acc[%d], rv[%d], t, f;' % (vd, nb, nb, nb, nb),
                        '    __builtin_memcpy(bv, b, sizeof bv);']
                _gather(W, 'bm', 'bv', [ALG.index[m] for m in range(32)], out)
            else:
                out += ['    double bf[32], rf[32];',
                        '    %s bm[%d], acc[%d], t;' % (vd, nb, nb),
                        '    %s sg;' % vi]
                out += ['    bf[%d] = b[%d];' % (m, i) for i, m in enumerate(masks)]
                out += ['    __builtin_memcpy(bm, bf, sizeof bm);']
            started = [False] * nb
            for k in ks:
                ma = masks[k]
                x, hi = ma % W, ma // W
                for q in range(nb):
                    lanes = [W * q + l for l in range(W)]
                    if dot and not any(_dot_keeps(ma, i ^ ma) for i in lanes):
                        continue
                    src = 'bm[%d]' % (q ^ hi)
                    if x:
                        out += ['    t = __builtin_shuffle(%s, (%s){%s});' % (
                            src, vi, ', '.join(str(lane ^ x) for lane in range(W)))]
                        src = 't'
                    op = '+=' if started[q] else '='
                    started[q] = True
                    if dot:
                        out += ['    __builtin_memcpy(&f, &mv_dot_factor[%d][%d], sizeof f);' % (k, W * q),
                                '    acc[%d] %s a[%d] * (%s * f);' % (q, op, k, src)]
                    else:
                        out += ['    __builtin_memcpy(&sg, &mv_gp_sign_bits[%d][%d], sizeof sg);'
                                % (k, W * q),
                                '    acc[%d] %s a[%d] * (%s)((%s)%s ^ sg);' % (q, op, k, vd, vi, src)]
            assert all(started)
            if dot:
                _gather(W, 'rv', 'acc', masks, out)
                out += ['    __builtin_memcpy(r, rv, sizeof rv);']
            else:
                out += ['    __builtin_memcpy(rf, acc, sizeof rf);']
                out += ['    r[%d] = rf[%d];' % (i, m) for i, m in enumerate(masks)]
            out += ['}']
    out += ['#endif']
    return out
