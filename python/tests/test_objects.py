"""Multivector's objects (issue 25, part 3; docs/python.md, "Objects"): meet,
join, meet_rel and the read-back garotor.Object, the versor constructors and
apply, inverse, /, **, pow, sqrt, &, commutator, project, reject, and the fits.

Each is compared bit for bit with the C function, called through ctypes on the
shared library (GAROTOR_LIB, set by python/meson.build; those tests are
skipped without it), and checked against an independent path (known geometry,
or the module's own products); every status path raises garotor.Error with the
status.
"""
import ctypes
import doctest
import os

import numpy as np
import pytest

import docpage
import garotor
from garotor import Multivector as M

GA_ERR_NOTFINITE = -1
GA_ERR_SINGULAR = -2
GA_ERR_DOMAIN = -5
GA_ERR_ARG = -6
GA_ERR_NOTBLADE = -7

KINDS = ["empty", "flat point", "line", "plane", "point pair", "circle", "sphere"]
REALITIES = ["real", "tangent", "imaginary"]


# ---- the C library through ctypes ---------------------------------------------


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
    sigs = {
        "ga_mv_meet": ([CMV, CMV], CMV),
        "ga_mv_commutator": ([CMV, CMV], CMV),
        "ga_mv_regressive": ([CMV, CMV], CMV),
        "ga_mv_gp": ([CMV, CMV], CMV),
        "ga_mv_join": ([CMV, CMV, P(CMV)], ctypes.c_int),
        "ga_mv_meet_rel": ([CMV, CMV, P(CMV)], ctypes.c_int),
        "ga_mv_project": ([CMV, CMV, P(CMV)], ctypes.c_int),
        "ga_mv_reject": ([CMV, CMV, P(CMV)], ctypes.c_int),
        "ga_versor_apply": ([CMV, CMV, P(CMV)], ctypes.c_int),
        "ga_mv_inverse": ([CMV, P(CMV)], ctypes.c_int),
        "ga_mv_sqrt": ([CMV, P(CMV)], ctypes.c_int),
        "ga_mv_pow": ([CMV, ctypes.c_double, P(CMV)], ctypes.c_int),
        "ga_object_from_mv": ([CMV, P(CObj)], ctypes.c_int),
        "ga_object_from_mv_about": ([CMV, CV3, ctypes.c_double, P(CObj)], ctypes.c_int),
        "ga_versor_reflection": ([CV3, ctypes.c_double], CMV),
        "ga_versor_inversion": ([CV3, ctypes.c_double], CMV),
        "ga_versor_rotation": ([CV3, ctypes.c_double], CMV),
        "ga_versor_transversion": ([CV3], CMV),
        "ga_versor_translation": ([CV3], CMV),
        "ga_versor_dilation": ([CV3, ctypes.c_double, P(CMV)], ctypes.c_int),
        "ga_fit_sphere": ([P(CV3), ctypes.c_size_t, P(CV3), P(ctypes.c_double)], ctypes.c_int),
        "ga_fit_plane": ([P(CV3), ctypes.c_size_t, P(CV3), P(ctypes.c_double)], ctypes.c_int),
        "ga_fit_circle": ([P(CV3), ctypes.c_size_t, P(CV3), P(ctypes.c_double), P(CV3)], ctypes.c_int),
        "ga_fit_line": ([P(CV3), ctypes.c_size_t, P(CV3), P(CV3)], ctypes.c_int),
    }
    for name, (args, res) in sigs.items():
        f = getattr(lib, name)
        f.argtypes, f.restype = args, res
    return lib


def cmv(m):
    x = CMV()
    x.c[:] = list(np.asarray(m))
    return x


def cv3(v):
    return CV3(*[float(t) for t in v])


def coeffs(x):
    return np.array(x.c[:])


def v3(x):
    return np.array([x.x, x.y, x.z])


def same(a, b):
    """bit for bit, -0 and 0 told apart"""
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    return a.shape == b.shape and a.tobytes() == b.tobytes()


def c_status(f, *args):
    out = CMV()
    st = f(*args, ctypes.byref(out))
    return st, coeffs(out)


