"""The module's edges (issue 26, docs/python.md): object arrays read as lists
are, NaN and infinity refused by every call with the index of the element,
results that would not be finite refused, Multivector's truth value, pickling
and copying of Path and Multivector, out= written in place, and the
benchmark's C loop on a bad element.
"""
import copy
import pickle
import subprocess
import sys
import tracemalloc
from decimal import Decimal
from fractions import Fraction

import numpy as np
import pytest

import garotor

GA_ERR_NOTFINITE = -1
GA_ERR_DOMAIN = -5
SCHEMES = ["screw", "bivector", "quadratic", "smooth", "lihao2", "lihao3", "decoupled", "decoupled-c2",
           "bspline", "c2"]
APPENDS = ["screw", "bivector", "lihao2", "decoupled", "bspline"]
GROUPS = ["cga", "matrix", "affine"]
RIGID_ONLY = ["decoupled", "decoupled-c2", "c2"]
N = 5  # elements in the arrays below
BAD = 3  # the element that gets the NaN


def rigid(rng, shape):
    return garotor.exp(rng.normal(size=tuple(shape) + (6,)))


def unit_quats(rng, n):
    q = rng.normal(size=(n, 4))
    return q / np.linalg.norm(q, axis=1)[:, None]


def affine_gens(rng, n):
    A = np.zeros((n, 4, 4))
    A[:, :3, :] = 0.3 * rng.normal(size=(n, 3, 4))
    return A


# ---- the calls that take arrays, each with one argument to spoil -------------

def array_calls(rng):
    """(label, argument name, its clean value, call): every array argument of
    every call of the module that takes arrays of elements (n, ...)."""
    T = rigid(rng, (N,))
    xi = rng.normal(size=(N, 6))
    x = rng.normal(size=(N, 3))
    q = unit_quats(rng, N)
    P = garotor.to_pose(T)
    D = garotor.to_dualquat(T)
    X = garotor.up(x)
    times = np.arange(4.0)
    K = rigid(rng, (4,))
    t = np.linspace(0.1, 2.9, N)
    path = garotor.Path(times, K)
    calls = []
    for g in GROUPS:
        if g == "affine":
            calls.append((f"exp/{g}", "xi", affine_gens(rng, N), lambda a, g=g: garotor.exp(a, g)))
        else:
            calls.append((f"exp/{g}", "xi", xi, lambda a, g=g: garotor.exp(a, g)))
        calls += [
            (f"log/{g}", "T", T, lambda a, g=g: garotor.log(a, g)),
            (f"compose/{g}:A", "A", T, lambda a, g=g: garotor.compose(a, T, g)),
            (f"compose/{g}:B", "B", T, lambda a, g=g: garotor.compose(T, a, g)),
            (f"inverse/{g}", "T", T, lambda a, g=g: garotor.inverse(a, g)),
            (f"apply/{g}:T", "T", T, lambda a, g=g: garotor.apply(a, x, g)),
            (f"apply/{g}:points", "points", x, lambda a, g=g: garotor.apply(T, a, g)),
        ]
    # the Jacobians (python/jacobian.c): twists, and rigid motions on cga and
    # matrix; a pair of Jacobians as one array of both's numbers
    def both(r):
        return np.concatenate([np.ravel(j) for j in r])

    calls += [(f, "xi", xi, getattr(garotor, f)) for f in ("jr", "jl", "jr_inverse", "jl_inverse", "ad")]
    XA = 0.1 * T.copy()  # affine algebra elements: a NaN in any of the 16 numbers, the last row's too
    XA[..., 3, :] = 0.0
    calls += [(f, "X", XA, getattr(garotor, f))
              for f in ("affine_jr", "affine_jl", "affine_jr_inverse", "affine_jl_inverse", "affine_ad")]
    for g in ("cga", "matrix", "affine"):
        calls += [
            (f"adjoint/{g}", "T", T, lambda a, g=g: garotor.adjoint(a, g)),
            (f"jac_compose/{g}:A", "A", T, lambda a, g=g: both(garotor.jac_compose(a, T, g))),
            (f"jac_compose/{g}:B", "B", T, lambda a, g=g: both(garotor.jac_compose(T, a, g, "left"))),
            (f"jac_inverse/{g}", "T", T, lambda a, g=g: garotor.jac_inverse(a, g)),
            (f"jac_between/{g}:A", "A", T, lambda a, g=g: both(garotor.jac_between(a, T, g, "left"))),
            (f"jac_between/{g}:B", "B", T, lambda a, g=g: both(garotor.jac_between(T, a, g))),
            (f"jac_act/{g}:T", "T", T, lambda a, g=g: both(garotor.jac_act(a, x, g))),
            (f"jac_act/{g}:points", "points", x, lambda a, g=g: both(garotor.jac_act(T, a, g, "left"))),
            (f"jac_log/{g}", "T", T, lambda a, g=g: garotor.jac_log(a, g)),
        ]
    calls += [
        ("from_quat:q", "q", q, lambda a: garotor.from_quat(a, x)),
        ("from_quat:t", "t", x, lambda a: garotor.from_quat(q, a)),
        ("to_quat", "T", T, garotor.to_quat),
        ("from_pose", "poses", P, garotor.from_pose),
        ("to_pose", "T", T, garotor.to_pose),
        ("to_pose/discontinuous", "T", T, lambda a: garotor.to_pose(a, continuous=False)),
        ("to_dualquat", "T", T, garotor.to_dualquat),
        ("from_dualquat", "d", D, garotor.from_dualquat),
        ("up", "x", x, garotor.up),
        ("down", "X", X, garotor.down),
        ("MultivectorArray", "c", X, lambda a: np.asarray(garotor.MultivectorArray(a))),
        ("Path.sample", "t", t, path.sample),
        ("Path.velocity", "t", t, path.velocity),
        ("Path.acceleration", "t", t, path.acceleration),
    ]
    return calls


