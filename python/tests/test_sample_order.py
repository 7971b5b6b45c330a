"""Path.sample at times in any order (issue 30, item 5): the samples are
ga_path_sample's on blocks of times (interp/step.c locates a block at once),
the same numbers bit for bit as each time sampled alone, whatever the order:
shuffled, sorted, repeated, at the keys and the range's ends, with out= and
without, in any shape; a time outside the range is named by its flat index
as before, out= holding the samples before it. (Path.sample has no extrapolation
mode: a time outside the range is an error in every order.)"""
import numpy as np
import pytest

import garotor

SCHEMES = ["screw", "lihao3", "bivector", "smooth", "decoupled", "c2", "bspline"]


def build(rng, scheme, group="cga", n=41):
    if scheme == "bspline":  # evenly spaced keys
        times = 1.2 + 0.5 * np.arange(n)
    else:
        times = 1.2 + np.cumsum(rng.uniform(0.2, 1.8, size=n))
    K = garotor.exp(rng.normal(size=(n, 6)) * 0.7)
    return garotor.Path(times, K, scheme=scheme, group=group), times


def order_times(rng, p, times, m=2000):
    """m times inside the range, shuffled: the keys inside it, the ends and
    their neighbours, repeats, and times drawn uniformly."""
    t0, t1 = p.range
    k = times[(times >= t0) & (times <= t1)]
    edge = [t0, t1, np.nextafter(t0, np.inf), np.nextafter(t1, -np.inf)]
    u = rng.uniform(t0, t1, size=m - len(k) - len(edge) - 300)
    t = np.concatenate([k, edge, u])
    t = np.concatenate([t, rng.choice(t, size=300)])  # repeats
    return rng.permutation(t)


def one_by_one(p, t):
    return np.array([p.sample(float(x)) for x in t.ravel()]).reshape(t.shape + (4, 4))


@pytest.mark.parametrize("group", ["cga", "affine"])
@pytest.mark.parametrize("scheme", SCHEMES)
def test_any_order_bit_for_bit(scheme, group):
    rng = np.random.default_rng(3030)
    if scheme in ("decoupled", "c2") and group == "affine":
        pytest.skip("not defined on affine")
    p, times = build(rng, scheme, group)
    t = order_times(rng, p, times)
    want = one_by_one(p, t)
    assert np.array_equal(p.sample(t), want)
    s = np.sort(t)
    assert np.array_equal(p.sample(s), one_by_one(p, s))
    out = np.full((len(t), 4, 4), 7.0)
    assert p.sample(t, out=out) is out and np.array_equal(out, want)
    t2 = t[:1998].reshape(2, 37, 27)  # leading dimensions, in C order
    assert np.array_equal(p.sample(t2), want[:1998].reshape(2, 37, 27, 4, 4))
    assert np.array_equal(p.sample(t[::-1]), want[::-1])  # not contiguous
    assert np.array_equal(p.sample(t[5]), want[5])


def test_nanosecond_times_any_order():
    """int64 nanoseconds, read relative to the first key, then sampled in
    blocks: the same as one at a time."""
    rng = np.random.default_rng(3031)
    stamps = 1_700_000_000_000_000_000 + np.cumsum(rng.integers(10**8, 10**9, size=30)).astype(np.int64)
    p = garotor.Path(stamps, garotor.exp(rng.normal(size=(30, 6))), scheme="screw", time_unit="ns")
    t = rng.integers(stamps[0], stamps[-1], size=1000).astype(np.int64)
    t[::7] = stamps[rng.integers(0, 30, size=len(t[::7]))]
    want = np.array([p.sample(np.int64(x)) for x in t])
    assert np.array_equal(p.sample(t), want)
    assert np.array_equal(p.sample(np.sort(t)), want[np.argsort(t, kind="stable")])


@pytest.mark.parametrize("where", [0, 63, 64, 127, 128, 1500, 1999])
@pytest.mark.parametrize("bad", ["above", "below", "nan"])
def test_outside_named_in_any_order(where, bad):
    """A time outside the range, at a block's edge or inside one: the error
    names its flat index, as element by element; out= holds the samples
    before it, and from it on is left as it was."""
    rng = np.random.default_rng(3032)
    p, times = build(rng, "screw")
    t0, t1 = p.range
    t = order_times(rng, p, times)
    t[where] = {"above": np.nextafter(t1, np.inf), "below": t0 - 1.0, "nan": np.nan}[bad]
    out = np.full((len(t), 4, 4), 5.0)
    msg = "not finite" if bad == "nan" else "outside the path's range"
    with pytest.raises(ValueError, match=r"Path.sample: index %d: .*%s" % (where, msg)) as e:
        p.sample(t, out=out)
    assert e.value.index == (where,)
    assert np.array_equal(out[:where], one_by_one(p, t[:where])) and np.all(out[where:] == 5.0)
    with pytest.raises(ValueError, match=r"Path.sample: index %d: " % where):
        p.sample(t)  # the result made by the call
