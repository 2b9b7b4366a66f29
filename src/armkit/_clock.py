"""The one notion of time every layer shares: real time for hardware, virtual
time for a simulator (whose ``sleep`` advances the simulation, so tests,
benchmarks and the demo run faster than real time and never wait)."""

from __future__ import annotations

import time
from typing import Any, Protocol, runtime_checkable


@runtime_checkable
class Clock(Protocol):
    """A monotonic clock [s] and a way to let time pass."""

    def now(self) -> float:
        """Current time [s] (the origin is arbitrary)."""
        ...

    def sleep(self, seconds: float) -> None:
        """Let ``seconds`` pass (no-op for seconds <= 0)."""
        ...


class WallClock:
    """Real time: ``time.monotonic`` and ``time.sleep``; what drivers of real hardware use."""

    def now(self) -> float:
        """Seconds since an arbitrary origin."""
        return time.monotonic()

    def sleep(self, seconds: float) -> None:
        """Block for ``seconds``."""
        if seconds > 0:
            time.sleep(seconds)


def clock_of(driver: Any) -> Clock:
    """The driver's own clock if it has one (simulators), else real time."""
    clock = getattr(driver, "clock", None)
    return clock if isinstance(clock, Clock) else WallClock()
