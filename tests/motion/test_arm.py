"""Arm: mm and degrees at the boundary, round trips, refusals that move nothing."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from armkit._errors import DeviceError, InputError, JointLimitError, UnreachableError
from armkit.arm import Arm
from armkit.kinematics import fk, pitch_of
from armkit.model import load_model
from armkit.motion import EarlyStreaming, PathError, circle
from armkit.scene import check_clear
from armkit.sim import World
from armkit.sim._servo_body import ServoParams

OMX = load_model("openmanipulator_x")

# a blocking move ends when every servo is within its settle band
SETTLE_DEG = math.degrees(ServoParams().settle) + 1e-6
NEAR_MM = 0.5  # the tool point for joints within SETTLE_DEG


def _world(arm: Arm) -> World:
    assert arm.world is not None
    return arm.world


@settings(max_examples=30, derandomize=True, deadline=None)
@given(st.lists(st.floats(0.1, 0.9), min_size=4, max_size=4))
def test_move_to_round_trip(fractions: list[float]) -> None:
    q = OMX.lower + np.array(fractions) * (OMX.upper - OMX.lower)
    assume(check_clear(OMX, q) is None)  # poses with a link in the table are refused
    T = fk(OMX, q)
    x, y, z = T[:3, 3] * 1000
    pitch = math.degrees(float(pitch_of(T)))
    with Arm(OMX, "sim") as arm:
        arm.move_to(x, y, z, pitch)
        where = arm.position()
    assert math.dist(where[:3], (x, y, z)) < NEAR_MM
    assert where.pitch == pytest.approx(pitch, abs=3 * SETTLE_DEG)  # three pitch joints


def test_move_joints_turn_and_angles() -> None:
    with Arm("lynx6", "sim") as arm:
        arm.move_joints([80, 100, 70, 95, 90])
        assert list(arm.angles().values()) == pytest.approx([80, 100, 70, 95, 90], abs=SETTLE_DEG)
        arm.move_joints({"elbow": 60})
        arm.turn_to("base", 120)
        arm.turn_by("wrist", -15)
        got = arm.angles()
        assert [got["base"], got["elbow"], got["wrist"]] == pytest.approx(
            [120, 60, 80], abs=SETTLE_DEG
        )
        arm.home()
        assert list(arm.angles().values()) == pytest.approx([90] * 5, abs=SETTLE_DEG)


def test_refused_moves_send_nothing() -> None:
    with Arm(OMX, "sim") as arm:
        world = _world(arm)
        with pytest.raises(UnreachableError):
            arm.move_to(600, 0, 50)
        with pytest.raises(JointLimitError, match="wrist"):
            arm.move_joints({"wrist": 150})
        with pytest.raises(ValueError, match="give 4 angles"):
            arm.move_joints([0, 0, 0])
        with pytest.raises(ValueError, match="unknown joint"):
            arm.turn_to("knee", 10)
        with pytest.raises(ValueError, match="speed"):
            arm.move_to(150, 0, 100, speed=0.0)
        with pytest.raises(ValueError, match="too short"):
            arm.move_joints({"waist": 90}, duration=0.1)
        with pytest.raises(ValueError, match="grip width"):
            arm.grip(200)
        assert world.now() == 0.0  # nothing waited: nothing was sent
        assert len(world.recording().t) == 1


def test_refused_path_moves_nothing() -> None:
    with Arm(OMX, "sim") as arm:
        world = _world(arm)
        start = arm.angles()
        far = circle([0.25, 0.0, 0.05], 0.06, 0.002) * 1000  # crosses out of reach
        with pytest.raises(PathError, match="is unreachable"):
            arm.follow(far, -90)
        assert world.now() == 0.0
        assert len(world.recording().t) == 1
        assert arm.angles() == start


@pytest.mark.parametrize("pitch", ["down", [1, 2], float("nan")])
def test_a_bad_pitch_of_a_path_is_an_input_error_and_moves_nothing(pitch: object) -> None:
    with Arm(OMX, "sim") as arm:
        world = _world(arm)
        pts = circle([0.17, 0.0, 0.05], 0.02, 0.002) * 1000
        for call in (lambda: arm.follow(pts, pitch), lambda: arm.approach(170, 0, 50, pitch)):  # type: ignore[arg-type]
            with pytest.raises(InputError, match=r"pitch \[deg\]"):
                call()
        with pytest.raises(InputError, match=r"x, y, z \[mm\]"):
            arm.approach(170, 0, "low")  # type: ignore[arg-type]
        assert world.now() == 0.0


def test_bad_joint_angles_and_streamers_are_input_errors() -> None:
    with Arm(OMX, "sim") as arm:
        world = _world(arm)
        with pytest.raises(InputError, match=r"waist \[deg\]"):
            arm.move_joints({"waist": "x"})  # type: ignore[dict-item]
        with pytest.raises(InputError, match=r"elbow \[deg\]"):
            arm.turn_by("elbow", [1, 2])  # type: ignore[arg-type]
        with pytest.raises(InputError, match="streamer must be NaiveStepping"):
            arm.follow([[170, 0, 50], [180, 0, 50]], streamer="fast")  # type: ignore[arg-type]
        with pytest.raises(InputError, match="wait must be True or False, got 'no'"):
            arm.move_to(170, 0, 50, wait="no")  # type: ignore[arg-type]
        assert world.now() == 0.0


def test_follow_draws_the_path() -> None:
    with Arm(OMX, "sim") as arm:
        pts = circle([0.17, 0.0, 0.05], 0.02, 0.002) * 1000
        path = arm.follow(pts, -90, streamer=EarlyStreaming(fraction=0.6))
        assert path.q.shape == (len(pts), 4)
        assert math.dist(arm.position()[:3], pts[-1]) < NEAR_MM


def test_timeout_stops_the_arm_and_context_closes() -> None:
    arm = Arm(OMX, "sim")
    with pytest.raises(DeviceError, match=r"within 0\.05 s"):
        arm.move_joints({"waist": 90}, timeout=0.05)
    assert 0 < arm.angles()["waist"] < 90
    with arm:
        pass
    with pytest.raises(DeviceError, match="closed"):
        arm.home()


def test_grip_changes_the_grip_point_of_a_scissor_gripper() -> None:
    with Arm("lynx6", "sim") as arm:
        closed = arm.position()
        arm.grip(40)
        opened = arm.position()
    assert closed.z != pytest.approx(opened.z, abs=1.0) or closed.x != pytest.approx(
        opened.x, abs=1.0
    )


def test_approach_from_above_and_retreat() -> None:
    with Arm(OMX, "sim") as arm:
        arm.approach(180, 20, 30, -90)
        world = _world(arm)
        t = world.recording().t
        tool = fk(OMX, world.recording().q)[:, :3, 3] * 1000
        assert math.dist(arm.position()[:3], (180, 20, 30)) < NEAR_MM
        # the last 30 mm are straight down onto the point
        low = tool[:, 2] < 59.0
        assert np.all(np.hypot(tool[low, 0] - 180, tool[low, 1] - 20) < 0.5)
        arm.retreat()
        assert math.dist(arm.position()[:3], (180, 20, 60)) < NEAR_MM
        assert world.now() > t[-1]
        with pytest.raises(PathError):
            arm.approach(600, 0, 30, -90)


def test_single_joint_turn_after_a_move_settles() -> None:
    """Regression: joints that barely move in a shared profile (steps below one ulp)
    used to never reach their goal, so the move timed out."""
    with Arm("openmanipulator_x", driver="sim") as arm:
        arm.move_to(200, 0, 50, pitch=-90)
        arm.grip(30)
        arm.turn_by("waist", 20)
        assert abs(arm.angles()["waist"] - 20.0) < 0.1
