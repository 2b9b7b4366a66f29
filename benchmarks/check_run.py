"""``armkit check`` against ``armkit run`` on random scripts (issue 26, point 2), printed
as a table: for each simulated arm, N scripts from fixed seeds (moves, lines, joint
moves, grips, speeds, waits, poses, repeats, procedures, every job of the language
(``search`` included, on the search_002 scene) and mistakes; see
tests/script/check_run_scripts.py), each checked and then run on a fresh simulated arm.

Columns: the scripts that fail (check and run stopping at the same line for the same
reason), those that run to the end, how many agree; the disagreements by kind (the
line or the reason differs, the check's time is more than 1 % off the run's
simulated time, the check leaves a step's time to the run); the largest and median
time error of the scripts that run to the end [%]; and the wall time [s]. The first
few disagreeing seeds are listed under the table (rerun one alone with --seed).

Run: .venv/bin/python benchmarks/check_run.py [N scripts per arm, default 500]
         [--arm NAME] [--seed K]
"""

from __future__ import annotations

import argparse
import os
import sys
import tempfile
import time
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "tests" / "script"))

from check_run_compare import Outcome, check_and_run  # noqa: E402
from check_run_scripts import ARMS, generate  # noqa: E402

SHOWN = 5  # disagreeing seeds listed per arm


@dataclass
class Tally:
    """One arm's results."""

    arm: str
    outcomes: list[Outcome] = field(default_factory=list)
    wall_s: float = 0.0

    def count(self, kind: str) -> int:
        """How many outcomes are of ``kind`` (``Outcome.kind``)."""
        return sum(1 for o in self.outcomes if kind_of(o) == kind)

    def time_errors(self) -> list[float]:
        """The check's time error of each script that runs to the end [%]."""
        return [
            100.0 * abs(o.check_s - o.run_s) / max(o.run_s, 1e-9)
            for o in self.outcomes
            if o.run is None and o.check is None and o.check_s is not None
        ]

    def row(self) -> str:
        """The table row."""
        fails = sum(1 for o in self.outcomes if o.run is not None)
        errors = self.time_errors()
        worst = f"{max(errors):.2f}" if errors else "-"
        median = f"{float(np.median(errors)):.3f}" if errors else "-"
        return (
            f"{self.arm:<18} {len(self.outcomes):>7} {fails:>6} {len(self.outcomes) - fails:>5} "
            f"{self.count('agree'):>6} {self.count('verdict'):>8} {self.count('time'):>5} "
            f"{self.count('untimed'):>8} {worst:>8} {median:>9} {self.wall_s:>7.1f}"
        )


def kind_of(o: Outcome) -> str:
    """``agree``, ``verdict`` (line or reason), ``untimed`` or ``time``."""
    found = o.disagreement()
    if found is None:
        return "agree"
    if o.check != o.run:
        return "verdict"
    return "untimed" if o.check_s is None else "time"


def run_arm(arm: str, seeds: range) -> Tally:
    """Check and run every seed's script on ``arm`` (on any of its scenes)."""
    tally = Tally(arm)
    t0 = time.perf_counter()
    for seed in seeds:
        with tempfile.TemporaryDirectory() as folder:
            script = generate(arm, seed, search=None)
            tally.outcomes.append(check_and_run(script, Path(folder)))
    tally.wall_s = time.perf_counter() - t0
    return tally


def table(tallies: list[Tally]) -> str:
    """The results as text."""
    head = (
        f"{'arm':<18} {'scripts':>7} {'fail':>6} {'pass':>5} {'agree':>6} "
        f"{'verdict':>8} {'time':>5} {'untimed':>8} {'worst %':>8} {'median %':>9} {'wall s':>7}"
    )
    lines = [head, "-" * len(head), *(t.row() for t in tallies)]
    for t in tallies:
        bad = [o for o in t.outcomes if kind_of(o) != "agree"]
        for o in bad[:SHOWN]:
            lines.append(f"  {t.arm} seed {o.script.seed}: {o.disagreement()}"[:300])
    return "\n".join(lines)


def main() -> int:
    print(f"load average {' '.join(f'{v:.2f}' for v in os.getloadavg())} ({os.cpu_count()} cores)")
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("n", nargs="?", type=int, default=500, help="scripts per arm")
    parser.add_argument("--arm", choices=ARMS, action="append", help="only this arm")
    parser.add_argument("--seed", type=int, help="only this seed (prints its script)")
    args = parser.parse_args()
    arms = args.arm or list(ARMS)
    if args.seed is not None:
        for arm in arms:
            with tempfile.TemporaryDirectory() as folder:
                script = generate(arm, args.seed, search=None)
                print(check_and_run(script, Path(folder)).report())
        return 0
    print(f"check = run: {args.n} random scripts per arm, seeds 0..{args.n - 1}")
    tallies = [run_arm(arm, range(args.n)) for arm in arms]
    print(table(tallies))
    return 0 if all(t.count("agree") == len(t.outcomes) for t in tallies) else 1


if __name__ == "__main__":
    sys.exit(main())
