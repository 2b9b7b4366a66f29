"""The terminal in cbreak mode, for commands that read single keys (OWI keys, the shell)."""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager
from typing import TextIO


@contextmanager
def cbreak(stdin: TextIO) -> Iterator[None]:
    """Keys arrive one at a time without echo (Ctrl-C still interrupts); the terminal's
    settings come back however the block is left. A stdin that is no terminal is left alone."""
    if not stdin.isatty():
        yield
        return
    import termios
    import tty

    fd = stdin.fileno()
    saved = termios.tcgetattr(fd)
    try:
        tty.setcbreak(fd)
        yield
    finally:
        termios.tcsetattr(fd, termios.TCSADRAIN, saved)
