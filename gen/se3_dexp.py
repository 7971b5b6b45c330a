"""gen/se3_dexp.py: interp/se3_dexp.inc, the vector part of se3_dexp.

se3_dexp (interp/group.c) computes J_r(x) y for the right Jacobian of SE(3).
Its vector part is generated from the matrix formula in group.c's comment
(Jr(w) = I - a1 W + a W^2, Q with a, b, c), expanded by multiplying the 3x3
matrices W = [w]x and V = [v]x symbolically (section 11); the code emitted is
a chain of cross products (a straight-line program, section 10), asserted
equal to that expansion. The scalar coefficients a1, a, b, c (their closed
forms, and the Taylor series jac_series for th < 1) stay hand-written C in
group.c: the script generates only what is built from them.
"""

from fractions import Fraction

from common import HEADER, Poly, Vars, comment_block, wrap

PATH = 'interp/se3_dexp.inc'


# ---- 10. straight-line programs over 3-vectors ------------------------------

class Expr:
    """A scalar C expression: its text, its precedence, its value as a Poly
    and what evaluating it costs. Sums and products associate left to right,
    as C evaluates them."""

    ATOM, MUL, ADD = 3, 2, 1

    def __init__(self, text, prec, value, mul=0, add=0):
        self.text, self.prec, self.value = text, prec, value
        self.mul, self.add = mul, add

    def _side(self, prec, right):
        paren = self.prec < prec or (right and self.prec == prec)
        return '(' + self.text + ')' if paren else self.text

    def _bin(self, o, op, prec, value, dmul, dadd):
        text = self._side(prec, False) + ' ' + op + ' ' + o._side(prec, True)
        return Expr(text, prec, value, self.mul + o.mul + dmul, self.add + o.add + dadd)

    def __add__(self, o):
        return self._bin(o, '+', Expr.ADD, self.value + o.value, 0, 1)

    def __sub__(self, o):
        return self._bin(o, '-', Expr.ADD, self.value - o.value, 0, 1)

    def __mul__(self, o):
        return self._bin(o, '*', Expr.MUL, self.value * o.value, 1, 0)

    def neg(self):
        """-self, of a variable or constant (free: it folds into the next operation)."""
        assert self.prec == Expr.ATOM and not self.text.startswith('-')
        return Expr('-' + self.text, Expr.ATOM, -self.value)


class Program:
    """A straight-line program: named scalars and 3-vectors (ga_vec3), each
    component one C expression. Keeps the C lines, the symbolic value of
    every name, and the op count."""

    def __init__(self):
        self.lines = []
        self.mul = self.add = 0

    def _count(self, e):
        self.mul += e.mul
        self.add += e.add

    def scalar(self, name, e, note=None):
        self._count(e)
        line = '    double %s = %s;' % (name, e.text)
        self.lines.append(line + (' /* %s */' % note if note else ''))
        return Expr(name, Expr.ATOM, e.value)

    def vector(self, name, comps, note):
        self.lines.append('    ga_vec3 %s; /* %s */' % (name, note))
        out = []
        for axis, e in zip('xyz', comps):
            self._count(e)
            self.lines += wrap('%s.%s' % (name, axis), e.text)
            out.append(Expr('%s.%s' % (name, axis), Expr.ATOM, e.value))
        return out

    def store(self, lhs, e):
        self._count(e)
        self.lines += wrap(lhs, e.text)


def leaf(text, value):
    return Expr(text, Expr.ATOM, value)


def vec_leaf(vars_, cname):
    """The ga_vec3 in scope named cname, its components variables."""
    return [leaf('%s.%s' % (cname, a), vars_('%s.%s' % (cname, a))) for a in 'xyz']


def cross(a, b):
    """a x b, component by component."""
    return [a[1] * b[2] - a[2] * b[1],
            a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0]]


def lincomb(terms):
    """sum of +- coef x over terms (sign, coef or None, x), left to right: a
    negative term is a subtraction, or has its coefficient negated if it
    comes first (both exact: (-k) x = -(k x))."""
    out = []
    for axis in range(3):
        acc = None
        for sign, k, x in terms:
            if acc is None:
                if k is None:
                    acc = x[axis].neg() if sign < 0 else x[axis]
                else:
                    acc = (k.neg() if sign < 0 else k) * x[axis]
            else:
                t = x[axis] if k is None else k * x[axis]
                acc = acc + t if sign > 0 else acc - t
        out.append(acc)
    return out


