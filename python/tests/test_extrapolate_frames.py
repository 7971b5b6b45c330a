"""garotor interp --extrapolate constant-velocity: the derivatives past the
keys in every frame against central differences of the samples there (the
world frame's position derivatives R v, R (w x v), R (w x (w x v)) are not
zero although the body velocity is constant)."""
import os

import numpy as np
import pytest

KEYS = [[0, 0, 0, 0, 0, 0, 0, 1],
        [1, 1, 0.2, 0, 0, 0, 0.3, 0.9539392014169457],
        [2, 1.5, 1, 0.3, 0.1, 0, 0.5, 0.8602325267042626]]


@pytest.mark.parametrize("scheme", ["screw", "c2", "decoupled"])
@pytest.mark.parametrize("t", [-1.5, 3.0])
def test_constant_velocity_world(tool, tmp_path, scheme, t):
    h = 1e-3
    times = tmp_path / "times"

    def run(ts, frame, width):
        times.write_text("\n".join(repr(x) for x in ts) + "\n")
        return tool(["interp", "--format", "pose", "--scheme", scheme, "--normalize", "--times", os.fspath(times),
                     "--extrapolate", "constant-velocity", "--with", width, "--frame", frame], KEYS)

    A = run([t - h, t, t + h], "world", "velocity,acceleration,jerk")
    p = A[:, 1:4]
    v, a, j = A[1, 8:14], A[1, 14:20], A[1, 20:26]
    assert np.allclose(v[3:], (p[2] - p[0]) / (2 * h), atol=1e-6)
    assert np.allclose(a[3:], (p[2] - 2 * p[1] + p[0]) / h**2, atol=1e-5)
    acc = run([t - h, t + h], "world", "acceleration")[:, 8 + 3:8 + 6]
    assert np.allclose(j[3:], (acc[1] - acc[0]) / (2 * h), atol=1e-9)
    # the rotation rate in world axes stays: no derivative
    assert np.array_equal(a[:3], np.zeros(3)) and np.array_equal(j[:3], np.zeros(3))
    assert np.linalg.norm(a[3:]) > 1e-3  # the case is not trivial
    # body and spatial: constant, no acceleration or jerk
    for frame in ("body", "spatial"):
        B = run([t - h, t + h], frame, "velocity,acceleration,jerk")
        assert np.allclose(B[0, 8:14], B[1, 8:14], atol=1e-12 if frame == "body" else 1e-9)
        assert not B[:, 14:26].any()
