"""A simulated Pololu Mini Maestro 24: the compact binary protocol and its pulse outputs.

Each command byte has its high bit set and is followed by a fixed number of
7-bit data bytes (Maestro User's Guide, "compact protocol";
``armkit.devices.maestro`` speaks it from the host side). ``COMMANDS`` is the
table of command byte -> (data bytes, handler). A byte that breaks the framing
sets the serial protocol error bit and starts a new command, like the device.
Servos ramp toward their targets at their speed limit [25 µs/s per unit]; the
acceleration limit is stored. Any baud rate is accepted (the Maestro detects it).

Known differences from the real controller (issue 11, point 5: the next step):
the Pololu (0xAA) and Mini SSC (0xFF) protocols, Set Multiple Targets (0x9F),
the factory 992..2000 µs channel range, home on error, and acceleration ramps.
"""

from __future__ import annotations

from collections import deque
from collections.abc import Callable

from ._outbox import Outbox, log
from ._pulses import MoveRecord, PulseOutputs, VirtualServo

PROTOCOL_ERROR = 1 << 4  # "serial protocol error" bit of the error field


class SimMaestro(PulseOutputs):
    """A Mini Maestro 24 (``channels`` outputs). Attributes as ``SimSSC32``'s, plus
    ``speed``/``acceleration`` (per channel, device units) and ``error_bits``."""

    name = "maestro"

    def __init__(self, channels: int = 24) -> None:
        self.baudrate: int | None = None
        self.servos = [VirtualServo() for _ in range(channels)]
        self.speed = [0] * channels  # units of 0.25 µs / 10 ms
        self.acceleration = [0] * channels
        self.outbox = Outbox()
        self.received: deque[bytes] = log()
        self.errors: deque[str] = log()
        self.history: deque[MoveRecord] = log()
        self.error_bits = 0
        self._packet = b""
        self.commands: dict[int, tuple[int, Callable[[bytes, float], None]]] = {
            0x84: (3, self._set_target),
            0x87: (3, self._set_speed),
            0x89: (3, self._set_acceleration),
            0x90: (1, self._get_position),
            0x93: (0, self._get_moving_state),
            0xA1: (0, self._get_errors),
            0xA2: (0, self._go_home),
        }

    def receive(self, data: bytes, now: float) -> None:
        """Bytes from the host at time ``now`` [s]: executed packet by packet."""
        for byte in data:
            if byte & 0x80 and self._packet:
                self._protocol_error(f"command {byte:#04x} inside packet {self._packet!r}")
            if not self._packet and not byte & 0x80:
                self._protocol_error(f"data byte {byte:#04x} without a command")
                continue
            self._packet += bytes([byte])
            self._dispatch_if_complete(now)

    def pulse(self, channel: int, now: float) -> float:
        """The pulse ``channel`` sends at ``now`` [µs] (0 = off)."""
        return self.servos[channel].pulse(now)

    def _dispatch_if_complete(self, now: float) -> None:
        entry = self.commands.get(self._packet[0])
        if entry is None:
            self._protocol_error(f"unknown command {self._packet[0]:#04x}")
            return
        size, handler = entry
        if len(self._packet) == 1 + size:
            packet, self._packet = self._packet, b""
            self.received.append(packet)
            handler(packet[1:], now)

    def _protocol_error(self, what: str) -> None:
        self.errors.append(what)
        self.error_bits |= PROTOCOL_ERROR
        self._packet = b""

    def _channel(self, data: bytes) -> int | None:
        if data[0] >= len(self.servos):
            self._protocol_error(f"no channel {data[0]}")
            return None
        return data[0]

    def _set_target(self, data: bytes, now: float) -> None:
        ch = self._channel(data)
        if ch is None:
            return
        target = (data[1] | data[2] << 7) / 4.0
        start = self.servos[ch].pulse(now)
        rate = self.speed[ch] * 25.0
        duration = abs(target - start) / rate if rate and start and target else 0.0
        servo = self.go(ch, target, duration, now)
        self.history.append(MoveRecord(now, servo.duration_s, {ch: (start, target)}))

    def _set_speed(self, data: bytes, now: float) -> None:
        ch = self._channel(data)
        if ch is not None:
            self.speed[ch] = data[1] | data[2] << 7

    def _set_acceleration(self, data: bytes, now: float) -> None:
        ch = self._channel(data)
        if ch is not None:
            self.acceleration[ch] = data[1] | data[2] << 7

    def _get_position(self, data: bytes, now: float) -> None:
        ch = self._channel(data)
        if ch is not None:
            quarter = round(self.servos[ch].pulse(now) * 4)
            self.outbox.send(quarter.to_bytes(2, "little"), now)

    def _get_moving_state(self, data: bytes, now: float) -> None:
        moving = any(s.moving(now) for s in self.servos)
        self.outbox.send(b"\x01" if moving else b"\x00", now)

    def _get_errors(self, data: bytes, now: float) -> None:
        self.outbox.send(self.error_bits.to_bytes(2, "little"), now)
        self.error_bits = 0

    def _go_home(self, data: bytes, now: float) -> None:
        for servo in self.servos:
            servo.hold(now)
