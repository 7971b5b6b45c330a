"""garotor.dask: garotor's calls on dask arrays, Path.sample at a dask array
of times, and a pose-file pipeline as a dask bag (docs/python.md, "Beyond
one machine").

Each call here runs garotor's own call on every block (chunk) of its input,
in whatever process or machine the dask scheduler picks; every element is
computed by the same C code on the same numbers as in one process, so the
result is the single-process call's, bit for bit.

The blocks are handed to dask.array.apply_gufunc with the core dimensions
named and their output sizes and dtype given (never inferred: dask 2022.12
infers a dtype by calling the function on size-1 arrays, which a function of
fixed core sizes refuses). A core dimension (the 6 of a twist, the 4 x 4 of a
motion) split over several chunks is first joined into one chunk; leading
dimensions keep their chunks, and broadcast as numpy's do.
"""
from __future__ import annotations

import decimal
import functools
import os
from typing import Any, Callable, Iterable, Sequence

import numpy as np
from numpy.typing import NDArray

import dask
import dask.array as da
import dask.bag as db

from . import _garotor as _g

__all__ = ["exp", "log", "compose", "inverse", "apply", "sample", "velocity", "acceleration",
           "read_tum", "resample_file", "resample_files"]

# core shapes per group: a twist / generator, a motion
_TWIST = {"cga": (6,), "matrix": (6,), "affine": (4, 4)}
_MOTION = (4, 4)


def _core(names: str, shape: tuple[int, ...]) -> tuple[str, dict[str, int]]:
    """('(a,b)', {'a': 4, 'b': 4}) for names 'ab' and shape (4, 4)."""
    return "(" + ",".join(names[: len(shape)]) + ")", dict(zip(names, shape))


def _twist_shape(group: str) -> tuple[int, ...]:
    if group not in _TWIST:
        raise ValueError("garotor.dask: group must be 'cga', 'matrix' or 'affine', not %r" % (group,))
    return _TWIST[group]


def _prepare(x: Any, core: tuple[int, ...]) -> da.Array:
    """x as a float64 dask array whose last len(core) dimensions are core,
    each in one chunk."""
    a = da.asarray(x)
    if a.dtype != np.float64:
        a = a.astype(np.float64)
    if a.ndim < len(core) or tuple(a.shape[a.ndim - len(core):]) != core:
        raise ValueError("garotor.dask: expected an array of shape (..., %s), got %s"
                         % (", ".join(map(str, core)), a.shape))
    if any(len(c) > 1 for c in a.chunks[a.ndim - len(core):]):
        a = a.rechunk({a.ndim - 1 - i: -1 for i in range(len(core))})
    return a


def _gufunc(fn: Callable[..., Any], ins: Sequence[tuple[Any, tuple[int, ...], str]],
            out: tuple[tuple[int, ...], str], **kw: Any) -> da.Array:
    sigs, sizes, arrays = [], {}, []
    for x, core, names in ins:
        s, d = _core(names, core)
        sigs.append(s)
        sizes.update(d)
        arrays.append(_prepare(x, core))
    if len(arrays) > 1:  # the leading dimensions chunked alike, for apply_gufunc
        nloop = max(a.ndim - len(c[1]) for a, c in zip(arrays, ins))
        loop = "ABCDEFGHIJKLMNOPQRSTUVWXYZ"[:nloop]
        pairs: list[Any] = []
        for j, (a, c) in enumerate(zip(arrays, ins)):
            k = a.ndim - len(c[1])
            pairs += [a, loop[nloop - k:] + "".join(chr(ord("a") + 8 * j + i) for i in range(len(c[1])))]
        arrays = list(da.core.unify_chunks(*pairs)[1])
    osig, osizes = _core(out[1], out[0])
    sizes.update(osizes)
    return da.apply_gufunc(functools.partial(fn, **kw), ",".join(sigs) + "->" + osig, *arrays,
                           output_dtypes=np.float64, output_sizes=osizes, vectorize=False)


def exp(xi: Any, group: str = "cga") -> da.Array:
    """garotor.exp(xi, group) on each block: twists (..., 6) -> (..., 4, 4)
    (affine: generators (..., 4, 4))."""
    return _gufunc(_g.exp, [(xi, _twist_shape(group), "ab")], ((4, 4), "cd"), group=group)


def log(T: Any, group: str = "cga") -> da.Array:
    """garotor.log(T, group) on each block: motions (..., 4, 4) -> (..., 6)
    (affine: (..., 4, 4))."""
    return _gufunc(_g.log, [(T, _MOTION, "ab")], (_twist_shape(group), "cd"), group=group)


def compose(A: Any, B: Any, group: str = "cga") -> da.Array:
    """garotor.compose(A, B, group) on each pair of blocks, broadcast: A B."""
    _twist_shape(group)
    return _gufunc(_g.compose, [(A, _MOTION, "ab"), (B, _MOTION, "ab")], (_MOTION, "ab"), group=group)


def inverse(T: Any, group: str = "cga") -> da.Array:
    """garotor.inverse(T, group) on each block."""
    _twist_shape(group)
    return _gufunc(_g.inverse, [(T, _MOTION, "ab")], (_MOTION, "ab"), group=group)


def apply(T: Any, points: Any, group: str = "cga") -> da.Array:
    """garotor.apply(T, points, group) on each pair of blocks, broadcast:
    (..., 4, 4) and (..., 3) -> (..., 3)."""
    _twist_shape(group)
    return _gufunc(_g.apply, [(T, _MOTION, "ab"), (points, (3,), "c")], ((3,), "c"), group=group)


# ---- a Path at a dask array of times ----------------------------------------------

