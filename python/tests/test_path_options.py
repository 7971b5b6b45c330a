"""garotor.Path's options against `garotor interp`'s, bit for bit on the same
input: extrapolate= (--extrapolate hold, extend, constant-velocity) for the
poses and every derivative and frame, clip (--clip), normalize=
(--normalize, quaternions and matrices), the growth warning (its words and
its threshold), min_gap= and dedup= (--min-gap, --dedup). The tool runs on
the text Python writes (repr), so both read the same decimals."""
import os
import pickle
import shutil
import subprocess
import warnings

import numpy as np
import pytest

import garotor

MODES = ["hold", "extend", "constant-velocity"]
FRAMES = ["body", "spatial", "world"]


def _tool_path():
    path = os.environ.get("GAROTOR_TOOL") or shutil.which("garotor")
    if not path or not os.access(path, os.X_OK):
        pytest.skip("the garotor tool is not found (set GAROTOR_TOOL)")
    return path


def run_tool(args, rows, tmp_path, check=True):
    """The tool on rows written with repr (the text Path reads its floats as);
    (output as an array, output as text rows, standard error)."""
    f = tmp_path / "keys.txt"
    f.write_text("\n".join(" ".join(repr(float(x)) for x in row) for row in rows) + "\n")
    r = subprocess.run([_tool_path(), "interp", "--in", os.fspath(f)] + list(args), capture_output=True,
                       text=True)
    if check:
        assert r.returncode == 0, r.stderr
    lines = [line.split() for line in r.stdout.splitlines() if line.strip()]
    out = np.array([[float(x) for x in line] for line in lines]) if lines else np.zeros((0, 0))
    return out, lines, r


def times_file(tmp_path, t):
    f = tmp_path / "times.txt"
    f.write_text("\n".join(repr(float(x)) for x in t) + "\n")
    return os.fspath(f)


def pose_keys(rng, n, t0=0.0):
    times = t0 + np.concatenate([[0.0], np.cumsum(rng.uniform(0.5, 1.5, size=n - 1))])
    P = garotor.to_pose(garotor.exp(0.8 * rng.normal(size=(n, 6))))
    return times, P


@pytest.mark.parametrize("scheme", ["screw", "lihao3", "decoupled", "decoupled-c2", "c2", "bspline"])
@pytest.mark.parametrize("mode", MODES)
def test_extrapolate_equals_tool(rng, tmp_path, scheme, mode):
    n = 6
    times, P = pose_keys(rng, n)
    if scheme == "bspline":
        times = np.arange(n) * 0.75
    p = garotor.Path(times, P, scheme=scheme)
    r0, r1 = p.range
    t = np.concatenate([[r0 - 2.5, r0 - 0.3, r0], np.linspace(r0, r1, 7), [r1, r1 + 0.01, r1 + 1.7]])
    rows = np.column_stack([times, P])
    for frame in FRAMES:
        out, _, _ = run_tool(["--scheme", scheme, "--format", "pose", "--times", times_file(tmp_path, t),
                              "--extrapolate", mode, "--with", "velocity,acceleration,jerk", "--frame", frame],
                             rows, tmp_path)
        assert np.array_equal(out[:, 0], t)
        assert np.array_equal(p.sample_pose(t, extrapolate=mode), out[:, 1:8])
        assert np.array_equal(p.velocity(t, frame=frame, extrapolate=mode), out[:, 8:14])
        assert np.array_equal(p.acceleration(t, frame=frame, extrapolate=mode), out[:, 14:20])
        assert np.array_equal(p.jerk(t, frame=frame, extrapolate=mode), out[:, 20:26])
    # matrices: the same poses as the tool's --format mat
    out, _, _ = run_tool(["--scheme", scheme, "--times", times_file(tmp_path, t), "--extrapolate", mode],
                         np.column_stack([times, garotor.from_pose(P).reshape(n, 16)]), tmp_path)
    assert np.array_equal(p.sample(t, extrapolate=mode).reshape(-1, 16), out[:, 1:])
    # inside the range every mode is the path itself
    inside = np.linspace(r0, r1, 11)
    assert np.array_equal(p.sample(inside, extrapolate=mode), p.sample(inside))
    assert np.array_equal(p.velocity(inside, extrapolate=mode, frame="world"), p.velocity(inside, frame="world"))


