"""Multivector.between, Multivector.interp and garotor.object_mean (the C
library's ga_versor_between, ga_object_interp and ga_object_mean; object.h,
docs/python.md, "Objects"): bit for bit the C functions called through ctypes
on the shared library (GAROTOR_LIB, set by python/meson.build; skipped
without it), and the errors: garotor.Error with the status, naming the bad
element's index where there is one.
"""
import ctypes
import os

import numpy as np
import pytest

import garotor
from garotor import Multivector as M

GA_ERR_NOTFINITE = -1
GA_ERR_DOMAIN = -5
GA_ERR_ARG = -6


class CMV(ctypes.Structure):
    _fields_ = [("c", ctypes.c_double * 32)]


class CObject(ctypes.Structure):  # ga_object (object.h)
    _fields_ = [("kind", ctypes.c_int), ("reality", ctypes.c_int), ("centre", ctypes.c_double * 3),
                ("direction", ctypes.c_double * 3), ("r2", ctypes.c_double), ("err", ctypes.c_double),
                ("r2_err", ctypes.c_double), ("angle_err", ctypes.c_double)]


KINDS = ["empty", "flat point", "line", "plane", "point pair", "circle", "sphere"]
REALITIES = ["real", "tangent", "imaginary"]


@pytest.fixture(scope="module")
def C():
    path = os.environ.get("GAROTOR_LIB")
    if not path or not os.path.exists(path):
        pytest.skip("the shared library is not found (set GAROTOR_LIB)")
    lib = ctypes.CDLL(path)
    P = ctypes.POINTER
    lib.ga_versor_between.argtypes, lib.ga_versor_between.restype = [CMV, CMV, P(CMV)], ctypes.c_int
    lib.ga_object_interp.argtypes = [CMV, CMV, ctypes.c_double, P(CMV)]
    lib.ga_object_interp.restype = ctypes.c_int
    lib.ga_object_mean.argtypes = [P(CMV), P(ctypes.c_double), ctypes.c_size_t, P(CMV)]
    lib.ga_object_mean.restype = ctypes.c_int
    lib.ga_object_mean_read.argtypes = [P(CMV), P(ctypes.c_double), ctypes.c_size_t, P(CMV), P(CObject)]
    lib.ga_object_mean_read.restype = ctypes.c_int
    return lib


def cmv(m):
    x = CMV()
    x.c[:] = list(np.asarray(m))
    return x


def same(a, b):
    """bit for bit, -0 and 0 told apart"""
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    return a.shape == b.shape and a.tobytes() == b.tobytes()


def sphere(c, r):
    return M.up(c) - 0.5 * r * r * garotor.n


def circle(rng, c, r):
    u = rng.normal(size=3)
    u /= np.linalg.norm(u)
    v = np.cross(u, rng.normal(size=3))
    v /= np.linalg.norm(v)
    w = np.cross(u, v)
    a = rng.uniform(0, 2 * np.pi, 3)
    p = [c + r * (np.cos(t) * v + np.sin(t) * w) for t in a]
    return M.up(p[0]) ^ M.up(p[1]) ^ M.up(p[2])


def objects(rng, kind, n):
    c0 = rng.normal(size=3) * 5
    if kind == "sphere":
        return [sphere(c0 + 0.1 * rng.normal(size=3), rng.uniform(0.5, 2)) for _ in range(n)]
    if kind == "circle":
        return [circle(rng, c0 + 0.01 * rng.normal(size=3), rng.uniform(0.5, 2)) for _ in range(n)]
    # lines through two points near two fixed ones
    a, b = c0, c0 + rng.normal(size=3)
    return [M.up(a + 0.01 * rng.normal(size=3)) ^ M.up(b + 0.01 * rng.normal(size=3)) ^ garotor.n
            for _ in range(n)]


@pytest.mark.parametrize("kind", ["sphere", "circle", "line"])
def test_mean_bit_for_bit(C, kind):
    rng = np.random.default_rng(25)
    for n in range(1, 8):
        A = objects(rng, kind, n)
        w = rng.uniform(0.1, 10, n)
        arr = (CMV * n)(*[cmv(a) for a in A])
        for weights in (w, None):
            out = CMV()
            wp = None if weights is None else (ctypes.c_double * n)(*weights)
            assert C.ga_object_mean(arr, wp, n, ctypes.byref(out)) == 0
            got = garotor.object_mean(A, weights)
            assert same(np.asarray(got), out.c[:])
        # any order, the same bits (the sums are exact)
        p = rng.permutation(n)
        assert same(np.asarray(garotor.object_mean([A[i] for i in p], w[p])),
                    np.asarray(garotor.object_mean(A, w)))


