#!/usr/bin/env python3
"""`garotor eval` against evo's definitions, recomputed here in numpy on the
same files (evo itself is not installable here; issue 27 item 8).

evo's definitions, read from its source (evo/core/sync.py, metrics.py,
geometry.py, trajectory.py) and written anew:
  - association: the trajectory with fewer poses is the short one (the
    estimate when both have as many); each of its stamps goes to the argmin
    of |long stamps (+ offset on the estimate) - stamp|, kept when that is
    <= max_diff;
  - alignment: Umeyama's SVD of cov_xy = 1/n sum (y - my)(x - mx)^T, x the
    estimate's positions, y the reference's, with the det correction;
    c = tr(D S)/sigma_x^2 for Sim(3); the estimate becomes [R R_i, c R t_i + t];
  - APE: translation part |t_est - t_ref|; rotation angle of est^-1 ref;
  - RPE: E = (Q_i^-1 Q_j)^-1 (P_i^-1 P_j), pairs (i, i+delta) consecutive
    (ids 0, delta, 2 delta, ...) or all; translation |E_t|, rotation angle
    of E (scipy's Rotation magnitude);
  - statistics: numpy's max, mean, median, min, sqrt(mean(e^2)), sum(e^2),
    std (population).
Cases: Sim(3), SE(3) and no alignment; delta 3 over all pairs, radians; an
offset; an estimate with more poses than the reference; epoch stamps; the
same stamps in nanoseconds with --time-unit ns (the same report byte for
byte; refused without it); a KITTI reference with --stamps times.txt. Then
the errors: exit 2, the file and line named, no --out file left.
Usage: eval_check.py GAROTOR
"""
import os
import subprocess
import sys
import tempfile

try:
    import numpy as np
    from scipy.spatial.transform import Rotation as Rot
except ImportError:
    print("skip: numpy/scipy not found")
    sys.exit(77)

TOOL = sys.argv[1]
fails = 0


def check(cond, what):
    global fails
    print(("ok   " if cond else "FAIL ") + what)
    fails += not cond


def write_tum(path, t, pos, quat, tfmt="%.6f"):
    with open(path, "w") as f:
        f.write("# timestamp tx ty tz qx qy qz qw\n")
        for i in range(len(t)):
            f.write((tfmt % t[i]) + " " + " ".join("%.17g" % x for x in [*pos[i], *quat[i]]) + "\n")


def read_tum(path):
    rows = [list(map(float, l.split())) for l in open(path) if l.strip() and not l.startswith("#")]
    a = np.array(rows)
    T = np.zeros((len(a), 4, 4))
    T[:, :3, :3] = Rot.from_quat(a[:, 4:8]).as_matrix()
    T[:, :3, 3] = a[:, 1:4]
    T[:, 3, 3] = 1
    return a[:, 0], T


def associate(t_ref, t_est, max_diff, offset):
    est_long = len(t_est) > len(t_ref)
    if est_long:
        short, long_, off = t_ref, t_est + offset, 0.0
    else:
        short, long_, off = t_est + offset, t_ref, 0.0
    i_s, i_l = [], []
    for i, s in enumerate(short):
        d = np.abs(long_ + off - s)
        j = int(np.argmin(d))
        if d[j] <= max_diff:
            i_s.append(i)
            i_l.append(j)
    return (i_s, i_l) if est_long else (i_l, i_s)  # (ref ids, est ids)


def umeyama(x, y, with_scale):
    m, n = x.shape
    mx, my = x.mean(axis=1), y.mean(axis=1)
    sigma_x = 1.0 / n * np.linalg.norm(x - mx[:, None]) ** 2
    cov = sum(np.outer(y[:, i] - my, x[:, i] - mx) for i in range(n)) / n
    u, d, v = np.linalg.svd(cov)
    s = np.eye(m)
    if np.linalg.det(u) * np.linalg.det(v) < 0:
        s[m - 1, m - 1] = -1
    r = u @ s @ v
    c = 1 / sigma_x * np.trace(np.diag(d) @ s) if with_scale else 1.0
    return r, my - c * r @ mx, c