@pytest.mark.parametrize("mode", MODES)
def test_extrapolate_in_long_arrays_is_each_time_alone(rng, mode):
    # sample() takes arrays in blocks through ga_path_sample, which refuses a
    # time outside the range; from that block on the times go one by one
    # through the extrapolation: the same numbers as each time alone
    times, P = pose_keys(rng, 7)
    p = garotor.Path(times, P, scheme="c2")
    r0, r1 = p.range
    t = rng.uniform(r0, r1, size=700)
    t[[300, 301, 555]] = [r1 + 0.4, r0 - 1.1, r1 + 2.0]
    each = np.stack([p.sample(t[i:i + 1], extrapolate=mode)[0] for i in range(t.size)])
    assert np.array_equal(p.sample(t, extrapolate=mode), each)
    assert np.array_equal(p.sample(t[:300], extrapolate=mode), p.sample(t[:300]))


def test_extrapolate_modes_mean_what_they_say(rng):
    times, P = pose_keys(rng, 5)
    p = garotor.Path(times, P, scheme="c2")
    r0, r1 = p.range
    # hold: the end key, nothing moves
    assert np.array_equal(p.sample([r1 + 3.0], extrapolate="hold")[0], p.sample([r1])[0])
    assert np.abs(p.sample([r0 - 3.0], extrapolate="hold")[0] - garotor.from_pose(P[0])).max() < 1e-15
    assert not p.velocity([r0 - 1.0, r1 + 1.0], extrapolate="hold").any()
    # constant-velocity: the end pose moved by its body velocity, which stays
    v1 = p.velocity([r1])[0]
    E = p.sample([r1])[0]
    assert np.allclose(p.sample([r1 + 0.7], extrapolate="constant-velocity")[0],
                       garotor.compose(E, garotor.exp(0.7 * v1)), atol=1e-13)
    assert np.allclose(p.velocity([r1 + 5.0], extrapolate="constant-velocity")[0], v1, atol=1e-15)
    # extend: the end segment's formula, continuous across the end
    h = 1e-7
    a, b = p.sample([r1 - h, r1 + h], extrapolate="extend")
    assert np.abs(a - b).max() < 1e-5


def test_extrapolate_errors(rng):
    times, P = pose_keys(rng, 4)
    p = garotor.Path(times, P)
    with pytest.raises(ValueError, match="extrapolate must be 'error', 'hold', 'extend' or 'constant-velocity'"):
        p.sample([0.0], extrapolate="linear")
    with pytest.raises(ValueError, match="extrapolate must be"):
        p.velocity([0.0], extrapolate="clamp")
    # 'error' (and None) is the default: outside the range is an error naming the index
    with pytest.raises(garotor.Error, match=r"index 1: .*outside the path's range"):
        p.sample([times[1], times[-1] + 1.0], extrapolate="error")
    # a time so far out that extend overflows names its index and the mode
    with pytest.raises(garotor.Error, match=r"index 1: .*extrapolated \(extrapolate='extend'\)"):
        p.sample([times[0], 1e300], extrapolate="extend")


