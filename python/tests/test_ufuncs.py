"""garotor.ufunc (issue 30, item 1; docs/python.md, "Generalized ufuncs"):
numpy generalized ufuncs of the module's kernels. Their signatures through
numpy.ufunc's attributes; results equal to the module's own calls (and so
to C) bit for bit, in any layout, broadcast, cast, into out=;
the policy for a bad element (NaN and numpy's 'invalid' flag); pickling.
"""
import pickle
import warnings

import numpy as np
import pytest

import garotor
from garotor import Multivector as M
from garotor import ufunc as U

GROUPS = {"": "cga", "_matrix": "matrix", "_affine": "affine"}

# name: signature; every ufunc of garotor.ufunc is here
SIGNATURES = {
    "from_quat": "(4),(3)->(4,4)", "to_quat": "(4,4)->(4)", "from_pose": "(7)->(4,4)",
    "to_pose": "(n,4,4)->(n,7)", "to_dualquat": "(4,4)->(8)", "from_dualquat": "(8)->(4,4)",
    "up": "(3)->(32)", "down": "(32)->(3)", "mv_pow": "(32),()->(32)", "norm2": "(32)->()",
}
for sfx in ("", "_matrix"):
    SIGNATURES.update({"exp" + sfx: "(6)->(4,4)", "log" + sfx: "(4,4)->(6)", "compose" + sfx: "(4,4),(4,4)->(4,4)",
                       "inverse" + sfx: "(4,4)->(4,4)", "apply" + sfx: "(4,4),(3)->(3)"})
SIGNATURES.update({"exp_affine": "(4,4)->(4,4)", "log_affine": "(4,4)->(4,4)",
                   "compose_affine": "(4,4),(4,4)->(4,4)", "inverse_affine": "(4,4)->(4,4)",
                   "apply_affine": "(4,4),(3)->(3)"})
MV_BINARY = {"gp": lambda a, b: a * b, "op": lambda a, b: a ^ b, "lc": lambda a, b: a | b,
             "regressive": lambda a, b: a & b, "dot": M.dot, "ip": M.ip, "commutator": M.commutator,
             "meet": M.meet, "join": M.join, "meet_rel": M.meet_rel, "project": M.project,
             "reject": M.reject, "mv_apply": M.apply}
MV_UNARY = {"reverse": M.reverse, "involute": M.involute, "conjugate": M.conjugate, "dual": M.dual,
            "undual": M.undual, "mv_inverse": M.inverse, "mv_exp": M.exp, "mv_log": M.log, "mv_sqrt": M.sqrt}
SIGNATURES.update({k: "(32),(32)->(32)" for k in MV_BINARY})
SIGNATURES.update({k: "(32)->(32)" for k in MV_UNARY})


def same(a, b):
    """bit for bit, -0 and 0 told apart"""
    a, b = np.asarray(a), np.asarray(b)
    return a.dtype == b.dtype == np.float64 and a.shape == b.shape and a.tobytes() == b.tobytes()


def test_signatures():
    names = sorted(n for n in dir(U) if isinstance(getattr(U, n), np.ufunc))
    assert names == sorted(SIGNATURES)
    for name, sig in SIGNATURES.items():
        f = getattr(U, name)
        nin = sig.split("->")[0].count("(")
        assert f.__name__ == name and f.signature == sig, name
        assert (f.nin, f.nout, f.nargs) == (nin, 1, nin + 1), name
        assert f.types == ["d" * nin + "->d"], name
        assert f.__doc__ and name in f.__doc__


def motions(rng, shape):
    return garotor.exp(rng.normal(size=tuple(shape) + (6,)))


def affine(rng, shape):
    A = np.zeros(tuple(shape) + (4, 4))
    A[..., :3, :] = 0.3 * rng.normal(size=tuple(shape) + (3, 4))
    return A


def layouts(a):
    """a in other memory layouts, the same numbers"""
    yield a
    yield np.asfortranarray(a)
    big = np.zeros(a.shape[:-1] + (2 * a.shape[-1],))
    big[..., ::2] = a
    yield big[..., ::2]  # strided core
    yield np.flip(np.flip(a, 0).copy(), 0)  # negative strides
    yield a.astype(a.dtype.newbyteorder(">"))  # byte-swapped


