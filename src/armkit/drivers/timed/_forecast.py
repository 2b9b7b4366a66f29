"""What the OWI-535's driver will do, worked out before it does it: the motor runs
of a move, a timed run or a grip, how long they take and where the estimate ends,
from a pose and the motor-seconds used so far, with no device, clock or state file.

A move's runs are decided once, by ``move_legs`` (limits, ``safe_order``,
``plan_legs``), for the driver's ``move_report`` and for ``forecast_move``, which
times them (``plan_turns`` and so ``TimingModel.duration``) one joint at a time,
each from the pose and battery the previous run left: the same runs the driver
will make, for the script checker (``armkit.script``) to time a script the way it
will run.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from ...model import ArmModel
from ._order import safe_order
from ._plan import ShortMoveError, Turn, plan_turns
from ._short import plan_legs
from ._timing import TimingModel

F64 = NDArray[np.float64]


@dataclass(frozen=True)
class TurnForecast:
    """The runs one command will make, and the driver's estimate after them.

    Attributes:
        steps: the motor runs, one after another (one joint each).
        q: estimated joint angles after them [rad], shape (4,).
        motor_s: motor-seconds used after them [s] (what drains the battery).
        notes: joints left where they are (within the 0.5 deg resolution).
    """

    steps: tuple[Turn, ...]
    q: F64
    motor_s: float
    notes: tuple[str, ...] = ()

    @property
    def seconds(self) -> float:
        """How long the runs take [s]."""
        return float(sum(s.seconds for s in self.steps))


def move_legs(
    timing: TimingModel, model: ArmModel, q0: F64, q1: F64, motor_s: float, table: bool = True
) -> tuple[list[tuple[int, float]], list[str]]:
    """The one-joint runs, (joint, target [rad]) in order, that ``TimedDriver.move(q1)``
    makes from the estimate ``q0`` [rad], shape (4,), with ``motor_s`` [s] used, and notes
    on joints left where they are: every target inside the limits, joints in the order that
    keeps the arm off the table (``table=False``: the best order even below it), short
    turns as two legs. All of it decided before a motor starts.

    Raises:
        JointLimitError: a target is outside the unit's limits.
        UnreachableError: every order sweeps the arm through the table.
        ShortMoveError: a turn too small for the motors, with no room for two legs.
    """
    names, height = model.joint_names, model.dh[0].d
    plan_turns(timing, names, q0, dict(enumerate(q1)), 0.0, clamp=False, skip_short=True)
    order = safe_order(q0, q1, timing.lengths, height, table)
    notes: list[str] = []
    legs = plan_legs(timing, names, q0, (order, q1), motor_s, height if table else None, notes)
    return legs, notes


def forecast_move(
    timing: TimingModel, model: ArmModel, q0: F64, q1: F64, motor_s: float = 0.0
) -> TurnForecast:
    """The runs of ``TimedDriver.move(q1)`` from the estimate ``q0`` [rad], shape (4,),
    with ``motor_s`` [s] used (``move_legs``), each timed from where the one before left
    the arm. Raises as ``move_legs``."""
    start = np.array(q0, dtype=np.float64)
    legs, notes = move_legs(timing, model, start, np.asarray(q1, dtype=np.float64), motor_s)
    names, steps = model.joint_names, []
    pose, used = start.copy(), motor_s
    for j, target in legs:
        part = plan_turns(timing, names, pose, {j: target}, used, clamp=False, skip_short=True)
        before, spent = pose.copy(), used
        for s in part.steps:  # the driver's estimate after a run (``after_run``): advanced
            pose[s.joint] = timing.advance(before, s.joint, s.direction, s.seconds, spent)
            used += s.seconds  # by the run's time from the pose and motor time before it
        steps += part.steps
        notes += part.notes
    return TurnForecast(tuple(steps), pose, used, tuple(notes))


def forecast_run(
    timing: TimingModel, q0: F64, j: int, direction: int, seconds: float, motor_s: float = 0.0
) -> TurnForecast:
    """``TimedDriver.turn_for``: joint ``j``'s motor run ``seconds`` [s] in ``direction``
    (+1/-1) from ``q0`` [rad]; the angle as the timing model advances it, clamped.

    Raises:
        ShortMoveError: ``seconds`` under the motors' shortest reliable run.
    """
    if seconds < timing.min_move_s:
        raise ShortMoveError(
            f"a run of {seconds * 1000:.0f} ms is under the {timing.min_move_s * 1000:.0f} ms "
            "minimum; run it longer"
        )
    q = np.array(q0, dtype=np.float64)
    q[j] = timing.advance(q, j, direction, seconds, motor_s)
    return TurnForecast((Turn(j, direction, seconds, float(q[j])),), q, motor_s + seconds)


def grip_seconds(timing: TimingModel, model: ArmModel, before: float | None, width: float) -> float:
    """How long ``TimedDriver.grip(width)`` [m] runs the gripper [s]: its timed period,
    or 0 when it is already open (or closed) as asked. ``before``: the width it was last
    set to [m] (None: unknown, so it runs)."""
    middle = (model.gripper.width_min + model.gripper.width_max) / 2
    if before is not None and (before > middle) == (width > middle):
        return 0.0
    return timing.gripper_s
