"""The fuzzers' worker process: runs cases through ``armkit.cli.main`` in-process and
reports, per step, what a user would have seen and whether anything moved.

Protocol: one JSON object per line on stdin (a case: its folder, files, steps), one
JSON object per line on the protocol pipe (the results). The parent (``fuzz_engine``)
kills this process when a case outlives its time bound and starts another, so a hang
in C code (a regular expression, an XML parser) is caught too. Memory is capped
(``RLIMIT_AS``) so a runaway allocation is a ``MemoryError`` here, not the machine's.

Run: python fuzz_worker.py PROTOCOL_FD
"""

from __future__ import annotations

import base64
import contextlib
import io
import json
import os
import re
import resource
import shutil
import signal
import sys
import time
import traceback
from pathlib import Path
from typing import Any

MEMORY_CAP = 4 << 30  # [bytes] address space of one worker
CPU_S = float(
    os.environ.get("ARMKIT_FUZZ_HANG_S") or 60
)  # [s] processor time of a step (the engine's)
SHORT_STEPS = 300  # a script checked with at most this many steps is also run when accepted
# What a user must never see: Python's own words for a crash, or a warning not armkit's.
LEAKS = re.compile(
    r"Traceback \(most recent call last\)|RecursionError|OverflowError|MemoryError"
    r"|Exceeds the limit|maximum recursion depth|(?<!armkit: )\b[A-Z]\w*Warning: "
    r"|Unable to allocate|object has no attribute|np\.float64"
)


ONE_LINE = re.compile(r"armkit: (error: \S.*|interrupted)$")


def _state(config: Path) -> dict[str, bytes]:
    """What the simulated arms keep between commands (their state files)."""
    if not config.exists():
        return {}
    return {
        str(p.relative_to(config)): p.read_bytes()
        for p in config.rglob("*")
        if p.is_file() and not p.name.endswith(".lock")
    }


def _listing(folder: Path) -> dict[str, int]:
    """The files of the case's folder and their sizes (its config folder and lock files
    left out: a port's lock lies beside it by design, see armkit._lock)."""
    return {
        str(p.relative_to(folder)): p.stat().st_size
        for p in folder.rglob("*")
        if p.is_file() and p.relative_to(folder).parts[0] != ".config" and p.suffix != ".lock"
    }


def _innermost(exc: BaseException) -> str:
    """``file:line`` of the innermost frame of ``exc`` inside armkit (else the last)."""
    frames = traceback.extract_tb(exc.__traceback__)
    ours = [f for f in frames if "/armkit/" in f.filename] or frames
    if not ours:
        return "?"
    f = ours[-1]
    return f"{f.filename.rpartition('/src/')[2] or f.filename}:{f.lineno}"


class Hang(BaseException):
    """The case used up its processor time (``CPU_S``): a hang."""


def _out_of_time(signum: int, frame: object) -> None:
    raise Hang


def _run_step(argv: list[str], stdin: bytes | None) -> dict[str, Any]:
    from armkit.cli import main

    out, err = io.StringIO(), io.StringIO()
    crash = hang = None
    saved_stdin = sys.stdin
    # as a pipe in a UTF-8 locale (strict decoding, not a terminal); empty if none given
    sys.stdin = io.TextIOWrapper(io.BytesIO(stdin or b""), encoding="utf-8")
    start = time.perf_counter()
    try:
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
            try:
                code = main(argv)
            except SystemExit as exc:
                code = exc.code if isinstance(exc.code, int) else 1
    except Hang as exc:
        code, hang = -1, f"more than {CPU_S:g} s of processor time ({_innermost(exc)})"
    except BaseException as exc:
        code = -1
        text = str(exc)
        crash = f"{type(exc).__name__}: {text[:300]} ({_innermost(exc)})"
    finally:
        sys.stdin = saved_stdin
    seconds = time.perf_counter() - start
    error = err.getvalue()
    leak = LEAKS.search(error)
    if crash is None and leak is not None:
        at = error[max(0, leak.start() - 200) : leak.end() + 300]
        crash = f"stderr shows {leak.group(0)!r}: {at!r}"
    if crash is None and code not in (0, 1, 2):
        crash = f"exit status {code}"
    last = error.strip().rpartition("\n")[2]
    if crash is None and code in (1, 2) and stdin is None and not ONE_LINE.match(last):
        crash = f"refused without an 'armkit: error:' line: {error[-300:]!r}"
    return {
        "code": code,
        "crash": crash,
        "hang": hang,
        "seconds": seconds,
        "stderr": error[-2000:],
        "stdout": out.getvalue()[-500:],
    }


def _short(checked: str) -> bool:
    """Whether ``armkit check`` said the script is a few steps, all checked."""
    m = re.search(r"(\d+) steps", checked)
    return m is not None and int(m.group(1)) <= SHORT_STEPS and "warning" not in checked


def _run_case(case: dict[str, Any]) -> dict[str, Any]:
    folder = Path(case["dir"])
    config = folder / ".config"
    shutil.rmtree(folder, ignore_errors=True)
    folder.mkdir(parents=True)
    for name, data in case["files"].items():
        path = folder / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_bytes(base64.b64decode(data))
    os.environ["ARMKIT_CONFIG_DIR"] = str(config)
    os.chdir(folder)
    steps: list[dict[str, Any]] = []
    last = 0
    try:
        for step in case["steps"]:
            when = step["when"]
            if (when == "refused" and last == 0) or (
                when != "refused" and when != "always" and last != 0
            ):
                continue
            if when == "short" and not _short(steps[-1]["stdout"]):
                continue
            before, files = _state(config), _listing(folder)
            stdin = base64.b64decode(step["stdin"]) if step.get("stdin") is not None else None
            signal.setitimer(signal.ITIMER_PROF, CPU_S)
            try:
                result = _run_step(step["argv"], stdin)
            finally:
                signal.setitimer(signal.ITIMER_PROF, 0)
            result["argv"] = step["argv"]
            if step["whole"] and result["code"] not in (0, -1):  # refused: nothing moved or written
                result["moved"] = _state(config) != before
                result["wrote"] = sorted(set(_listing(folder)) - set(files))
            steps.append(result)
            last = result["code"]
            if result["crash"] or result["hang"]:
                break
    finally:
        os.chdir("/")
        shutil.rmtree(folder, ignore_errors=True)
    return {"steps": steps}


def serve(cases: io.TextIOBase, channel: io.TextIOBase) -> None:
    """Answer the cases read from ``cases`` until it closes."""
    for line in cases:
        result = _run_case(json.loads(line))
        channel.write(json.dumps(result) + "\n")
        channel.flush()


def _start() -> tuple[io.TextIOBase, io.TextIOBase]:
    """The protocol's two ends (cases in on fd 0, results out on PROTOCOL_FD); then fd 0
    reads /dev/null and fd 1 and 2 write there (what C code or a child process does)."""
    cases = os.fdopen(os.dup(0), "r", encoding="utf-8")
    channel = os.fdopen(int(sys.argv[1]), "w", encoding="utf-8")
    devnull = os.open(os.devnull, os.O_RDWR)
    for fd in (0, 1, 2):
        os.dup2(devnull, fd)
    os.close(devnull)
    resource.setrlimit(resource.RLIMIT_AS, (MEMORY_CAP, MEMORY_CAP))
    signal.signal(signal.SIGPROF, _out_of_time)
    import armkit.cli  # noqa: F401 - once, before the first case

    return cases, channel


if __name__ == "__main__":
    serve(*_start())
