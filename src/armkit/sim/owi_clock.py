"""A simulated clock: ``sleep`` advances time at once, so simulated OWI moves
of many seconds run in microseconds."""

from __future__ import annotations

import threading


class SimClock:
    """Simulated seconds, shared by the simulated device and the driver."""

    def __init__(self, start: float = 0.0) -> None:
        self._t = start
        self._lock = threading.Lock()

    def now(self) -> float:
        """Current simulated time [s]."""
        return self._t

    def sleep(self, seconds: float) -> None:
        """Advance the time by ``seconds`` [s] (negative = 0) without waiting."""
        with self._lock:
            self._t += max(0.0, seconds)