def stats(e):
    return {"max": np.max(e), "mean": float(np.mean(e)), "median": np.median(e), "min": np.min(e),
            "rmse": np.sqrt(np.mean(e ** 2)), "sse": np.sum(e ** 2), "std": float(np.std(e))}


def angle(R):
    return Rot.from_matrix(R).magnitude()


def evo(ref_path, est_path, max_diff=0.01, offset=0.0, align=None, delta=1, all_pairs=False, deg=True):
    t_ref, Q = read_tum(ref_path)
    t_est, P = read_tum(est_path)
    ir, ie = associate(t_ref, t_est, max_diff, offset)
    Q, P = Q[ir], P[ie].copy()
    scale = None
    if align:
        r, t, c = umeyama(P[:, :3, 3].T, Q[:, :3, 3].T, align == "sim3")
        P[:, :3, 3] *= c
        A = np.eye(4)
        A[:3, :3], A[:3, 3] = r, t
        P = A @ P
        scale = c if align == "sim3" else None
    k = 180 / np.pi if deg else 1.0
    out = {"pairs": len(ir), "scale": scale}
    out["ape_t"] = stats(np.linalg.norm(P[:, :3, 3] - Q[:, :3, 3], axis=1))
    out["ape_r"] = stats(k * np.array([angle((np.linalg.inv(p) @ q)[:3, :3]) for p, q in zip(P, Q)]))
    n = len(P)
    if all_pairs:
        pairs = [(i, i + delta) for i in range(n) if i + delta < n]
    else:
        ids = np.arange(0, n, delta)
        pairs = list(zip(ids, ids[1:]))
    E = [np.linalg.inv(np.linalg.inv(Q[i]) @ Q[j]) @ (np.linalg.inv(P[i]) @ P[j]) for i, j in pairs]
    out["rpe_t"] = stats(np.array([np.linalg.norm(e[:3, 3]) for e in E]))
    out["rpe_r"] = stats(k * np.array([angle(e[:3, :3]) for e in E]))
    return out


def run(args, out=None):
    r = subprocess.run([TOOL, "eval"] + args + (["--out", out] if out else []), capture_output=True, text=True)
    return r.returncode, r.stdout if not out else (open(out).read() if os.path.exists(out) else ""), r.stderr


def parse(text):
    blocks = {}
    key = None
    first = text.splitlines()[0]
    pairs = int(first.split()[1])
    scale = None
    order = ["ape_t", "ape_r", "rpe_t", "rpe_r"]
    b = -1
    for line in text.splitlines():
        if line.startswith("Sim(3) scale correction"):
            scale = float(line.split()[-1])
        if line.startswith("APE w.r.t.") or line.startswith("RPE w.r.t."):
            b += 1
            key = order[b]
            blocks[key] = {}
        elif key and len(line.split()) == 2 and line.split()[0] in ("max", "mean", "median", "min", "rmse", "sse", "std"):
            name, val = line.split()
            blocks[key][name] = float(val)
    return pairs, scale, blocks


def compare(name, args, ref, est, **kw):
    rc, out, err = run(["--ref", ref, "--est", est] + args)
    check(rc == 0, "%s: exit status 0 (%s)" % (name, err.strip()[:200]))
    if rc:
        return
    want = evo(ref, est, **kw)
    pairs, scale, got = parse(out)
    check(pairs == want["pairs"], "%s: %d associated pairs, evo's association gives %d" % (name, pairs, want["pairs"]))
    if want["scale"] is not None:
        check(abs(scale - want["scale"]) <= 1e-12 * abs(want["scale"]),
              "%s: Sim(3) scale %.17g, evo's Umeyama %.17g" % (name, scale, want["scale"]))
    worst = 0.0
    for key in ["ape_t", "ape_r", "rpe_t", "rpe_r"]:
        for s, v in want[key].items():
            # relative, with a floor of 1e-3 for the units: errors of a rounding (1e-15) are 0
            worst = max(worst, abs(got[key][s] - v) / max(abs(v), 1e-3))
    check(worst <= 1e-10, "%s: every statistic within 1e-10 (relative) of evo's formulas: worst %.2e" % (name, worst))


