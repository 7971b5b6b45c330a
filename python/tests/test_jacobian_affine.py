"""The affine group's Jacobians (docs/conventions.md, "The affine group";
issue 27 item 9, "for every group").

Checked against references independent of the library's C:
  - scipy.linalg.expm_frechet (Al-Mohy and Higham's Frechet derivative of
    expm): J_r(X) E = expm(-X) L(X, E), J_l(X) E = L(X, E) expm(-X);
  - mpmath's expm at 40 digits with central differences of step 1e-15
    (J_r on a few elements, to 1e-12);
  - central differences of the group operations in numpy (scipy's expm and
    logm); the rigid Jacobians on se(3), embedded.
"""
import mpmath
import numpy as np
import pytest
from scipy.linalg import expm, expm_frechet, logm

import garotor

SIDES = ["right", "left"]
RNG = np.random.default_rng(20261203)


def hat(x):
    m = np.zeros((4, 4))
    m[:3, :] = np.reshape(x, (3, 4))
    return m


def vee(m):
    return np.asarray(m)[:3, :].reshape(12)


def elements(n, scale):
    """algebra elements: general [A, b] with A U(-1,1), b U(-3,3), times scale"""
    out = []
    for _ in range(n):
        x = np.zeros((4, 4))
        x[:3, :3] = RNG.uniform(-1, 1, (3, 3))
        x[:3, 3] = RNG.uniform(-3, 3, 3)
        out.append(x * scale)
    return np.array(out)


@pytest.mark.parametrize("scale", [0.1, 1.0, 4.0])
def test_jr_jl_against_expm_frechet(scale):
    X = elements(20, scale)
    jr, jl = garotor.affine_jr(X), garotor.affine_jl(X)
    assert jr.shape == (20, 12, 12)
    worst = 0.0
    for x, r, l in zip(X, jr, jl):
        ei = expm(-x)
        s = max(1.0, np.abs(r).max(), np.abs(l).max())
        for k in range(12):
            e = np.zeros(12)
            e[k] = 1.0
            L = expm_frechet(x, hat(e), compute_expm=False)
            worst = max(worst, np.abs(vee(ei @ L) - r[:, k]).max() / s,
                        np.abs(vee(L @ ei) - l[:, k]).max() / s)
    assert worst < 1e-12, worst


