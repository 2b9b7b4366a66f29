"""The forecast the script checker times OWI scripts with is the driver's own plan:
the same runs, the same times, the same estimate after them."""

from __future__ import annotations

import math

import numpy as np
import pytest

from armkit import UnreachableError
from armkit.drivers.timed import TimedDriver, forecast_move, forecast_run, grip_seconds
from armkit.model import ArmModel
from armkit.sim.owi_sim import OwiSim

DEG = math.radians


@pytest.mark.filterwarnings("ignore::armkit.drivers.timed.UncertainEstimateWarning")
def test_forecast_move_is_the_driver_s_runs(owi: ArmModel, driver: TimedDriver) -> None:
    rng = np.random.default_rng(3)
    for _ in range(6):  # gravity both ways, several joint orders, a rising battery count
        goal = rng.uniform(owi.lower, owi.upper) * 0.6
        ahead = forecast_move(driver.timing, owi, driver.read(), goal, driver.state.motor_s)
        report = driver.move_report(goal)
        assert [(s.joint, s.direction, s.target) for s in ahead.steps] == [
            (s.joint, s.direction, s.target) for s in report.steps
        ]
        assert [s.seconds for s in ahead.steps] == pytest.approx([s.seconds for s in report.steps])
        assert ahead.q == pytest.approx(driver.read(), abs=1e-9)
        assert ahead.motor_s == pytest.approx(driver.state.motor_s)


@pytest.mark.filterwarnings("ignore::armkit.drivers.timed.UncertainEstimateWarning")
def test_the_estimate_after_a_move_is_forecast_as_the_driver_advances_it(
    owi: ArmModel, sim: OwiSim, driver: TimedDriver
) -> None:
    # check = run's OWI seed 349: from home, the shoulder's run to 10 deg leaves the
    # driver's estimate at 10.25 deg (advanced by the run's time, after_run), and the
    # next move is timed from there; the forecast said 10, so home was 0.1 s short
    goal = np.radians([18.0, 10.0, -22.0, 29.0])
    ahead = forecast_move(driver.timing, owi, driver.read(), goal, driver.state.motor_s)
    driver.move(goal)
    assert ahead.q == pytest.approx(driver.read(), abs=1e-9)
    home = forecast_move(driver.timing, owi, ahead.q, owi.home, ahead.motor_s)
    t0 = sim.clock.now()
    driver.move(owi.home)
    assert sim.clock.now() - t0 == pytest.approx(home.seconds, abs=0.005)


def test_forecast_move_refuses_what_the_driver_refuses(owi: ArmModel, driver: TimedDriver) -> None:
    into_the_table = np.radians([0.0, 90.0, 90.0, 0.0])
    with pytest.raises(UnreachableError, match="below the table"):
        forecast_move(driver.timing, owi, driver.read(), into_the_table)
    with pytest.raises(UnreachableError, match="below the table"):
        driver.move(into_the_table)


def test_a_short_turn_is_forecast_as_two_legs(owi: ArmModel, driver: TimedDriver) -> None:
    goal = driver.read()
    goal[0] += DEG(3)
    ahead = forecast_move(driver.timing, owi, driver.read(), goal)
    assert [s.joint for s in ahead.steps] == [0, 0]
    assert ahead.q[0] == pytest.approx(goal[0])


def test_forecast_run_and_grip_are_the_driver_s(owi: ArmModel, driver: TimedDriver) -> None:
    ahead = forecast_run(driver.timing, driver.read(), 1, 1, 1.5, driver.state.motor_s)
    driver.turn_for("shoulder", 1, 1.5)
    assert ahead.q == pytest.approx(driver.read(), abs=1e-6)
    assert ahead.seconds == 1.5
    assert grip_seconds(driver.timing, owi, None, 0.0) == driver.timing.gripper_s
    assert grip_seconds(driver.timing, owi, 0.0, 0.0) == 0.0  # already closed: nothing runs