# ---- objects to work on -----------------------------------------------------------


def dual_sphere(c, r):
    return M.up(c) - 0.5 * r * r * garotor.n


def scene(rng, scale=1.0):
    """direct objects of every kind, built from random points about a random
    place up to `scale` from the origin"""
    o = rng.normal(size=3) * scale
    P = [M.up(o + rng.normal(size=3)) for _ in range(4)]
    return {
        "point pair": P[0] ^ P[1],
        "circle": P[0] ^ P[1] ^ P[2],
        "sphere": P[0] ^ P[1] ^ P[2] ^ P[3],
        "flat point": P[0] ^ garotor.n,
        "line": P[0] ^ P[1] ^ garotor.n,
        "plane": P[0] ^ P[1] ^ P[2] ^ garotor.n,
        "point": P[3],
    }


def pairs(rng, n=6):
    for k in range(n):
        s, t = scene(rng, 10.0 ** (k % 3)), scene(rng, 10.0 ** (k % 3))
        for a in s.values():
            for b in t.values():
                yield a, b


def check_object(C, X, ob):
    cob = CObj()
    st = C.ga_object_from_mv(cmv(X), ctypes.byref(cob))
    assert st == 0
    assert ob.kind == KINDS[cob.kind] and ob.reality == REALITIES[cob.reality]
    assert same(ob.centre, v3(cob.centre)) and same(ob.direction, v3(cob.direction))
    assert same([ob.r2, ob.err, ob.r2_err, ob.angle_err], [cob.r2, cob.err, cob.r2_err, cob.angle_err])


# ---- bit for bit with C --------------------------------------------------------------


def test_meet_join_meet_rel_object_bit_for_bit(C):
    rng = np.random.default_rng(2501)
    counts = {"meet": 0, "join": 0, "meet_rel": 0, "object": 0, "refused": 0}
    for a, b in pairs(rng):
        m = a.meet(b)
        assert same(m, coeffs(C.ga_mv_meet(cmv(a), cmv(b))))
        counts["meet"] += 1
        for name, f in (("join", C.ga_mv_join), ("meet_rel", C.ga_mv_meet_rel)):
            st, want = c_status(f, cmv(a), cmv(b))
            if st == 0:
                assert same(getattr(a, name)(b), want)
                counts[name] += 1
            else:
                with pytest.raises(garotor.Error) as e:
                    getattr(a, name)(b)
                assert e.value.status == st
                counts["refused"] += 1
        for X in (m, a):
            try:
                ob = X.object()
            except garotor.Error as e:
                cob = CObj()
                assert e.status == C.ga_object_from_mv(cmv(X), ctypes.byref(cob)) != 0
                counts["refused"] += 1
                continue
            check_object(C, X, ob)
            counts["object"] += 1
    # most are answered: the comparison is not vacuous
    assert counts["join"] > 200 and counts["meet_rel"] > 200 and counts["object"] > 300, counts


def test_object_about_bit_for_bit(C):
    rng = np.random.default_rng(2502)
    for _ in range(20):
        o = rng.normal(size=3) * 1e6
        s = scene(rng)  # about o, in units of 4
        for X in s.values():
            if X is s["point"]:
                continue
            ob = X.object(o, 4.0)
            cob = CObj()
            assert C.ga_object_from_mv_about(cmv(X), cv3(o), 4.0, ctypes.byref(cob)) == 0
            assert ob.kind == KINDS[cob.kind] and same(ob.centre, v3(cob.centre))
            assert same([ob.r2, ob.err, ob.r2_err], [cob.r2, cob.err, cob.r2_err])


