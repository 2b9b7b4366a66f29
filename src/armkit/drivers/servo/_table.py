"""A hobby servo's calibration table: points (angle or width, pulse), interpolated both ways.

Seed 002 calibrates each Lynx6 servo at the ends of its range and every 30°
between, and finds a pulse by interpolating between those points. The same
table read backwards turns a pulse into an angle. A value outside the table's
range is refused, never clipped.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Literal

import numpy as np

from ..._errors import InputError, JointLimitError

PULSE_MIN_US = 500.0
PULSE_MAX_US = 2500.0
IDEAL_US_PER_DEG = 2000.0 / 180.0  # 500..2500 µs ≈ 0..180° (002)
STEP_DEG = 30.0
_SLACK = 1e-9
Unit = Literal["deg", "mm"]
_SCALE = {"deg": math.degrees(1.0), "mm": 1000.0}  # SI value -> shown value


@dataclass(frozen=True)
class ServoCalibration:
    """One servo's table.

    Attributes:
        name: the servo (a joint name, or ``"grip"``).
        channel: its channel on the controller.
        values: table points, strictly increasing: joint angle [rad] or grip width [m],
            shape (n,), n >= 2.
        pulses_us: pulse at each point [µs], strictly increasing or decreasing, within 500..2500.
        unit: how people read the values: ``"deg"`` (joints) or ``"mm"`` (the gripper).
    """

    name: str
    channel: int
    values: tuple[float, ...]
    pulses_us: tuple[float, ...]
    unit: Unit = "deg"

    def __post_init__(self) -> None:
        _check_table(self.name, self.values, self.pulses_us)

    @property
    def lower(self) -> float:
        """The smallest value the table covers [rad or m]."""
        return self.values[0]

    @property
    def upper(self) -> float:
        """The largest value the table covers [rad or m]."""
        return self.values[-1]

    def shown(self, value: float) -> float:
        """``value`` [rad or m] in the unit people read (degrees or millimetres)."""
        return value * _SCALE[self.unit]

    def range_text(self) -> str:
        """The range for messages, e.g. ``"15.0..165.0°"``."""
        suffix = "°" if self.unit == "deg" else " mm"
        return f"{self.shown(self.lower):.1f}..{self.shown(self.upper):.1f}{suffix}"

    def check(self, value: float) -> None:
        """Raise JointLimitError naming the servo and its range if ``value`` is outside it."""
        if not math.isfinite(value) or not self.lower - _SLACK <= value <= self.upper + _SLACK:
            suffix = "°" if self.unit == "deg" else " mm"
            raise JointLimitError(
                f"{self.name} {self.shown(value):.1f}{suffix} is outside its range "
                f"{self.range_text()}; give a value inside it (nothing was sent)"
            )

    def to_pulse(self, value: float) -> float:
        """Pulse [µs] for ``value`` [rad or m], interpolated; JointLimitError outside the range."""
        self.check(value)
        return float(np.interp(value, self.values, self.pulses_us))

    def to_value(self, pulse_us: float) -> float:
        """Value [rad or m] for ``pulse_us`` [µs], interpolated backwards (clamped to the table)."""
        pulses, values = np.asarray(self.pulses_us), np.asarray(self.values)
        if pulses[0] > pulses[-1]:
            pulses, values = pulses[::-1], values[::-1]
        return float(np.interp(pulse_us, pulses, values))

    def max_rate(self, pulse_a: float, pulse_b: float) -> float:
        """The steepest |d value / d pulse| [rad/µs or m/µs] of the table between two pulses:
        a move whose pulse changes at r µs/s turns the servo at most r times this."""
        low, high = sorted((pulse_a, pulse_b))
        segments = sorted(
            (*sorted(self.pulses_us[i : i + 2]), self.values[i + 1] - self.values[i])
            for i in range(len(self.values) - 1)
        )
        rates = []
        for i, (p0, p1, dv) in enumerate(segments):
            reach0 = -math.inf if i == 0 else p0  # the end segments extend beyond the table
            reach1 = math.inf if i == len(segments) - 1 else p1
            if reach1 >= low and reach0 <= high:
                rates.append(dv / (p1 - p0))
        return max(rates, default=0.0)


def _check_table(name: str, values: Sequence[float], pulses: Sequence[float]) -> None:
    if len(values) < 2 or len(values) != len(pulses):
        raise InputError(
            f"{name}: a table needs at least 2 points and one pulse per point "
            f"(got {len(values)} points, {len(pulses)} pulses)"
        )
    if not all(math.isfinite(v) for v in [*values, *pulses]):
        raise InputError(f"{name}: table entries must be finite numbers")
    if any(b <= a for a, b in itertools.pairwise(values)):
        raise InputError(f"{name}: table points must increase strictly")
    steps = [b - a for a, b in itertools.pairwise(pulses)]
    if not (all(s > 0 for s in steps) or all(s < 0 for s in steps)):
        raise InputError(f"{name}: pulses must all increase or all decrease along the table")
    if not all(PULSE_MIN_US <= p <= PULSE_MAX_US for p in pulses):
        raise InputError(f"{name}: pulses must lie in {PULSE_MIN_US:.0f}..{PULSE_MAX_US:.0f} µs")


def table_angles_deg(lower_deg: float, upper_deg: float, center_deg: float) -> list[float]:
    """Table points [deg]: the range ends and every 30° of servo angle between
    (servo angle 90° = the joint angle ``center_deg``)."""
    offset = center_deg - 90.0
    k = math.floor((lower_deg - offset) / STEP_DEG) + 1
    inner = []
    while (angle := offset + k * STEP_DEG) < upper_deg - 1e-9:
        inner.append(angle)
        k += 1
    return [lower_deg, *[a for a in inner if a > lower_deg + 1e-9], upper_deg]


def ideal_joint(
    name: str,
    channel: int,
    lower: float,
    upper: float,
    center_deg: float = 90.0,
    direction: int = 1,
) -> ServoCalibration:
    """The ideal table of 002 (1500 µs at ``center_deg``, 2000 µs per 180°, turning
    with ``direction`` = +1 or -1) over the joint range ``lower..upper`` [rad]."""
    angles = table_angles_deg(math.degrees(lower), math.degrees(upper), center_deg)
    pulses = [1500.0 + direction * (a - center_deg) * IDEAL_US_PER_DEG for a in angles]
    return ServoCalibration(name, channel, tuple(math.radians(a) for a in angles), tuple(pulses))


def ideal_grip(
    channel: int, width_min: float, width_max: float, pulses_us: Sequence[float], points: int = 5
) -> ServoCalibration:
    """A straight-line gripper table: ``pulses_us`` = (closed, open) [µs] over the
    width range [m], sampled at ``points`` evenly spaced widths."""
    widths = np.linspace(width_min, width_max, points)
    pulses = np.linspace(pulses_us[0], pulses_us[1], points)
    return ServoCalibration(
        "grip", channel, tuple(map(float, widths)), tuple(map(float, pulses)), "mm"
    )