@pytest.mark.parametrize("ns", [False, True])
def test_clip_equals_tool(rng, tmp_path, ns):
    times, P = pose_keys(rng, 5)
    t = np.array([-0.5, times[0], 0.3, times[-1], times[-1] + 1e-9, times[-1] + 2.0, -1e-12, times[-1] - 0.25])
    if ns:  # whole nanoseconds, epoch stamps: exact int64, no float in between
        T0 = 1_700_000_000_000_000_000
        tk = T0 + np.round(times * 1e9).astype(np.int64)
        tt = T0 + np.round(t * 1e9).astype(np.int64)
        tt[4], tt[6] = tk[-1] + 1, tk[0] - 1
        p = garotor.Path(tk, P, time_unit="ns")
        rows_t, args = [str(x) for x in tk], ["--time-unit", "ns"]
        tf = tmp_path / "times.txt"
        tf.write_text("\n".join(str(x) for x in tt) + "\n")
        tfile = os.fspath(tf)
    else:
        p = garotor.Path(times, P)
        tt = t
        tfile = times_file(tmp_path, t)
        args = []
    kept = p.clip(tt)
    assert kept.dtype == (np.int64 if ns else np.float64)
    if ns:
        f = tmp_path / "keys.txt"
        f.write_text("\n".join(" ".join([rows_t[i]] + [repr(float(x)) for x in P[i]]) for i in range(5)) + "\n")
        r = subprocess.run([_tool_path(), "interp", "--in", os.fspath(f), "--format", "pose", "--times", tfile,
                            "--clip"] + args, capture_output=True, text=True, check=True)
        lines = [line.split() for line in r.stdout.splitlines()]
        assert [int(x[0]) for x in lines] == kept.tolist()
        out = np.array([[float(x) for x in line[1:]] for line in lines])
    else:
        out, lines, _ = run_tool(["--format", "pose", "--times", tfile, "--clip"], np.column_stack([times, P]),
                                 tmp_path)
        assert [float(x[0]) for x in lines] == kept.tolist()
        out = out[:, 1:]
    assert len(kept) == 4  # the key times themselves are in; 1e-9 s (1 ns) past either end is not
    assert np.array_equal(p.sample_pose(kept), out)
    # nothing inside: an empty array, as the tool writes no line
    assert p.clip(np.array([-5.0, 1e9] if not ns else np.array([1, 2]))).shape == (0,)
    with pytest.raises(garotor.Error, match=r"Path.clip: index 1: not finite"):
        garotor.Path(times, P).clip([0.5, np.nan])


def test_normalize_poses_equal_tool(rng, tmp_path):
    times, P = pose_keys(rng, 6)
    P4 = np.round(P, 4)  # quaternions written with 4 decimals: off unit norm by up to ~1e-4
    assert np.abs(np.linalg.norm(P4[:, 3:], axis=1) - 1).max() > 1e-9
    t = np.linspace(times[0], times[-1], 23)
    for scheme in ("screw", "c2", "lihao2"):
        out, _, _ = run_tool(["--scheme", scheme, "--format", "pose", "--normalize", "--times",
                              times_file(tmp_path, t)], np.column_stack([times, P4]), tmp_path)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", RuntimeWarning)  # lihao2 may break the growth rule
            p = garotor.Path(times, P4, scheme=scheme, normalize=True)
        assert np.array_equal(p.sample_pose(t), out[:, 1:])
    # without it: refused, naming the row, its norm and normalize=True
    with pytest.raises(garotor.Error, match=r"Path: poses: index \d: not a rigid motion: poses\[\d, 3:7\] "
                       r"\(qx qy qz qw\): the quaternion has norm .*normalize=True accepts up to 1e-3"):
        garotor.Path(times, P4)
    far = P.copy()
    far[2, 3:] *= 1.01
    with pytest.raises(garotor.Error, match=r"index 2: .*farther from 1 than normalize=True accepts"):
        garotor.Path(times, far, normalize=True)


@pytest.mark.parametrize("group", ["cga", "matrix"])
def test_normalize_matrices_equal_tool(rng, tmp_path, group):
    times, P = pose_keys(rng, 5)
    K = garotor.from_pose(P)
    K[:, :3, :3] += 2e-5 * rng.normal(size=(5, 3, 3))  # within 1e-3 of a rotation, not 1e-9
    t = np.linspace(times[0], times[-1], 17)
    out, _, _ = run_tool(["--group", group, "--normalize", "--times", times_file(tmp_path, t)],
                         np.column_stack([times, K.reshape(5, 16)]), tmp_path)
    p = garotor.Path(times, K, group=group, normalize=True)
    assert np.array_equal(p.sample(t).reshape(-1, 16), out[:, 1:])
    with pytest.raises(garotor.Error, match=r"index 0: .*poses\[0\] is not a rigid motion to 1e-9 .*normalize=True"):
        garotor.Path(times, K, group=group)
    with pytest.raises(ValueError, match="normalize applies to the groups 'cga' and 'matrix'"):
        garotor.Path(times, K, group="affine", normalize=True)


def growth_keys():
    # lihao2's recurrence on keys that turn back and forth: its velocity grows
    # past 3 times the fastest chord (docs/schemes.md, "lihao2: growth")
    n = 9
    times = np.arange(n) * 0.5
    xi = np.zeros((n, 6))
    xi[:, 2] = 0.6 * (-1.0) ** np.arange(n)
    xi[:, 3] = np.arange(n) * 0.2
    return times, garotor.to_pose(garotor.exp(xi))