def _path_call(path: _g.Path, method: str, t: Any, core: tuple[int, ...]) -> da.Array:
    if not isinstance(path, _g.Path):
        raise TypeError("garotor.dask: path must be a garotor.Path, not %s" % type(path).__name__)
    t = da.asarray(t)
    if t.dtype != np.float64:
        t = t.astype(np.float64)
    # one key of the graph holds the Path: it is pickled once and sent to
    # each worker that samples a block, not once per block
    p = dask.delayed(path, pure=True)
    new = list(range(t.ndim, t.ndim + len(core)))
    return da.map_blocks(_call_method, t, p, method, dtype=np.float64, name=method,
                         chunks=t.chunks + tuple((c,) for c in core), new_axis=new,
                         meta=np.empty((0,) * (t.ndim + len(core)), dtype=np.float64))


def _call_method(t: NDArray[np.float64], path: _g.Path, method: str) -> NDArray[np.float64]:
    result: NDArray[np.float64] = getattr(path, method)(t)
    return result


def sample(path: _g.Path, t: Any) -> da.Array:
    """path.sample(t) on each block of t: times (...) -> (..., 4, 4)."""
    return _path_call(path, "sample", t, (4, 4))


def velocity(path: _g.Path, t: Any) -> da.Array:
    """path.velocity(t) on each block of t: (...) -> (..., 6) (affine: (..., 4, 4))."""
    return _path_call(path, "velocity", t, (4, 4) if path.group == "affine" else (6,))


def acceleration(path: _g.Path, t: Any) -> da.Array:
    """path.acceleration(t) on each block of t: (...) -> (..., 6) (affine: (..., 4, 4))."""
    return _path_call(path, "acceleration", t, (4, 4) if path.group == "affine" else (6,))


# ---- pose files: one Path per file ------------------------------------------------

def read_tum(file: str | os.PathLike[str], normalize: bool = True) -> tuple[list[str], NDArray[np.float64]]:
    """A TUM pose file: lines `t tx ty tz qx qy qz qw` ('#' lines and blank
    lines skipped). Returns (stamps, poses): the stamps as written (text) and
    the (n, 7) poses, each quaternion divided by its norm with normalize
    (TUM files round it to a few decimals; Path takes norms within 1e-9)."""
    stamps, rows = [], []
    with open(file) as f:
        for line in f:
            w = line.split()
            if not w or w[0].startswith("#"):
                continue
            if len(w) != 8:
                raise ValueError("%s: a line of %d numbers, not 8 (t tx ty tz qx qy qz qw): %r"
                                 % (os.fspath(file), len(w), line.strip()))
            stamps.append(w[0])
            rows.append([float(v) for v in w[1:]])
    poses = np.array(rows, dtype=np.float64).reshape(-1, 7)
    if normalize:
        poses[:, 3:] /= np.linalg.norm(poses[:, 3:], axis=1, keepdims=True)
    return stamps, poses


def _relative(stamps: Sequence[str]) -> NDArray[np.float64]:
    """Each stamp minus the first, exactly in decimal, then rounded once to
    a double (as the tool reads times)."""
    with decimal.localcontext() as c:
        c.prec = 60
        t0 = decimal.Decimal(stamps[0])
        return np.array([float(decimal.Decimal(s) - t0) for s in stamps], dtype=np.float64)


def resample_file(file: str | os.PathLike[str], rate: float, out_dir: str | os.PathLike[str] | None = None,
                  scheme: str = "screw", group: str = "cga") -> dict[str, Any]:
    """One pose file, resampled in this process: the Path through its keys
    (times relative to the first stamp, as the tool builds it), sampled at
    k / rate for k = 0, 1, ... up to the last key, written to
    out_dir/<name> as TUM lines (the stamp: the first stamp plus k / rate,
    exactly in decimal; the pose as garotor.to_pose writes it, each number
    as Python's repr) when out_dir is given. Returns {'file', 'out', 'keys',
    'samples'} (and 'poses', the (m, 7) array, where out_dir is None)."""
    stamps, poses = read_tum(file)
    t = _relative(stamps)
    path = _g.Path(t, poses, scheme=scheme, group=group)
    t0, t1 = path.range
    k = np.arange(int(np.floor(t1 * rate)) + 2, dtype=np.float64)
    ts = k / rate
    ts = ts[(ts >= t0) & (ts <= t1)]
    out = _g.to_pose(path.sample(ts))
    res: dict[str, Any] = {"file": os.fspath(file), "out": None, "keys": len(t), "samples": len(ts)}
    if out_dir is None:
        res["poses"] = out
        return res
    dest = os.path.join(os.fspath(out_dir), os.path.basename(os.fspath(file)))
    with decimal.localcontext() as c:
        c.prec = 60
        base = decimal.Decimal(stamps[0])
        lines = ["%s %s\n" % (base + decimal.Decimal(repr(float(s))), " ".join(map(repr, row.tolist())))
                 for s, row in zip(ts, out)]
    with open(dest, "w") as f:
        f.writelines(lines)
    res["out"] = dest
    return res


def resample_files(files: Iterable[str | os.PathLike[str]], rate: float,
                   out_dir: str | os.PathLike[str] | None = None, scheme: str = "screw",
                   group: str = "cga") -> db.Bag:
    """resample_file over many files as a dask bag, one file a partition:
    bag.compute() (on whatever scheduler is current: a distributed Client's
    workers, say) gives the list of resample_file's results, in the order of
    files."""
    fs = [os.fspath(f) for f in files]
    return db.from_sequence(fs, npartitions=max(1, len(fs))).map(
        resample_file, rate=rate, out_dir=out_dir, scheme=scheme, group=group)