def test_group_calls_equal_the_module_bit_for_bit(rng):
    for sfx, g in GROUPS.items():
        T = motions(rng, (4, 3)) if g != "affine" else garotor.exp(affine(rng, (4, 3)), "affine")
        xi = rng.normal(size=(4, 3, 6)) if g != "affine" else affine(rng, (4, 3))
        x = rng.normal(size=(3, 3))
        cases = [
            ("exp", (xi,), garotor.exp(xi, g)),
            ("log", (T,), garotor.log(T, g)),
            ("compose", (T, T[:1]), garotor.compose(T, T[:1], g)),
            ("inverse", (T,), garotor.inverse(T, g)),
            ("apply", (T, x), garotor.apply(T, x, g)),
        ]
        for name, args, want in cases:
            f = getattr(U, name + sfx)
            assert same(f(*args), want), name + sfx
            for a0 in layouts(args[0]):  # any layout of the first argument
                assert same(f(a0, *args[1:]), want), (name + sfx, a0.strides)


def test_conversions_equal_the_module_bit_for_bit(rng):
    T = motions(rng, (5, 6))
    q = garotor.to_quat(T)
    t = rng.normal(size=(6, 3))
    P = garotor.to_pose(T, continuous=False)
    D = garotor.to_dualquat(T)
    x = rng.normal(size=(2, 5, 3))
    X = garotor.up(x)
    assert same(U.from_quat(q, t), garotor.from_quat(q, t))
    assert same(U.to_quat(T), q)
    assert same(U.from_pose(P), garotor.from_pose(P))
    assert same(U.to_dualquat(T), D)
    assert same(U.from_dualquat(D), garotor.from_dualquat(D))
    assert same(U.up(x), X)
    assert same(U.down(X), garotor.down(X))
    # to_pose: continuous along the core dimension n, as garotor.to_pose along
    # the last leading one; a chain that flips the sign of w on its way
    chain = garotor.exp(np.outer(np.linspace(0, 3, 40), [0, 0, 2.5, 1, 0, 0]).reshape(2, 20, 6))
    want = garotor.to_pose(chain)
    assert np.any(want[..., 6] < 0)
    assert same(U.to_pose(chain), want)
    assert same(U.to_pose(np.asfortranarray(chain)), want)
    assert same(U.to_pose(T), garotor.to_pose(T))


def test_broadcast_cast_out(rng):
    A = motions(rng, (5, 1))
    B = motions(rng, (3,))
    want = garotor.compose(A, B)
    assert same(U.compose(A, B), want) and want.shape == (5, 3, 4, 4)
    # dtype casting by numpy's rules: float32 and integers in, float64 out
    xi32 = rng.normal(size=(4, 6)).astype(np.float32)
    assert same(U.exp(xi32), garotor.exp(xi32))
    ints = np.arange(12).reshape(2, 6) % 3
    assert same(U.exp(ints), garotor.exp(ints))
    assert same(U.exp([0, 0, 1, 0, 0, 1]), garotor.exp([0, 0, 1, 0, 0, 1]))
    # an object array is cast only when asked for (numpy's same_kind rule)
    obj = np.array([0, 0, 1, 0, 0, 1], dtype=object)
    with pytest.raises(TypeError):
        U.exp(obj)
    assert same(U.exp(obj, dtype=np.float64, casting="unsafe"), garotor.exp(obj))
    # out=, in any layout, and in place
    out = np.zeros((4, 4, 5, 3)).transpose(2, 3, 0, 1)
    r = U.compose(A, B, out=out)
    assert r is out and np.array_equal(out, want)
    T = motions(rng, (6,))
    want = garotor.inverse(T)
    U.inverse(T, out=T)
    assert same(T, want)
    # where= is not for generalized ufuncs (numpy's rule)
    with pytest.raises(TypeError, match="where"):
        U.exp(rng.normal(size=(4, 6)), where=True)
    xi = rng.normal(size=(4, 6))
    # a float32 out is filled by numpy's cast of the float64 results
    o32 = np.zeros((4, 4, 4), dtype=np.float32)
    U.exp(xi, out=o32)
    assert np.array_equal(o32, garotor.exp(xi).astype(np.float32))


