"""LM: fk of the answer equals the target within the tolerance, tool included,
and the limits hold, on every arm and every task mask."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from numeric_cases import ARMS, TOL_ANG, TOL_POS, assert_reaches, masks_for, solve, target_for

from armkit._errors import NoSolutionError, UnreachableError
from armkit.kinematics import Target, fk
from armkit.model import load_model

CASES = [(arm, mask) for arm in ARMS for mask in masks_for(load_model(arm))]


@pytest.mark.parametrize(("arm", "mask"), CASES)
@settings(max_examples=12, deadline=None, derandomize=True)
@given(u=st.lists(st.floats(0.0, 1.0), min_size=6, max_size=6))
def test_lm_reaches_reachable_targets(arm: str, mask: str, u: list[float]) -> None:
    model = load_model(arm)
    q_true = model.lower + np.array(u[: model.dof]) * (model.upper - model.lower)
    target = target_for(model, q_true, mask)
    result = solve("lm", model, target, model.home, TOL_POS, TOL_ANG)
    assert result.method == "lm"
    assert result.solutions.shape == (1, model.dof)
    assert result.position_error <= TOL_POS and result.angle_error <= TOL_ANG
    assert_reaches(model, result.q, target, TOL_POS, TOL_ANG)


def test_lm_includes_the_tool() -> None:
    """Not RTB's bug: the tool is applied once, so a longer tool moves the answer."""
    model = load_model("openmanipulator_x")
    longer = model.with_tool_length(model.tool_length + 0.05)
    target = target_for(model, np.radians([20.0, 10.0, 10.0, 30.0]), "position")
    q = solve("lm", longer, target, model.home, TOL_POS, TOL_ANG).q
    assert np.linalg.norm(fk(longer, q)[:3, 3] - target.position) <= TOL_POS
    assert np.linalg.norm(fk(model, q)[:3, 3] - target.position) > 0.01


def test_lm_is_reproducible_from_its_seed() -> None:
    model = load_model("puma560")
    target = target_for(model, np.radians([100.0, 150.0, -200.0, 50.0, -60.0, 200.0]), "pose")
    a = solve("lm", model, target, model.home, TOL_POS, TOL_ANG, rng_seed=4)
    b = solve("lm", model, target, model.home, TOL_POS, TOL_ANG, rng_seed=4)
    np.testing.assert_array_equal(a.q, b.q)


def test_lm_out_of_reach_raises_with_the_closest_pose() -> None:
    model = load_model("openmanipulator_x")
    with pytest.raises(UnreachableError) as info:
        solve("lm", model, Target(np.array([2.0, 0.0, 0.1])), model.home, TOL_POS, TOL_ANG)
    assert info.value.reason == "too_far"
    assert model.within_limits(info.value.closest)


def test_lm_target_outside_the_limits_raises_no_solution() -> None:
    model = load_model("owi535")  # wrist limited to +-60 deg: pointing straight up is impossible
    target = target_for(model, np.radians([0.0, 0.0, 0.0, 0.0]), "position+pitch")
    target = Target(target.position - np.array([0.0, 0.0, 0.15]), 0.0)
    with pytest.raises(NoSolutionError) as info:
        solve("lm", model, target, model.home, TOL_POS, TOL_ANG)
    assert info.value.reason == "no_convergence"
    assert model.within_limits(info.value.closest)