# ---- 11. se3_dexp's vector part (interp/se3_dexp.inc) -----------------------

def mat_hat(x):
    """[x]x, the 3x3 cross-product matrix of x (3 Polys)."""
    z = Poly()
    return [[z, -x[2], x[1]], [x[2], z, -x[0]], [-x[1], x[0], z]]


def mat_mul(A, B):
    return [[sum((A[i][k] * B[k][j] for k in range(3)), Poly()) for j in range(3)]
            for i in range(3)]


def mat_lin(terms):
    """sum of k M over (k, M), k a Poly or a number."""
    return [[sum((k * M[i][j] for k, M in terms), Poly()) for j in range(3)] for i in range(3)]


def mat_vec(M, x):
    return [sum((M[i][k] * x[k] for k in range(3)), Poly()) for i in range(3)]


def dexp_definition(w, v, dw, dv, a1, a, b, c):
    """(Jr(w) dw, Q dw + Jr(w) dv) by the matrix formula of group.c's comment
    (Barfoot & Furgale 2014, eqs. 100-102, in (w, v) order):
        Jr(w) = I - a1 W + a W^2,
        Q = -V/2 + a (WV + VW - WVW) - b (WWV + VWW - 3 WVW) + c (WVWW + WWVW)."""
    one = Poly.lift(1)
    I = [[one if i == j else Poly() for j in range(3)] for i in range(3)]
    W, V = mat_hat(w), mat_hat(v)
    WW, WV, VW = mat_mul(W, W), mat_mul(W, V), mat_mul(V, W)
    WVW, WWV, VWW = mat_mul(WV, W), mat_mul(W, WV), mat_mul(V, WW)
    WVWW, WWVW = mat_mul(WVW, W), mat_mul(W, WVW)
    Jr = mat_lin([(one, I), (-a1, W), (a, WW)])
    Q = mat_lin([(Fraction(-1, 2), V), (a, WV), (a, VW), (-a, WVW), (-b, WWV), (-b, VWW),
                 (3 * b, WVW), (c, WVWW), (c, WWVW)])
    jdv = mat_vec(Jr, dv)
    return mat_vec(Jr, dw) + [q + j for q, j in zip(mat_vec(Q, dw), jdv)]


def dexp_program(w, v, dw, dv, a1, a, b, c, factored):
    """The cross-product chain that evaluates dexp_definition.

    Both forms share y = W dw and z = W W dw, with Jr(w) dw = dw - a1 y + a z
    (and the same for dv). factored=False applies every matrix product of Q
    as its own chain and sums them in the formula's order, as the
    hand-written se3_dexp did (8 distinct cross products for Q dw);
    factored=True collects Q dw by its leftmost factor, with p = V dw, the
    coefficient (3 b - a) of WVW and W (c V W dw - b V dw) for c WWVW - b WWV:
        Q dw = -p/2 + a V y - b V z + W g,
        g = a p + (3 b - a) V y + c V z + W (c V y - b p),
    5 cross products."""
    P = Program()
    half = leaf('0.5', Poly.lift(Fraction(1, 2)))
    three = leaf('3.0', Poly.lift(3))
    y = P.vector('wdw', cross(w, dw), 'W dw')
    z = P.vector('wwdw', cross(w, y), 'W W dw')
    ydv = P.vector('wdv', cross(w, dv), 'W dv')
    zdv = P.vector('wwdv', cross(w, ydv), 'W W dv')
    p = P.vector('vdw', cross(v, dw), 'V dw')
    vy = P.vector('vwdw', cross(v, y), 'V W dw')
    vz = P.vector('vwwdw', cross(v, z), 'V W W dw')
    if factored:
        k = P.scalar('k', three * b - a, '3 b - a')
        t = P.vector('t', lincomb([(1, c, vy), (-1, b, p)]), 'c V W dw - b V dw')
        wt = P.vector('wt', cross(w, t), 'W t')
        g = P.vector('g', lincomb([(1, a, p), (1, k, vy), (1, c, vz), (1, None, wt)]),
                     'a V dw + (3 b - a) V W dw + c V W W dw + W t')
        wg = P.vector('wg', cross(w, g), 'W g')
        q = P.vector('q', lincomb([(-1, half, p), (1, a, vy), (-1, b, vz), (1, None, wg)]),
                     'Q dw = -V dw / 2 + a V W dw - b V W W dw + W g')
    else:
        b3 = P.scalar('b3', three * b, '3 b')
        wp = P.vector('wvdw', cross(w, p), 'W V dw')
        wvy = P.vector('wvwdw', cross(w, vy), 'W V W dw')
        wwp = P.vector('wwvdw', cross(w, wp), 'W W V dw')
        wvz = P.vector('wvwwdw', cross(w, vz), 'W V W W dw')
        wwvy = P.vector('wwvwdw', cross(w, wvy), 'W W V W dw')
        q = P.vector('q', lincomb([(-1, half, p), (1, a, wp), (1, a, vy), (-1, a, wvy),
                                   (-1, b, wwp), (-1, b, vz), (1, b3, wvy), (1, c, wvz),
                                   (1, c, wwvy)]), 'Q dw')
    outs = lincomb([(1, None, dw), (-1, a1, y), (1, a, z)]) + \
        lincomb([(1, None, dv), (-1, a1, ydv), (1, a, zdv), (1, None, q)])
    for i, e in enumerate(outs):  # Jr(w) dw, then Jr(w) dv + Q dw
        P.store('out[%d]' % i, e)
    return P, [e.value for e in outs]


