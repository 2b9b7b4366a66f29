"""The OWI-535 driver: joints that know their angle, on timed motors.

Angles are estimated through the unit's timing model and kept in its state
file, written atomically before a move (marked uncertain, with the move in
progress, so a ``kill -9`` leaves an honest file) and after it (with the new
estimate). A move cut short keeps the estimate of where it stopped and stays
uncertain until the arm is re-homed.
"""

from __future__ import annotations

import time
from collections.abc import Callable
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from ..._clock import Clock
from ..._errors import InputError
from ..._lock import exclusive
from ...model import ArmModel, OwiSection, check_grip, check_joints, move_time, owi_section
from .._driver import Forecast
from ._config import default_timing
from ._estimate import recovered
from ._forecast import move_legs
from ._forecaster import TimedForecaster
from ._journal import warn
from ._motors import Device, Motors
from ._plan import MoveReport
from ._safety import ExitGuard
from ._state import UnitState, load
from ._timing import TimingModel
from ._turns import TimedTurns
from ._waypoints import PathRuns, plan_path_runs

F64 = NDArray[np.float64]


class TimedDriver:
    """A :class:`~armkit.drivers.Driver` for the OWI-535 (open-loop timed motors); its own
    turns, gripper and light (``turn_to``, ``drive_to_limit``, ...) are those of the
    ``TimedTurns`` it holds, which owns the estimate and its state file."""

    moves = "timed"  # see armkit.drivers.Forecaster

    def __init__(
        self,
        model: ArmModel,
        device: Device,
        clock: Clock,
        path: Path,
        unit: str = "default",
        *,
        durable: bool = True,
    ) -> None:
        """Open the unit whose state file is ``path`` (created on first use): take its lock
        (a second process is refused with DeviceError before a byte is sent), send stop,
        and if the last process died mid-move, account for it. ``durable=False`` skips
        fsync (simulations).

        Attributes:
            warn: called with a message before a move starts from an uncertain estimate
                (default: ``warnings.warn`` with UncertainEstimateWarning), once per driver.
        """
        self.durable = durable
        self.model, self.clock, self.path = model, clock, path
        self.config: OwiSection = owi_section(model)
        self._lock = exclusive(path, f"the OWI-535 unit {unit!r} ({path})")
        try:
            self._open(model, device, clock, unit)
        except BaseException:
            if hasattr(self, "_guard"):
                self._guard.uninstall()
            self._lock.release()
            raise

    def _open(self, model: ArmModel, device: Device, clock: Clock, unit: str) -> None:
        self.warn: Callable[[str], None] = warn
        self._warned = False
        self._asked: tuple[F64, UnitState] | None = None  # the last goal, and the state after it
        self.motors = Motors(
            device,
            clock,
            base_reversed=self.config.base_reversed,
            watchdog_margin_s=self.config.watchdog_margin_s,
        )
        state = load(self.path) if self.path.exists() else _fresh_state(model, unit)
        self._turns = TimedTurns(
            model, clock, self.config, self.motors, self.path, state, durable=self.durable
        )
        self.motors.light = state.light
        self._guard = ExitGuard(self.motors.stop)
        self._guard.install()
        self._closed = False
        self.simulation: object | None = None  # the OwiSim behind a simulated device
        self.motors.stop()
        if state.pending is not None:
            self._turns.set_state(recovered(state, time.time()))

    # -- the estimate (``TimedTurns``) ---------------------------------------
    @property
    def state(self) -> UnitState:
        """The unit's estimate, as last saved (replace it with :meth:`set_state`)."""
        return self._turns.state

    @property
    def timing(self) -> TimingModel:
        """The unit's timing model."""
        return self._turns.timing

    @property
    def joint_names(self) -> tuple[str, ...]:
        """base, shoulder, elbow, wrist."""
        return self._turns.joint_names

    def read(self) -> F64:
        """Estimated joint angles [rad], shape (4,)."""
        return self._turns.read()

    def set_state(self, state: UnitState) -> None:
        """Replace the unit's state (calibration, re-homing) and save it."""
        self._turns.set_state(state)

    # -- Driver protocol -----------------------------------------------------
    def move(
        self,
        q: F64,
        *,
        duration: float | None = None,
        speed: float | None = None,
        wait: bool = True,
    ) -> None:
        """Turn every joint to ``q`` [rad], shape (4,), one joint at a time in an order that
        keeps the arm off the table. ``duration`` and ``speed`` are checked by the shared
        rule (``armkit.model._limits.move_time``) but cannot change the OWI's one motor
        speed; moves always block. Joints within the 200 ms resolution stay where they are.

        Raises:
            JointLimitError: a target is outside the model's or the unit's limits (nothing moves).
            ValueError: a bad speed or a duration too short for the joints' speed limits.
            UnreachableError: every order would sweep the arm through the table.
        """
        goal = check_joints(self.model, q)
        move_time(self.model, self._start(), goal, speed=speed, duration=duration)
        self.move_report(goal)
        self._asked = (goal, self.state)

    def forecast(
        self,
        q0: F64,
        q1: F64,
        *,
        duration: float | None = None,
        speed: float | None = None,
        motor_s: float = 0.0,
    ) -> Forecast:
        """What ``move(q1)`` does from the estimate ``q0`` [rad] with ``motor_s`` [s] used
        (``TimedForecaster`` with this unit's timing); no motor starts."""
        return self.forecaster().forecast(q0, q1, duration=duration, speed=speed, motor_s=motor_s)

    def forecast_grip(self, before: float | None, width: float) -> float:
        """How long ``grip(width)`` [m] takes from ``before`` [m] [s]."""
        return self.forecaster().forecast_grip(before, width)

    def forecast_path(
        self, model: ArmModel, q0: F64, q: F64, points: F64, motor_s: float = 0.0
    ) -> Forecast:
        """What ``follow_path(model, q, points)`` does from ``q0`` [rad]."""
        return self.forecaster().forecast_path(model, q0, q, points, motor_s)

    def forecast_run(
        self, q0: F64, joint: str, direction: int, seconds: float, motor_s: float = 0.0
    ) -> Forecast:
        """What ``turn_for(joint, direction, seconds)`` does from ``q0`` [rad]."""
        return self.forecaster().forecast_run(q0, joint, direction, seconds, motor_s)

    def forecaster(self) -> TimedForecaster:
        """This unit's forecasts as a value (its model and timing model)."""
        return TimedForecaster(self.model, self.timing)

    def _start(self) -> F64:
        """Where a move starts for the timing rule [rad]: the angles the last move was
        asked for, while nothing has changed since (a joint within the resolution stays
        where it is, so a stream of small steps is timed step by step), else the estimate."""
        if self._asked is not None and self._asked[1] is self.state:
            return self._asked[0]
        return self.read()

    def move_report(self, q: F64, *, table: bool = True) -> MoveReport:
        """:meth:`move`, returning what was done (steps, and notes on joints already
        within the 0.5 deg resolution). ``table=False`` skips the table check
        (calibration, re-homing: the arm stands at the edge of the table).

        A joint whose turn is shorter than the motors' shortest reliable run turns in
        two timed legs (past the target, then back); every leg is planned before the
        first motor starts, so a refused move moves nothing."""
        if q.shape != (4,):
            raise InputError(f"q must be 4 joint angles, got shape {q.shape}")
        legs, notes = move_legs(self.timing, self.model, self.read(), q, self.state.motor_s, table)
        report = MoveReport(notes=notes)
        if legs:
            self._warn_if_uncertain()
        for j, target in legs:  # each run timed from the estimate the one before left
            part = self._turns.plan({j: target}, clamp=False, skip_short=True)
            report.steps += self._turns.run_steps(part.steps)
        return report

    def follow_path(self, model: ArmModel, q: F64, points: F64) -> PathRuns:
        """Follow the joint path ``q`` [rad], (N, 4), whose tool points are ``points`` [m],
        (N, 3), (``model``: the kinematics they were solved with, the grip included) the
        way timed motors can: onto its start, then through ``path_waypoints``, one run per
        joint and level (see ``armkit.drivers.timed._waypoints``). Everything is planned
        first, so a path that would stray too far is refused (UnreachableError) before a
        motor starts. Returns the plan (its runs, time and deviation)."""
        plan = plan_path_runs(self.timing, model, self.read(), self.state.motor_s, q, points)
        self.move(np.asarray(q[0], dtype=np.float64))
        for w in plan.waypoints:
            self.move(w)
        return plan

    @property
    def uncertainty(self) -> str | None:
        """Why the estimated angles may be wrong (never homed, a move cut short, the
        watchdog, the program died mid-move), or None when they are certain."""
        return self.state.reason if self.state.uncertain else None

    def _warn_if_uncertain(self) -> None:
        if self.state.uncertain and not self._warned:
            self._warned = True
            self.warn(
                f"the OWI-535's joint angles are an uncertain estimate ({self.state.reason}) "
                "and this move starts from it; re-home the arm to know them again"
            )

    def grip(self, width: float) -> None:
        """Open (``width`` [m] over half the gripper's range) or close the gripper."""
        check_grip(self.model, width)
        self._turns.open_gripper(
            width > (self.model.gripper.width_min + self.model.gripper.width_max) / 2
        )

    def stop(self) -> None:
        """Stop every motor now (the light keeps its state). Safe to repeat, a no-op once
        closed (the motors were stopped when it closed)."""
        if self._closed:
            return
        self.motors.stop()

    def relax(self) -> None:
        """Every motor off: the OWI's DC motors hold nothing and run only during a move,
        so this is ``stop`` (for the tasks that switch an arm off at the end)."""
        self.stop()

    # -- the OWI's own turns, gripper and light (``TimedTurns``) ---------------
    def turn_to(self, joint: str, angle: float, *, clamp: bool = True) -> MoveReport:
        """Turn ``joint`` to ``angle`` [rad]; beyond a limit it is clamped (noted) or, with
        ``clamp=False``, refused. Moves under the minimum time are refused (ShortMoveError)."""
        return self._turns.turn_to(joint, angle, clamp=clamp)

    def turn_by(self, joint: str, delta: float, *, clamp: bool = True) -> MoveReport:
        """Turn ``joint`` by ``delta`` [rad] from its estimated angle (see :meth:`turn_to`)."""
        return self._turns.turn_by(joint, delta, clamp=clamp)

    def turn_many(self, targets: dict[str, float], *, clamp: bool = True) -> MoveReport:
        """Turn several joints at once ({name: angle [rad]}), all motors started together."""
        return self._turns.turn_many(targets, clamp=clamp)

    def turn_for(self, joint: str, direction: int, seconds: float) -> None:
        """Run one motor for ``seconds`` [s] in ``direction`` (-1 or +1), the angle estimated
        by the timing model and clamped at the limits."""
        self._turns.turn_for(joint, direction, seconds)

    def drive_to_limit(
        self, joint: str, direction: int, wait: Callable[[], object] | None = None
    ) -> float:
        """Run ``joint`` against its limit until ``wait()`` returns (or for 1.25 times the
        slowest limit-to-limit time); its angle is then that limit. Returns the motor
        time [s]; ArmkitError if the watchdog stopped it first."""
        return self._turns.drive_to_limit(joint, direction, wait)

    def open_gripper(self, open_: bool) -> None:
        """Open or close the gripper for its timed period; nothing is sent if it already is."""
        self._turns.open_gripper(open_)

    def set_light(self, on: bool) -> None:
        """Switch the light on or off (kept across stops)."""
        self._turns.set_light(on)

    def close(self) -> None:
        """Stop, save, release the device. Safe to call twice."""
        if self._closed:
            return
        self._closed = True
        try:
            self.motors.stop()
        finally:
            self._guard.uninstall()
            self.motors.device.close()
            self._lock.release()


def _fresh_state(model: ArmModel, unit: str) -> UnitState:
    return UnitState(
        unit=unit, timing=default_timing(model), angles=tuple(float(a) for a in model.home)
    )