def mvs(rng, n):
    return rng.normal(size=(n, 32))


def blades(rng, n):
    """objects: direct spheres, circles, lines, point pairs, and dual spheres"""
    out = []
    for k in range(n):
        P = [M.up(rng.normal(size=3)) for _ in range(4)]
        objs = [P[0] ^ P[1] ^ P[2] ^ P[3], P[0] ^ P[1] ^ P[2], P[0] ^ P[1] ^ garotor.n, P[0] ^ P[1],
                P[0] - 0.5 * garotor.n]
        out.append(np.asarray(objs[k % len(objs)]))
    return np.array(out)


def rotors(rng, n):
    return np.array([np.asarray(M.rotation(rng.normal(size=3), rng.uniform(0, 3)) *
                                M.translation(rng.normal(size=3))) for _ in range(n)])


def bivectors(rng, n):
    B = np.zeros((n, 32))
    B[:, 6:16] = rng.normal(size=(n, 10))
    return B


def multivector_inputs(rng, name, n):
    if name in ("join", "meet_rel", "project", "reject", "meet"):
        return blades(rng, n), blades(rng, n)
    if name == "mv_apply":
        return rotors(rng, n), blades(rng, n)
    if name == "mv_exp":
        return (bivectors(rng, n),)
    if name in ("mv_log", "mv_sqrt"):
        return (rotors(rng, n),)
    return (mvs(rng, n),) if name in MV_UNARY else (mvs(rng, n), mvs(rng, n))


def test_multivector_ufuncs_equal_multivector_bit_for_bit(rng):
    n = 12
    for name, fn in list(MV_BINARY.items()) + list(MV_UNARY.items()):
        args = multivector_inputs(rng, name, n)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", RuntimeWarning)  # a status is NaN here
            got = getattr(U, name)(*args)
        assert got.shape == (n, 32)
        ok = 0
        for i in range(n):
            try:
                want = np.asarray(fn(*[M(a[i]) for a in args]))
            except garotor.Error:
                assert np.all(np.isnan(got[i])), (name, i)
                continue
            assert same(got[i], want), (name, i)
            ok += 1
        assert ok >= n // 2, name  # most elements are good ones
    R = rotors(rng, n)
    t = rng.uniform(-2, 2, size=n)
    got = U.mv_pow(R, t)
    assert all(same(got[i], np.asarray(M(R[i]).pow(t[i]))) for i in range(n))
    X = mvs(rng, n)
    assert same(U.norm2(X), np.array([M(x).norm2() for x in X]))
    # broadcast: one multivector against many
    a = mvs(rng, 1)[0]
    B = mvs(rng, n)
    assert same(U.gp(a, B), np.array([np.asarray(M(a) * M(b)) for b in B]))


def test_bad_elements_are_nan_and_invalid(rng):
    T = motions(rng, (5,))
    T[2, 0, 0] = 3.0  # not rigid
    T[4, 1, 2] = np.nan
    good = garotor.log(T[[0, 1, 3]])
    with pytest.warns(RuntimeWarning, match="invalid value encountered in log"):
        r = U.log(T)
    assert same(r[[0, 1, 3]], good)
    assert np.all(np.isnan(r[[2, 4]]))
    with np.errstate(invalid="raise"):
        with pytest.raises(FloatingPointError, match="invalid value encountered in log"):
            U.log(T)
    with np.errstate(invalid="ignore"), warnings.catch_warnings():
        warnings.simplefilter("error")
        U.log(T)
    # the module's call names the first bad element instead
    with pytest.raises(garotor.Error, match="index 2: not a rigid motion"):
        garotor.log(T)
    # a result that would not be finite: NaN too
    with pytest.warns(RuntimeWarning, match="invalid value encountered in up"):
        r = U.up([[1e200, 0, 0], [1, 2, 3]])
    assert np.all(np.isnan(r[0])) and same(r[1], garotor.up([1, 2, 3]))
    # good elements raise no flag, whatever the kernels do inside: none is
    # reported with every error raising (underflow included)
    with np.errstate(all="raise"):
        for name, args in [("exp", (np.zeros((3, 6)),)), ("exp", (1e-300 * rng.normal(size=(3, 6)),)),
                           ("log", (np.broadcast_to(np.eye(4), (3, 4, 4)),)),
                           ("gp", (1e-200 * mvs(rng, 3), 1e-200 * mvs(rng, 3))),
                           ("mv_log", (rotors(rng, 3),))]:
            getattr(U, name)(*args)


