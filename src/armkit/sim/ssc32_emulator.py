"""An SSC-32 on a pseudo-terminal: the real ``SSC32`` class (pyserial) talks to it by path.

The emulator parses the ASCII protocol exactly (see ``armkit.devices.ssc32``) and
moves virtual servos in real time at the commanded speed and time. It can drop,
delay or garble its next replies (``inject``) and ignores a client at the wrong
baud rate, like the board would. ``PtyEmulator`` and ``VirtualServo`` are shared
with the Maestro emulator.

    with SSC32Emulator() as emu:
        board = SSC32(emu.port, 9600)
"""

from __future__ import annotations

import heapq
import os
import re
import select
import termios
import threading
import time
import tty
from collections import deque
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Self

FAULTS = ("drop", "late", "garbage")  # what ``inject`` can do to the next replies


@dataclass
class VirtualServo:
    """One servo's output pulse [µs], moving linearly in time; 0 = never commanded."""

    start_us: float = 0.0
    target_us: float = 0.0
    t0: float = 0.0
    duration_s: float = 0.0

    def pulse(self, now: float) -> float:
        """The pulse being sent at time ``now`` [s, monotonic clock]."""
        if self.duration_s <= 0.0 or now >= self.t0 + self.duration_s:
            return self.target_us
        frac = (now - self.t0) / self.duration_s
        return self.start_us + (self.target_us - self.start_us) * frac

    def moving(self, now: float) -> bool:
        """True while the pulse is still changing."""
        return self.duration_s > 0.0 and now < self.t0 + self.duration_s

    def go(self, target_us: float, duration_s: float, now: float) -> None:
        """Start a move from here to ``target_us`` lasting ``duration_s`` (a first move jumps)."""
        start = self.pulse(now)
        self.start_us, self.target_us, self.t0 = start, target_us, now
        self.duration_s = duration_s if start > 0.0 else 0.0

    def hold(self, now: float) -> None:
        """Stop where the servo is now."""
        self.go(self.pulse(now), 0.0, now)


@dataclass(frozen=True)
class MoveRecord:
    """One move as the emulator executed it: start time [s, device clock], duration [s], and
    channel -> (start pulse, target pulse) [µs]."""

    t0: float
    duration_s: float
    servos: dict[int, tuple[float, float]] = field(default_factory=dict)


class PtyEmulator:
    """A device on a pseudo-terminal, run by a background thread.

    Subclasses implement ``_feed(data)`` and answer with ``_reply(data)``. Motion runs
    on ``now()``; ``time_scale`` > 1 makes it faster than real time (replies are not).
    Attributes: ``port`` (the path to open), ``received`` (complete commands as
    received, for byte-exact tests), ``errors`` (what the device refused).
    """

    name = "device"
    servos: list[VirtualServo]

    def __init__(self, baudrate: int, time_scale: float = 1.0) -> None:
        self.baudrate = baudrate
        self.time_scale = time_scale
        self.received: list[bytes] = []
        self.errors: list[str] = []
        self._lock = threading.RLock()
        self._faults: deque[tuple[str, float]] = deque()
        self._outbox: list[tuple[float, int, bytes]] = []
        self._master, self._slave = os.openpty()
        tty.setraw(self._slave)
        os.set_blocking(self._master, False)
        self.port = os.ttyname(self._slave)
        self._wake_r, self._wake_w = os.pipe()
        self._running = True
        self._thread = threading.Thread(target=self._run, name=f"{self.name}-emu", daemon=True)
        self._thread.start()

    def now(self) -> float:
        """The device's clock [s]: monotonic time, ``time_scale`` times faster (tests)."""
        return time.monotonic() * self.time_scale

    def inject(self, fault: str, count: int = 1, delay_s: float = 0.15) -> None:
        """Make the next ``count`` replies faulty: ``"drop"`` (never sent), ``"late"``
        (sent ``delay_s`` [s] late) or ``"garbage"`` (every byte replaced by 0xFF)."""
        if fault not in FAULTS:
            raise ValueError(f"unknown fault {fault!r}; faults are {', '.join(FAULTS)}")
        with self._lock:
            self._faults.extend([(fault, delay_s)] * count)

    def pulse(self, channel: int) -> float:
        """The pulse ``channel`` is sending now [µs] (0 = never commanded)."""
        with self._lock:
            return self.servos[channel].pulse(self.now())

    def _reply(self, data: bytes) -> None:
        fault, delay = self._faults.popleft() if self._faults else ("", 0.0)
        if fault == "drop":
            return
        if fault == "garbage":
            data = b"\xff" * len(data)
        due = time.monotonic() + (delay if fault == "late" else 0.0)
        heapq.heappush(self._outbox, (due, len(self._outbox), data))

    def _feed(self, data: bytes) -> None:
        raise NotImplementedError

    def _run(self) -> None:
        while self._running:
            ready, _, _ = select.select([self._master, self._wake_r], [], [], self._wait_s())
            if self._master in ready:
                self._receive()
            with self._lock:
                self._send_due()

    def _wait_s(self) -> float:
        with self._lock:  # until the next reply is due
            return max(0.0, self._outbox[0][0] - time.monotonic()) if self._outbox else 0.5

    def _receive(self) -> None:
        try:
            data = os.read(self._master, 4096)
        except (BlockingIOError, OSError):
            return
        with self._lock:
            if self._baud_matches():
                self._feed(data)
            else:
                self.errors.append(f"bytes at the wrong baud rate (device set to {self.baudrate})")

    def _baud_matches(self) -> bool:
        speed = termios.tcgetattr(self._slave)[5]
        return bool(speed == getattr(termios, f"B{self.baudrate}", None))

    def _send_due(self) -> None:
        now = time.monotonic()
        while self._outbox and self._outbox[0][0] <= now:
            _, _, data = heapq.heappop(self._outbox)
            try:
                os.write(self._master, data)
            except OSError:
                self.errors.append("reply lost: nobody reading")

    def close(self) -> None:
        """Stop the thread and close the pseudo-terminal. Safe to call twice."""
        if not self._running:
            return
        self._running = False
        os.write(self._wake_w, b"x")
        self._thread.join(timeout=2.0)
        for fd in (self._master, self._slave, self._wake_r, self._wake_w):
            os.close(fd)

    def __enter__(self) -> Self:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()


