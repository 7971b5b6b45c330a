#!/usr/bin/env python3
"""python/bench.py: garotor's vectorised calls against what Python users use
now (scipy.spatial.transform), and against the same work as a plain C loop.

    PYTHONPATH=build/python python3 python/bench.py [--n 1000000] [--repeat 5] [--clock cpu] [--json]
        [--dask 10000000]

Three figures per task, each the median time of --repeat runs on the same
seeded input: wall time, or with --clock cpu the CPU time of the calling
thread (time.thread_time, and the same clock in C), which other work on a
shared machine disturbs less (the module's loops run in the calling thread):
  garotor   the module's call (array in, array out)
  C loop    _garotor_bench.c_loop (python/bench_loop.c, built beside the
            module, not installed): the same library calls per element in a
            plain C loop, timed in C (no numpy, no broadcasting): the ratio
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
ufunc"); compose of --n pairs of motions, by garotor.compose and
garotor.ufunc.compose ("compose ufunc"; no scipy column); interpolation
of --n samples through --keys key poses (garotor:
Path(scheme='screw').sample); the geometric product of --n pairs of dense
multivectors, MultivectorArray's * ("gp") and garotor.ufunc.gp ("gp ufunc"),
against ga_mv_gp in a plain C loop (no scipy column); one versor on --n
points, Multivector.apply ("apply": V's inverse once, ga_versor_apply_many,
against that call in C) and the same per element ("apply each":
MultivectorArray.apply with V broadcast, against ga_versor_apply in a C
loop), no scipy column.

Then Path.sample at the same --n times sorted and shuffled (--keys and 100
times as many keys; CPU time), and with --dask N: N poses sampled through --keys keys
and summed (only a 4 x 4 comes back) on a distributed.LocalCluster of 2
worker processes (1 thread each) against the same work in this one process,
in chunks of 10^6 (the wall time of each, --repeat runs, and the speed-up).
"""
import argparse
import json
import platform
import time

import numpy as np

import garotor

try:
    import _garotor_bench  # the C loop, in the build tree only
except ImportError:
    _garotor_bench = None

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
    ap.add_argument("--dask", type=int, default=0, help="poses for the dask figure (0: none)")
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
    c_loop = _garotor_bench.c_loop if _garotor_bench else None
    if c_loop is None:
        raise SystemExit("bench.py: _garotor_bench not found (PYTHONPATH=build/python)")
    put("exp", "c_loop", median_c(lambda: c_loop("exp", xi, None, None, cpu), a.repeat))
    put("log", "garotor", median_time(lambda: garotor.log(T), a.repeat))
    put("log", "c_loop", median_c(lambda: c_loop("log", T, None, None, cpu), a.repeat))
    put("exp ufunc", "garotor", median_time(lambda: garotor.ufunc.exp(xi), a.repeat))
    put("exp ufunc", "c_loop", ns["exp"]["c_loop"] * n / 1e9)
    put("log ufunc", "garotor", median_time(lambda: garotor.ufunc.log(T), a.repeat))
    put("log ufunc", "c_loop", ns["log"]["c_loop"] * n / 1e9)
    T2 = T[::-1].copy()  # other motions, so that no pair is a motion with itself
    put("compose", "garotor", median_time(lambda: garotor.compose(T, T2), a.repeat))
    put("compose", "c_loop", median_c(lambda: c_loop("compose", T, T2, None, cpu), a.repeat))
    put("compose ufunc", "garotor", median_time(lambda: garotor.ufunc.compose(T, T2), a.repeat))
    put("compose ufunc", "c_loop", ns["compose"]["c_loop"] * n / 1e9)
    del T2

    times = np.cumsum(rng.uniform(0.5, 1.5, size=a.keys))
    K = garotor.exp(rng.normal(size=(a.keys, 6)))
    path = garotor.Path(times, K, scheme="screw")
    t = np.sort(rng.uniform(times[0], times[-1], size=n))
    put("interp", "garotor", median_time(lambda: path.sample(t), a.repeat))
    put("interp", "c_loop", median_c(lambda: c_loop("sample", t, times, K, cpu), a.repeat))

    X, Y = rng.normal(size=(n, 32)), rng.normal(size=(n, 32))
    A, B = garotor.MultivectorArray(X), garotor.MultivectorArray(Y)
    put("gp", "garotor", median_time(lambda: A * B, a.repeat))
    put("gp", "c_loop", median_c(lambda: c_loop("gp", X, Y, None, cpu), a.repeat))
    put("gp ufunc", "garotor", median_time(lambda: garotor.ufunc.gp(X, Y), a.repeat))
    put("gp ufunc", "c_loop", ns["gp"]["c_loop"] * n / 1e9)
    del X, Y, A, B

    # one versor (a rigid motion) on n points: Multivector.apply takes V's
    # checks and inverse once (ga_versor_apply_many); "apply each" gives
    # MultivectorArray.apply V broadcast to (n, 32) (a view), so the sandwich
    # runs per element (ga_versor_apply), as Multivector.apply did before
    V = garotor.Multivector.translation([1.0, 2.0, 3.0]) * garotor.Multivector.rotation([0.0, 0.6, 0.8], 0.7)
    P = garotor.MultivectorArray.up(rng.normal(size=(n, 3)))
    Pn, Vn = np.asarray(P), np.asarray(V)
    VB = garotor.MultivectorArray(np.broadcast_to(Vn, (n, 32)))
    put("apply", "garotor", median_time(lambda: V.apply(P), a.repeat))
    put("apply", "c_loop", median_c(lambda: c_loop("apply_many", Pn, Vn, None, cpu), a.repeat))
    put("apply each", "garotor", median_time(lambda: VB.apply(P), a.repeat))
    put("apply each", "c_loop", median_c(lambda: c_loop("apply", Pn, Vn, None, cpu), a.repeat))
    del V, P, Pn, Vn, VB

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
    del xi, T

    res["sample_order"] = sample_order(a, rng)
    if a.dask:
        res["dask"] = dask_figure(a)

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
    print(f"{'task':13} {'garotor':>9} {'C loop':>9} {'C/garotor':>10} {'scipy':>9} {'scipy/garotor':>14}")
    for task, r in ns.items():
        sc = r.get("scipy")
        print(f"{task:13} {r['garotor']:9.1f} {r['c_loop']:9.1f} {r['c_loop'] / r['garotor']:10.2f} "
              + (f"{sc:9.1f} {sc / r['garotor']:14.2f}" if sc else ""))
    print(f"Path.sample, CPU ns/sample:  {'keys':>7} {'sorted':>8} {'shuffled':>9} {'ratio':>6}")
    for keys, r in res["sample_order"].items():
        print(f"{'':28}{keys:7} {r['sorted']:8.1f} {r['shuffled']:9.1f} {r['shuffled'] / r['sorted']:6.2f}")
    if "dask" in res:
        d = res["dask"]
        print(f"dask: {d['poses']} poses summed, wall s: one process "
              + " ".join(f"{x:.2f}" for x in d["one_process_s"]) + "; 2 workers "
              + " ".join(f"{x:.2f}" for x in d["cluster_s"]) + f"; speed-up {d['speedup']:.2f}")


