#!/usr/bin/env python3
"""tests/scipy_check.py: `garotor interp --scheme decoupled` and
`--scheme decoupled-c2` against scipy, the reference they are meant to equal
(docs/schemes.md, "decoupled").

- decoupled: the rotation against scipy.spatial.transform.Slerp, the position
  against numpy.interp (linear), at every sample;
- decoupled-c2: the position, its first and second derivative against
  scipy.interpolate.CubicSpline (default not-a-knot), the rotation, the body
  angular rate and acceleration against scipy.spatial.transform.RotationSpline,
  whose construction decoupled-c2 is. scipy stops RotationSpline's
  fixed-point sweeps after 10 or at a change of 1e-9; here it runs them until
  they stop changing (MAX_ITER 100, TOL 0), so both are the converged spline.
  The body velocity (w, v) the tool writes gives p' = R v and
  p'' = R (v' + w x v).

Both groups (cga, matrix), random keys (seeded), irregular times, quaternion
signs flipped at random (q and -q are one rotation), samples at the keys,
between them and at random times. Relative rotations per segment are kept in
[0.2, 2.5] rad: scipy's RotationSpline forms its coefficient functions in
closed form above 1e-4 rad, where they lose up to 5e-3 relative to
cancellation at 1e-3 rad; above 0.2 rad that loss is below 1e-13.

Bound: every difference <= 1e-12 (absolute: rotation entries are O(1),
positions, rates and accelerations O(10) here). Exit 77 (skipped) where
numpy/scipy are missing. Run by `meson test` (suite tool) with the tool's path.
"""
import subprocess
import sys

try:
    import numpy as np
    from scipy.interpolate import CubicSpline
    from scipy.spatial.transform import Rotation, RotationSpline, Slerp
except ImportError:
    print("scipy_check: numpy/scipy not installed: skipped")
    sys.exit(77)

TOOL = sys.argv[1]
BOUND = 1e-12
rng = np.random.default_rng(20240615)


def keys(n):
    t = np.cumsum(np.concatenate([[rng.uniform(-2, 2)], rng.uniform(0.3, 1.5, n - 1)]))
    rots = [Rotation.from_rotvec(rng.normal(size=3) * 0.5)]
    for _ in range(n - 1):
        axis = rng.normal(size=3)
        axis /= np.linalg.norm(axis)
        rots.append(rots[-1] * Rotation.from_rotvec(axis * rng.uniform(0.2, 2.5)))
    q = np.array([r.as_quat() for r in rots])  # x y z w
    q *= np.where(rng.uniform(size=n) < 0.3, -1.0, 1.0)[:, None]
    p = rng.uniform(-5, 5, size=(n, 3))
    return t, q, p


def run(scheme, group, t, q, p, ts, extra=("--with", "velocity,acceleration")):
    text = "".join("%r %r %r %r %r %r %r %r\n" % (ti, *pi, *qi) for ti, pi, qi in zip(t, p, q))
    at = ",".join(repr(x) for x in ts)
    out = subprocess.run([TOOL, "interp", "--scheme", scheme, "--group", group, "--format", "pose",
                          "--at", at, *extra],
                         input=text, capture_output=True, text=True, check=True).stdout
    return np.array([[float(x) for x in line.split()] for line in out.splitlines()])


worst = {}


def check(name, a, b):
    d = float(np.max(np.abs(np.asarray(a) - np.asarray(b))))
    worst[name] = max(worst.get(name, 0.0), d)


for trial in range(6):
    n = [2, 3, 4, 5, 8, 12][trial]
    t, q, p = keys(n)
    ts = np.concatenate([t, (t[:-1] + t[1:]) / 2, rng.uniform(t[0], t[-1], 20)])
    rot = Rotation.from_quat(q)
    for group in ("cga", "matrix"):
        # decoupled: Slerp and linear position
        out = run("decoupled", group, t, q, p, ts)
        R = Rotation.from_quat(out[:, 4:8]).as_matrix()
        check("decoupled rotation", R, Slerp(t, rot)(ts).as_matrix())
        check("decoupled position", out[:, 1:4], np.stack([np.interp(ts, t, p[:, c]) for c in range(3)], 1))
        # decoupled-c2: CubicSpline and RotationSpline
        out = run("decoupled-c2", group, t, q, p, ts)
        R = Rotation.from_quat(out[:, 4:8]).as_matrix()
        w, v, wd, vd = out[:, 8:11], out[:, 11:14], out[:, 14:17], out[:, 17:20]
        cs = CubicSpline(t, p)
        check("decoupled-c2 position", out[:, 1:4], cs(ts))
        check("decoupled-c2 p'", np.einsum("kij,kj->ki", R, v), cs(ts, 1))
        check("decoupled-c2 p''", np.einsum("kij,kj->ki", R, vd + np.cross(w, v)), cs(ts, 2))
        RotationSpline.MAX_ITER, RotationSpline.TOL = 100, 0.0
        rs = RotationSpline(t, rot)
        check("decoupled-c2 rotation", R, rs(ts).as_matrix())
        if n > 2:  # scipy's RotationSpline of 2 keys has no rate below order 0
            check("decoupled-c2 angular rate", w, rs(ts, 1))
            check("decoupled-c2 angular acceleration", wd, rs(ts, 2))
        # --frame world: the angular rate and acceleration in world axes (R w,
        # R w', as d/dt (R w) = R (w' + w x w)), the position's derivatives
        # (CubicSpline's orders 1 to 3)
        wo = run("decoupled-c2", group, t, q, p, ts, ("--with", "velocity,acceleration,jerk", "--frame", "world"))
        check("decoupled-c2 world: pose as body's", wo[:, :8], out[:, :8])
        check("decoupled-c2 world p'", wo[:, 11:14], cs(ts, 1))
        check("decoupled-c2 world p''", wo[:, 17:20], cs(ts, 2))
        # the third derivative is 6 c3, of order 100 on short segments: relative
        check("decoupled-c2 world p''' (relative)", wo[:, 23:26] / max(1.0, np.max(np.abs(cs(ts, 3)))),
              cs(ts, 3) / max(1.0, np.max(np.abs(cs(ts, 3)))))
        if n > 2:
            check("decoupled-c2 world angular rate", wo[:, 8:11], np.einsum("kij,kj->ki", R, rs(ts, 1)))
            check("decoupled-c2 world angular acceleration", wo[:, 14:17], np.einsum("kij,kj->ki", R, rs(ts, 2)))
        # decoupled, world: slerp's constant body rate (the segment's rotation
        # vector over its length) in world axes, the chord's slope, no
        # acceleration or jerk
        wo = run("decoupled", group, t, q, p, ts, ("--with", "velocity,acceleration,jerk", "--frame", "world"))
        seg = np.clip(np.searchsorted(t, ts, side="right") - 1, 0, n - 2)
        h = np.diff(t)
        rate = np.array([(rot[i].inv() * rot[i + 1]).as_rotvec() / h[i] for i in range(n - 1)])
        Rw = Rotation.from_quat(wo[:, 4:8]).as_matrix()
        check("decoupled world angular rate", wo[:, 8:11], np.einsum("kij,kj->ki", Rw, rate[seg]))
        check("decoupled world p'", wo[:, 11:14], (np.diff(p, axis=0) / h[:, None])[seg])
        check("decoupled world: no acceleration, no jerk", wo[:, 14:], 0 * wo[:, 14:])

bad = 0
for name, d in worst.items():
    ok = d <= BOUND
    bad += not ok
    print("%-4s %-36s worst %.3g (bound %g)" % ("ok" if ok else "FAIL", name, d, BOUND))
sys.exit(1 if bad else 0)
