"""Straight lines on the OWI-535: followed through waypoints its timed motors make in
one run each (no two-leg back-and-forth per millimetre), within PATH_TOLERANCE of the
line by the plan, and timed by the script checker as the driver runs them."""

from __future__ import annotations

import math

import numpy as np
import pytest

from armkit import Arm, UnreachableError
from armkit.drivers.timed import (
    PATH_TOLERANCE,
    TimedDriver,
    default_timing,
    forecast_move,
    path_waypoints,
    plan_path_runs,
)
from armkit.kinematics import ik
from armkit.model import ArmModel
from armkit.motion import JointPath, line, plan_path
from armkit.script import Source, run_source
from armkit.sim import World

pytestmark = pytest.mark.filterwarnings("ignore::armkit.drivers.timed.UncertainEstimateWarning")

LINES_MM = [  # 20, 50 and 100 mm: in the arm's plane, across it (the base), up
    ((200.0, 0.0, 150.0), (220.0, 0.0, 150.0)),
    ((200.0, -25.0, 120.0), (200.0, 25.0, 120.0)),
    ((150.0, 0.0, 120.0), (250.0, 0.0, 120.0)),
    ((220.0, 0.0, 80.0), (220.0, 0.0, 130.0)),
]


def _line_path(owi: ArmModel, a: tuple[float, ...], b: tuple[float, ...]) -> JointPath:
    start, end = np.array(a) / 1000.0, np.array(b) / 1000.0
    return plan_path(owi, line(start, end, 0.002), None, ik(owi, start, None, owi.home).q)


@pytest.mark.parametrize(("a", "b"), LINES_MM)
def test_a_line_is_one_run_per_joint_level_within_the_tolerance(
    owi: ArmModel, a: tuple[float, ...], b: tuple[float, ...]
) -> None:
    timing = default_timing(owi)
    path = _line_path(owi, a, b)
    runs = plan_path_runs(timing, owi, path.q[0], 0.0, path.q, path.points)
    assert 0.0 <= runs.deviation <= PATH_TOLERANCE
    assert runs.q == pytest.approx(path.q[-1], abs=math.radians(0.5))
    pose, steps = path.q[0], []
    for w in runs.waypoints:
        ahead = forecast_move(timing, owi, pose, w)
        pose, steps = ahead.q, steps + list(ahead.steps)
    assert len(steps) == runs.runs
    assert all(s.seconds >= timing.min_move_s for s in steps)  # each one run, none two legs
    turned = sum(abs(s.target - q) for s, q in zip(steps, _before(path.q[0], steps), strict=True))
    assert turned < 1.2 * float(np.abs(path.q[-1] - path.q[0]).sum()) + math.radians(12)


def _before(q0: np.ndarray, steps: list) -> list[float]:  # type: ignore[type-arg]
    pose, out = np.array(q0), []
    for s in steps:
        out.append(float(pose[s.joint]))
        pose[s.joint] = s.target
    return out


def test_the_waypoints_end_on_the_path_s_end(owi: ArmModel) -> None:
    path = _line_path(owi, *LINES_MM[2])
    w = path_waypoints(default_timing(owi), path.q)
    assert w[-1] == pytest.approx(path.q[-1], abs=1e-12)
    assert 5 <= len(w) <= 30  # a 100 mm line: tens of waypoints, not 51 streamed points


def test_a_path_straying_past_the_tolerance_is_refused(owi: ArmModel) -> None:
    path = _line_path(owi, *LINES_MM[0])
    with pytest.raises(UnreachableError, match=r"stray \d+ mm .*use joint moves \(move\)"):
        plan_path_runs(default_timing(owi), owi, path.q[0], 0.0, path.q, path.points, 0.005)


def test_the_driver_follows_a_line_as_planned(owi: ArmModel, driver: TimedDriver) -> None:
    path = _line_path(owi, *LINES_MM[2])
    ahead = plan_path_runs(driver.timing, owi, driver.read(), 0.0, path.q, path.points)
    t0 = driver.clock.now()
    done = driver.follow_path(owi, path.q, path.points)
    assert driver.clock.now() - t0 == pytest.approx(ahead.seconds, rel=0.01)  # virtual time
    assert driver.read() == pytest.approx(ahead.q, abs=1e-9)
    assert driver.state.motor_s == pytest.approx(ahead.motor_s)
    assert done.runs == ahead.runs


@pytest.mark.parametrize(("a", "b"), LINES_MM)
def test_check_times_an_owi_line_as_it_runs(a: tuple[float, ...], b: tuple[float, ...]) -> None:
    arm = Arm("owi535", "sim", world=World())
    try:
        xyz = " ".join(f"{v:g}" for v in a)
        to = " ".join(f"{v:g}" for v in b)
        t0 = arm.clock.now()
        result = run_source(arm, Source("l.arm", f"move xyz {xyz}\nline xyz {to}\n"))
        took = arm.clock.now() - t0  # simulated seconds
        assert result.timetable.unknown == 0
        assert result.timetable.total == pytest.approx(took, rel=0.02)
        line_step = result.timetable.rows[-1]
        assert "mm off the path" in line_step.note
        assert line_step.duration < 8.0  # was 29.8 s for the 20 mm line, 183 s for 100 mm
    finally:
        arm.close()
