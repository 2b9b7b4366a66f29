"""A Pololu Maestro on a pseudo-terminal: the real ``Maestro`` class talks to it by path.

It parses the compact binary protocol exactly (see ``armkit.devices.maestro``):
each command byte has its high bit set and is followed by a fixed number of
7-bit data bytes. A byte that breaks that rule sets the serial protocol error
bit and starts a new command, like the device. Servos ramp toward their targets
at their speed limit [25 µs/s per unit] in real time; the acceleration limit is
stored but not simulated. Fault injection as in ``PtyEmulator``.
"""

from __future__ import annotations

from collections.abc import Callable

from .ssc32_emulator import MoveRecord, PtyEmulator, VirtualServo

PROTOCOL_ERROR = 1 << 4  # "serial protocol error" bit of the error field


class MaestroEmulator(PtyEmulator):
    """A Mini Maestro 24. Any baud rate is accepted (the Maestro detects it)."""

    name = "maestro"

    def __init__(self, channels: int = 24, time_scale: float = 1.0) -> None:
        self.servos = [VirtualServo() for _ in range(channels)]
        self.speed = [0] * channels  # units of 0.25 µs / 10 ms
        self.acceleration = [0] * channels
        self.history: list[MoveRecord] = []
        self.error_bits = 0
        self._packet = b""
        # command byte -> (data bytes that follow, handler)
        self._commands: dict[int, tuple[int, Callable[[bytes, float], None]]] = {
            0x84: (3, self._set_target),
            0x87: (3, self._set_speed),
            0x89: (3, self._set_acceleration),
            0x90: (1, self._get_position),
            0x93: (0, self._get_moving_state),
            0xA1: (0, self._get_errors),
            0xA2: (0, self._go_home),
        }
        super().__init__(0, time_scale)

    def _baud_matches(self) -> bool:
        return True

    def _feed(self, data: bytes) -> None:
        for byte in data:
            if byte & 0x80 and self._packet:
                self._protocol_error(f"command {byte:#04x} inside packet {self._packet!r}")
            if not self._packet and not byte & 0x80:
                self._protocol_error(f"data byte {byte:#04x} without a command")
                continue
            self._packet += bytes([byte])
            self._dispatch_if_complete()

    def _dispatch_if_complete(self) -> None:
        entry = self._commands.get(self._packet[0])
        if entry is None:
            self._protocol_error(f"unknown command {self._packet[0]:#04x}")
            return
        size, handler = entry
        if len(self._packet) == 1 + size:
            packet, self._packet = self._packet, b""
            self.received.append(packet)
            handler(packet[1:], self.now())

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
        servo, target = self.servos[ch], (data[1] | data[2] << 7) / 4.0
        start = servo.pulse(now)
        rate = self.speed[ch] * 25.0
        duration = abs(target - start) / rate if rate and start and target else 0.0
        servo.go(target, duration, now)
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
            self._reply(quarter.to_bytes(2, "little"))

    def _get_moving_state(self, data: bytes, now: float) -> None:
        self._reply(b"\x01" if any(s.moving(now) for s in self.servos) else b"\x00")

    def _get_errors(self, data: bytes, now: float) -> None:
        self._reply(self.error_bits.to_bytes(2, "little"))
        self.error_bits = 0

    def _go_home(self, data: bytes, now: float) -> None:
        for servo in self.servos:
            servo.hold(now)
