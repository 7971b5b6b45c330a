"""The Lie-group Jacobians (docs/python.md, "Jacobians"; issue 27 item 9).

Checked three ways, each independent of the library's C:
  - the closed forms of gtsam (Pose3/Rot3 ExpmapDerivative, LogmapDerivative,
    compose, inverse, between, transformFrom, adjointMap), manif
    (SE3Tangent rjac/ljac/rjacinv/ljacinv through its fillQ, SE3 act) and
    Sophus (SE3 leftJacobian through jacobianUpperRightBlock), re-derived
    here in numpy from their formulas and evaluated on the inputs of their
    own test files (gtsam's testPose3.cpp: T, T2, T3, P, the screw xi, the
    ExpmapDerivative trajectory; manif's gtest_se3.cpp: the act poses);
    manif and Sophus order twists (v, w), garotor and gtsam (w, v): the
    blocks are swapped to compare;
  - central differences of exp, log, compose, ... in numpy (scipy's expm);
  - the module itself: rotors (cga) and matrices agree, shapes broadcast,
    bad elements raise with their index.
"""
import numpy as np
import pytest
from scipy.linalg import expm, logm

import garotor

GROUPS = ["cga", "matrix"]
SIDES = ["right", "left"]


# ---- numpy helpers ----------------------------------------------------------

def skew(w):
    return np.array([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]], dtype=float)


def rodrigues(w):
    """gtsam's Rot3::Rodrigues(w) = Rot3::Expmap(w)."""
    th = np.linalg.norm(w)
    W = skew(w)
    if th == 0:
        return np.eye(3)
    return np.eye(3) + np.sin(th) / th * W + (1 - np.cos(th)) / th**2 * W @ W


def pose(R, t):
    m = np.eye(4)
    m[:3, :3] = R
    m[:3, 3] = t
    return m


def hat(xi):
    m = np.zeros((4, 4))
    m[:3, :3] = skew(xi[:3])
    m[:3, 3] = xi[3:]
    return m


def vee(m):
    return np.array([m[2, 1], m[0, 2], m[1, 0], m[0, 3], m[1, 3], m[2, 3]])


def swap(J):
    """a 6x6 between (v, w) and (w, v) order"""
    P = np.zeros((6, 6))
    P[:3, 3:] = np.eye(3)
    P[3:, :3] = np.eye(3)
    return P @ J @ P.T


# ---- gtsam's forms (Pose3.cpp, Rot3/SO3.cpp), (w, v) order --------------------

def gtsam_rot3_expmap_derivative(w):
    th = np.linalg.norm(w)
    W = skew(w)
    return np.eye(3) - (1 - np.cos(th)) / th**2 * W + (th - np.sin(th)) / th**3 * W @ W


def gtsam_rot3_logmap_derivative(w):
    th = np.linalg.norm(w)
    W = skew(w)
    return np.eye(3) + 0.5 * W + (1 / th**2 - (1 + np.cos(th)) / (2 * th * np.sin(th))) * W @ W


def gtsam_q(xi):
    """computeQforExpmapDerivative, as gtsam writes it (the right Jacobian's)."""
    W, V = skew(xi[:3]), skew(xi[3:])
    phi = np.linalg.norm(xi[:3])
    s, c = np.sin(phi), np.cos(phi)
    p2, p3, p4, p5 = phi**2, phi**3, phi**4, phi**5
    return (-0.5 * V + (phi - s) / p3 * (W @ V + V @ W - W @ V @ W)
            + (1 - p2 / 2 - c) / p4 * (W @ W @ V + V @ W @ W - 3 * W @ V @ W)
            - 0.5 * ((1 - p2 / 2 - c) / p4 - 3 * (phi - s - p3 / 6.) / p5) * (W @ V @ W @ W + W @ W @ V @ W))


def gtsam_expmap_derivative(xi):
    Jw = gtsam_rot3_expmap_derivative(xi[:3])
    return np.block([[Jw, np.zeros((3, 3))], [gtsam_q(xi), Jw]])


def gtsam_logmap(m):
    """Pose3::Logmap through the matrix log (principal for angles below pi)."""
    return vee(np.real(logm(m)))


def gtsam_logmap_derivative(m):
    xi = gtsam_logmap(m)
    Jw = gtsam_rot3_logmap_derivative(xi[:3])
    Q = gtsam_q(xi)
    return np.block([[Jw, np.zeros((3, 3))], [-Jw @ Q @ Jw, Jw]])


def gtsam_adjoint_map(m):
    R, t = m[:3, :3], m[:3, 3]
    return np.block([[R, np.zeros((3, 3))], [skew(t) @ R, R]])


def gtsam_small_adjoint(xi):
    return np.block([[skew(xi[:3]), np.zeros((3, 3))], [skew(xi[3:]), skew(xi[:3])]])


