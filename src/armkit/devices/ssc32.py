"""Lynxmotion SSC-32 / SSC-32U servo controller: the ASCII protocol on a serial port.

Commands (SSC-32U user guide; spaces optional, every line ends with CR):

    #<ch>P<pw>S<spd> ... #<ch>P<pw>T<ms>\\r   one servo, or a group move: every servo
                                              starts and finishes together, in at
                                              least T ms and no faster than each S
    Q\\r                                       "." = move done, "+" = still moving
    QP<ch>QP<ch>...\\r                          one binary byte per servo = pulse / 10 µs
    STOP<ch>\\r                                stop that servo where it is
    VER\\r                                     firmware version text, ends with CR

Pulses are µs (500..2500), speeds µs/s, times ms (at most 65535). The board has
no feedback: QP reports the pulse it is sending, 0 for a servo never commanded
(the first command to a servo ignores S and T and jumps).

pyserial is imported only when a port is opened (``serial`` extra).
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping

from .._clock import Clock, WallClock
from .._errors import DeviceError, InputError, ReplyError
from ._serial import CR as CR
from ._serial import SerialLink as SerialLink
from ._serial import SerialPort

PULSE_MIN_US = 500
PULSE_MAX_US = 2500
CHANNELS = range(32)
BAUDRATES = (9600, 38400, 115200)
TIME_MAX_MS = 65535
SPEED_MAX_US_PER_S = 65535
STATUS_QUERY = b"Q\r"
VERSION_QUERY = b"VER\r"
STATUS_REPLY = {b".": False, b"+": True}  # Q reply byte -> still moving


def check_channel(channel: int, channels: range = CHANNELS) -> None:
    """Raise ValueError unless ``channel`` is one of ``channels``."""
    if not isinstance(channel, int) or channel not in channels:
        raise InputError(
            f"servo channel {channel!r} does not exist; use {channels.start}..{channels.stop - 1}"
        )


def check_pulse(channel: int, pulse_us: int) -> None:
    """Raise ValueError unless ``pulse_us`` [µs] is an int in 500..2500."""
    if not isinstance(pulse_us, int) or not PULSE_MIN_US <= pulse_us <= PULSE_MAX_US:
        raise InputError(
            f"pulse {pulse_us!r} µs on channel {channel} is outside "
            f"{PULSE_MIN_US}..{PULSE_MAX_US} µs; give a whole number of µs in that range"
        )


def _check_int(name: str, value: int, low: int, high: int, unit: str) -> None:
    if not isinstance(value, int) or not low <= value <= high:
        raise InputError(f"{name} {value!r} {unit} is outside {low}..{high} {unit}")


def check_baudrate(baudrate: int) -> None:
    """Raise ValueError unless ``baudrate`` is one the SSC-32 can be set to."""
    if baudrate not in BAUDRATES:
        raise InputError(
            f"SSC-32 baud rate {baudrate!r} is not one of {BAUDRATES}; set the board's"
        )


def group_move_bytes(
    pulses: Mapping[int, int],
    time_ms: int | None = None,
    speeds: Mapping[int, int] | None = None,
) -> bytes:
    """The bytes of one (group) move: ``#<ch>P<pw>[S<spd>]`` per servo, then ``[T<ms>]`` CR.

    Args:
        pulses: channel -> pulse [µs], at least one.
        time_ms: time for the whole move [ms], 1..65535, or None.
        speeds: channel -> maximum speed [µs/s] for some of those channels, or None.

    Raises:
        ValueError: an empty move, an unknown channel, or a value out of range.
    """
    speeds = dict(speeds or {})
    if not pulses:
        raise InputError("a move needs at least one servo; give channel -> pulse")
    for ch in speeds:
        if ch not in pulses:
            raise InputError(f"speed given for channel {ch}, which is not in the move")
    parts = [_servo_clause(ch, pw, speeds.get(ch)) for ch, pw in pulses.items()]
    if time_ms is not None:
        _check_int("move time", time_ms, 1, TIME_MAX_MS, "ms")
        parts.append(f"T{time_ms}")
    return "".join(parts).encode("ascii") + CR


def _servo_clause(channel: int, pulse_us: int, speed: int | None) -> str:
    check_channel(channel)
    check_pulse(channel, pulse_us)
    if speed is None:
        return f"#{channel}P{pulse_us}"
    _check_int(f"speed of channel {channel}", speed, 1, SPEED_MAX_US_PER_S, "µs/s")
    return f"#{channel}P{pulse_us}S{speed}"


def query_pulse_bytes(channels: Iterable[int]) -> bytes:
    """The bytes of one pulse query ``QP<ch>...`` CR for ``channels`` (reply: one byte each)."""
    channels = list(channels)
    if not channels:
        raise InputError("a pulse query needs at least one channel")
    for ch in channels:
        check_channel(ch)
    return "".join(f"QP{ch}" for ch in channels).encode("ascii") + CR


def stop_bytes(channel: int) -> bytes:
    """The bytes that stop servo ``channel`` at its present pulse."""
    check_channel(channel)
    return f"STOP{channel}".encode("ascii") + CR


def parse_status(reply: bytes) -> bool:
    """True while moving, from the one-byte reply to ``Q``; ValueError if it is neither."""
    if reply not in STATUS_REPLY:
        raise ReplyError(f"status reply {reply!r} is not '.' or '+'")
    return STATUS_REPLY[reply]


def parse_pulses(reply: bytes, channels: list[int]) -> dict[int, int]:
    """Channel -> pulse [µs] (0 = never commanded) from the reply to a pulse query."""
    if len(reply) != len(channels):
        raise ReplyError(f"pulse reply has {len(reply)} bytes, expected {len(channels)}")
    pulses = {ch: 10 * b for ch, b in zip(channels, reply, strict=True)}
    for ch, pw in pulses.items():
        if pw and not PULSE_MIN_US <= pw <= PULSE_MAX_US:
            raise ReplyError(
                f"channel {ch} reports {pw} µs, outside {PULSE_MIN_US}..{PULSE_MAX_US}"
            )
    return pulses


class SSC32:
    """An SSC-32 / SSC-32U on a serial port.

    Args:
        port: serial device path (``/dev/ttyUSB0``, an emulator's ``.port``), or an open
            ``SerialPort`` (a simulated line).
        baudrate: 9600 (factory default), 38400 or 115200, as set on the board.
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
        check_baudrate(baudrate)
        self.clock = clock or WallClock()
        self._link = SerialLink("SSC-32", port, baudrate, timeout_s, retries, self.clock)
        self.port = self._link.port

    def move(
        self, channel: int, pulse_us: int, *, speed: int | None = None, time_ms: int | None = None
    ) -> None:
        """Move one servo to ``pulse_us`` [µs], at most ``speed`` [µs/s], in ``time_ms`` [ms]."""
        self.group_move({channel: pulse_us}, time_ms, None if speed is None else {channel: speed})

    def group_move(
        self,
        pulses: Mapping[int, int],
        time_ms: int | None = None,
        speeds: Mapping[int, int] | None = None,
    ) -> None:
        """Move several servos so they start and finish together (see ``group_move_bytes``)."""
        self._link.write(group_move_bytes(pulses, time_ms, speeds))

    def is_moving(self) -> bool:
        """True while the last move is still running (``Q``)."""
        return self._link.exchange(STATUS_QUERY, 1, parse_status, "status query (Q)")

    def wait(self, timeout_s: float, poll_s: float = 0.005) -> None:
        """Poll ``Q`` until the move is done; DeviceError if it is not within ``timeout_s`` [s]."""
        deadline = self.clock.now() + timeout_s
        while self.is_moving():
            if self.clock.now() > deadline:
                raise DeviceError(
                    f"SSC-32 on {self.port} still moving after {timeout_s:.2f} s; "
                    "check for a stalled servo, or wait longer"
                )
            self.clock.sleep(poll_s)

    def query_pulses(self, channels: Iterable[int]) -> dict[int, int]:
        """Channel -> pulse being sent [µs] (0 = never commanded), by one ``QP`` query."""
        channels = list(channels)
        request = query_pulse_bytes(channels)
        what = f"pulse query (QP) of channel {', '.join(map(str, channels))}"
        return self._link.exchange(
            request, len(channels), lambda r: parse_pulses(r, channels), what
        )

    def read_analog(self, channel: int) -> float:
        """The voltage on analog input ``channel`` (0..7 = ``VA``..``VH``) [V], 0..4.98 in
        steps of 5/256 V, by one ``V<A-H>`` query (SSC-32U user guide, "Analog Inputs":
        one byte back, "multiply by 5/256")."""
        if channel not in range(8):
            raise InputError(f"the SSC-32U has analog inputs 0..7 (VA..VH), got {channel}")
        letter = "ABCDEFGH"[channel]
        reply = self._link.exchange(
            f"V{letter}".encode("ascii") + CR, 1, bytes, f"analog query (V{letter})"
        )
        return reply[0] * 5.0 / 256.0

    def pulses_off(self, channels: Iterable[int]) -> None:
        """Stop sending pulses on ``channels`` (``#<ch>P0`` each, one line; SSC-32U user
        guide, "Servo Move or Group Move": a pulse width of 0 turns the output off): the
        servos stop holding. QP then reads 0."""
        channels = list(channels)
        for ch in channels:
            check_channel(ch)
        clauses = "".join(f"#{ch}P0" for ch in channels)
        if clauses:
            self._link.write(clauses.encode("ascii") + CR)

    def stop(self, channels: Iterable[int]) -> None:
        """Stop each servo in ``channels`` where it is now."""
        for ch in channels:
            self._link.write(stop_bytes(ch))

    def version(self) -> str:
        """The firmware's version text (``VER``)."""
        return self._link.exchange(VERSION_QUERY, None, _parse_version, "version query (VER)")

    def close(self) -> None:
        """Release the port. Safe to call twice."""
        self._link.close()

    def __enter__(self) -> SSC32:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()


def _parse_version(reply: bytes) -> str:
    if not reply.endswith(CR) or not reply.isascii() or len(reply) < 2:
        raise ReplyError(f"version reply {reply!r} is not text ending with CR")
    return reply[:-1].decode("ascii")