def test_nan_named_by_index_in_every_array_call(rng):
    """A NaN (and an infinity) at a chosen element of any argument: garotor.Error
    naming the element's index, and the argument and position of the number."""
    calls = array_calls(rng)
    # every function of the module that takes arrays is in the table; the
    # fits take one set of points, not elements (test_objects.py spoils each
    # number of it), and Object is a type; object_mean takes Multivectors
    # (which hold no NaN) and its weights are spoiled in test_object_mean.py;
    # the trajectory calls take whole trajectories (test_trajectory.py spoils
    # a row and checks the array and row named)
    public = {n for n in dir(garotor) if not n.startswith("_") and callable(getattr(garotor, n))
              and n not in ("Error", "Path", "Multivector", "Object", "object_mean",
                            "evaluate", "ape", "rpe", "align", "fit")
              and not n.startswith("fit_")}
    covered = {label.split("/")[0].split(":")[0] for label, *_ in calls}
    assert public <= covered, public - covered
    for label, name, clean, call in calls:
        call(clean)  # the clean input succeeds
        core = clean[BAD].size
        for comp in range(core):  # every number of an element: none is passed over
            for bad in (np.nan, np.inf, -np.inf) if comp in (0, core - 1) else (np.nan,):
                a = clean.copy()
                a.reshape(N, core)[BAD, comp] = bad
                with pytest.raises(garotor.Error) as e:
                    call(a)
                pos = ", ".join(str(i) for i in np.unravel_index(BAD * core + comp, a.shape))
                want = f"index {BAD}: not finite (NaN or infinity): {name}[{pos}] is {bad!r}"
                assert want in str(e.value), (label, str(e.value))
                assert e.value.index == (BAD,) and e.value.status == GA_ERR_NOTFINITE, label


