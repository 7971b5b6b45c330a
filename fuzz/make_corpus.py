#!/usr/bin/env python3
"""fuzz/make_corpus.py: write the seed corpus fuzz/corpus/{numeric,path,tool}/.

    python3 fuzz/make_corpus.py        (from the repository root)

    python3 fuzz/make_corpus.py --check  (the committed corpus is what it writes)

The seeds are committed; this script says what each one is, and rewrites them
all, byte for byte. A file in fuzz/corpus/ that it does not write (a seed
added by hand, or the old name of a renamed one) is kept and listed, never
deleted: add such a seed here, or `git rm` it; --check fails on it (the test
fuzz-corpus runs --check). Each seed is one meaningful call: every numeric operation on ordinary,
edge and invalid values, every scheme on every group for the path target, and
every input format and option of the tool (docs/tool.md). The fuzzers start
from these instead of from nothing.

The numeric and path targets read bytes as doubles through fuzz_reader.h: a
tag byte, then (tag 0) eight raw bytes. enc() below writes the one-byte tag
for the values that have one and the raw form for the rest.
"""
import math
import os
import struct
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
NAN, INF = float("nan"), float("inf")
PI = 3.141592653589793


def enc(x):
    """One double as fuzz_reader.h reads it."""
    if isinstance(x, str):  # named tags
        return {"sub": bytes([9, 0]), "-sub": bytes([9 | 16, 0]), "pi-": bytes([11 | 32]),
                "max": bytes([14]), "-max": bytes([14 | 16])}[x]
    if math.isnan(x):
        return bytes([5])
    if x == INF:
        return bytes([6])
    if x == -INF:
        return bytes([7])
    if x == 0.0:
        return bytes([2 if math.copysign(1, x) < 0 else 1])
    if x == 1.0:
        return bytes([3])
    if x == -1.0:
        return bytes([4])
    if abs(x) == 1e308:
        return bytes([8 | (16 if x < 0 else 0)])
    if abs(x) == PI:
        return bytes([11 | (16 if x < 0 else 0)])
    return bytes([0]) + struct.pack("<d", x)


def doubles(xs):
    return b"".join(enc(x) for x in xs)


SEEDS = {}  # (target, name) -> bytes, written (or checked) at the end


def write(target, name, data):
    assert (target, name) not in SEEDS, "two seeds named %s/%s" % (target, name)
    SEEDS[target, name] = data if isinstance(data, bytes) else data.encode()

# ---- numeric: fuzz_numeric.c, first byte the operation -----------------------
OPS = {"exp-log": 0, "rotor": 1, "rotor-drift": 2, "mat": 3, "mat-near": 4, "se3": 5,
       "expm-logm": 6, "bridge": 7, "screw": 8, "mv": 9, "points": 10}
TWISTS = {  # generators (e12 e13 e23 e1n e2n e3n) / twists
    "zero": [0, 0, 0, 0, 0, 0],
    "general": [0.3, -0.2, 0.9, 1, 2, 3],
    "half-turn": [PI, 0, 0, 0, 0, 1],
    "near-half-turn": ["pi-", 0, 0, 0, 1, 0],
    "tiny-rotation-big-translation": [1e-9, 0, 0, 1000, 0, 0],
    "pure-translation": [0, 0, 0, 1e6, -2e6, 3],
    "edge-1e6": [1e6, 0, 0, 0, 0, 1e6],
    "subnormal": ["sub", 0, 0, "-sub", 0, 0],
    "huge": [1e308, 0, 0, 0, 0, -1e308],
    "dbl-max": ["max", 0, 0, 0, 0, 0],
    "nan": [NAN, 0, 0, 0, 0, 0],
    "inf": [0, 0, 0, INF, 0, 0],
    "neg-zero": [-0.0, -0.0, -0.0, -0.0, -0.0, -0.0],
}
for k, x in TWISTS.items():
    write("numeric", "exp-log-" + k, bytes([OPS["exp-log"]]) + doubles(x))
    write("numeric", "screw-" + k, bytes([OPS["screw"]]) + doubles(
        [abs(x[0]) if not isinstance(x[0], str) else x[0], 0, 0, 1, 0, 0, 0] + x[3:5]))
    write("numeric", "se3-" + k, bytes([OPS["se3"]]) + doubles(x + [0.1, 0, 0, 0, 1, 0, 0.5]))
