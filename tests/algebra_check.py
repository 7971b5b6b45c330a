#!/usr/bin/env python3
"""tests/algebra_check.py: garotor's general inverse, regressive and
commutator products, projection and rejection (exact rational arithmetic),
powers of rotors (mpmath) and fits (scipy's geometric least squares),
against tests/algebra_dump's cases.

    algebra_check.py ALGEBRA_DUMP

The exact parts need the standard library only: an independent G(4,1) is
written here from the blade rule (a blade is a set of basis vectors; the sign
of a product is the parity of the swaps that sort it, times -1 for e5 e5).
The mpmath and scipy parts are skipped, with a line saying so, where the
module is missing. Every check prints one line, as tests/testkit.h does
("ok" or "FAIL", the count, the worst figure against its bound); exit status
1 when one fails.

Bounds (u = 2^-52, as the headers count; |x|_1 the sum of the absolute
coefficients):
  - inverse: mv.h's a a^-1 = 1 to u |a|_1 |a^-1|_1 (computed residual; the
    exact one is measured here) for the general way, 2 * 64 u sum a_i^2 / |s|
    for versors and blades; the forward error |X - a^-1| then within
    |a^-1|_1 times that; GA_ERR_SINGULAR exactly where a is a zero divisor
    (d = 0 exactly), not for the invertible ones;
  - regressive, commutator: small-integer inputs keep every partial sum an
    integer below 2^53, so the result is exact: equal, bit for bit;
  - projection, rejection: of integer vectors and blades, against the exact
    (a _| B) _| B^-1 and (a ^ B) |_ B^-1: within 4 * 33 u |a|_1 |B|_1 |B^-1|_1
    (the rounding of the two products and of the inverse);
  - powers: exp(t B) in mpmath at 40 digits (Taylor series of the product,
    scaling and squaring) against ga_mv_pow(ga_mv_exp(B), t): mv.h's 1e-13
    of |R| for exp and log, times (1 + |t|);
  - fits: fit.h's bias. Planes and lines are the geometric fit: within 1e-9
    of scipy.optimize.least_squares on the orthogonal distances (its own
    tolerance); spheres and circles of radius 1, noise sigma 0.05 on 1000
    points, 30 fits each: the mean of (r_linear - r_geometric) r / sigma^2
    within 0.06 of 1.5 (sphere) and 2 (circle) (over 5 standard errors of
    the mean: those are 0.008 and 0.011), the centres within 0.05 sigma
    of the geometric fit's.
"""
import subprocess
import sys
from fractions import Fraction

U = 2.0 ** -52
FAILS = 0

# ---- an exact G(4,1) ------------------------------------------------------------
MASKS = [0x00, 0x01, 0x02, 0x04, 0x08, 0x10, 0x03, 0x05, 0x09, 0x11, 0x06, 0x0a, 0x12, 0x0c, 0x14, 0x18, 0x07,
         0x0b, 0x13, 0x0d, 0x15, 0x19, 0x0e, 0x16, 0x1a, 0x1c, 0x0f, 0x17, 0x1b, 0x1d, 0x1e, 0x1f]
INDEX = {m: i for i, m in enumerate(MASKS)}
GRADE = [bin(m).count("1") for m in MASKS]


def blade_sign(a, b):
    swaps, x = 0, a >> 1
    while x:
        swaps += bin(x & b).count("1")
        x >>= 1
    if a & b & 0x10:
        swaps += 1
    return -1 if swaps & 1 else 1


TABLE = [[(INDEX[MASKS[i] ^ MASKS[j]], blade_sign(MASKS[i], MASKS[j])) for j in range(32)] for i in range(32)]


def product(a, b, keep):
    """sum over blade pairs (i, j) that keep(mask_i, mask_j) allows"""
    r = [0] * 32
    for i in range(32):
        if not a[i]:
            continue
        for j in range(32):
            if b[j] and keep(MASKS[i], MASKS[j]):
                k, s = TABLE[i][j]
                r[k] += s * a[i] * b[j]
    return r


def gp(a, b):
    return product(a, b, lambda x, y: True)


def op(a, b):
    return product(a, b, lambda x, y: x & y == 0)


def lc(a, b):
    return product(a, b, lambda x, y: x & y == x)


def signs(a, s):
    return [a[i] * s[GRADE[i]] for i in range(32)]


def reverse(a):
    return signs(a, [1, 1, -1, -1, 1, 1])


def rc(a, b):  # the right contraction: (~b _| ~a)~
    return reverse(lc(reverse(b), reverse(a)))


I5 = [0] * 31 + [1]
MINUS_I5 = [0] * 31 + [-1]


def dual(a):
    return gp(a, MINUS_I5)


