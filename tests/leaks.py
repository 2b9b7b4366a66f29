"""What one test may leave behind for the next, and the check that it left nothing
(``_no_leaks`` in tests/conftest.py): drivers still open, OWI exit guards still installed,
signal handlers changed, threads still running, ``os.environ`` changed, files in the
session's guard config folder. Each leak found is undone, so it fails only its own test."""

from __future__ import annotations

import contextlib
import gc
import os
import shutil
import signal
import threading
import time
import weakref
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

SIGNALS = tuple(
    getattr(signal, name) for name in ("SIGINT", "SIGTERM", "SIGHUP", "SIGTSTP") if hasattr(signal, name)
)  # fmt: skip
THREAD_GRACE_S = 2.0  # how long a thread the test started may take to end after it
OPEN: weakref.WeakSet[Any] = weakref.WeakSet()  # drivers opened and not yet closed
GUARDS: weakref.WeakSet[Any] = weakref.WeakSet()  # exit guards installed and not uninstalled


def _track(cls: type, opened: str, closed: str, into: weakref.WeakSet[Any]) -> None:
    """Wrap ``cls.opened`` to add the object to ``into`` and ``cls.closed`` to take it out."""
    open_, close = getattr(cls, opened), getattr(cls, closed)

    def opening(self: Any, *args: Any, **kwargs: Any) -> Any:
        result = open_(self, *args, **kwargs)
        into.add(self)
        return result

    def closing(self: Any, *args: Any, **kwargs: Any) -> Any:
        into.discard(self)
        return close(self, *args, **kwargs)

    setattr(cls, opened, opening)
    setattr(cls, closed, closing)


def track_drivers() -> None:
    """Count every driver of real hardware's kinds (they run on the simulated devices
    too) from its ``__init__`` to its ``close``, and every OWI exit guard from its
    ``install`` to its ``uninstall``."""
    from armkit.drivers.dynamixel import DynamixelDriver
    from armkit.drivers.servo._arm import ServoArmDriver
    from armkit.drivers.timed import TimedDriver
    from armkit.drivers.timed._safety import ExitGuard

    for cls in (TimedDriver, ServoArmDriver, DynamixelDriver):
        _track(cls, "__init__", "close", OPEN)
    _track(ExitGuard, "install", "uninstall", GUARDS)


def _environ() -> dict[str, str]:
    """``os.environ`` less pytest's own ``PYTEST_CURRENT_TEST``."""
    return {k: v for k, v in os.environ.items() if not k.startswith("PYTEST_")}


@dataclass
class Snapshot:
    """What is open, installed and running before a test."""

    drivers: set[int]
    guards: set[int]
    handlers: dict[int, Any]
    threads: set[threading.Thread]
    environ: dict[str, str]
    problems: list[str] = field(default_factory=list)

    @classmethod
    def take(cls) -> Snapshot:
        return cls(
            {id(d) for d in OPEN},
            {id(g) for g in GUARDS},
            {sig: signal.getsignal(sig) for sig in SIGNALS},
            set(threading.enumerate()),
            _environ(),
        )

    def leaks_since(self, guard: Path) -> list[str]:
        """What the test left behind (and now undone), in words."""
        self._guards()
        self._drivers()
        self._handlers()
        self._threads()
        self._environ()
        self._guard_folder(guard)
        return self.problems

    def _undo(self, what: str, undo: Callable[[], object]) -> None:
        self.problems.append(what)
        with contextlib.suppress(Exception):
            undo()

    def _drivers(self) -> None:
        if any(id(d) not in self.drivers for d in OPEN):
            gc.collect()  # a driver only a reference cycle holds (a kept traceback) is not kept
        for driver in [d for d in list(OPEN) if id(d) not in self.drivers]:
            self._undo(f"a driver left open: {type(driver).__name__} (close it)", driver.close)

    def _guards(self) -> None:
        for exit_guard in [g for g in list(GUARDS) if id(g) not in self.guards]:
            self._undo(
                "an OWI exit guard left installed (atexit hook and SIGTERM/SIGHUP handlers): "
                "close the TimedDriver",
                exit_guard.uninstall,
            )

    def _handlers(self) -> None:
        for sig, before in self.handlers.items():
            if signal.getsignal(sig) is not before:
                name = signal.Signals(sig).name
                self._undo(
                    f"the {name} handler changed to {signal.getsignal(sig)!r}",
                    lambda sig=sig, before=before: signal.signal(sig, before),
                )

    def _threads(self) -> None:
        deadline = time.monotonic() + THREAD_GRACE_S
        for thread in set(threading.enumerate()) - self.threads:
            thread.join(max(0.0, deadline - time.monotonic()))
            if thread.is_alive():
                self.problems.append(f"a thread still running: {thread.name} ({thread!r})")

    def _environ(self) -> None:
        now = _environ()
        if now == self.environ:
            return
        changed = sorted(
            k for k in now.keys() | self.environ.keys() if now.get(k) != self.environ.get(k)
        )

        def restore() -> None:
            for key in changed:
                if key in self.environ:
                    os.environ[key] = self.environ[key]
                else:
                    os.environ.pop(key, None)

        self._undo(f"os.environ changed: {', '.join(changed)} (use monkeypatch.setenv)", restore)

    def _guard_folder(self, guard: Path) -> None:
        written = sorted(p.name for p in guard.iterdir()) if guard.exists() else []
        if written:

            def clear() -> None:
                shutil.rmtree(guard)
                guard.mkdir()

            self._undo(
                f"wrote {', '.join(written)} into the session's config folder, outside its "
                "own (a thread or a process that outlived the test?)",
                clear,
            )
