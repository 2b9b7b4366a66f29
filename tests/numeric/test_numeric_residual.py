"""The residual's Jacobian rows are the derivatives of its rows (finite differences)."""

from __future__ import annotations

import numpy as np
import pytest
from numeric_cases import ARMS, joint_vectors, target_for

from armkit.kinematics._chain import chain_of
from armkit.kinematics._numeric._residual import Task, residual, rotation_log
from armkit.kinematics._numeric._residual_batch import _rotation_log
from armkit.model import load_model


def task_of(model, target):  # type: ignore[no-untyped-def]
    """The solvers' Task of a Target (see numeric_cases)."""
    p = tuple(np.asarray(target.position, dtype=float).tolist())
    R = None if target.orientation is None else tuple(np.ravel(target.orientation).tolist())
    return Task(p, target.pitch, R, chain_of(model).weight)


@pytest.mark.parametrize("arm", ARMS)
@pytest.mark.parametrize("mask", ["position", "position+pitch", "pose"])
def test_residual_jacobian_matches_finite_differences(arm: str, mask: str) -> None:
    model = load_model(arm)
    chain = chain_of(model)
    qs = joint_vectors(model, 6, seed=2)
    task = task_of(model, target_for(model, qs[0], mask))
    for q in qs[1:]:
        res = residual(task, chain.state(q.tolist()))
        J = np.array(res.cols).T
        h = 1e-6
        for i in range(model.dof):
            dq = np.zeros(model.dof)
            dq[i] = h
            ep = residual(task, chain.state((q + dq).tolist()), jac=False).e
            em = residual(task, chain.state((q - dq).tolist()), jac=False).e
            fd = -(np.array(ep) - np.array(em)) / (2 * h)  # e = goal - actual
            if mask == "pose":  # log map's derivative is J_w only at zero error
                fd, col = fd[:3], J[:3, i]
            else:
                col = J[:, i]
            np.testing.assert_allclose(col, fd, atol=1e-5)


def test_rotation_log_batch_matches_scalar_near_pi() -> None:
    rng = np.random.default_rng(3)
    axis = rng.normal(size=3)
    axis /= np.linalg.norm(axis)
    for theta in (1e-9, 0.5, np.pi - 1e-9, np.pi):
        K = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
        Rg = np.eye(3) + np.sin(theta) * K + (1 - np.cos(theta)) * K @ K
        one = rotation_log(tuple(Rg.ravel()), ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0)))
        many = _rotation_log(Rg[None], np.eye(3)[None])[0]
        assert np.linalg.norm(one) == pytest.approx(theta, abs=1e-7)
        np.testing.assert_allclose(np.abs(one), np.abs(theta * axis), atol=1e-6)
        np.testing.assert_allclose(many, one, atol=1e-6)
