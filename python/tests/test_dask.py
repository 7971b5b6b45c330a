"""garotor.dask on a distributed.LocalCluster of 2 worker processes, one
thread each (issue 30; docs/python.md, "Beyond one machine"): every array is
cut in chunks that the two workers share (the task stream shows both
workers computing, neither all the chunks), and every result equals the
single-process call's bit for bit.

The cluster is started once for the module (a few seconds), by replaying
the session of docs/python.md's "Beyond one machine", which makes it; the
tests then use its client. Skipped, with the reason, where dask or
distributed is not installed (Debian: python3-dask python3-distributed).
"""
import doctest
import os
import pathlib

import numpy as np
import pytest

import docpage
import garotor

dask = pytest.importorskip("dask", reason="dask is not installed (Debian: python3-dask)")
distributed = pytest.importorskip("distributed", reason="distributed is not installed (Debian: python3-distributed)")
import dask.array as da  # noqa: E402

import garotor.dask as gd  # noqa: E402

DOC = docpage.DOC


def doc_session():
    """The ```pycon block of docs/python.md's section "Beyond one machine"."""
    blocks = docpage.blocks("pycon", "Beyond one machine")
    assert len(blocks) == 1, "docs/python.md's 'Beyond one machine' should show one ```pycon session"
    return blocks[0]


@pytest.fixture(scope="module")
def client(tmp_path_factory):
    """The docs' session, replayed by doctest in a scratch directory: it
    starts the cluster, and its client serves the tests below."""
    cwd = os.getcwd()
    os.chdir(tmp_path_factory.mktemp("beyond"))
    globs = {}
    try:
        parser = doctest.DocTestParser()
        runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
        test = parser.get_doctest(doc_session(), globs, "docs/python.md, Beyond one machine", str(DOC), 0)
        runner.run(test, clear_globs=False)
        globs = test.globs
    finally:
        os.chdir(cwd)
    c = globs.get("client")
    try:
        assert runner.failures == 0, "the session of docs/python.md prints differently now (see above)"
        assert isinstance(c, distributed.Client)
        yield c
    finally:
        if c is not None:
            c.close()
            c.cluster.close()


def both_workers(client, fn):
    """fn() under the task stream: its result, after checking that the two
    worker processes both computed chunks (so neither held all the data)."""
    with distributed.get_task_stream(client) as ts:
        r = fn()
    workers = {t["worker"] for t in ts.data}
    assert len(client.scheduler_info()["workers"]) == 2
    assert len(workers) == 2, workers
    return r


def test_cluster_is_two_processes(client):
    info = client.scheduler_info()["workers"]
    assert len(info) == 2 and all(w["nthreads"] == 1 for w in info.values())
    pids = client.run(os.getpid)
    assert len(set(pids.values())) == 2 and os.getpid() not in pids.values()


@pytest.mark.parametrize("group", ["cga", "matrix", "affine"])
def test_exp_log_compose_inverse_apply(client, rng, group):
    xi = rng.normal(size=(1200, 6))
    if group == "affine":  # generators (last row zero), as garotor.exp takes them
        xi = garotor.log(garotor.exp(xi), group="matrix")
        xi = np.array([[[0.0, -w[2], w[1], w[3]], [w[2], 0.0, -w[0], w[4]], [-w[1], w[0], 0.0, w[5]],
                        [0.0, 0.0, 0.0, 0.0]] for w in xi])
    # the core dimension split in two chunks too: garotor.dask joins it
    x = da.from_array(xi, chunks=(300,) + (3,) * (xi.ndim - 1))
    T = garotor.exp(xi, group=group)
    got = both_workers(client, lambda: gd.exp(x, group=group).compute())
    assert got.tobytes() == T.tobytes()
    Td = da.from_array(T, chunks=(400, 4, 4))
    assert both_workers(client, lambda: gd.log(Td, group=group).compute()).tobytes() == \
        garotor.log(T, group=group).tobytes()
    # broadcast: (3, 1200) against (1200,) motions, chunked differently
    B = garotor.exp(rng.normal(size=(3, 1, 6)))
    want = garotor.compose(B, T, group=group)
    got = gd.compose(da.from_array(B, chunks=(1, 1, 4, 4)), Td, group=group).compute()
    assert got.shape == (3, 1200, 4, 4) and got.tobytes() == want.tobytes()
    assert gd.inverse(Td, group=group).compute().tobytes() == garotor.inverse(T, group=group).tobytes()
    pts = rng.normal(size=(1200, 3))
    got = gd.apply(Td, da.from_array(pts, chunks=(500, 3)), group=group).compute()
    assert got.tobytes() == garotor.apply(T, pts, group=group).tobytes()


