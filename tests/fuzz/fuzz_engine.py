"""The fuzzers' engine: cases, the worker process that runs them, and the verdicts.

A case is files (written into a fresh folder) and steps (command lines run there
in order, each on the same fresh simulated arm; a step may run only when the one
before it was refused or accepted). Cases run in a worker process
(``fuzz_worker.py``) that is killed and replaced when a case outlives its time
bound: that case is a hang. A case is a crash if an exception left ``main``, a
traceback or one of Python's own error words reached stderr, or the exit status
was not 0, 1 or 2; it moved if a refused step changed the simulated arm's kept
state or left a file behind.

Budgets (``budget()``): ``SMALL`` cases per language in ``make test``, ``LARGE`` under
``ARMKIT_PROFILE=ci`` (``.ci/run``) and in ``benchmarks/fuzz.py``; ``ARMKIT_FUZZ_BUDGET``
sets another. The time bound
is a hang detector, never a performance assertion: a step that uses more than
``ARMKIT_FUZZ_HANG_S`` (default ``HANG_S``) seconds of processor time is stopped in
the worker (so a busy machine does not make a hang); a case whose worker used
``CPU_FACTOR`` times that (a loop inside C code), or that is silent and idle after
``WALL_FACTOR`` times that of wall-clock time (waiting for what never comes), is
killed from here.
"""

from __future__ import annotations

import base64
import json
import os
import select
import shutil
import subprocess
import sys
import tempfile
import time
from collections.abc import Callable, Iterable, Iterator
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Literal

SMALL = 10  # cases per language in `make test`
LARGE = 1000  # cases per language in .ci/run and benchmarks/fuzz.py
HANG_S = (
    60.0  # [s] processor time of one step; more is a hang (a 20,000-stroke drawing plans in ~20 s)
)
WALL_FACTOR = 10  # a case silent for this many times HANG_S of wall-clock time is a hang
CPU_FACTOR = 4  # a worker using this many times HANG_S on one case (of <= 3 steps) is hung
POLL_S = 5.0  # [s] how often the worker's processor time is read while a case runs
IDLE_S = 0.05  # [s] processor time in POLL_S below which a silent worker is waiting
WORKER = Path(__file__).with_name("fuzz_worker.py")
ROOT = Path(__file__).resolve().parents[2]

When = Literal["always", "refused", "accepted", "short"]  # short: accepted, and few steps


def budget() -> int:
    """Cases per language: ``$ARMKIT_FUZZ_BUDGET`` if set, else ``LARGE`` under
    ``ARMKIT_PROFILE=ci`` (.ci/run; the suite's profiles, tests/budget.py) and ``SMALL``
    otherwise (``make test``)."""
    if os.environ.get("ARMKIT_FUZZ_BUDGET"):
        return int(os.environ["ARMKIT_FUZZ_BUDGET"])
    return LARGE if os.environ.get("ARMKIT_PROFILE") == "ci" else SMALL


def hang_s() -> float:
    """The time bound of one case [s]: ``$ARMKIT_FUZZ_HANG_S`` or ``HANG_S``."""
    return float(os.environ.get("ARMKIT_FUZZ_HANG_S") or HANG_S)


@dataclass(frozen=True)
class Step:
    """One command line (``armkit`` left out), its stdin, and when it runs; ``whole``:
    a refusal refuses the whole command, so nothing may have moved (not so for the
    shell, whose lines each run or fail on their own)."""

    argv: tuple[str, ...]
    when: When = "always"
    stdin: bytes | None = None
    whole: bool = True


@dataclass(frozen=True)
class Case:
    """Files and the steps run on them; ``label`` says how the case was made."""

    label: str
    files: dict[str, bytes]
    steps: tuple[Step, ...]

    def to_json(self, folder: Path) -> str:
        return json.dumps(
            {
                "dir": str(folder),
                "files": {k: base64.b64encode(v).decode() for k, v in self.files.items()},
                "steps": [
                    {
                        "argv": list(s.argv),
                        "when": s.when,
                        "stdin": None if s.stdin is None else base64.b64encode(s.stdin).decode(),
                        "whole": s.whole,
                    }
                    for s in self.steps
                ],
            }
        )


Verdict = Literal["accepted", "refused", "crash", "hang", "moved"]


@dataclass
class Outcome:
    """What one case did: its verdict, the worst step's detail, the time it took [s]."""

    case: Case
    verdict: Verdict
    detail: str = ""
    seconds: float = 0.0
    steps: list[dict[str, Any]] = field(default_factory=list)
    cpu: float = 0.0  # [s] processor time the worker used on it (0 where unknown)

    def __str__(self) -> str:
        shown = "; ".join(" ".join(s["argv"]) + f" -> {s['code']}" for s in self.steps)
        return f"[{self.verdict}] {self.case.label}: {self.detail} ({shown})"


