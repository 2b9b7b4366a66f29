"""Pulse tables: 002's ideal table, interpolation both ways, refusal outside the range."""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from armkit._errors import JointLimitError
from armkit.drivers.servo import ServoCalibration
from armkit.drivers.servo._table import ideal_grip, ideal_joint, table_angles_deg

SETTINGS = settings(derandomize=True, max_examples=200, deadline=None)


@st.composite
def tables(draw: st.DrawFn) -> ServoCalibration:
    """Random valid tables: 2..8 points, pulses increasing or decreasing in 500..2500."""
    n = draw(st.integers(2, 8))
    values = sorted(draw(st.lists(st.integers(-180, 180), min_size=n, max_size=n, unique=True)))
    pulses = sorted(draw(st.lists(st.integers(500, 2500), min_size=n, max_size=n, unique=True)))
    if draw(st.booleans()):
        pulses.reverse()
    return ServoCalibration(
        "wrist", 3, tuple(math.radians(v) for v in values), tuple(float(p) for p in pulses)
    )


def test_002s_ideal_table_has_the_ends_and_every_30_degrees() -> None:
    assert table_angles_deg(15, 165, 90) == [15, 30, 60, 90, 120, 150, 165]
    assert table_angles_deg(0, 160, 90) == [0, 30, 60, 90, 120, 150, 160]
    assert table_angles_deg(-90, 90, 0) == [-90, -60, -30, 0, 30, 60, 90]


def test_ideal_table_is_500_to_2500_over_0_to_180_degrees() -> None:
    cal = ideal_joint("wrist", 3, 0.0, math.pi)
    assert cal.to_pulse(0.0) == pytest.approx(500.0)
    assert cal.to_pulse(math.pi / 2) == pytest.approx(1500.0)
    assert cal.to_pulse(math.pi) == pytest.approx(2500.0)
    reversed_cal = ideal_joint("wrist", 3, 0.0, math.pi, direction=-1)
    assert reversed_cal.to_pulse(0.0) == pytest.approx(2500.0)


def test_between_points_the_pulse_is_interpolated() -> None:
    cal = ServoCalibration("elbow", 2, (0.0, 1.0, 2.0), (600.0, 1600.0, 2000.0))
    assert cal.to_pulse(0.5) == pytest.approx(1100.0)
    assert cal.to_pulse(1.5) == pytest.approx(1800.0)
    assert cal.to_value(1800.0) == pytest.approx(1.5)


def test_outside_the_range_is_refused_naming_servo_and_range() -> None:
    cal = ideal_joint("base", 0, math.radians(15), math.radians(165))
    with pytest.raises(JointLimitError, match=r"base 10\.0° is outside its range 15\.0\.\.165\.0°"):
        cal.to_pulse(math.radians(10))
    with pytest.raises(JointLimitError):
        cal.to_pulse(math.nan)


def test_grip_width_is_refused_in_millimetres() -> None:
    grip = ideal_grip(5, 0.0, 0.0508, (500.0, 2500.0))
    assert grip.to_pulse(0.0254) == pytest.approx(1500.0)
    with pytest.raises(
        JointLimitError, match=r"grip 60\.0 mm is outside its range 0\.0\.\.50\.8 mm"
    ):
        grip.to_pulse(0.060)


@pytest.mark.parametrize(
    ("values", "pulses", "words"),
    [
        ((0.0,), (1500.0,), "at least 2 points"),
        ((0.0, 0.0), (1000.0, 2000.0), "increase strictly"),
        ((0.0, 1.0, 2.0), (1000.0, 2000.0, 1500.0), "all increase or all decrease"),
        ((0.0, 1.0), (400.0, 2000.0), "500..2500"),
        ((0.0, math.inf), (1000.0, 2000.0), "finite"),
    ],
)
def test_broken_tables_are_refused(
    values: tuple[float, ...], pulses: tuple[float, ...], words: str
) -> None:
    with pytest.raises(ValueError, match=words):
        ServoCalibration("hand", 4, values, pulses)


@SETTINGS
@given(tables(), st.floats(0.0, 1.0))
def test_angle_to_pulse_to_angle_round_trips(cal: ServoCalibration, t: float) -> None:
    value = cal.lower + t * (cal.upper - cal.lower)
    assert cal.to_value(cal.to_pulse(value)) == pytest.approx(value, abs=1e-9)


@SETTINGS
@given(tables(), st.floats(0.0, 1.0))
def test_pulse_to_angle_to_pulse_round_trips(cal: ServoCalibration, t: float) -> None:
    low, high = sorted((cal.pulses_us[0], cal.pulses_us[-1]))
    pulse = low + t * (high - low)
    value = min(max(cal.to_value(pulse), cal.lower), cal.upper)
    assert cal.to_pulse(value) == pytest.approx(pulse, abs=1e-6)


@SETTINGS
@given(tables(), st.floats(0.0, 1.0), st.floats(0.0, 1.0))
def test_max_rate_bounds_every_step_between_two_pulses(
    cal: ServoCalibration, a: float, b: float
) -> None:
    low, high = sorted((cal.pulses_us[0], cal.pulses_us[-1]))
    pa, pb = low + a * (high - low), low + b * (high - low)
    rate = cal.max_rate(pa, pb)
    for k in range(11):
        p0 = pa + (pb - pa) * k / 11
        p1 = pa + (pb - pa) * (k + 1) / 11
        assert abs(cal.to_value(p1) - cal.to_value(p0)) <= rate * abs(p1 - p0) + 1e-12
