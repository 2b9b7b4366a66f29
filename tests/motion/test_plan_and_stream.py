"""Planning (one branch, whole path checked first) and the three ways to stream."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from armkit.connect import open_driver
from armkit.kinematics import fk, pitch_of
from armkit.model import ArmModel, load_model
from armkit.motion import (
    EarlyStreaming,
    NaiveStepping,
    PathError,
    Streamer,
    TimedStreaming,
    circle,
    distance_to_polyline,
    line,
    plan_path,
    rectangle,
    time_path,
)

DOWN = -math.pi / 2


@settings(max_examples=25, derandomize=True, deadline=None)
@given(st.floats(0.14, 0.2), st.floats(-0.05, 0.05), st.floats(0.03, 0.08), st.floats(0.005, 0.03))
def test_planned_circle_is_on_the_path_and_within_limits(x, y, z, r) -> None:
    omx = load_model("openmanipulator_x")
    pts = circle([x, y, z], r, 0.002)
    path = plan_path(omx, pts, DOWN, omx.home)
    T = fk(omx, path.q)
    np.testing.assert_allclose(T[:, :3, 3], pts, atol=1e-6)
    assert np.all(omx.within_limits(path.q))
    # between samples (joint-space interpolation) the tool stays near the circle
    fine = np.linspace(0, 1, 5)[1:-1, None, None]
    between = (path.q[:-1][None] * (1 - fine) + path.q[1:][None] * fine).reshape(-1, omx.dof)
    assert np.max(distance_to_polyline(fk(omx, between)[:, :3, 3], pts)) < 0.2e-3


def test_branch_of_the_start_is_kept() -> None:
    planar = load_model("planar2")
    pts = line([0.5, 0.0, 0.5], [0.7, 0.0, 0.2], 0.005)
    for elbow_sign in (1.0, -1.0):
        seed = np.array([0.0, elbow_sign * 1.5])
        path = plan_path(planar, pts, None, seed)
        assert np.all(np.sign(path.q[:, 1]) == elbow_sign)
        np.testing.assert_allclose(fk(planar, path.q)[:, :3, 3], pts, atol=1e-9)


def test_unreachable_point_is_named(omx: ArmModel) -> None:
    pts = line([0.15, 0.0, 0.05], [0.45, 0.0, 0.05], 0.002)
    with pytest.raises(PathError) as info:
        plan_path(omx, pts, DOWN, omx.home)
    i = info.value.index
    assert 0 < i < len(pts)
    assert f"point {i} of {len(pts)}" in str(info.value)
    assert info.value.reason == "too_far"
    plan_path(omx, pts[:i], DOWN, omx.home)  # everything before it is fine


def test_coarse_spacing_that_leaves_the_path_is_refused(omx: ArmModel) -> None:
    pts = np.array([[0.12, -0.1, 0.05], [0.12, 0.1, 0.05]])
    with pytest.raises(PathError, match="leave the path") as info:
        plan_path(omx, pts, DOWN, omx.home)
    assert info.value.index == 0 and info.value.reason == "discontinuous"


def test_a_path_that_flips_at_chosen_pitches_is_planned_at_one_pitch() -> None:
    """Without a pitch the solver picks one per point; where the Lynx6 would flip on
    this circle (the wrist turning 103 deg), the path is planned at one pitch."""
    lynx6 = load_model("lynx6")
    pts = circle([0.15, 0.0, 0.02], 0.02, 0.002)
    path = plan_path(lynx6, pts, None, lynx6.home)
    pitches = pitch_of(fk(lynx6, path.q))
    assert np.ptp(pitches) < 1e-6
    assert np.allclose(fk(lynx6, path.q)[:, :3, 3], pts, atol=1e-9)


def test_a_flip_at_chosen_pitches_names_the_joint_and_the_pitches(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    import armkit.motion._plan as plan

    monkeypatch.setattr(plan, "PITCHES_TRIED", 0)  # no whole-path pitch: the flip is refused
    lynx6 = load_model("lynx6")
    pts = circle([0.15, 0.0, 0.02], 0.02, 0.002)
    with pytest.raises(PathError, match=r"the wrist turns [\d.]+ deg: .* at the pitches it chose"):
        plan_path(lynx6, pts, None, lynx6.home)


def test_timed_path_keeps_joint_limits_and_stops_at_corners(omx: ArmModel) -> None:
    pts = rectangle([0.17, 0.0, 0.05], 0.08, 0.08, 0.002)
    timed = time_path(omx, plan_path(omx, pts, DOWN, omx.home), speed=0.5, accel=5.0)
    vel = np.diff(timed.q, axis=0) / np.diff(timed.t)[:, None]
    vmax = np.array([j.max_velocity for j in omx.joints])
    assert np.all(np.abs(vel) <= vmax * (1 + 1e-9))
    assert np.all(np.diff(timed.t) > 0)


STREAMERS: dict[str, tuple[Streamer, float]] = {
    "naive": (NaiveStepping(), 0.3e-3),
    "early": (EarlyStreaming(fraction=0.5), 0.3e-3),
    "timed": (TimedStreaming(rate=100.0, speed=0.06), 0.3e-3),
}
# An SSC-32 reports the pulses it sends, not where its servos are: early streaming on it
# follows the pulses at full speed while the servos lag them by their time constant
# (25 ms), so the true path is off by that lag (about 1 mm at these speeds). Devices
# that report their servos' positions (the XM430s) keep 0.3 mm in every mode.
NO_FEEDBACK_EARLY = 1.5e-3


@pytest.mark.parametrize("mode", sorted(STREAMERS))
@pytest.mark.parametrize("arm_name", ["openmanipulator_x", "lynx6"])
def test_streamed_drawing_stays_near_the_path(mode: str, arm_name: str) -> None:
    model = load_model(arm_name)
    streamer, tolerance = STREAMERS[mode]
    if arm_name == "lynx6" and mode == "early":
        tolerance = NO_FEEDBACK_EARLY
    pitch = DOWN if arm_name == "openmanipulator_x" else -math.pi / 3
    pts = circle([0.17, 0.0, 0.04], 0.02, 0.002)
    arm = open_driver(model, "sim")  # the arm's own driver on its simulated device
    world = arm.clock.world  # type: ignore[attr-defined]
    path = plan_path(model, pts, pitch, arm.read())
    arm.move(path.q[0])
    t0 = world.now()
    streamer.run(arm, model, path, world.clock)
    true = fk(model, world.recording().between(t0, world.now()).q)[:, :3, 3]
    assert np.max(distance_to_polyline(true, pts)) < tolerance
    np.testing.assert_allclose(true[-1], pts[-1], atol=0.5e-3)  # servos settle to 0.05 deg
    assert world.now() - t0 > 0.5  # it really took (simulated) time to draw 126 mm
    arm.close()


def test_a_stream_at_the_joints_speed_limit_is_not_refused_mid_path(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """Where a joint's limit binds, the timed path is slowed to 90 % of it: a 100 Hz
    segment sent a bus exchange late still fits its period. At the full limit the
    OpenManipulator-X's driver refused this circle mid-path (10.25 ms needed for 10)."""
    import armkit.motion._plan as plan

    monkeypatch.setattr(plan, "PITCHES_TRIED", 0)  # the pitch point by point: the wrist races
    model = load_model("openmanipulator_x")
    arm = open_driver(model, "sim")
    path = plan_path(model, circle([0.17, 0.0, 0.05], 0.04, 0.002), None, arm.read())
    timed = time_path(model, path, speed=0.05, accel=0.5)
    vel = np.diff(timed.q, axis=0) / np.diff(timed.t)[:, None]
    vmax = np.array([j.max_velocity for j in model.joints])
    assert np.max(np.abs(vel) / vmax) == pytest.approx(0.9)  # the limit binds, at 90 %
    arm.move(path.q[0])
    TimedStreaming(rate=100.0, speed=0.05, accel=0.5).run(arm, model, path, arm.clock)
    np.testing.assert_allclose(arm.read(), path.q[-1], atol=np.radians(0.1))
    arm.close()