for k, r in {"identity": [1, 0, 0, 0, 0, 0, 0, 0], "minus-identity": [-1, 0, 0, 0, 0, 0, 0, 0],
             "zero": [0] * 8, "drifted": [1 + 1e-10, 0, 0, 0, 0, 0, 0, 0],
             "far-off": [2, 0, 0, 0, 0, 0, 0, 0], "nan": [NAN] + [0] * 7,
             "huge": [1e308, 1e308, 0, 0, 0, 0, 0, 0], "subnormal": ["sub"] * 8}.items():
    write("numeric", "rotor-" + k, bytes([OPS["rotor"]]) + doubles(r))
for k, dd in {"tiny": [1e-13] * 8, "1e-6": [1e-6] + [0] * 7, "inf": [INF] + [0] * 7}.items():
    write("numeric", "rotor-drift-" + k, bytes([OPS["rotor-drift"]]) +
          doubles(TWISTS["general"] + dd))
I4 = [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]
ROT = [0, -1, 0, 1, 1, 0, 0, 0, 0, 0, 1, 2, 0, 0, 0, 1]
HALF = [1, 0, 0, 0, 0, -1, 0, 0, 0, 0, -1, 0, 0, 0, 0, 1]
for k, m in {"identity": I4, "rotation": ROT, "half-turn": HALF, "zero": [0] * 16,
             "reflection": [-1] + I4[1:], "bad-last-row": I4[:12] + [1, 0, 0, 1],
             "scaled": [2 * v for v in I4[:15]] + [1], "nan": I4[:5] + [NAN] + I4[6:],
             "huge-translation": I4[:3] + [1e308] + I4[4:]}.items():
    write("numeric", "mat-" + k, bytes([OPS["mat"]]) + doubles(m))
    write("numeric", "expm-logm-" + k, bytes([OPS["expm-logm"]]) + doubles(m))
for k, dd in {"1e-10": [1e-10] * 16, "1e-8": [0, 1e-8] + [0] * 14, "nan": [NAN] + [0] * 15}.items():
    write("numeric", "mat-near-" + k, bytes([OPS["mat-near"]]) + doubles(TWISTS["general"] + dd))
for k, b in {"identity": [1, 0, 0, 0, 0, 0, 0], "general": [0.5, 0.5, -0.5, 0.5, 1, -2, 3],
             "subnormal": ["sub", 0, 0, 1, 0, 0, 0], "nan": [NAN, 0, 0, 1, 0, 0, 0],
             "big-translation": [0, 0, 0, 1, 1e6, 0, 0]}.items():
    write("numeric", "bridge-" + k, bytes([OPS["bridge"]]) + doubles(b + [1, 0, 0, 0, 0, 0, 0, 0]))
for k, c in {"point": [0, 1, 2, 3, -0.5, 0.5] + [0] * 26, "zero": [0] * 32,
             "nan": [NAN] + [0] * 31, "huge": [1e308] * 32}.items():
    write("numeric", "mv-" + k, bytes([OPS["mv"]]) + doubles(c + [1]))
# exp and log of the general algebra (on the bivector part, and log of X):
# a rotor's coefficients, then bivectors of each kind (indices 6..15 = e12..e45)
for k, b in {"rotation": [1.2, 0, 0, 0, 0, 0, 0, 0, 0, 0], "dilation": [0] * 9 + [0.7],
             "translation": [0, 0, 0.5, 0.5, 0, 0, 0, 0, 0, 0],
             "rotation-transversion": [0, 0, 0.25, -0.25, 0.5, 0, 0, 0, 0, 0],
             "two-rotations": [1.4, 0, 0, 0, 0, 0, 0, 1.3, 0, 0],
             "near-half-turn": ["pi-", 0, 0, 0, 0, 0, 0, 0, 0, 0],
             "dense": [0.2, -0.3, 0.4, 0.1, 0.25, -0.6, 0.35, 0.15, -0.2, 0.45],
             "big": [8, 0, 0, 0, 0, 0, 0, 0, 0, -8]}.items():
    write("numeric", "mv-exp-log-" + k, bytes([OPS["mv"]]) + doubles([0] * 6 + b + [0] * 16 + [1]))
