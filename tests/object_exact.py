#!/usr/bin/env python3
"""tests/object_exact.py: the read-back of conformal objects against exact
arithmetic.

Runs tests/object_dump (path in argv[1]), which prints objects of every kind
at distances 1 to 1e8 from the origin with what ga_object_from_mv reads of
them, and reads each multivector again here in exact rational arithmetic
(fractions.Fraction, square roots in 60-digit decimals), with a G(4,1)
product written here from the blade rule (e1..e4 square to +1, e5 to -1).
Checks, for every GA_OK answer (object.h, "Accuracy"):
  - the kind is the exact kind of the multivector as given;
  - |centre - exact| <= err, |r2 - exact| <= r2_err, and the direction
    within angle_err of the exact one (up to sign);
and that every GA_ERR_PRECISION of a dual sphere or plane is where its exact
weight is within four times its uncertainty of 0 (the read-back's rule), and
that nothing at D = 1 is refused. Standard library only.
"""
import sys
import subprocess
from fractions import Fraction as Q
from decimal import Decimal, getcontext

getcontext().prec = 60
U = Q(1, 2**53)

# blades in the canonical order, as bit masks (conventions.md)
MASKS = [0x00, 0x01, 0x02, 0x04, 0x08, 0x10, 0x03, 0x05, 0x09, 0x11, 0x06,
         0x0a, 0x12, 0x0c, 0x14, 0x18, 0x07, 0x0b, 0x13, 0x0d, 0x15, 0x19,
         0x0e, 0x16, 0x1a, 0x1c, 0x0f, 0x17, 0x1b, 0x1d, 0x1e, 0x1f]
INDEX = {m: i for i, m in enumerate(MASKS)}
E = {name: INDEX[sum(1 << (int(ch) - 1) for ch in name[1:])] for name in
     ["e1", "e2", "e3", "e4", "e5", "e14", "e24", "e34", "e45", "e145", "e245", "e345",
      "e124", "e125", "e134", "e135", "e234", "e235"]}


def grade(i):
    return bin(MASKS[i]).count("1")


def sign(a, b):
    s = 0
    x = a >> 1
    while x:
        s += bin(x & b).count("1")
        x >>= 1
    if a & b & 0x10:
        s += 1
    return -1 if s & 1 else 1


def gp(a, b):
    r = [Q(0)] * 32
    for i, x in enumerate(a):
        if x:
            for j, y in enumerate(b):
                if y:
                    r[INDEX[MASKS[i] ^ MASKS[j]]] += sign(MASKS[i], MASKS[j]) * x * y
    return r


def op(a, b):
    r = [Q(0)] * 32
    for i, x in enumerate(a):
        if x:
            for j, y in enumerate(b):
                if y and not (MASKS[i] & MASKS[j]):
                    r[INDEX[MASKS[i] | MASKS[j]]] += sign(MASKS[i], MASKS[j]) * x * y
    return r


def part(x, k):
    return [c if grade(i) == k else Q(0) for i, c in enumerate(x)]


def reverse(x):
    return [c * (-1 if grade(i) % 4 in (2, 3) else 1) for i, c in enumerate(x)]


I5 = [Q(0)] * 32
I5[31] = Q(1)
N = [Q(0)] * 32
N[E["e4"]] = N[E["e5"]] = Q(1)


def dec(q):
    """a Fraction (or a Decimal) as a 60-digit Decimal"""
    return q if isinstance(q, Decimal) else Decimal(q.numerator) / Decimal(q.denominator)


def sqrt(q):
    return dec(q).sqrt()


def dnorm(v):  # |v| of a 3-vector, as a Decimal
    return sqrt(sum(dec(c) * dec(c) for c in v))


def dist(a, b):
    return sqrt(sum((dec(x) - dec(y)) ** 2 for x, y in zip(a, b)))


# a flat whose weight is exactly 0 is at infinity (ga/object.c, at_infinity)
TOL = 0


def read_dual(v):
    """kind, centre, r2, direction of a dual vector, exactly"""
    m = [v[1], v[2], v[3]]
    w = v[5] - v[4]
    if w == 0:
        ln = dnorm(m)
        if ln <= dec(TOL * max(abs(c) for c in v)):
            return ("empty", None, None, None)
        d = dec(v[4] + v[5]) / 2 / ln
        u = [dec(c) / ln for c in m]
        return ("plane", [d * x for x in u], Decimal(0), u)
    c = [x / w for x in m]
    return ("sphere", [dec(x) for x in c], dec(sum(x * x for x in c) - (v[4] + v[5]) / w), None)


