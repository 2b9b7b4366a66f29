"""FK against an independent DH product, batch against single, Jacobian against finite differences."""

from __future__ import annotations

import math

import numpy as np
import pytest

from armkit.kinematics import fk, fk_frames, jacobian
from armkit.model import load_model

ARMS = ["owi535", "openmanipulator_x", "lynx6", "planar2"]


def reference_fk(model, q):  # type: ignore[no-untyped-def]
    """Textbook DH matrices multiplied one by one."""
    T = np.eye(4)
    for row, qi in zip(model.dh, q, strict=True):
        th = row.sign * qi + row.theta_offset
        ct, st, ca, sa = math.cos(th), math.sin(th), math.cos(row.alpha), math.sin(row.alpha)
        if model.convention == "standard":
            A = [
                [ct, -st * ca, st * sa, row.a * ct],
                [st, ct * ca, -ct * sa, row.a * st],
                [0, sa, ca, row.d],
            ]
        else:
            A = [
                [ct, -st, 0, row.a],
                [st * ca, ct * ca, -sa, -sa * row.d],
                [st * sa, ct * sa, ca, ca * row.d],
            ]
        T = T @ np.vstack([A, [0, 0, 0, 1]])
    return T @ model.T_flange_tool


@pytest.mark.parametrize("name", ARMS)
def test_fk_matches_reference_and_batch(name: str) -> None:
    m = load_model(name)
    q = np.random.default_rng(7).uniform(m.lower, m.upper, (50, m.dof))
    batch = fk(m, q)
    assert batch.shape == (50, 4, 4)
    for i in range(50):
        assert np.allclose(batch[i], reference_fk(m, q[i]), atol=1e-14)
        assert np.allclose(fk(m, q[i]), batch[i], atol=1e-15)
    R = batch[:, :3, :3]
    assert np.allclose(R @ R.transpose(0, 2, 1), np.eye(3), atol=1e-12)


@pytest.mark.parametrize("name", ARMS)
def test_frames(name: str) -> None:
    m = load_model(name)
    q = m.home + 0.1
    frames = fk_frames(m, q)
    assert frames.shape == (m.dof + 2, 4, 4)
    assert np.allclose(frames[0], np.eye(4))
    assert np.allclose(frames[-1], fk(m, q))
    qs = np.random.default_rng(4).uniform(m.lower, m.upper, (7, m.dof))
    many = fk_frames(m, qs)  # a batch: each pose's frames
    assert many.shape == (7, m.dof + 2, 4, 4)
    for i in range(7):
        assert np.allclose(many[i], fk_frames(m, qs[i]), atol=1e-15)


@pytest.mark.parametrize("name", ARMS)
def test_jacobian_against_finite_differences(name: str) -> None:
    m = load_model(name)
    q = np.random.default_rng(8).uniform(m.lower, m.upper, (20, m.dof))
    J = jacobian(m, q)
    assert J.shape == (20, 6, m.dof)
    eps = 1e-6
    for n in range(20):
        for i in range(m.dof):
            dq = np.zeros(m.dof)
            dq[i] = eps
            Tp, Tm = fk(m, q[n] + dq), fk(m, q[n] - dq)
            dp = (Tp[:3, 3] - Tm[:3, 3]) / (2 * eps)
            dR = (Tp[:3, :3] - Tm[:3, :3]) / (2 * eps) @ fk(m, q[n])[:3, :3].T
            w = np.array([dR[2, 1], dR[0, 2], dR[1, 0]])
            assert np.allclose(J[n, :3, i], dp, atol=1e-8)
            assert np.allclose(J[n, 3:, i], w, atol=1e-8)
    assert np.allclose(jacobian(m, q[0]), J[0])


@pytest.mark.parametrize("bad", [[0.0, 0.0], [[0.0] * 4] * 2 + [[0.0]], [float("nan")] * 4, "abcd"])
def test_fk_rejects_bad_q(bad: object) -> None:
    m = load_model("openmanipulator_x")
    with pytest.raises(ValueError, match="q"):
        fk(m, bad)  # type: ignore[arg-type]


@pytest.mark.parametrize("name", [*ARMS, "al5d", "puma560"])
def test_the_single_pose_fast_path_is_pinned_to_the_dense_product(name: str) -> None:
    """fk of one float array runs the generated pose code (issue 29.4); every other input
    form and the dense frames agree with it to the last bits."""
    m = load_model(name)
    q = np.random.default_rng(8).uniform(m.lower, m.upper, (300, m.dof))
    dense = fk_frames(m, q)[:, -1]
    for i in range(len(q)):
        fast = fk(m, q[i])
        assert fast.shape == (4, 4) and fast.dtype == np.float64
        assert np.abs(fast - dense[i]).max() < 1e-15
        assert np.array_equal(fast, fk(m, q[i].tolist())) and np.array_equal(
            fast, fk(m, q[i : i + 1])[0]
        )


def test_the_fast_path_keeps_the_checks() -> None:
    m = load_model("openmanipulator_x")
    for bad in ([0.0, np.nan, 0.0, 0.0], [np.inf, -np.inf, 0.0, 0.0], [0.0, 0.0, 0.0]):
        with pytest.raises(ValueError, match="q"):
            fk(m, np.array(bad))
    big = np.array([1e308, 1e308, 0.0, 0.0])  # finite, though their sum is not
    assert np.isfinite(fk(m, big)).all()