def test_algebra_bit_for_bit(C):
    rng = np.random.default_rng(2503)
    for _ in range(50):
        a, b = M(rng.normal(size=32)), M(rng.normal(size=32))
        assert same(a & b, coeffs(C.ga_mv_regressive(cmv(a), cmv(b))))
        assert same(a.commutator(b), coeffs(C.ga_mv_commutator(cmv(a), cmv(b))))
        st, inv = c_status(C.ga_mv_inverse, cmv(b))
        assert st == 0
        assert same(b.inverse(), inv)
        assert same(a / b, coeffs(C.ga_mv_gp(cmv(a), cmv(M(inv)))))
        assert same(2.5 / b, coeffs(C.ga_mv_gp(cmv(M.blade(0) * 2.5), cmv(M(inv)))))
        # blades: projection and rejection of a vector and a bivector on a 2- and 3-blade
        v = [M(np.r_[0, rng.normal(size=5), np.zeros(26)]) for _ in range(5)]
        for A, B in ((v[0], v[1] ^ v[2]), (v[0] ^ v[1], v[2] ^ v[3] ^ v[4]), (v[0], v[1] ^ v[2] ^ v[3])):
            for name, f in (("project", C.ga_mv_project), ("reject", C.ga_mv_reject)):
                st, want = c_status(f, cmv(A), cmv(B))
                assert st == 0
                assert same(getattr(A, name)(B), want)


def test_rotors_and_versors_bit_for_bit(C):
    rng = np.random.default_rng(2504)
    for _ in range(30):
        axis, ang, t = rng.normal(size=3), rng.uniform(-3, 3), rng.normal(size=3) * 5
        R = M.translation(t) * M.rotation(axis, ang) * M.dilation(rng.normal(size=3), rng.uniform(0.5, 2))
        assert same(M.rotation(axis, ang), coeffs(C.ga_versor_rotation(cv3(axis), ang)))
        assert same(M.translation(t), coeffs(C.ga_versor_translation(cv3(t))))
        assert same(M.transversion(t), coeffs(C.ga_versor_transversion(cv3(t))))
        assert same(M.reflection(axis, ang), coeffs(C.ga_versor_reflection(cv3(axis), ang)))
        assert same(M.inversion(t, abs(ang)), coeffs(C.ga_versor_inversion(cv3(t), abs(ang))))
        st, D = c_status(C.ga_versor_dilation, cv3(t), 1.5)
        assert st == 0 and same(M.dilation(t, 1.5), D)
        for tt in (0.5, -1.0, 2.0, 0.3):
            st, want = c_status(C.ga_mv_pow, cmv(R), tt)
            assert st == 0 and same(R.pow(tt), want)
        st, want = c_status(C.ga_mv_sqrt, cmv(R))
        assert st == 0 and same(R.sqrt(), want)
        X = scene(rng)["circle"]
        for V in (R, M.reflection(axis, ang), M.inversion(t, 2.0)):
            st, want = c_status(C.ga_versor_apply, cmv(V), cmv(X))
            assert st == 0 and same(V.apply(X), want)


def test_fits_bit_for_bit(C):
    rng = np.random.default_rng(2505)
    for _ in range(10):
        pts = rng.normal(size=(int(rng.integers(5, 40)), 3)) * 3 + rng.normal(size=3) * 100
        arr = (CV3 * len(pts))(*[cv3(p) for p in pts])
        c, m, q = CV3(), CV3(), CV3()
        r, d = ctypes.c_double(), ctypes.c_double()
        n = len(pts)
        assert C.ga_fit_sphere(arr, n, ctypes.byref(c), ctypes.byref(r)) == 0
        gc, gr = garotor.fit_sphere(pts)
        assert same(gc, v3(c)) and same(gr, r.value)
        assert C.ga_fit_plane(arr, n, ctypes.byref(m), ctypes.byref(d)) == 0
        gm, gd = garotor.fit_plane(pts)
        assert same(gm, v3(m)) and same(gd, d.value)
        st = C.ga_fit_circle(arr, n, ctypes.byref(c), ctypes.byref(r), ctypes.byref(m))
        if st == 0:
            gc, gr, gm = garotor.fit_circle(pts)
            assert same(gc, v3(c)) and same(gr, r.value) and same(gm, v3(m))
        else:
            with pytest.raises(garotor.Error) as e:
                garotor.fit_circle(pts)
            assert e.value.status == st
        assert C.ga_fit_line(arr, n, ctypes.byref(m), ctypes.byref(q)) == 0
        gu, gq = garotor.fit_line(pts)
        assert same(gu, v3(m)) and same(gq, v3(q))


