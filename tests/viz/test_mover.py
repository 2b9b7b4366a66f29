"""The mover and the driver source on the simulated arm (no page)."""

from __future__ import annotations

import math

import numpy as np
import pytest

import armkit
from armkit.viz import DriverSource, Goal, Mover


@pytest.fixture
def arm() -> armkit.Arm:
    return armkit.Arm("openmanipulator_x")  # in-memory simulator: no state file


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
    source = DriverSource(arm.model, arm.driver)
    mover = Mover(arm)
    try:
        mover.request(Goal(grip=0.03))
        assert mover.wait_idle(10.0)
        state = source.state()
        assert state.grip == pytest.approx(0.03)
        np.testing.assert_array_equal(state.q, arm.driver.read())
    finally:
        mover.close()


def test_a_driver_has_no_history(arm: armkit.Arm) -> None:
    with pytest.raises(ValueError, match="now"):
        DriverSource(arm.model, arm.driver).state(1.0)
