"""Path.velocity, Path.acceleration and Path.jerk in the three frames
(frame='body', 'spatial', 'world'): equal to the tool's --with
velocity,acceleration,jerk --frame F columns bit for bit, and the world
frame's position derivatives against differences of the sampled positions.
"""
import numpy as np
import pytest

import garotor

SCHEMES = ["screw", "bivector", "quadratic", "smooth", "lihao2", "lihao3", "decoupled", "decoupled-c2",
           "bspline", "c2"]
FRAMES = ["body", "spatial", "world"]


def keys(rng, scheme, n):
    # the first key at t = 0, so that the tool's relative times are the Path's
    # (test_garotor.keys_for); bspline: evenly spaced
    if scheme == "bspline":
        times = 0.75 * np.arange(n)
    else:
        times = np.concatenate([[0.0], np.cumsum(rng.uniform(0.5, 1.5, size=n - 1))])
    return times, garotor.exp(0.8 * rng.normal(size=(n, 6)))


@pytest.mark.parametrize("frame", FRAMES)
@pytest.mark.parametrize("scheme", SCHEMES)
def test_derivatives_equal_tool(tool, rng, scheme, frame):
    n = 3 if scheme == "quadratic" else 6
    times, K = keys(rng, scheme, n)
    p = garotor.Path(times, K, scheme=scheme)
    t0, t1 = p.range
    t = np.concatenate([np.sort(rng.uniform(t0, t1, size=25)), [t0, t1]])
    at = ",".join("%.17g" % v for v in t)
    out = tool(["interp", "--scheme", scheme, "--at", at, "--with", "velocity,acceleration,jerk",
                "--frame", frame], np.column_stack([times, K.reshape(n, 16)]))
    assert np.array_equal(p.velocity(t, frame=frame), out[:, 17:23])
    assert np.array_equal(p.acceleration(t, frame=frame), out[:, 23:29])
    assert np.array_equal(p.jerk(t, frame=frame), out[:, 29:35])


@pytest.mark.parametrize("scheme", SCHEMES)
def test_world_is_position_derivative(rng, scheme):
    """frame='world': the last three entries are p', p'', p''' of the
    sampled position, the first three R(t) w_body (and their derivatives)."""
    n = 3 if scheme == "quadratic" else 6
    times, K = keys(rng, scheme, n)
    p = garotor.Path(times, K, scheme=scheme)
    t0, t1 = p.range
    # inside the segments, away from smooth's breakpoints (the midpoints)
    seg = rng.integers(0, len(times) - 1, size=20)
    t = np.clip(times[seg] + rng.choice([0.2, 0.35, 0.7, 0.85], size=20) * np.diff(times)[seg], t0 + 0.01, t1 - 0.01)
    h = 1e-3

    def pos(s):
        return p.sample(s)[..., :3, 3]

    v, a, j = p.velocity(t, frame="world"), p.acceleration(t, frame="world"), p.jerk(t, frame="world")
    d1 = (pos(t + h) - pos(t - h)) / (2 * h)
    d2 = (pos(t + h) - 2 * pos(t) + pos(t - h)) / h**2
    d3 = (pos(t + 2 * h) - 2 * pos(t + h) + 2 * pos(t - h) - pos(t - 2 * h)) / (2 * h**3)
    # truncation ~ h^2 times the rates' size squared: lihao2's grow (to 15/s here)
    for x, y, tol in ((v[:, 3:], d1, 1e-4), (a[:, 3:], d2, 1e-3), (j[:, 3:], d3, 2e-2)):
        assert np.abs(x - y).max() <= tol * (1 + np.abs(x).max())
    R = p.sample(t)[:, :3, :3]
    assert np.allclose(v[:, :3], np.einsum("kij,kj->ki", R, p.velocity(t)[:, :3]), rtol=0, atol=1e-12 * (1 + np.abs(v).max()))
    assert np.allclose(a[:, :3], np.einsum("kij,kj->ki", R, p.acceleration(t)[:, :3]), rtol=0,
                       atol=1e-12 * (1 + np.abs(a).max()))


def test_frame_errors(rng):
    times, K = keys(rng, "screw", 4)
    p = garotor.Path(times, K)
    with pytest.raises(ValueError, match="frame must be 'body', 'spatial' or 'world', not 'up'"):
        p.velocity(0.5, frame="up")
    A = K.copy()
    A[:, :3, :3] *= 1.1
    q = garotor.Path(times, A, group="affine")
    with pytest.raises(ValueError, match="frame='world' needs a rigid group"):
        q.jerk(0.5, frame="world")
    assert q.jerk(0.5, frame="spatial").shape == (4, 4)
    # body is the default, and is ga_path_velocity's
    assert np.array_equal(p.velocity(0.3), p.velocity(0.3, frame="body"))
