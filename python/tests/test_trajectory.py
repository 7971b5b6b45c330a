"""garotor.evaluate, ape, rpe, align and fit (docs/python.md, "Evaluating and
fitting trajectories") against the tool's `garotor eval` and `garotor fit` on
the same files, bit for bit (the tool prints the shortest decimal of each
double, which reads back as the same double), and against evo's formulas
recomputed in numpy by tests/eval_check.py.

The stamps are epoch seconds with binary fractions (k/64 s plus multiples of
2^-12 s), exact as doubles and written as their exact decimals, so that the
module's t - t[0] and the tool's exact decimal difference are the same
number."""
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
            # the stamp's exact decimal (the tool reads stamps as exact decimals,
            # and repr's shortest text is not the double's exact value)
            f.write("%.12f " % r[0] + " ".join(repr(float(x)) for x in r[1:]) + "\n")


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
    assert got["pairs"] == pairs
    if kw.get("align") == "sim3":
        assert got["scale"] == scale
    for key, stats in blocks.items():
        for name, v in stats.items():
            assert got[key][name] == v, (key, name, got[key][name], v)
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
