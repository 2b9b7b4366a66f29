"""A simulated Pololu Mini Maestro 24: its three serial protocols and its pulse outputs.

Pololu Maestro Servo Controller User's Guide, 5.c "Serial Protocols" and 5.e
"Serial Servo Commands" (``armkit.devices.maestro`` speaks it from the host side):

* compact protocol: a command byte (high bit set), then 7-bit data bytes;
* Pololu protocol: 0xAA, device number (``device_number``, factory 12), the
  command byte with its high bit cleared, the data; a packet for another device
  number is ignored;
* Mini SSC protocol: 0xFF, servo number (channel + ``mini_ssc_offset``), an
  8-bit target mapped to neutral +- range (factory 1500 +- 476.25 µs).

``commands`` is the table of command byte -> (data bytes, handler): Set Target
(0x84), Set Multiple Targets (0x9F: count, first channel, targets), Set Speed
(0x87), Set Acceleration (0x89), Get Position (0x90), Get Moving State (0x93),
Get Errors (0xA1), Go Home (0xA2). A byte that breaks the framing sets the
serial protocol error bit.

5.f "Serial Script Commands": Stop Script (0xA4), Restart Script at Subroutine
(0xA7, subroutine number), with Parameter (0xA8, subroutine, parameter low and
high 7 bits: 0..16383 pushed on the stack) and Get Script Status (0xAE: 0x00
running, 0x01 stopped). None of them touches the servos. The emulator runs no
script bytecode: the loaded script is ``script_subroutines`` subroutines (factory:
an empty script, none, and stopped), a started one runs until Stop Script (a
subroutine started by serial command loops forever or ends with QUIT, 5.f); a
subroutine the script does not define leaves the script stopped (logged in
``errors``; the guide names no error bit for it).

4.b "Channel Settings": each channel has a range (factory 992..2000 µs; a target
outside it is clamped, ``configure`` widens it) and a home setting (factory
"off"). On any error, and on Go Home, every channel goes to its home setting:
"off" stops its pulses, "ignore" leaves it, a pulse [µs] is a target. Speed
[0.25 µs/10 ms = 25 µs/s per unit] and acceleration [0.25 µs/10 ms/80 ms =
312.5 µs/s^2 per unit] limits ramp a servo's pulse (0 = no limit). Any baud rate
is accepted (the Maestro detects it).
"""

from __future__ import annotations

import threading
from collections import deque
from collections.abc import Callable

from ._outbox import Outbox, log
from ._pulses import MoveRecord, PulseOutputs, VirtualServo, ramped_move

PROTOCOL_ERROR = 1 << 4  # "serial protocol error" bit of the error field
SPEED_UNIT = 25.0  # [µs/s]
ACCEL_UNIT = 312.5  # [µs/s^2]
FACTORY_RANGE = (992.0, 2000.0)  # [µs]
POLOLU, MINI_SSC = 0xAA, 0xFF
Home = float | str  # a pulse [µs], "off" or "ignore"


