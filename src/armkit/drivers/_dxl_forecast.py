"""What a Dynamixel arm's move and grip will take, worked out without a bus: a move is
one time-based profile of the shared rule's time (``move_time``, ramps included) to
the goal's tick, rounded up to the millisecond, in pieces of at most one profile,
each followed by the wait for the servos to report their arrival; the gripper runs
at its own speed until it reaches its opening (or stalls on what it holds)."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import ClassVar

import numpy as np
from numpy.typing import NDArray

from ..model import ArmModel, DynamixelSection, check_grip, check_joints, check_speed, move_time
from ._driver import Forecast, pieces
from ._dxl_wait import POLL_S

F64 = NDArray[np.float64]
MAX_PROFILE_MS = 32737  # time-based Profile Velocity limit
# After its profile an XM430 reports Moving until its position loop has caught up (its
# time constant, about 10 ms), then the driver reads it on the goal: one more poll.
ARRIVAL_S = 0.010 + POLL_S / 5
GRIP_SPEED = 0.05  # the jaws' opening speed [m/s] (the XM430 gripper at its default profile)


@dataclass(frozen=True)
class DynamixelForecaster:
    """A Dynamixel arm's ``Forecaster`` (``armkit.drivers.Forecaster``) from its model
    and its ``[drivers.dynamixel]`` section (the tick calibration)."""

    model: ArmModel
    config: DynamixelSection
    moves: ClassVar[str] = "smart"

    def ticks(self, q: F64) -> NDArray[np.int64]:
        """Joint angles [rad], shape (dof,) -> goal ticks, clipped to the mode's range."""
        per_rad = self.config.ticks_per_turn / (2.0 * math.pi)
        ticks = np.rint(self.config.center_tick + np.asarray(q) * per_rad)
        low, high = (-1_048_575, 1_048_575) if self.extended else (0, 4095)
        return np.clip(ticks, low, high).astype(np.int64)

    def angles(self, ticks: NDArray[np.int64]) -> F64:
        """Ticks, shape (dof,) -> joint angles [rad], shape (dof,)."""
        per_rad = self.config.ticks_per_turn / (2.0 * math.pi)
        return (np.asarray(ticks, dtype=np.float64) - self.config.center_tick) / per_rad

    @property
    def extended(self) -> bool:
        """Whether the joints run in extended (multi-turn) position mode."""
        return self.config.operating_mode == "extended"

    def forecast(
        self,
        q0: F64,
        q1: F64,
        *,
        duration: float | None = None,
        speed: float | None = None,
        motor_s: float = 0.0,
    ) -> Forecast:
        """A waiting ``move(q1)`` from ``q0`` [rad] (the goal the last move reached): its
        profiles between the two goals' ticks, each with its arrival (none for servos
        already on their goal's tick); the driver then reads the goal itself."""
        goal = check_joints(self.model, q1)
        frac = check_speed(speed)
        asked = np.asarray(q0, dtype=np.float64)
        seconds = move_time(self.model, asked, goal, speed=frac, duration=duration)
        start, end = self.angles(self.ticks(asked)), self.angles(self.ticks(goal))
        if duration is None:  # the profile is timed for what the servos do: tick to tick
            seconds = move_time(self.model, start, end, speed=frac)
        arrival = ARRIVAL_S if np.any(self.ticks(asked) != self.ticks(goal)) else 0.0
        parts = pieces(start, goal, seconds, MAX_PROFILE_MS / 1000.0)
        took = sum(max(1, math.ceil(1000.0 * s - 1e-9)) / 1000.0 + arrival for _, s in parts)
        return Forecast(took, goal.copy(), motor_s)

    def forecast_grip(self, before: float | None, width: float) -> float:
        """The jaws' travel from ``before`` [m] (None: fully open) at ``GRIP_SPEED``, then
        the poll that sees them stopped [s]."""
        check_grip(self.model, width)
        start = self.model.gripper.width_max if before is None else before
        return abs(width - start) / GRIP_SPEED + POLL_S
