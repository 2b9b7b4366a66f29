"""The target check behind the marker: reach, joint limits, the table."""

from __future__ import annotations

import math

import numpy as np

import armkit
from armkit.scene import load_scene
from armkit.viz import check_target
from armkit.viz._target import describe_target

OMX = armkit.load_model("openmanipulator_x")


def test_a_target_above_a_cube_is_reachable_and_clear() -> None:
    check = check_target(OMX, (0.2, 0.0, 0.06), -math.pi / 2)
    assert check.ok and check.reason == ""
    np.testing.assert_allclose(armkit.fk(OMX, check.q)[:3, 3], (0.2, 0.0, 0.06), atol=1e-6)
    assert "reachable and clear" in describe_target(check)


def test_too_far_says_so() -> None:
    check = check_target(OMX, (0.6, 0.0, 0.05), None)
    assert not check.ok and "out of reach" in check.reason
    assert "(600, 0, 50) mm" in describe_target(check)


def test_below_the_table_is_refused_with_the_link() -> None:
    # reachable for the kinematics (z < 0), but the tool link would go into the table
    check = check_target(OMX, (0.2, 0.0, -0.01), -math.pi / 2)
    assert armkit.ik(OMX, np.array([0.2, 0.0, -0.01]), -math.pi / 2).q is not None
    assert not check.ok and check.reason == "the gripper would be 10.0 mm into the table"


def test_a_raised_table_is_in_the_way() -> None:
    from dataclasses import replace

    raised = replace(OMX, table_z=0.1)
    check = check_target(raised, (0.2, 0.0, 0.06), -math.pi / 2)
    assert not check.ok and "table" in check.reason


def test_a_joint_limit_in_the_way_is_named() -> None:
    # pointing straight up at 200 mm forward needs the wrist past its limit
    check = check_target(OMX, (0.2, 0.0, 0.2), math.pi / 2)
    assert not check.ok and check.reason == "a joint limit is in the way"


def test_the_board_is_in_the_way_and_a_cube_is_not_when_the_target_is_on_it() -> None:
    scene = load_scene("board_001")
    red = scene.cube("red")
    on_red = check_target(OMX, red.center, -math.pi / 2, scene=scene)
    assert on_red.ok and on_red.on == "red"
    assert "on red, reachable and clear" in describe_target(on_red)
    # inside the board, between two sockets: the gripper would go into the board
    board = scene.board("board")
    inside = board.origin + np.array([-0.0225, 0.0, -0.003])
    check = check_target(OMX, inside, -math.pi / 2, scene=scene)
    assert not check.ok and check.on == "" and "board" in check.reason
    # the same point without the scene: only the table plane, and it is above it
    assert check_target(OMX, inside, -math.pi / 2).ok