def test_growth_warning_equals_tool(tmp_path):
    times, P = growth_keys()
    _, _, r = run_tool(["--scheme", "lihao2", "--format", "pose", "--samples", "3"], np.column_stack([times, P]),
                       tmp_path)
    tool_msg = r.stderr.strip()
    assert "warning" in tool_msg
    with pytest.warns(RuntimeWarning) as rec:
        garotor.Path(times, P, scheme="lihao2")
    assert len(rec) == 1
    msg = str(rec[0].message)
    # the same words, ratio and times; the tool names the file and its lines,
    # the Path the indices
    lines = [int(x) for x in tool_msg.split("(lines ")[1].split(")")[0].split(" to ")]
    expect = tool_msg.split(": warning: ", 1)[1].split(": ", 1)[1]
    expect = expect.replace("(lines %d to %d)" % tuple(lines), "(indices %d to %d)" % (lines[0] - 1, lines[1] - 1))
    assert msg == "Path: " + expect
    # the rule's threshold: screw on the same keys does not warn, nor the tool
    _, _, r = run_tool(["--scheme", "screw", "--format", "pose", "--samples", "3"], np.column_stack([times, P]),
                       tmp_path)
    assert r.stderr == ""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        garotor.Path(times, P, scheme="screw")
        # warnings as errors: the Path is not built
        with pytest.raises(RuntimeWarning, match="grows past 3 times the fastest chord"):
            garotor.Path(times, P, scheme="lihao2")


def near_dup_keys():
    # a pose logged twice 100 us apart in a 30 Hz log (docs/tool.md), and
    # the first key twice too
    times = np.array([0.0, 0.0001, 0.0333, 0.0334, 0.0666, 0.1, 0.1333])
    P = np.zeros((7, 7))
    P[:, 0] = [0.0, 0.00012, 0.1, 0.1001, 0.2, 0.3, 0.4]
    P[:, 1] = [0.0, 0.0, 0.01, 0.0101, 0.03, 0.02, 0.0]
    P[:, 5] = np.sin([0.0, 0.00005, 0.05, 0.05001, 0.1, 0.12, 0.1])
    P[:, 6] = np.sqrt(1 - P[:, 5] ** 2)
    return times, P


@pytest.mark.parametrize("ns", [False, True])
@pytest.mark.parametrize("scheme", ["screw", "c2", "lihao3"])
def test_dedup_equals_tool(tmp_path, ns, scheme):
    times, P = near_dup_keys()
    if ns:  # epoch nanoseconds: the merged stamps in whole ns, exact
        T0 = 1_305_031_102_175_800_000
        tk = T0 + np.round(times * 1e9).astype(np.int64)
        texts = [str(x) for x in tk]
        args = ["--time-unit", "ns"]
    else:  # epoch seconds: the merged times' stamps exact in decimal
        T0 = 1305031102.1758
        tk = np.array([T0 + x for x in [0.0, 0.0001, 0.0333, 0.0334, 0.0666, 0.1, 0.1333]])
        texts = [repr(x) for x in tk]
        args = []
    f = tmp_path / "keys.txt"
    f.write_text("\n".join(" ".join([texts[i]] + [repr(float(x)) for x in P[i]]) for i in range(7)) + "\n")
    tool = [_tool_path(), "interp", "--in", os.fspath(f), "--format", "pose", "--scheme", scheme] + args
    # without dedup: refused, naming the later key of the first pair, as the tool does
    r = subprocess.run(tool + ["--samples", "5"], capture_output=True, text=True)
    assert r.returncode == 2
    tool_why = r.stderr.strip().split(": ", 2)[2]
    with pytest.raises(garotor.Error) as e:
        garotor.Path(tk, P, scheme=scheme, time_unit="ns" if ns else "s", min_gap="auto")
    msg = str(e.value)
    assert msg.startswith("Path: times: index 1: invalid argument: ")
    py_why = msg.split("invalid argument: ", 1)[1]
    assert py_why == tool_why.replace("(line 1)", "(index 0)").replace("or --min-gap 0", "or min_gap=0").replace(
        "--min-gap", "min_gap").replace("pass --dedup", "pass dedup=True")
    # and by default, as the tool's default (min_gap 'auto')
    with pytest.raises(garotor.Error) as e:
        garotor.Path(tk, P, scheme=scheme, time_unit="ns" if ns else "s")
    assert str(e.value) == msg
    # with dedup: the same keys, times and samples, bit for bit
    r = subprocess.run(tool + ["--samples", "9", "--dedup", "--with", "velocity"], capture_output=True, text=True,
                       check=True)
    lines = [line.split() for line in r.stdout.splitlines()]
    p = garotor.Path(tk, P, scheme=scheme, time_unit="ns" if ns else "s", dedup=True)
    assert len(p.times) == 5
    # the first and last samples are at the first and last key: stamped as the keys
    assert lines[0][0] == (str(p.times[0]) if ns else repr(p.times[0]))
    assert lines[-1][0] == texts[-1]
    out = np.array([[float(x) for x in line[1:]] for line in lines])
    # the sample times: the tool's stamps, read back as Path reads them
    st = np.array([int(x[0]) for x in lines]) if ns else np.array([float(x[0]) for x in lines])
    if not ns:  # a computed stamp of more digits than a double: the samples at the keys only
        keep = [i for i, x in enumerate(lines) if repr(float(x[0])) == x[0]]
        st, out = st[keep], out[keep]
    assert np.array_equal(p.sample_pose(st), out[:, :7])
    assert np.array_equal(p.velocity(st), out[:, 7:13])
    # min_gap given in the keys' unit: a gap below every spacing keeps them all
    assert len(garotor.Path(tk, P, scheme=scheme, time_unit="ns" if ns else "s", min_gap=0).times) == 7
    assert len(garotor.Path(tk, P, scheme=scheme, time_unit="ns" if ns else "s",
                            min_gap=50 if ns else 5e-8, dedup=True).times) == 7


