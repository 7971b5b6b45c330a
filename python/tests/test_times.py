"""Path's times: stamps read exactly (floats as their shortest decimal, int64
nanoseconds with time_unit='ns') and the path built relative to the first
key, as `garotor interp` builds its own: epoch stamps give the tool's samples
and derivatives bit for bit (docs/python.md, "Times")."""
import os
import pickle
import subprocess

import numpy as np
import pytest

import garotor
from conftest import _tool

SCHEMES = ["screw", "bivector", "smooth", "decoupled", "decoupled-c2", "c2"]


def tum_keys(rng, n):
    """n keys x y z qx qy qz qw (unit quaternions, qw > 0)."""
    q = rng.normal(size=(n, 4))
    q /= np.linalg.norm(q, axis=1)[:, None]
    q *= np.sign(q[:, 3])[:, None]
    q = q + 0.0  # no -0.0
    return np.column_stack([rng.uniform(-2, 2, size=(n, 3)), q])


def run_tool(args, text):
    path = _tool()
    if path is None:
        pytest.skip("the garotor tool is not found (set GAROTOR_TOOL)")
    r = subprocess.run([path, "interp"] + args, input=text, capture_output=True, text=True, check=True)
    return np.array([[float(x) for x in line.split()] for line in r.stdout.splitlines() if line.strip()])


def stamps(rng, n, ns):
    """Epoch stamps as text (TUM: seconds with 6 decimals; or whole
    nanoseconds of 19 digits), uneven, and the sample times among them."""
    if ns:
        t = 1_700_000_000_123_456_789 + np.cumsum(rng.integers(20_000_000, 60_000_000, size=n))
        t = t.astype(np.int64)
        at = np.sort(rng.integers(t[0], t[-1], size=30)).astype(np.int64)
        return [str(v) for v in t], t, [str(v) for v in at], at
    t = 1700000000.123456 + np.cumsum(rng.integers(20_000, 60_000, size=n)) * 1e-6
    text = ["%.6f" % v for v in t]
    at_text = ["%.6f" % v for v in np.sort(rng.uniform(t[0], t[-1], size=30))]
    return text, np.array([float(s) for s in text]), at_text, np.array([float(s) for s in at_text])


@pytest.mark.parametrize("ns", [False, True], ids=["s", "ns"])
@pytest.mark.parametrize("scheme", SCHEMES)
def test_epoch_stamps_equal_tool(rng, scheme, ns):
    n = 9
    P = tum_keys(rng, n)
    text, t, at_text, at = stamps(rng, n, ns)
    body = "".join(s + " " + " ".join("%.17g" % v for v in row) + "\n" for s, row in zip(text, P))
    unit = ["--time-unit", "ns"] if ns else ["--time-unit", "s"]
    out = run_tool(["--scheme", scheme, "--format", "pose", "--at", ",".join(at_text)] + unit, body)
    p = garotor.Path(t, P, scheme=scheme, time_unit="ns" if ns else "s")
    assert np.array_equal(p.sample_pose(at), out[:, 1:])
    # the keys are hit, at their stamps
    outk = run_tool(["--scheme", scheme, "--format", "pose", "--at", ",".join(text)] + unit, body)
    assert np.array_equal(p.sample_pose(t), outk[:, 1:])
    for frame in ("body", "world"):
        outv = run_tool(
            ["--scheme", scheme, "--format", "pose", "--at", ",".join(at_text), "--frame", frame,
             "--with", "velocity,acceleration"] + unit, body)
        assert np.array_equal(p.velocity(at, frame=frame), outv[:, 8:14])
        assert np.array_equal(p.acceleration(at, frame=frame), outv[:, 14:20])
    # the times as given: int64 nanoseconds exactly, or the floats
    assert p.times.dtype == (np.int64 if ns else np.float64)
    assert np.array_equal(p.times, t)
    r = p.range
    assert r == (t[0], t[-1]) and type(r[0]) is (int if ns else float)
    q = pickle.loads(pickle.dumps(p))
    assert np.array_equal(q.times, p.times) and q.range == p.range
    assert np.array_equal(q.sample(at), p.sample(at))