def sample_order(a, rng):
    """ns per sample of Path.sample at --n times sorted and shuffled, with
    --keys and 100 times as many keys, into one `out` (first touched before),
    the runs of the two interleaved, median of --repeat; CPU time of this
    process (time.process_time: the call runs in this thread), which other
    jobs on a shared machine change less than the wall time."""
    res = {}
    out = np.zeros((a.n, 4, 4))
    for keys in (a.keys, 100 * a.keys):
        times = np.cumsum(rng.uniform(0.5, 1.5, size=keys))
        path = garotor.Path(times, garotor.exp(rng.normal(size=(keys, 6))), scheme="screw")
        t = np.sort(rng.uniform(times[0], times[-1], size=a.n))
        ts = rng.permutation(t)
        sorted_s, shuffled_s = [], []
        for _ in range(a.repeat):
            for x, acc in ((t, sorted_s), (ts, shuffled_s)):
                c0 = time.process_time()
                path.sample(x, out=out)
                acc.append(time.process_time() - c0)
        res[keys] = {"sorted": 1e9 * float(np.median(sorted_s)) / a.n,
                     "shuffled": 1e9 * float(np.median(shuffled_s)) / a.n}
    return res


def dask_figure(a):
    """--dask poses through --keys keys, summed, on 2 worker processes and in
    this process; wall seconds of each run."""
    import dask.array as da
    from distributed import Client, LocalCluster

    import garotor.dask as gd

    rng = np.random.default_rng(a.seed)
    times = np.cumsum(rng.uniform(0.5, 1.5, size=a.keys))
    path = garotor.Path(times, garotor.exp(rng.normal(size=(a.keys, 6))), scheme="screw")
    chunk = 1_000_000

    def t_chunk(k):  # the times of chunk k, made where they are used
        m = min(chunk, a.dask - k * chunk)
        return np.random.default_rng([a.seed, k]).uniform(times[0], times[-1], size=m)

    nchunks = -(-a.dask // chunk)

    def one_process():
        return sum(path.sample(t_chunk(k)).sum(axis=0) for k in range(nchunks))

    t = da.concatenate([da.from_delayed(__import__("dask").delayed(t_chunk)(k),
                                        shape=(min(chunk, a.dask - k * chunk),), dtype=float)
                        for k in range(nchunks)])
    res = {"poses": a.dask, "chunk": chunk, "one_process_s": [], "cluster_s": []}
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True) as cl, Client(cl) as client:
        client.wait_for_workers(2)
        total = gd.sample(path, t).sum(axis=0)
        for _ in range(a.repeat):
            t0 = time.perf_counter()
            here = one_process()
            res["one_process_s"].append(time.perf_counter() - t0)
            t0 = time.perf_counter()
            there = total.compute()
            res["cluster_s"].append(time.perf_counter() - t0)
    # the same samples, summed in another order (chunks, then the tree)
    res["max_sum_difference"] = float(np.max(np.abs(here - there)))
    res["speedup"] = float(np.median(res["one_process_s"]) / np.median(res["cluster_s"]))
    return res


if __name__ == "__main__":
    main()
