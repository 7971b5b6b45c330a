"""garotor.evaluate, ape, rpe, align and fit (docs/python.md, "Evaluating and
fitting trajectories") against the tool's `garotor eval` and `garotor fit` on
the same files, bit for bit (the tool prints the shortest decimal of each
double, which reads back as the same double), and against evo's formulas
recomputed in numpy by tests/eval_check.py.

The stamps are epoch seconds written as repr writes them (their shortest
decimal, what a file written from the floats holds): the module reads each
float stamp as that decimal, as Path does, and takes it relative to the first
exactly, rounded once, as the tool does from the text. Files stamped in
whole nanoseconds (19 digits) go through time_unit='ns', the times given
as int64, against the tool's --time-unit ns."""
import importlib.util
import os
import subprocess

import numpy as np
import pytest

import garotor

Rot = pytest.importorskip("scipy.spatial.transform").Rotation

HERE = os.path.dirname(os.path.abspath(__file__))
EVAL_CHECK = os.path.join(HERE, "..", "..", "tests", "eval_check.py")


def _tool_path():
    path = os.environ.get("GAROTOR_TOOL")
    if not path or not os.access(path, os.X_OK):
        pytest.skip("the garotor tool is not found (set GAROTOR_TOOL)")
    return path


@pytest.fixture(scope="module")
def evo():
    spec = importlib.util.spec_from_file_location("eval_check", EVAL_CHECK)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def write_tum(path, rows):
    with open(path, "w") as f:
        f.write("# timestamp tx ty tz qx qy qz qw\n")
        for r in rows:
            # repr's shortest decimal: what the module reads a float stamp as
            f.write(" ".join(repr(float(x)) for x in r) + "\n")


@pytest.fixture(scope="module")
def files(tmp_path_factory):
    d = tmp_path_factory.mktemp("traj")
    rng = np.random.default_rng(20261202)
    n = 300
    t = 1305031102.0 + np.arange(n) / 64.0
    s = t - t[0]
    pos = np.c_[np.cos(s), np.sin(0.7 * s), 0.1 * s]
    rv = np.c_[0.1 * np.sin(s), 0.2 * np.cos(2 * s), s]
    ref = np.c_[t, pos, Rot.from_rotvec(rv).as_quat()]
    keep = np.sort(rng.choice(n, 250, replace=False))
    Rg = Rot.from_rotvec([0.3, -0.2, 0.5])
    pe = 1.3 * Rg.apply(pos[keep]) + [1.0, 2.0, 3.0] + rng.normal(scale=0.01, size=(len(keep), 3))
    qe = (Rg * Rot.from_rotvec(rv[keep]) * Rot.from_rotvec(rng.normal(scale=0.02, size=(len(keep), 3)))).as_quat()
    te = t[keep] + rng.integers(-30, 31, len(keep)) / 4096.0  # up to 0.0073 s off: some beyond max_diff 0.005
    est = np.c_[te, pe, qe]
    m = 200
    tf = 1700000000.0 + np.sort(rng.choice(10 * 256, m, replace=False)) / 256.0  # uneven, 10 s
    sf = tf - tf[0]
    pf = np.c_[np.cos(sf), np.sin(sf), 0.2 * sf] + rng.normal(scale=0.01, size=(len(tf), 3))
    qf = (Rot.from_rotvec(np.c_[0.1 * sf, 0 * sf, 0.3 * sf]) * Rot.from_rotvec(rng.normal(scale=0.01, size=(len(tf), 3)))).as_quat()
    noisy = np.c_[tf, pf, qf]
    paths = {}
    for name, rows in [("ref", ref), ("est", est), ("noisy", noisy)]:
        paths[name] = str(d / (name + ".txt"))
        write_tum(paths[name], rows)
    return paths