# gtsam's testPose3.cpp inputs
GT_R = rodrigues([0.3, 0, 0])
GT_P = np.array([0.2, 0.7, -2])
GT_P2 = np.array([3.5, -8.2, 4.2])
GT_T = pose(GT_R, GT_P2)
GT_T2 = pose(rodrigues([0.3, 0.2, 0.1]), GT_P2)
GT_T3 = pose(rodrigues([-90, 0, 0]), [1, 2, 3])
GT_TINV2 = pose(rodrigues([0.3, 0.4, -0.5]), [3.5, -8.2, 4.2])
GT_SCREW = np.array([0.0, 0.0, 0.3, 0.3, 0.0, 1.0])
GT_W = np.array([0.1, 0.2, 0.3, 4.0, 5.0, 6.0])
GT_TRAJ = [np.array([2 * t, np.sin(t), 4 * t * t, 2 * t, np.sin(t), 4 * t * t])
           for t in np.arange(-2.0, 2.0, 0.3)]
GT_POSES = [GT_T, GT_T2, GT_T3, GT_TINV2, np.eye(4), pose(np.eye(3), [100, 0, 0])]
GT_TWISTS = [GT_SCREW, GT_W, np.array([0.1, -0.2, 0.3, -0.4, 0.5, -0.6]),
             np.array([0.2, 0.3, -0.8, 100.0, 120.0, -60.0])] + GT_TRAJ


# ---- manif's forms (SE3Tangent_base.h fillQ, SO3 jacobians), (v, w) order -----

def manif_so3(w):
    th = np.linalg.norm(w)
    W = skew(w)
    a, b = (1 - np.cos(th)) / th**2, (th - np.sin(th)) / th**3
    cinv = 1 / th**2 - (1 + np.cos(th)) / (2 * th * np.sin(th))
    return (np.eye(3) + a * W + b * W @ W, np.eye(3) - a * W + b * W @ W,
            np.eye(3) - 0.5 * W + cinv * W @ W, np.eye(3) + 0.5 * W + cinv * W @ W)


def manif_q(v, w):
    th2 = w @ w
    th = np.sqrt(th2)
    V, W = skew(v), skew(w)
    B = (th - np.sin(th)) / (th2 * th)
    C = (1 - th2 / 2 - np.cos(th)) / (th2 * th2)
    D = C - 3 * (th - np.sin(th) - th2 * th / 6) / (th2 * th2 * th)
    VW = V @ W
    WV = VW.T
    WVW = WV @ W
    VWW = VW @ W
    return 0.5 * V + B * (WV + VW + WVW) - C * (VWW - VWW.T - 3 * WVW) - D * WVW @ W


def manif_jacobians(tau):
    """rjac, ljac, rjacinv, ljacinv of the tangent tau = (v, w)."""
    v, w = tau[:3], tau[3:]
    jl, jr, jli, jri = manif_so3(w)
    Ql, Qr = manif_q(v, w), manif_q(-v, -w)
    Z = np.zeros((3, 3))
    return (np.block([[jr, Qr], [Z, jr]]), np.block([[jl, Ql], [Z, jl]]),
            np.block([[jri, -jri @ Qr @ jri], [Z, jri]]), np.block([[jli, -jli @ Ql @ jli], [Z, jli]]))


def manif_rpy(x, y, z, roll, pitch, yaw):
    """manif's SE3d(x, y, z, roll, pitch, yaw): R = Rz(yaw) Ry(pitch) Rx(roll)."""
    R = rodrigues([0, 0, yaw]) @ rodrigues([0, pitch, 0]) @ rodrigues([roll, 0, 0])
    return pose(R, [x, y, z])


# ---- Sophus's form (SE3 leftJacobian, jacobianUpperRightBlock), (v, w) order ---

def sophus_left_jacobian(upsilon_omega):
    ups, om = upsilon_omega[:3], upsilon_omega[3:]
    th2 = om @ om
    th = np.sqrt(th2)
    U, O = skew(ups), skew(om)
    it2, it4 = 1 / th2, 1 / th2**2
    st, ct = np.sin(th), np.cos(th)
    c1 = it2 - st * it2 / th
    c2 = 0.5 * it2 + ct * it4 - it4
    c3 = it4 + 0.5 * ct * it4 - 1.5 * st / th * it4
    OU = O @ U
    OUO = OU @ O
    Q = 0.5 * U + c1 * (OU + U @ O + OUO) - c2 * (th2 * U + 2 * OUO) + c3 * (OUO @ O + O @ OUO)
    J = np.eye(3) + (1 - ct) / th2 * O + (th - st) / (th2 * th) * O @ O
    return np.block([[J, Q], [np.zeros((3, 3)), J]])


