#!/usr/bin/env python3
"""The tool's time to its first output byte against its whole run
(docs/benchmarks.md, "The tool"): `garotor interp` on three keys with
--samples N written to a pipe, read here. Prints the time to the first byte,
the whole run and their ratio.

usage: tool_first_byte.py GAROTOR [N] [extra interp options...]"""
import os
import subprocess
import sys
import tempfile
import time

KEYS = ("0 0 0 0 0 0 0 1\n"
        "1 1 0.5 0.2 0 0 0.3826834323650898 0.9238795325112867\n"
        "2 2 1 0 0.1 0.2 0.5 0.8366600265340756\n")


def main():
    tool = sys.argv[1]
    n = sys.argv[2] if len(sys.argv) > 2 else "10000000"
    with tempfile.NamedTemporaryFile("w", suffix=".keys", delete=False) as f:
        f.write(KEYS)
    try:
        args = [tool, "interp", "--format", "pose", "--in", f.name, "--samples", n] + sys.argv[3:]
        t0 = time.perf_counter()
        p = subprocess.Popen(args, stdout=subprocess.PIPE, bufsize=0)
        fd = p.stdout.fileno()
        first = os.read(fd, 1)
        t1 = time.perf_counter()
        total = len(first)
        while True:
            b = os.read(fd, 1 << 20)
            if not b:
                break
            total += len(b)
        rc = p.wait()
        t2 = time.perf_counter()
    finally:
        os.unlink(f.name)
    print(f"samples {n}: first byte {t1 - t0:.4f} s, whole run {t2 - t0:.3f} s, "
          f"ratio {(t1 - t0) / (t2 - t0) * 100:.3f}%, {total} bytes, exit {rc}")
    return rc


if __name__ == "__main__":
    sys.exit(main())
