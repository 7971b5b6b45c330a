"""garotor.MultivectorArray (issue 25, part 3; docs/python.md,
"MultivectorArray"): (..., 32) multivectors whose operations run as one C
loop. Every element equals Multivector's answer and the C function's (through
ctypes, GAROTOR_LIB) bit for bit; broadcasting; indexing, pickling; bad input
(NaN, wrong shape, not a blade, a result that would not be finite) raises
garotor.Error (a ValueError) naming the index.
"""
import ctypes
import os
import pickle

import numpy as np
import pytest

import garotor
from garotor import Multivector as M
from garotor import MultivectorArray as MA

GA_ERR_NOTFINITE = -1
GA_ERR_SINGULAR = -2
GA_ERR_DOMAIN = -5
GA_ERR_NOTBLADE = -7
KINDS = ["empty", "flat point", "line", "plane", "point pair", "circle", "sphere"]
REALITIES = ["real", "tangent", "imaginary"]


class CMV(ctypes.Structure):
    _fields_ = [("c", ctypes.c_double * 32)]


class CV3(ctypes.Structure):
    _fields_ = [("x", ctypes.c_double), ("y", ctypes.c_double), ("z", ctypes.c_double)]


class CObj(ctypes.Structure):
    _fields_ = [("kind", ctypes.c_int), ("reality", ctypes.c_int), ("centre", CV3), ("direction", CV3),
                ("r2", ctypes.c_double), ("err", ctypes.c_double), ("r2_err", ctypes.c_double),
                ("angle_err", ctypes.c_double)]


@pytest.fixture(scope="module")
def C():
    path = os.environ.get("GAROTOR_LIB")
    if not path or not os.path.exists(path):
        pytest.skip("the shared library is not found (set GAROTOR_LIB)")
    lib = ctypes.CDLL(path)
    P = ctypes.POINTER
    for name in ("ga_mv_gp", "ga_mv_op", "ga_mv_lc", "ga_mv_regressive", "ga_mv_commutator", "ga_mv_meet",
                 "ga_mv_dot", "ga_mv_ip"):
        f = getattr(lib, name)
        f.argtypes, f.restype = [CMV, CMV], CMV
    lib.ga_versor_apply.argtypes, lib.ga_versor_apply.restype = [CMV, CMV, P(CMV)], ctypes.c_int
    lib.ga_mv_inverse.argtypes, lib.ga_mv_inverse.restype = [CMV, P(CMV)], ctypes.c_int
    lib.ga_object_from_mv.argtypes, lib.ga_object_from_mv.restype = [CMV, P(CObj)], ctypes.c_int
    return lib


def cmv(v):
    x = CMV()
    x.c[:] = [float(t) for t in v]
    return x


def same(a, b):
    """bit for bit, -0 and 0 told apart"""
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    return a.shape == b.shape and a.tobytes() == b.tobytes()


def blades(rng, n, scale=1.0):
    out = []
    for k in range(n):
        o = rng.normal(size=3) * scale
        P = [M.up(o + rng.normal(size=3)) for _ in range(4)]
        objs = [P[0] ^ P[1] ^ P[2] ^ P[3], P[0] ^ P[1] ^ P[2], P[0] ^ P[1] ^ garotor.n, P[0] ^ P[1],
                P[0] ^ P[1] ^ P[2] ^ garotor.n, P[0] ^ garotor.n]
        out.append(np.asarray(objs[k % len(objs)]))
    return np.array(out)


def rotors(rng, n):
    return np.array([np.asarray(M.rotation(rng.normal(size=3), rng.uniform(0, 3)) *
                                M.translation(rng.normal(size=3))) for _ in range(n)])


