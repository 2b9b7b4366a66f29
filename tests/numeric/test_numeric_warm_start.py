"""LM's warm start (the first joint's exact turn), the scalar chain's tool shortcut,
and the clamp: each checked against the plain definitions."""

from __future__ import annotations

import math
from dataclasses import replace

import lm_reference as _lm
import numpy as np
import pytest
from numeric_cases import ARMS, TOL_ANG, TOL_POS, joint_vectors, masks_for, target_for

from armkit.kinematics import fk, jacobian
from armkit.kinematics._chain import chain_of
from armkit.kinematics._numeric._sampling import clamp
from armkit.kinematics._numeric._turn import best_turn
from armkit.kinematics._residual import Task, residual
from armkit.model import load_model


def _problem(model, task):  # type: ignore[no-untyped-def]
    chain = chain_of(model)
    return _lm._Problem(
        chain.state, task, chain.lower, chain.upper, TOL_POS, TOL_ANG, _lm.DEFAULT_SETTINGS
    )


def task_of(model, target):  # type: ignore[no-untyped-def]
    """The solvers' Task of a Target."""
    p = tuple(np.asarray(target.position, dtype=float).tolist())
    R = None if target.orientation is None else tuple(np.ravel(target.orientation).tolist())
    return Task(p, target.pitch, R, chain_of(model).weight)


@pytest.mark.parametrize("arm", ARMS)
def test_best_turn_is_the_best_angle_of_that_joint(arm: str) -> None:
    """No angle of joint 0 on a fine grid beats best_turn's (position targets: exact)."""
    model = load_model(arm)
    state = chain_of(model).state
    qs = joint_vectors(model, 6, seed=3)
    for q, qt in zip(qs[:3], qs[3:], strict=True):
        task = task_of(model, target_for(model, qt, "position"))
        t = best_turn(task, state(q.tolist()), 0)

        def cost(angle: float, q: np.ndarray = q, task=task) -> float:  # type: ignore[no-untyped-def]
            return residual(task, state([q[0] + angle, *q[1:].tolist()]), jac=False).cost

        grid = min(cost(a) for a in np.linspace(-math.pi, math.pi, 721))
        assert cost(t) <= grid + 1e-12


@pytest.mark.parametrize("arm", ARMS)
def test_turn_first_joint_lowers_the_cost_or_faces_away(arm: str) -> None:
    model = load_model(arm)
    qs = joint_vectors(model, 40, seed=4)
    for q, qt in zip(qs[:20], qs[20:], strict=True):
        for mask in masks_for(model):
            prob = _problem(model, task_of(model, target_for(model, qt, mask)))
            st = prob.state(q.tolist())
            res = residual(prob.task, st, jac=False)
            q2, st2, res2 = _lm._turn_first_joint(prob, q.tolist(), st, res)
            assert q2[1:] == q.tolist()[1:]
            assert st2.p == prob.state(q2).p
            assert prob.lower[0] <= q2[0] <= prob.upper[0]
            assert res2.cost == residual(prob.task, prob.state(q2), jac=False).cost
            if res2.cost > res.cost:  # allowed only when facing away from an unreachable best
                best = q[0] + best_turn(prob.task, st, 0)
                assert not prob.lower[0] <= best <= prob.upper[0]
                assert abs(abs(q2[0] - best) - math.pi) < 1e-9


def test_facing_away_reaches_targets_behind_the_al5d_without_restarts() -> None:
    """The AL5D's base turns +-90 deg: a target behind it is reached by leaning back
    over the base. From home, LM with the warm start finds that in its first run."""
    model = load_model("al5d")
    q_behind = np.radians([25.0, -37.0, -83.0, -87.0, 56.0])  # tool point behind the base
    target = target_for(model, q_behind, "position")
    prob = _problem(model, task_of(model, target))
    _, res, _ = _lm.lm_run(prob, model.home.tolist())
    assert res.position_error <= TOL_POS


def test_scalar_chain_with_a_tool_that_is_not_square() -> None:
    """A tool mounted at an odd angle: every rotation term is written out; still equals the sweep."""
    model = load_model("openmanipulator_x")
    c, s = math.cos(0.3), math.sin(0.3)
    T = model.T_flange_tool.copy()
    T[:3, :3] = T[:3, :3] @ np.array([[c, 0.0, s], [0.0, 1.0, 0.0], [-s, 0.0, c]])
    T[:3, 3] += [0.01, -0.02, 0.005]
    odd = replace(model, T_flange_tool=T)
    chain = chain_of(odd)
    assert chain.tool.columns[0] is not None and chain.tool.columns[2] is not None
    for q in joint_vectors(odd, 10, seed=6):
        st = chain.state(q.tolist())
        Tq = fk(odd, q[None])[0]
        np.testing.assert_allclose(st.p, Tq[:3, 3], atol=1e-12)
        np.testing.assert_allclose(np.array(st.R).T, Tq[:3, :3], atol=1e-12)
        np.testing.assert_allclose(np.array(st.jv).T, jacobian(odd, q)[:3], atol=1e-12)


def test_clamp_keeps_joints_inside_and_returns_python_floats() -> None:
    out = clamp([np.float64(-5.0), 0.5, 7], [-1.0, -1.0, -1.0], [1.0, 1.0, 1.0])
    assert out == [-1.0, 0.5, 1.0]
    assert all(type(v) is float for v in out)
