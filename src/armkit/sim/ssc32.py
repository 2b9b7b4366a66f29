"""A simulated Lynxmotion SSC-32U: its ASCII protocol and its 32 pulse outputs.

The command language (SSC-32U user guide; ``armkit.devices.ssc32`` speaks it
from the host side) is parsed exactly: ``#`` lines (group moves with ``P``,
``S``, ``T``; ``P0`` pulse off; ``PO`` offsets; ``H``/``L`` and ``#<bank>:<value>``
digital outputs: ``_ssc32_lines``, clamping 500..2500 µs and skipping only a bad
clause), ``Q``, ``QP<ch>...``, ``STOP<ch>``, ``VER``, the digital inputs
``A B C D`` and latched ``AL BL CL DL`` ("Digital Input": ASCII "0"/"1" each,
a latched read is "0" if the input went low since the last one); ESC cancels a
line, CR ends it. Pulses move linearly in the device's time at the commanded
speed and time (``_pulses.VirtualServo``). Each command is one row of
``commands`` (name -> handler): a new command of the manual is one row and one method.

The board has no feedback: ``QP`` reports the pulse it sends (offset included,
0 while off). Its replies go through an ``Outbox`` (faults: ``inject``). It
listens at one baud rate and ignores a host at another (``baudrate``), like the board.
The analog inputs ``VA``..``VD`` answer one byte each, 0..255 for 0..5 V, from ``analog``.
"""

from __future__ import annotations

import re
import threading
from collections import deque
from collections.abc import Callable

from ._outbox import Outbox, log
from ._pulses import MoveRecord, PulseOutputs, VirtualServo
from ._ssc32_lines import CHANNELS, HashLine, Tokens, parse_hash_line

VERSION = b"SSC32-V2.50USB\r"
_TOKEN = re.compile(r"(STOP|VER|V[A-D]|QP|PO|AL|BL|CL|DL|Q|#|P|S|T|H|L|:|A|B|C|D)(-?\d*)")
INPUTS = ("A", "B", "C", "D")


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
        self.lock = threading.RLock()  # held while the host's bytes are handled
        self.servos = [VirtualServo() for _ in range(CHANNELS)]
        self.outbox = Outbox()
        self.received: deque[bytes] = log()
        self.errors: deque[str] = log()
        self.history: deque[MoveRecord] = log()
        self.analog: dict[int, Callable[[], float]] = {}
        self.offsets = [0] * CHANNELS  # PO [µs]
        self.levels: dict[int, bool] = {}  # channels driven as digital outputs -> high
        self.inputs = dict.fromkeys(INPUTS, True)  # A..D, pulled up
        self._latched = dict.fromkeys(INPUTS, True)
        self._line = b""
        self.commands: dict[str, Callable[[Tokens, float], None]] = {
            "#": self._move,
            "Q": self._status,
            "QP": self._query_pulses,
            "STOP": self._stop,
            "VER": self._version,
            **{f"V{c}": self._query_analog for c in "ABCD"},
            **{name: self._read_inputs for name in INPUTS + tuple(i + "L" for i in INPUTS)},
        }

    def set_input(self, name: str, high: bool) -> None:
        """Drive digital input ``name`` (A..D) high or low (a low is latched)."""
        self.inputs[name] = high
        if not high:
            self._latched[name] = False

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
        """The pulse ``channel`` sends at ``now`` [µs], offset included (0 = off)."""
        pulse = self.servos[channel].pulse(now)
        return pulse + self.offsets[channel] if pulse > 0.0 else 0.0

    def setpoint(self, channel: int, t: float) -> float | None:
        """The pulse [µs] on ``channel`` at ``t`` [s]; None while it sends no pulse."""
        pulse = self.pulse(channel, t)
        return pulse if pulse > 0.0 else None

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
        line = parse_hash_line(tokens)
        self.errors.extend(line.skipped)
        for ch, offset in line.offsets.items():
            self.offsets[ch] = offset
        for ch, high in line.levels.items():
            self.levels[ch] = high
            self.go(ch, 0.0, 0.0, now)  # a digital output sends no pulse
        if line.moves:
            self._group(line, now)

    def _group(self, line: HashLine, now: float) -> None:
        moving = [c for c in line.moves if c[1]]
        duration = max([line.time_ms / 1000.0] + [self._speed_time(c, now) for c in moving])
        record = MoveRecord(now, duration)
        for ch, pw, _ in line.moves:
            self.levels.pop(ch, None)
            servo = self.go(ch, pw, duration if pw else 0.0, now)
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
        self.outbox.send(bytes(round(self.pulse(ch, now) / 10) for ch in channels), now)

    def _stop(self, tokens: Tokens, now: float) -> None:
        if len(tokens) != 1 or not tokens[0][1] or int(tokens[0][1]) >= CHANNELS:
            self.errors.append(f"bad stop: {tokens}")
            return
        self.servos[int(tokens[0][1])].hold(now)

    def _query_analog(self, tokens: Tokens, now: float) -> None:
        """``VA``..``VD`` (any of them, in one line): one byte each, 0..255 for 0..5 V
        (SSC-32U user guide, "Read analog inputs"); an unconnected input reads 0."""
        if any(kind[0] != "V" or kind == "VER" or arg for kind, arg in tokens):
            self.errors.append(f"bad analog query: {tokens}")
            return
        volts = [self.analog.get(ord(kind[1]) - ord("A"), lambda: 0.0)() for kind, _ in tokens]
        self.outbox.send(bytes(round(min(5.0, max(0.0, v)) / 5.0 * 255) for v in volts), now)

    def _version(self, tokens: Tokens, now: float) -> None:
        self.outbox.send(VERSION, now)

    def _read_inputs(self, tokens: Tokens, now: float) -> None:
        if any(kind[0] not in INPUTS or arg for kind, arg in tokens):
            self.errors.append(f"bad input read: {tokens}")
            return
        reply = ""
        for kind, _ in tokens:
            name = kind[0]
            level = self.inputs[name] and (len(kind) == 1 or self._latched[name])
            if len(kind) == 2:
                self._latched[name] = self.inputs[name]
            reply += "1" if level else "0"
        self.outbox.send(reply.encode("ascii"), now)


def _tokenize(text: str) -> Tokens:
    """``"#1P1500T9"`` -> ``[("#", "1"), ("P", "1500"), ("T", "9")]``; [] if any junk."""
    tokens, pos = [], 0
    for match in _TOKEN.finditer(text):
        if match.start() != pos:
            return []
        tokens.append((match.group(1), match.group(2)))
        pos = match.end()
    return tokens if pos == len(text) else []
