"""A Path used from several threads (docs/python.md, "Threads"): sample,
velocity, acceleration and the attributes while another thread appends keys.

Each call sees the path before or after an append, never one half way
through: a result is that of the Path built from all the keys, bit for bit,
or, for a time past the last key so far, a garotor.Error naming the range.
"""
import sys
import threading
import time

import numpy as np
import pytest

import garotor

N = 64  # keys at the end
JOIN_TIMEOUT = 120  # seconds: a deadlock fails the test instead of hanging it


@pytest.fixture(autouse=True)
def quick_switches():
    """Threads take turns with the GIL more often: more interleavings, and the
    appender waits less for its turn."""
    before = sys.getswitchinterval()
    sys.setswitchinterval(1e-5)
    yield
    sys.setswitchinterval(before)


@pytest.mark.parametrize("scheme", ["screw", "bspline"])
def test_sample_while_appending(rng, scheme):
    times = 0.25 * np.arange(N)
    K = garotor.exp(rng.normal(size=(N, 6)))
    full = garotor.Path(times, K, scheme=scheme)
    first = 8  # the first chunk of times below is in the range of these keys
    grown = garotor.Path(times[:first], K[:first], scheme=scheme, capacity=N)
    t0, t1 = full.range
    ts = np.linspace(t0, t1, 2000)
    want = {kind: getattr(full, kind)(ts) for kind in ("sample", "velocity", "acceleration")}
    chunks = np.array_split(np.arange(len(ts)), 40)
    appending = threading.Event()
    appending.set()
    start = threading.Barrier(5)  # the four readers and the appender
    failures = []
    seen = {kind: [0, 0] for kind in ("sample", "velocity", "acceleration", "attributes")}

    def reader(kind):
        call = getattr(grown, kind)
        try:
            start.wait()
            while True:  # at least once, until the appends are done
                for idx in chunks:
                    try:
                        got = call(ts[idx])
                    except garotor.Error as e:  # past the keys so far, as the later chunks
                        assert "outside the path's range" in str(e), str(e)
                        seen[kind][1] += 1
                        break
                    assert np.array_equal(got, want[kind][idx]), kind
                    seen[kind][0] += 1
                if not appending.is_set():
                    break
        except Exception as e:  # reported by the main thread
            failures.append(e)

    def attributes():
        try:
            start.wait()
            while True:
                got = grown.times
                n = len(got)
                assert first <= n <= N and np.array_equal(got, times[:n])
                r0, r1 = grown.range
                assert r0 == t0 and r1 in times
                assert repr(grown).startswith("<garotor.Path: %s on cga, " % scheme)
                seen["attributes"][0] += 1
                if not appending.is_set():
                    break
        except Exception as e:
            failures.append(e)

    threads = [threading.Thread(target=reader, args=(kind,), daemon=True)
               for kind in ("sample", "velocity", "acceleration")]
    threads.append(threading.Thread(target=attributes, daemon=True))
    for th in threads:
        th.start()
    try:
        start.wait(JOIN_TIMEOUT)
        for i in range(first, N):
            grown.append(times[i], K[i])
            time.sleep(1e-4)  # the readers run meanwhile (an append alone is quicker than a GIL switch)
    finally:
        appending.clear()
    for th in threads:
        th.join(JOIN_TIMEOUT)
        assert not th.is_alive(), "a reader did not finish (deadlock?)"
    assert not failures, failures
    for kind, (good, _) in seen.items():
        assert good > 0, kind
    assert np.array_equal(grown.times, times)
    for kind in want:
        assert np.array_equal(getattr(grown, kind)(ts), want[kind])


def test_two_appenders(rng):
    """Two threads appending the same keys: a key either goes in or is
    refused (the other thread got there first, or filled the path); the keys
    that went in make the path, bit for bit."""
    times = 0.5 * np.arange(N)
    K = garotor.exp(rng.normal(size=(N, 6)))
    grown = garotor.Path(times[:2], K[:2], capacity=N)
    failures = []

    def appender():
        try:
            for i in range(2, N):
                try:
                    grown.append(times[i], K[i])
                except ValueError as e:
                    # the key, or the last one (full), is in already
                    assert "after the last key's time" in str(e) or "full" in str(e), str(e)
        except Exception as e:
            failures.append(e)

    threads = [threading.Thread(target=appender, daemon=True) for _ in range(2)]
    for th in threads:
        th.start()
    for th in threads:
        th.join(JOIN_TIMEOUT)
        assert not th.is_alive(), "an appender did not finish (deadlock?)"
    assert not failures, failures
    got = grown.times
    idx = np.searchsorted(times, got)
    assert len(got) >= 3 and got[-1] == times[-1] and np.array_equal(times[idx], got)
    ts = np.linspace(*grown.range, 500)
    assert np.array_equal(grown.sample(ts), garotor.Path(times[idx], K[idx]).sample(ts))
