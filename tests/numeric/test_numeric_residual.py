"""The residual's Jacobian rows are the derivatives of its rows (finite differences), and
the residual on lanes (k targets) is the residual of each."""

from __future__ import annotations

import numpy as np
import pytest
from numeric_cases import ARMS, joint_vectors, target_for

from armkit.kinematics._chain import chain_of
from armkit.kinematics._lanes import LANES
from armkit.kinematics._residual import Task, residual, rotation_log
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
        eye = tuple(tuple(np.array([v]) for v in col) for col in np.eye(3))
        many = np.ravel(rotation_log(tuple(np.array([v]) for v in Rg.ravel()), eye, LANES))
        assert np.linalg.norm(one) == pytest.approx(theta, abs=1e-7)
        np.testing.assert_allclose(np.abs(one), np.abs(theta * axis), atol=1e-6)
        np.testing.assert_allclose(many, one, atol=1e-6)


@pytest.mark.parametrize("arm", ARMS)
@pytest.mark.parametrize("mask", ["position", "position+pitch", "pose"])
def test_residual_on_lanes_is_the_residual_of_each_target(arm: str, mask: str) -> None:
    model = load_model(arm)
    chain = chain_of(model)
    qs = joint_vectors(model, 12, seed=7)
    tasks = [task_of(model, target_for(model, q, mask)) for q in qs[::-1]]
    lanes = Task(
        tuple(np.array(v) for v in zip(*(t.p for t in tasks), strict=True)),
        None if tasks[0].pitch is None else np.array([t.pitch for t in tasks]),
        None if tasks[0].R is None else tuple(np.array(v) for v in zip(*(t.R for t in tasks), strict=True)),
        tasks[0].weight,
    )  # fmt: skip
    many = residual(lanes, chain.lanes(list(qs.T)))
    for i, (task, q) in enumerate(zip(tasks, qs, strict=True)):
        one = residual(task, chain.state(q.tolist()))
        np.testing.assert_allclose([v[i] for v in many.e], one.e, atol=1e-12)
        assert many.cols is not None and one.cols is not None
        for col_many, col_one in zip(many.cols, one.cols, strict=True):
            np.testing.assert_allclose(
                [np.broadcast_to(v, qs.shape[:1])[i] for v in col_many], col_one, atol=1e-12
            )
        assert many.position_error[i] == pytest.approx(one.position_error, abs=1e-12)
        assert np.broadcast_to(many.angle_error, qs.shape[:1])[i] == pytest.approx(
            one.angle_error, abs=1e-12
        )