_TOKEN = re.compile(r"(STOP|VER|QP|Q|#|P|S|T)(\d*)")
VERSION = b"SSC32-V2.50USB\r"


class SSC32Emulator(PtyEmulator):
    """An SSC-32U with 32 channels at ``baudrate`` (9600, 38400 or 115200).

    ``history`` lists every move executed (``MoveRecord``); ``pulse(ch)`` is the
    pulse a channel is sending now [µs].
    """

    name = "ssc32"

    def __init__(self, baudrate: int = 9600, time_scale: float = 1.0) -> None:
        self.servos = [VirtualServo() for _ in range(32)]
        self.history: list[MoveRecord] = []
        self._busy_until = 0.0
        self._line = b""
        self._handlers: dict[str, Callable[[list[tuple[str, str]], float], None]] = {
            "#": self._move,
            "Q": self._status,
            "QP": self._query_pulses,
            "STOP": self._stop,
            "VER": self._version,
        }
        super().__init__(baudrate, time_scale)

    def _feed(self, data: bytes) -> None:
        for byte in data:
            if byte == 0x1B:  # ESC cancels the line being typed
                self._line = b""
            elif byte == 0x0D:
                self._execute(self._line)
                self._line = b""
            else:
                self._line += bytes([byte])

    def _execute(self, line: bytes) -> None:
        self.received.append(line + b"\r")
        text = re.sub(rb"[ \t\n]", b"", line).decode("latin-1").upper()
        tokens = _tokenize(text)
        handler = self._handlers.get(tokens[0][0]) if tokens else None
        if handler is None:
            self.errors.append(f"not a command: {line!r}")
            return
        handler(tokens, self.now())

    def _move(self, tokens: list[tuple[str, str]], now: float) -> None:
        parsed = _parse_move(tokens)
        if isinstance(parsed, str):
            self.errors.append(parsed)
            return
        clauses, time_ms = parsed
        duration = max([time_ms / 1000.0] + [self._speed_time(c, now) for c in clauses])
        record = MoveRecord(now, duration)
        for ch, pw, _ in clauses:
            servo = self.servos[ch]
            servo.go(pw, duration, now)
            record.servos[ch] = (servo.start_us, servo.target_us)
        self.history.append(record)
        self._busy_until = max(self._busy_until, now + duration)

    def _speed_time(self, clause: tuple[int, int, int], now: float) -> float:
        ch, pw, speed = clause
        start = self.servos[ch].pulse(now)
        return abs(pw - start) / speed if speed and start else 0.0

    def _status(self, tokens: list[tuple[str, str]], now: float) -> None:
        self._reply(b"+" if now < self._busy_until else b".")

    def _query_pulses(self, tokens: list[tuple[str, str]], now: float) -> None:
        channels = [int(arg) for kind, arg in tokens if kind == "QP" and arg]
        if len(channels) != len(tokens) or any(ch > 31 for ch in channels):
            self.errors.append(f"bad pulse query: {tokens}")
            return
        self._reply(bytes(round(self.servos[ch].pulse(now) / 10) for ch in channels))

    def _stop(self, tokens: list[tuple[str, str]], now: float) -> None:
        if len(tokens) != 1 or not tokens[0][1] or int(tokens[0][1]) > 31:
            self.errors.append(f"bad stop: {tokens}")
            return
        self.servos[int(tokens[0][1])].hold(now)

    def _version(self, tokens: list[tuple[str, str]], now: float) -> None:
        self._reply(VERSION)


def _tokenize(text: str) -> list[tuple[str, str]]:
    """``"#1P1500T9"`` -> ``[("#", "1"), ("P", "1500"), ("T", "9")]``; [] if any junk."""
    tokens, pos = [], 0
    for match in _TOKEN.finditer(text):
        if match.start() != pos:
            return []
        tokens.append((match.group(1), match.group(2)))
        pos = match.end()
    return tokens if pos == len(text) else []


def _parse_move(tokens: list[tuple[str, str]]) -> tuple[list[tuple[int, int, int]], int] | str:
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
        if ch > 31 or not 500 <= pw <= 2500:
            return f"move out of range: channel {ch}, pulse {pw}"
        clauses.append((ch, pw, speed))
        i += size
    return clauses, time_ms
