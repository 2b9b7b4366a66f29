"""What a hobby-servo driver's move and grip will take, worked out without a port: the
group move's time by the shared rule (``move_time``, constant speed: the servos
ramp), rounded up to the controller's milliseconds and lengthened where a servo's
table is steeper than its joint's speed allows, in pieces of at most one command,
each followed by the servos' settle time (they report nothing)."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import ClassVar

import numpy as np
from numpy.typing import NDArray

from ..._errors import InputError
from ...model import ArmModel, check_grip, check_joints, check_speed, move_time
from .._driver import Forecast, pieces
from ._bus import MaestroBus, SSC32Bus
from ._config import load_setup
from ._table import ServoCalibration

JAWS_SPEED = 0.05  # a hobby servo gripper's jaws [m/s]: the arm waits for them to get there

F64 = NDArray[np.float64]


def group_ms(
    model: ArmModel,
    joints: tuple[ServoCalibration, ...],
    pulses: dict[int, float],
    starts: dict[int, float],
    timing: tuple[float, float, bool, float],
    bus: str,
) -> int:
    """Group time [ms] of a move from ``starts`` to ``pulses`` [µs] by channel, given
    ``timing`` = (the shared rule's seconds, the start's uncertainty [µs], whether the
    time was asked for exactly, the speed fraction): rounded up, longer only where a
    servo's table is steeper than its joint's speed allows (InputError when exact: then
    up to the servo's own speed, ``peak_velocity``)."""
    seconds, pad, exact, speed = timing
    needed = 0.0
    for table, joint in zip(joints, model.joints, strict=True):
        start, target = starts.get(table.channel), pulses.get(table.channel)
        if start is not None and target is not None:
            travel = abs(target - start) + (0.0 if exact else pad)  # µs of pulse
            rate = table.max_rate(start, target)
            vmax = joint.peak_velocity if exact else joint.max_velocity
            needed = max(needed, travel * rate / (vmax * speed))
    if exact and needed > seconds + 1e-3:
        raise InputError(
            f"duration {seconds:.3f} s is too short for the servo tables: this move "
            f"needs {needed:.3f} s on the {bus}"
        )
    return math.ceil(max(seconds, needed) * 1000.0 - 1e-9)


@dataclass(frozen=True)
class ServoForecaster:
    """A servo arm's ``Forecaster`` (``armkit.drivers.Forecaster``): its tables, the
    controller's longest command [s] and name, and the servos' settle time [s]."""

    model: ArmModel
    joints: tuple[ServoCalibration, ...]
    moves: ClassVar[str] = "hobby"
    longest: float
    bus: str
    settle_s: float

    def forecast(
        self,
        q0: F64,
        q1: F64,
        *,
        duration: float | None = None,
        speed: float | None = None,
        motor_s: float = 0.0,
    ) -> Forecast:
        """A waiting ``move(q1)`` from ``q0`` [rad]: each piece's group time, then the settle."""
        goal = check_joints(self.model, q1)
        frac = check_speed(speed)
        start = np.asarray(q0, dtype=np.float64)
        seconds = move_time(self.model, start, goal, speed=frac, duration=duration, ramps=False)
        took, origin = 0.0, self._pulses(start)
        for target, piece_s in pieces(start, goal, seconds, self.longest):
            pulses = self._pulses(target)
            timing = (piece_s, 0.0, duration is not None, frac)
            took += group_ms(self.model, self.joints, pulses, origin, timing, self.bus) / 1000.0
            took += self.settle_s
            origin = pulses
        return Forecast(took, goal.copy(), motor_s)

    def forecast_grip(self, before: float | None, width: float) -> float:
        """The gripper jumps (one pulse, no time): the settle time [s]."""
        check_grip(self.model, width)
        return self.settle_s

    def _pulses(self, q: F64) -> dict[int, float]:
        return {t.channel: t.to_pulse(float(a)) for t, a in zip(self.joints, q, strict=True)}


def servo_forecaster(model: ArmModel, kind: str) -> ServoForecaster:
    """The forecasts of ``model``'s servos on an ``"ssc32"`` or a ``"maestro"``, from the
    model's section and the unit's tables (``load_setup``), with no port."""
    setup = load_setup(model, kind)
    bus = SSC32Bus if kind == "ssc32" else MaestroBus
    return ServoForecaster(model, setup.joints, bus.max_time_ms / 1000.0, kind, setup.settle_s)
