"""A typed user of garotor, checked by mypy --strict against the stubs
(python/tests/check_typing.py); it runs too (the same test runs it)."""
import numpy as np
from numpy.typing import NDArray

import garotor
from garotor import Multivector, Path


def motions(n: int, seed: int) -> NDArray[np.float64]:
    return garotor.exp(np.random.default_rng(seed).normal(size=(n, 6)))


def resample(p: Path, rate: float) -> NDArray[np.float64]:
    t0, t1 = p.range
    t: NDArray[np.float64] = np.arange(t0, t1, 1.0 / rate)
    out = np.empty(t.shape + (4, 4))
    return garotor.to_pose(p.sample(t, out=out))


def moved(points: NDArray[np.float64], T: NDArray[np.float64]) -> NDArray[np.float64]:
    return garotor.apply(garotor.compose(T, garotor.inverse(T)), points)


def circle_radius() -> float:
    s1: Multivector = Multivector.up([0, 0, 0]) - 0.5 * garotor.n
    s2 = Multivector.up([1, 0, 0]) - 0.5 * garotor.n
    ob: garotor.Object = s1.meet(s2).object()
    return float(np.sqrt(ob.r2))


def main() -> None:
    K = motions(5, 1)
    p = Path(np.arange(5.0), K, scheme="lihao3", capacity=None)
    poses = resample(p, 10.0)
    assert poses.shape == (40, 7)
    v: NDArray[np.float64] = p.velocity(np.array([0.5, 1.5]))
    assert v.shape == (2, 6)
    assert moved(np.zeros((5, 3)), K).shape == (5, 3)
    assert abs(circle_radius() - 0.75 ** 0.5) < 1e-15
    try:
        garotor.log(np.zeros((4, 4)))
    except garotor.Error as e:
        assert e.status == -4 and e.index == ()
    version: str = garotor.__version__
    assert version.count(".") == 2
    c, r = garotor.fit_sphere([[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, 0, 1], [0, 0, -1]])
    assert c.shape == (3,) and abs(r - 1.0) < 1e-12
    R: Multivector = Multivector.rotation([0, 0, 1], np.pi / 2) * Multivector.translation([1, 0, 0])
    assert R ** 2 == R * R and bool(R) and R["e12"] == R[6]


if __name__ == "__main__":
    main()
