"""Joint profiles: every limit respected, every joint arriving together, shortest time."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from armkit.model import ArmModel, load_model
from armkit.motion import quintic, trapezoid, trapezoid_in_line

SERVO_ARMS = ("openmanipulator_x", "lynx6", "planar2")

MODELS = {name: load_model(name) for name in (*SERVO_ARMS, "owi535")}
SETTINGS = settings(max_examples=60, derandomize=True, deadline=None)


def _limits(model: ArmModel) -> tuple[np.ndarray, np.ndarray]:
    vmax = np.array([j.max_velocity for j in model.joints])
    amax = np.array([j.max_acceleration for j in model.joints])
    return vmax, amax


@st.composite
def moves(draw: st.DrawFn) -> tuple[ArmModel, np.ndarray, np.ndarray, float]:
    model = MODELS[draw(st.sampled_from(sorted(MODELS)))]
    unit = st.floats(0.0, 1.0)
    u0 = np.array([draw(unit) for _ in range(model.dof)])
    u1 = np.array([draw(unit) for _ in range(model.dof)])
    span = model.upper - model.lower
    speed = draw(st.floats(0.05, 1.0))
    return model, model.lower + u0 * span, model.lower + u1 * span, speed


def _single_joint_time(dist: float, v: float, a: float) -> float:
    return 2 * np.sqrt(dist / a) if dist < v * v / a else dist / v + v / a


@SETTINGS
@given(moves())
def test_trapezoid_respects_limits_and_arrives_together(move) -> None:
    model, q0, q1, speed = move
    prof = trapezoid(model, q0, q1, speed)
    vmax, amax = _limits(model)
    t = np.linspace(0.0, prof.duration, 2001)
    pos, vel, acc = prof.sample(t)
    assert np.all(np.abs(vel) <= speed * vmax * (1 + 1e-9) + 1e-12)
    assert np.all(np.abs(acc) <= amax * (1 + 1e-9))
    np.testing.assert_allclose(pos[0], q0, atol=1e-12)
    np.testing.assert_allclose(pos[-1], q1, atol=1e-9)
    # velocity is the derivative of position (catches an inconsistent profile)
    if prof.duration > 0:
        dt = t[1] - t[0]
        np.testing.assert_allclose(
            np.gradient(pos, dt, axis=0)[1:-1], vel[1:-1], atol=amax.max() * dt * 2
        )


@SETTINGS
@given(moves())
def test_trapezoid_is_as_fast_as_the_slowest_joint_allows(move) -> None:
    model, q0, q1, speed = move
    vmax, amax = _limits(model)
    times = [
        _single_joint_time(abs(b - a), speed * v, ac)
        for a, b, v, ac in zip(q0, q1, vmax, amax, strict=True)
    ]
    assert trapezoid(model, q0, q1, speed).duration == pytest.approx(
        max(times), rel=1e-9, abs=1e-12
    )


@SETTINGS
@given(moves(), st.floats(1.0, 3.0))
def test_longer_duration_keeps_limits_and_ends(move, stretch: float) -> None:
    model, q0, q1, speed = move
    fastest = trapezoid(model, q0, q1, speed).duration
    prof = trapezoid(model, q0, q1, speed, duration=fastest * stretch + 0.01)
    vmax, amax = _limits(model)
    pos, vel, acc = prof.sample(np.linspace(0.0, prof.duration, 1001))
    assert np.all(np.abs(vel) <= speed * vmax * (1 + 1e-9) + 1e-12)
    assert np.all(np.abs(acc) <= amax * (1 + 1e-9))
    np.testing.assert_allclose(pos[-1], q1, atol=1e-9)


@SETTINGS
@given(moves())
def test_quintic_respects_limits_and_arrives_together(move) -> None:
    model, q0, q1, speed = move
    prof = quintic(model, q0, q1, speed)
    vmax, amax = _limits(model)
    pos, vel, acc = prof.sample(np.linspace(0.0, prof.duration, 2001))
    assert np.all(np.abs(vel) <= speed * vmax * (1 + 1e-6) + 1e-12)
    assert np.all(np.abs(acc) <= amax * (1 + 1e-6) + 1e-12)
    np.testing.assert_allclose(pos[-1], q1, atol=1e-9)
    np.testing.assert_allclose(vel[[0, -1]], 0.0, atol=1e-12)
    # shortest: some joint touches its velocity or acceleration limit
    touch = np.max(np.maximum(np.abs(vel) / (speed * vmax), np.abs(acc) / amax))
    assert touch == pytest.approx(1.0, abs=1e-3) or np.allclose(q0, q1)


def test_too_short_duration_and_bad_speed_are_refused(omx: ArmModel) -> None:
    q1 = omx.home + 0.5
    fastest = trapezoid(omx, omx.home, q1).duration
    with pytest.raises(ValueError, match="too short"):
        trapezoid(omx, omx.home, q1, duration=fastest / 2)
    with pytest.raises(ValueError, match="speed"):
        quintic(omx, omx.home, q1, speed=1.5)


@SETTINGS
@given(moves())
def test_trapezoid_in_line_stays_on_the_joint_line_within_limits(move) -> None:
    model, q0, q1, speed = move
    prof = trapezoid_in_line(model, q0, q1, speed)
    vmax, amax = _limits(model)
    pos, vel, acc = prof.sample(np.linspace(0.0, prof.duration, 2001))
    assert np.all(np.abs(vel) <= speed * vmax * (1 + 1e-9) + 1e-12)
    assert np.all(np.abs(acc) <= amax * (1 + 1e-9))
    np.testing.assert_allclose(pos[-1], q1, atol=1e-9)
    delta = q1 - q0
    share = (pos - q0) @ delta / max(float(delta @ delta), 1e-300)
    np.testing.assert_allclose(pos, q0 + share[:, None] * delta, atol=1e-9)
    # shortest on the line: some joint reaches its velocity or acceleration limit
    touch = np.max(np.maximum(np.abs(vel) / (speed * vmax), np.abs(acc) / amax))
    assert touch == pytest.approx(1.0, abs=1e-9) or np.allclose(q0, q1)
    assert prof.duration >= trapezoid(model, q0, q1, speed).duration - 1e-9
