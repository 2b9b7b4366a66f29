"""A serial ADC board that prints its readings (for arms without an SSC-32), its
emulator on a pseudo-terminal, and the reading side (pyserial).

The board (any small microcontroller running a ten-line sketch) samples its four
10-bit inputs (0..5 V) 50 times a second and prints one line per sample at
115200 baud: ``A0:0512 A1:0000 A2:0000 A3:0000`` CR LF. ``AdcBoard.read(channel)``
waits for the next complete line and converts ``channel``'s count to volts.
"""

from __future__ import annotations

import contextlib
import os
import re
import threading
import time
import tty
from collections.abc import Callable
from typing import Any

from .._errors import DeviceError, InputError, ReplyError

BAUDRATE = 115200
RATE_HZ = 50.0
INPUTS = 4
FULL_SCALE = 1023
_LINE = re.compile(rb"A0:(\d{4}) A1:(\d{4}) A2:(\d{4}) A3:(\d{4})\r\n$")


def reading_line(volts: list[float]) -> bytes:
    """The line the board prints for four input voltages [V]."""
    counts = [round(min(5.0, max(0.0, v)) / 5.0 * FULL_SCALE) for v in volts]
    return " ".join(f"A{k}:{c:04d}" for k, c in enumerate(counts)).encode("ascii") + b"\r\n"


def parse_line(line: bytes) -> list[float]:
    """The four voltages [V] of one printed line; ReplyError (a ValueError) if it is not one."""
    m = _LINE.search(line)
    if m is None:
        raise ReplyError(f"not an ADC reading line: {line!r}")
    return [int(g) * 5.0 / FULL_SCALE for g in m.groups()]


class AdcEmulator:
    """The board on a pseudo-terminal: ``.port`` is the path to open; its inputs are
    ``inputs`` (channel -> volts, e.g. ``SimArm.analog``), read under ``lock``."""

    def __init__(
        self, inputs: dict[int, Callable[[], float]], lock: Any = None, rate_hz: float = RATE_HZ
    ) -> None:
        self.inputs, self._lock = inputs, lock or threading.Lock()
        self._period = 1.0 / rate_hz
        self._master, self._slave = os.openpty()
        tty.setraw(self._slave)
        self.port = os.ttyname(self._slave)
        self._stop = threading.Event()
        self._thread = threading.Thread(target=self._print, name="adc-pty", daemon=True)
        self._thread.start()

    def _print(self) -> None:
        while not self._stop.wait(self._period):
            with self._lock:
                volts = [self.inputs.get(k, lambda: 0.0)() for k in range(INPUTS)]
            with contextlib.suppress(OSError):  # nobody reading: lost, as on a real line
                os.write(self._master, reading_line(volts))

    def close(self) -> None:
        """Stop printing and close the pseudo-terminal. Safe to call twice."""
        if self._stop.is_set():
            return
        self._stop.set()
        self._thread.join(timeout=2.0)
        os.close(self._master)
        os.close(self._slave)


class AdcBoard:
    """The reading side: the board at ``port`` (pyserial), ``timeout_s`` per line."""

    def __init__(self, port: str, *, timeout_s: float = 0.5) -> None:
        import serial

        try:
            self._serial = serial.Serial(port, BAUDRATE, timeout=timeout_s)
        except (OSError, serial.SerialException) as exc:
            raise DeviceError(f"cannot open the ADC board on {port}: {exc}") from None
        self.port, self._timeout = port, timeout_s

    def read(self, channel: int) -> float:
        """The voltage on input ``channel`` (0..3) [V] from the next complete line."""
        if channel not in range(INPUTS):
            raise InputError(f"the ADC board has inputs 0..{INPUTS - 1}, got {channel}")
        self._serial.reset_input_buffer()
        deadline = time.monotonic() + 3 * self._timeout
        while time.monotonic() < deadline:
            line = self._serial.readline()
            with contextlib.suppress(ValueError):
                if line.startswith(b"A0:"):
                    return parse_line(line)[channel]
        raise DeviceError(
            f"the ADC board on {self.port} printed no reading in {3 * self._timeout:.1f} s; "
            f"check the port and that it prints at {BAUDRATE} baud"
        )

    def close(self) -> None:
        """Release the port. Safe to call twice."""
        self._serial.close()