def test_nan_index_in_more_dimensions(rng):
    xi = rng.normal(size=(3, 4, 6))
    xi[1, 3, 2] = np.nan
    xi[2, 0, 0] = np.nan  # later: the first is named
    with pytest.raises(garotor.Error, match=r"^exp: index \(1, 3\): not finite \(NaN or infinity\): "
                       r"xi\[1, 3, 2\] is nan$") as e:
        garotor.exp(xi)
    assert e.value.index == (1, 3)
    # broadcast: the element of the result, and the argument's own position
    A = rigid(rng, (2, 1))
    B = rigid(rng, (3,))
    B[2, 1, 0] = np.inf
    with pytest.raises(garotor.Error, match=r"compose: index \(0, 2\): .*: B\[2, 1, 0\] is inf$"):
        garotor.compose(A, B)
    # a single element has no index
    with pytest.raises(garotor.Error, match=r"^up: not finite \(NaN or infinity\): x\[1\] is nan$") as e:
        garotor.up([0, np.nan, 0])
    assert e.value.index == ()
    p = garotor.Path([0.0, 1.0], rigid(rng, (2,)))
    with pytest.raises(garotor.Error, match=r"^Path.sample: not finite \(NaN or infinity\): t is nan$"):
        p.sample(np.nan)


def test_nan_in_path_construction_and_append(rng):
    times = np.arange(N, dtype=float)
    K = rigid(rng, (N,))
    V = rng.normal(size=(N, 6))
    cases = [
        ("times", times, lambda a: garotor.Path(a, K)),
        ("poses", K, lambda a: garotor.Path(times, a)),
        ("poses", garotor.to_pose(K), lambda a: garotor.Path(times, a)),
        ("poses", K, lambda a: garotor.Path(times, a, group="affine")),
        ("velocities", V, lambda a: garotor.Path(times, K, scheme="lihao3", velocities=a)),
        ("velocities", np.stack([garotor.exp(V[0], "matrix") * 0] * N),  # (n, 4, 4) velocities, affine
         lambda a: garotor.Path(times, K, scheme="lihao3", group="affine", velocities=a)),
    ]
    for name, clean, call in cases:
        call(clean)
        core = clean[BAD].size
        for comp in range(core):
            a = clean.copy()
            a.reshape(N, core)[BAD, comp] = np.nan
            with pytest.raises(garotor.Error) as e:
                call(a)
            pos = ", ".join(str(i) for i in np.unravel_index(BAD * core + comp, a.shape))
            assert str(e.value) == f"Path: {name}: index {BAD}: not finite (NaN or infinity): {name}[{pos}] is nan"
            assert e.value.index == (BAD,) and e.value.status == GA_ERR_NOTFINITE
    v0 = np.zeros(6)
    v0[4] = -np.inf
    with pytest.raises(garotor.Error, match=r"^Path: velocities: not finite \(NaN or infinity\): "
                       r"velocities\[4\] is -inf$"):
        garotor.Path(times, K, scheme="lihao2", velocities=v0)
    p = garotor.Path(times[:2], K[:2], capacity=4)
    with pytest.raises(garotor.Error, match=r"^Path.append: not finite \(NaN or infinity\): t is nan$") as e:
        p.append(np.nan, K[2])
    assert e.value.status == GA_ERR_NOTFINITE and e.value.index == ()
    bad = K[2].copy()
    bad[1, 3] = np.nan
    with pytest.raises(garotor.Error, match=r"^Path.append: not finite \(NaN or infinity\): "
                       r"pose\[1, 3\] is nan$"):
        p.append(2.0, bad)
    row = garotor.to_pose(K[2])
    row[6] = np.inf
    with pytest.raises(garotor.Error, match=r"pose\[6\] is inf$"):
        p.append(2.0, row)
    assert len(p.times) == 2


def test_nan_in_multivector(rng):
    c = rng.normal(size=32)
    for i in (0, 17, 31):
        bad = c.copy()
        bad[i] = np.nan
        with pytest.raises(garotor.Error, match=rf"^Multivector: not finite \(NaN or infinity\): c\[{i}\] is nan$") as e:
            garotor.Multivector(bad)
        assert e.value.status == GA_ERR_NOTFINITE and e.value.index == ()
    with pytest.raises(garotor.Error, match=r"^Multivector.up: not finite \(NaN or infinity\): x\[2\] is inf$"):
        garotor.Multivector.up([0, 0, np.inf])
    m = garotor.Multivector(c)
    nan = float("nan")
    ops = {
        "+": [lambda s: m + s, lambda s: s + m],
        "-": [lambda s: m - s, lambda s: s - m],
        "*": [lambda s: m * s, lambda s: s * m],
        "^": [lambda s: m ^ s, lambda s: s ^ m],
        "|": [lambda s: m | s, lambda s: s | m],
        "/": [lambda s: m / s],
        "dot": [lambda s: m.dot(s)],
        "ip": [lambda s: m.ip(s)],
    }
    for op, fs in ops.items():
        for f in fs:
            for s in (nan, np.float64(np.inf), -np.inf):
                with pytest.raises(garotor.Error, match=r": not finite \(NaN or infinity\): the number is") as e:
                    f(s)
                assert e.value.status == GA_ERR_NOTFINITE, op
                assert str(e.value).startswith(f"Multivector {op}:" if len(op) == 1 else f"Multivector.{op}:")
    # comparing is not computing: == with NaN is False, as for floats
    assert (m == nan) is False and (m != nan) is True


