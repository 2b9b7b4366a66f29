"""CCD, Jacobian iteration and 003's random search, with honest expectations:
whatever they return is right (fk within tolerance, limits held); when they
give up they say so with a closest pose inside the limits; on easy arms most
targets are solved."""

from __future__ import annotations

import numpy as np
import pytest
from numeric_cases import TOL_ANG, TOL_POS, assert_reaches, joint_vectors, solve, target_for

from armkit._errors import UnreachableError
from armkit.model import load_model

# method, arm, share of 20 reachable position targets at least solved
EXPECT = [
    ("ccd", "planar2", 0.7),
    ("ccd", "openmanipulator_x", 0.3),
    ("jacobian", "planar2", 0.8),
    ("jacobian", "openmanipulator_x", 0.8),
    ("random", "planar2", 0.6),
    ("random", "openmanipulator_x", 0.5),
]


@pytest.mark.parametrize(("method", "arm", "share"), EXPECT)
def test_method_answers_are_right_or_honest_failures(method: str, arm: str, share: float) -> None:
    model = load_model(arm)
    solved = 0
    for q in joint_vectors(model, 20, seed=7):
        target = target_for(model, q, "position")
        try:
            result = solve(method, model, target, model.home, TOL_POS, TOL_ANG, rng_seed=1)
        except UnreachableError as exc:
            assert exc.reason == "no_convergence"
            assert model.within_limits(exc.closest, slack=0.0)
            continue
        assert result.method == method
        assert_reaches(model, result.q, target, TOL_POS, TOL_ANG)
        solved += 1
    assert solved >= share * 20


@pytest.mark.parametrize("method", ["ccd", "jacobian", "random"])
def test_method_handles_pitch_and_pose_on_an_easy_target(method: str) -> None:
    model = load_model("openmanipulator_x")
    q = np.radians([10.0, 5.0, 10.0, 20.0])
    for mask in ("position+pitch", "pose"):
        target = target_for(model, q, mask)
        result = solve(method, model, target, model.home, TOL_POS, TOL_ANG, rng_seed=2)
        assert_reaches(model, result.q, target, TOL_POS, TOL_ANG)
