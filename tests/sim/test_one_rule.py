"""One rule for limits and timing: Arm and every driver accept and refuse the same moves.

Before, ``arm.driver.move(q, duration=0.01)`` was stretched and accepted while
``arm.move_joints(..., duration=0.01)`` raised. Now both raise the same error and
nothing moves, on every driver (each arm's own on its simulated device, and the
Maestro with ``port="emu"``).
"""

from __future__ import annotations

import math
from collections.abc import Iterator

import numpy as np
import pytest

from armkit import Arm, JointLimitError
from armkit.cli import main
from armkit.connect import open_driver
from armkit.model import load_model
from armkit.model._limits import GripWidthError, constant_speed_time, move_time, shortest_time
from armkit.sim import World

CASES = [("owi535", "sim"), ("openmanipulator_x", "sim"), ("lynx6", "sim"), ("al5d", "sim")]
CASES += [("planar2", "sim"), ("puma560", "sim"), ("lynx6", "maestro")]


@pytest.fixture(params=CASES, ids=[f"{a}-{d}" for a, d in CASES])
def arm(request: pytest.FixtureRequest) -> Iterator[Arm]:
    name, driver = request.param
    model = load_model(name)
    with Arm(model, open_driver(model, driver, "emu")) as opened:
        yield opened


def _far(arm: Arm) -> np.ndarray:
    """A legal pose a good way from home (a quarter of each joint's range)."""
    m = arm.model
    return np.clip(m.home + 0.25 * (m.upper - m.lower), m.lower, m.upper)


def test_a_too_short_duration_is_refused_by_arm_and_driver_alike(arm: Arm) -> None:
    world = arm.world
    assert world is not None
    before, q = world.now(), _far(arm)
    with pytest.raises(ValueError, match="too short") as by_arm:
        arm.move_joints(list(np.degrees(q)), duration=0.01)
    with pytest.raises(ValueError, match="too short") as by_driver:
        arm.driver.move(q, duration=0.01)
    assert str(by_arm.value) == str(by_driver.value)
    assert world.now() == before  # nothing was sent, nothing waited
    np.testing.assert_array_equal(world.arm().q(), world.recording().q[0])


def test_limits_and_grip_width_are_refused_alike(arm: Arm) -> None:
    m, world = arm.model, arm.world
    assert world is not None
    bad = m.home.copy()
    bad[-1] = m.upper[-1] + 0.1
    for move in (lambda: arm.driver.move(bad), lambda: arm.move_joints(list(np.degrees(bad)))):
        with pytest.raises(JointLimitError, match=f"{m.joints[-1].name} .* is outside its limits"):
            move()
    too_wide = m.gripper.width_max + 0.01
    for grip in (lambda: arm.driver.grip(too_wide), lambda: arm.grip(too_wide * 1000)):
        with pytest.raises(GripWidthError, match="grip width") as info:
            grip()
        assert isinstance(info.value, ValueError) and isinstance(info.value, JointLimitError)
    assert world.now() == 0.0


def test_a_legal_duration_is_kept(arm: Arm) -> None:
    world = arm.world
    assert world is not None
    q = _far(arm)
    needed = constant_speed_time(arm.model, arm.driver.read(), q)
    if arm.model.name == "owi535":
        pytest.skip("the OWI's motors run at one speed: it checks the rule, cannot slow down")
    start = world.now()
    arm.driver.move(q, duration=needed + 1.0)
    assert world.now() - start >= needed + 1.0
    assert move_time(arm.model, q, q, duration=0.0) == 0.0


def test_without_a_duration_devices_that_ramp_take_the_trapezoid() -> None:
    omx = load_model("openmanipulator_x")
    q0, q1 = omx.home, omx.home + np.radians([40, 0, 0, 0])
    assert shortest_time(omx, q0, q1) > constant_speed_time(omx, q0, q1)
    assert move_time(omx, q0, q1) == shortest_time(omx, q0, q1)
    assert move_time(omx, q0, q1, ramps=False) == constant_speed_time(omx, q0, q1)
    with pytest.raises(ValueError, match="speed"):
        move_time(omx, q0, q1, speed=0.0)
    with pytest.raises(ValueError, match="duration"):
        move_time(omx, q0, q1, duration=math.nan)


@pytest.mark.parametrize("name", ["openmanipulator_x", "lynx6"])
def test_a_move_longer_than_one_device_command_goes_in_pieces(name: str) -> None:
    world = World()
    model = load_model(name)
    with Arm(model, "sim", world=world) as arm:
        q = np.clip(model.home + np.radians(5.0), model.lower, model.upper)
        with pytest.raises(ValueError, match="must wait"):
            arm.driver.move(q, duration=100.0, wait=False)
        assert world.now() == 0.0
        arm.driver.move(q, duration=100.0)
        assert world.now() >= 100.0
        np.testing.assert_allclose(arm.driver.read(), q, atol=math.radians(0.1))


def test_a_long_legal_move_completes_on_the_command_line(
    capsys: pytest.CaptureFixture[str],
) -> None:
    # the longest move the CLI accepts (MAX_MOVE_S, issue 10); a longer one is refused
    assert main(["joints", "10", "-60", "20", "40", "--duration", "30"]) == 0
    out = capsys.readouterr().out
    assert "joints waist 10.0" in out and "wrist 40.0" in out
    assert main(["joints", "-10", "-60", "20", "40", "--duration", "100"]) == 2
    assert "must be 0..30 s" in capsys.readouterr().err
