"""Path(..., scheme="bspline"): the uniform cumulative cubic B-spline
(docs/schemes.md): against a reference written here with scipy's expm/logm,
the tool, finite differences, and its errors."""
import numpy as np
import pytest
from scipy.linalg import expm, logm

import garotor


def even_keys(rng, n, h=0.5, t0=0.0):
    # each key a moderate step from the one before (rotations below pi, so
    # logm's principal log is the library's)
    times = t0 + h * np.arange(n)
    steps = garotor.exp(0.6 * rng.normal(size=(n, 6)))
    K = np.empty((n, 4, 4))
    K[0] = steps[0]
    for i in range(1, n):
        K[i] = K[i - 1] @ steps[i]
    return times, K


def reference(times, K, t):
    """A(t) = A_s exp(b1 d1) exp(b2 d2) exp(b3 d3) with 4x4 expm/logm."""
    h = times[1] - times[0]
    s = min(int(np.floor((t - times[1]) / h)), len(times) - 4)
    u = (t - times[s + 1]) / h
    b = [(5 + 3 * u - 3 * u**2 + u**3) / 6, (1 + 3 * u + 3 * u**2 - 2 * u**3) / 6, u**3 / 6]
    A = K[s].copy()
    for j in range(3):
        d = np.real(logm(np.linalg.inv(K[s + j]) @ K[s + j + 1]))
        A = A @ expm(b[j] * d)
    return A


@pytest.mark.parametrize("group", ["cga", "matrix"])
def test_bspline_equals_reference(rng, group):
    times, K = even_keys(rng, 7)
    p = garotor.Path(times, K, scheme="bspline", group=group)
    assert p.range == (times[1], times[-2])
    t = np.linspace(times[1], times[-2], 41)
    got = p.sample(t)
    want = np.array([reference(times, K, x) for x in t])
    assert np.abs(got - want).max() <= 1e-12 * max(1.0, np.abs(want).max())


def test_bspline_equals_tool(tool, rng):
    times, K = even_keys(rng, 6)
    p = garotor.Path(times, K, scheme="bspline")
    t = np.linspace(times[1], times[-2], 23)
    at = ",".join("%.17g" % v for v in t)
    out = tool(["interp", "--scheme", "bspline", "--at", at, "--with", "velocity,acceleration"],
               np.column_stack([times, K.reshape(-1, 16)]))
    assert np.array_equal(p.sample(t).reshape(-1, 16), out[:, 1:17])
    assert np.array_equal(p.velocity(t), out[:, 17:23])
    assert np.array_equal(p.acceleration(t), out[:, 23:29])


def test_bspline_derivatives(rng):
    times, K = even_keys(rng, 8, h=0.3, t0=2.0)
    pc = garotor.Path(times, K, scheme="bspline", group="cga")
    pm = garotor.Path(times, K, scheme="bspline", group="matrix")
    t = rng.uniform(times[1] + 1e-3, times[-2] - 1e-3, size=40)
    e = 1e-5
    rel = garotor.compose(garotor.inverse(pc.sample(t - e)), pc.sample(t + e))
    fd_v = garotor.log(rel) / (2 * e)
    v, a = pc.velocity(t), pc.acceleration(t)
    scale = np.abs(v).max()
    assert np.abs(v - fd_v).max() <= 1e-7 * scale
    fd_a = (pc.velocity(t + e) - pc.velocity(t - e)) / (2 * e)
    assert np.abs(a - fd_a).max() <= 1e-7 * scale / 0.3
    # cga and matrix: the same path to 1e-12 of its scales
    assert np.abs(pc.sample(t) - pm.sample(t)).max() <= 1e-12 * max(1.0, np.abs(K).max())
    assert np.abs(v - pm.velocity(t)).max() <= 1e-12 * scale
    assert np.abs(a - pm.acceleration(t)).max() <= 1e-12 * scale / 0.3


def test_bspline_errors(rng):
    times, K = even_keys(rng, 5)
    with pytest.raises(ValueError, match="needs one key or at least 4, got 3"):
        garotor.Path(times[:3], K[:3], scheme="bspline")
    uneven = times.copy()
    uneven[2] += 1e-6
    with pytest.raises(ValueError, match="evenly spaced times.*index 2"):
        garotor.Path(uneven, K, scheme="bspline")
    p = garotor.Path(times, K, scheme="bspline")
    with pytest.raises(ValueError, match="index 0: invalid argument"):
        p.sample([times[0]])
    with pytest.raises(ValueError, match="index 1: invalid argument"):
        p.velocity([times[1], times[-1]])
