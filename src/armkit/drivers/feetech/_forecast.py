"""What a Feetech arm's move and grip will take, worked out without a bus.

A move is one goal per servo (``Goal Position`` with its own ``Goal Velocity`` and
``Acceleration``, the STS3215's position profile): every joint gets the shared timing
rule's total time and ramp (``move_time``, ``ramp_time``), so its speed is its
distance over (total - ramp) and its acceleration that speed over the ramp, rounded
up to the servo's units (1 step/s, 100 step/s^2; at most 254 units); the move then
takes its slowest servo's trapezoid, and the poll that sees every servo stopped."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import ClassVar

import numpy as np
from numpy.typing import NDArray

from ...devices import sts3215 as sts
from ...model import (
    ArmModel,
    FeetechSection,
    check_grip,
    check_joints,
    check_speed,
    limits,
    move_time,
    ramp_time,
)
from .._driver import Forecast

F64 = NDArray[np.float64]
I64 = NDArray[np.int64]
POLL_S = 0.005  # between reads of Moving while waiting [s]
ARRIVAL_S = 0.010 + POLL_S / 5  # the servo's loop catching up, then one more poll [s]
MAX_ACCEL_UNITS = 254


@dataclass(frozen=True)
class Goals:
    """One move as the servos are told it: goal steps, Goal Velocity [step/s] and
    Acceleration [100 step/s^2] per joint, and how long it takes [s]."""

    ticks: I64
    speeds: tuple[int, ...]
    accels: tuple[int, ...]
    seconds: float


def trapezoid_s(distance: float, speed: float, accel: float) -> float:
    """How long a trapezoid of ``distance`` [step] at ``speed`` [step/s] and ``accel``
    [step/s^2] (inf: no ramp) takes [s]."""
    d = abs(distance)
    if d == 0.0:
        return 0.0
    if math.isinf(accel):
        return d / speed
    if d < speed * speed / accel:
        return 2.0 * math.sqrt(d / accel)
    return d / speed + speed / accel


@dataclass(frozen=True)
class FeetechForecaster:
    """A Feetech arm's ``Forecaster`` from its model and ``[drivers.feetech]``."""

    model: ArmModel
    config: FeetechSection
    moves: ClassVar[str] = "smart"

    def ticks(self, q: F64) -> I64:
        """Joint angles [rad], shape (dof,) -> goal steps, clipped to 0..4095."""
        per_rad = self.config.ticks_per_turn / (2.0 * math.pi)
        sign = np.asarray(self.config.direction, dtype=np.float64)
        steps = np.rint(np.asarray(self.config.centers) + sign * np.asarray(q) * per_rad)
        return np.clip(steps, 0, sts.STEPS_PER_TURN - 1).astype(np.int64)

    def angles(self, ticks: I64) -> F64:
        """Steps, shape (dof,) -> joint angles [rad]."""
        per_rad = self.config.ticks_per_turn / (2.0 * math.pi)
        sign = np.asarray(self.config.direction, dtype=np.float64)
        centers = np.asarray(self.config.centers, dtype=np.float64)
        return (np.asarray(ticks, dtype=np.float64) - centers) * sign / per_rad

    def goals(self, start: F64, goal: F64, seconds: float, peak: bool) -> Goals:
        """The servos' goals for a move from ``start`` to ``goal`` [rad] in ``seconds``."""
        ticks = self.ticks(goal)
        distance = np.abs(ticks - self.ticks(start)).astype(np.float64)
        _, amax = limits(self.model, peak=peak)
        ramp = ramp_time(seconds, self.angles(ticks) - start, amax)
        cruise = max(seconds - ramp, 1e-3)
        speeds, accels, took = [], [], 0.0
        for d in distance.tolist():
            speed = min(sts.MAX_SPEED_STEPS, max(1, math.ceil(d / cruise - 1e-9)))
            accel = 0 if ramp <= 0 else min(MAX_ACCEL_UNITS, max(1, math.ceil(speed / ramp / 100)))
            speeds.append(speed)
            accels.append(accel)
            took = max(took, trapezoid_s(d, speed, accel * 100 or math.inf))
        return Goals(ticks, tuple(speeds), tuple(accels), took)

    def plan(
        self, q0: F64, q1: F64, duration: float | None, speed: float | None
    ) -> tuple[F64, Goals]:
        """(the goal checked [rad], the servos' goals) of ``move(q1)`` from ``q0``."""
        goal = check_joints(self.model, q1)
        frac = check_speed(speed)
        start = np.asarray(q0, dtype=np.float64)
        end = self.angles(self.ticks(goal))
        seconds = move_time(self.model, start, goal, speed=frac, duration=duration)
        if duration is None:
            seconds = move_time(self.model, start, end, speed=frac)
        return goal, self.goals(start, goal, seconds, peak=duration is not None)

    def forecast(
        self,
        q0: F64,
        q1: F64,
        *,
        duration: float | None = None,
        speed: float | None = None,
        motor_s: float = 0.0,
    ) -> Forecast:
        """A waiting ``move(q1)`` from ``q0`` [rad]: its slowest servo, then the arrival."""
        _, goals = self.plan(q0, q1, duration, speed)
        return Forecast(goals.seconds + ARRIVAL_S, self.angles(goals.ticks), motor_s)

    def grip_tick(self, width: float) -> int:
        """The gripper's goal step for an opening ``width`` [m] (ValueError outside the
        model's range)."""
        check_grip(self.model, width)
        return round(self._jaw_step(width))

    def _jaw_step(self, width: float) -> float:
        """The gripper's step for an opening ``width`` [m] (the chord law), unrounded."""
        per_rad = self.config.ticks_per_turn / (2.0 * math.pi)
        angle = self.config.jaw_angle(width)
        return self.config.gripper_zero_tick + self.config.gripper_direction * angle * per_rad

    def forecast_grip(self, before: float | None, width: float) -> float:
        """The gripper servo's travel from ``before`` [m] (None: fully open) to ``width``
        at its full speed (``grip`` writes only the goal: Goal Velocity 0 and Acceleration
        0 are the servo's fastest), then the poll that sees it stopped [s]."""
        goal = self.grip_tick(width)
        start = self.model.gripper.width_max if before is None else before
        steps = abs(goal - round(self._jaw_step(start)))
        return steps / sts.MAX_SPEED_STEPS + POLL_S