# ---- independent paths ------------------------------------------------------------------


def test_meet_of_two_spheres_is_the_known_circle():
    # |x| = 1 and |x - (1, 0, 0)| = 1 meet in the circle x = 1/2, r^2 = 3/4
    ob = dual_sphere([0, 0, 0], 1).meet(dual_sphere([1, 0, 0], 1)).object()
    assert ob.kind == "circle" and ob.reality == "real"
    assert np.all(np.abs(ob.centre - [0.5, 0, 0]) <= ob.err)
    assert abs(ob.r2 - 0.75) <= ob.r2_err
    assert abs(abs(ob.direction[0]) - 1) <= ob.angle_err
    # spheres that miss each other: an imaginary circle, r^2 = 1 - 1.5^2
    ob = dual_sphere([0, 0, 0], 1).meet(dual_sphere([3, 0, 0], 1)).object()
    assert ob.kind == "circle" and ob.reality == "imaginary"
    assert np.all(np.abs(ob.centre - [1.5, 0, 0]) <= ob.err) and abs(ob.r2 + 1.25) <= ob.r2_err
    # spheres that touch: tangent
    assert dual_sphere([0, 0, 0], 1).meet(dual_sphere([2, 0, 0], 1)).object().reality == "tangent"


def test_object_pickles():
    import pickle
    ob = dual_sphere([1, 2, 3], 2).meet(garotor.e3 + garotor.n).object()
    back = pickle.loads(pickle.dumps(ob))
    assert type(back) is garotor.Object and back.kind == ob.kind == "circle"
    assert back[:2] == ob[:2] and all(same(x, y) for x, y in zip(back[2:], ob[2:]))


def test_kinds_read_back():
    rng = np.random.default_rng(2506)
    s = scene(rng)
    for kind in KINDS[1:]:
        assert s[kind].object().kind == kind
    # parallel planes meet at infinity: empty
    p1 = garotor.e3 + 0 * garotor.n
    p2 = garotor.e3 + 2 * garotor.n
    assert p1.meet(p2).object().kind == "empty"
    # a point on a line: the join is the line, meet_rel the point (both as given)
    A, B = M.up([0, 0, 0]), M.up([1, 2, 3])
    L = A ^ B ^ garotor.n
    P = M.up([2, 4, 6])
    assert L.join(P) == L and L.meet_rel(P) == P
    # two lines through a common point: meet_rel is their flat point there
    L2 = A ^ M.up([3, -1, 0]) ^ garotor.n
    ob = L.meet_rel(L2).object()
    assert ob.kind == "flat point" and np.all(np.abs(ob.centre) <= 1e-15)
    assert L.join(L2).object().kind == "plane"


def test_products_through_the_module():
    rng = np.random.default_rng(2507)
    a, b = M(rng.normal(size=32)), M(rng.normal(size=32))
    assert a ** 1 == a and a ** 0 == M.blade(0) and a ** 3 == a * a * a
    ai = a.inverse()
    assert a ** -2 == ai * ai and a / b == a * b.inverse()
    assert np.max(np.abs(np.asarray(a * ai - 1))) < 1e-12
    # the regressive product is the dual's outer product undualised, bit for
    # bit; the commutator is (a b - b a) / 2 summed over the anticommuting
    # blade pairs, each once (include/garotor/mv.h): within 64 u |a|_1 |b|_1
    # of the difference as written (every term of a blade is at most
    # |a_i| |b_j|), and antisymmetric bit for bit
    assert a & b == (a.dual() ^ b.dual()).undual()
    diff = np.asarray(a.commutator(b) - (a * b - b * a) / 2)
    bound = 64 * np.finfo(float).eps * np.sum(np.abs(np.asarray(a))) * np.sum(np.abs(np.asarray(b)))
    assert np.max(np.abs(diff)) <= bound
    assert a.commutator(b) == -b.commutator(a)
    # e1 projected onto the e1 e2 plane; e1 + e3 rejected from it
    B = garotor.e1 ^ garotor.e2
    assert (garotor.e1 + garotor.e3).project(B) == garotor.e1
    assert (garotor.e1 + garotor.e3).reject(B) == garotor.e3
    # rotors: sqrt squared, pow(1), a quarter turn applied to a point
    R = M.rotation([0, 0, 1], np.pi / 2) * M.translation([1, 2, 3])
    S = R.sqrt()
    assert np.max(np.abs(np.asarray(S * S - R))) < 1e-15 and S == R.pow(0.5)
    assert np.max(np.abs(np.asarray(R.pow(1) - R))) < 1e-15
    x = R.apply(M.up([1, 0, 0])).down()
    assert np.allclose(x, [-2, 2, 3], rtol=0, atol=1e-15)
    assert np.allclose(M.dilation([1, 1, 1], 3).apply(M.up([2, 1, 1])).down(), [4, 1, 1], rtol=0, atol=1e-14)
    assert np.allclose(M.inversion([0, 0, 0], 2).apply(M.up([4, 0, 0])).down(), [1, 0, 0], rtol=0, atol=1e-15)
    assert np.allclose(M.reflection([1, 0, 0], 1).apply(M.up([3, 5, 0])).down(), [-1, 5, 0], rtol=0, atol=1e-14)