def rel(a, b):
    return np.max(np.abs(np.asarray(a) - np.asarray(b))) / max(1.0, np.max(np.abs(b)))


# ---- against gtsam ----------------------------------------------------------------

def test_gtsam_expmap_derivative():
    for xi in GT_TWISTS:
        assert rel(garotor.jr(xi), gtsam_expmap_derivative(xi)) < 1e-12
        assert rel(garotor.jl(xi), gtsam_expmap_derivative(-xi)) < 1e-12


@pytest.mark.parametrize("group", GROUPS)
def test_gtsam_logmap_derivative(group):
    ms = [garotor.exp(GT_W, group), GT_T, GT_T2, GT_T3, GT_TINV2, garotor.exp(GT_SCREW, group)]
    for m in ms:
        assert rel(garotor.jac_log(m, group), gtsam_logmap_derivative(m)) < 1e-10
        xi = garotor.log(m, group)
        assert rel(garotor.jr_inverse(xi), np.linalg.inv(gtsam_expmap_derivative(xi))) < 1e-12


@pytest.mark.parametrize("group", GROUPS)
def test_gtsam_group_jacobians(group):
    ad = gtsam_adjoint_map
    for a in GT_POSES:
        assert rel(garotor.adjoint(a, group), ad(a)) < 1e-14
        # Pose3::inverse: H = -AdjointMap()
        assert rel(garotor.jac_inverse(a, group), -ad(a)) < 1e-14
        # Pose3::transformFrom: H1 = [R skew(-p), R], H2 = R
        ja, jp = garotor.jac_act(a, GT_P, group)
        R = a[:3, :3]
        assert rel(ja, np.hstack([R @ skew(-GT_P), R])) < 1e-14
        assert rel(jp, R) < 1e-15
        for b in GT_POSES:
            # Pose3::compose: H1 = b.inverse().AdjointMap(), H2 = I
            j1, j2 = garotor.jac_compose(a, b, group)
            assert rel(j1, ad(np.linalg.inv(b))) < 1e-13
            assert np.array_equal(j2, np.eye(6))
            # Pose3::between: H1 = -result.inverse().AdjointMap(), H2 = I
            j1, j2 = garotor.jac_between(a, b, group)
            assert rel(j1, -ad(np.linalg.inv(np.linalg.inv(a) @ b))) < 1e-13
            assert np.array_equal(j2, np.eye(6))


def test_gtsam_adjoint_map():
    for xi in GT_TWISTS:
        assert np.array_equal(garotor.ad(xi), gtsam_small_adjoint(xi))


# ---- against manif and Sophus -------------------------------------------------------

def test_manif_tangent_jacobians():
    for xi in GT_TWISTS[:10]:
        tau = np.concatenate([xi[3:], xi[:3]])
        rj, lj, rji, lji = (swap(J) for J in manif_jacobians(tau))
        assert rel(garotor.jr(xi), rj) < 1e-11
        assert rel(garotor.jl(xi), lj) < 1e-11
        if np.linalg.norm(xi[:3]) < 2 * np.pi:
            assert rel(garotor.jr_inverse(xi), rji) < 1e-11
            assert rel(garotor.jl_inverse(xi), lji) < 1e-11


@pytest.mark.parametrize("group", GROUPS)
def test_manif_act(group):
    # gtest_se3.cpp, TEST_SE3_ACT: the moved points, then their Jacobians
    # (SE3::act: J_vout_m = [R, -R [v]x] in (v, w) order, J_vout_v = R)
    cases = [(manif_rpy(1, 1, 1, np.pi, np.pi / 2, np.pi / 4), [1, -0.414213562373, 0]),
             (manif_rpy(-1, -1, -1, np.pi / 4, -np.pi / 2, -np.pi), [0.414213562373, -1, 0])]
    p = np.array([1.0, 1.0, 1.0])
    for m, want in cases:
        assert np.max(np.abs(garotor.apply(m, p, group) - want)) < 1e-12
        ja, jp = garotor.jac_act(m, p, group)
        R = m[:3, :3]
        manif = np.hstack([R, -R @ skew(p)])
        assert rel(ja, np.hstack([manif[:, 3:], manif[:, :3]])) < 1e-14
        assert rel(jp, R) < 1e-15


def test_sophus_left_jacobian():
    for xi in GT_TWISTS:
        ups_om = np.concatenate([xi[3:], xi[:3]])
        assert rel(garotor.jl(xi), swap(sophus_left_jacobian(ups_om))) < 1e-11


# ---- central differences (scipy's expm) ---------------------------------------------

def fd(f, x0, ncols, plus, minus, h=1e-6):
    """the central differences (minus(f(x0 (+) h e_k), f0) - minus(f(x0 (+) -h e_k), f0)) / 2h"""
    f0 = f(x0)
    cols = []
    for k in range(ncols):
        e = np.zeros(ncols)
        e[k] = h
        cols.append((minus(f(plus(x0, e)), f0) - minus(f(plus(x0, -e)), f0)) / (2 * h))
    return np.stack(cols, axis=1)


