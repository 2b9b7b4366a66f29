"""What a plan is: the joint commands, the strikes, and the notes that cannot be played."""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field
from functools import cached_property

import numpy as np
from numpy.typing import NDArray

from .._errors import ArmkitError
from .._terminal import count
from ..model import ArmModel
from ._layout import StrikeSpot
from ._onsets import Contact
from ._predict import JointProfile
from ._score import MIN_TEMPO, Note
from ._strike import StrikePoses

F64 = NDArray[np.float64]


@dataclass(frozen=True)
class Move:
    """One joint command of the performance.

    Attributes:
        t: when to send it [s].  q: goal [rad], shape (dof,).
        profile: the predicted motion from ``t`` on.  speed: its speed fraction.
        kind: ``"travel"``, ``"down"`` or ``"rebound"``.  strike: index of its strike.
        timed: sent with its duration (``profile.duration``) rather than its speed: every
            move the planner makes (the servos then run it at their own limits, ramping only
            as long as the time allows).
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

    target: StrikeSpot
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


# Problems a slower tempo can solve: a note too soon after the last, a travel that
# had to stay low; an unreachable note stays unreachable at any tempo.
TEMPO_REASONS = ("too soon", "low travel")


class PerformanceError(ArmkitError):
    """A piece the arm cannot play; ``problems`` lists every note, ``tempo`` is the
    fastest tempo factor the planner found it plays at (None: none)."""

    def __init__(
        self, message: str, problems: tuple[Problem, ...], tempo: float | None = None
    ) -> None:
        super().__init__(message)
        self.problems, self.tempo = problems, tempo


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
        replan: the same plan at another tempo factor (``plan_performance`` sets it;
            None: cannot be planned again), what ``suggested_tempo`` tries tempi with.
    """

    strikes: tuple[Strike, ...]
    moves: tuple[Move, ...]
    problems: tuple[Problem, ...]
    offset: float
    model: ArmModel
    source: str = ""
    tempo: float = 1.0
    replan: Callable[[float], Performance] | None = field(default=None, compare=False, repr=False)

    @cached_property
    def suggested_tempo(self) -> float | None:
        """The fastest tempo factor below this one (in hundredths) at which the planner
        plays every note in time (``fastest_tempo`` with ``replan``); None if no note is
        late, a note is unreachable at any tempo, not even ``MIN_TEMPO`` plays, or the
        plan cannot be made again (``replan`` None)."""
        return self.fitting_tempo()

    def fitting_tempo(self, plays: Callable[[Performance], bool] | None = None) -> float | None:
        """``suggested_tempo``, a plan at a tempo passing ``plays`` too (the job's own
        checks, such as the scene's clearance)."""
        again = self.replan
        if again is None or not self.problems:
            return None
        if any(p.reason not in TEMPO_REASONS for p in self.problems):
            return None

        def fits(tempo: float) -> bool:
            perf = again(tempo)
            return perf.feasible and (plays is None or plays(perf))

        ratios = [p.available / p.needed for p in self.problems if p.available and p.needed]
        guess = self.tempo * min(ratios) if ratios else None
        return fastest_tempo(fits, self.tempo, guess)

    @property
    def feasible(self) -> bool:
        """True when every note can be played on time."""
        return not self.problems

    def contacts(self) -> tuple[Contact, ...]:
        """The planned contacts, for comparing with the played ones."""
        return tuple(s.contact() for s in self.strikes)


def fastest_tempo(
    plays: Callable[[float], bool], below: float, guess: float | None = None
) -> float | None:
    """The fastest tempo factor under ``below``, in hundredths, at which ``plays`` (the
    planner's own test), by bisection on the hundredths ``MIN_TEMPO``.. ``below``, the
    first try at ``guess`` (rounded down; an estimate saves tries); None if not even
    ``MIN_TEMPO`` plays. Only a tempo tried and played is returned."""
    lo, hi = round(MIN_TEMPO * 100), math.ceil(round(below * 100, 6)) - 1
    best = None
    probe = None if guess is None else math.floor(round(guess * 100, 6))
    while lo <= hi:
        mid = probe if probe is not None and lo <= probe <= hi else (lo + hi + 1) // 2
        probe = None
        if plays(mid / 100):
            best, lo = mid, mid + 1
        else:
            hi = mid - 1
    return None if best is None else best / 100


def written_tempo(tempo: float, script: bool = False) -> str:
    """A tempo factor as the user writes it, a percentage of the written tempo (one unit
    for the CLI and scripts): ``--tempo 46``, in a script ``tempo 46%``."""
    return f"tempo {tempo * 100:.6g}%" if script else f"--tempo {tempo * 100:.6g}"


def check_performance(
    performance: Performance,
    plays: Callable[[Performance], bool] | None = None,
    *,
    script: bool = False,
) -> None:
    """PerformanceError listing every note that cannot be played, or nothing. When a
    slower tempo helps, it names the fastest one the planner plays the piece at (and
    that passes ``plays``, the job's other checks), written as on the command line
    (``--tempo 46``) or, with ``script``, as in a script (``tempo 46%``)."""
    problems = performance.problems
    if not problems:
        return
    listed = "; ".join(str(p) for p in problems)
    tempo = performance.fitting_tempo(plays) if plays is not None else performance.suggested_tempo
    remedy = "lower the hover or move the instrument closer"
    if tempo is not None:
        advice = f"slow the piece down ({written_tempo(tempo, script)} plays it), {remedy}"
    elif any(p.reason not in TEMPO_REASONS for p in problems):
        advice = f"no tempo brings a note into reach: {remedy}"
    elif performance.replan is not None:
        advice = f"not even {written_tempo(MIN_TEMPO, script)} is slow enough: {remedy}"
    else:
        advice = f"slow the piece down (below {written_tempo(performance.tempo, script)}), {remedy}"
    raise PerformanceError(
        f"{len({id(p.note) for p in problems})} of "
        f"{count(len(performance.strikes) + _unstruck(problems), 'note')} of "
        f"{performance.source or 'the piece'} cannot be played: {listed}; {advice}",
        problems,
        tempo,
    )


def _unstruck(problems: tuple[Problem, ...]) -> int:
    return sum(1 for p in problems if p.reason == "unreachable")