def main():
    rng = np.random.default_rng(20261202)
    d = tempfile.mkdtemp()
    n = 400
    t = 1305031102.175304 + np.arange(n) / 30.0
    s = t - t[0]
    pos = np.c_[np.cos(s), np.sin(0.7 * s), 0.1 * s]
    rv = np.c_[0.1 * np.sin(s), 0.2 * np.cos(2 * s), s]
    ref = os.path.join(d, "ref.txt")
    write_tum(ref, t, pos, Rot.from_rotvec(rv).as_quat())
    Rg, sg, tg = Rot.from_rotvec([0.3, -0.2, 0.5]), 1.3, np.array([1.0, 2.0, 3.0])
    keep = np.sort(rng.choice(n, 330, replace=False))
    pe = sg * Rg.apply(pos[keep]) + tg + rng.normal(scale=0.01, size=(len(keep), 3))
    qe = (Rg * Rot.from_rotvec(rv[keep]) * Rot.from_rotvec(rng.normal(scale=0.02, size=(len(keep), 3)))).as_quat()
    te = t[keep] + rng.uniform(-0.012, 0.012, len(keep))  # some beyond 0.01: not associated
    est = os.path.join(d, "est.txt")
    write_tum(est, te, pe, qe)
    compare("sim3", ["--align", "sim3"], ref, est, align="sim3")
    compare("se3", ["--align", "se3"], ref, est, align="se3")
    compare("not aligned", [], ref, est)
    compare("delta 3, all pairs, rad, max-diff 0.02", ["--align", "se3", "--delta", "3", "--all-pairs",
            "--angle", "rad", "--max-diff", "0.02"], ref, est, align="se3", delta=3, all_pairs=True,
            deg=False, max_diff=0.02)
    compare("delta 5 consecutive", ["--align", "sim3", "--delta", "5"], ref, est, align="sim3", delta=5)
    # an estimate with more poses, 0.25 s late: --offset -0.25
    te2 = t + 0.25 + rng.uniform(-0.003, 0.003, n)
    pos2 = pos + rng.normal(scale=0.02, size=pos.shape)
    est2 = os.path.join(d, "est2.txt")
    write_tum(est2, np.r_[te2, te2[-1] + 1 + np.arange(20) / 30.0], np.r_[pos2, pos2[-20:]],
              np.r_[(Rot.from_rotvec(rv) * Rot.from_rotvec(rng.normal(scale=0.01, size=(n, 3)))).as_quat(),
                    Rot.from_rotvec(rv[-20:]).as_quat()])
    compare("estimate longer, --offset -0.25", ["--offset", "-0.25", "--align", "se3"], ref, est2,
            offset=-0.25, align="se3")
    rc, out, err = run(["--ref", ref, "--est", est2])
    check(rc == 2 and "no pose of" in err and "--max-diff" in err, "no association: exit 2 naming --max-diff")

    # --time-unit ns: the same stamps in whole nanoseconds (written from the
    # seconds' text, exactly) give the same report byte for byte, --offset
    # and --max-diff staying in seconds; without --time-unit they are refused
    def to_ns(path_s, path_ns):
        with open(path_ns, "w") as f:
            for line in open(path_s):
                if line.startswith("#"):
                    f.write(line)
                    continue
                t, rest = line.split(" ", 1)
                whole, frac = t.split(".")
                f.write("%d %s" % (int(whole + (frac + "000000000")[:9]), rest))
    ref_ns, est_ns, est2_ns = (os.path.join(d, n) for n in ("ref.ns", "est.ns", "est2.ns"))
    to_ns(ref, ref_ns)
    to_ns(est, est_ns)
    to_ns(est2, est2_ns)
    for name, r, e, e_ns, args in [("se3", ref, est, est_ns, ["--align", "se3"]),
                                   ("--offset -0.25", ref, est2, est2_ns, ["--offset", "-0.25", "--align", "sim3"])]:
        rc, out_s, err_s = run(["--ref", r, "--est", e] + args)
        rc2, out_ns, err_ns = run(["--ref", ref_ns, "--est", e_ns, "--time-unit", "ns"] + args)
        check(rc == 0 and rc2 == 0 and out_s == out_ns and len(out_s) > 500,
              "--time-unit ns, %s: the report of the same stamps in seconds (%s)" % (name, (err_s + err_ns).strip()))
    rc, out, err = run(["--ref", ref_ns, "--est", est_ns, "--time-unit", "s", "--align", "se3"])
    check(rc == 2 and "no pose of" in err, "--time-unit s on nanoseconds: read as seconds, nothing associated")
    rc, out, err = run(["--ref", ref_ns, "--est", est_ns], out=os.path.join(d, "report.ns"))
    check(rc == 2 and "ref.ns:2: the time %s looks like nanoseconds (a whole number of 19 digits): pass --time-unit ns"
          % open(ref_ns).read().splitlines()[1].split()[0] in err and not os.path.exists(os.path.join(d, "report.ns")),
          "nanoseconds without --time-unit: refused, the line named (%s)" % err.strip())
    rc, out, err = run(["--ref", ref, "--est", est_ns])
    check(rc == 2 and "est.ns:2: the time" in err and "looks like nanoseconds" in err,
          "an estimate in nanoseconds against a reference in seconds: refused (%s)" % err.strip())
    rc, out, err = run(["--ref", ref, "--est", est, "--time-unit", "ns"])
    check(rc == 2 and "ref.txt:2: --time-unit ns takes whole nanoseconds, not '%s'"
          % open(ref).read().splitlines()[1].split()[0] in err, "--time-unit ns on seconds: refused (%s)" % err.strip())
    rc, out, err = run(["--ref", ref, "--est", est, "--time-unit", "us"])
    check(rc == 2 and "garotor eval: --time-unit must be s or ns, not 'us'" in err, "bad --time-unit named")

    outp = os.path.join(d, "report.txt")
    # --stamps FILE: the reference as KITTI poses (3x4 [R t], 12 numbers a
    # line) with its stamps in a times.txt: evo's numbers as from the TUM file
    ref_rows = [l.split() for l in open(ref) if not l.startswith("#")]
    kitti, times = os.path.join(d, "ref.kitti"), os.path.join(d, "times.txt")
    with open(kitti, "w") as f, open(times, "w") as ft:
        for r in ref_rows:
            M = np.eye(4)
            M[:3, :3] = Rot.from_quat([float(x) for x in r[4:8]]).as_matrix()
            M[:3, 3] = [float(x) for x in r[1:4]]
            f.write(" ".join("%.17g" % x for x in M[:3].ravel()) + "\n")
            ft.write(r[0] + "\n")
    for name, args, kw in [("sim3", ["--align", "sim3"], dict(align="sim3")),
                           ("not aligned, delta 4", ["--delta", "4"], dict(delta=4))]:
        rc, out, err = run(["--ref", kitti, "--stamps", times, "--est", est] + args)
        check(rc == 0, "KITTI reference with --stamps, %s: exit 0 (%s)" % (name, err.strip()))
        if rc == 0:
            want = evo(ref, est, **kw)
            pairs, scale, got = parse(out)
            worst = max(abs(got[k][st] - v) / max(abs(v), 1e-3) for k in want if k in got for st, v in want[k].items())
            check(pairs == want["pairs"] and worst <= 1e-10,
                  "KITTI reference with --stamps, %s: %d pairs, every statistic within 1e-10 of evo's on the TUM "
                  "file: worst %.2e" % (name, pairs, worst))
    short = os.path.join(d, "short.txt")
    open(short, "w").write("".join(r[0] + "\n" for r in ref_rows[:-3]))
    rc, _, err = run(["--ref", kitti, "--stamps", short, "--est", est], out=outp)
    check(rc == 2 and "ref.kitti:%d: pose %d has no stamp: " % (len(ref_rows) - 2, len(ref_rows) - 2) in err
          and not os.path.exists(outp), "--stamps too short: the first pose without a stamp named (%s)" % err.strip())
    rc, _, err = run(["--ref", kitti, "--est", est], out=outp)
    check(rc == 2 and "ref.kitti:1: expected 8 numbers (t x y z qx qy qz qw), found 12: a KITTI pose (3x4, no t)? "
          "give its stamps with --stamps FILE" in err, "a KITTI file without --stamps: named (%s)" % err.strip())
    rc, _, err = run(["--ref", ref, "--est", est, "--stamps", times], out=outp)
    check(rc == 2 and "--stamps gives KITTI poses (12 numbers a line) their stamps, but" in err,
          "--stamps with two TUM files: refused (%s)" % err.strip())
    bent = os.path.join(d, "bent.kitti")
    kl = open(kitti).read().splitlines()
    v = kl[4].split()
    v[0] = repr(float(v[0]) * 1.01)
    kl[4] = " ".join(v)
    open(bent, "w").write("\n".join(kl) + "\n")
    rc, _, err = run(["--ref", bent, "--stamps", times, "--est", est], out=outp)
    check(rc == 2 and "bent.kitti:5: columns 1-12 (a KITTI 3x4 [R t]): not a rigid motion" in err,
          "a KITTI pose that is not rigid: named (%s)" % err.strip())

    # errors: the file and the line named, exit 2, no --out file
    lines = open(est).read().splitlines()
    bad = os.path.join(d, "bad.txt")
    outp = os.path.join(d, "report.txt")
    cases = [(7, lines[7].rsplit(" ", 1)[0], "bad.txt:8: expected 8 numbers (t x y z qx qy qz qw), found 7"),
             (9, lines[9].rsplit(" ", 1)[0] + " 0.9", "bad.txt:10: columns 5-8 (qx qy qz qw): the quaternion has norm"),
             (11, lines[10], "bad.txt:12: column 1: times must increase strictly"),
             (13, lines[11], "bad.txt:14: column 1: times must increase strictly: %s after %s (out of order: "
              "evo sorts by time, garotor reads the file as given: sort it by its first column, `sort -g -k1,1`)"
              % (lines[11].split()[0], lines[12].split()[0])),
             (11, lines[10].split()[0] + " " + lines[11].split(" ", 1)[1],
              "bad.txt:12: column 1: times must increase strictly: %s after %s (a repeated stamp: keep one of "
              "the two lines)" % (lines[10].split()[0], lines[10].split()[0]))]
    for k, text, want in cases:
        l2 = list(lines)
        l2[k] = text
        open(bad, "w").write("\n".join(l2) + "\n")
        rc, _, err = run(["--ref", ref, "--est", bad], out=outp)
        check(rc == 2 and want in err and not os.path.exists(outp), "error: '%s'" % want)
    rc, _, err = run(["--ref", ref, "--est", est, "--align", "sideways"])
    check(rc == 2 and "--align must be none, se3 or sim3, not 'sideways'" in err, "bad --align named")
    rc, _, err = run(["--ref", ref])
    check(rc == 2 and "--est FILE is required" in err, "missing --est named")
    rc, out, _ = run(["--ref", ref, "--est", est, "--align", "sim3"], out=outp)
    rc2, out2, _ = run(["--ref", ref, "--est", est, "--align", "sim3"])
    check(rc == 0 and rc2 == 0 and out == out2, "--out FILE holds what standard output shows")
    print("eval_check: %s" % ("all passed" if not fails else "%d FAILED" % fails))
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