@pytest.mark.parametrize("kind", ["sphere", "circle", "line"])
def test_mean_read_bit_for_bit(C, kind):
    """object_mean(..., read=True): ga_object_mean_read's mean and Object, every field bit for bit"""
    rng = np.random.default_rng(26)
    for n in range(1, 8):
        A = objects(rng, kind, n)
        w = rng.uniform(0.1, 10, n)
        arr = (CMV * n)(*[cmv(a) for a in A])
        for weights in (w, None):
            out, ob = CMV(), CObject()
            wp = None if weights is None else (ctypes.c_double * n)(*weights)
            assert C.ga_object_mean_read(arr, wp, n, ctypes.byref(out), ctypes.byref(ob)) == 0
            got, o = garotor.object_mean(A, weights, read=True)
            assert isinstance(o, garotor.Object) and o.kind == kind
            assert same(np.asarray(got), out.c[:])
            assert same(np.asarray(got), np.asarray(garotor.object_mean(A, weights)))
            assert o.kind == KINDS[ob.kind] and o.reality == REALITIES[ob.reality]
            assert same(o.centre, ob.centre[:]) and same(o.direction, ob.direction[:])
            assert same([o.r2, o.err, o.r2_err, o.angle_err], [ob.r2, ob.err, ob.r2_err, ob.angle_err])
    # the same errors as without read, and read must be a truth value
    S = [sphere([0, 0, 0], 1), sphere([1, 0, 0], 2)]
    with pytest.raises(garotor.Error, match=r"weights\[1\] is negative") as e:
        garotor.object_mean(S, [1, -1], read=True)
    assert e.value.status == GA_ERR_ARG and e.value.index == (1,)
    with pytest.raises(TypeError):
        garotor.object_mean(S, None, True)  # read is keyword-only


def same_or_status(st, out, call):
    """the module's answer is the C one bit for bit, or raises its status"""
    if st != 0:
        with pytest.raises(garotor.Error) as e:
            call()
        assert e.value.status == st
        return 0
    assert same(np.asarray(call()), out.c[:])
    return 1


def test_between_interp_bit_for_bit(C):
    rng = np.random.default_rng(7)
    answered = 0
    for _ in range(100):
        A = circle(rng, rng.normal(size=3), rng.uniform(0.5, 2))
        B = circle(rng, rng.normal(size=3) * 3, rng.uniform(0.5, 2))
        out = CMV()
        st = C.ga_versor_between(cmv(A), cmv(B), ctypes.byref(out))
        answered += same_or_status(st, out, lambda: A.between(B))
        t = rng.uniform(-0.5, 1.5)
        st = C.ga_object_interp(cmv(A), cmv(B), t, ctypes.byref(out))
        answered += same_or_status(st, out, lambda: A.interp(B, t))
    assert answered > 100  # most answer; the rest are refused alike


def test_interp_ends_and_radius():
    S1, S3 = sphere([0, 0, 0], 1), sphere([2, 0, 0], 3)
    o = S1.interp(S3, 0.5).object()
    assert o.kind == "sphere" and abs(o.r2 - 3) < 1e-12
    assert np.allclose(S1.between(S3).apply(S1).object().centre, [2, 0, 0], atol=1e-12)


def test_errors():
    S = [sphere([0, 0, 0], 1), sphere([1, 0, 0], 2)]
    P = M.up([0, 0, 0]) ^ M.up([1, 0, 0]) ^ M.up([0, 1, 0]) ^ garotor.n
    with pytest.raises(ValueError, match="no objects"):
        garotor.object_mean([])
    with pytest.raises(TypeError, match=r"objects\[1\] is not a Multivector"):
        garotor.object_mean([S[0], 3.0])
    with pytest.raises(garotor.Error, match=r"weights\[1\] is negative") as e:
        garotor.object_mean(S, [1, -1])
    assert e.value.status == GA_ERR_ARG and e.value.index == (1,)
    with pytest.raises(garotor.Error, match=r"weights\[0\] is not finite") as e:
        garotor.object_mean(S, [np.inf, 1])
    assert e.value.status == GA_ERR_NOTFINITE
    for i in range(2):  # NaN at each weight: named by its index
        w = np.ones(2)
        w[i] = np.nan
        with pytest.raises(garotor.Error, match=r"weights\[%d\] is not finite" % i) as e:
            garotor.object_mean(S, w)
        assert e.value.status == GA_ERR_NOTFINITE and e.value.index == (i,)
    with pytest.raises(ValueError, match=r"weights must have shape \(2,\)"):
        garotor.object_mean(S, [1, 2, 3])
    with pytest.raises(garotor.Error, match=r"objects\[1\] is of another kind") as e:
        garotor.object_mean([S[0], P])
    assert e.value.status == GA_ERR_ARG and e.value.index == (1,)
    with pytest.raises(garotor.Error) as e:
        garotor.object_mean(S, [0, 0])
    assert e.value.status == GA_ERR_ARG
    with pytest.raises(garotor.Error) as e:
        S[0].between(M.up([0, 0, 0]) ^ M.up([1, 0, 0]) ^ garotor.n)  # a sphere to a line: grades differ
    assert e.value.status == GA_ERR_ARG
    with pytest.raises(garotor.Error) as e:
        S[0].interp(P, 0.5)  # a sphere and a plane: a rotor, but no interpolation across kinds
    assert e.value.status == GA_ERR_ARG
    with pytest.raises(garotor.Error) as e:
        S[0].between(M.up([3, 0, 0]))  # a sphere to a point: no dilation from radius 0
    assert e.value.status == GA_ERR_DOMAIN
    with pytest.raises((ValueError, garotor.Error)):
        S[0].interp(S[1], float("nan"))
