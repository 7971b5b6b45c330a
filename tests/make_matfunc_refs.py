#!/usr/bin/python3
"""tests/make_matfunc_refs.py: writes tests/matfunc_refs.h, the peer matrices
of ga_mat4_expm and ga_mat4_logm with high-precision references, which
tests/test_matfunc.c checks in the default suite.

Run by hand (not by the test suite, which needs no python), with Debian's
python3-mpmath and python3-scipy:
    /usr/bin/python3 tests/make_matfunc_refs.py > tests/matfunc_refs.h
    tools/format.sh   # the committed table is in clang-format's layout

The matrices (src, the first field of each row):
  "scipy"  every real input of size <= 4 that scipy's own tests pass to expm
           and logm (scipy/linalg/tests/test_matfuncs.py and
           scipy/sparse/linalg/tests/test_matfuncs.py of the installed
           scipy), recorded by running the test functions with expm and logm
           replaced by recorders; TestExpmConditionNumber is left out (its
           thousands of random perturbations are not test matrices);
  "eigen"  Eigen's deterministic real test matrices of size <= 4
           (unsupported/test/MatrixFunctions: expm of 2-D rotation generators
           and Pascal generators, logm of MatrixPower's 2-D rotations);
  "peer"   the Al-Mohy--Higham 2012 experiment-1 matrix with last entry 1
           (homogeneous), a 3x3 block with 3e5 off-diagonals, Moler's badly
           scaled matrix;
  "halfturn_1e-8", "halfturn_1e-13"  rigid motions turning by pi - 1e-8 and
           pi - 1e-13, built at 60 digits and rounded;
  "regress" inputs that fuzzing found mishandled: scipy's logm inputs scaled
           by 1e-4, diag(1e-100, 1, 1, 1), a matrix with entries near 1e-298.
n x n inputs with n < 4 are embedded in 4x4: [M 0; 0 0] for expm (whose exp
is [e^M 0; 0 I], a homogeneous generator) and [M 0; 0 I] for logm
(log [log M 0; 0 0]); 4x4 inputs are taken as they are.

Each reference is mpmath's expm/logm at 60 digits, checked against 80 digits
(the two agree to far below double rounding, or the case is dropped).
scipy_err is scipy's own error on the same double input, max |entry error|
/ max |reference entry| over the n x n input, measured here with the
installed scipy.
"""
import importlib.util
import inspect
import sys
import warnings

import mpmath as mp
import numpy as np
import scipy
import scipy.linalg as sl

cases = {"expm": [], "logm": []}


def recorder(kind, real):
    def f(A, *args, **kw):
        try:
            M = np.array(A, dtype=float) if not np.iscomplexobj(A) else None
        except Exception:
            M = None
        if M is not None and M.ndim == 2 and M.shape[0] == M.shape[1] and 1 <= M.shape[0] <= 4:
            cases[kind].append(M.copy())
        return real(A, *args, **kw)
    return f


def harvest(path):
    spec = importlib.util.spec_from_file_location("t" + str(abs(hash(path))), path)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    if hasattr(mod, "expm"):
        mod.expm = recorder("expm", mod.expm)
    if hasattr(mod, "logm"):
        mod.logm = recorder("logm", mod.logm)
    for cname, cls in inspect.getmembers(mod, inspect.isclass):
        if not cname.startswith("Test"):
            continue
        if cname == "TestExpmConditionNumber":
            continue  # thousands of random perturbations, not test matrices
        for mname, meth in inspect.getmembers(cls, inspect.isfunction):
            if not mname.startswith("test_") or "slow" in mname or "medium" in mname:
                continue
            try:
                with warnings.catch_warnings():
                    warnings.simplefilter("ignore")
                    meth(cls())
            except Exception:
                pass


base = scipy.__path__[0]
harvest(base + "/linalg/tests/test_matfuncs.py")
harvest(base + "/sparse/linalg/tests/test_matfuncs.py")
src = {}
for kind in ("expm", "logm"):
    for m in cases[kind]:
        src.setdefault((kind, m.tobytes()), "scipy")

# Eigen's deterministic real test matrices of size <= 4
# (unsupported/test/MatrixFunctions): expm of angle * [0 1; -1 0],
# angle = 10^(i/5 - 2), i = 0..20 (test2dRotation), and of the Pascal
# generators of size 1..4 (testPascal, subdiagonal 1, 2, 3); logm of the
# rotations [c s; -s c], angle = 10^((i - 10)/5), of MatrixPower's
# test2dRotation (which takes their log).
for i in range(21):
    a = 10.0 ** (i / 5.0 - 2)
    M = np.array([[0.0, a], [-a, 0.0]])
    cases["expm"].append(M)
    src[("expm", M.tobytes())] = "eigen"
