"""gen/mv_products.py: ga/mv_products.inc, the dense products of ga/mv.c.

gp, op and lc of two general multivectors (ga_mv_gp, ga_mv_op, ga_mv_lc),
every term written out from the blade products of section 1 (gen/common.py),
each component summing its terms in the order of the blade loop they replace;
and, for gcc, the geometric product again in vectors of 2, 4 or 8 doubles
(gen_gp_blocks), the same operations in the same order.
"""

from common import ALG, Algebra, HEADER, Poly, Vars, a_major, comment_block, dense_vars, emit_sum

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