def test_construction_shape_and_read_back(rng):
    X = rng.normal(size=(4, 3, 32))
    a = MA(X)
    assert a.shape == (4, 3) and a.ndim == 2 and len(a) == 4
    c = np.asarray(a)
    assert same(c, X) and not c.flags.writeable
    X[0, 0, 0] = 99.0  # a's numbers are its own
    assert c[0, 0, 0] != 99.0
    assert np.asarray(a, dtype=np.float32).dtype == np.float32
    assert MA(a).shape == (4, 3) and same(np.asarray(MA(a)), c)
    one = MA(garotor.e12)
    assert one.shape == () and same(np.asarray(one), np.asarray(garotor.e12))
    assert MA([[1] + [0] * 31]).shape == (1,)  # lists, integers
    assert MA(np.array([np.arange(32)], dtype=object)).shape == (1,)
    assert repr(a) == "MultivectorArray(shape=(4, 3))"
    # indexing: the leading dimensions, as numpy's
    assert isinstance(a[1, 2], M) and same(np.asarray(a[1, 2]), c[1, 2])
    assert a[1].shape == (3,) and same(np.asarray(a[1]), c[1])
    assert a[1:3, ::2].shape == (2, 2) and same(np.asarray(a[1:3, ::2]), c[1:3, ::2])
    assert a[..., 0].shape == (4,) and same(np.asarray(a[..., 0]), c[..., 0, :])
    mask = np.array([True, False, True, False])
    assert same(np.asarray(a[mask]), c[mask])
    assert [same(np.asarray(m), c[i]) for i, m in enumerate(a)] == [True] * 4
    with pytest.raises(IndexError):
        a[1, 2, 3]
    with pytest.raises(IndexError):
        a[4]
    b = pickle.loads(pickle.dumps(a))
    assert isinstance(b, MA) and same(np.asarray(b), c)


def test_bad_input_names_the_index(rng):
    X = rng.normal(size=(3, 4, 32))
    X[2, 1, 7] = np.nan
    with pytest.raises(garotor.Error, match=r"^MultivectorArray: index \(2, 1\): not finite \(NaN or "
                       r"infinity\): c\[2, 1, 7\] is nan$") as e:
        MA(X)
    assert isinstance(e.value, ValueError)
    assert e.value.index == (2, 1) and e.value.status == GA_ERR_NOTFINITE
    for bad in (np.zeros((3, 31)), np.zeros(31), 1.0, np.zeros((2, 32, 3))):
        with pytest.raises(ValueError, match=r"MultivectorArray: c must have shape \(\.\.\., 32\), not"):
            MA(bad)
    # not a blade: exp of something that is not a bivector, read-back of a sum
    B = np.zeros((5, 32))
    B[:, 6] = 1.0
    B[3, 1] = 0.5
    with pytest.raises(garotor.Error, match=r"^MultivectorArray.exp: index 3: not an object of the expected kind$") as e:
        MA(B).exp()
    assert e.value.index == (3,) and e.value.status == GA_ERR_NOTBLADE
    S = blades(rng, 4)
    S[1] += np.asarray(garotor.e1)
    with pytest.raises(garotor.Error, match=r"^MultivectorArray.object: index 1: ") as e:
        MA(S).object()
    assert e.value.index == (1,)
    # a result that would not be finite
    big = np.zeros((3, 32))
    big[:, 1] = 1.0
    big[2, 1] = 1e200
    with pytest.raises(garotor.Error, match=r"^MultivectorArray \*: index 2: outside the domain: the "
                       r"result would not be finite$") as e:
        MA(big) * MA(big)
    assert e.value.status == GA_ERR_DOMAIN
    # operands of another kind
    with pytest.raises(TypeError):
        MA(big) * "x"
    with pytest.raises(TypeError):
        MA(big).meet(np.zeros(32))
    with pytest.raises(garotor.Error, match="not finite"):
        MA(big) * float("nan")


OPERATORS = {
    "*": (lambda a, b: a * b, "ga_mv_gp"), "^": (lambda a, b: a ^ b, "ga_mv_op"),
    "|": (lambda a, b: a | b, "ga_mv_lc"), "&": (lambda a, b: a & b, "ga_mv_regressive"),
    "dot": (lambda a, b: a.dot(b), "ga_mv_dot"), "ip": (lambda a, b: a.ip(b), "ga_mv_ip"),
    "commutator": (lambda a, b: a.commutator(b), "ga_mv_commutator"),
    "meet": (lambda a, b: a.meet(b), "ga_mv_meet"),
}