for size in range(1, 5):
    M = np.zeros((size, size))
    for i in range(size - 1):
        M[i + 1, i] = i + 1
    cases["expm"].append(M)
    src[("expm", M.tobytes())] = "eigen"
for i in range(21):
    a = 10.0 ** ((i - 10) / 5.0)
    c, s_ = np.cos(a), np.sin(a)
    M = np.array([[c, s_], [-s_, c]])
    cases["logm"].append(M)
    src[("logm", M.tobytes())] = "eigen"

# The peer matrices: the Al-Mohy--Higham 2012 experiment-1 matrix with last
# entry 1 (homogeneous), a 3x3 block with 3e5 off-diagonals under the same
# last row, and Moler's badly scaled matrix (scipy's test_burkardt_14).
amh = np.array([[3.2346e-1, 3e4, 3e4, 3e4], [0, 3.0089e-1, 3e4, 3e4], [0, 0, 3.221e-1, 3e4], [0, 0, 0, 1.0]])
blk = np.array([[3.2346e-1, 3e5, 3e5, 0], [0, 3.0089e-1, 3e5, 0], [0, 0, 3.221e-1, 0], [0, 0, 0, 1.0]])
moler = np.array([[0, 1e-8, 0], [-(2e10 + 4e8 / 6), -3, 2e10], [200 / 3.0, 0, -200 / 3.0]])
for M in (amh, blk):
    cases["logm"].append(M)
    src[("logm", M.tobytes())] = "peer"
cases["expm"].append(moler)
src[("expm", moler.tobytes())] = "peer"

# Rigid motions turning by pi - d, d = 1e-8 and 1e-13: the rotation built at
# 60 digits (Rodrigues) and rounded; the reference is the log of the rounded
# matrix.
mp.mp.dps = 60
for d, tag in ((mp.mpf("1e-8"), "halfturn_1e-8"), (mp.mpf("1e-13"), "halfturn_1e-13")):
    for k, (axis, t) in enumerate((((1, 2, 3), (0.5, -1.0, 2.0)), ((0, 0, 1), (0.0, 0.0, 0.0)),
                                   ((-3, 1, 1), (10.0, 20.0, -5.0)), ((1, 1, 0), (1e-3, 0.0, 1.0)))):
        u = mp.matrix(axis)
        u = u / mp.norm(u)
        th = mp.pi - d
        K = mp.matrix([[0, -u[2], u[1]], [u[2], 0, -u[0]], [-u[1], u[0], 0]])
        R = mp.eye(3) + mp.sin(th) * K + (1 - mp.cos(th)) * K * K
        A = np.eye(4)
        for i in range(3):
            for j in range(3):
                A[i, j] = float(R[i, j])
            A[i, 3] = t[i]
        cases["logm"].append(A)
        src[("logm", A.tobytes())] = tag


# The regressions found by fuzzing (src "regress"): every scipy logm input
# (embedded in 4x4) scaled by 1e-4, where a Schur form of A - I would keep
# only 12 digits of the eigenvalues; diag(1e-100, 1, 1, 1), whose 1e-100 - 1
# rounds to -1; and expm(X) of fuzz/regress/numeric/logm-expm-tiny-entries
# (entries near 1e-298 that once stalled the QR iteration).
for M in list(cases["logm"]):
    if src[("logm", M.tobytes())] == "scipy":
        E = np.eye(4)
        E[: M.shape[0], : M.shape[0]] = M
        E = E * 1e-4
        cases["logm"].append(E)
        src.setdefault(("logm", E.tobytes()), "regress")
for M in (np.diag([1e-100, 1.0, 1.0, 1.0]),
          np.array([[2.7182818284590455, -7.1828182845904517e-301, 0, 1.7182818284590453],
                    [-4.3988014808551557e-298, 1, -2.0000000000000001e-300, -1.8388014808551558e-298],
                    [0, -2.5600000000000001e-298, 1, -2.5600000000000001e-298],
                    [-4.3988014808551557e-298, -1e-300, 0, 1]])):
    cases["logm"].append(M)
    src[("logm", M.tobytes())] = "regress"


def dedupe(ms):
    seen, out = set(), []
    for m in ms:
        k = (m.shape, m.tobytes())
        if k not in seen:
            seen.add(k)
            out.append(m)
    return out