def run_tool(args):
    r = subprocess.run([_tool_path()] + args, capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    return r.stdout


def assert_same_report(got, pairs, scale, blocks, kw):
    """evaluate()'s result holds the tool's printed numbers, bit for bit"""
    assert got["pairs"] == pairs
    if kw.get("align") == "sim3":
        assert got["scale"] == scale
    for key, stats in blocks.items():
        for name, v in stats.items():
            assert got[key][name] == v, (key, name, got[key][name], v)


def parse_eval(text):
    """The tool's report: pairs, scale, and each block's seven statistics."""
    order = ["ape_trans", "ape_rot", "rpe_trans", "rpe_rot"]
    blocks, key, b, scale = {}, None, -1, None
    pairs = int(text.splitlines()[0].split()[1])
    for line in text.splitlines():
        w = line.split()
        if line.startswith("Sim(3) scale correction"):
            scale = float(w[-1])
        if line.startswith(("APE w.r.t.", "RPE w.r.t.")):
            b += 1
            key = order[b]
            blocks[key] = {}
        elif key and len(w) == 2 and w[0] in ("max", "mean", "median", "min", "rmse", "sse", "std"):
            blocks[key][w[0]] = float(w[1])
    return pairs, scale, blocks


CASES = [
    ([], {}),
    (["--align", "se3"], {"align": "se3"}),
    (["--align", "sim3"], {"align": "sim3"}),
    (["--align", "sim3", "--delta", "3", "--all-pairs", "--angle", "rad", "--max-diff", "0.005"],
     {"align": "sim3", "delta": 3, "all_pairs": True, "angle": "rad", "max_diff": 0.005}),
    (["--align", "se3", "--delta", "5", "--offset", "0.001953125"],
     {"align": "se3", "delta": 5, "offset": 0.001953125}),
]


@pytest.mark.parametrize("args,kw", CASES)
@pytest.mark.parametrize("swap", [False, True])
def test_evaluate_equals_tool(files, args, kw, swap):
    ref, est = (files["est"], files["ref"]) if swap else (files["ref"], files["est"])
    pairs, scale, blocks = parse_eval(run_tool(["eval", "--ref", ref, "--est", est] + args))
    got = garotor.evaluate(np.loadtxt(ref), np.loadtxt(est), **kw)
    assert_same_report(got, pairs, scale, blocks, kw)
    # ape and rpe: the same numbers as evaluate's
    a = garotor.ape(np.loadtxt(ref), np.loadtxt(est), **kw)
    r = garotor.rpe(np.loadtxt(ref), np.loadtxt(est), **kw)
    assert "rpe_trans" not in a and "ape_trans" not in r
    for key in ("ape_trans", "ape_rot"):
        assert np.array_equal(a[key]["errors"], got[key]["errors"])
    for key in ("rpe_trans", "rpe_rot"):
        assert np.array_equal(r[key]["errors"], got[key]["errors"])


@pytest.mark.parametrize("args,kw", CASES[:4])
def test_evaluate_against_evo_formulas(files, evo, args, kw):
    align = kw.get("align")
    want = evo.evo(files["ref"], files["est"], max_diff=kw.get("max_diff", 0.01), offset=kw.get("offset", 0.0),
                   align=None if align in (None, "none") else align, delta=kw.get("delta", 1),
                   all_pairs=kw.get("all_pairs", False), deg=kw.get("angle", "deg") == "deg")
    got = garotor.evaluate(np.loadtxt(files["ref"]), np.loadtxt(files["est"]), **kw)
    assert got["pairs"] == want["pairs"]
    if want["scale"] is not None:
        assert abs(got["scale"] - want["scale"]) <= 1e-12 * want["scale"]
    worst = 0.0
    for mine, theirs in [("ape_trans", "ape_t"), ("ape_rot", "ape_r"), ("rpe_trans", "rpe_t"), ("rpe_rot", "rpe_r")]:
        for s, v in want[theirs].items():
            worst = max(worst, abs(got[mine][s] - v) / max(abs(v), 1e-3))
    assert worst <= 1e-10


def test_errors_and_indices(files):
    ref, est = np.loadtxt(files["ref"]), np.loadtxt(files["est"])
    got = garotor.evaluate(ref, est, align="se3")
    ir, ie = got["ref_index"], got["est_index"]
    assert len(ir) == got["pairs"] and np.all(np.abs(ref[ir, 0] - est[ie, 0]) <= 0.01)
    # the per-pair APE is |T est - ref| after the alignment
    T = got["transform"]
    P = garotor.from_pose(est[ie, 1:])
    d = np.linalg.norm((T @ P)[:, :3, 3] - ref[ir, 1:4], axis=1)
    assert np.max(np.abs(d - got["ape_trans"]["errors"])) <= 1e-12
    assert got["ape_trans"]["max"] == np.max(got["ape_trans"]["errors"])


def test_align(rng):
    q = rng.normal(size=(50, 3))
    R = Rot.from_rotvec([0.2, -0.4, 1.1])
    p = (R.inv().apply(q - [1.0, 2.0, 3.0])) / 2.5
    T, s = garotor.align(q, p, scale=True)
    assert abs(s - 2.5) <= 1e-12 and np.allclose(T[:3, :3], R.as_matrix(), atol=1e-13, rtol=0)
    assert np.allclose(T[:3, 3], [1, 2, 3], atol=1e-12, rtol=0)
    T2, s2 = garotor.align(garotor.from_pose(np.c_[q, np.tile([0, 0, 0, 1.0], (50, 1))]), p, scale=True)
    assert np.array_equal(T, T2) and s == s2
    with pytest.raises(garotor.Error, match="do not fix an alignment"):
        garotor.align(np.c_[np.arange(5.0), np.zeros(5), np.zeros(5)], np.c_[np.arange(5.0), np.zeros((5, 2))])
    with pytest.raises(ValueError, match="as many poses"):
        garotor.align(q, p[:3])


def parse_rows(text):
    return np.array([[float(x) for x in line.split()] for line in text.splitlines() if line.strip()])


@pytest.mark.parametrize("spacing,smooth", [(0.5, 0.0), (1.0, 0.1), (0.25, 3.0)])
def test_fit_equals_tool(files, tmp_path, spacing, smooth):
    ctl = str(tmp_path / "controls.txt")
    out = run_tool(["fit", "--in", files["noisy"], "--spacing", repr(spacing), "--smooth", repr(smooth),
                    "--controls", ctl])
    rows = parse_rows(out)
    got = garotor.fit(np.loadtxt(files["noisy"]), spacing, smooth=smooth)
    assert np.array_equal(got["fitted"], rows[:, :8])
    assert np.array_equal(got["residuals"], rows[:, 8:])
    c = parse_rows(open(ctl).read())
    assert np.array_equal(got["controls"][:, 1:], c[:, 1:])
    assert np.array_equal(got["controls"][:, 0], c[:, 0])  # the knots, t_0 + (j - 1) spacing, exact here


def test_bad_input_named(files):
    ref = np.loadtxt(files["ref"])
    bad = ref.copy()
    bad[7, 7] = 0.9
    with pytest.raises(garotor.Error, match=r"evaluate: est: index 7: .*est\[7, 4:8\] .*norm"):
        garotor.evaluate(ref, bad)
    bad = ref.copy()
    bad[11, 0] = bad[10, 0]
    with pytest.raises(garotor.Error, match=r"index 11: .*times must increase strictly: ref\[11, 0\]"):
        garotor.evaluate(bad, ref)
    bad = ref.copy()
    bad[3, 2] = np.nan
    with pytest.raises(garotor.Error, match=r"fit: poses: index 3: .*poses\[3, 2\] is nan"):
        garotor.fit(bad, 0.5)
    with pytest.raises(ValueError, match=r"\(n, 8\) array .* not shape \(300, 7\)"):
        garotor.evaluate(ref[:, :7], ref)
    with pytest.raises(ValueError, match="align must be 'none', 'se3' or 'sim3', not 'sideways'"):
        garotor.evaluate(ref, ref, align="sideways")
    with pytest.raises(garotor.Error, match="no pose of the estimate is within max_diff"):
        garotor.evaluate(ref, ref + [[100.0] + [0.0] * 7])
    with pytest.raises(garotor.Error, match="delta 400 leaves no pair") as e:
        garotor.rpe(ref, ref, delta=400)
    assert e.value.index == () and e.value.status == -6  # GA_ERR_ARG
    garotor.ape(ref, ref, delta=400)  # the APE has no pairs to make
    with pytest.raises(ValueError, match="spacing must be a number > 0, not 0.0"):
        garotor.fit(ref, 0.0)
    ok = garotor.evaluate(ref, np.c_[ref[:, :4], -ref[:, 4:]], normalize=True)
    assert ok["ape_rot"]["max"] == 0  # q and -q: the same rotation


EXAMPLES = os.path.join(HERE, "..", "..", "docs", "examples")


def test_decimal_stamps_equal_tool(tmp_path):
    """docs/examples' files, stamped with four decimals (not exact in
    binary): each float stamp is read as its shortest decimal, the text in
    the file, so the report and the fit are the tool's bit for bit (before,
    t - t[0] in doubles differed from the tool's exact difference)."""
    ref, est = os.path.join(EXAMPLES, "eval_ref.tum"), os.path.join(EXAMPLES, "eval_est.tum")
    for args, kw in [(["--align", "sim3"], {"align": "sim3"}),
                     (["--offset", "0.0013", "--max-diff", "0.004"], {"offset": 0.0013, "max_diff": 0.004})]:
        pairs, scale, blocks = parse_eval(run_tool(["eval", "--ref", ref, "--est", est, "--normalize"] + args))
        got = garotor.evaluate(np.loadtxt(ref), np.loadtxt(est), normalize=True, **kw)
        assert got["pairs"] == pairs and (scale is None or got["scale"] == scale)
        for key, stats in blocks.items():
            for name, v in stats.items():
                assert got[key][name] == v, (args, key, name)
    ctl = str(tmp_path / "ctl.tum")
    rows = parse_rows(run_tool(["fit", "--in", est, "--normalize", "--spacing", "0.31", "--smooth", "0.01",
                                "--controls", ctl]))
    got = garotor.fit(np.loadtxt(est), 0.31, smooth=0.01, normalize=True)
    assert np.array_equal(got["fitted"], rows[:, :8]) and np.array_equal(got["residuals"], rows[:, 8:])
    # the knots t_0 + (j - 1) 0.31 as the tool writes them: exact decimals, read back
    assert np.array_equal(got["controls"], parse_rows(open(ctl).read()))


T0_NS = 1_700_000_000_000_000_000


def write_ns(path, t, rows):
    with open(path, "w") as f:
        for ti, r in zip(t, rows):
            f.write("%d " % ti + " ".join(repr(float(x)) for x in r) + "\n")


@pytest.fixture(scope="module")
def ns_files(tmp_path_factory):
    """The fixture's motions stamped in whole nanoseconds at 1.7e18: 19
    digits, the odd nanoseconds lost in a float64 (256 ns apart there)."""
    d = tmp_path_factory.mktemp("traj_ns")
    rng = np.random.default_rng(20261203)
    n = 300
    tr = T0_NS + np.arange(n, dtype=np.int64) * 15_625_000 + rng.integers(0, 999, n)  # 64 Hz, jittered
    s = (tr - tr[0]) * 1e-9
    pos = np.c_[np.cos(s), np.sin(0.7 * s), 0.1 * s]
    rv = np.c_[0.1 * np.sin(s), 0.2 * np.cos(2 * s), s]
    ref = np.c_[pos, Rot.from_rotvec(rv).as_quat()]
    keep = np.sort(rng.choice(n, 250, replace=False))
    Rg = Rot.from_rotvec([0.3, -0.2, 0.5])
    pe = 1.3 * Rg.apply(pos[keep]) + [1.0, 2.0, 3.0] + rng.normal(scale=0.01, size=(len(keep), 3))
    qe = (Rg * Rot.from_rotvec(rv[keep]) * Rot.from_rotvec(rng.normal(scale=0.02, size=(len(keep), 3)))).as_quat()
    te = tr[keep] + rng.integers(-7_000_000, 7_000_001, len(keep))  # up to 7 ms off
    tf = T0_NS + np.sort(rng.choice(10_000_000, 200, replace=False)).astype(np.int64) * 1000 + 7  # uneven, 10 s
    sf = (tf - tf[0]) * 1e-9
    pf = np.c_[np.cos(sf), np.sin(sf), 0.2 * sf] + rng.normal(scale=0.01, size=(len(tf), 3))
    qf = (Rot.from_rotvec(np.c_[0.1 * sf, 0 * sf, 0.3 * sf]) * Rot.from_rotvec(rng.normal(scale=0.01, size=(len(tf), 3)))).as_quat()
    paths = {}
    for name, t, rows in [("ref", tr, ref), ("est", te, np.c_[pe, qe]), ("noisy", tf, np.c_[pf, qf])]:
        paths[name] = str(d / (name + ".txt"))
        write_ns(paths[name], t, rows)
    return paths


def load_ns(path):
    """(int64 stamps, (n, 7) poses): the stamps exactly, as ROS gives them"""
    return np.loadtxt(path, usecols=0, dtype=np.int64), np.loadtxt(path, usecols=range(1, 8))


@pytest.mark.parametrize("args,kw", CASES)
def test_evaluate_ns_equals_tool(ns_files, args, kw):
    ref, est = ns_files["ref"], ns_files["est"]
    pairs, scale, blocks = parse_eval(run_tool(["eval", "--ref", ref, "--est", est, "--time-unit", "ns"] + args))
    got = garotor.evaluate(load_ns(ref), load_ns(est), time_unit="ns", **kw)
    assert_same_report(got, pairs, scale, blocks, kw)
    r = garotor.rpe(load_ns(ref), load_ns(est), time_unit="ns", **kw)
    assert np.array_equal(r["rpe_rot"]["errors"], got["rpe_rot"]["errors"])


def test_rows_and_pairs_agree(ns_files, files):
    """an (n, 8) array and the tuple (times, poses) are read alike; an
    integer (n, 8) array keeps its stamps exact too"""
    (tr, _), (te, E) = load_ns(ns_files["ref"]), load_ns(ns_files["est"])
    still = np.tile([0, 0, 0, 0, 0, 0, 1], (len(tr), 1))
    a = garotor.ape(np.c_[tr, still], (te, E), time_unit="ns", offset=0.0025)
    b = garotor.ape((tr, still.astype(float)), (te, E), time_unit="ns", offset=0.0025)
    assert a["pairs"] > 200 and np.array_equal(a["ref_index"], b["ref_index"])
    assert np.array_equal(a["ape_trans"]["errors"], b["ape_trans"]["errors"])
    ref, est = np.loadtxt(files["ref"]), np.loadtxt(files["est"])
    x = garotor.evaluate(ref, est, align="se3", offset=0.003)
    y = garotor.evaluate((ref[:, 0], ref[:, 1:]), (est[:, 0], est[:, 1:]), align="se3", offset=0.003)
    assert np.array_equal(x["est_index"], y["est_index"]) and x["rpe_rot"]["rmse"] == y["rpe_rot"]["rmse"]


@pytest.mark.parametrize("spacing,smooth", [(0.5, 0.0), (0.31, 0.1), (1 / 3, 0.0)])
def test_fit_ns_equals_tool(ns_files, tmp_path, spacing, smooth):
    ctl = str(tmp_path / "controls.txt")
    out = run_tool(["fit", "--in", ns_files["noisy"], "--spacing", repr(spacing), "--smooth", repr(smooth),
                    "--controls", ctl, "--time-unit", "ns"])
    rows = parse_rows(out)
    t, P = load_ns(ns_files["noisy"])
    got = garotor.fit((t, P), spacing, smooth=smooth, time_unit="ns")
    assert np.array_equal(got["fitted"][:, 1:], rows[:, 1:8])
    assert np.array_equal(got["residuals"], rows[:, 8:])
    assert got["times"].dtype == np.int64 and np.array_equal(got["times"], t)
    assert np.array_equal(got["times"], [int(line.split()[0]) for line in out.splitlines()])
    assert np.array_equal(got["fitted"][:, 0], t.astype(float))
    c = parse_rows(open(ctl).read())
    assert np.array_equal(got["controls"], c)  # the knots' nearest doubles, as loadtxt reads the tool's
    knots = [line.split()[0] for line in open(ctl)]
    if spacing == 1 / 3:  # 333333333.33333331 ns: not whole, the nearest doubles
        assert got["control_times"].dtype == np.float64 and np.array_equal(got["control_times"], c[:, 0])
    else:
        assert got["control_times"].dtype == np.int64
        assert np.array_equal(got["control_times"], [int(k) for k in knots])


def tool_error(args):
    r = subprocess.run([_tool_path()] + args, capture_output=True, text=True)
    assert r.returncode == 2 and r.stdout == ""
    return r.stderr.strip()


def test_unit_refused_as_the_tool_refuses(ns_files, tmp_path):
    """without time_unit, a first stamp that is a whole number of 12 digits
    or more is refused, in the tool's words with Python's spelling"""
    ref, est = ns_files["ref"], ns_files["est"]
    msg = tool_error(["eval", "--ref", ref, "--est", est])
    want = msg.split(": ", 2)[2].replace("--time-unit ns", "time_unit='ns'").replace("--time-unit s", "time_unit='s'")
    assert "looks like nanoseconds (a whole number of 19 digits)" in want
    with pytest.raises(garotor.Error) as e:
        garotor.evaluate(load_ns(ref), load_ns(est))
    assert str(e.value) == "evaluate: ref: index 0: invalid argument: " + want
    with pytest.raises(garotor.Error, match=r"fit: poses: index 0: .* looks like nanoseconds"):
        garotor.fit(load_ns(ns_files["noisy"]), 0.5)
    # a float64 array of the same stamps is refused alike (1.7e+18: 19 digits)
    t, P = load_ns(ref)
    with pytest.raises(garotor.Error, match=r"the time 1.70000000000000\d*e\+18 looks like nanoseconds"):
        garotor.ape((t.astype(float), P), load_ns(est))
    # epoch milliseconds: 13 digits
    ms = str(tmp_path / "ms.txt")
    write_ns(ms, t // 1_000_000, P)
    msg = tool_error(["fit", "--in", ms, "--spacing", "0.5"])
    want = msg.split(": ", 2)[2].replace("--time-unit takes s or ns", "time_unit takes 's' or 'ns'")
    want = want.replace("--time-unit s", "time_unit='s'")
    with pytest.raises(garotor.Error) as e:
        garotor.fit((t // 1_000_000, P), 0.5)
    assert str(e.value) == "fit: poses: index 0: invalid argument: " + want
    # time_unit='s' says they are seconds, as --time-unit s does; the estimate's first stamp is checked too
    garotor.ape((t // 1_000_000, P), (t // 1_000_000, P), time_unit="s")
    with pytest.raises(garotor.Error, match="est: index 0: .*looks like milliseconds"):
        garotor.ape((np.arange(len(t), dtype=float), P), (t // 1_000_000, P))
    with pytest.raises(ValueError, match="time_unit must be 's' or 'ns', not 'ms'"):
        garotor.evaluate(load_ns(ref), load_ns(est), time_unit="ms")
    with pytest.raises(garotor.Error, match=r"est: index 2: .*est\[0\]\[2\] = 0.5 is not a whole number \(time_unit='ns'"):
        garotor.evaluate(load_ns(ref), (np.array([1e18, 2e18, 0.5]), P[:3]), time_unit="ns")
    with pytest.raises(ValueError, match=r"or a tuple \(times \(n,\), poses \(n, 7\)\), with n >= 4, not shapes \(3\) and \(4, 7\)"):
        garotor.fit((t[:3], P[:4]), 0.5, time_unit="ns")


def test_docs_session():
    """the ```pycon session of docs/python.md's "Evaluating and fitting
    trajectories", run as a doctest: it prints what it shows"""
    import doctest

    import docpage
    blocks = docpage.blocks("pycon", "Evaluating and fitting trajectories")
    assert len(blocks) == 1
    test = doctest.DocTestParser().get_doctest(blocks[0], {}, "python.md", "python.md", 0)
    runner = doctest.DocTestRunner()
    runner.run(test)
    assert runner.summarize(verbose=False).failed == 0
