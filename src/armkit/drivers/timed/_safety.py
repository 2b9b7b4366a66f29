"""Every way out of a move stops the motors.

An OWI motor runs until it is told to stop, so the driver wraps each move in
``try/finally`` (exceptions, Ctrl-C) and, through :class:`ExitGuard`, also
stops at normal process exit (``atexit``) and on SIGTERM/SIGHUP (turned into
``SystemExit`` so the ``finally`` blocks run). :class:`Watchdog` is a thread
that stops the arm if a move overruns its plan, i.e. the program hung.
Only ``kill -9`` cannot be caught; the state file covers that case.

:class:`SignalGate` makes the bookkeeping around a move (state saved, motors
started, motors stopped, state saved) safe against a signal at any instant:
during a move, Ctrl-C, SIGTERM, SIGHUP and Ctrl-Z (SIGTSTP) only cut short the
waits; anywhere else they are held until the state is on disk.
"""

from __future__ import annotations

import atexit
import contextlib
import os
import signal
import threading
from collections.abc import Callable
from types import FrameType, TracebackType
from typing import Any

Stop = Callable[[], None]
_SIGNALS = tuple(getattr(signal, name) for name in ("SIGTERM", "SIGHUP") if hasattr(signal, name))
_GATED = tuple(
    getattr(signal, name) for name in ("SIGINT", "SIGTERM", "SIGHUP", "SIGTSTP") if hasattr(signal, name)
)  # fmt: skip


class Watchdog:
    """A thread that calls ``stop`` unless the move ends within ``timeout_s`` real seconds.

    Use as a context manager around one move; ``fired`` tells whether it stopped the arm.
    """

    def __init__(self, stop: Stop, timeout_s: float) -> None:
        self._stop, self.timeout_s = stop, timeout_s
        self._done = threading.Event()
        self._thread = threading.Thread(target=self._watch, name="owi535-watchdog", daemon=True)
        self.fired = False  # set before stop is sent, so the mover sees it at once

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


class Interrupted(BaseException):
    """A signal cut a move's wait short (raised only inside :meth:`SignalGate.pause`)."""

    def __init__(self, signum: int) -> None:
        super().__init__(f"signal {signum}")
        self.signum = signum


class Suspended(Exception):
    """The move was stopped because the program was suspended (Ctrl-Z)."""


class SignalGate:
    """Hold Ctrl-C, SIGTERM, SIGHUP and Ctrl-Z while a move's state is written and its
    motors are started or stopped; let them cut short only the waits run through
    :meth:`pause` / :meth:`wait`.

    On leaving, the first signal is delivered as the program expects: its previous
    handler runs (Ctrl-C: KeyboardInterrupt; SIGTERM under ExitGuard: SystemExit),
    or, for Ctrl-Z, the process suspends now that the motors are stopped; when it is
    resumed a move cut short raises :class:`Suspended`. Outside the main thread
    (where Python cannot handle signals) it only waits.
    """

    def __init__(self) -> None:
        self.signum: int | None = None
        self._open = False
        self._previous: dict[int, Any] = {}

    def __enter__(self) -> SignalGate:
        if threading.current_thread() is threading.main_thread():
            for sig in _GATED:
                previous = signal.getsignal(sig)
                if previous is not signal.SIG_IGN and previous is not None:
                    self._previous[sig] = signal.signal(sig, self._handle)
        return self

    def _handle(self, signum: int, frame: FrameType | None) -> None:
        if self.signum is None:
            self.signum = signum
        if self._open:
            self._open = False
            raise Interrupted(signum)

    def check(self) -> None:
        """Raise :class:`Interrupted` if a signal came while the gate was shut."""
        if self.signum is not None:
            raise Interrupted(self.signum)

    def pause(self, sleep: Callable[[float], None], seconds: float) -> None:
        """``sleep(seconds)``, cut short by a signal (:class:`Interrupted`)."""
        self.wait(lambda: sleep(seconds))

    def wait(self, block: Callable[[], object]) -> None:
        """Run ``block`` (a wait), cut short by a signal (:class:`Interrupted`)."""
        self.check()
        self._open = True
        try:
            block()
        finally:
            self._open = False

    def __exit__(
        self,
        exc_type: type[BaseException] | None,
        exc: BaseException | None,
        tb: TracebackType | None,
    ) -> None:
        for sig, previous in self._previous.items():
            signal.signal(sig, previous)
        if self.signum is None:
            return
        cut = isinstance(exc, Interrupted)
        if self.signum == getattr(signal, "SIGTSTP", None):
            _suspend(self._previous.get(self.signum, signal.SIG_DFL))
            if cut:
                raise Suspended(
                    "the move was stopped when the program was suspended (Ctrl-Z); the arm "
                    "is where it stopped: run the command again to finish it"
                ) from None
            return
        _deliver(self.signum, self._previous.get(self.signum, signal.SIG_DFL))
        if cut:  # a handler that did not raise: the move still ended early
            raise Suspended(f"the move was stopped by signal {self.signum}") from None


def _deliver(signum: int, previous: Any) -> None:
    """Do what the program had set up for ``signum``, now that the move is safe."""
    if callable(previous):
        previous(signum, None)
    elif signum == signal.SIGINT:
        raise KeyboardInterrupt
    elif previous == signal.SIG_DFL:
        raise SystemExit(128 + signum)


def _suspend(previous: Any) -> None:
    """Suspend the process (the shell's Ctrl-Z), returning when it is resumed."""
    if callable(previous):
        previous(signal.SIGTSTP, None)
        return
    os.kill(os.getpid(), signal.SIGSTOP)