def mpf_ref(kind, M, dps, tag=""):
    mp.mp.dps = dps
    A = mp.matrix([[mp.mpf(float(x)) for x in row] for row in M])
    if tag.startswith("halfturn"):
        # mpmath's logm returns a complex (non-principal) result for
        # eigenvalues this near -1; A = [R t; 0 1] has log
        # [log R, g(R) t; 0 0] with g(z) = log(z)/(z - 1) (g(1) = 1), and R
        # (eigenvalues -1 +- i delta and 1, distinct) is diagonalisable:
        # f(R) = V diag(f(lambda)) V^-1 at this precision.
        R = A[0:3, 0:3]
        E, V = mp.eig(R)
        Vi = mp.inverse(V)
        def fR(f):
            D = mp.diag([f(e) for e in E])
            return V * D * Vi
        L = fR(mp.log)
        G = fR(lambda z: mp.log(z) / (z - 1) if abs(z - 1) > mp.mpf(10) ** (-dps // 3) else 1 - (z - 1) / 2)
        t = A[0:3, 3]
        gt = G * t
        F = mp.matrix(4, 4)
        for i in range(3):
            for j in range(3):
                F[i, j] = L[i, j]
            F[i, 3] = gt[i]
        return F
    F = mp.expm(A) if kind == "expm" else mp.logm(A)
    return F


def has_real_log(M):
    # from the double eigenvalues: none 0, none real and negative (within
    # 1e-12 relative of the negative real axis counts as on it)
    for z in np.linalg.eigvals(M):
        if z == 0 or (z.real < 0 and abs(z.imag) <= 1e-12 * abs(z)):
            return False
    return True


def embed(kind, M):
    n = M.shape[0]
    if n == 4:
        return M
    E = np.zeros((4, 4))
    E[:n, :n] = M
    if kind == "logm":
        for i in range(n, 4):
            E[i, i] = 1.0
    return E


rows = []
for kind in ("expm", "logm"):
    for M in dedupe(cases[kind]):
        tag = src[(kind, M.tobytes())]
        n = M.shape[0]
        if not np.all(np.isfinite(M)):
            continue
        haslog = True
        if kind == "logm" and not tag.startswith("halfturn"):  # a half turn short of pi has one
            haslog = has_real_log(M)
        ref = [[0.0] * 4 for _ in range(4)]
        serr = 0.0
        if haslog:
            try:
                F60, F80 = mpf_ref(kind, M, 60, tag), mpf_ref(kind, M, 80, tag)
            except Exception:
                continue
            mp.mp.dps = 80
            big = max(abs(F80[i, j]) for i in range(n) for j in range(n))
            drift = max(abs(F60[i, j] - F80[i, j]) for i in range(n) for j in range(n))
            if big == 0 or drift > mp.mpf(2) ** -70 * big or not mp.isfinite(big):
                continue
            if max(abs(mp.im(F80[i, j])) for i in range(n) for j in range(n)) > mp.mpf(2) ** -70 * big:
                continue  # a complex log: none real
            F80 = F80.apply(mp.re)
            for i in range(n):
                for j in range(n):
                    ref[i][j] = float(F80[i, j])
            if kind == "expm":
                for i in range(n, 4):
                    ref[i][i] = 1.0
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                try:
                    S = sl.expm(M) if kind == "expm" else sl.logm(M, disp=False)[0]
                    S = np.array(S)
                    if np.iscomplexobj(S):
                        S = S.real if np.all(np.abs(S.imag) <= 1e-12 * np.abs(S).max()) else np.full(S.shape, np.nan)
                    serr = float(max(abs(mp.mpf(float(S[i, j])) - F80[i, j]) for i in range(n) for j in range(n)) / big)
                    if not np.isfinite(serr):
                        serr = float("inf")
                except Exception:
                    serr = float("inf")
        rows.append((kind, n, embed(kind, M), ref, haslog, serr, tag))

print("/* tests/matfunc_refs.h: written by tests/make_matfunc_refs.py (scipy %s, mpmath %s);"
      % (scipy.__version__, mp.__version__))
print(" * do not edit. The test matrices of size <= 4 of scipy's and Eigen's expm/logm")
print(" * tests and the peer and near-half-turn matrices (see the generator),")
print(" * embedded as homogeneous 4x4, its 80-digit reference rounded to double and")
print(" * scipy's measured error on the same double input (max |entry error| / max")
print(" * |reference entry|; INFINITY where scipy failed). has_log = 0: no real")
print(" * principal log (a real eigenvalue <= 0). */")
print("typedef struct {")
print("    const char *src;")
print("    int logm, n, has_log;")
print("    double a[16], ref[16], scipy_err;")
print("} matfunc_ref;")
print("static const matfunc_ref matfunc_refs[] = {")
for kind, n, A, ref, haslog, serr, tag in rows:
    fa = ", ".join(repr(float(x)) for x in A.flatten())
    fr = ", ".join(repr(float(x)) for r in ref for x in r)
    se = "INFINITY" if serr == float("inf") else repr(serr)
    print('    {"%s", %d, %d, %d, {%s}, {%s}, %s},' % (tag, kind == "logm", n, haslog, fa, fr, se))
print("};")
print("#define N_MATFUNC_REFS (sizeof matfunc_refs / sizeof matfunc_refs[0])")