def undual(a):
    return gp(a, I5)


def exact_inverse(a):
    """Hitzer and Sangwine's closed form in exact arithmetic (a rational):
    (a^-1, d), d = 0 for a zero divisor"""
    abar = signs(a, [1, -1, -1, 1, 1, -1])
    P = gp(a, abar)
    Ph = signs(P, [1, -1, 1, -1, 1, -1])
    B = gp(P, Ph)
    C = signs(B, [1, -1, 1, 1, -1, 1])
    d = gp(B, C)
    assert all(x == 0 for x in d[1:]), "B C is not a scalar: the closed form is wrong"
    if d[0] == 0:
        return None, 0
    N = gp(abar, gp(Ph, C))
    return [Fraction(x) / d[0] for x in N], d[0]


def sumabs(a):
    return sum(abs(x) for x in a)


def maxabs(a):
    return max(abs(x) for x in a)


def sub(a, b):
    return [x - y for x, y in zip(a, b)]


def exact(xs):
    return [Fraction(x) for x in xs]


class Check:
    def __init__(self, name, kind="max", tol=0.0):
        self.name, self.kind, self.tol = name, kind, tol
        self.n, self.bad, self.worst, self.ratio = 0, 0, 0.0, 0.0

    def add_tol(self, err, tol):
        self.n += 1
        r = 0.0 if err == 0 else (float("inf") if tol == 0 else err / tol)
        if not err <= tol:
            self.bad += 1
        if r >= self.ratio:
            self.ratio, self.worst, self.tol = r, float(err), float(tol)

    def add_bool(self, ok):
        self.n += 1
        self.bad += 0 if ok else 1

    def end(self):
        global FAILS
        ok = self.bad == 0
        if self.kind == "bool":
            tail = "held" if ok else "failed %d times" % self.bad
        else:
            tail = "worst %.3e  tol %.1e  (tol per case; worst err/tol %.3g)" % (self.worst, self.tol, self.ratio)
        print("%-4s %-62s n=%-7d %s" % ("ok" if ok else "FAIL", self.name, self.n, tail))
        FAILS += 0 if ok else 1


def read(dump, what):
    out = subprocess.run([dump, what], check=True, capture_output=True, text=True).stdout
    return [line.split() for line in out.splitlines()]


def mvs(fields, k):
    return [[float.fromhex(x) for x in fields[32 * i:32 * i + 32]] for i in range(k)]


# ---- the inverse ----------------------------------------------------------------------
def check_inverse(dump):
    names = {0: "dense", 3: "near zero divisors", 5: "zero divisors", 6: "versors and blades"}
    kind = {0: 0, 1: 0, 2: 0, 3: 3, 4: 3, 5: 5, 6: 6, 7: 6}
    st_ok = {k: Check("inverse, %s: GA_OK, or GA_ERR_SINGULAR where d = 0 exactly" % names[k], "bool") for k in names}
    res = {k: Check("inverse, %s: exact residual a a^-1 - 1" % names[k]) for k in names}
    fwd = {k: Check("inverse, %s: |X - a^-1| within |a^-1|_1 times that bound" % names[k]) for k in names}
    for f in read(dump, "inverse"):
        k, st = kind[int(f[1])], int(f[2])
        a, X = mvs(f[3:], 2)
        # dyadic coefficients: scaled to integers for the closed form
        scale = 2 ** 32
        ai = [int(Fraction(x) * scale) for x in a]
        assert all(Fraction(x) * scale == v for x, v in zip(a, ai))
        inv_i, d = exact_inverse(ai)
        st_ok[k].add_bool(st == (-2 if d == 0 else 0))
        if d == 0 or st != 0:
            continue
        inv = [x * scale for x in inv_i]
        ea, eX = exact(a), exact(X)
        r = gp(ea, eX)
        r[0] -= 1
        # the way mv.h takes: the versor way where a ~a is a scalar (these
        # are exact, integer or dyadic products: the library computes a ~a
        # without rounding and sees what is here)
        aa = gp(ai, reverse(ai))
        versor = all(x == 0 for x in aa[1:])
        s, sbar = aa[0] / scale ** 2, sum(x * x for x in a)
        bound = 2 * 64 * U * sbar / abs(s) if versor else U * sumabs(a) * sumabs(X)
        res[k].add_tol(float(maxabs(r)), bound)
        fwd[k].add_tol(float(maxabs(sub(eX, inv))), float(sumabs(inv)) * bound)
    for k in names:
        st_ok[k].end()
        if k != 5:
            res[k].end()
            fwd[k].end()