def test_results_that_would_not_be_finite(rng):
    """Finite input whose result overflows: garotor.Error 'outside the domain'
    naming the element, instead of an infinity in the result."""
    T = garotor.from_quat([0, 0, 0, 1], [1e308, 0, 0])
    x = np.zeros((3, 3))
    x[1, 0] = 1e308
    with pytest.raises(garotor.Error, match=r"^apply: index 1: outside the domain: the result would not be "
                       r"finite$") as e:
        garotor.apply(T, x)
    assert e.value.status == GA_ERR_DOMAIN and e.value.index == (1,)
    y = np.zeros((3, 3))
    y[2, 1] = 1e200
    with pytest.raises(garotor.Error, match=r"^up: index 2: outside the domain"):
        garotor.up(y)
    big = 1e200 * garotor.e1
    for f in (lambda: big * big, lambda: big * 1e200, lambda: (1e308 * garotor.e1) + (1e308 * garotor.e1),
              lambda: garotor.e1 / 1e-320, big.norm2, lambda: big.dot(big)):
        with pytest.raises(garotor.Error, match="outside the domain: the result would not be finite") as e:
            f()
        assert e.value.status == GA_ERR_DOMAIN


# ---- object arrays -------------------------------------------------------------

def as_objects(a, kinds):
    """a as an object array whose elements cycle through kinds of number."""
    o = np.empty(a.shape, dtype=object)
    flat = o.reshape(-1)
    for i, v in enumerate(a.reshape(-1)):
        flat[i] = kinds[i % len(kinds)](v)
    return o


def test_object_arrays_read_as_lists(rng):
    kinds = [float, np.float64, lambda v: Fraction(float(v)),
             lambda v: Decimal(float(v))]
    for label, name, clean, call in array_calls(rng):
        o = as_objects(clean, kinds)
        want = call(np.asarray(o.tolist(), dtype=float))
        got = call(o)
        assert got.dtype == np.float64 and got.tobytes() == want.tobytes(), label
        assert call(o.tolist()).tobytes() == want.tobytes(), label
    # integers and booleans, as in a list
    ints = np.array([0, 0, 1, 2, True, 0], dtype=object)
    assert garotor.exp(ints).tobytes() == garotor.exp([0, 0, 1, 2, True, 0]).tobytes()
    # None is NaN in a list and in an object array alike
    with pytest.raises(garotor.Error, match=r"index 1: not finite \(NaN or infinity\): xi\[1, 0\] is nan"):
        garotor.exp(np.array([[0] * 6, [None] + [0] * 5], dtype=object))
    with pytest.raises(garotor.Error, match=r"index 1: not finite \(NaN or infinity\): xi\[1, 0\] is nan"):
        garotor.exp([[0] * 6, [None] + [0] * 5])
    # what a list refuses, an object array refuses the same way
    for junk in (1j, "one", [1, 2]):
        with pytest.raises((TypeError, ValueError)) as e_list:
            garotor.exp([junk, 0, 0, 0, 0, 0])
        with pytest.raises(type(e_list.value)):
            garotor.exp(np.array([junk, 0, 0, 0, 0, 0], dtype=object)
                        if not isinstance(junk, list) else _object_row(junk))
    # a non-contiguous object array, and an object array as out is refused
    o = as_objects(rng.normal(size=(6, 8)), kinds)
    assert garotor.exp(o.T).tobytes() == garotor.exp(np.asarray(o.T.tolist(), dtype=float)).tobytes()
    with pytest.raises(TypeError, match="out must have dtype float64"):
        garotor.exp(np.zeros(6), out=np.empty((4, 4), dtype=object))