write("numeric", "mv-log-rotor", bytes([OPS["mv"]]) + doubles([0.6] + [0] * 5 + [0.8] + [0] * 25 + [1]))
# text after the doubles: ga_mv_parse (docs/conventions.md, "Multivectors as text")
for k, t in {"text": "1 + 2e12 - 0.5e1234", "text-python-repr": "3 + e12 - 0.5*e12345",
             "text-exponents": "-1e+20e12345 + 2.5E-3 - .5e1 + 1e-5", "text-bad-name": "2e21",
             "text-overflow": "1e+999e1"}.items():
    write("numeric", "mv-" + k, bytes([OPS["mv"]]) + doubles([0.5] * 32 + [1]) + t.encode())
PTS = [0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1]
for which in range(8):
    write("numeric", "points-object-%d" % which, bytes([OPS["points"]]) +
          doubles(PTS + [1, 2]) + bytes([which]))
write("numeric", "points-far", bytes([OPS["points"]]) + doubles([1e5, 0, 0] + PTS[3:] + [1e-7, 1e308]) + bytes([7]))
write("numeric", "points-nan", bytes([OPS["points"]]) + doubles([NAN] + PTS[1:] + [1, 1]) + bytes([5]))

# ---- path: fuzz_path.c ---------------------------------------------------------
GROUPS = ["cga", "matrix", "affine"]
SCHEMES = ["screw", "bivector", "quadratic", "smooth", "lihao2", "lihao3", "decoupled", "decoupled-c2", "bspline", "c2"]
EVALS = ["direct", "euler", "exact"]


def path_seed(group, scheme, ev, n, flags, times, keys, vel=None, extra=b""):
    g, s, e = GROUPS.index(group), SCHEMES.index(scheme), EVALS.index(ev)
    # fuzz_path.c: b0 / 3 below 80 is one of the first 8 schemes, from 80 the later ones
    head = bytes([g + 3 * (s if s < 8 else 80 + s - 8), e + 3 * (n - 2), flags])
    body = doubles(times) + b"".join(doubles(k) for k in keys)
    if vel is not None:
        body += doubles(vel)
    # three evaluation times inside, one segment formula at u = 0.5,
    # 9 uniform samples with an Euler step of 0.25, 3 samples at given times
    tail = (doubles([0.25]) + bytes([1]) + doubles([0.5]) + bytes([1]) + doubles([0.75]) + bytes([1])
            + bytes([0]) + doubles([0.5]) + bytes([7]) + doubles([0.25])
            + bytes([2]) + doubles([0.1]) + bytes([0]) + doubles([0.5]) + bytes([0])
            + doubles([0.9]) + bytes([0]))
    return head + body + tail + extra


def twist_keys(n):
    return [[0.1 * i, -0.2 * i, 0.3 * i, 1.0 * i, 0.5 * i * i, -i] for i in range(n)]


def affine_keys(n):
    return [[0.05 * i, 0.01, 0, 0.2 * i, 0, -0.04 * i, 0.02, 0.1, 0.01 * i, 0, 0.03, -0.1 * i]
            for i in range(n)]