def _verdict(case: Case, steps: list[dict[str, Any]], seconds: float) -> Outcome:
    for s in steps:
        if s.get("hang"):
            return Outcome(case, "hang", s["hang"], seconds, steps)
    for s in steps:
        if s["crash"]:
            return Outcome(case, "crash", s["crash"], seconds, steps)
    for s in steps:
        if s.get("moved") or s.get("wrote"):
            what = "moved the arm" if s.get("moved") else f"wrote {s['wrote']}"
            return Outcome(
                case, "moved", f"refused but {what}: {s['stderr'][-300:]}", seconds, steps
            )
    refused = any(s["code"] != 0 for s in steps)
    return Outcome(case, "refused" if refused else "accepted", "", seconds, steps)


class Worker:
    """One worker process, replaced when it hangs or dies."""

    def __init__(self, scratch: Path) -> None:
        self.scratch = scratch
        self.proc: subprocess.Popen[bytes] | None = None
        self.results: Any = None

    def _start(self) -> subprocess.Popen[bytes]:
        read_fd, write_fd = os.pipe()
        env = {
            **os.environ,
            "PYTHONHASHSEED": "0",
            "MPLBACKEND": "Agg",
            "ARMKIT_FUZZ_HANG_S": str(hang_s()),
        }
        proc = subprocess.Popen(
            [sys.executable, str(WORKER), str(write_fd)],
            stdin=subprocess.PIPE,
            pass_fds=(write_fd,),
            env=env,
            cwd=self.scratch,
        )
        os.close(write_fd)
        self.results = os.fdopen(read_fd, "rb")
        return proc

    def run(self, case: Case, timeout: float) -> Outcome:
        """Run ``case``; a hang if no answer within ``timeout`` [s]."""
        if self.proc is None:
            self.proc = self._start()
        assert self.proc.stdin is not None
        start, cpu = time.perf_counter(), _cpu_seconds(self.proc.pid)
        self.proc.stdin.write((case.to_json(self.scratch / "case") + "\n").encode())
        self.proc.stdin.flush()
        why = self._wait(timeout)
        seconds = time.perf_counter() - start
        used = _cpu_seconds(self.proc.pid)
        spent = used - cpu if used is not None and cpu is not None else 0.0
        if why:
            self.close()
            return Outcome(case, "hang", why, seconds, cpu=spent)
        line = self.results.readline()
        if not line:
            code = self.proc.wait()
            self.close()
            return Outcome(case, "crash", f"the process died (exit status {code})", seconds)
        outcome = _verdict(case, json.loads(line)["steps"], seconds)
        outcome.cpu = spent
        return outcome

    def _wait(self, timeout: float) -> str:
        """Wait for the answer: "" once it is there, else why the case is a hang. The
        worker stops a step at ``hang_s()`` of processor time itself; from here a case is
        a hang when the worker used ``CPU_FACTOR`` times that (a loop inside C code
        that the worker's timer cannot interrupt), or when it used no processor time for
        ``POLL_S`` after ``timeout`` seconds (it waits for something that never comes).
        A busy machine only makes a case slow, never a hang."""
        assert self.proc is not None
        start, used = time.perf_counter(), _cpu_seconds(self.proc.pid)
        last = used
        while True:
            ready, _, _ = select.select([self.results], [], [], POLL_S)
            if ready:
                return ""
            now = _cpu_seconds(self.proc.pid)
            waited = time.perf_counter() - start
            if now is None or used is None or last is None:  # no /proc: the clock decides
                if waited > timeout:
                    return f"no answer in {timeout:g} s"
                continue
            if now - used > CPU_FACTOR * hang_s():
                return f"{now - used:.0f} s of processor time and no answer"
            if waited > timeout and now - last < IDLE_S:
                return f"no answer in {waited:.0f} s, using no processor time"
            last = now

    def close(self) -> None:
        if self.proc is not None:
            if self.proc.poll() is None:
                self.proc.kill()
            self.proc.wait()
            if self.proc.stdin:
                self.proc.stdin.close()
            self.proc = None
        if self.results is not None:
            self.results.close()
            self.results = None


def _cpu_seconds(pid: int) -> float | None:
    """Processor time [s] process ``pid`` has used (Linux's /proc), or None."""
    try:
        stat = Path(f"/proc/{pid}/stat").read_text()
    except OSError:
        return None
    fields = stat.rpartition(")")[2].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


def run_cases(
    cases: Iterable[Case], timeout: float | None = None, on: Callable[[Outcome], None] | None = None
) -> list[Outcome]:
    """Every case's outcome, in one worker (``on`` is told of each as it ends)."""
    scratch = Path(tempfile.mkdtemp(prefix="armkit-fuzz-"))
    worker = Worker(scratch)
    outcomes = []
    try:
        for case in cases:
            outcome = worker.run(case, WALL_FACTOR * hang_s() if timeout is None else timeout)
            outcomes.append(outcome)
            if on is not None:
                on(outcome)
    finally:
        worker.close()
        shutil.rmtree(scratch, ignore_errors=True)
    return outcomes


def failures(outcomes: Iterable[Outcome]) -> Iterator[Outcome]:
    """The outcomes that break the contract (crash, hang, moved)."""
    return (o for o in outcomes if o.verdict in ("crash", "hang", "moved"))