class SimMaestro(PulseOutputs):
    """A Mini Maestro 24 (``channels`` outputs). Attributes as ``SimSSC32``'s, plus
    ``speed``/``acceleration`` (per channel, device units), ``ranges`` [µs], ``homes``
    and ``error_bits``."""

    name = "maestro"

    def __init__(self, channels: int = 24, device_number: int = 12) -> None:
        self.baudrate: int | None = None
        self.lock = threading.RLock()  # held while the host's bytes are handled
        self.device_number, self.mini_ssc_offset = device_number, 0
        self.servos = [VirtualServo() for _ in range(channels)]
        self.speed = [0] * channels  # units of 0.25 µs / 10 ms
        self.acceleration = [0] * channels
        self.ranges = [FACTORY_RANGE] * channels
        self.homes: list[Home] = ["off"] * channels
        self.outbox = Outbox()
        self.received: deque[bytes] = log()
        self.errors: deque[str] = log()
        self.history: deque[MoveRecord] = log()
        self.error_bits = 0
        self.script_subroutines = 0  # the loaded script's subroutines (factory: empty)
        self.script_running = False
        self.script_stack: list[int] = []
        self._packet = b""
        self.commands: dict[int, tuple[int, Callable[[bytes, float], None]]] = {
            0x84: (3, self._set_target),
            0x87: (3, self._set_speed),
            0x89: (3, self._set_acceleration),
            0x90: (1, self._get_position),
            0x93: (0, self._get_moving_state),
            0x9F: (-1, self._set_multiple_targets),  # 2 + 2 x count
            0xA1: (0, self._get_errors),
            0xA2: (0, self._go_home),
            0xA4: (0, self._stop_script),
            0xA7: (1, self._restart_script),
            0xA8: (3, self._restart_script),
            0xAE: (0, self._get_script_status),
        }

    def configure(self, channel: int, low_us: float, high_us: float, home: Home = "off") -> None:
        """Channel settings (the Control Center's): range [µs] and home setting."""
        self.ranges[channel], self.homes[channel] = (low_us, high_us), home

    def receive(self, data: bytes, now: float) -> None:
        """Bytes from the host at time ``now`` [s]: executed packet by packet."""
        for byte in data:
            if not self._packet:
                if byte & 0x80:
                    self._packet = bytes([byte])
                    self._dispatch_if_complete(now)
                else:
                    self._protocol_error(f"data byte {byte:#04x} without a command", now)
                continue
            lead = self._packet[0]
            if lead != MINI_SSC and byte & 0x80:  # a command byte inside a packet
                self._protocol_error(f"byte {byte:#04x} inside packet {self._packet!r}", now)
                self._packet = bytes([byte])
            else:
                self._packet += bytes([byte])
            self._dispatch_if_complete(now)

    def pulse(self, channel: int, now: float) -> float:
        """The pulse ``channel`` sends at ``now`` [µs] (0 = off)."""
        return self.servos[channel].pulse(now)

    def _dispatch_if_complete(self, now: float) -> None:
        packet = self._packet
        if packet[0] == MINI_SSC:
            if len(packet) == 3:
                self._packet = b""
                self.received.append(packet)
                self._mini_ssc(packet[1], packet[2], now)
            return
        pololu = packet[0] == POLOLU
        body = packet[2:] if pololu else packet
        if not body:
            return
        command = body[0] | 0x80
        entry = self.commands.get(command)
        if entry is None:
            self._protocol_error(f"unknown command {command:#04x}", now)
            return
        size, handler = entry
        if size < 0:
            size = 2 + 2 * body[1] if len(body) > 1 else 1 << 30
        if len(body) == 1 + size:
            self._packet = b""
            self.received.append(packet)
            if not pololu or packet[1] == self.device_number:
                handler(body[1:], now)

    def _protocol_error(self, what: str, now: float) -> None:
        self.errors.append(what)
        self.error_bits |= PROTOCOL_ERROR
        self._packet = b""
        self._go_home(b"", now)

    def _channel(self, number: int, now: float) -> int | None:
        if number >= len(self.servos):
            self._protocol_error(f"no channel {number}", now)
            return None
        return number

    def _target(self, ch: int, target: float, now: float) -> None:
        """Move ``ch`` toward ``target`` [µs] (0 = off), clamped to its range, ramped."""
        if target:
            low, high = self.ranges[ch]
            target = min(max(target, low), high)
        start = self.servos[ch].pulse(now)
        speed, accel = self.speed[ch] * SPEED_UNIT, self.acceleration[ch] * ACCEL_UNIT
        duration, ramp = ramped_move(target - start, speed, accel) if start and target else (0, 0)
        servo = self.go(ch, target, duration, now, ramp)
        self.history.append(MoveRecord(now, servo.duration_s, {ch: (start, target)}))

    def _set_target(self, data: bytes, now: float) -> None:
        ch = self._channel(data[0], now)
        if ch is not None:
            self._target(ch, (data[1] | data[2] << 7) / 4.0, now)

    def _set_multiple_targets(self, data: bytes, now: float) -> None:
        count, first = data[0], data[1]
        if first + count > len(self.servos):
            self._protocol_error(f"channels {first}..{first + count - 1} do not exist", now)
            return
        for k in range(count):
            low, high = data[2 + 2 * k], data[3 + 2 * k]
            self._target(first + k, (low | high << 7) / 4.0, now)

    def _mini_ssc(self, number: int, value: int, now: float) -> None:
        ch = number - self.mini_ssc_offset
        if not 0 <= ch < len(self.servos) or value > 254:
            return  # another device's servo number
        self._target(ch, 1500.0 + 476.25 * (value - 127) / 127, now)

    def _set_speed(self, data: bytes, now: float) -> None:
        ch = self._channel(data[0], now)
        if ch is not None:
            self.speed[ch] = data[1] | data[2] << 7

    def _set_acceleration(self, data: bytes, now: float) -> None:
        ch = self._channel(data[0], now)
        if ch is not None:
            self.acceleration[ch] = data[1] | data[2] << 7

    def _get_position(self, data: bytes, now: float) -> None:
        ch = self._channel(data[0], now)
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
        for ch, home in enumerate(self.homes):
            if home == "off":
                self.go(ch, 0.0, 0.0, now)
            elif home != "ignore":
                self._target(ch, float(home), now)

    def _stop_script(self, data: bytes, now: float) -> None:
        self.script_running = False

    def _restart_script(self, data: bytes, now: float) -> None:
        """Restart Script at Subroutine ``data[0]``, with the parameter ``data[1:]`` if given."""
        self.script_running, self.script_stack = False, []
        if data[0] >= self.script_subroutines:
            self.errors.append(f"no subroutine {data[0]}: the script has {self.script_subroutines}")
            return
        if len(data) == 3:
            self.script_stack = [data[1] | data[2] << 7]
        self.script_running = True

    def _get_script_status(self, data: bytes, now: float) -> None:
        self.outbox.send(b"\x00" if self.script_running else b"\x01", now)
