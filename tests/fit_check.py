#!/usr/bin/env python3
"""`garotor fit` on a synthetic noisy trajectory against the true one
(issue 27 item 7). Seeded; the truth is a smooth screw-like motion, the
keys are at uneven stamps (uniform random times over 10 s, epoch-sized
stamps), each position and rotation disturbed by noise of 0.01 per axis.
  - the error of the fitted poses against the truth falls as keys are added
    (100, 400, 1600 keys, knots 0.5 apart: least squares averages the
    noise, error ~ 1/sqrt(keys per knot): each fourfold more keys must at
    least cut it by 0.6), and the residuals are the noise's size;
  - the control poses (--controls) read by `interp --scheme bspline`
    give the fitted poses again (1e-12), and its velocity (--with
    velocity) follows the true body velocity, better with more keys;
  - --smooth lowers the smoothing term of the controls;
  - --time-unit ns: the same keys in whole nanoseconds give the same fit;
  - errors: exit 2, the line named, no --out file left.
Usage: fit_check.py GAROTOR
"""
import os
import subprocess
import sys
import tempfile

try:
    import numpy as np
    from scipy.linalg import logm
    from scipy.spatial.transform import Rotation as Rot
except ImportError:
    print("skip: numpy/scipy not found")
    sys.exit(77)

TOOL = sys.argv[1]
fails = 0
T0 = 1305031102


def check(cond, what):
    global fails
    print(("ok   " if cond else "FAIL ") + what)
    fails += not cond


def truth(s):
    pos = np.c_[np.cos(s), np.sin(0.7 * s), 0.2 * s]
    rv = np.c_[0.3 * np.sin(s), 0.2 * np.cos(0.5 * s), 0.8 * s]
    return pos, Rot.from_rotvec(rv)


def body_velocity(s, d=1e-5):
    """the true body velocity (w, v) at s by central differences of the truth"""
    p0, r0 = truth(s)
    pp, rp = truth(s + d)
    pm, rm = truth(s - d)
    w = ((r0.inv() * rp).as_rotvec() - (r0.inv() * rm).as_rotvec()) / (2 * d)
    v = r0.inv().apply((pp - pm) / (2 * d))
    return np.c_[w, v]


def keys_file(d, n, seed, noise=0.01):
    rng = np.random.default_rng(seed)
    us = np.sort(rng.choice(10_000_000, n, replace=False))  # whole microseconds: stamps written exactly
    us[0], us[-1] = 0, 10_000_000
    s = us / 1e6
    pos, rot = truth(s)
    p = pos + rng.normal(scale=noise, size=(n, 3))
    q = (rot * Rot.from_rotvec(rng.normal(scale=noise, size=(n, 3)))).as_quat()
    path = os.path.join(d, "keys%d.txt" % n)
    with open(path, "w") as f:
        for i in range(n):
            f.write("%d.%06d %s\n" % (T0 + us[i] // 1_000_000, us[i] % 1_000_000,
                                      " ".join("%.17g" % x for x in [*p[i], *q[i]])))
    return path, s


def read(path):
    return np.array([[float(x) for x in l.split()] for l in open(path) if l.strip()])


def fit(d, keys, *args):
    out, ctl = os.path.join(d, "fitted.txt"), os.path.join(d, "ctl.txt")
    r = subprocess.run([TOOL, "fit", "--in", keys, "--out", out, "--controls", ctl] + list(args),
                       capture_output=True, text=True)
    check(r.returncode == 0, "fit %s %s: exit status 0 %s" % (os.path.basename(keys), " ".join(args), r.stderr[:200]))
    return read(out), ctl


