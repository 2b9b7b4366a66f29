"""Check a generated script and run it on a fresh simulated arm, and compare: the line
``armkit check`` says fails first (and why) with the line ``armkit run`` stops at, and
the time the check gives with the simulated time the run takes.

The run here is the runner alone (``run_checked`` given the check's result with its
diagnostics taken away): it refuses what it refuses by itself, as a script does when
the arm's state differs from what the check assumed.
"""

from __future__ import annotations

import dataclasses
import warnings
from dataclasses import dataclass
from pathlib import Path

from check_run_scripts import Script

from armkit import Arm
from armkit.script import Diagnostic, ScriptRunError, Source, check_source, run_checked

TIME_TOLERANCE = 0.01  # check's time within 1 % of the run's simulated time
TIME_FLOOR_S = 0.005  # and never closer than the simulator's few ticks [s]


@dataclass(frozen=True)
class Verdict:
    """Where and why a script fails: line, column, message (None: it does not fail)."""

    line: int
    col: int
    message: str

    def __str__(self) -> str:
        return f"{self.line}:{self.col}: {self.message}"


@dataclass(frozen=True)
class Outcome:
    """A script checked and run.

    Attributes:
        check: the check's first error as the script runs, or None.
        run: where the run stopped, or None.
        check_s: the check's time [s] (None: some step is timed only when it runs).
        run_s: the run's simulated time [s].
    """

    script: Script
    check: Verdict | None
    run: Verdict | None
    check_s: float | None
    run_s: float

    def disagreement(self) -> str | None:
        """What check and run disagree on, or None."""
        if self.check != self.run:
            return f"check says {self.check}, run says {self.run}"
        if self.check is not None:
            return None  # the time to a failure is not compared (yet)
        if self.check_s is None:
            return f"check leaves the time to the run ({self.run_s:.3f} s)"
        off = abs(self.check_s - self.run_s)
        if off > max(TIME_TOLERANCE * self.run_s, TIME_FLOOR_S):
            return f"check says {self.check_s:.3f} s, run takes {self.run_s:.3f} s"
        return None

    def report(self) -> str:
        """The script and the disagreement, for a failing test."""
        numbered = "\n".join(
            f"{k:3d}  {line}" for k, line in enumerate(self.script.text.splitlines(), 1)
        )
        verdict = self.disagreement() or "check and run agree"
        head = f"{self.script.arm} seed {self.script.seed}: {verdict}"
        return f"{head}\n{numbered}"


def check_and_run(script: Script, folder: Path) -> Outcome:
    """Write ``script``'s files into ``folder``, check the script for a fresh simulated
    arm, then run it there without the check's verdict."""
    for name, text in script.files.items():
        (folder / name).write_text(text, encoding="utf-8")
    source = Source(str(folder / "gen.arm"), script.text)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # an OWI's uncertain estimate, cut drawings, ...
        with Arm(script.arm, "sim") as arm:
            result = check_source(source, model=arm.model, arm=arm, base_dir=folder)
            check = _first_error(result.first_error)
            t0 = arm.clock.now()
            run = None
            try:
                run_checked(arm, dataclasses.replace(result, diagnostics=[]), base_dir=folder)
            except ScriptRunError as exc:
                message = Diagnostic(exc.loc, exc.message).message  # numbers as check says them
                run = Verdict(exc.loc.line, exc.loc.col, message)
            run_s = arm.clock.now() - t0
    table = result.timetable
    return Outcome(script, check, run, None if table.unknown else table.total, run_s)


def _first_error(d: Diagnostic | None) -> Verdict | None:
    return None if d is None else Verdict(d.loc.line, d.loc.col, d.message)
