"""What a plan is: the joint commands, the strikes, and the notes that cannot be played."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from .._errors import ArmkitError
from .._terminal import count
from ..model import ArmModel
from ._layout import Target
from ._onsets import Contact
from ._predict import JointProfile
from ._score import Note
from ._strike import StrikePoses

F64 = NDArray[np.float64]


@dataclass(frozen=True)
class Move:
    """One joint command of the performance.

    Attributes:
        t: when to send it [s].  q: goal [rad], shape (dof,).
        profile: the predicted motion from ``t`` on.  speed: its speed fraction.
        kind: ``"travel"``, ``"down"`` or ``"rebound"``.  strike: index of its strike.
        timed: sent with its duration (``profile.duration``) rather than its speed: the
            rebound, whose servos then ramp only as long as the time allows.
    """

    t: float
    q: F64
    profile: JointProfile
    speed: float
    kind: str
    strike: int
    timed: bool = False


@dataclass(frozen=True)
class Strike:
    """One planned strike: ``target``; ``time`` [s] of the contact; ``hover`` height [m];
    the ``poses``; predicted tip ``speed`` at contact [m/s]; the bar's ``latency`` [s]."""

    target: Target
    time: float
    hover: float
    poses: StrikePoses
    speed: float
    latency: float

    def contact(self) -> Contact:
        """The contact this strike should make."""
        note = self.target.note
        return Contact(self.time, self.target.instrument, note.pitch, self.speed, note.drum)


@dataclass(frozen=True)
class Problem:
    """A note the arm cannot play as written: ``reason`` is ``"unreachable"``,
    ``"too soon"`` or ``"low travel"``; ``available`` and ``needed`` [s] are the time
    since the previous note and the time the arm would need (None if unreachable)."""

    note: Note
    reason: str
    available: float | None = None
    needed: float | None = None
    detail: str = ""

    def __str__(self) -> str:
        head = f"{self.note.name} at {self.note.onset:.3f} s"
        if self.reason == "too soon" and self.available == 0.0:
            return f"{head}: sounds with the previous note; one stick strikes one note at a time"
        if self.reason == "too soon" and self.available is not None and self.needed is not None:
            return (
                f"{head}: {self.available:.3f} s after the previous note, needs {self.needed:.3f} s"
            )
        return f"{head}: {self.reason}" + (f" ({self.detail})" if self.detail else "")


class PerformanceError(ArmkitError):
    """A piece the arm cannot play; ``problems`` lists every note."""

    def __init__(self, message: str, problems: tuple[Problem, ...]) -> None:
        super().__init__(message)
        self.problems = problems


@dataclass(frozen=True)
class Performance:
    """A planned piece: strikes, the joint commands in time order, and the problems.

    Attributes:
        strikes: the notes that will be struck, in time order.
        moves: every command, sorted by send time [s].
        problems: notes that cannot be played as written (empty if feasible).
        offset: performance time of the score's time 0 [s].
        model: the arm with the stick as its tool.
        source: the score's file.
        tempo: the tempo factor it was planned at (1 = as written).
    """

    strikes: tuple[Strike, ...]
    moves: tuple[Move, ...]
    problems: tuple[Problem, ...]
    offset: float
    model: ArmModel
    source: str = ""
    tempo: float = 1.0

    @property
    def suggested_tempo(self) -> float | None:
        """A tempo factor (two decimals, rounded down) at which every late note would
        have the time it needs at its present hover; None if no note is late. A
        slower piece may choose higher hovers, so check the new plan too."""
        ratios = [p.available / p.needed for p in self.problems if p.available and p.needed]
        if not ratios:
            return None
        return max(math.floor(self.tempo * min(ratios) * 100) / 100, 0.1)

    @property
    def feasible(self) -> bool:
        """True when every note can be played on time."""
        return not self.problems

    def contacts(self) -> tuple[Contact, ...]:
        """The planned contacts, for comparing with the played ones."""
        return tuple(s.contact() for s in self.strikes)


def check_performance(performance: Performance) -> None:
    """PerformanceError listing every note that cannot be played, or nothing."""
    problems = performance.problems
    if not problems:
        return
    listed = "; ".join(str(p) for p in problems)
    tempo = performance.suggested_tempo
    slower = f"--tempo {tempo}" if tempo is not None else "--tempo below 1"
    raise PerformanceError(
        f"{len({id(p.note) for p in problems})} of "
        f"{count(len(performance.strikes) + _unstruck(problems), 'note')} of "
        f"{performance.source or 'the piece'} cannot be played: {listed}; slow the piece "
        f"down ({slower}), lower the hover or move the instrument closer",
        problems,
    )


def _unstruck(problems: tuple[Problem, ...]) -> int:
    return sum(1 for p in problems if p.reason == "unreachable")
