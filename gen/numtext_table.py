"""gen/numtext_table.py: ga/numtext_table.inc, the powers of ten of ga/numtext.c.

The table g(k) of the shortest-decimal writer (Schubfach) and the integer
approximations of logarithms it uses, each checked exactly over its range.
"""

from common import HEADER, comment_block

PATH = 'ga/numtext_table.inc'


# ---- 7. powers of ten for the shortest-decimal writer (ga/numtext_table.inc)

# The tool writes each double as the shortest decimal that reads back as it
# (ga/numtext.c, after Giulietti's Schubfach). It needs, for every k with
# 10^k between the doubles' extremes, g(k) = floor(beta) + 1 where
# 10^-k = beta 2^r, 2^125 <= beta < 2^126: an overestimate of 10^-k by less
# than one unit in its 126th bit, split into two 63-bit halves. Also the three
# integer approximations of logarithms it uses, checked here exactly over the
# whole range they are used on.

NT_Q_MIN, NT_Q_MAX = -1074, 2046 - 1075  # v = c 2^q, c < 2^53 (subnormals: q = Q_MIN)
NT_LOG10_2 = (661971961083, 41)  # floor(q log10 2) = q * A >> S
NT_LOG10_3_4 = -274743187321     # floor(log10(3/4 2^q)) = (q * A + B) >> S
NT_LOG2_10 = (913124641741, 38)  # floor(e log2 10) = e * A >> S


def floor_log(num, den, base):
    """floor(log_base(num/den)) for positive integers, exactly."""
    e = 0
    while num >= den * base:
        den *= base
        e += 1
    while num < den:
        num *= base
        e -= 1
    return e


def nt_check_logs():
    a, sh = NT_LOG10_2
    for q in range(NT_Q_MIN - 1, NT_Q_MAX + 2):
        num, den = (2 ** q, 1) if q >= 0 else (1, 2 ** -q)
        assert (q * a) >> sh == floor_log(num, den, 10), q
        assert (q * a + NT_LOG10_3_4) >> sh == floor_log(3 * num, 4 * den, 10), q
    a, sh = NT_LOG2_10
    for e in range(-400, 401):
        num, den = (10 ** e, 1) if e >= 0 else (1, 10 ** -e)
        assert (e * a) >> sh == floor_log(num, den, 2), e


def generate():
    nt_check_logs()
    a, sh = NT_LOG10_2
    k_min = (NT_Q_MIN * a + NT_LOG10_3_4) >> sh
    k_min = min(k_min, (NT_Q_MIN * a) >> sh)
    k_max = (NT_Q_MAX * a) >> sh
    rows = []
    for k in range(k_min, k_max + 1):
        num, den = (10 ** -k, 1) if k <= 0 else (1, 10 ** k)
        r = floor_log(num, den, 2) - 125
        # beta = num / (den 2^r)
        if r >= 0:
            beta_num, beta_den = num, den << r
        else:
            beta_num, beta_den = num << -r, den
        g = beta_num // beta_den + 1
        assert 2 ** 125 < g <= 2 ** 126
        rows.append('    {0x%016xu, 0x%016xu}, /* %d */' % (g >> 63, g & (2 ** 63 - 1), k))
    head = [HEADER, '',
            'g(k) for 10^-k = beta 2^r, 2^125 <= beta < 2^126: floor(beta) + 1, as two',
            '63-bit halves {g >> 63, g mod 2^63}, for k = NT_K_MIN .. NT_K_MAX (row k - NT_K_MIN).',
            'ga/numtext.c includes it; section 7 of the script derives it.']
    out = comment_block(head) + [
        '#define NT_K_MIN (%d)' % k_min, '#define NT_K_MAX %d' % k_max,
        '#define NT_LOG10_2 %dLL' % NT_LOG10_2[0], '#define NT_LOG10_2_SHIFT %d' % NT_LOG10_2[1],
        '#define NT_LOG10_3_4 (%dLL)' % NT_LOG10_3_4,
        '#define NT_LOG2_10 %dLL' % NT_LOG2_10[0], '#define NT_LOG2_10_SHIFT %d' % NT_LOG2_10[1],
        'static const uint64_t nt_g[%d][2] = {' % (k_max - k_min + 1)] + rows + ['};']
    return '\n'.join(out) + '\n', {}
