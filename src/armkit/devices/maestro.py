"""Pololu Maestro servo controller: the compact binary protocol on a serial port.

Commands (Pololu Maestro user's guide, "compact protocol"); data bytes carry 7 bits:

    0x84 ch lo hi   set target, quarter-µs (lo = value & 0x7F, hi = value >> 7); 0 = off
    0x87 ch lo hi   set speed limit, 0.25 µs per 10 ms (= 25 µs/s per unit); 0 = none
    0x89 ch lo hi   set acceleration limit, 0.25 µs per 10 ms per 80 ms; 0 = none
    0x90 ch         get position -> 2 bytes, little-endian, quarter-µs
    0x93            get moving state -> 1 byte, 0 = done, 1 = moving
    0xA1            get errors -> 2 bytes, little-endian bit field (cleared by reading)

The Maestro has no feedback: "position" is the pulse it is sending, ramped by
the speed and acceleration limits. pyserial is imported only when a port opens.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping

from .._clock import Clock, WallClock
from .._errors import DeviceError, InputError, ReplyError
from ._serial import SerialLink, SerialPort
from .ssc32 import PULSE_MAX_US, PULSE_MIN_US, check_channel

SET_TARGET = 0x84
SET_SPEED = 0x87
SET_ACCELERATION = 0x89
GET_POSITION = 0x90
GET_MOVING_STATE = 0x93
GET_ERRORS = 0xA1
CHANNELS = range(24)  # Mini Maestro 24; the Micro Maestro has 6
SPEED_UNIT_US_PER_S = 25.0  # one speed unit: 0.25 µs per 10 ms
ACCEL_UNIT_US_PER_S2 = 312.5  # one acceleration unit: 0.25 µs per 10 ms per 80 ms
ACCEL_MAX = 255  # largest acceleration limit (User's Guide, "Set Acceleration")
LIMIT_MAX = 0x3FFF  # largest 14-bit value a data pair can carry


def _seven_bit_pair(value: int) -> bytes:
    return bytes([value & 0x7F, (value >> 7) & 0x7F])


def _check_limit(name: str, channel: int, value: int) -> None:
    if not isinstance(value, int) or not 0 <= value <= LIMIT_MAX:
        raise InputError(f"{name} {value!r} on channel {channel} is outside 0..{LIMIT_MAX}")


def target_bytes(channel: int, pulse_us: float) -> bytes:
    """``0x84 ch lo hi``: move ``channel`` to ``pulse_us`` [µs, 500..2500, 0.25 µs steps]."""
    check_channel(channel, CHANNELS)
    if not isinstance(pulse_us, int | float) or not PULSE_MIN_US <= pulse_us <= PULSE_MAX_US:
        raise InputError(
            f"pulse {pulse_us!r} µs on channel {channel} is outside "
            f"{PULSE_MIN_US}..{PULSE_MAX_US} µs; give a pulse in that range"
        )
    return bytes([SET_TARGET, channel]) + _seven_bit_pair(round(pulse_us * 4))


def speed_bytes(channel: int, units: int) -> bytes:
    """``0x87 ch lo hi``: speed limit in units of 25 µs/s (0 = unlimited)."""
    check_channel(channel, CHANNELS)
    _check_limit("speed", channel, units)
    return bytes([SET_SPEED, channel]) + _seven_bit_pair(units)


def acceleration_bytes(channel: int, units: int) -> bytes:
    """``0x89 ch lo hi``: acceleration limit (0 = unlimited)."""
    check_channel(channel, CHANNELS)
    _check_limit("acceleration", channel, units)
    return bytes([SET_ACCELERATION, channel]) + _seven_bit_pair(units)


def position_query_bytes(channel: int) -> bytes:
    """``0x90 ch``: ask for the pulse ``channel`` is sending (reply: 2 bytes LE, quarter-µs)."""
    check_channel(channel, CHANNELS)
    return bytes([GET_POSITION, channel])


def parse_position(reply: bytes) -> float:
    """Pulse [µs] (0 = off) from a 2-byte position reply; ValueError if impossible."""
    if len(reply) != 2:
        raise ReplyError(f"position reply has {len(reply)} bytes, expected 2")
    quarter = int.from_bytes(reply, "little")
    if quarter > LIMIT_MAX:
        raise ReplyError(f"position {quarter} quarter-µs is beyond {LIMIT_MAX}")
    return quarter / 4.0


def parse_moving(reply: bytes) -> bool:
    """True while moving, from the 1-byte moving-state reply; ValueError if not 0 or 1."""
    if reply not in (b"\x00", b"\x01"):
        raise ReplyError(f"moving-state reply {reply!r} is not 0 or 1")
    return reply == b"\x01"


def speed_units(delta_us: float, time_s: float) -> int:
    """The speed limit [units of 25 µs/s] that covers ``delta_us`` in at most ``time_s``
    (rounded up; at least 1, since 0 would mean unlimited)."""
    return max(1, math.ceil(abs(delta_us) / time_s / SPEED_UNIT_US_PER_S - 1e-9))


def ramped_time(delta_us: float, speed: float, accel: float) -> float:
    """How long the Maestro takes for ``delta_us`` [µs] at speed limit ``speed`` [µs/s]
    and acceleration limit ``accel`` [µs/s^2] (0 = none): it ramps up, cruises, ramps down."""
    d = abs(delta_us)
    if accel <= 0:
        return d / speed
    if d < speed * speed / accel:
        return 2.0 * math.sqrt(d / accel)
    return d / speed + speed / accel


def motion_limits(delta_us: float, time_s: float) -> tuple[int, int]:
    """(speed units, acceleration units) that take ``delta_us`` [µs] in the time closest
    to ``time_s`` [s] the Maestro's units allow, never shorter (never faster on average).

    A speed of 1.6 units rounded to 1 would take 1.6 x as long; rounded to 2 with an
    acceleration limit, its ramps take up the time the rounding gained: the search
    is over both roundings of the speed and every acceleration limit (0 = none).
    """
    exact = abs(delta_us) / time_s / SPEED_UNIT_US_PER_S
    options = [
        (
            ramped_time(delta_us, speed * SPEED_UNIT_US_PER_S, accel * ACCEL_UNIT_US_PER_S2),
            speed,
            accel,
        )
        for speed in {max(1, math.floor(exact)), max(1, math.ceil(exact - 1e-9))}
        for accel in _accel_candidates(abs(delta_us), speed * SPEED_UNIT_US_PER_S, time_s)
    ]
    late = [option for option in options if option[0] >= time_s * (1 - 1e-9)]
    _, speed, accel = min(late) if late else max(options)  # below one unit: the slowest
    return speed, accel


def _accel_candidates(d: float, v: float, time_s: float) -> set[int]:
    """Acceleration limits [units] around the exact one that makes ``d`` [µs] at speed
    limit ``v`` [µs/s] last ``time_s`` [s] (trapezoid: d/v + v/a; triangle: 2 sqrt(d/a)),
    plus none (0) and the extremes."""
    exact = []
    if time_s > d / v:
        exact.append(v / (time_s - d / v) / ACCEL_UNIT_US_PER_S2)
    exact.append(4.0 * d / (time_s * time_s) / ACCEL_UNIT_US_PER_S2)
    found = {0, 1, ACCEL_MAX}
    for a in exact:
        found |= {min(ACCEL_MAX, max(1, math.floor(a))), min(ACCEL_MAX, max(1, math.ceil(a)))}
    return found


class Maestro:
    """A Pololu Maestro on a serial port (its USB command port, or TTL at ``baudrate``).

    Args:
        port: serial device path, an emulator's ``.port``, or an open ``SerialPort``.
        baudrate: for the TTL port (the Maestro detects it); ignored over USB.
        timeout_s: how long to wait for a reply [s].  retries: extra tries per query.
        clock: time for waiting (real time by default; a simulation's clock).
    """

    def __init__(
        self,
        port: str | SerialPort,
        baudrate: int = 9600,
        *,
        timeout_s: float = 0.1,
        retries: int = 2,
        clock: Clock | None = None,
    ) -> None:
        self.clock = clock or WallClock()
        self._link = SerialLink("Maestro", port, baudrate, timeout_s, retries, self.clock)

    @property
    def port(self) -> str:
        """The serial port's path."""
        return self._link.port

    def set_target(self, channel: int, pulse_us: float) -> None:
        """Move ``channel`` to ``pulse_us`` [µs] at its present speed limit."""
        self._link.write(target_bytes(channel, pulse_us))

    def set_speed(self, channel: int, units: int) -> None:
        """Speed limit of ``channel`` [units of 25 µs/s]; 0 = unlimited."""
        self._link.write(speed_bytes(channel, units))

    def set_acceleration(self, channel: int, units: int) -> None:
        """Acceleration limit of ``channel``; 0 = unlimited."""
        self._link.write(acceleration_bytes(channel, units))

    def get_position(self, channel: int) -> float:
        """The pulse ``channel`` is sending now [µs]; 0 = off."""
        what = f"position of channel {channel}"
        return self._link.exchange(position_query_bytes(channel), 2, parse_position, what)

    def is_moving(self) -> bool:
        """True while any servo is still ramping toward its target."""
        return self._link.exchange(bytes([GET_MOVING_STATE]), 1, parse_moving, "moving state")

    def errors(self) -> int:
        """The error bit field (reading clears it)."""
        request = bytes([GET_ERRORS])
        return self._link.exchange(request, 2, lambda r: int.from_bytes(r, "little"), "errors")

    def group_move(
        self,
        pulses: Mapping[int, float],
        time_ms: int | None = None,
        speeds: Mapping[int, int] | None = None,
    ) -> None:
        """Move several servos to arrive together: each one's speed and acceleration
        limits are set to cover its distance in the move's time (at least ``time_ms``,
        longer if a ``speeds`` limit [µs/s] needs it; ``motion_limits``), then all
        targets go out in one write. Servos never commanded before jump."""
        data = b"".join(target_bytes(ch, pw) for ch, pw in pulses.items())  # validates
        starts = {ch: self.get_position(ch) for ch in pulses}
        move_s = _move_time(pulses, starts, time_ms, speeds or {})
        limits = b""
        for ch, pw in pulses.items():
            delta = round(pw * 4) / 4.0 - starts[ch]  # as the Maestro sees it: quarter-µs
            speed, accel = motion_limits(delta, move_s) if move_s > 0 and delta else (0, 0)
            limits += speed_bytes(ch, speed) + acceleration_bytes(ch, accel)
        self._link.write(limits + data)

    def wait(self, timeout_s: float, poll_s: float = 0.005) -> None:
        """Poll the moving state until done; DeviceError after ``timeout_s`` [s]."""
        deadline = self.clock.now() + timeout_s
        while self.is_moving():
            if self.clock.now() > deadline:
                raise DeviceError(
                    f"Maestro on {self.port} still moving after {timeout_s:.2f} s; "
                    "check its speed limits and servo power, or wait longer"
                )
            self.clock.sleep(poll_s)

    def pulses_off(self, channels: Iterable[int]) -> None:
        """Stop sending pulses on ``channels`` (Set Target 0, Maestro User's Guide,
        "Command Reference": a target of 0 tells the Maestro to stop sending pulses):
        the servos stop holding. Get Position then reads 0."""
        data = b"".join(bytes([SET_TARGET, ch, 0, 0]) for ch in channels)
        if data:
            self._link.write(data)

    def stop(self, channels: Iterable[int], at: Mapping[int, float] | None = None) -> None:
        """Hold each servo in ``channels`` where it is now (target := position): at the
        pulse ``at`` gives for it [µs] (the host's own estimate: no reply needed; a
        channel absent from ``at`` was never commanded and is left), else at the
        position it reports."""
        data = b""
        for ch in channels:
            pulse = self.get_position(ch) if at is None else at.get(ch, 0.0)
            if pulse:
                data += bytes([SET_TARGET, ch]) + _seven_bit_pair(round(pulse * 4))
        self._link.write(data)

    def close(self) -> None:
        """Release the port. Safe to call twice."""
        self._link.close()

    def __enter__(self) -> Maestro:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()


def _move_time(
    pulses: Mapping[int, float],
    starts: Mapping[int, float],
    time_ms: int | None,
    speeds: Mapping[int, int],
) -> float:
    """Seconds the group move takes: at least ``time_ms``, and long enough that no
    servo with a ``speeds`` entry [µs/s] exceeds it (servos that are off jump)."""
    needed = [(time_ms or 0) / 1000.0]
    for ch, limit in speeds.items():
        if limit <= 0:
            raise InputError(f"speed of channel {ch} must be > 0 µs/s, got {limit}")
        if starts.get(ch):
            needed.append(abs(pulses[ch] - starts[ch]) / limit)
    return max(needed)