@pytest.mark.parametrize("side", SIDES)
def test_central_differences(side, rng):
    def plus(m, tau):
        e = expm(hat(tau))
        return m @ e if side == "right" else e @ m

    def minus(a, b):
        if a.shape == (4, 4):
            return vee(np.real(logm(np.linalg.inv(b) @ a if side == "right" else a @ np.linalg.inv(b))))
        return a - b

    def vminus(u, v):
        return u - v

    for i in range(8):
        angle = [0.0, 1e-6, np.pi - 1e-2, rng.uniform(0, np.pi)][i % 4]
        w = rng.normal(size=3)
        xa = np.concatenate([w / np.linalg.norm(w) * angle, rng.uniform(-2, 2, 3)])
        xb = np.concatenate([rng.normal(size=3), rng.uniform(-2, 2, 3)])
        a, b = expm(hat(xa)), expm(hat(xb))
        p = rng.uniform(-2, 2, 3)
        num = {
            "compose": (fd(lambda m: m @ b, a, 6, plus, minus), fd(lambda m: a @ m, b, 6, plus, minus)),
            "between": (fd(lambda m: np.linalg.inv(m) @ b, a, 6, plus, minus),
                        fd(lambda m: np.linalg.inv(a) @ m, b, 6, plus, minus)),
            "inverse": fd(np.linalg.inv, a, 6, plus, minus),
            "act": (fd(lambda m: m[:3, :3] @ p + m[:3, 3], a, 6, plus, vminus),
                    fd(lambda q: a[:3, :3] @ q + a[:3, 3], p, 3, lambda q, e: q + e, vminus)),
            "log": fd(lambda m: vee(np.real(logm(m))), a, 6, plus, vminus),
        }
        for group in GROUPS:
            for got, want in zip(garotor.jac_compose(a, b, group, side), num["compose"]):
                assert rel(got, want) < 1e-7
            for got, want in zip(garotor.jac_between(a, b, group, side), num["between"]):
                assert rel(got, want) < 1e-7
            assert rel(garotor.jac_inverse(a, group, side), num["inverse"]) < 1e-7
            for got, want in zip(garotor.jac_act(a, p, group, side), num["act"]):
                assert rel(got, want) < 1e-7
            if angle < np.pi - 1e-3:
                assert rel(garotor.jac_log(a, group, side), num["log"]) < 1e-7


# ---- the module -------------------------------------------------------------------

def test_groups_agree_and_broadcast(rng):
    xi = np.concatenate([rng.normal(size=(4, 5, 3)), rng.normal(size=(4, 5, 3))], axis=-1)
    assert garotor.jr(xi).shape == (4, 5, 6, 6)
    for k in range(4):
        assert np.array_equal(garotor.jr(xi[k]), garotor.jr(xi)[k])
    T = garotor.exp(xi, "matrix")
    for side in SIDES:
        for fn in (garotor.jac_inverse, garotor.jac_log):
            c, m = fn(T, "cga", side), fn(T, "matrix", side)
            assert c.shape == (4, 5, 6, 6) and rel(c, m) < 1e-13
        c = garotor.jac_compose(T, T[0], "cga", side)
        m = garotor.jac_compose(T, T[0], "matrix", side)
        assert c[0].shape == (4, 5, 6, 6) and rel(c[0], m[0]) < 1e-13 and rel(c[1], m[1]) < 1e-13
        ja, jp = garotor.jac_act(T, np.zeros(3), side=side)
        assert ja.shape == (4, 5, 3, 6) and jp.shape == (4, 5, 3, 3)


def test_errors():
    bad = np.zeros((3, 6))
    bad[2, 0] = 7.0  # beyond 2 pi
    with pytest.raises(garotor.Error, match=r"jr_inverse: index 2: .*not below 2 pi") as e:
        garotor.jr_inverse(bad)
    assert e.value.index == (2,)
    bad[1, 4] = np.nan
    with pytest.raises(ValueError, match=r"index 1: .*xi\[1, 4\] is nan"):
        garotor.jl(bad)
    T = np.stack([np.eye(4)] * 3)
    T[1, 0, 0] = 1.1
    for group in GROUPS:
        with pytest.raises(garotor.Error, match=r"jac_log: index 1: "):
            garotor.jac_log(T, group)
    with pytest.raises(ValueError, match="side must be 'right' or 'left', not 'up'"):
        garotor.jac_inverse(np.eye(4), side="up")
    # affine has its own (12 x 12; python/tests/test_jacobian_affine.py)
    assert np.array_equal(garotor.jac_inverse(np.eye(4), "affine"), -np.eye(12))
