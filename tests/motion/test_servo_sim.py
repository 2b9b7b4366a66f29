"""The simulated servo arm: limits, lag, record at 1 kHz, virtual time, state file."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest

from armkit._errors import DeviceError, JointLimitError
from armkit.drivers._driver import Driver
from armkit.model import ArmModel
from armkit.motion import WallClock, clock_of
from armkit.sim import open_sim_driver
from armkit.sim.servo_arm import ServoArmSim, open_servo_sim
from armkit.sim.servo_dynamics import ServoBank, ServoParams


def _vmax(model: ArmModel) -> np.ndarray:
    return np.array([j.max_velocity for j in model.joints])


def test_sim_driver_is_the_servo_sim_for_servo_arms(omx: ArmModel) -> None:
    assert isinstance(open_sim_driver(omx, None), ServoArmSim)


def test_move_reaches_the_goal_within_speed_limits(omx: ArmModel) -> None:
    arm = open_servo_sim(omx)
    goal = omx.home + np.array([1.0, 0.4, -0.3, 0.2])
    arm.move(goal, speed=0.5)
    np.testing.assert_allclose(arm.read(), goal, atol=ServoParams().settle)
    rec = arm.recording()
    np.testing.assert_allclose(np.diff(rec.t), 0.001, atol=1e-9)  # 1 kHz of simulated time
    vel = np.diff(rec.q, axis=0) / 0.001
    assert np.all(np.abs(vel) <= 0.5 * _vmax(omx) * 1.05)
    assert rec.t[-1] == pytest.approx(arm.clock.now())


def test_joints_start_and_stop_together(omx: ArmModel) -> None:
    arm = open_servo_sim(omx)
    goal = omx.home + np.array([1.2, 0.1, -0.05, 0.6])
    arm.move(goal)
    q = arm.recording().q
    moving = np.abs(np.diff(q, axis=0)) > 1e-6
    # the slowest joint (waist) and a short mover (elbow) finish within a few lag constants
    done = [int(np.flatnonzero(col)[-1]) for col in moving.T]
    assert max(done) - min(done) < 80


def test_duration_gives_a_linear_move_of_that_length(lynx6: ArmModel) -> None:
    arm = open_servo_sim(lynx6)
    goal = lynx6.home + np.radians([10, -10, 5, 0, 0])
    arm.move(goal, duration=2.0, wait=False)
    arm.clock.sleep(1.0)
    halfway = (lynx6.home + goal) / 2
    lag = arm.params.lag * np.abs(goal - lynx6.home) / 2.0
    np.testing.assert_allclose(arm.read(), halfway, atol=float(np.max(lag)) * 1.2 + 1e-6)
    arm.clock.sleep(1.5)
    np.testing.assert_allclose(arm.read(), goal, atol=1e-4)


def test_first_order_lag_on_a_step() -> None:
    bank = ServoBank(np.zeros(1), np.array([100.0]), ServoParams(lag=0.02))
    bank.command_linear(np.array([0.1]), 0.001)
    for _ in range(20):
        bank.step()
    # the setpoint steps in the first tick; after one time constant, 63 % of the step
    assert bank.joint[0] == pytest.approx(0.1 * (1 - math.exp(-1.0)), rel=1e-9)


def test_backlash_leaves_a_dead_band_on_reversal() -> None:
    bank = ServoBank(np.zeros(1), np.array([10.0]), ServoParams(lag=0.005, backlash=0.01))
    bank.command_profile(np.array([0.1]), np.array([1.0]), np.array([10.0]))
    for _ in range(1000):
        bank.step()
    assert bank.joint[0] == pytest.approx(0.1 - 0.005, abs=1e-4)
    bank.command_profile(np.array([0.0]), np.array([1.0]), np.array([10.0]))
    for _ in range(1000):
        bank.step()
    assert bank.joint[0] == pytest.approx(0.005, abs=1e-4)


def test_refused_move_changes_nothing(omx: ArmModel) -> None:
    arm = open_servo_sim(omx)
    bad = omx.home.copy()
    bad[3] = math.radians(150)
    with pytest.raises(JointLimitError, match="wrist"):
        arm.move(bad)
    with pytest.raises(ValueError):
        arm.move(np.array([0.0, 0.0]))
    with pytest.raises(ValueError, match="grip width"):
        arm.grip(0.5)
    assert arm.commands == 0
    assert arm.clock.now() == 0.0
    np.testing.assert_array_equal(arm.read(), omx.home)


def test_grip_moves_the_gripper(omx: ArmModel) -> None:
    arm = open_servo_sim(omx)
    arm.grip(0.03)
    assert arm.grip_width == pytest.approx(0.03)
    assert arm.clock.now() > 0.5  # 45 mm at 50 mm/s


def test_state_file_round_trip_and_closed_arm(omx: ArmModel, tmp_path: Path) -> None:
    state = tmp_path / "state.json"
    arm = open_servo_sim(omx, str(state))
    assert not state.exists()
    goal = omx.home + 0.3
    arm.move(goal)
    arm.close()
    arm.close()
    with pytest.raises(DeviceError, match="closed"):
        arm.move(goal)
    again = open_servo_sim(omx, str(state))
    np.testing.assert_allclose(again.read(), goal, atol=ServoParams().settle)
    assert json.loads(state.read_text())["arm"] == "openmanipulator_x"


def test_state_file_of_another_arm_is_refused(
    omx: ArmModel, lynx6: ArmModel, tmp_path: Path
) -> None:
    state = tmp_path / "state.json"
    arm = open_servo_sim(omx, str(state))
    arm.move(omx.home + 0.1)
    arm.close()
    with pytest.raises(DeviceError, match="not for this lynx6"):
        open_servo_sim(lynx6, str(state))
    state.write_text("{not json")
    with pytest.raises(DeviceError, match="unreadable"):
        open_servo_sim(omx, str(state))


def test_recording_writes_csv(omx: ArmModel, tmp_path: Path) -> None:
    arm = open_servo_sim(omx)
    arm.move(omx.home + 0.05)
    out = tmp_path / "rec.csv"
    rows = arm.recording().write_csv(out)
    lines = out.read_text().splitlines()
    assert lines[0] == "t_s,waist_deg,shoulder_deg,elbow_deg,wrist_deg"
    assert len(lines) == rows + 1
    assert rows == len(arm.recording().t)
    first = [float(v) for v in lines[1].split(",")]
    assert first[0] == 0.0
    np.testing.assert_allclose(first[1:], np.degrees(omx.home), atol=1e-5)


def test_servo_sim_is_a_driver_with_a_virtual_clock(omx: ArmModel) -> None:
    arm = open_servo_sim(omx)
    assert isinstance(arm, Driver)
    assert clock_of(arm) is arm.clock
    arm.clock.sleep(0.25)
    assert arm.clock.now() == pytest.approx(0.25)
    assert len(arm.recording().t) == 251
    assert isinstance(clock_of(object()), WallClock)


def test_backlash_shows_in_the_arm_after_a_reversal(omx: ArmModel) -> None:
    band = math.radians(1.0)
    arm = open_servo_sim(omx, None, ServoParams(lag=0.01, backlash=band))
    out = omx.home + np.array([0.3, 0.0, 0.0, 0.0])
    arm.move(out)
    arm.move(omx.home)
    # the joint stays half the band short of the motor, which settles to within `settle`
    assert arm.read()[0] == pytest.approx(omx.home[0] + band / 2, abs=arm.params.settle)
