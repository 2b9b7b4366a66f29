"""Joints that know their angle: the OWI-535's own timed turns (one joint, several at
once, for a time, against a limit) and its gripper and light, each journaled in the
unit's state file: saved uncertain with the move pending before a motor starts, then
saved with the new estimate (``_journal.journaled_run``).

``TimedDriver`` opens the unit (its lock, motors, state file), holds one
``TimedTurns`` made of them and does the ``Driver`` protocol's moves with its
``plan`` and ``run_steps``; this object owns the estimate and is the only writer of
the state file.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from ..._clock import Clock
from ..._errors import ArmkitError, InputError
from ...model import ArmModel, OwiSection
from ._estimate import MOVING, after_run, pending_of
from ._journal import Until, journaled_run, raise_if_watchdog, write
from ._motors import Motors, Run
from ._plan import MoveReport, ShortMoveError, Turn, plan_turns
from ._state import UnitState
from ._timing import TimingModel

F64 = NDArray[np.float64]


class TimedTurns:
    """The OWI-535's joints, turned by time from their estimated angles.

    Args:
        model: the arm.
        clock: time for the runs.
        config: the ``[drivers.owi535]`` setup (its watchdog margin [s]).
        motors: the unit's motors, already open.
        path: the unit's state file, written before and after every run.
        state: the estimate to start from (as loaded from ``path``, or fresh).
        durable: fsync the state file (False in simulations).

    Attributes:
        state: the estimate, as last saved.
    """

    def __init__(
        self,
        model: ArmModel,
        clock: Clock,
        config: OwiSection,
        motors: Motors,
        path: Path,
        state: UnitState,
        *,
        durable: bool = True,
    ) -> None:
        self.model, self.clock, self.config, self.motors = model, clock, config, motors
        self.path, self.durable = path, durable
        self.state = state

    @property
    def joint_names(self) -> tuple[str, ...]:
        """base, shoulder, elbow, wrist."""
        return self.model.joint_names

    def read(self) -> F64:
        """Estimated joint angles [rad], shape (4,)."""
        return np.array(self.state.angles)

    @property
    def timing(self) -> TimingModel:
        """The unit's timing model."""
        return self.state.timing

    def turn_to(self, joint: str, angle: float, *, clamp: bool = True) -> MoveReport:
        """Turn ``joint`` to ``angle`` [rad]; beyond a limit it is clamped (noted) or, with
        ``clamp=False``, refused. Moves under the minimum time are refused (ShortMoveError)."""
        return self.turn_many({joint: angle}, clamp=clamp)

    def turn_by(self, joint: str, delta: float, *, clamp: bool = True) -> MoveReport:
        """Turn ``joint`` by ``delta`` [rad] from its estimated angle (see :meth:`turn_to`)."""
        return self.turn_to(
            joint, self.state.angles[self.model.joint_index(joint)] + delta, clamp=clamp
        )

    def turn_many(self, targets: dict[str, float], *, clamp: bool = True) -> MoveReport:
        """Turn several joints at once ({name: angle [rad]}), all motors started together."""
        index = {self.model.joint_index(name): float(a) for name, a in targets.items()}
        report = self.plan(index, clamp=clamp, skip_short=False)
        report.steps = self.run_steps(report.steps)
        return report

    def turn_for(self, joint: str, direction: int, seconds: float) -> None:
        """Run one motor for ``seconds`` [s] (000's timed turn; keyboard mode), the angle
        estimated by the timing model and clamped at the limits."""
        j = self.model.joint_index(joint)
        if direction not in (-1, 1):
            raise InputError(f"turn {joint} needs direction -1 or +1, got {direction}")
        if seconds < self.timing.min_move_s:
            raise ShortMoveError(
                f"turn {joint} for {seconds * 1000:.0f} ms is under the "
                f"{self.timing.min_move_s * 1000:.0f} ms minimum; run it longer"
            )
        self.run_steps([Turn(j, direction, seconds, math.nan)])

    def drive_to_limit(
        self, joint: str, direction: int, wait: Callable[[], object] | None = None
    ) -> float:
        """Run ``joint`` against its limit in ``direction`` until ``wait()`` returns (a person
        saying it is there), or with no ``wait`` for 1.25 times the slowest limit-to-limit
        time; then its angle is that limit, exactly. Returns the motor time [s].

        Raises:
            ArmkitError: nobody answered before the watchdog stopped the arm.
        """
        j = self.model.joint_index(joint)
        worst = (
            1.25 * (self.timing.upper[j] - self.timing.lower[j]) / min(self.timing.joints[j].rates)
        )
        worst /= self.timing.battery(self.state.motor_s)
        step = Turn(
            j, direction, worst, self.timing.upper[j] if direction > 0 else self.timing.lower[j]
        )
        run = Run({joint: (direction, worst)})
        before = self.state
        until = None if wait is None else (wait, 2 * worst + self.config.watchdog_margin_s)
        self._execute(
            run,
            before.with_(uncertain=True, reason=MOVING, pending=pending_of([step])),
            lambda: after_run(before, [step], run, self.joint_names, at_limit=run.complete),
            until,
        )
        if not run.complete:
            raise ArmkitError(
                f"the {joint} was stopped by the watchdog before anyone said it reached "
                "its limit; start again"
            )
        return run.elapsed[joint]

    def open_gripper(self, open_: bool) -> None:
        """Open or close the gripper for its timed period; nothing is sent if it already is."""
        wanted = "open" if open_ else "closed"
        if self.state.gripper == wanted:
            return
        run = Run({"gripper": (1 if open_ else -1, self.timing.gripper_s)})
        before = self.state

        def done() -> UnitState:
            moved = wanted if run.complete else "unknown"
            return before.with_(gripper=moved if run.started else before.gripper)

        self._execute(run, before.with_(gripper="unknown"), done)
        raise_if_watchdog(run)

    def set_light(self, on: bool) -> None:
        """Switch the light on or off (kept across stops)."""
        self.motors.set_light(on)
        self._save(self.state.with_(light=on))

    def set_state(self, state: UnitState) -> None:
        """Replace the unit's state (calibration, re-homing) and save it."""
        self._save(state)

    def plan(self, targets: dict[int, float], *, clamp: bool, skip_short: bool) -> MoveReport:
        """The steps that turn {joint index: angle [rad]} from the estimate (nothing runs):
        see ``_plan.plan_turns``."""
        q, motor_s = self.read(), self.state.motor_s
        return plan_turns(
            self.timing, self.joint_names, q, targets, motor_s, clamp=clamp, skip_short=skip_short
        )

    def run_steps(self, steps: list[Turn]) -> list[Turn]:
        """Run planned ``steps`` together, journaled; returns them. DeviceError if the
        watchdog had to stop the run (the estimate is saved first)."""
        if not steps:
            return steps
        names = self.joint_names
        run = Run({names[s.joint]: (s.direction, s.seconds) for s in steps})
        before = self.state
        self._execute(
            run,
            before.with_(uncertain=True, reason=MOVING, pending=pending_of(steps)),
            lambda: after_run(before, steps, run, self.joint_names),
        )
        raise_if_watchdog(run)
        return steps

    # -- internals ---------------------------------------------------------
    def _execute(
        self,
        run: Run,
        pending: UnitState,
        done: Callable[[], UnitState],
        until: Until | None = None,
    ) -> None:
        """Save ``pending``, run the motors, save ``done()`` (see ``journaled_run``)."""
        journaled_run(self.motors, self.clock, run, self._save, pending, done, until)

    def _save(self, state: UnitState) -> None:
        self.state = state
        write(self.path, state, self.durable)
