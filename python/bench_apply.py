#!/usr/bin/env python3
"""python/bench_apply.py: one motion on many points, the batch against the
loop of one motion per point (docs/python.md, "Speed").

    PYTHONPATH=build/python python3 python/bench_apply.py [--n 1000000] [--repeat 5]

For each group (cga, matrix) and one rigid motion T, the CPU time of the
calling thread (time.thread_time; the module's loops run in it), median of
--repeat runs, in ns per point, of:
  apply        garotor.apply(T, X), X of shape (n, 3): T converted once,
               then the batch (ga_rotor_apply_many / ga_mat4_apply_many)
  ufunc        garotor.ufunc.apply (apply_matrix) of the same
  per point    garotor.apply of T broadcast to (n, 4, 4) (a view, no copy):
               the same numbers element by element, T converted per point
"""
import argparse
import time

import numpy as np

import garotor


def median_cpu(fn, repeat):
    times = []
    for _ in range(repeat):
        t0 = time.thread_time()
        fn()
        times.append(time.thread_time() - t0)
    return float(np.median(times))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--n", type=int, default=1_000_000)
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--seed", type=int, default=1)
    a = ap.parse_args()
    rng = np.random.default_rng(a.seed)
    T = garotor.exp([0.3, -0.5, 1.1, 0.7, -0.2, 1.5])
    X = rng.normal(size=(a.n, 3))
    out = np.empty_like(X)
    TB = np.broadcast_to(T, (a.n, 4, 4))
    for g, uf in (("cga", garotor.ufunc.apply), ("matrix", garotor.ufunc.apply_matrix)):
        row = {
            "apply": median_cpu(lambda: garotor.apply(T, X, g, out=out), a.repeat),
            "ufunc": median_cpu(lambda: uf(T, X, out=out), a.repeat),
            "per point": median_cpu(lambda: garotor.apply(TB, X, g, out=out), a.repeat),
        }
        print(g, "  ".join("%s %.2f ns" % (k, 1e9 * v / a.n) for k, v in row.items()),
              " per point / apply %.2f" % (row["per point"] / row["apply"]))


if __name__ == "__main__":
    main()
