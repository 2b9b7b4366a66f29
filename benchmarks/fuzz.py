"""The input fuzzers' large budget: every input language armkit reads, 1,000 cases
each (by default), and how many crashed, hung or moved the arm before a refusal.

The cases and the verdicts are the suite's (tests/fuzz): case N of a language is the
same on every run, so a failure is found again by its number
(``--languages NAME --first N --cases 1``). Each case runs ``armkit`` in a worker
process on a fresh simulated arm; a step using more than ``--hang-s`` seconds of
processor time is a hang. The table (with each language's processor time: the cost of
the budget in .ci/run) is what docs/limits.md quotes; the exit status
is 1 if any case crashed, hung or moved the arm before a refusal.

Run: .venv/bin/python benchmarks/fuzz.py [--cases N] [--jobs J] [--languages NAME ...]
"""

from __future__ import annotations

import argparse
import os
import sys
import threading
import time
from collections import Counter
from collections.abc import Iterator
from pathlib import Path
from queue import Empty, Queue

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests" / "fuzz"))

from fuzz_engine import LARGE, Case, Outcome, run_cases
from fuzz_languages import LANGUAGES

COLUMNS = ("cases", "accepted", "refused", "crash", "hang", "moved")


def _work(jobs: Queue[tuple[str, int]], results: list[tuple[str, Outcome]], show: bool) -> None:
    """Run cases from ``jobs`` (made here, one at a time: some are megabytes) in one worker."""

    def cases() -> Iterator[Case]:
        while True:
            try:
                name, k = jobs.get_nowait()
            except Empty:
                return
            names.append(name)
            yield LANGUAGES[name].case(k)

    names: list[str] = []

    def done(outcome: Outcome) -> None:
        results.append((names[-1], outcome))
        if show and outcome.verdict in ("crash", "hang", "moved"):
            print(" ".join(str(outcome).split())[:400], flush=True)

    run_cases(cases(), on=done)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--cases", type=int, default=LARGE, help=f"per language (default {LARGE})")
    parser.add_argument("--first", type=int, default=0, help="number of the first case (default 0)")
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 1, help="worker processes")
    parser.add_argument("--languages", nargs="*", default=list(LANGUAGES), metavar="NAME")
    parser.add_argument("--hang-s", type=float, default=None, help="processor time of a step [s]")
    parser.add_argument("-q", "--quiet", action="store_true", help="do not print each failure")
    args = parser.parse_args()
    if args.hang_s is not None:
        os.environ["ARMKIT_FUZZ_HANG_S"] = str(args.hang_s)
    unknown = [n for n in args.languages if n not in LANGUAGES]
    if unknown:
        parser.error(f"unknown language(s) {unknown}; the languages are {list(LANGUAGES)}")
    jobs: Queue[tuple[str, int]] = Queue()
    for k in range(args.first, args.first + args.cases):  # interleaved: slow ones spread out
        for name in args.languages:
            jobs.put((name, k))
    results: list[tuple[str, Outcome]] = []
    start = time.perf_counter()
    threads = [
        threading.Thread(target=_work, args=(jobs, results, not args.quiet))
        for _ in range(max(1, args.jobs))
    ]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    _table(args.languages, results, time.perf_counter() - start)
    return int(any(o.verdict in ("crash", "hang", "moved") for _, o in results))


def _table(
    names: list[str], results: list[tuple[str, Outcome]], seconds: float, slow: int = 10
) -> None:
    heads = f"{'CPU [s]':>10}{'most [s]':>10}"
    print(f"\n{'language':<16}" + "".join(f"{c:>10}" for c in COLUMNS) + heads)
    for name in names:
        mine = [o for n, o in results if n == name]
        counts = Counter(o.verdict for o in mine)
        row = [len(mine), *(counts[c] for c in COLUMNS[1:])]
        cpu = sum(o.cpu for o in mine)
        most = max((o.cpu for o in mine), default=0.0)
        print(f"{name:<16}" + "".join(f"{v:>10}" for v in row) + f"{cpu:>10.0f}{most:>10.1f}")
    total = sum(o.cpu for _, o in results)
    print(
        f"\n{len(results)} cases in {seconds:.0f} s on {os.cpu_count()} cores "
        f"({total:.0f} s of processor time, load {os.getloadavg()[0]:.0f}); the most processor time:"
    )
    for outcome in sorted((o for _, o in results), key=lambda o: -o.cpu)[:slow]:
        print(f"  {outcome.cpu:6.1f} s  {outcome.case.label} ({outcome.verdict})")


if __name__ == "__main__":
    sys.exit(main())