def _object_row(junk):
    r = np.empty(6, dtype=object)
    r[:] = 0
    r[0] = junk
    return r


def test_object_arrays_in_path_and_multivector(rng):
    kinds = [float, Fraction, Decimal, int]
    times = np.arange(5.0)
    K = rigid(rng, (5,))
    V = rng.normal(size=(5, 6))
    ref = garotor.Path(times, K, scheme="lihao3", velocities=V)
    p = garotor.Path(as_objects(times, kinds), as_objects(K, [float, Fraction]), scheme="lihao3",
                     velocities=as_objects(V, [Decimal, float]))
    t = np.linspace(0, 4, 33)
    assert p.sample(t).tobytes() == ref.sample(t).tobytes()
    q = garotor.Path(times[:2], K[:2], capacity=3)
    q.append(2.0, as_objects(K[2], [Fraction]))
    r = garotor.Path(times[:3], K[:3])
    assert q.sample(t[t <= 2]).tobytes() == r.sample(t[t <= 2]).tobytes()
    c = rng.normal(size=32)
    assert garotor.Multivector(as_objects(c, [Fraction, float])) == garotor.Multivector(c)
    x = rng.normal(size=3)
    assert garotor.Multivector.up(as_objects(x, [Decimal])) == garotor.Multivector.up(x)


# ---- Multivector's truth value ----------------------------------------------------

def test_multivector_bool():
    assert not garotor.Multivector()
    assert not garotor.Multivector(np.zeros(32))
    assert not garotor.Multivector(-np.zeros(32))  # -0 is zero
    assert not (garotor.e1 - garotor.e1)
    assert not (garotor.n * garotor.n)
    assert garotor.e1 and garotor.e12345 and garotor.Multivector.blade(0)
    tiny = np.zeros(32)
    tiny[31] = 5e-324
    assert garotor.Multivector(tiny)
    assert bool(garotor.Multivector(tiny)) is True and bool(garotor.Multivector()) is False


# ---- pickling and copying ------------------------------------------------------------

def test_multivector_pickle_and_copy(rng):
    c = rng.normal(size=32)
    c[3] = -0.0
    c[5] = 5e-324
    m = garotor.Multivector(c)
    for proto in range(pickle.HIGHEST_PROTOCOL + 1):
        m2 = pickle.loads(pickle.dumps(m, protocol=proto))
        assert type(m2) is garotor.Multivector
        assert np.asarray(m2).tobytes() == np.asarray(m).tobytes(), proto
    for m2 in (copy.copy(m), copy.deepcopy(m), copy.deepcopy([m, m])[1]):
        assert np.asarray(m2).tobytes() == np.asarray(m).tobytes()
    assert pickle.loads(pickle.dumps(garotor.Multivector())) == 0


def some_paths(rng):
    """(label, path) over every scheme and group, with velocities given, and
    grown by append to part of a capacity."""
    out = []
    for group in GROUPS:
        for scheme in SCHEMES:
            if group == "affine" and scheme in RIGID_ONLY:
                continue
            n = 3 if scheme == "quadratic" else 6
            times = np.concatenate([[0.0], np.cumsum(rng.uniform(0.5, 1.5, size=n - 1))])
            if scheme == "bspline":
                times = 0.5 * np.arange(n)
            K = rigid(rng, (n,)) if group != "affine" else garotor.exp(0.4 * rng.normal(size=(n, 6)))
            out.append((f"{scheme}/{group}", garotor.Path(times, K, scheme=scheme, group=group)))
            if scheme in APPENDS:
                first = 4 if scheme == "bspline" else 2
                grown = garotor.Path(times[:first], K[:first], scheme=scheme, group=group, capacity=n + 3)
                for i in range(first, n):
                    grown.append(times[i], K[i])
                out.append((f"{scheme}/{group}/grown", grown))
        times = np.arange(4.0)
        K = garotor.exp(0.4 * rng.normal(size=(4, 6)))
        V = rng.normal(size=(4, 6))
        out.append((f"lihao3/{group}/velocities",
                    garotor.Path(times, K, scheme="lihao3", group=group, velocities=V)))
        l2 = garotor.Path(times[:1], K[:1], scheme="lihao2", group=group, velocities=V[0], capacity=4)
        for i in range(1, 4):
            l2.append(times[i], K[i])
        out.append((f"lihao2/{group}/v0/grown", l2))
        out.append((f"screw/{group}/one", garotor.Path(times[:1], K[:1], group=group)))
    out.append(("screw/cga/poses", garotor.Path(np.arange(3.0), garotor.to_pose(rigid(rng, (3,))))))
    return out


