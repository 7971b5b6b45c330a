"""gen/series.py: ga/internal/series_coef.inc, the coefficients of the sinc family.

Every series that the library's closed forms switch to near an angle of 0 is
one of

    sum_k (-1)^k w(k) x^k / (2k + d)!,    x the square of the angle,

with w(k) = 1 (f_d: f_0 = cos, f_1 = sinc, f_2 = (1 - cos)/th^2, ...) or a
linear weight (the derivatives and Jacobians built from them). Each
coefficient is the double nearest the exact rational: one rounding of a
Fraction, which is also what C gives for `1.0 / 720`.
"""

from fractions import Fraction
from math import comb, factorial

PATH = 'ga/internal/series_coef.inc'

# ---- 12. the sinc family (ga/internal/series_coef.inc)

TERMS = 18  # enough for |x| <= 1 to below 1/36! of the first term

# name, d, weight (a, b) for w(k) = a k + b, the sign of the whole series,
# what it is. Order matters only for the enum values.
FAMILIES = [
    ('F0', 0, (0, 1), 1, 'f_0 = cos th'),
    ('F1', 1, (0, 1), 1, 'f_1 = sin th / th'),
    ('F2', 2, (0, 1), 1, 'f_2 = (1 - cos th) / th^2'),
    ('F3', 3, (0, 1), 1, 'f_3 = (th - sin th) / th^3'),
    ('F4', 4, (0, 1), 1, 'f_4 = (cos th - 1 + th^2/2) / th^4'),
    ('K', 3, (2, 2), -1, 'k = (cos th - sinc th) / th^2'),
    ('N1', 4, (2, 2), 1, 'n_1 = (2 - 2 cos th - th sin th) / th^4'),
    ('N2', 5, (2, 2), -1, 'n_2 = (3 sin th - 2 th - th cos th) / th^5'),
    ('JC', 5, (1, 1), 1, 'sum (-1)^k (k+1) x^k / (2k+5)!'),
]


# and one series of another family, whose terms are Bernoulli numbers:
# COT(th) = (1 - (th/2) cot(th/2)) / th^2 = sum_k (-1)^k B_2k+2 x^k / (2k+2)!,
# the coefficient of [w]x^2 in the inverse of the SO(3) Jacobian (and of V^-1
# in the SE(3) log)
COT = ('COT', 'cot = (1 - (th/2) cot(th/2)) / th^2: (-1)^k B_(2k+2) / (2k+2)!')


def coefficient(d, weight, sign, k):
    a, b = weight
    return float(Fraction(sign * (-1) ** k * (a * k + b), factorial(2 * k + d)))


def bernoulli(n):
    """B_0 .. B_n as Fractions (B_1 = -1/2)."""
    b = [Fraction(1)]
    for m in range(1, n + 1):
        b.append(-sum(comb(m + 1, j) * b[j] for j in range(m)) / (m + 1))
    return b


def cot_coefficients():
    b = bernoulli(2 * TERMS + 2)
    return [float((-1) ** k * b[2 * k + 2] / factorial(2 * k + 2)) for k in range(TERMS)]


def generate():
    out = ['/* ga/internal/series_coef.inc: written by gen/generate.py (gen/series.py,',
           ' * section 12); do not edit. Included by ga/internal/series.h.',
           ' *',
           ' * GA__SERIES[f][k] = s (-1)^k w(k) / (2k + d)!, the double nearest the',
           ' * exact rational, the series of f in x = th^2: */',
           'enum {']
    for i, (name, d, weight, sign, what) in enumerate(FAMILIES):
        a, b = weight
        w = '1' if a == 0 else '%sk+%d' % ('' if a == 1 else a, b)
        out.append('    GA__SERIES_%s = %d, /* %s: d = %d, w = %s, s = %d */' % (name, i, what, d, w, sign))
    out.append('    GA__SERIES_%s = %d, /* %s */' % (COT[0], len(FAMILIES), COT[1]))
    out.append('    GA__SERIES_FAMILIES = %d' % (len(FAMILIES) + 1))
    out.append('};')
    out.append('enum { GA__SERIES_TERMS = %d };' % TERMS)
    out.append('static const double GA__SERIES[GA__SERIES_FAMILIES][GA__SERIES_TERMS] = {')
    rows = [(name, [coefficient(d, weight, sign, k) for k in range(TERMS)])
            for name, d, weight, sign, what in FAMILIES] + [(COT[0], cot_coefficients())]
    for name, row in rows:
        out.append('    /* %s */' % name)
        vals = [repr(v) for v in row]
        for i in range(0, TERMS, 4):
            out.append('    ' + ('{' if i == 0 else ' ') + ', '.join(vals[i:i + 4])
                       + ('},' if i + 4 >= TERMS else ','))
    out.append('};')
    return '\n'.join(out) + '\n', {}
