"""Tests that must have the machine to themselves while they run (marker ``alone``): under
pytest-xdist every other worker's tests wait for them, and they wait for the tests running.

The tests of ``armkit emulate`` under a deliberate CPU load (tests/emulate/) measure how an
emulator in its own process answers a client beside busy processes; another worker's test
beside them is load they did not plan. Every test takes a shared lock on a file of the
session's temporary folder (one for all workers), an ``alone`` test an exclusive one; a
turnstile lock keeps a waiting ``alone`` test from being overtaken forever."""

from __future__ import annotations

import fcntl
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path


@contextmanager
def _locked(path: Path, kind: int) -> Iterator[None]:
    with path.open("a") as f:
        fcntl.flock(f, kind)
        try:
            yield
        finally:
            fcntl.flock(f, fcntl.LOCK_UN)


@contextmanager
def turn(folder: Path, alone: bool) -> Iterator[None]:
    """Run the block beside other tests (``alone`` False) or with none (True)."""
    gate, room = folder / "armkit-alone.gate", folder / "armkit-alone.room"
    if alone:
        with _locked(gate, fcntl.LOCK_EX), _locked(room, fcntl.LOCK_EX):
            yield
        return
    with _locked(gate, fcntl.LOCK_EX):
        pass  # wait here while an alone test waits for the room
    with _locked(room, fcntl.LOCK_SH):
        yield
