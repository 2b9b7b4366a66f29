"""The terminal: cbreak mode for commands that read single keys (OWI keys, the shell),
and the words and numbers printed to it (``count(1, "step")``, ``fixed(-0.001)``)."""

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


def count(n: int, noun: str, many: str | None = None) -> str:
    """``"1 step"``, ``"3 steps"``, ``"0 steps"``; ``many`` where adding 's' is wrong."""
    return f"{n} {noun if n == 1 else many or noun + 's'}"


def fixed(value: float, digits: int = 2) -> str:
    """``value`` with ``digits`` decimals, never ``-0.00`` (a tiny negative prints as 0)."""
    return f"{round(float(value), digits) + 0.0:.{digits}f}"