def test_products_equal_multivector_and_c_bit_for_bit(rng, C):
    X, Y = rng.normal(size=(6, 32)), rng.normal(size=(6, 32))
    A, B = MA(X), MA(Y)
    for label, (fn, cname) in OPERATORS.items():
        got = np.asarray(fn(A, B))
        for i in range(6):
            assert same(got[i], np.asarray(fn(M(X[i]), M(Y[i])))), label
            assert same(got[i], getattr(C, cname)(cmv(X[i]), cmv(Y[i])).c[:]), label
    for label, fn in {"+": lambda a, b: a + b, "-": lambda a, b: a - b}.items():
        got = np.asarray(fn(A, B))
        assert all(same(got[i], np.asarray(fn(M(X[i]), M(Y[i])))) for i in range(6)), label
    # unary
    for label, fn in {"-": lambda a: -a, "~": lambda a: ~a, "+": lambda a: +a, "reverse": lambda a: a.reverse(),
                      "involute": lambda a: a.involute(), "conjugate": lambda a: a.conjugate(),
                      "dual": lambda a: a.dual(), "undual": lambda a: a.undual(),
                      "grade 2": lambda a: a.grade(2), "grade 7": lambda a: a.grade(7)}.items():
        got = np.asarray(fn(A))
        assert all(same(got[i], np.asarray(fn(M(X[i])))) for i in range(6)), label
    assert same(A.norm2(), [M(x).norm2() for x in X])


def test_broadcasting_with_multivectors_and_numbers(rng):
    X = rng.normal(size=(5, 1, 32))
    Y = rng.normal(size=(3, 32))
    P = MA(X) * MA(Y)
    assert P.shape == (5, 3)
    assert all(same(np.asarray(P[i, j]), np.asarray(M(X[i, 0]) * M(Y[j]))) for i in range(5) for j in range(3))
    m = M(Y[0])
    for r in (MA(Y) * m, m * MA(Y)):
        assert r.shape == (3,)
    assert same(np.asarray(m * MA(Y))[1], np.asarray(m * M(Y[1])))
    assert same(np.asarray(MA(Y) * m)[1], np.asarray(M(Y[1]) * m))
    assert same(np.asarray(2 * MA(Y))[2], np.asarray(2 * M(Y[2])))
    assert same(np.asarray(MA(Y) + 1)[2], np.asarray(M(Y[2]) + 1))
    assert same(np.asarray(np.float64(0.5) * MA(Y))[0], np.asarray(0.5 * M(Y[0])))
    with pytest.raises(TypeError):
        np.zeros(32) * MA(Y)  # an array is not taken for multivectors
    with pytest.raises(ValueError, match="do not broadcast"):
        MA(Y) * MA(rng.normal(size=(4, 32)))
    t = np.linspace(0.1, 0.9, 4)
    R = MA(rotors(rng, 4))
    got = np.asarray(R.pow(t))
    assert all(same(got[i], np.asarray(M(np.asarray(R)[i]).pow(t[i]))) for i in range(4))


def test_exp_log_apply_points_objects(rng, C):
    n = 8
    Bv = np.zeros((n, 32))
    Bv[:, 6:16] = rng.normal(size=(n, 10))
    for i in range(0, n, 2):  # rigid generators too: through the compact rotor
        Bv[i, [9, 12, 14]] = Bv[i, [8, 11, 13]]  # e_i5 = e_i4: e_i n
        Bv[i, 15] = 0.0
    E = MA(Bv).exp()
    assert all(same(np.asarray(E[i]), np.asarray(M(Bv[i]).exp())) for i in range(n))
    R = rotors(rng, n)
    L = MA(R).log()
    assert all(same(np.asarray(L[i]), np.asarray(M(R[i]).log())) for i in range(n))
    S = MA(R).sqrt()
    assert all(same(np.asarray(S[i]), np.asarray(M(R[i]).sqrt())) for i in range(n))
    Inv = MA(R).inverse()
    for i in range(n):
        out = CMV()
        assert C.ga_mv_inverse(cmv(R[i]), ctypes.byref(out)) == 0
        assert same(np.asarray(Inv[i]), out.c[:])
    # versors on objects and on points
    Ob = blades(rng, n, scale=10.0)
    moved = MA(R).apply(MA(Ob))
    for i in range(n):
        out = CMV()
        assert C.ga_versor_apply(cmv(R[i]), cmv(Ob[i]), ctypes.byref(out)) == 0
        assert same(np.asarray(moved[i]), out.c[:])
        assert same(np.asarray(moved[i]), np.asarray(M(R[i]).apply(M(Ob[i]))))
    x = rng.normal(size=(n, 3))
    Xp = MA.up(x)
    assert same(np.asarray(Xp), garotor.up(x))
    assert same(Xp.down(), garotor.down(garotor.up(x)))
    y = MA(R).apply(Xp).down()
    assert all(same(y[i], M(R[i]).apply(M.up(x[i])).down()) for i in range(n))
    # a Multivector's methods take a MultivectorArray: one versor, many points
    V = M(R[0])
    for name in ("apply", "meet", "dot", "ip", "commutator"):
        got = getattr(V, name)(Xp)
        assert isinstance(got, MA) and same(np.asarray(got), np.asarray(getattr(MA(V), name)(Xp))), name
        assert all(same(np.asarray(got[i]), np.asarray(getattr(V, name)(M.up(x[i])))) for i in range(n)), name
    # the read-back: a structured array with garotor.Object's fields
    ob = MA(Ob).object()
    fields = ("kind", "reality", "centre", "direction", "r2", "err", "r2_err", "angle_err")
    assert ob.shape == (n,) and ob.dtype.names == fields
    assert all(hasattr(M(Ob[0]).object(), f) for f in fields)
    for i in range(n):
        o = M(Ob[i]).object()
        c = CObj()
        assert C.ga_object_from_mv(cmv(Ob[i]), ctypes.byref(c)) == 0
        assert ob["kind"][i] == o.kind == KINDS[c.kind] and ob["reality"][i] == o.reality == REALITIES[c.reality]
        assert same(ob["centre"][i], o.centre) and same(ob["direction"][i], o.direction)
        assert same([ob[f][i] for f in ("r2", "err", "r2_err", "angle_err")], [o.r2, o.err, o.r2_err, o.angle_err])
    assert set(ob["kind"]) >= {"sphere", "circle", "line", "point pair", "plane", "flat point"}
    # the object methods of two arguments, where C refuses: the index
    for name in ("join", "meet_rel", "project", "reject"):
        got = getattr(MA(Ob), name)(MA(Ob[::-1]))
        assert all(same(np.asarray(got[i]), np.asarray(getattr(M(Ob[i]), name)(M(Ob[n - 1 - i]))))
                   for i in range(n)), name
    Z = Ob.copy()
    Z[5] = 0.0
    with pytest.raises(garotor.Error, match="^MultivectorArray.project: index 5: ") as e:
        MA(Ob).project(MA(Z))
    assert e.value.index == (5,)