def read(X):
    k = max(range(6), key=lambda g: max(abs(c) for i, c in enumerate(X) if grade(i) == g))
    X = part(X, k)
    if k in (1, 4):
        v = X if k == 1 else part(gp(X, I5), 1)
        return read_dual(v)
    F = op(X, N)
    s = max(abs(c) for c in X)
    if all(c == 0 for c in F):
        if k == 3:
            u = [X[E["e145"]], X[E["e245"]], X[E["e345"]]]
            w = dnorm(u)
            if w <= dec(TOL * s):
                return ("empty", None, None, None)
            uu = [dec(c) / w for c in u]
            b = [dec(X[E[p + "4"]] + X[E[p + "5"]]) / 2 / w for p in ("e23", "e13", "e12")]
            mom = [b[0], -b[1], b[2]]
            p = [uu[1] * mom[2] - uu[2] * mom[1], uu[2] * mom[0] - uu[0] * mom[2], uu[0] * mom[1] - uu[1] * mom[0]]
            return ("line", p, Decimal(0), uu)
        w = -X[E["e45"]]
        if abs(w) <= TOL * s:
            return ("empty", None, None, None)
        return ("flatpoint", [dec(X[E[p]] / w) for p in ("e14", "e24", "e34")], Decimal(0), None)
    f = gp(F, reverse(F))[0]
    sigma = [c / f for c in part(gp(X, reverse(F)), 1)]
    kind, c, r2, _ = read_dual(sigma)
    if kind != "sphere":
        return ("?", None, None, None)
    if k == 2:
        u = [F[E["e145"]], F[E["e245"]], F[E["e345"]]]
        w = dnorm(u)
        return ("pointpair", c, r2, [dec(x) / w for x in u])
    _, _, _, m = read_dual(part(gp(F, I5), 1))
    return ("circle", c, r2, m)


KINDS = ["empty", "flatpoint", "line", "plane", "pointpair", "circle", "sphere"]


def main():
    out = subprocess.run([sys.argv[1]], capture_output=True, text=True, check=True).stdout
    n_ok = n_refused = 0
    worst = {}
    refused = {}
    bad = []
    for line in out.splitlines():
        f = line.split()
        name, D = f[0], float(f[1])
        X = [Q(float.fromhex(x)) for x in f[2:34]]
        st, kind, reality = int(f[34]), int(f[35]), int(f[36])
        centre = [Q(float.fromhex(x)) for x in f[37:40]]
        direction = [Q(float.fromhex(x)) for x in f[40:43]]
        r2, err, r2_err, angle_err = (Q(float.fromhex(x)) for x in f[43:47])
        if st != 0:
            n_refused += 1
            refused.setdefault(name, {})[D] = refused.get(name, {}).get(D, 0) + 1
            if D == 1.0:
                bad.append(f"{name} at D = 1 refused ({st})")
            if st == -9 and name == "sphere-dual":
                v = X
                w = v[5] - v[4]
                dw = 2 * U * max(abs(v[4]), abs(v[5])) + U * abs(w)
                if abs(w) > 4 * dw:
                    bad.append(f"{name} at D = {D:g}: refused, but its weight {float(w):.3g} is known to {float(dw):.3g}")
            continue
        n_ok += 1
        ek, ec, er2, edir = read(X)
        if KINDS[kind] != ek:
            bad.append(f"{name} at D = {D:g}: read {KINDS[kind]}, exactly {ek}")
            continue
        key = (name, D)
        ratio = Decimal(0)
        if ec is not None:
            dc = dist(centre, ec)
            if dc > dec(err) * (1 + Decimal("1e-12")):
                bad.append(f"{name} at D = {D:g}: centre off by {float(dc):.3g}, bound {float(err):.3g}")
            ratio = max(ratio, dc / dec(err) if err else (Decimal(0) if dc == 0 else Decimal("inf")))
        if ek in ("sphere", "circle", "pointpair"):
            d2 = abs(dec(r2) - er2)
            if d2 > dec(r2_err) * (1 + Decimal("1e-12")):
                bad.append(f"{name} at D = {D:g}: r2 off by {float(d2):.3g}, bound {float(r2_err):.3g}")
            ratio = max(ratio, d2 / dec(r2_err) if r2_err else (Decimal(0) if d2 == 0 else Decimal("inf")))
        if edir is not None:
            dd = min(dist(direction, edir), dist(direction, [-x for x in edir]))
            if dd > dec(angle_err) * (1 + Decimal("1e-9")):
                bad.append(f"{name} at D = {D:g}: direction off by {float(dd):.3g}, bound {float(angle_err):.3g}")
        worst[key] = max(worst.get(key, Decimal(0)), ratio)
    print(f"{n_ok} read back with GA_OK, checked against exact arithmetic; {n_refused} refused:")
    for nm in sorted(refused):
        print(f"  {nm:18s} refused: " + "  ".join(f"D={d:g} {refused[nm].get(d, 0)}" for d in (1, 1e2, 1e4, 1e6, 1e8)))
    names = sorted({k[0] for k in worst})
    for nm in names:
        print(f"  {nm:18s} worst error / its bound: " +
              "  ".join(f"D={d:g} {float(worst[(nm, d)]):.3f}" for d in (1, 1e2, 1e4, 1e6, 1e8) if (nm, d) in worst))
    for b in bad[:20]:
        print("FAIL", b)
    if bad:
        print(f"{len(bad)} failures")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
