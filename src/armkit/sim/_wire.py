"""An in-process serial line from the host to a simulated byte device, timed by a world.

``Wire`` is the host's end: the methods armkit's serial code uses
(``write``, ``read``, ``read_until``, ``reset_input_buffer``, ``in_waiting``,
``timeout``, ``baudrate``, ``close``), with pyserial's meaning. Bytes written
reach the device at once, at the world's time; a read waits on the world's
clock for the reply to become due (so a lost reply costs the read timeout in
simulated time, as on a real line). A host at another baud rate than the
device's is not understood (the device sees nothing).

Where pyserial is installed, ``serial_port(wire)`` wraps the wire in a
``serial.SerialBase`` subclass, the pluggable level pyserial offers (its
``loop://`` and ``socket://`` ports are built the same way): the host's code
then runs through pyserial's own ``read_until``, settings and checks.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from ._outbox import ByteDevice
from ._world import World

POLL_S = 0.0005  # simulated time a non-blocking read that finds nothing costs [s]


class Wire:
    """The host's end of a serial line to ``device`` on ``world`` (see module doc).

    Args:
        baudrate: the host's rate [bit/s].  timeout: read timeout [s]; 0 = non-blocking;
            None = until a reply is due (never longer than what is queued).
    """

    def __init__(
        self, device: ByteDevice, world: World, *, baudrate: int, timeout: float | None = None
    ) -> None:
        self.device, self.world = device, world
        self.baudrate, self.timeout = baudrate, timeout
        self.port = f"sim://{device.name}"
        self.is_open = True
        self.misheard = 0  # bytes the device could not understand (wrong baud rate)
        self._on_close: list[Callable[[], None]] = []

    def on_close(self, action: Callable[[], None]) -> None:
        """Run ``action`` once when the host closes the line."""
        self._on_close.append(action)

    def write(self, data: bytes | bytearray | memoryview) -> int:
        """Send ``data``; returns its length."""
        raw = bytes(data)
        with self.world.lock:
            if self.device.baudrate is not None and self.device.baudrate != self.baudrate:
                self.misheard += len(raw)
            else:
                self.device.receive(raw, self.world.now())
        return len(raw)

    def read(self, size: int = 1) -> bytes:
        """Up to ``size`` bytes, waiting (in simulated time) as ``timeout`` says."""
        world, outbox = self.world, self.device.outbox
        got = bytearray()
        with world.lock:
            start = world.now()
        deadline = None if self.timeout is None else start + self.timeout
        while True:
            with world.lock:
                now = world.now()
                got += outbox.take(now, size - len(got))
                due = outbox.next_due()
            if len(got) >= size:
                return bytes(got)
            if deadline is not None and now >= deadline - 1e-12:
                if self.timeout == 0 and not got:
                    world.advance(POLL_S)  # a busy host's poll takes time too
                return bytes(got)
            wake = deadline if due is None else due if deadline is None else min(due, deadline)
            if wake is None:
                return bytes(got)
            world.advance(max(wake - now, world.dt))

    def read_until(self, expected: bytes = b"\n", size: int | None = None) -> bytes:
        """Bytes up to and including ``expected`` (or ``size`` of them), or what came in time."""
        line = bytearray()
        while size is None or len(line) < size:
            byte = self.read(1)
            if not byte:
                break
            line += byte
            if line.endswith(expected):
                break
        return bytes(line)

    @property
    def in_waiting(self) -> int:
        """Bytes readable now."""
        with self.world.lock:
            return self.device.outbox.waiting(self.world.now())

    def reset_input_buffer(self) -> None:
        """Drop what has arrived (replies still in flight arrive later)."""
        with self.world.lock:
            self.device.outbox.drop_due(self.world.now())

    def reset_output_buffer(self) -> None:
        """Nothing waits to be sent: writes reach the device at once."""

    def flush(self) -> None:
        """Nothing waits to be sent."""

    def close(self) -> None:
        """Close the line (the close actions run once)."""
        if not self.is_open:
            return
        self.is_open = False
        actions, self._on_close = self._on_close, []
        for action in actions:
            action()


def serial_port(wire: Wire) -> Any:
    """``wire`` as a pyserial port (``serial.SerialBase``) where pyserial is installed;
    else the wire itself (it has the same methods)."""
    try:
        from ._serial_port import SimSerial
    except ModuleNotFoundError:
        return wire
    return SimSerial(wire)