for group in GROUPS:
    dim = 12 if group == "affine" else 6
    for scheme in SCHEMES:
        n = 3 if scheme in ("quadratic", "smooth") else 4 if scheme == "lihao3" else 2
        if scheme in ("smooth", "decoupled-c2", "c2"):
            n = 5
        if scheme == "bspline":
            n = 6
        keys = affine_keys(n) if group == "affine" else twist_keys(n)
        times = [0.0] + [1.0] * (n - 1)  # t0, then spacings
        vel = None
        flags = 0
        if scheme == "lihao2":
            vel, flags = [0.1] * dim, 4
        if scheme == "lihao3":
            vel, flags = [0.05 * (k % 7) for k in range(n * dim)], 4
        for ev in EVALS:
            write("path", "%s-%s-%s" % (group, scheme, ev),
                  path_seed(group, scheme, ev, n, flags, times, keys, vel))
    # keys given as matrices, one perturbed off the group; raw times
    n = 3
    keys = affine_keys(n) if group == "affine" else twist_keys(n)
    write("path", group + "-screw-mat-keys", path_seed(group, "screw", "direct", n, 2 | 1,
                                                       [0, 0.5, 2], keys))
    pert = b"".join(doubles(k) + bytes([5]) + doubles([1e-6]) for k in keys)
    write("path", group + "-screw-perturbed-key",
          bytes([GROUPS.index(group), 3 * (n - 2), 2 | 8]) + doubles([0, 1, 1]) + pert)
    write("path", group + "-times-not-increasing",
          path_seed(group, "screw", "direct", n, 1, [0, 2, 1], keys))
    write("path", group + "-times-nan", path_seed(group, "screw", "direct", n, 1, [0, NAN, 1], keys))
    write("path", group + "-spacing-subnormal",
          path_seed(group, "lihao3", "direct", n, 0, [0, 1, "sub"], keys))
write("path", "cga-screw-half-turn", path_seed("cga", "screw", "exact", 2, 0, [0, 1],
                                               [[0] * 6, [PI, 0, 0, 0, 0, 1]]))
write("path", "cga-lihao2-too-few-keys", bytes([0 + 3 * 3, 0, 0]) + doubles([0, 1]))

# ---- tool: fuzz_tool.c, line 1 the command line, then the input file ------------
TW = "0 0 0 0 0 0\n0.3 -0.2 0.9 1 2 3\n1e-9 0 0 1000 0 0\n0 0 3.141592653589793 0 0 1\n"
M1 = "1 0 0 0  0 1 0 0  0 0 1 0  0 0 0 1"
M2 = "0 -1 0 1  1 0 0 0  0 0 1 2  0 0 0 1"
M3 = "1 0 0 3  0 -1 0 0  0 0 -1 1  0 0 0 1"
AFF = "1.1 0.2 0 1  0 0.9 0.1 2  0.05 0 1.2 3  0 0 0 1"
P1, P2, P3 = "0 0 0 0 0 0 1", "1 2 0 0 0 0.7071067811865476 0.7071067811865476", "2 0 1 0 1 0 0"
KEYS = "0 %s\n1 %s\n2.5 %s\n" % (M1, M2, M3)
POSES = "0 %s\n1 %s\n2.5 %s\n" % (P1, P2, P3)
VEL = "0.1 0 0 1 0 0\n0 0.2 0 0 1 0\n0 0 0 0 0 1\n"


def mv32(nz):
    """32 coefficients in canonical order, nz: index -> value."""
    return " ".join(repr(float(nz[i])) if i in nz else "0" for i in range(32))


# bivectors e12 e13 e14 e15 e23 e24 e25 e34 e35 e45: a rotation, a dilation,
# a translation (null), a rotation with a transversion, dense, zero
BIVS = [[0.7, 0, 0, 0, 0, 0, 0, 0, 0, 0], [0, 0, 0, 0, 0, 0, 0, 0, 0, -0.4],
        [0, 0, 0.5, 0.5, 0, 0, 0, 0, 0, 0], [0, 0, 0.25, -0.25, 0.5, 0, 0, 0, 0, 0],
        [0.2, -0.3, 0.4, 0.1, 0.25, -0.6, 0.35, 0.15, -0.2, 0.45], [0] * 10]