def test_dedup_pickles_and_errors(rng):
    import pickle
    times, P = near_dup_keys()
    p = garotor.Path(times + 7.25, P, scheme="c2", dedup=True)  # the first key merged: its reference kept
    q = pickle.loads(pickle.dumps(p))
    t = np.linspace(*p.range, 13)
    assert np.array_equal(q.times, p.times) and np.array_equal(q.sample(t), p.sample(t))
    # the doc's keys: the merged key at the mean time, the mean pose
    d = garotor.Path([0, 0.0333, 0.0334, 0.0666], [[0, 0, 0, 0, 0, 0, 1], [0.1, 0, 0, 0, 0, 0, 1],
                                                   [0.1001, 0, 0, 0, 0, 0, 1], [0.2, 0, 0, 0, 0, 0, 1]], dedup=True)
    assert d.times.tolist() == [0.0, 0.0333 / 2 + 0.0334 / 2, 0.0666]
    with pytest.raises(ValueError, match="min_gap must be None, 'auto' or a number >= 0"):
        garotor.Path(times, P, min_gap=-1.0)
    with pytest.raises(ValueError, match="min_gap must be"):
        garotor.Path(times, P, min_gap="median")
    K = garotor.from_pose(P)
    with pytest.raises(ValueError, match="dedup applies to the groups 'cga' and 'matrix'"):
        garotor.Path(times, K, group="affine", dedup=True)
    # the affine group is checked all the same
    with pytest.raises(garotor.Error, match="closer than min_gap"):
        garotor.Path(times, K, group="affine", min_gap="auto")
    with pytest.raises(ValueError, match="needs one key or at least 3, got 2 after dedup"):
        garotor.Path([0, 1e-6, 1, 1 + 1e-6], P[:4], scheme="smooth", min_gap=0.01, dedup=True)


