"""The OWI-535 driver's forecasts as a value: what its moves, paths and grips will
take, from its model and its unit's timing model, with no device (``TimedDriver``
forecasts with one; ``armkit check`` with one made for the model alone)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

import numpy as np
from numpy.typing import NDArray

from ..._errors import InputError
from ...model import ArmModel, check_grip, check_joints, move_time
from .._driver import Forecast
from ._forecast import forecast_move, forecast_run, grip_seconds
from ._timing import TimingModel
from ._waypoints import plan_path_runs

F64 = NDArray[np.float64]


@dataclass(frozen=True)
class TimedForecaster:
    """The OWI-535's ``Forecaster`` (``armkit.drivers.Forecaster``): its model and its
    unit's timing model (a new unit's: ``default_timing``)."""

    model: ArmModel
    timing: TimingModel
    moves: ClassVar[str] = "timed"

    def forecast(
        self,
        q0: F64,
        q1: F64,
        *,
        duration: float | None = None,
        speed: float | None = None,
        motor_s: float = 0.0,
    ) -> Forecast:
        """``TimedDriver.move(q1)`` from the estimate ``q0`` [rad]: its runs (``forecast_move``),
        the speed and duration checked by the shared rule (the motors cannot change speed)."""
        goal = check_joints(self.model, q1)
        move_time(self.model, q0, goal, speed=speed, duration=duration)
        ahead = forecast_move(self.timing, self.model, q0, goal, motor_s)
        return Forecast(ahead.seconds, ahead.q, ahead.motor_s)

    def forecast_path(
        self, model: ArmModel, q0: F64, q: F64, points: F64, motor_s: float = 0.0
    ) -> Forecast:
        """``TimedDriver.follow_path(model, q, points)`` from ``q0`` [rad] (``plan_path_runs``)."""
        runs = plan_path_runs(self.timing, model, q0, motor_s, q, points)
        return Forecast(runs.seconds, runs.q, runs.motor_s)

    def forecast_run(
        self, q0: F64, joint: str, direction: int, seconds: float, motor_s: float = 0.0
    ) -> Forecast:
        """``TimedDriver.turn_for(joint, direction, seconds)`` from ``q0`` [rad]: the angle
        as the timing model advances it, clamped at the limits (``forecast_run``).

        Raises:
            InputError: a direction other than -1 or +1.  ShortMoveError: under the
                motors' shortest reliable run.
        """
        j = self.model.joint_index(joint)
        if direction not in (-1, 1):
            raise InputError(f"turn {joint} needs direction -1 or +1, got {direction}")
        ahead = forecast_run(
            self.timing, np.asarray(q0, dtype=np.float64), j, direction, seconds, motor_s
        )
        return Forecast(ahead.seconds, ahead.q, ahead.motor_s)

    def forecast_grip(self, before: float | None, width: float) -> float:
        """``TimedDriver.grip(width)`` [m] from ``before`` [m]: its timed period, or 0 when
        the gripper already is open (or closed) as asked (``grip_seconds``)."""
        check_grip(self.model, width)
        return grip_seconds(self.timing, self.model, before, width)