ROT = mv32({0: 0.6, 6: 0.8})                                   # cos + sin e12
DIL = mv32({0: 1.0810723718384549, 15: -0.41075232580281562})  # exp(-0.4 e45): x e^0.8
TOOL = {
    "exp-cga": "exp\n" + TW,
    "exp-matrix": "exp --group matrix\n" + TW,
    "exp-commas-comments": "exp\n# wx wy wz vx vy vz\n\n1.2,0.4,-0.7,0.5,-3,2\n",
    "exp-csv-header": "exp --header\nwx,wy,wz,vx,vy,vz\n0.1,0.2,0.3,1,2,3\n",
    "exp-affine": "exp --group affine\n0.1 0.2 0 1 0 -0.3 0.1 2 0.05 0 0.2 3 0 0 0 0\n",
    "exp-nan": "exp\n0 0 nan 0 0 0\n",
    "exp-inf": "exp\n0 0 0 inf 0 0\n",
    "exp-huge": "exp\n1e308 0 0 0 0 1e308\n",
    "exp-short-line": "exp\n1 2 3\n",
    "exp-garbage": "exp\n1 2 x 4 5 6\n",
    "log-cga": "log\n%s\n%s\n%s\n" % (M1, M2, M3),
    "log-matrix": "log --group matrix\n%s\n" % M2,
    "log-affine": "log --group affine\n%s\n" % AFF,
    "log-not-rigid": "log\n2 0 0 0  0 1 0 0  0 0 1 0  0 0 0 1\n",
    "log-bad-last-row": "log\n1 0 0 0  0 1 0 0  0 0 1 0  0 0 1 1\n",
    "log-drifted": "log\n1.0000000001 0 0 0  0 1 0 0  0 0 1 0  0 0 0 1\n",
    "log-csv-header": "log --header\nm00,m01,m02,m03,m10,m11,m12,m13,m20,m21,m22,m23,m30,m31,m32,m33\n"
                      + M2.replace("  ", " ").replace(" ", ",") + "\n",
    "interp-screw-mat": "interp --scheme screw --samples 5\n" + KEYS,
    "interp-screw-pose": "interp --scheme screw --format pose --samples 5\n" + POSES,
    "interp-bivector": "interp --scheme bivector --samples 4 --group matrix\n" + KEYS,
    "interp-quadratic": "interp --scheme quadratic --at 0.5,1,2\n" + KEYS,
    "interp-smooth": "interp --scheme smooth --samples 6 --format pose\n" + POSES,
    "interp-lihao2-v0": "interp --scheme lihao2 --samples 5 --v0 0 0 0.1 1 0 0\n" + KEYS,
    "interp-lihao3-velocities": "interp --scheme lihao3 --samples 5 --velocities v\n" + KEYS + "%%\n" + VEL,
    "interp-lihao3-default": "interp --scheme lihao3 --samples 7 --group matrix\n" + KEYS,
    "interp-decoupled": "interp --scheme decoupled --samples 5 --format pose\n" + POSES,
    "interp-decoupled-c2": "interp --scheme decoupled-c2 --samples 7 --group matrix\n" + KEYS,
    "interp-c2": "interp --scheme c2 --samples 7 --with velocity,acceleration\n" + KEYS,
    "interp-decoupled-affine": "interp --scheme decoupled --group affine --samples 3\n0 %s\n1 %s\n" % (M1, AFF),
    "interp-bspline-epoch": "interp --scheme bspline --format pose --rate 250 --with velocity,acceleration"
    " --extrapolate hold\n" + "".join("1305031102.%02d %s\n" % (17 + i, p) for i, p in enumerate(
        [P1, P2, P3, "2 1 1 0 0.6 0 0.8", "3 1 0 0.6 0 0 0.8"])),
    "interp-bspline-ns-exact": "interp --scheme bspline --eval exact --time-unit ns --samples 7 --extrapolate extend\n"
    + "".join("%d %s\n" % (1305031102170000000 + 10000000 * i, m) for i, m in enumerate([M1, M2, M3, M1])),
    "interp-euler": "interp --scheme lihao3 --samples 5 --eval euler --step 0.1\n" + KEYS,
    "interp-exact": "interp --scheme lihao2 --samples 9 --eval exact\n" + KEYS,
    "interp-affine": "interp --scheme screw --group affine --samples 4\n0 %s\n1 %s\n" % (M1, AFF),
    "interp-csv-header": "interp --scheme screw --samples 3 --format pose --header\nt,x,y,z,qx,qy,qz,qw\n"
                         + POSES.replace(" ", ","),
    "interp-svg": "interp --scheme screw --samples 5 --svg p.svg --view xy\n" + KEYS,
    "interp-times-decreasing": "interp --scheme screw --samples 3\n1 %s\n0 %s\n" % (M1, M2),
    "interp-quaternion-not-unit": "interp --scheme screw --format pose --samples 3\n0 0 0 0 0 0 0 2\n1 %s\n" % P2,
    "interp-too-few-keys": "interp --scheme smooth --samples 3\n0 %s\n1 %s\n" % (M1, M2),
    "interp-at-outside": "interp --scheme screw --at 5\n" + KEYS,
    "interp-velocities-short": "interp --scheme lihao3 --samples 3 --velocities v\n" + KEYS + "%%\n0 0 0 1 0 0\n",
    "interp-bad-option": "interp --scheme spline --samples 3\n" + KEYS,
    # exact times (docs/tool.md, "Times"): epoch stamps, integer nanoseconds
    "interp-epoch-rate": "interp --format pose --rate 100\n"
                         "1305031102.1758 %s\n1305031102.2758 %s\n1305031102.30 %s\n" % (P1, P2, P3),
    "interp-epoch-at": "interp --format pose --at 1305031102.2758,1305031102.2,0x1.37p30 --extrapolate hold\n"
                       "1305031102.1758 %s\n1305031102.2758 %s\n1305031102.30 %s\n" % (P1, P2, P3),
    "interp-ns-rate": "interp --format pose --time-unit ns --rate 30\n"
                      "1305031102175800000 %s\n1305031102275800000 %s\n1305031102300000000 %s\n" % (P1, P2, P3),
    "interp-ns-samples": "interp --time-unit ns --samples 4 --eval exact\n"
                         "1.3e18 %s\n1300000000000000100 %s\n" % (M1, M2),
    "interp-ns-not-whole": "interp --format pose --time-unit ns --samples 3\n0.5 %s\n1 %s\n" % (P1, P2),
    "interp-time-unit-bad": "interp --format pose --time-unit ms --samples 3\n" + POSES,
    # --columns on quoted CSV fields (RFC 4180), and its three quoting errors
    "interp-columns-quoted": "interp --columns header --samples 3\n"
                             '"t","frame","x","y","z","qx","qy","qz","qw"\n'
                             '0,"map, ""a""",0,0,0,0,0,0,1\n1,"odom" ,"1",0,0,0,0,0,1\n',
    "interp-columns-quote-open": "interp --columns header --samples 3\nt,x,y,z,qx,qy,qz,qw\n0,\"0,0,0,0,0,0,1\n",
    "interp-columns-quote-after": "interp --columns t,x,y,z,qx,qy,qz,qw --samples 3\n0,\"0\"x,0,0,0,0,0,1\n",
    "interp-columns-quote-inside": "interp --columns t,x,y,z,qx,qy,qz,qw --samples 3\n0,0\"0,0,0,0,0,0,1\n",
    "interp-long-decimal": "interp --format pose --samples 3\n1e-700 %s\n0.%s1 %s\n1e300 %s\n"
                           % (P1, "0" * 500, P2, P3),
    # versor (docs/tool.md, "garotor versor"): 10 numbers, 32, 32 + 3
    "versor-exp": "versor exp\n" + "\n".join(" ".join(map(str, b)) for b in BIVS) + "\n",
    "versor-exp-overflow": "versor exp\n0 0 0 0 0 0 0 0 0 800\n",
    "versor-exp-short": "versor exp\n0 0 0 0 0 0 0 0 0\n",
    "versor-log": "versor log\n%s\n%s\n%s\n" % (mv32({0: 1}), ROT, DIL),
    "versor-log-csv-header": "versor log --header\n" + ",".join("c%d" % i for i in range(32)) + "\n"
                             + ROT.replace(" ", ",") + "\n",
    "versor-log-not-rotor": "versor log\n%s\n" % mv32({0: 2}),
    "versor-log-odd": "versor log\n%s\n" % mv32({1: 1}),
    "versor-log-drifted": "versor log\n%s\n" % mv32({0: 0.6, 6: 0.80000002}),
    "versor-apply": "versor apply\n%s 1 2 3\n%s 2 0 0\n%s -1 0.5 4\n" % (DIL, mv32({4: 1}), ROT),
    "versor-apply-to-infinity": "versor apply\n%s 0 0 0\n" % mv32({4: 1}),
    "versor-apply-mixed": "versor apply\n%s 1 2 3\n" % mv32({0: 1, 1: 1}),
    "versor-apply-zero": "versor apply\n%s 1 2 3\n" % mv32({}),
    "versor-apply-nan": "versor apply\n%s 1 nan 3\n" % mv32({0: 1}),
    "versor-unknown": "versor sqrt\n%s\n" % mv32({0: 1}),
    # the reader (docs/tool.md, "Text, and how long a line"): NUL bytes, lines
    # about a small --max-line, in every file a command reads
    "exp-nul-byte": "exp\n0 0 1 0 0 1\0junk\n",
    "exp-nul-only": "exp\n\0\0\0\0",
    "exp-nul-comment": "exp --header\nwx,wy\0\n# a\0b\n" + TW,
    "exp-max-line": "exp --max-line 11\n0 0 0 0 0 0\n0 0 0 0 0 0.5\n",
    "log-max-line": "log --max-line 40\n%s\n%s\n" % (M1, M2),
    "interp-max-line-pose": "interp --format pose --samples 3 --max-line 52\n" + POSES,
    "interp-max-line-velocities": "interp --scheme lihao3 --samples 3 --velocities v --max-line 15\n" + KEYS
                                  + "%%\n0 0 0 0 0 0\n0.1 0 0 0 0 1e-3\n0 0 0 0 0 0\n",
    "interp-nul-velocities": "interp --scheme lihao3 --samples 3 --velocities v\n" + KEYS + "%%\n" + VEL[:20]
                             + "\0" + VEL[20:],
    "versor-max-line": "versor apply --max-line=100\n%s 1 2 3\n" % ROT,
    # the layouts fuzz_tool.c checks (its commit 28e09c4 added these by hand):
    # KITTI's 3 x 4 rows, --output-format csv after its header with --with
    # jerk's widths, and versor --text (blade names, not numbers)
    "interp-kitti": "interp --format kitti --samples 5\n1 0 0 0 0 1 0 0 0 0 1 0\n1 0 0 1 0 1 0 0 0 0 1 0\n",
    "interp-output-csv-jerk-world": "interp --format pose --output-format csv --with velocity,acceleration,jerk "
                                    "--frame world\n0 0 0 0 0 0 0 1\n1 1 0 0 0 0 0 1\n",
    "versor-exp-text": "versor exp --text\n1e12 + 0.5e45\n",
}
for name, text in TOOL.items():
    write("tool", name, text)


