"""Angles to timed rotations: check the limits, convert through the timing
model, refuse (or skip) moves too short for the motors. Nothing here sends a
byte, so a refused move changes nothing."""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from numpy.typing import NDArray

from ..._errors import ArmkitError, JointLimitError
from ._timing import TimingModel

F64 = NDArray[np.float64]


class ShortMoveError(ArmkitError):
    """A move would run a motor for less than the shortest reliable time."""


@dataclass(frozen=True)
class Turn:
    """One joint's part of a move: turn ``direction`` for ``seconds`` to reach ``target`` [rad]."""

    joint: int
    direction: int
    seconds: float
    target: float


@dataclass
class MoveReport:
    """What a move did: the steps run, and notes on clamped or skipped joints."""

    steps: list[Turn] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)


def plan_turns(
    timing: TimingModel,
    names: tuple[str, ...],
    q: F64,
    targets: dict[int, float],
    motor_s: float,
    *,
    clamp: bool,
    skip_short: bool,
) -> MoveReport:
    """Steps that turn each joint in ``targets`` ({index: angle [rad]}) from pose ``q``.

    Args:
        clamp: clamp targets beyond a limit to it (noted); False = JointLimitError.
        skip_short: leave joints whose move is under the minimum time where they
            are (noted); False = ShortMoveError.
    """
    report = MoveReport()
    for j, wanted in targets.items():
        target = _limited(timing, names[j], j, wanted, clamp, report)
        if abs(target - q[j]) < 1e-9:
            continue
        seconds = timing.duration(q, j, target, motor_s)
        if seconds < timing.min_move_s:
            _short(timing, names[j], (q, j, target, motor_s), seconds, skip_short, report)
            continue
        report.steps.append(Turn(j, 1 if target > q[j] else -1, seconds, target))
    return report


def _limited(
    timing: TimingModel, name: str, j: int, angle: float, clamp: bool, report: MoveReport
) -> float:
    lo, hi = timing.lower[j], timing.upper[j]
    if lo - 1e-9 <= angle <= hi + 1e-9:
        return min(hi, max(lo, angle))
    span = f"{math.degrees(lo):.1f}..{math.degrees(hi):.1f} deg"
    if not clamp:
        raise JointLimitError(
            f"{name} to {math.degrees(angle):.1f} deg is outside its limits {span}; "
            "choose an angle inside them"
        )
    limited = min(hi, max(lo, angle))
    report.notes.append(
        f"{name}: {math.degrees(angle):.1f} deg clamped to its limit "
        f"{math.degrees(limited):.1f} deg"
    )
    return limited


def _short(
    timing: TimingModel,
    name: str,
    move: tuple[F64, int, float, float],
    seconds: float,
    skip: bool,
    report: MoveReport,
) -> None:
    q, j, target, motor_s = move
    delta = math.degrees(target - q[j])
    minimum = timing.min_move_s * 1000
    direction = 1 if target > q[j] else -1
    smallest = abs(timing.advance(q, j, direction, timing.min_move_s, motor_s) - q[j])
    text = (
        f"{name} by {delta:+.1f} deg needs {seconds * 1000:.0f} ms of motor time, "
        f"under the {minimum:.0f} ms minimum"
    )
    if not skip:
        raise ShortMoveError(
            f"{text}; turn it further (or not at all): its smallest step is "
            f"{math.degrees(smallest):.1f} deg"
        )
    report.notes.append(f"{text}: left where it is")