def test_ns_exact_where_float64_is_not(rng):
    """Stamps 1 ns apart at 1.7e18 ns are one float64 apart only every 256 ns:
    read as int64 they are distinct keys, at 1e-9 s apart."""
    P = tum_keys(rng, 3)
    t = np.array([1_700_000_000_000_000_000, 1_700_000_000_000_000_001, 1_700_000_000_000_000_003])
    assert len(set(t.astype(float))) == 1
    p = garotor.Path(t, P, scheme="screw", time_unit="ns")
    assert np.array_equal(p.times, t)
    assert np.array_equal(p.sample_pose(t[1:2])[0], garotor.Path(np.array([0, 1e-9, 3e-9]), P).sample_pose([1e-9])[0])
    with pytest.raises(ValueError, match="is outside the path's range \\[1700000000000000000, 1700000000000000003\\]"):
        p.sample(np.array([1_700_000_000_000_000_004]))
    with pytest.raises(ValueError, match="whole nanoseconds"):
        garotor.Path(np.array([0.5, 1, 2]), P, time_unit="ns")
    with pytest.raises(ValueError, match="time_unit must be 's' or 'ns'"):
        garotor.Path(t, P, time_unit="ms")


def test_relative_to_first_key(rng):
    """Shifted stamps give the same path: a shift of the first key's stamp
    changes nothing (exactly, for stamps whose decimals differ by the
    shift)."""
    P = tum_keys(rng, 6)
    base = np.array([0.0, 0.25, 0.5, 1.0, 1.75, 2.0])
    at = np.array([0.1, 0.3, 0.9, 1.9])
    p0 = garotor.Path(base, P, scheme="c2")
    for shift in (1700000000.0, 1e6 + 0.5):
        p = garotor.Path(base + shift, P, scheme="c2")
        assert np.array_equal(p.sample(at + shift), p0.sample(at))
        assert np.array_equal(p.velocity(at + shift), p0.velocity(at))


def test_append_ns(rng):
    P = tum_keys(rng, 5)
    t = np.array([10**18 + 10**8 * k for k in range(5)], dtype=np.int64)
    full = garotor.Path(t, P, scheme="screw", time_unit="ns")
    p = garotor.Path(t[:3], P[:3], scheme="screw", time_unit="ns", capacity=6)
    p.append(int(t[3]), P[3])
    p.append(t[4], P[4])
    assert np.array_equal(p.times, t)
    at = np.linspace(t[0], t[-1], 11).astype(np.int64)
    assert np.array_equal(p.sample(at), full.sample(at))
    with pytest.raises(ValueError, match="t = 1000000000400000000 must be finite and after the last key's time 1000000000400000000"):
        p.append(t[4], P[4])
    with pytest.raises(ValueError, match="whole nanoseconds"):
        p.append(2.5, P[4])


def test_relative_times_correctly_rounded(rng):
    """Each sample time minus the first key's, from their shortest decimals,
    rounded once (Fraction's float is): a Path at those relative times gives
    the same samples bit for bit, over times of many magnitudes (the fast
    route of path_times.c and its exact fallbacks)."""
    from decimal import Decimal
    from fractions import Fraction

    def dec(x):
        return Fraction(Decimal(repr(float(x))))

    P = tum_keys(rng, 2)
    for t0, span in ((1.2345678901234567, 1e5), (1700000000.123456, 3600.0), (-3.0e-7, 1e-3),
                     (123456.789, 1e-6), (1e15 + 0.5, 1e3), (0.1, 0.2)):
        t1 = t0 + span
        at = np.concatenate([rng.uniform(t0, t1, size=300), [t0, t1]])
        at = at[(at >= t0) & (at <= t1)]
        rel = np.array([float(dec(x) - dec(t0)) for x in at])
        r1 = float(dec(t1) - dec(t0))
        p = garotor.Path([t0, t1], P)
        q = garotor.Path([0.0, r1], P)
        assert np.array_equal(p.sample(at), q.sample(rel)), t0
        ns0 = 1_700_000_000_000_000_007
        ins = np.sort(rng.integers(ns0, ns0 + 10**15, size=200))
        pn = garotor.Path(np.array([ns0, ns0 + 10**15]), P, time_unit="ns")
        qn = garotor.Path([0.0, 1e6], P)
        reln = np.array([float(Fraction(int(x) - ns0, 10**9)) for x in ins])
        assert np.array_equal(pn.sample(ins), qn.sample(reln))
