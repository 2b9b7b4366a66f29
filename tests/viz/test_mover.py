"""The mover and the driver source on the simulated arm (no page)."""

from __future__ import annotations

import math
from collections.abc import Iterator

import numpy as np
import pytest

import armkit
from armkit.viz import ArmSource, Goal, Mover


@pytest.fixture
def arm() -> Iterator[armkit.Arm]:
    with armkit.Arm("openmanipulator_x") as arm:  # in-memory simulator: no state file
        yield arm


def test_mover_reaches_the_latest_goal(arm: armkit.Arm) -> None:
    messages: list[str] = []
    mover = Mover(arm, on_error=messages.append)
    try:
        first = np.radians([10.0, 0.0, 0.0, 0.0])
        last = np.radians([-20.0, 10.0, 5.0, -30.0])
        mover.request(Goal(q=first, speed=1.0))
        mover.request(Goal(q=last, speed=1.0))
        assert mover.wait_idle(30.0)
        np.testing.assert_allclose(arm.driver.read(), last, atol=math.radians(0.05))
        assert messages == []
    finally:
        mover.close()


def test_a_refused_goal_is_reported_and_nothing_moves(arm: armkit.Arm) -> None:
    messages: list[str] = []
    mover = Mover(arm, on_error=messages.append)
    try:
        before = arm.driver.read()
        mover.request(Goal(q=np.radians([0.0, 120.0, 0.0, 0.0])))
        assert mover.wait_idle(10.0)
        assert len(messages) == 1 and "shoulder" in messages[0] and "limits" in messages[0]
        np.testing.assert_array_equal(arm.driver.read(), before)
    finally:
        mover.close()


def test_grip_goal_opens_the_jaws_and_the_source_reads_it(arm: armkit.Arm) -> None:
    source = ArmSource(arm)
    mover = Mover(arm)
    try:
        mover.request(Goal(grip=0.03))
        assert mover.wait_idle(10.0)
        state = source.state()
        assert state.grip == pytest.approx(0.03, abs=7e-5)  # one gripper tick: 0.063 mm
        assert arm.world is not None  # on the simulator the source shows the world's truth
        truth = arm.world.arm()
        np.testing.assert_array_equal(state.q, truth.q())
        assert state.grip == truth.grip()
        np.testing.assert_allclose(state.q, arm.driver.read(), atol=math.radians(0.1))
    finally:
        mover.close()


class _Hardware:
    """An arm with no simulation world behind it (real hardware, as a view sees it)."""

    def __init__(self, model: armkit.ArmModel) -> None:
        self.model, self.world, self.sim = model, None, None

    def read(self) -> np.ndarray:
        return np.radians([1.0, 2.0, 3.0, 4.0])


def test_on_hardware_the_source_reads_the_arm_back(arm: armkit.Arm) -> None:
    source = ArmSource(_Hardware(arm.model))  # type: ignore[arg-type]
    source.set_grip(0.025)
    state = source.state()
    np.testing.assert_array_equal(state.q, np.radians([1.0, 2.0, 3.0, 4.0]))
    assert state.grip == 0.025


def test_a_driver_has_no_history(arm: armkit.Arm) -> None:
    with pytest.raises(ValueError, match="now"):
        ArmSource(arm).state(1.0)