def test_append_checks_near_duplicates_as_the_tool(tmp_path):
    """Path.append refuses a key closer to the last than the Path's min_gap
    (by default 'auto': 1% of the median spacing of the keys the Path was
    built with), in the tool's words for the same keys in a file; the Path
    is unchanged and takes the next key as before"""
    n = 8
    times = np.arange(n) * 0.0333
    xi = np.zeros((n + 1, 6))
    xi[:, 3] = np.arange(n + 1) * 0.1
    xi[:, 2] = 0.05 * np.arange(n + 1)
    P = garotor.to_pose(garotor.exp(xi))
    near = times[-1] + 0.0001
    _, _, r = run_tool(["--format", "pose", "--samples", "3"], np.column_stack([np.r_[times, near], P]), tmp_path,
                       check=False)
    assert r.returncode == 2
    tool_why = r.stderr.strip().split(": ", 2)[2]
    p = garotor.Path(times, P[:n], capacity=n + 2)
    with pytest.raises(garotor.Error) as e:
        p.append(near, P[n])
    msg = str(e.value)
    assert msg.startswith("Path.append: invalid argument: ")
    want = tool_why.replace("(line %d)" % n, "(index %d)" % (n - 1)).replace("--min-gap", "min_gap").split(": pass")[0]
    assert msg.split("invalid argument: ", 1)[1] == want + (
        ": append does not merge keys (dedup=True merges those given to Path): leave this one out, or build the "
        "Path with min_gap=0 to keep such keys")
    assert len(p.times) == n  # unchanged
    # a pickled Path checks the same
    q = pickle.loads(pickle.dumps(p))
    with pytest.raises(garotor.Error, match="closer than min_gap"):
        q.append(near, P[n])
    # the next key as before: equal to the Path of all the keys, bit for bit
    p.append(times[-1] + 0.0333, P[n])
    full = garotor.Path(np.r_[times, times[-1] + 0.0333], P[: n + 1])
    s = np.linspace(0, times[-1] + 0.0333, 17)
    assert np.array_equal(p.sample(s), full.sample(s))
    # min_gap=0 keeps such keys, as --min-gap 0; a number is the gap
    z = garotor.Path(times, P[:n], capacity=n + 1, min_gap=0)
    z.append(near, P[n])
    g = garotor.Path(times, P[:n], capacity=n + 1, min_gap=0.00005)
    g.append(near, P[n])
    g = garotor.Path(times, P[:n], capacity=n + 1, min_gap=0.0002)
    with pytest.raises(garotor.Error, match=r"closer than min_gap 0.0002 s: append does not merge keys"):
        g.append(near, P[n])
    # time_unit='ns': the gap in nanoseconds
    tn = 1_700_000_000_000_000_000 + np.arange(n, dtype=np.int64) * 33_300_000
    pn = garotor.Path(tn, P[:n], capacity=n + 1, time_unit="ns")
    with pytest.raises(garotor.Error, match=r"is 1e\+05 ns after .* closer than min_gap 333000 ns \(1% of the median "
                       r"spacing, 3.33e\+07 ns\)"):
        pn.append(int(tn[-1]) + 100_000, P[n])


def test_append_warn_growth():
    """append(..., warn_growth=True): the growth rule over every key after
    the append, the warning Path(...) gives on all those keys; without it
    append does not measure the rule (a pass over every key)"""
    times, P = growth_keys()
    with pytest.warns(RuntimeWarning) as rec:
        full_msg = None
        garotor.Path(times, P, scheme="lihao2")
    full_msg = str(rec[0].message)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        p = garotor.Path(times[:3], P[:3], scheme="lihao2", capacity=len(times))
        for i in range(3, len(times)):
            p.append(times[i], P[i])  # no measure, no warning
    p = garotor.Path(times[:3], P[:3], scheme="lihao2", capacity=len(times))
    with warnings.catch_warnings(record=True) as rec:
        warnings.simplefilter("always")
        for i in range(3, len(times)):
            p.append(times[i], P[i], warn_growth=True)
    assert rec and all(issubclass(w.category, RuntimeWarning) for w in rec)
    assert str(rec[-1].message) == full_msg.replace("Path: ", "Path.append: ", 1)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        q = garotor.Path(times[:3], P[:3], scheme="screw", capacity=len(times))
        for i in range(3, len(times)):
            q.append(times[i], P[i], warn_growth=True)  # screw keeps the rule: no warning


def normalize_keys(rng, n, form):
    """n keys 0.5 s apart (bspline's even grid) off the group by more than
    1e-9 and less than 1e-3: pose rows with 4 decimals, or matrices with a
    rotation part moved by about 2e-5"""
    times = np.arange(n) * 0.5
    P = garotor.to_pose(garotor.exp(0.8 * rng.normal(size=(n, 6))))
    if form == "pose":
        K = np.round(P, 4)
        assert np.abs(np.linalg.norm(K[:, 3:], axis=1) - 1).max() > 1e-9
        return times, K, P
    K = garotor.from_pose(P)
    K[:, :3, :3] += 2e-5 * rng.normal(size=(n, 3, 3))
    return times, K, garotor.from_pose(P)