def samples(p):
    t0, t1 = p.range
    t = np.concatenate([np.linspace(t0, t1, 41), p.times[(p.times >= t0) & (p.times <= t1)]])
    return b"".join(f(t).tobytes() for f in (p.sample, p.velocity, p.acceleration))


def attributes(p):
    return (p.scheme, p.group, p.capacity, p.range, p.times.tobytes())


def test_path_pickle_and_copy(rng):
    paths = some_paths(rng)
    assert len(paths) > 30
    for label, p in paths:
        want = samples(p), attributes(p)
        for proto in range(pickle.HIGHEST_PROTOCOL + 1):
            q = pickle.loads(pickle.dumps(p, protocol=proto))
            assert type(q) is garotor.Path and q is not p
            assert (samples(q), attributes(q)) == want, (label, proto)
        for q in (copy.copy(p), copy.deepcopy(p)):
            assert (samples(q), attributes(q)) == want, label


def test_path_pickle_in_another_process(rng):
    """Unpickled where no pointer of this process means anything (as a Dask
    worker would): the same samples, bit for bit."""
    paths = some_paths(rng)
    blob = pickle.dumps(paths, protocol=pickle.HIGHEST_PROTOCOL)
    script = ("import pickle, sys\n"
              "import numpy as np\n"
              "import garotor\n"
              f"sys.path.insert(0, {repr(__file__.rsplit('/', 1)[0])})\n"
              "from test_edges import samples, attributes\n"
              "paths = pickle.loads(sys.stdin.buffer.read())\n"
              "sys.stdout.buffer.write(pickle.dumps([(l, samples(p), attributes(p)) for l, p in paths]))\n")
    r = subprocess.run([sys.executable, "-c", script], input=blob, capture_output=True, check=True)
    there = pickle.loads(r.stdout)
    assert [(l, samples(p), attributes(p)) for l, p in paths] == there


def test_path_copy_is_independent(rng):
    times = np.arange(6.0)
    K = rigid(rng, (6,))
    p = garotor.Path(times[:3], K[:3], capacity=6)
    q = copy.copy(p)
    q.append(times[3], K[3])
    assert len(p.times) == 3 and len(q.times) == 4
    p.append(times[3], K[4])  # another key: the two differ from here
    assert not np.array_equal(p.sample(3.0), q.sample(3.0))
    r = copy.deepcopy(q)
    r.append(times[4], K[4])
    q.append(times[4], K[4])
    assert samples(r) == samples(q)
    assert q.capacity == r.capacity == 6


def test_path_pickle_state_is_checked(rng):
    p = garotor.Path(np.arange(3.0), rigid(rng, (3,)))
    with pytest.raises(ValueError, match="not initialised"):
        pickle.dumps(garotor.Path.__new__(garotor.Path))
    with pytest.raises(TypeError, match="already initialised"):
        p.__setstate__(p.__reduce__()[2])
    state = p.__reduce__()[2]
    blank = garotor.Path.__new__(garotor.Path)
    bad_key = list(state)
    keys = np.array(state[3])
    keys[1, 0] += 0.5  # no longer a rotor
    bad_key[3] = keys
    with pytest.raises(ValueError, match=r"Path: state: keys: index 1: not a rigid motion"):
        blank.__setstate__(tuple(bad_key))
    with pytest.raises(ValueError, match="Path: state"):
        blank.__setstate__(state[:3])
    with pytest.raises(ValueError, match="Path: state: keys must have shape"):
        blank.__setstate__(state[:3] + (np.zeros((3, 3)),) + state[4:])
    blank.__setstate__(state)
    assert samples(blank) == samples(p)