# The form emitted. factored=False is the old hand-written se3_dexp, bit for
# bit (but for its sum starting at +0.0); factored=True takes 91 multiplications
# and 64 additions instead of 112 and 75, ran its vector part in about 0.85x
# the time, and against a long double evaluation its largest error, relative
# to the norm of Jr(w) dw and of Q dw + Jr(w) dv, was the same or smaller for
# |w| from 1e-9 to 20 (2e6 random inputs).
DEXP_FACTORED = True


def generate():
    vars_ = Vars()  # the names in scope
    a1, a, b, c = (leaf(n, vars_(n)) for n in ('a1', 'a', 'b', 'c'))
    w, v, dw, dv = (vec_leaf(vars_, n) for n in ('w', 'v', 'dw', 'dv'))
    val = lambda x: [e.value for e in x]
    want = dexp_definition(val(w), val(v), val(dw), val(dv), a1.value, a.value, b.value,
                           c.value)
    full = [sum(o) for o in zip(*(p.ops() for p in want))]
    counts = {'se3_dexp, full expansion': tuple(full)}
    chosen = None
    for factored in (False, True):
        P, got = dexp_program(w, v, dw, dv, a1, a, b, c, factored)
        for i in range(6):
            assert got[i] == want[i], 'se3_dexp: the chain differs from the formula in out[%d]' % i
        counts['se3_dexp, %s' % ('factored chain' if factored else 'one chain per product')] = \
            (P.mul, P.add)
        if factored == DEXP_FACTORED:
            chosen = P
    head = [HEADER, '',
            'The vector part of se3_dexp (interp/group.c): out = J_r(x) y for the right',
            'Jacobian of SE(3) in twist coordinates x = (w, v), y = (dw, dv):',
            '    out = (Jr(w) dw, Q dw + Jr(w) dv),  Jr(w) = I - a1 W + a W^2,',
            '    Q = -V/2 + a (WV + VW - WVW) - b (WWV + VWW - 3 WVW) + c (WVWW + WWVW),',
            'W = [w]x, V = [v]x (the formula of group.c), evaluated as the chain of cross',
            'products below, which the script asserts equal to the matrix products',
            'expanded symbolically.']
    if DEXP_FACTORED:
        head += ['Q dw is collected by its leftmost factor (p = V dw, y = W dw, z = W y):',
                 '    Q dw = -p/2 + a V y - b V z + W g,',
                 '    g = a p + (3 b - a) V y + c V z + W (c V y - b p).']
    head += ['%d multiplications, %d additions (the full expansion in monomials would' %
             (chosen.mul, chosen.add),
             'take %d and %d).' % tuple(full),
             'Needs in scope: ga_vec3 w, v, dw, dv; double a1, a, b, c (the coefficients',
             'of group.c); double *out (6 doubles).']
    text = '\n'.join(comment_block(head) + chosen.lines) + '\n'
    return text, counts
