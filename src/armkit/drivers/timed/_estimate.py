"""Where the joints are after a run of the motors: after a run that finished,
one cut short (exception, Ctrl-C, watchdog), or one whose process died
(``kill -9``), estimated through the timing model and written down honestly."""

from __future__ import annotations

import time

import numpy as np

from ._motors import Run
from ._plan import Turn
from ._state import Pending, UnitState

MOVING = "a move was in progress"


def pending_of(steps: list[Turn]) -> Pending:
    """The record written before a run starts: directions, planned times, wall-clock start."""
    return Pending(
        {s.joint: s.direction for s in steps}, {s.joint: s.seconds for s in steps}, time.time()
    )


def after_run(
    before: UnitState, steps: list[Turn], run: Run, names: tuple[str, ...], at_limit: bool = False
) -> UnitState:
    """The state after ``run``: each joint advanced by its measured motor time (or, with
    ``at_limit``, exactly at the step's target limit); uncertain if the run was cut short.
    A run whose motors never started leaves ``before`` as it was."""
    if not run.started:
        return before.with_(pending=None)
    q = np.array(before.angles)
    angles = list(before.angles)
    for s in steps:
        elapsed = run.elapsed.get(names[s.joint], 0.0)
        advanced = before.timing.advance(q, s.joint, s.direction, elapsed, before.motor_s)
        angles[s.joint] = s.target if at_limit else advanced
    cut = None
    if not run.complete:
        cut = "stopped by the watchdog" if run.watchdog_fired else "a move was cut short"
    return before.with_(
        angles=tuple(angles),
        motor_s=before.motor_s + sum(run.elapsed.values()),
        pending=None,
        uncertain=before.uncertain or cut is not None,
        reason=cut or before.reason,
    )


def recovered(state: UnitState, now_unix: float) -> UnitState:
    """The state after a process died mid-move: its motors ran until ``now_unix`` (when a
    new driver sent stop), so advance them that long, clamped, and mark it uncertain."""
    if state.pending is None:
        return state
    q = np.array(state.angles)
    ran = max(0.0, now_unix - state.pending.started_unix)
    angles = list(state.angles)
    for j, d in state.pending.directions.items():
        angles[j] = state.timing.advance(q, j, d, ran, state.motor_s)
    reason = "the program died during a move; run rehome"
    return state.with_(angles=tuple(angles), pending=None, uncertain=True, reason=reason)