def test_fits_of_exact_points():
    rng = np.random.default_rng(2508)
    u = rng.normal(size=(20, 3))
    u /= np.linalg.norm(u, axis=1)[:, None]
    c, r = garotor.fit_sphere([5, -2, 1] + 3 * u)
    assert np.allclose(c, [5, -2, 1], rtol=0, atol=1e-13) and abs(r - 3) < 1e-13
    t = rng.uniform(0, 2 * np.pi, 12)
    pts = np.c_[2 * np.cos(t), 2 * np.sin(t), np.full(12, 7.0)]
    c, r, m = garotor.fit_circle(pts)
    assert np.allclose(c, [0, 0, 7], rtol=0, atol=1e-13) and abs(r - 2) < 1e-13
    assert np.allclose(m, [0, 0, 1], rtol=0, atol=1e-13)
    m, d = garotor.fit_plane(pts)
    assert np.allclose(m, [0, 0, 1], rtol=0, atol=1e-13) and abs(d - 7) < 1e-13
    u, q = garotor.fit_line(np.outer(rng.normal(size=8), [1, 2, 2]) + [0, 0, 1])
    assert np.allclose(u, np.array([1, 2, 2]) / 3, rtol=0, atol=1e-14)
    assert np.allclose(q, [-2 / 9, -4 / 9, 5 / 9], rtol=0, atol=1e-14)


# ---- statuses ---------------------------------------------------------------------------


def raises(status, f, *args):
    with pytest.raises(garotor.Error) as e:
        f(*args)
    assert e.value.status == status, str(e.value)
    assert e.value.index == ()
    return str(e.value)


