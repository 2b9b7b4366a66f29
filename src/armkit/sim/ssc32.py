"""A simulated Lynxmotion SSC-32U: its ASCII protocol and its 32 pulse outputs.

The command language (SSC-32U user guide; ``armkit.devices.ssc32`` speaks it
from the host side) is parsed exactly: ``#`` lines (group moves with ``P``,
``S``, ``T``; ``P0`` pulse off; ``PO`` offsets; ``H``/``L`` and ``#<bank>:<value>``
digital outputs: ``_ssc32_lines``, clamping 500..2500 µs and skipping only a bad
clause), ``Q``, ``QP<ch>...``, ``STOP<ch>``, ``VER``, the digital inputs
``A``..``F`` and latched ``AL``..``FL`` ("Digital Input": ASCII "0"/"1" each,
a latched read is "0" if the input went low since the last one), the analog
inputs ``VA``..``VH`` ("Analog Inputs": one byte each, volts x 256/5, 255 at
4.98 V), the registers ``R<r>`` (read: the value in ASCII and CR), ``R<r>=<n>``
and ``RDFLT`` ("OK" CR) ("Register Read/Write"); ESC cancels a line, CR ends it.
A line is a run of commands: each query in it is answered in turn, and a piece
the board cannot read is skipped without silencing the rest. Pulses move linearly in the device's time at the commanded
speed and time (``_pulses.VirtualServo``). Each command is one row of
``commands`` (name -> handler): a new command of the manual is one row and one method.

The board has no feedback: ``QP`` reports the pulse it sends (offset included,
0 while off). Its replies go through an ``Outbox`` (faults: ``inject``). It
listens at one baud rate and ignores a host at another (``baudrate``), like the board.
The analog inputs read ``analog`` (channel 0..7 = A..H -> volts).
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
_TOKEN = re.compile(
    r"(RDFLT|STOP|VER|V[A-H]|QP|PO|AL|BL|CL|DL|EL|FL|Q|R|=|#|P|S|T|H|L|:|A|B|C|D|E|F)(-?\d*)"
)
INPUTS = ("A", "B", "C", "D", "E", "F")  # G and H are analog only
MOVE_TOKENS = frozenset(("#", "P", "S", "T", "H", "L", ":", "PO"))
REGISTERS = 256  # R0..R255
REGISTER_DEFAULTS = {1: 600, 2: 70}  # Transmit Delay [us], Transmit Pacing [us]; R4 = baud / 10


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
            **{f"V{c}": self._query_analog for c in "ABCDEFGH"},
            **{name: self._read_inputs for name in INPUTS + tuple(i + "L" for i in INPUTS)},
            "R": self._register,
            "RDFLT": self._defaults,
        }
        self.registers = [0] * REGISTERS
        self._answer = bytearray()  # the answers of the line being executed
        self._defaults([], 0.0, answer=False)

    def set_input(self, name: str, high: bool) -> None:
        """Drive digital input ``name`` (A..F) high or low (a low is latched)."""
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
        self._answer = bytearray()
        for command in _commands(_tokenize(text)):
            handler = self.commands.get(command[0][0])
            if handler is None:
                self.errors.append(f"not a command: {command} in {line!r}")
                continue
            handler(command, now)
        if self._answer:  # the line's answers, in order, as one reply
            self.outbox.send(bytes(self._answer), now)

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
        self._answer += b"+" if self.busy(now) else b"."

    def _query_pulses(self, tokens: Tokens, now: float) -> None:
        channels = [_whole(arg) for kind, arg in tokens if kind == "QP"]
        if len(channels) != len(tokens) or not all(0 <= ch < CHANNELS for ch in channels):
            self.errors.append(f"bad pulse query: {tokens}")
            return
        self._answer += bytes(round(self.pulse(ch, now) / 10) for ch in channels)

    def _stop(self, tokens: Tokens, now: float) -> None:
        if len(tokens) != 1 or not 0 <= _whole(tokens[0][1]) < CHANNELS:
            self.errors.append(f"bad stop: {tokens}")
            return
        self.servos[_whole(tokens[0][1])].hold(now)

    def _query_analog(self, tokens: Tokens, now: float) -> None:
        """``VA``..``VH``: one byte, the volts x 256/5 (SSC-32U user guide, "Analog
        Inputs": "multiply by 5/256", 255 = 4.98 V); an unconnected input reads 0."""
        if any(arg for _, arg in tokens):
            self.errors.append(f"bad analog query: {tokens}")
            return
        volts = [self.analog.get(ord(kind[1]) - ord("A"), lambda: 0.0)() for kind, _ in tokens]
        self._answer += bytes(min(255, max(0, int(v * 256.0 / 5.0))) for v in volts)

    def _register(self, tokens: Tokens, now: float) -> None:
        """``R<r>``: the register's value in ASCII and CR; ``R<r>=<n>``: set it (SSC-32U
        user guide, "Register Read/Write", r = 0..255)."""
        number = _whole(tokens[0][1])
        if not 0 <= number < REGISTERS:
            self.errors.append(f"bad register: {tokens}")
            return
        if len(tokens) == 1:
            self._answer += f"{self.registers[number]}\r".encode("ascii")
        elif tokens[1][0] == "=" and tokens[1][1].lstrip("-").isdigit() and len(tokens[1][1]) < 12:
            self.registers[number] = int(tokens[1][1])
        else:
            self.errors.append(f"bad register write: {tokens}")

    def _defaults(self, tokens: Tokens, now: float, *, answer: bool = True) -> None:
        """``RDFLT``: every register to its default, then "OK" CR."""
        self.registers = [REGISTER_DEFAULTS.get(r, 0) for r in range(REGISTERS)]
        self.registers[4] = (self.baudrate or 9600) // 10  # R4: the baud rate / 10
        if answer:
            self._answer += b"OK\r"

    def _version(self, tokens: Tokens, now: float) -> None:
        self._answer += VERSION

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
        self._answer += reply.encode("ascii")


def _whole(text: str) -> int:
    """The number ``text`` writes in plain digits (a channel, a register), else -1: a
    sign, no digits or a run too long to be either is no such number."""
    return int(text) if text.isascii() and text.isdigit() and len(text) < 12 else -1


def _tokenize(text: str) -> Tokens:
    """``"#1P1500T9"`` -> ``[("#", "1"), ("P", "1500"), ("T", "9")]``; text that is no
    token becomes ``("?", text)``."""
    tokens, pos = [], 0
    for match in _TOKEN.finditer(text):
        if match.start() != pos:
            tokens.append(("?", text[pos : match.start()]))
        tokens.append((match.group(1), match.group(2)))
        pos = match.end()
    if pos != len(text):
        tokens.append(("?", text[pos:]))
    return tokens


def _commands(tokens: Tokens) -> list[Tokens]:
    """A line's tokens as commands: a ``#`` run of move clauses, ``R<r>`` with its
    ``=<n>``, every other token alone (each query answered in turn)."""
    commands: list[Tokens] = []
    for token in tokens:
        kind = token[0]
        joins = commands and (
            (kind in MOVE_TOKENS and commands[-1][0][0] == "#")
            or (kind == "=" and commands[-1][0][0] == "R" and len(commands[-1]) == 1)
        )
        if joins:
            commands[-1].append(token)
        else:
            commands.append([token])
    return commands