# ---- the regressive and commutator products, projections -------------------------------
def check_products(dump):
    reg = Check("regressive: small integers, exactly (a* ^ b*) I", "bool")
    com = Check("commutator: small integers, exactly (a b - b a) / 2", "bool")
    for f in read(dump, "products"):
        a, b, r = mvs(f[1:], 3)
        ai, bi = [int(x) for x in a], [int(x) for x in b]
        if f[0] == "reg":
            want = undual(op(dual(ai), dual(bi)))
            reg.add_bool(want == r)
        else:
            want = [Fraction(x - y, 2) for x, y in zip(gp(ai, bi), gp(bi, ai))]
            com.add_bool(want == exact(r))
    reg.end()
    com.end()


def check_projection(dump):
    st_ok = Check("projection: GA_OK onto invertible blades, SINGULAR onto null", "bool")
    pc = Check("projection: (a _| B) _| B^-1, exact")
    rj = Check("rejection: (a ^ B) |_ B^-1, exact")
    for f in read(dump, "projection"):
        st = int(f[1])
        a, B, P, R = mvs(f[2:], 4)
        ai, Bi = [int(x) for x in a], [int(x) for x in B]
        n2 = gp(Bi, reverse(Bi))[0]
        st_ok.add_bool(st == (0 if n2 != 0 else -2))
        if n2 == 0 or st != 0:
            continue
        Binv = [Fraction(x, n2) for x in reverse(Bi)]
        wantP, wantR = lc(lc(ai, Bi), Binv), rc(op(ai, Bi), Binv)
        tol = 4 * 33 * U * sumabs(a) * sumabs(B) * float(sumabs(Binv))
        pc.add_tol(float(maxabs(sub(exact(P), wantP))), tol)
        rj.add_tol(float(maxabs(sub(exact(R), wantR))), tol)
    st_ok.end()
    pc.end()
    rj.end()


# ---- powers: mpmath --------------------------------------------------------------------
def check_powers(dump):
    try:
        import mpmath
    except ImportError:
        print("SKIP powers against mpmath: no mpmath")
        return
    mpmath.mp.dps = 40

    def mexp(B):
        B = [mpmath.mpf(x) for x in B]
        n = max(abs(x) for x in B)
        s = max(0, int(mpmath.ceil(mpmath.log(n * 32, 2))) + 3)
        X = [x / 2 ** s for x in B]
        E, T = [mpmath.mpf(1)] + [mpmath.mpf(0)] * 31, [mpmath.mpf(1)] + [mpmath.mpf(0)] * 31
        for k in range(1, 30):
            T = [x / k for x in gp(T, X)]
            E = [e + t for e, t in zip(E, T)]
        for _ in range(s):
            E = gp(E, E)
        return E

    kinds = ["rotation", "boost", "null", "two rotations", "rotation x boost", "rotation x null"]
    chk = Check("pow(exp B, t) = exp(t B), mpmath, all kinds, t = 0.5, -1, 0.3, 2.5")
    for f in read(dump, "powers"):
        kind, st, t = int(f[1]), int(f[2]), float.fromhex(f[3])
        B, R, P = mvs(f[4:], 3)
        if st != 0:
            print("  pow of %s, t = %g: status %d" % (kinds[kind], t, st))
            chk.add_tol(float("inf"), 0)
            continue
        want = mexp([t * x for x in B])
        err = max(abs(mpmath.mpf(p) - w) for p, w in zip(P, want)) / max(abs(w) for w in want)
        chk.add_tol(float(err), 1e-13 * (1 + abs(t)))
    chk.end()