def test_statuses():
    s = dual_sphere([1, 2, 3], 2)
    # a sphere met with a multiple of itself: 0 exactly, read back as singular
    assert not s.meet(3 * s)
    msg = raises(GA_ERR_SINGULAR, lambda: s.meet(3 * s).object())
    assert msg.endswith("the multivector is 0 (the meet of objects in special position: meet_rel gives it)")
    # ... where meet_rel gives the sphere (the smaller one as given: B)
    assert s.dual().meet_rel((3 * s).dual()) == (3 * s).dual()
    raises(GA_ERR_NOTBLADE, lambda: (garotor.e1 + garotor.e12).object())
    raises(GA_ERR_SINGULAR, lambda: M().join(garotor.e1))
    raises(GA_ERR_DOMAIN, lambda: M.blade(0).join(garotor.e1))
    raises(GA_ERR_NOTBLADE, lambda: (garotor.e1 + garotor.e12).meet_rel(garotor.e2))
    msg = raises(GA_ERR_SINGULAR, garotor.n.inverse)
    assert msg.startswith("Multivector.inverse: ")
    raises(GA_ERR_SINGULAR, lambda: garotor.e1 / garotor.n)
    raises(GA_ERR_SINGULAR, lambda: garotor.n ** -1)
    raises(GA_ERR_SINGULAR, lambda: garotor.e1.project(garotor.n ^ garotor.e2))
    raises(GA_ERR_SINGULAR, lambda: garotor.e1.reject(garotor.n))
    raises(GA_ERR_ARG, lambda: (1 + garotor.e1).apply(garotor.e2))
    raises(GA_ERR_ARG, M.dilation, [0, 0, 0], 0.0)
    raises(GA_ERR_ARG, M.dilation, [0, 0, 0], -2.0)
    raises(GA_ERR_DOMAIN, lambda: (1e200 * garotor.e12 + 1e200) ** 3)
    raises(GA_ERR_ARG, garotor.fit_sphere, np.zeros((3, 3)))
    raises(GA_ERR_ARG, garotor.fit_line, np.zeros((1, 3)))
    raises(GA_ERR_DOMAIN, garotor.fit_plane, [[0, 0, 0], [1, 1, 1], [2, 2, 2], [3, 3, 3]])
    raises(GA_ERR_DOMAIN, garotor.fit_sphere, [[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0], [2, 3, 0]])
    with pytest.raises(ValueError, match=r"\(n, 3\)"):
        garotor.fit_circle(np.zeros((5, 2)))
    with pytest.raises(TypeError):
        garotor.e1 ** 0.5
    with pytest.raises(ValueError, match="exponent"):
        garotor.e1 ** (10 ** 7)


def test_fits_name_every_bad_number():
    rng = np.random.default_rng(2509)
    pts = rng.normal(size=(6, 3))
    for fit in (garotor.fit_sphere, garotor.fit_plane, garotor.fit_circle, garotor.fit_line):
        fit(pts)  # the clean points succeed
        for i in range(6):
            for j in range(3):
                for bad in (np.nan, np.inf, -np.inf):
                    a = pts.copy()
                    a[i, j] = bad
                    msg = raises(GA_ERR_NOTFINITE, fit, a)
                    assert msg.endswith("points[%d, %d] is %s" % (i, j, bad)), msg


def test_not_finite():
    nan = float("nan")
    msg = raises(GA_ERR_NOTFINITE, garotor.fit_sphere, [[0, 0, 0], [1, 0, 0], [0, 1, nan], [0, 0, 1]])
    assert msg.endswith("points[2, 2] is nan"), msg
    msg = raises(GA_ERR_NOTFINITE, M.rotation, [0, float("inf"), 1], 1.0)
    assert msg.endswith("axis[1] is inf"), msg
    msg = raises(GA_ERR_NOTFINITE, M.dilation, [0, 0, 0], nan)
    assert msg.endswith("the number is nan"), msg
    raises(GA_ERR_NOTFINITE, M.translation, [nan, 0, 0])
    raises(GA_ERR_NOTFINITE, M.rotation([0, 0, 1], 1).pow, nan)
    raises(GA_ERR_NOTFINITE, garotor.e1.meet, nan)
    raises(GA_ERR_NOTFINITE, garotor.e1.object, [0, nan, 0])
    raises(GA_ERR_NOTFINITE, lambda: garotor.e1 & nan)
    raises(GA_ERR_NOTFINITE, lambda: nan / garotor.e1)


# ---- the session of docs/python.md ----------------------------------------------------------


def test_docs_session():
    """the ```pycon blocks of docs/python.md, replayed by doctest: each line
    shown is what the module prints"""
    doc = docpage.DOC
    blocks = docpage.blocks("pycon")
    # "Beyond one machine" starts a dask cluster: test_dask.py replays it
    blocks = [b for b in blocks if "garotor.dask" not in b]
    assert blocks, "docs/python.md shows no ```pycon session"
    parser, runner = doctest.DocTestParser(), doctest.DocTestRunner(optionflags=doctest.ELLIPSIS)
    for k, text in enumerate(blocks):
        test = parser.get_doctest(text, {}, "docs/python.md block %d" % (k + 1), str(doc), 0)
        runner.run(test)
    assert runner.failures == 0, "docs/python.md's pycon session prints differently now (see above)"
