"""The check's timetable of a script: each statement's motion with its line, start, time
and end pose, and the total time, printed by ``armkit run --dry-run``."""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from numpy.typing import NDArray

from .._terminal import count, fixed
from ._ast import Source

F64 = NDArray[np.float64]
MAX_ROWS = 200  # rows printed before the rest is summarised


@dataclass(frozen=True)
class TimetableRow:
    """One statement as it will run.

    Attributes:
        line: its line in the script.
        context: ``repeat 2/5``, ``dip`` ... ('' at the top level).
        start: when it starts [s] after the script starts (None once unknown).
        duration: how long it takes [s], None if not known before it runs.
        q: joint angles after it [rad], shape (dof,), None if not known.
        note: what else to say (``x98 like iteration 2``).
    """

    line: int
    context: str
    start: float | None
    duration: float | None
    q: F64 | None
    note: str = ""


@dataclass
class Timetable:
    """Every step of a checked script and its total time.

    Attributes:
        rows: in execution order.  total: sum of the known durations [s].
        unknown: how many steps have a duration only known when they run (jobs, unknown values).
        joint_names: the arm's joints, for printing.
    """

    joint_names: tuple[str, ...]
    rows: list[TimetableRow] = field(default_factory=list)
    total: float = 0.0
    unknown: int = 0

    def format(self, source: Source) -> str:
        """The timetable as text: line, start, duration, statement, joint angles [deg]."""
        head = f"{'line':>5} {'start s':>8} {'took s':>7}  statement"
        rows = [head, "-" * len(head)]
        for step in self.rows[:MAX_ROWS]:
            rows.append(_row(step, source))
        if len(self.rows) > MAX_ROWS:
            rows.append(f"      ... {len(self.rows) - MAX_ROWS} more steps")
        known = f"total {self.total:.2f} s"
        if self.unknown:
            known += f" + {self.unknown} step{'s' if self.unknown > 1 else ''} timed only when run"
        rows.append(
            f"{known} ({count(len(self.rows), 'step')}; joints {', '.join(self.joint_names)} in deg)"
        )
        return "\n".join(rows)


def _row(step: TimetableRow, source: Source) -> str:
    start = "?" if step.start is None else f"{step.start:.2f}"
    took = "?" if step.duration is None else f"{step.duration:.2f}"
    text = source.line(step.line).split("#")[0].strip()
    if step.context:
        text = f"{text}  [{step.context}]"
    if step.note:
        text = f"{text}  {step.note}"
    if step.q is not None:
        text = f"{text:<44} -> " + " ".join(f"{fixed(math.degrees(a)):>7}" for a in step.q)
    return f"{step.line:>5} {start:>8} {took:>7}  {text}"
