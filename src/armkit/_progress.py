"""How far a long job has got, on stderr: ``drawing: 12/62 strokes, 9 s``.

Anything that takes more than a second shows its progress: on a terminal one line
rewritten in place (at most ``REDRAW`` times a second), else (a pipe, a log) a line
every ``EVERY`` seconds. A job done within ``SHOW_AFTER`` seconds shows nothing; one
that showed anything ends with its final count. The seconds are the wall clock's,
whatever clock the job runs on.
"""

from __future__ import annotations

import re
import sys
import time
from types import TracebackType
from typing import TextIO

SHOW_AFTER = 1.0  # [s] a job quicker than this shows no progress
EVERY = 5.0  # [s] between lines when stderr is no terminal
REDRAW = 0.1  # [s] between rewrites of the line on a terminal
LINE = re.compile(r"^\S[^:]*: \d+/\d+ \S+(, .*)?, \d+ s$")  # a progress line, as written


class Progress:
    """Progress of ``total`` ``unit`` (``"strokes"``) of the job ``what`` (``"drawing"``),
    written to ``stream`` (default: stderr). ``update(done)`` as the job goes,
    ``close()`` (or the end of a ``with`` block) when it stops, however it stops."""

    def __init__(self, what: str, total: int, unit: str, *, stream: TextIO | None = None):
        self.what, self.total, self.unit = what, total, unit
        self.stream = sys.stderr if stream is None else stream
        self.tty = _isatty(self.stream)
        self.done = 0
        self.detail = ""
        self._start = _now()
        self._shown: float | None = None  # when the last line was written
        self._last = ""  # the last line written
        self._open = False  # a terminal line is waiting for its newline

    def update(self, done: int, detail: str = "") -> None:
        """``done`` of the total so far; ``detail``: what is under way (``"method ccd"``)."""
        self.done, self.detail = done, detail
        now = _now()
        if now - self._start < SHOW_AFTER:
            return
        wait = REDRAW if self.tty else EVERY
        if self._shown is None or now - self._shown >= wait:
            self._write(now)

    def close(self) -> None:
        """End the progress: the final count if any progress was shown (then the line ends)."""
        if self._shown is not None and self.line() != self._last:
            self._write(_now())
        if self._open:
            self.stream.write("\n")
            self.stream.flush()
            self._open = False

    def line(self) -> str:
        """``drawing: 12/62 strokes, method ccd, 9 s``."""
        detail = f", {self.detail}" if self.detail else ""
        seconds = _now() - self._start
        return f"{self.what}: {self.done}/{self.total} {self.unit}{detail}, {seconds:.0f} s"

    def _write(self, now: float) -> None:
        text = self.line()
        self._shown, self._last = now, text
        if self.tty:
            self.stream.write(f"\r{text}\x1b[K")
            self._open = True
        else:
            self.stream.write(text + "\n")
        self.stream.flush()

    def __enter__(self) -> Progress:
        return self

    def __exit__(
        self,
        kind: type[BaseException] | None,
        exc: BaseException | None,
        tb: TracebackType | None,
    ) -> None:
        self.close()


def _now() -> float:
    """The wall clock [s] (``time.monotonic``)."""
    return time.monotonic()


def _isatty(stream: TextIO) -> bool:
    try:
        return stream.isatty()
    except (AttributeError, ValueError):  # a closed or odd stream: no terminal
        return False
