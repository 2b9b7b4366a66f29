"""A simulated Lynxmotion SSC-32U: its ASCII protocol and its 32 pulse outputs.

The command language (SSC-32U user guide; ``armkit.devices.ssc32`` speaks it
from the host side) is parsed exactly: ``#<ch>P<pw>[S<spd>] ... [T<ms>]`` group
moves, ``Q``, ``QP<ch>...``, ``STOP<ch>``, ``VER``; ESC cancels a line, CR ends
it. Pulses move linearly in the device's time at the commanded speed and time
(``_pulses.VirtualServo``). Each command is one row of ``COMMANDS`` (name ->
handler): a new command of the manual is one row and one method.

The board has no feedback: ``QP`` reports the pulse it sends. Its replies go
through an ``Outbox`` (faults: ``inject``). It listens at one baud rate and
ignores a host at another (``baudrate``), like the board.

Known differences from the real board (issue 11, point 5: the next step):
``P0``, out-of-range pulses (the board clamps them), ``PO`` offsets, digital
I/O ``H``/``L``/``A``..``D``/``AL``..``DL`` and the analog inputs ``VA``..``VD``
(``SimArm.analog``) are not yet answered.
"""

from __future__ import annotations

import re
from collections import deque
from collections.abc import Callable

from ._outbox import Outbox, log
from ._pulses import MoveRecord, PulseOutputs, VirtualServo

CHANNELS = 32
VERSION = b"SSC32-V2.50USB\r"
_TOKEN = re.compile(r"(STOP|VER|QP|Q|#|P|S|T)(\d*)")
Tokens = list[tuple[str, str]]


class SimSSC32(PulseOutputs):
    """An SSC-32U with 32 channels listening at ``baudrate`` (9600, 38400 or 115200).

    Attributes:
        received: every complete command line as received (byte-exact tests).
        errors: what the board could not execute.  history: every move executed.
        outbox: its replies.  analog: input channel (0..3 = VA..VD) -> volts, or empty.
    """

    name = "ssc32"

    def __init__(self, baudrate: int = 9600) -> None:
        self.baudrate: int | None = baudrate
        self.servos = [VirtualServo() for _ in range(CHANNELS)]
        self.outbox = Outbox()
        self.received: deque[bytes] = log()
        self.errors: deque[str] = log()
        self.history: deque[MoveRecord] = log()
        self.analog: dict[int, Callable[[], float]] = {}
        self._line = b""
        self.commands: dict[str, Callable[[Tokens, float], None]] = {
            "#": self._move,
            "Q": self._status,
            "QP": self._query_pulses,
            "STOP": self._stop,
            "VER": self._version,
        }

    def receive(self, data: bytes, now: float) -> None:
        """Bytes from the host at time ``now`` [s]: executed line by line."""
        for byte in data:
            if byte == 0x1B:  # ESC cancels the line being typed
                self._line = b""
            elif byte == 0x0D:
                self._execute(self._line, now)
                self._line = b""
            else:
                self._line += bytes([byte])

    def pulse(self, channel: int, now: float) -> float:
        """The pulse ``channel`` sends at ``now`` [µs] (0 = never commanded)."""
        return self.servos[channel].pulse(now)

    def _execute(self, line: bytes, now: float) -> None:
        self.received.append(line + b"\r")
        text = re.sub(rb"[ \t\n]", b"", line).decode("latin-1").upper()
        tokens = _tokenize(text)
        handler = self.commands.get(tokens[0][0]) if tokens else None
        if handler is None:
            self.errors.append(f"not a command: {line!r}")
            return
        handler(tokens, now)

    def _move(self, tokens: Tokens, now: float) -> None:
        parsed = _parse_move(tokens)
        if isinstance(parsed, str):
            self.errors.append(parsed)
            return
        clauses, time_ms = parsed
        duration = max([time_ms / 1000.0] + [self._speed_time(c, now) for c in clauses])
        record = MoveRecord(now, duration)
        for ch, pw, _ in clauses:
            servo = self.go(ch, pw, duration, now)
            record.servos[ch] = (servo.start_us, servo.target_us)
        self.history.append(record)

    def _speed_time(self, clause: tuple[int, int, int], now: float) -> float:
        ch, pw, speed = clause
        start = self.servos[ch].pulse(now)
        return abs(pw - start) / speed if speed and start else 0.0

    def _status(self, tokens: Tokens, now: float) -> None:
        self.outbox.send(b"+" if self.busy(now) else b".", now)

    def _query_pulses(self, tokens: Tokens, now: float) -> None:
        channels = [int(arg) for kind, arg in tokens if kind == "QP" and arg]
        if len(channels) != len(tokens) or any(ch >= CHANNELS for ch in channels):
            self.errors.append(f"bad pulse query: {tokens}")
            return
        self.outbox.send(bytes(round(self.servos[ch].pulse(now) / 10) for ch in channels), now)

    def _stop(self, tokens: Tokens, now: float) -> None:
        if len(tokens) != 1 or not tokens[0][1] or int(tokens[0][1]) >= CHANNELS:
            self.errors.append(f"bad stop: {tokens}")
            return
        self.servos[int(tokens[0][1])].hold(now)

    def _version(self, tokens: Tokens, now: float) -> None:
        self.outbox.send(VERSION, now)


def _tokenize(text: str) -> Tokens:
    """``"#1P1500T9"`` -> ``[("#", "1"), ("P", "1500"), ("T", "9")]``; [] if any junk."""
    tokens, pos = [], 0
    for match in _TOKEN.finditer(text):
        if match.start() != pos:
            return []
        tokens.append((match.group(1), match.group(2)))
        pos = match.end()
    return tokens if pos == len(text) else []


def _parse_move(tokens: Tokens) -> tuple[list[tuple[int, int, int]], int] | str:
    """Move tokens -> ([(channel, pulse µs, speed µs/s or 0)], time ms), or what is wrong."""
    time_ms = 0
    if tokens[-1][0] == "T":
        time_ms, tokens = int(tokens[-1][1] or 0), tokens[:-1]
    clauses: list[tuple[int, int, int]] = []
    i = 0
    while i < len(tokens):
        kinds = [kind for kind, _ in tokens[i : i + 3]]
        size = 3 if kinds == ["#", "P", "S"] else 2
        if kinds[:2] != ["#", "P"] or any(not arg for _, arg in tokens[i : i + size]):
            return f"bad move at {tokens[i:]}"
        ch, pw = int(tokens[i][1]), int(tokens[i + 1][1])
        speed = int(tokens[i + 2][1]) if size == 3 else 0
        if ch >= CHANNELS or not 500 <= pw <= 2500:
            return f"move out of range: channel {ch}, pulse {pw}"
        clauses.append((ch, pw, speed))
        i += size
    return clauses, time_ms