def test_blocks_of_contiguous_elements(rng):
    """Contiguous operands take the loop's fast path (results straight to
    the output, checked for NaN and infinity 64 elements at a time): the
    numbers of the element-by-element path (a strided out=), bit for bit,
    bad elements in several blocks and at a block's edges."""
    n = 200
    T = motions(rng, (n,))
    for i in (0, 63, 64, 130):
        T[i, 0, 0] = 3.0  # not rigid: a status
    T[199, 1, 2] = np.nan
    X = rng.normal(size=(n, 3))
    X[[5, 127, 128]] = 1e200  # up: a result that would not be finite
    with np.errstate(invalid="ignore"):
        for name, args in [("log", (T,)), ("compose", (T, T[::-1])), ("up", (X,)),
                           ("exp", (rng.normal(size=(n, 6)),)), ("gp", (mvs(rng, n), mvs(rng, n)))]:
            fast = getattr(U, name)(*args)
            slow = np.full(fast.shape + (2,), 7.0)[..., 0]  # every number 16 bytes apart
            getattr(U, name)(*args, out=slow)
            assert same(fast, np.ascontiguousarray(slow)), name
    with np.errstate(invalid="ignore"):
        r = U.log(T)
    assert np.flatnonzero(np.isnan(r).all(axis=1)).tolist() == [0, 63, 64, 130, 199]
    good = np.setdiff1d(np.arange(n), [0, 63, 64, 130, 199])
    assert same(r[good], garotor.log(T[good]))
    with np.errstate(invalid="ignore"):
        r = U.up(X)
    assert np.flatnonzero(np.isnan(r).all(axis=1)).tolist() == [5, 127, 128]
    with pytest.warns(RuntimeWarning, match="invalid value encountered in compose"):
        U.compose(T, T)


def test_pickle_and_import():
    import garotor.ufunc as u2
    assert u2 is U
    for name in ("exp", "gp", "to_pose", "mv_apply"):
        f = getattr(U, name)
        assert pickle.loads(pickle.dumps(f)) is f


def test_axes_and_threads(rng):
    """axes= puts the core dimensions elsewhere; four threads on slices of one
    array (the GIL released around numpy's loop) give the serial result."""
    import threading

    xi = rng.normal(size=(5, 6))
    assert same(U.exp(xi.T, axes=[(0,), (1, 2)]), garotor.exp(xi))
    assert same(np.moveaxis(U.exp(xi.T, axes=[(0,), (0, 1)]), 2, 0), garotor.exp(xi))
    X, Y = rng.normal(size=(4000, 32)), rng.normal(size=(4000, 32))
    want = U.gp(X, Y)
    out = np.zeros_like(want)
    parts = np.array_split(np.arange(4000), 4)
    threads = [threading.Thread(target=lambda p=p: U.gp(X[p[0]:p[-1] + 1], Y[p[0]:p[-1] + 1],
                                                        out=out[p[0]:p[-1] + 1])) for p in parts]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert same(out, want)
    A, B = garotor.MultivectorArray(X), garotor.MultivectorArray(Y)
    assert same(np.asarray(A * B), want)


def test_dask_recipe(rng):
    """docs/python.md's recipe: apply_gufunc with named core dimensions, their
    sizes and the output's dtype runs a ufunc chunk by chunk, bit for bit."""
    da = pytest.importorskip("dask.array")
    from dask.array.gufunc import apply_gufunc

    xi = rng.normal(size=(100, 6))
    x = da.from_array(xi, chunks=(25, 6))
    T = apply_gufunc(U.exp, "(i)->(j,k)", x, output_dtypes=float, output_sizes={"j": 4, "k": 4})
    assert same(T.compute(scheduler="synchronous"), garotor.exp(xi))
