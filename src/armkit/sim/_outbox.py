"""What a simulated serial device has said and when the host can read it, with faults.

Every simulated byte device (SSC-32, Maestro, Dynamixel bus) answers into an
``Outbox``: bytes become readable at a due time of the device's clock. Faults
injected with ``inject`` spoil the next replies as a flaky line or a confused
board would: ``"drop"`` (never sent), ``"late"`` (sent ``delay_s`` late) or
``"garbage"`` (every byte replaced by 0xFF).
"""

from __future__ import annotations

import heapq
import threading
from collections import deque
from typing import Any, Protocol

FAULTS = ("drop", "late", "garbage")
LOG_ROWS = 10_000  # a device keeps its last this many commands for inspection (bounded memory)


def log() -> deque[Any]:
    """A bounded log of what a device received or did (the oldest entries go)."""
    return deque(maxlen=LOG_ROWS)


class ByteDevice(Protocol):
    """A simulated device on a serial line, as a wire or a pty server drives it.

    ``lock`` is held while the host's bytes are handled and replies taken; a simulation
    step never takes it (the device's outputs are read without it: ``_servo_body``),
    so the device answers its host whatever the world's thread is doing."""

    name: str
    lock: threading.RLock
    baudrate: int | None  # the rate it listens at; None: it detects the host's (Maestro)
    outbox: Outbox

    def receive(self, data: bytes, now: float) -> None:
        """Bytes from the host at device time ``now`` [s]; replies go to ``outbox``."""
        ...


def deliver(device: ByteDevice, data: bytes, now: float, baudrate: int | None) -> bool:
    """Bytes from a host at ``baudrate`` [bit/s] (None: unknown) to ``device`` at ``now`` [s].

    A device with a ``hear(data, now, baudrate)`` method sorts the rate out itself (a
    Dynamixel bus: each servo has its own); any other hears only at its ``baudrate``
    (None: any). Returns False when the bytes were noise to the device.
    """
    hear = getattr(device, "hear", None)
    if hear is not None:
        return bool(hear(data, now, baudrate))
    if device.baudrate is not None and device.baudrate != baudrate:
        return False
    device.receive(data, now)
    return True


class Outbox:
    """Replies waiting to be read: (due time [s], bytes), in order of due time."""

    def __init__(self) -> None:
        self._queue: list[tuple[float, int, bytes]] = []
        self._count = 0
        self._faults: deque[tuple[str, float]] = deque()

    def inject(self, fault: str, count: int = 1, delay_s: float = 0.15) -> None:
        """Spoil the next ``count`` replies with ``fault`` (one of ``FAULTS``)."""
        if fault not in FAULTS:
            raise ValueError(f"unknown fault {fault!r}; faults are {', '.join(FAULTS)}")
        self._faults.extend([(fault, delay_s)] * count)

    def send(self, data: bytes, now: float, delay_s: float = 0.0) -> None:
        """Queue ``data`` as readable from ``now + delay_s`` [s], unless a fault spoils it."""
        fault, fault_delay = self._faults.popleft() if self._faults else ("", 0.0)
        if fault == "drop":
            return
        if fault == "garbage":
            data = b"\xff" * len(data)
        due = now + delay_s + (fault_delay if fault == "late" else 0.0)
        heapq.heappush(self._queue, (due, self._count, data))
        self._count += 1

    def take(self, now: float, size: int | None = None) -> bytes:
        """Up to ``size`` bytes (None: all) that are due by ``now``; the rest stay queued."""
        out = bytearray()
        while self._queue and self._queue[0][0] <= now and (size is None or len(out) < size):
            due, k, data = heapq.heappop(self._queue)
            room = len(data) if size is None else size - len(out)
            out += data[:room]
            if room < len(data):
                heapq.heappush(self._queue, (due, k, data[room:]))
        return bytes(out)

    def waiting(self, now: float) -> int:
        """How many bytes are readable at ``now``."""
        return sum(len(data) for due, _, data in self._queue if due <= now)

    def next_due(self) -> float | None:
        """When the next reply becomes readable [s], or None."""
        return self._queue[0][0] if self._queue else None

    def drop_due(self, now: float) -> None:
        """Discard what has arrived by ``now`` (the host flushed its input buffer)."""
        self.take(now)
