#!/usr/bin/env python3
"""python/bench.py: garotor's vectorised calls against what Python users use
now (scipy.spatial.transform), and against the same work as a plain C loop.

    PYTHONPATH=build/python python3 python/bench.py [--n 1000000] [--repeat 5] [--clock cpu] [--json]

Three figures per task, each the median time of --repeat runs on the same
seeded input: wall time, or with --clock cpu the CPU time of the calling
thread (time.thread_time, and the same clock in C), which other work on a
shared machine disturbs less (the module's loops run in the calling thread):
  garotor   the module's call (array in, array out)
  C loop    garotor._c_loop: the same library calls per element in a plain C
            loop, timed in C (no numpy, no broadcasting): the ratio
            C loop / garotor is the speed of the module relative to C
  scipy     the scipy way:
            exp: Rotation.from_rotvec(w).as_matrix() and the translation v
                 put into (n, 4, 4) matrices (rotation + translation, not a
                 screw motion: the nearest thing scipy has)
            log: Rotation.from_matrix(R).as_rotvec() and the translation
            interp: Slerp over the key rotations and np.interp of the key
                 positions, assembled into (n, 4, 4) matrices
Tasks: exp and log of --n twists / motions, by the module's calls and by
the generalized ufuncs garotor.ufunc.exp and .log (rows "exp ufunc", "log
ufunc"); interpolation of --n samples through --keys key poses (garotor:
Path(scheme='screw').sample); the geometric product of --n pairs of dense
multivectors, MultivectorArray's * ("gp") and garotor.ufunc.gp ("gp ufunc"),
against ga_mv_gp in a plain C loop (no scipy column).
"""
import argparse
import json
import platform
import time

import numpy as np

import garotor

try:
    from scipy.spatial.transform import Rotation, Slerp
    import scipy
except ImportError:  # the scipy column is then absent
    Rotation = Slerp = scipy = None


CLOCK = time.perf_counter


def median_time(fn, repeat):
    times = []
    for _ in range(repeat):
        t0 = CLOCK()
        fn()
        times.append(CLOCK() - t0)
    return float(np.median(times))


def median_c(fn, repeat):
    return float(np.median([fn() for _ in range(repeat)]))


def assemble(R, p):
    M = np.zeros((len(R), 4, 4))
    M[:, :3, :3] = R
    M[:, :3, 3] = p
    M[:, 3, 3] = 1.0
    return M


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--n", type=int, default=1_000_000)
    ap.add_argument("--keys", type=int, default=1000)
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--clock", choices=["wall", "cpu"], default="wall")
    ap.add_argument("--json", action="store_true")
    a = ap.parse_args()
    global CLOCK
    cpu = a.clock == "cpu"
    CLOCK = time.thread_time if cpu else time.perf_counter
    rng = np.random.default_rng(a.seed)
    n = a.n

    xi = rng.normal(size=(n, 6))
    T = garotor.exp(xi)
    res = {"n": n, "keys": a.keys, "repeat": a.repeat, "clock": a.clock, "ns_per_element": {}}
    ns = res["ns_per_element"]

    def put(task, who, seconds):
        ns.setdefault(task, {})[who] = 1e9 * seconds / n

    put("exp", "garotor", median_time(lambda: garotor.exp(xi), a.repeat))
    put("exp", "c_loop", median_c(lambda: garotor._c_loop("exp", xi, None, cpu), a.repeat))
    put("log", "garotor", median_time(lambda: garotor.log(T), a.repeat))
    put("log", "c_loop", median_c(lambda: garotor._c_loop("log", T, None, cpu), a.repeat))
    put("exp ufunc", "garotor", median_time(lambda: garotor.ufunc.exp(xi), a.repeat))
    put("exp ufunc", "c_loop", ns["exp"]["c_loop"] * n / 1e9)
    put("log ufunc", "garotor", median_time(lambda: garotor.ufunc.log(T), a.repeat))
    put("log ufunc", "c_loop", ns["log"]["c_loop"] * n / 1e9)

    times = np.cumsum(rng.uniform(0.5, 1.5, size=a.keys))
    K = garotor.exp(rng.normal(size=(a.keys, 6)))
    path = garotor.Path(times, K, scheme="screw")
    t = np.sort(rng.uniform(times[0], times[-1], size=n))
    put("interp", "garotor", median_time(lambda: path.sample(t), a.repeat))
    put("interp", "c_loop", median_c(lambda: garotor._c_loop("sample", t, path, cpu), a.repeat))

    X, Y = rng.normal(size=(n, 32)), rng.normal(size=(n, 32))
    A, B = garotor.MultivectorArray(X), garotor.MultivectorArray(Y)
    put("gp", "garotor", median_time(lambda: A * B, a.repeat))
    put("gp", "c_loop", median_c(lambda: garotor._c_loop("gp", X, Y, cpu), a.repeat))
    put("gp ufunc", "garotor", median_time(lambda: garotor.ufunc.gp(X, Y), a.repeat))
    put("gp ufunc", "c_loop", ns["gp"]["c_loop"] * n / 1e9)
    del X, Y, A, B

    if Rotation is not None:
        w, v = xi[:, :3], xi[:, 3:]
        put("exp", "scipy", median_time(lambda: assemble(Rotation.from_rotvec(w).as_matrix(), v), a.repeat))

        def scipy_log():
            return np.concatenate([Rotation.from_matrix(T[:, :3, :3]).as_rotvec(), T[:, :3, 3]], axis=1)

        put("log", "scipy", median_time(scipy_log, a.repeat))
        slerp = Slerp(times, Rotation.from_matrix(K[:, :3, :3]))

        def scipy_interp():
            p = np.column_stack([np.interp(t, times, K[:, i, 3]) for i in range(3)])
            return assemble(slerp(t).as_matrix(), p)

        put("interp", "scipy", median_time(scipy_interp, a.repeat))

    res["machine"] = {
        "python": platform.python_version(),
        "numpy": np.__version__,
        "scipy": scipy.__version__ if scipy else None,
        "cpu": platform.processor() or platform.machine(),
    }
    if a.json:
        print(json.dumps(res, indent=1))
        return
    print(f"{n} elements, median of {a.repeat} runs, ns per element ({a.clock} time)")
    print(f"{'task':9} {'garotor':>9} {'C loop':>9} {'C/garotor':>10} {'scipy':>9} {'scipy/garotor':>14}")
    for task, r in ns.items():
        sc = r.get("scipy")
        print(f"{task:9} {r['garotor']:9.1f} {r['c_loop']:9.1f} {r['c_loop'] / r['garotor']:10.2f} "
              + (f"{sc:9.1f} {sc / r['garotor']:14.2f}" if sc else ""))


if __name__ == "__main__":
    main()