def test_jr_against_mpmath():
    mpmath.mp.dps = 40
    X = elements(3, 1.5)
    h = mpmath.mpf("1e-15")
    for x in X:
        jr = garotor.affine_jr(x)
        xm = mpmath.matrix(x.tolist())
        ei = mpmath.expm(-xm)
        for k in range(12):
            d = mpmath.matrix(4, 4)
            d[k // 4, k % 4] = 1
            D = (mpmath.expm(xm + h * d) - mpmath.expm(xm - h * d)) / (2 * h)
            col = ei * D
            ref = np.array([float(col[i, j]) for i in range(3) for j in range(4)])
            assert np.abs(ref - jr[:, k]).max() < 1e-12 * max(1.0, np.abs(jr).max())


def test_identities():
    X = elements(30, 2.0)
    jr, jl = garotor.affine_jr(X), garotor.affine_jl(X)
    assert np.array_equal(jl, garotor.affine_jr(-X))
    jri, jli = garotor.affine_jr_inverse(X), garotor.affine_jl_inverse(X)
    eye = np.eye(12)
    assert np.abs(jr @ jri - eye).max() < 1e-12
    assert np.abs(jl @ jli - eye).max() < 1e-12
    ad = garotor.affine_ad(X)
    Y = elements(30, 1.0)
    xy = np.array([vee(x @ y - y @ x) for x, y in zip(X, Y)])
    assert np.abs(np.einsum("nij,nj->ni", ad, np.array([vee(y) for y in Y])) - xy).max() < 1e-13


def test_se3_embedded():
    """on se(3) the affine J_r is the rigid one (garotor.jr), embedded"""
    for _ in range(20):
        xi = np.concatenate([RNG.uniform(-1, 1, 3), RNG.uniform(-2, 2, 3)])
        X = garotor.twist_hat(xi) if hasattr(garotor, "twist_hat") else None
        if X is None:
            w, v = xi[:3], xi[3:]
            X = np.zeros((4, 4))
            X[:3, :3] = [[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]]
            X[:3, 3] = v
        ja, j6 = garotor.affine_jr(X), garotor.jr(xi)
        for k in range(6):
            e = np.zeros(6)
            e[k] = 1.0
            w, v = e[:3], e[3:]
            H = np.zeros((4, 4))
            H[:3, :3] = [[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]]
            H[:3, 3] = v
            c = j6[:, k]
            W = np.zeros((4, 4))
            W[:3, :3] = [[0, -c[2], c[1]], [c[2], 0, -c[0]], [-c[1], c[0], 0]]
            W[:3, 3] = c[3:]
            assert np.abs(ja @ vee(H) - vee(W)).max() < 1e-14 * max(1.0, np.abs(ja).max())


def group_elements(n):
    return np.array([expm(x) for x in elements(n, 0.5)])


def plus(a, tau, side):
    e = expm(hat(tau))
    return a @ e if side == "right" else e @ a


def minus(a, b, side):
    d = np.linalg.solve(a, b) if side == "right" else b @ np.linalg.inv(a)
    return vee(np.real(logm(d)))


@pytest.mark.parametrize("side", SIDES)
def test_group_against_central_differences(side):
    A, B = group_elements(6), group_elements(6)
    P = RNG.uniform(-2, 2, (6, 3))
    h = 1e-6
    ca, cb = garotor.jac_compose(A, B, group="affine", side=side)
    ci = garotor.jac_inverse(A, group="affine", side=side)
    ba, bb = garotor.jac_between(A, B, group="affine", side=side)
    aa, ap = garotor.jac_act(A, P, group="affine", side=side)
    lg = garotor.jac_log(A, group="affine", side=side)
    assert ca.shape == (6, 12, 12) and aa.shape == (6, 3, 12) and ap.shape == (6, 3, 3)
    for n in range(6):
        a, b, p = A[n], B[n], P[n]
        for k in range(12):
            t = np.zeros(12)
            t[k] = h

            def d_elem(f, arg):
                fp = f(plus(a, t, side), b) if arg == 0 else f(a, plus(b, t, side))
                fm = f(plus(a, -t, side), b) if arg == 0 else f(a, plus(b, -t, side))
                f0 = f(a, b)
                return (minus(f0, fp, side) - minus(f0, fm, side)) / (2 * h)

            comp = lambda x, y: x @ y
            betw = lambda x, y: np.linalg.solve(x, y)
            assert np.allclose(d_elem(comp, 0), ca[n][:, k], atol=1e-6)
            assert np.allclose(d_elem(comp, 1), cb[n][:, k], atol=1e-6)
            assert np.allclose(d_elem(betw, 0), ba[n][:, k], atol=1e-6)
            assert np.allclose(d_elem(betw, 1), bb[n][:, k], atol=1e-6)
            assert np.allclose(d_elem(lambda x, y: np.linalg.inv(x), 0), ci[n][:, k], atol=1e-6)
            pt = np.append(p, 1.0)
            dy = ((plus(a, t, side) @ pt)[:3] - (plus(a, -t, side) @ pt)[:3]) / (2 * h)
            assert np.allclose(dy, aa[n][:, k], atol=1e-6)
            dl = (vee(np.real(logm(plus(a, t, side)))) - vee(np.real(logm(plus(a, -t, side))))) / (2 * h)
            assert np.allclose(dl, lg[n][:, k], atol=1e-6)
        assert np.allclose(ap[n], a[:3, :3])


def test_refusals():
    with pytest.raises(ValueError):
        garotor.jac_inverse(np.diag([-1.0, 1.0, 1.0, 1.0]), group="affine")
    with pytest.raises(ValueError):
        garotor.affine_jr(np.full((4, 4), np.nan))