def on_disk():
    """(target, name) of every file now in fuzz/corpus/{numeric,path,tool}"""
    found = set()
    for target in ("numeric", "path", "tool"):
        d = os.path.join(HERE, "corpus", target)
        if os.path.isdir(d):
            found |= {(target, name) for name in os.listdir(d)}
    return found


def path_of(key):
    return os.path.join(HERE, "corpus", key[0], key[1])


others = sorted(on_disk() - set(SEEDS))
if sys.argv[1:] == ["--check"]:
    bad = []
    for key, data in sorted(SEEDS.items()):
        if not os.path.exists(path_of(key)):
            bad.append("missing: %s/%s" % key)
        else:
            with open(path_of(key), "rb") as f:
                if f.read() != data:
                    bad.append("differs from what this script writes: %s/%s" % key)
    bad += ["not written by this script (add it here, or git rm it): %s/%s" % key for key in others]
    for line in bad:
        print("fuzz/make_corpus.py --check: " + line)
    print("fuzz/make_corpus.py --check: %d seeds, %s" % (len(SEEDS), "%d problems" % len(bad) if bad else "all equal"))
    sys.exit(1 if bad else 0)
elif sys.argv[1:]:
    sys.exit("usage: python3 fuzz/make_corpus.py [--check]")
for key, data in SEEDS.items():
    os.makedirs(os.path.dirname(path_of(key)), exist_ok=True)
    with open(path_of(key), "wb") as f:
        f.write(data)
print("fuzz/make_corpus.py: wrote %d seeds" % len(SEEDS))
for key in others:
    print("fuzz/make_corpus.py: kept %s/%s, which this script does not write (add it here, or git rm it)" % key)
