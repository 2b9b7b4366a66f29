"""The target check behind the marker: reach, joint limits, the table."""

from __future__ import annotations

import math

import numpy as np

import armkit
from armkit.viz import check_target, table_clearance
from armkit.viz._target import describe

OMX = armkit.load_model("openmanipulator_x")


def test_a_target_above_a_cube_is_reachable_and_clear() -> None:
    check = check_target(OMX, (0.2, 0.0, 0.06), -math.pi / 2)
    assert check.ok and check.reason == ""
    np.testing.assert_allclose(armkit.fk(OMX, check.q)[:3, 3], (0.2, 0.0, 0.06), atol=1e-6)
    assert "reachable and clear" in describe(check)


def test_too_far_says_so() -> None:
    check = check_target(OMX, (0.6, 0.0, 0.05), None)
    assert not check.ok and "out of reach" in check.reason
    assert "(600, 0, 50) mm" in describe(check)


def test_below_the_table_is_refused_with_the_link() -> None:
    # reachable for the kinematics (z < 0), but the tool link would go into the table
    check = check_target(OMX, (0.2, 0.0, -0.01), -math.pi / 2)
    assert armkit.ik(OMX, np.array([0.2, 0.0, -0.01]), -math.pi / 2).q is not None
    assert not check.ok and "table" in check.reason and "link" in check.reason


def test_table_clearance_ignores_the_base_column_and_sees_a_raised_table() -> None:
    assert table_clearance(OMX, OMX.home) is None
    from dataclasses import replace

    raised = replace(OMX, table_z=0.3)
    assert "table" in (table_clearance(raised, OMX.home) or "")


def test_a_joint_limit_in_the_way_is_named() -> None:
    # pointing straight up at 200 mm forward needs the wrist past its limit
    check = check_target(OMX, (0.2, 0.0, 0.2), math.pi / 2)
    assert not check.ok and check.reason == "a joint limit is in the way"


def test_extra_clearance_checks_plug_in() -> None:
    def board(model: armkit.ArmModel, q: np.ndarray) -> str | None:
        return "the board is in the way"

    check = check_target(OMX, (0.2, 0.0, 0.06), -math.pi / 2, clearances=(table_clearance, board))
    assert not check.ok and check.reason == "the board is in the way"