EVEN = np.isin(np.arange(32), [0, *range(6, 16), *range(26, 31)])  # grades 0, 2, 4


def test_one_versor_on_many_is_the_batch_bit_for_bit(rng, C):
    """One versor on many multivectors runs ga_versor_apply_many (V's inverse
    once): each element is ga_versor_apply's answer bit for bit, through
    Multivector.apply, MultivectorArray.apply of one element and the ufunc
    mv_apply (with out= too, past its 48-element chunk), for even and odd
    versors, on points and on dense multivectors; a V that C refuses names
    the first element."""
    n = 130
    x = rng.normal(size=(n, 3))
    X = [np.asarray(MA.up(x)), blades(rng, n, scale=3.0), rng.normal(size=(n, 32))]
    V = [rotors(rng, 1)[0], np.asarray(M.reflection(rng.normal(size=3), 0.7)),
         np.asarray(M.inversion(rng.normal(size=3), 1.3)), rng.normal(size=32) * EVEN]
    for v in V:
        for xs in X:
            want = np.empty_like(xs)
            for i in range(n):
                out = CMV()
                assert C.ga_versor_apply(cmv(v), cmv(xs[i]), ctypes.byref(out)) == 0
                want[i] = out.c[:]
            assert same(np.asarray(M(v).apply(MA(xs))), want)
            assert same(np.asarray(MA(v).apply(MA(xs))), want)
            # per element (V broadcast, not one element): the same numbers
            assert same(np.asarray(MA(np.broadcast_to(v, (n, 32))).apply(MA(xs))), want)
            got = MA(v).apply(MA(xs.reshape(10, 13, 32)))
            assert got.shape == (10, 13) and same(np.asarray(got), want.reshape(10, 13, 32))
            assert same(garotor.ufunc.mv_apply(v, xs), want)
            o = np.full((n, 32), np.nan)
            assert garotor.ufunc.mv_apply(v, xs, out=o) is o and same(o, want)
    mixed = np.zeros(32)
    mixed[0], mixed[1] = 1.0, 0.5  # even and odd parts: GA_ERR_ARG
    with pytest.raises(garotor.Error, match=r"^Multivector.apply: index 0: ") as e:
        M(mixed).apply(MA(X[0]))
    assert e.value.index == (0,)
    with pytest.warns(RuntimeWarning, match="invalid value encountered in mv_apply"):
        r = garotor.ufunc.mv_apply(mixed, X[0])
    assert r.shape == (n, 32) and np.isnan(r).all()