# ---- fits: scipy ---------------------------------------------------------------------------
def check_fits(dump):
    try:
        import numpy as np
        from scipy.optimize import least_squares
    except ImportError:
        print("SKIP fits against scipy: no numpy or scipy")
        return
    out = subprocess.run([dump, "fits"], check=True, capture_output=True, text=True).stdout.splitlines()
    k, bias = 0, {0: [], 1: []}
    cen = {0: Check("sphere: centre against the geometric fit's, / sigma"),
           1: Check("circle: centre against the geometric fit's, / sigma")}
    flat = {2: Check("plane: normal, distance against the geometric fit's"),
            3: Check("line: direction, point against the geometric fit's")}
    status = Check("fits: GA_OK", "bool")
    while k < len(out):
        f = out[k].split()
        kind, st, sigma, n = int(f[1]), int(f[2]), float.fromhex(f[3]), int(f[4])
        v = [float.fromhex(x) for x in f[5:]]
        P = np.array([[float.fromhex(x) for x in line.split()] for line in out[k + 1:k + 1 + n]])
        k += 1 + n
        status.add_bool(st == 0)
        if st != 0:
            continue
        R = v[3]
        oc, orad, on = np.array(v[7:10]), v[10], np.array(v[11:14])
        o = P.mean(axis=0)  # the geometric fits about the centroid, as the points are far out
        Q = P - o
        if kind == 0:
            def f0(p):
                return np.linalg.norm(Q - p[:3], axis=1) - p[3]
            g = least_squares(f0, np.r_[oc - o, orad], xtol=1e-15, ftol=1e-15, gtol=1e-15).x
            bias[0].append((orad - g[3]) * R / sigma ** 2)
            cen[0].add_tol(np.linalg.norm(oc - o - g[:3]) / sigma, 0.05)
        elif kind == 1:
            def f1(p):
                c, th, ph, r = p[:3], p[3], p[4], p[5]
                nn = np.array([np.sin(th) * np.cos(ph), np.sin(th) * np.sin(ph), np.cos(th)])
                D = Q - c
                h = D @ nn
                return np.sqrt(h ** 2 + (np.linalg.norm(D - np.outer(h, nn), axis=1) - r) ** 2)
            th, ph = np.arccos(np.clip(on[2], -1, 1)), np.arctan2(on[1], on[0])
            g = least_squares(f1, np.r_[oc - o, th, ph, orad], xtol=1e-15, ftol=1e-15, gtol=1e-15).x
            bias[1].append((orad - g[5]) * R / sigma ** 2)
            cen[1].add_tol(np.linalg.norm(oc - o - g[:3]) / sigma, 0.05)
        elif kind == 2:
            def f2(p):
                th, ph, d = p
                nn = np.array([np.sin(th) * np.cos(ph), np.sin(th) * np.sin(ph), np.cos(th)])
                return Q @ nn - d
            th, ph = np.arccos(np.clip(on[2], -1, 1)), np.arctan2(on[1], on[0])
            g = least_squares(f2, [th, ph, 0.0], xtol=1e-15, ftol=1e-15, gtol=1e-15).x
            gn = np.array([np.sin(g[0]) * np.cos(g[1]), np.sin(g[0]) * np.sin(g[1]), np.cos(g[0])])
            dist = orad - on @ o  # the fitted plane's distance from the centroid
            flat[2].add_tol(max(min(np.linalg.norm(gn - on), np.linalg.norm(gn + on)), abs(abs(dist) - abs(g[2]))),
                            1e-9)
        else:
            def f3(p):
                th, ph, a, b = p
                u = np.array([np.sin(th) * np.cos(ph), np.sin(th) * np.sin(ph), np.cos(th)])
                e1 = np.cross(u, [1.0, 0, 0] if abs(u[0]) < 0.6 else [0, 1.0, 0])
                e1 /= np.linalg.norm(e1)
                q = a * e1 + b * np.cross(u, e1)
                D = Q - q
                return np.linalg.norm(D - np.outer(D @ u, u), axis=1)
            th, ph = np.arccos(np.clip(on[2], -1, 1)), np.arctan2(on[1], on[0])
            g = least_squares(f3, [th, ph, 0.0, 0.0], xtol=1e-15, ftol=1e-15, gtol=1e-15).x
            gu = np.array([np.sin(g[0]) * np.cos(g[1]), np.sin(g[0]) * np.sin(g[1]), np.cos(g[0])])
            # the fitted line's distance from the centroid: 0 for both
            D = o - oc
            off = np.linalg.norm(D - (D @ on) * on)
            flat[3].add_tol(max(min(np.linalg.norm(gu - on), np.linalg.norm(gu + on)), off / 1e3), 1e-9)
    status.end()
    for kind, want, name in ((0, 1.5, "sphere"), (1, 2.0, "circle")):
        m = float(np.mean(bias[kind]))
        c = Check("%s: mean (r_linear - r_geometric) r / sigma^2 - %g" % (name, want))
        c.add_tol(abs(m - want), 0.06)
        c.end()
        print("     (%s: %.3f +- %.3f over %d fits of 1000 points, sigma 0.05 r)"
              % (name, m, float(np.std(bias[kind]) / np.sqrt(len(bias[kind]))), len(bias[kind])))
        cen[kind].end()
    flat[2].end()
    flat[3].end()


def main():
    if len(sys.argv) != 2:
        print("usage: algebra_check.py ALGEBRA_DUMP", file=sys.stderr)
        return 2
    dump = sys.argv[1]
    check_inverse(dump)
    check_products(dump)
    check_projection(dump)
    check_powers(dump)
    check_fits(dump)
    print("algebra_check: %s" % ("all passed" if FAILS == 0 else "%d check(s) FAILED" % FAILS))
    return 1 if FAILS else 0


if __name__ == "__main__":
    sys.exit(main())
