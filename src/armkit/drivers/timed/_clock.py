"""Where the timed driver gets its time: the real clock on hardware, a
simulated one on the simulator (so tests and benchmarks never wait)."""

from __future__ import annotations

import time
from typing import Protocol


class Clock(Protocol):
    """Seconds on a monotonic clock, and a way to let them pass."""

    def now(self) -> float:
        """Current time [s] (monotonic, arbitrary origin)."""
        ...

    def sleep(self, seconds: float) -> None:
        """Let ``seconds`` [s] pass."""
        ...


class RealClock:
    """The computer's monotonic clock."""

    def now(self) -> float:
        """``time.monotonic()`` [s]."""
        return time.monotonic()

    def sleep(self, seconds: float) -> None:
        """``time.sleep`` [s]; negative values sleep 0."""
        time.sleep(max(0.0, seconds))
