"""Moves shorter than the motors' shortest reliable run, done in two legs.

An OWI motor run under ``min_move_s`` does not move the joint reliably, so a
small turn is made as two runs that are each long enough: first past the
target (or away from it), then back onto it, both timed by the unit's model.
A joint within ``RESOLUTION`` of its target counts as there. When neither way
fits inside the limits (or keeps the arm off the table), the move is refused
with the smallest step the joint can make.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import NDArray

from ._order import TABLE_TOLERANCE_M, lowest_point
from ._plan import ShortMoveError
from ._timing import TimingModel

F64 = NDArray[np.float64]
RESOLUTION = math.radians(0.5)  # a joint this close to its target is there
MARGIN = 1.25  # each leg runs at least this many times the shortest reliable run
FACTORS = (1.0, 1.5, 2.0, 3.0)  # how far past the smallest step the first leg may go


def smallest_step(timing: TimingModel, q: F64, j: int, direction: int, motor_s: float) -> float:
    """The smallest turn [rad] joint ``j`` makes reliably from pose ``q`` [rad]:
    ``MARGIN`` times the shortest run, slip and coast included (0 at a limit)."""
    after = timing.advance(q, j, direction, MARGIN * timing.min_move_s, motor_s)
    return abs(after - float(q[j]))


def legs(
    timing: TimingModel,
    name: str,
    q: F64,
    j: int,
    target: float,
    motor_s: float,
    shoulder_height: float | None,
) -> list[float]:
    """The targets [rad] joint ``j`` turns to, one run each, to go from ``q[j]`` to
    ``target``: [] within RESOLUTION, [target] for a long enough move, else two legs.
    ``shoulder_height`` [m]: keep every leg's pose above the table (None: don't check).

    Raises:
        ShortMoveError: a short move with no room for two legs (names the smallest step).
    """
    start = float(q[j])
    if abs(target - start) < RESOLUTION:
        return []
    if timing.duration(q, j, target, motor_s) >= timing.min_move_s:
        return [target]
    toward = 1 if target > start else -1
    at_target = np.array(q, dtype=float)
    at_target[j] = target
    for factor in FACTORS:
        for via in _vias(timing, q, at_target, j, toward, motor_s, factor):
            if _fits(timing, q, j, [via, target], motor_s, shoulder_height):
                return [via, target]
    step = smallest_step(timing, q, j, toward, motor_s)
    raise ShortMoveError(
        f"{name} by {math.degrees(target - start):+.1f} deg is under the smallest step it "
        f"makes ({math.degrees(step):.1f} deg) and there is no room inside its limits to come "
        "at it from farther away; turn it further (or not at all)"
    )


def _vias(
    timing: TimingModel, q: F64, at_target: F64, j: int, toward: int, motor_s: float, factor: float
) -> list[float]:
    """First-leg targets [rad]: past the target, then away from it behind the start."""
    past = float(at_target[j]) + toward * factor * smallest_step(
        timing, at_target, j, toward, motor_s
    )
    behind = float(q[j]) - toward * factor * smallest_step(timing, q, j, -toward, motor_s)
    return [past, behind]


def _fits(
    timing: TimingModel,
    q: F64,
    j: int,
    targets: list[float],
    motor_s: float,
    shoulder_height: float | None,
) -> bool:
    """Every leg inside the limits, long enough, and (if asked) above the table."""
    pose = np.array(q, dtype=float)
    for target in targets:
        if not timing.lower[j] <= target <= timing.upper[j]:
            return False
        if timing.duration(pose, j, target, motor_s) < MARGIN * timing.min_move_s * 0.99:
            return False
        pose[j] = target
        if shoulder_height is not None and (
            lowest_point(pose, timing.lengths, shoulder_height) < -TABLE_TOLERANCE_M
        ):
            return False
    return True


def plan_legs(
    timing: TimingModel,
    names: tuple[str, ...],
    q0: F64,
    move: tuple[list[int], F64],
    motor_s: float,
    shoulder_height: float | None,
    notes: list[str],
) -> list[tuple[int, float]]:
    """(joint, target [rad]) of every run of a move from ``q0`` to ``q1`` turning the
    joints in ``order`` (``move`` = (order, q1)), planned before any motor starts;
    joints within RESOLUTION are noted in ``notes`` and left where they are."""
    order, q1 = move
    pose, out = np.array(q0, dtype=float), []
    for j in order:
        target = float(q1[j])
        steps = legs(timing, names[j], pose, j, target, motor_s, shoulder_height)
        if not steps:
            notes.append(
                f"{names[j]}: {math.degrees(target - pose[j]):+.2f} deg is within the "
                f"{math.degrees(RESOLUTION):.1f} deg resolution: left where it is"
            )
            continue
        out += [(j, t) for t in steps]
        pose[j] = target
    return out