# ---- out= in place -----------------------------------------------------------------

def peak_during(f):
    tracemalloc.start()
    try:
        tracemalloc.reset_peak()
        before, _ = tracemalloc.get_traced_memory()
        f()
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    return peak - before


def test_out_written_in_place(rng):
    """No full-size temporary: the call with out= allocates a small fraction of
    out's size (before: a result of out's size, copied into out)."""
    n = 100_000
    T = rigid(rng, (n,))
    xi = rng.normal(size=(n, 6))
    x = rng.normal(size=(n, 3))
    p = garotor.Path(np.arange(4.0), rigid(rng, (4,)))
    t = np.linspace(0, 3, n)
    cases = [
        (lambda o: garotor.log(T, out=o), (n, 6)),
        (lambda o: garotor.exp(xi, out=o), (n, 4, 4)),
        (lambda o: garotor.apply(T[0], x, out=o), (n, 3)),
        (lambda o: garotor.to_pose(T, out=o), (n, 7)),
        (lambda o: p.sample(t, out=o), (n, 4, 4)),
        (lambda o: garotor.up(x, out=o), (n, 32)),
    ]
    for call, shape in cases:
        out = np.empty(shape)
        want = call(None)
        grew = peak_during(lambda: call(out))
        assert grew < out.nbytes / 100, (shape, grew, out.nbytes)
        assert out.tobytes() == want.tobytes()


def test_out_layouts_and_overlap(rng):
    n = 40
    T = rigid(rng, (n,))
    want = garotor.inverse(T)
    # non-contiguous, Fortran-ordered, byte-swapped and unaligned out
    outs = [np.zeros((4, 4, n)).transpose(2, 0, 1), np.asfortranarray(np.zeros((n, 4, 4))),
            np.zeros((n, 4, 4), dtype=">f8"),
            np.ndarray((n, 4, 4), dtype=float, buffer=bytearray(8 * 16 * n + 1), offset=1)]
    assert not outs[3].flags.aligned
    for o in outs:
        r = garotor.inverse(T, out=o)
        assert r is o and np.array_equal(o, want)
    # out is an input: each element is read before its result is written
    A = T.copy()
    assert garotor.inverse(A, out=A) is A and A.tobytes() == want.tobytes()
    A = T.copy()
    garotor.compose(A, A, out=A)
    assert A.tobytes() == garotor.compose(T, T).tobytes()
    x = rng.normal(size=(n, 3))
    y = x.copy()
    garotor.apply(T, y, out=y)
    assert y.tobytes() == garotor.apply(T, x).tobytes()
    # out overlaps an input shifted or reversed: the input is read as it was
    big = rng.normal(size=(n + 1, 3))
    ref = garotor.apply(T, big[1:].copy())
    garotor.apply(T, big[1:], out=big[:-1])
    assert big[:-1].tobytes() == ref.tobytes()
    B = T.copy()
    garotor.inverse(B, out=B[::-1])
    assert np.array_equal(B[::-1], want)
    # a broadcast input that out overwrites: row 0 of out is the point
    z = np.zeros((n, 3))
    z[0] = [1, 2, 3]
    ref = garotor.apply(T, np.array([1.0, 2, 3]))
    garotor.apply(T, z[:1], out=z)
    assert z.tobytes() == ref.tobytes()


def test_out_on_error_holds_the_elements_before(rng):
    """An error at element k: out holds the results of the elements before k
    (in C order), and is untouched from k on."""
    T = rigid(rng, (10,))
    T[6, 0, 0] = 2.0
    out = np.full((10, 6), 7.0)
    with pytest.raises(garotor.Error, match="index 6"):
        garotor.log(T, out=out)
    assert out[:6].tobytes() == garotor.log(T[:6]).tobytes()
    assert np.all(out[6:] == 7.0)