@pytest.mark.parametrize("scheme", ["screw", "bivector", "lihao2", "decoupled", "bspline"])
@pytest.mark.parametrize("form,group", [("pose", "cga"), ("pose", "matrix"), ("matrix", "cga"),
                                        ("matrix", "matrix")])
def test_append_normalizes_as_the_constructor(rng, scheme, form, group):
    """Path(..., normalize=True).append(t, key) reads the key as Path(...)
    reads its keys, projected onto the group: the Path grown key by key is
    the one built from all the keys with normalize=True, bit for bit (its
    samples, velocities and pickle), and so is a pickled copy grown after
    the pickle (the state keeps normalize=)"""
    n, m = 8, 4
    times, K, _ = normalize_keys(rng, n, form)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)  # lihao2 may break the growth rule
        try:
            full = garotor.Path(times, K, scheme=scheme, group=group, normalize=True)
        except ValueError as e:
            assert "is not defined on group" in str(e)
            pytest.skip(str(e))
        p = garotor.Path(times[:m], K[:m], scheme=scheme, group=group, normalize=True, capacity=n)
    q = pickle.loads(pickle.dumps(p))
    for i in range(m, n):
        p.append(times[i], K[i])
        q.append(times[i], K[i])
    t = np.linspace(*full.range, 41)
    for r in (p, q):
        assert np.array_equal(r.sample(t), full.sample(t))
        assert np.array_equal(r.velocity(t), full.velocity(t))
        assert np.array_equal(r.times, full.times)
        assert pickle.dumps(r) == pickle.dumps(full)  # the same keys as the group holds them, bit for bit


@pytest.mark.parametrize("form", ["pose", "matrix"])
def test_append_without_normalize_refuses_as_the_constructor(rng, form):
    """Without normalize= a key off the group is refused by append as by
    Path(...), in the same words (naming normalize=True), and the Path is
    unchanged; with it, a key farther than 1e-3 is refused"""
    n = 6
    times, K, exact = normalize_keys(rng, n, form)
    with pytest.raises(garotor.Error) as built:
        garotor.Path(times, np.concatenate([exact[:n - 1], K[n - 1:]]))
    p = garotor.Path(times[:n - 1], exact[:n - 1], capacity=n)
    with pytest.raises(garotor.Error) as appended:
        p.append(times[n - 1], K[n - 1])
    assert len(p.times) == n - 1
    name = "poses[%d%s" % (n - 1, ", " if form == "pose" else "]")
    want = str(built.value).replace("Path: poses: index %d: " % (n - 1), "Path.append: ").replace(
        name, "pose[" if form == "pose" else "pose")
    assert str(appended.value) == want and "normalize=True accepts up to 1e-3" in want
    assert appended.value.status == built.value.status
    if form == "pose":
        far = K[n - 1].copy()
        far[3:] *= 1.01
        pn = garotor.Path(times[:n - 1], K[:n - 1], capacity=n, normalize=True)
        with pytest.raises(garotor.Error, match=r"^Path.append: .*pose\[3:7\] \(qx qy qz qw\): the quaternion has "
                           r"norm 1.01.*, farther from 1 than normalize=True accepts \(1e-3\)$"):
            pn.append(times[n - 1], far)
        assert len(pn.times) == n - 1


def test_normalize_state(rng):
    """A pickle keeps normalize= where the Path has room to append (a tenth
    item, True); a state of nine items (before it) gives a Path whose append
    does not normalize; a tenth item other than a bool is refused"""
    times, K, _ = normalize_keys(rng, 5, "pose")
    p = garotor.Path(times[:4], K[:4], normalize=True, capacity=5)
    cls, args, state = p.__reduce__()[:3]
    assert len(state) == 10 and state[7] is None and state[9] is True
    assert len(garotor.Path(times[:4], K[:4], normalize=True).__reduce__()[2]) == 7  # no room: nothing to keep
    old = cls(*args)
    old.__setstate__(state[:9])
    with pytest.raises(garotor.Error, match="normalize=True accepts up to 1e-3"):
        old.append(times[4], K[4])
    bad = cls(*args)
    with pytest.raises(ValueError, match="the normalize item must be True or False"):
        bad.__setstate__(state[:9] + (1,))
