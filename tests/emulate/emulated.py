"""``armkit emulate`` as a separate process, and a CPU load beside it.

The Done-when of issue 27: the makers' clients (the official dynamixel-sdk, pyserial
with the raw bytes of the SSC-32U and Maestro guides) talk to ``armkit emulate`` in
another process while the machine's cores are busy. ``emulate`` starts the command
as a user would in a second terminal: its own session (so its own scheduling group
where the kernel groups by session, as a desktop's terminals are); ``cpu_load`` runs
``LOAD_PER_CORE`` busy processes per core in a session of their own (a build in a
third terminal). Both are ended by their process ids.
"""

from __future__ import annotations

import os
import signal
import subprocess
import sys
from collections.abc import Iterator
from contextlib import contextmanager

LOAD_PER_CORE = 2
SPIN = "while True: pass"


@contextmanager
def cpu_load(per_core: int = LOAD_PER_CORE) -> Iterator[int]:
    """``per_core`` x the cores' busy processes while the block runs; yields how many."""
    count = per_core * (os.cpu_count() or 1)
    hogs = [
        subprocess.Popen([sys.executable, "-c", SPIN], start_new_session=True) for _ in range(count)
    ]
    try:
        yield count
    finally:
        for hog in hogs:
            hog.kill()
        for hog in hogs:
            hog.wait()


@contextmanager
def emulate(*args: str) -> Iterator[tuple[str, list[str]]]:
    """``armkit emulate ARGS`` in its own process and session: yields (the pty's path,
    the lines it printed to stderr, filled in when it has stopped)."""
    process = subprocess.Popen(
        [sys.executable, "-m", "armkit.cli", "emulate", *args],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        start_new_session=True,
    )
    assert process.stdout is not None and process.stderr is not None
    path = process.stdout.readline().strip()
    stderr: list[str] = []
    try:
        assert path.startswith("/dev/"), process.stderr.read()
        yield path, stderr
    finally:
        process.send_signal(signal.SIGTERM)
        _, err = process.communicate(timeout=30)
        stderr.extend(err.splitlines())
