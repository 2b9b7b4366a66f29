"""Every way out of a move stops the motors.

An OWI motor runs until it is told to stop, so the driver wraps each move in
``try/finally`` (exceptions, Ctrl-C) and, through :class:`ExitGuard`, also
stops at normal process exit (``atexit``) and on SIGTERM/SIGHUP (turned into
``SystemExit`` so the ``finally`` blocks run). :class:`Watchdog` is a thread
that stops the arm if a move overruns its plan, i.e. the program hung.
Only ``kill -9`` cannot be caught; the state file covers that case.
"""

from __future__ import annotations

import atexit
import contextlib
import signal
import threading
from collections.abc import Callable
from types import FrameType, TracebackType
from typing import Any

Stop = Callable[[], None]
_SIGNALS = tuple(getattr(signal, name) for name in ("SIGTERM", "SIGHUP") if hasattr(signal, name))


class Watchdog:
    """A thread that calls ``stop`` unless the move ends within ``timeout_s`` real seconds.

    Use as a context manager around one move; ``fired`` tells whether it stopped the arm.
    """

    def __init__(self, stop: Stop, timeout_s: float) -> None:
        self._stop, self.timeout_s = stop, timeout_s
        self._done = threading.Event()
        self._thread = threading.Thread(target=self._watch, name="owi535-watchdog", daemon=True)
        self.fired = False

    def __enter__(self) -> Watchdog:
        self._thread.start()
        return self

    def __exit__(
        self,
        exc_type: type[BaseException] | None,
        exc: BaseException | None,
        tb: TracebackType | None,
    ) -> None:
        self._done.set()
        self._thread.join()

    def _watch(self) -> None:
        if self._done.wait(self.timeout_s):
            return
        self.fired = True
        with contextlib.suppress(Exception):
            self._stop()


class ExitGuard:
    """Stop at process exit and on termination signals, for as long as it is installed."""

    def __init__(self, stop: Stop) -> None:
        self._stop = stop
        self._previous: dict[int, Any] = {}
        self._installed = False

    def install(self) -> None:
        """Register the atexit hook and, in the main thread, the signal handlers
        (only where no other handler was set)."""
        if self._installed:
            return
        atexit.register(self._at_exit)
        self._installed = True
        if threading.current_thread() is not threading.main_thread():
            return
        for sig in _SIGNALS:
            if signal.getsignal(sig) in (signal.SIG_DFL, None):
                self._previous[sig] = signal.signal(sig, _raise_exit)

    def uninstall(self) -> None:
        """Undo :meth:`install`. Safe to call twice."""
        if not self._installed:
            return
        atexit.unregister(self._at_exit)
        self._installed = False
        for sig, previous in self._previous.items():
            if signal.getsignal(sig) is _raise_exit:
                signal.signal(sig, previous)
        self._previous.clear()

    def _at_exit(self) -> None:
        with contextlib.suppress(Exception):
            self._stop()


def _raise_exit(signum: int, frame: FrameType | None) -> None:
    raise SystemExit(128 + signum)