def main():
    d = tempfile.mkdtemp()
    errs, verrs = [], []
    for n in (100, 400, 1600):
        keys, s = keys_file(d, n, n)
        a, ctl = fit(d, keys, "--spacing", "0.5")
        pos, rot = truth(s)
        ep = np.sqrt(np.mean(np.sum((a[:, 1:4] - pos) ** 2, axis=1)))
        er = np.sqrt(np.mean((Rot.from_quat(a[:, 4:8]).inv() * rot).magnitude() ** 2))
        res = np.sqrt(np.mean(a[:, 8] ** 2))
        errs.append(max(ep, er))
        print("     %4d keys: position error %.3e, rotation error %.3e rad, residual %.3e" % (n, ep, er, res))
        check(0.8 * 0.01 * np.sqrt(3) < res < 1.2 * 0.01 * np.sqrt(3),
              "%d keys: rms residual %.4f is the noise's size (0.01 sqrt 3 = 0.0173, within 20%%)" % (n, res))
        # the controls through interp --scheme bspline: the fitted poses, and a velocity
        times = "".join(l.split()[0] + "\n" for l in open(keys))
        r = subprocess.run([TOOL, "interp", "--scheme", "bspline", "--format", "pose", "--in", ctl, "--times",
                            "/dev/stdin", "--with", "velocity"], input=times, capture_output=True, text=True)
        b = np.array([[float(x) for x in l.split()] for l in r.stdout.splitlines()])
        same = max(np.max(np.abs(b[:, 1:4] - a[:, 1:4])),
                   np.max(np.abs(np.abs(np.sum(b[:, 4:8] * a[:, 4:8], axis=1)) - 1)))
        check(r.returncode == 0 and same < 1e-12,
              "%d keys: interp --scheme bspline on the controls gives the fitted poses (%.1e)" % (n, same))
        inner = (s > 1) & (s < 9)
        ve = np.sqrt(np.mean(np.sum((b[inner, 8:14] - body_velocity(s[inner])) ** 2, axis=1)))
        verrs.append(ve)
        print("     %4d keys: body velocity error %.3e (rms over 1 < s < 9)" % (n, ve))
    for k in (1, 2):
        check(errs[k] < 0.6 * errs[k - 1], "error falls with 4x the keys: %.3e -> %.3e (< 0.6x)" % (errs[k - 1], errs[k]))
        check(verrs[k] < 0.8 * verrs[k - 1], "velocity error falls with 4x the keys: %.3e -> %.3e (< 0.8x)"
              % (verrs[k - 1], verrs[k]))
    check(errs[2] < 0.01 / 3, "1600 keys: error %.3e below a third of the noise (0.01)" % errs[2])

    # smoothing: the second differences of the controls' logs shrink
    def roughness(ctl):
        c = read(ctl)
        M = []
        for row in c:
            m = np.eye(4)
            m[:3, :3] = Rot.from_quat(row[4:8]).as_matrix()
            m[:3, 3] = row[1:4]
            M.append(m)
        logs = [np.real(logm(np.linalg.inv(M[j]) @ M[j + 1])) for j in range(len(M) - 1)]
        return sum(np.sum((logs[j] - logs[j + 1]) ** 2) for j in range(len(logs) - 1))

    keys, s = keys_file(d, 400, 400)
    _, ctl = fit(d, keys, "--spacing", "0.5")
    r0 = roughness(ctl)
    _, ctl = fit(d, keys, "--spacing", "0.5", "--smooth", "100")
    r1 = roughness(ctl)
    check(r1 < 0.5 * r0, "--smooth 100 halves the controls' roughness at least: %.3e -> %.3e" % (r0, r1))

    outp = os.path.join(d, "out.txt")
    # --time-unit ns: the same keys stamped in whole nanoseconds give the same
    # fitted poses, residuals and controls, the stamps in nanoseconds (the
    # knots t0 + (j - 1) H with H, in seconds, read exactly); without it refused
    ns_keys = os.path.join(d, "keys.ns")
    with open(ns_keys, "w") as f:
        for l in open(keys):
            t, rest = l.split(" ", 1)
            whole, frac = t.split(".")
            f.write("%d %s" % (int(whole + (frac + "000000000")[:9]), rest))
    outs, outn = os.path.join(d, "fit.s"), os.path.join(d, "fit.ns")
    ctls, ctln = os.path.join(d, "ctl.s"), os.path.join(d, "ctl.ns")
    r1 = subprocess.run([TOOL, "fit", "--in", keys, "--spacing", "0.5", "--out", outs, "--controls", ctls],
                        capture_output=True, text=True)
    r2 = subprocess.run([TOOL, "fit", "--in", ns_keys, "--spacing", "0.5", "--time-unit", "ns", "--out", outn,
                         "--controls", ctln], capture_output=True, text=True)
    def body(path):
        return [l.split(" ", 1)[1] for l in open(path)] if os.path.exists(path) else None
    def stamps(path):
        return [l.split(" ", 1)[0] for l in open(path)] if os.path.exists(path) else []
    check(r1.returncode == 0 and r2.returncode == 0 and body(outs) == body(outn) and body(ctls) == body(ctln)
          and len(body(outs)) > 10, "--time-unit ns: the same fit as in seconds, byte for byte (%s)" % r2.stderr[:200])
    to_ns = [int(t.split(".")[0] + (t.split(".")[1] + "000000000")[:9]) if "." in t else int(t) * 10**9
             for t in stamps(ctls)]
    check(to_ns == [int(t) for t in stamps(ctln)] and len(to_ns) > 5,
          "--time-unit ns: the controls' knots are the seconds' knots in whole nanoseconds")
    r = subprocess.run([TOOL, "fit", "--in", ns_keys, "--spacing", "0.5", "--out", outp], capture_output=True,
                       text=True)
    check(r.returncode == 2 and "keys.ns:1: the time" in r.stderr and "looks like nanoseconds" in r.stderr
          and not os.path.exists(outp), "nanoseconds without --time-unit: refused, line 1 named (%s)" % r.stderr[:200])

    # errors
    lines = open(keys).read().splitlines()
    bad = os.path.join(d, "bad.txt")
    l2 = list(lines)
    l2[5] = l2[5].rsplit(" ", 1)[0]
    open(bad, "w").write("\n".join(l2) + "\n")
    r = subprocess.run([TOOL, "fit", "--in", bad, "--spacing", "0.5", "--out", outp], capture_output=True, text=True)
    check(r.returncode == 2 and "bad.txt:6: expected 8 numbers" in r.stderr and not os.path.exists(outp),
          "a short line: exit 2, line 6 named, no --out file")
    r = subprocess.run([TOOL, "fit", "--in", keys], capture_output=True, text=True)
    check(r.returncode == 2 and "--spacing H is required" in r.stderr, "no --spacing: named")
    r = subprocess.run([TOOL, "fit", "--in", keys, "--spacing", "-1"], capture_output=True, text=True)
    check(r.returncode == 2 and "--spacing needs a number > 0, not '-1'" in r.stderr, "a bad --spacing named")
    print("fit_check: %s" % ("all passed" if not fails else "%d FAILED" % fails))
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