def test_path_at_dask_times(client, rng):
    """A Path shipped to the workers (pickled once, a key of the graph),
    sampled at shuffled times in chunks: the single-process answer."""
    times = np.cumsum(rng.uniform(0.5, 1.5, size=200))
    K = garotor.exp(rng.normal(size=(200, 6)))
    for scheme in ("screw", "c2"):
        p = garotor.Path(times, K, scheme=scheme)
        t = rng.uniform(times[0], times[-1], size=(20, 100))
        td = da.from_array(t, chunks=(5, 50))
        got = both_workers(client, lambda: gd.sample(p, td).compute())
        assert got.shape == (20, 100, 4, 4) and got.tobytes() == p.sample(t).tobytes()
        assert gd.velocity(p, td).compute().tobytes() == p.velocity(t).tobytes()
        assert gd.acceleration(p, td).compute().tobytes() == p.acceleration(t).tobytes()


def test_errors_come_back(client, rng):
    """garotor.Error raised on a worker reaches the caller with its index
    (of the element in its chunk) and status."""
    xi = rng.normal(size=(100, 6))
    xi[70, 2] = np.nan
    with pytest.raises(garotor.Error, match=r"^exp: index 20: not finite") as e:
        gd.exp(da.from_array(xi, chunks=(50, 6))).compute()
    assert e.value.status == -1 and e.value.index == (20,)
    p = garotor.Path([0.0, 1.0], garotor.exp(rng.normal(size=(2, 6))))
    with pytest.raises(garotor.Error, match="outside the path's range"):
        gd.sample(p, da.from_array(np.array([0.5, 2.0]), chunks=1)).compute()
    with pytest.raises(ValueError, match=r"shape \(\.\.\., 6\)"):
        gd.exp(da.zeros((4, 5)))


def write_tum(path, rng, n, start):
    """A TUM log: 4-decimal stamps from `start` at about 30 Hz, positions and
    quaternions rounded to 4 decimals (norms off by up to about 1e-4)."""
    T = garotor.exp(np.cumsum(0.05 * rng.normal(size=(n, 6)), axis=0))
    P = garotor.to_pose(T)
    steps = np.cumsum(rng.integers(300, 367, size=n)) - 300
    with open(path, "w") as f:
        f.write("# timestamp tx ty tz qx qy qz qw\n")
        for s, row in zip(steps, P):
            f.write("%d.%04d %s\n" % (start + s // 10000, s % 10000, " ".join("%.4f" % v for v in row)))


def test_pose_file_pipeline(client, rng, tmp_path):
    files = []
    for i in range(4):
        f = tmp_path / ("walk%d.txt" % i)
        write_tum(f, rng, 80 + 10 * i, 1305031102 + 100 * i)
        files.append(str(f))
    out = tmp_path / "out"
    out.mkdir()
    bag = gd.resample_files(files, rate=100, out_dir=str(out), scheme="lihao3")
    assert bag.npartitions == 4
    res = both_workers(client, bag.compute)
    assert [r["file"] for r in res] == files
    here = tmp_path / "here"
    here.mkdir()
    for f, r in zip(files, res):
        one = gd.resample_file(f, 100, str(here), scheme="lihao3")
        assert r["out"] == str(out / os.path.basename(f))
        assert (r["keys"], r["samples"]) == (one["keys"], one["samples"]) and r["samples"] > 200
        assert pathlib.Path(r["out"]).read_bytes() == pathlib.Path(one["out"]).read_bytes()
        # the file holds the Path's samples, as garotor computes them here
        stamps, poses = gd.read_tum(f)
        t = np.array([float(s) for s in stamps]) - float(stamps[0])
        rows = np.loadtxt(r["out"], dtype=str)
        assert rows[0, 0] == stamps[0] and rows[1, 0].endswith(".%04d" % ((int(stamps[0][-4:]) + 100) % 10000))
        got = rows[:, 1:].astype(float)
        p = garotor.Path(gd._relative(stamps), poses, scheme="lihao3")
        want = garotor.to_pose(p.sample(np.arange(r["samples"]) / 100))
        assert got.tobytes() == want.tobytes()
        assert np.max(np.abs(t - gd._relative(stamps))) < 1e-6
