"""Issue 30 (docs/python.md): Path.sample at times in any order (the results
those of one call per time, bit for bit, the errors and `out` of C order),
four threads on one Path, the module's version and what it ships (no benchmark helper), and
the benchmark's C loop (_garotor_bench, built beside the module only)."""
import concurrent.futures
import pathlib
import re

import numpy as np
import pytest

import garotor

SCHEMES = ["screw", "bivector", "lihao3", "decoupled", "bspline", "c2"]


def one_by_one(p, t):
    """p.sample element by element in C order: the reference."""
    flat = np.ravel(t)
    return np.array([p.sample(x) for x in flat]).reshape(np.shape(t) + (4, 4))


@pytest.mark.parametrize("scheme", SCHEMES)
def test_sample_any_order_bit_for_bit(rng, scheme):
    times = np.arange(40.0) * 0.5
    p = garotor.Path(times, garotor.exp(rng.normal(size=(40, 6))), scheme=scheme)
    t0, t1 = p.range
    # shuffled times, a 2-d shape, repeats, the ends
    t = rng.uniform(t0, t1, size=(3, 1500))
    t[0, :5] = [t1, t0, t1, t0, t1]
    want = one_by_one(p, t)
    assert p.sample(t).tobytes() == want.tobytes()
    assert p.sample(np.sort(t, axis=None).reshape(t.shape)).tobytes() == \
        want.reshape(-1, 4, 4)[np.argsort(t, axis=None, kind="stable")].reshape(want.shape).tobytes()
    out = np.full(t.shape + (4, 4), 7.0)
    assert p.sample(t, out=out) is out and out.tobytes() == want.tobytes()
    # an out in Fortran order: the same numbers
    outf = np.asfortranarray(np.full(t.shape + (4, 4), 7.0))
    assert np.array_equal(p.sample(t, out=outf), want)


def test_sample_any_order_errors_as_before(rng):
    """A time outside the range, or NaN: the error of C order, naming the
    first bad element in C order, with `out` holding the elements before it."""
    p = garotor.Path(np.arange(5.0), garotor.exp(rng.normal(size=(5, 6))))
    t = rng.uniform(0, 4, size=100)
    t[[30, 70]] = [9.0, -1.0]
    out = np.full((100, 4, 4), 7.0)
    with pytest.raises(garotor.Error, match=r"^Path.sample: index 30: invalid argument: t = 9.0 is outside") as e:
        p.sample(t, out=out)
    assert e.value.index == (30,)
    assert out[:30].tobytes() == one_by_one(p, t[:30]).tobytes() and np.all(out[30:] == 7.0)
    t[30] = np.nan
    with pytest.raises(garotor.Error, match=r"^Path.sample: index 30: not finite .*t\[30\] is nan"):
        p.sample(t)


def test_four_threads_one_path(rng):
    """Four threads sample one Path at once (the GIL released in the loop,
    the Path's lock shared): each gets the serial result, bit for bit."""
    times = np.cumsum(rng.uniform(0.5, 1.5, size=300))
    p = garotor.Path(times, garotor.exp(rng.normal(size=(300, 6))), scheme="lihao3")
    ts = [rng.uniform(times[0], times[-1], size=20000) for _ in range(8)]
    ts[1] = np.sort(ts[1])
    serial = [(p.sample(t), p.velocity(t), p.acceleration(t)) for t in ts]

    def work(k):
        t = ts[k]
        return p.sample(t), p.velocity(t), p.acceleration(t)

    with concurrent.futures.ThreadPoolExecutor(max_workers=4) as ex:
        got = list(ex.map(work, range(len(ts))))
    for g, s in zip(got, serial):
        for a, b in zip(g, s):
            assert a.tobytes() == b.tobytes()


def test_version_is_the_librarys():
    """garotor.__version__ is GAROTOR_VERSION_STRING, meson.build's project
    version (pyproject.toml takes it from there: dynamic)."""
    root = pathlib.Path(__file__).resolve().parents[2]
    want = re.search(r"^\s*version\s*:\s*'([0-9.]+)'", (root / "meson.build").read_text(), re.M).group(1)
    assert garotor.__version__ == want
    py = (root / "pyproject.toml").read_text()
    assert re.search(r"^dynamic = \['version'\]", py, re.M) and not re.search(r"^version\s*=", py, re.M)


def test_shipped_module_has_no_benchmark_helper():
    assert not hasattr(garotor, "_c_loop") and not hasattr(garotor._garotor, "_c_loop")
    names = [n for n in dir(garotor._garotor) if not n.startswith("__")]
    assert all(not n.startswith("_") for n in names), names


def test_bench_c_loop(rng):
    """python/bench.py's reference loop, built beside the module only."""
    b = pytest.importorskip("_garotor_bench", reason="_garotor_bench is built in the build tree only")
    x = rng.normal(size=(5, 6))
    assert b.c_loop("exp", x) >= 0
    x[2, 1] = np.nan
    with pytest.raises(ValueError, match=r"^c_loop: index 2: not finite"):
        b.c_loop("exp", x)
    T = garotor.exp(rng.normal(size=(4, 6)))
    T[3, 0, 0] = 2
    with pytest.raises(ValueError, match=r"^c_loop: index 3: not a rigid motion"):
        b.c_loop("log", T)
    assert b.c_loop("compose", T[:3], T[2::-1]) >= 0
    with pytest.raises(ValueError, match=r"^c_loop: index 2: not a rigid motion"):
        b.c_loop("compose", T[1:], T[:3])
    K = garotor.exp(rng.normal(size=(3, 6)))
    assert b.c_loop("sample", np.array([0.5, 1.5]), np.arange(3.0), K) >= 0
    with pytest.raises(ValueError, match=r"^c_loop: index 1: invalid argument"):
        b.c_loop("sample", np.array([0.5, 9.0]), np.arange(3.0), K)
    P, V = np.asarray(garotor.up(rng.normal(size=(4, 3)))), np.asarray(garotor.Multivector.translation([1, 2, 3]))
    assert b.c_loop("apply", P, V) >= 0 and b.c_loop("apply_many", P, V) >= 0
    V[1] = 1.0  # even and odd parts
    with pytest.raises(ValueError, match=r"^c_loop: index 0: invalid argument"):
        b.c_loop("apply", P, V)
    with pytest.raises(ValueError, match=r"^c_loop: index 0: invalid argument"):
        b.c_loop("apply_many", P, V)
