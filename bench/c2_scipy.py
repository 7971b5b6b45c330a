#!/usr/bin/env python3
"""bench/c2_scipy.py: garotor's c2 build against scipy's RotationSpline +
CubicSpline on the same keys, in the same run (docs/benchmarks.md).

Usage: bench/c2_scipy.py BUILD/bench/garotor-bench
Runs `garotor-bench --only c2_build_2000,c2_build_1e5 --json` (the keys of
bench/cases_path.c: t_i = 0.1 i + 0.02 u_i, a turn about a wandering axis, a
position on a Lissajous curve) and times scipy's build of the same motion
(the same formulas; the jitter from numpy's generator) on the same clock, the
process's CPU time (garotor-bench times these two keys on it): the median of
21 builds of 2000 keys and of 3 of 1e5. Prints both and the ratios.
"""
import json
import subprocess
import sys
import time

import numpy as np
from scipy.interpolate import CubicSpline
from scipy.spatial.transform import Rotation, RotationSpline


def scipy_build_ns(n, reps):
    s = 0.1 * np.arange(n)
    t = s + 0.02 * np.random.default_rng(1).random(n)
    c, sn = np.cos(0.3 * s), np.sin(0.3 * s)
    q = np.stack([sn * 0.6, sn * 0.8 * np.cos(s), sn * 0.8 * np.sin(s), c], 1)  # x y z w
    R = Rotation.from_quat(q)
    p = np.stack([np.sin(s), np.cos(0.7 * s), 0.1 * s], 1)
    runs = []
    for _ in range(reps):
        t0 = time.process_time_ns()
        RotationSpline(t, R)
        CubicSpline(t, p)
        runs.append(time.process_time_ns() - t0)
    return float(np.median(runs))


out = subprocess.run([sys.argv[1], "--only", "c2_build_2000,c2_build_1e5", "--json"], capture_output=True,
                     text=True, check=True).stdout
ns = json.loads(out)["ns"]
sc2000, sc1e5 = scipy_build_ns(2000, 21), scipy_build_ns(100000, 3)
g2000, g1e5 = ns["c2_build_2000"], ns["c2_build_1e5"]
print("c2 build, 2000 keys: garotor %.4g s, scipy %.4g s, ratio %.3f (target <= 2)" % (g2000 * 1e-9, sc2000 * 1e-9,
                                                                                      g2000 / sc2000))
print("c2 build, 1e5 keys:  garotor %.4g s, scipy %.4g s, ratio %.3f" % (g1e5 * 1e-9, sc1e5 * 1e-9, g1e5 / sc1e5))
print("garotor 1e5 / 2000: %.1f (50 times the keys; target <= 60)" % (g1e5 / g2000))
