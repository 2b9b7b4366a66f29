"""The SSC-32U's and the Maestro's answers from ``armkit emulate`` in another process,
spoken to by pyserial in the raw bytes of the makers' guides while every core is busy
twice over (issue 27 Done-when; the in-process versions are tests/servo/test_ssc32_guide.py
and test_maestro_faithful.py).

No pip-installable public client of either board speaks to a serial port as the guides
do (docs/emulators.md), so the clients here are the guides' own byte strings.
"""

from __future__ import annotations

import time
from collections.abc import Iterator
from typing import Any

import pytest
from emulated import cpu_load, emulate

serial = pytest.importorskip("serial")
TRIES = 5


class Line:
    """pyserial on the emulator's pty: a question asked again while no answer came (a
    busy machine can delay the emulator past one read's timeout; a late answer is
    drained before the next question)."""

    def __init__(self, path: str, baud: int) -> None:
        self.port: Any = serial.Serial(path, baud, timeout=0.5)

    def send(self, data: bytes) -> None:
        self.port.write(data)

    def ask(self, data: bytes, size: int) -> bytes:
        for _ in range(TRIES):
            self.port.reset_input_buffer()
            self.port.write(data)
            got = bytes(self.port.read(size))
            if len(got) == size:
                return got
        raise AssertionError(f"no {size}-byte answer to {data!r} in {TRIES} tries")

    def ask_line(self, text: str) -> bytes:
        """An ASCII command answered by text ending in CR (registers, version)."""
        for _ in range(TRIES):
            self.port.reset_input_buffer()
            self.port.write(text.encode("ascii") + b"\r")
            got = bytes(self.port.read_until(b"\r"))
            if got.endswith(b"\r"):
                return got
        raise AssertionError(f"no answer to {text!r} in {TRIES} tries")

    def until(self, data: bytes, size: int, wanted: bytes, seconds: float = 10.0) -> bytes:
        """Ask until the answer is ``wanted`` (a move in progress) or ``seconds`` pass."""
        deadline = time.monotonic() + seconds
        got = self.ask(data, size)
        while got != wanted and time.monotonic() < deadline:
            time.sleep(0.05)
            got = self.ask(data, size)
        return got


@pytest.fixture(scope="module")
def ssc32() -> Iterator[Line]:
    with cpu_load(), emulate("ssc32") as (path, _):
        line = Line(path, 9600)
        yield line
        line.port.close()


@pytest.fixture(scope="module")
def maestro() -> Iterator[Line]:
    with cpu_load(), emulate("maestro") as (path, _):
        line = Line(path, 9600)
        yield line
        line.port.close()


def test_ssc32_registers(ssc32: Line) -> None:
    """SSC-32U guide, "Register Read/Write": R4 is the baud rate / 10; R<r>=<n> programs a
    register (spaces optional); RDFLT answers OK and restores the defaults."""
    assert ssc32.ask_line("R4") == b"960\r"
    ssc32.send(b"R32 = -50\r")
    assert ssc32.ask_line("R32") == b"-50\r"
    assert ssc32.ask_line("RDFLT") == b"OK\r"
    assert ssc32.ask_line("R32") == b"0\r"


def test_ssc32_move_and_queries(ssc32: Line) -> None:
    """ "Servo Move": #<ch> P<pw> T<time>; "Query Pulse Width" QP<ch> answers one byte,
    the pulse width / 10; "Query Movement Status" Q answers '.' when done, '+' while
    moving."""
    ssc32.send(b"#0 P1500 T200\r")
    assert ssc32.until(b"Q\r", 1, b".") == b"."
    assert ssc32.ask(b"QP 0\r", 1) == bytes([150])
    ssc32.send(b"#0 P2000 T1500\r")
    assert ssc32.ask(b"Q\r", 1) == b"+"
    assert ssc32.until(b"Q\r", 1, b".") == b"."
    assert ssc32.ask(b"QP 0\r", 1) == bytes([200])


def test_ssc32_inputs_and_a_bad_query(ssc32: Line) -> None:
    """ "Digital Input": A..F read '1' on an open (pulled-up) input, one character each;
    "Analog Inputs": VA..VH one byte each; a piece the board cannot read is skipped and
    the queries around it are answered."""
    assert ssc32.ask(b"A B C D E F\r", 6) == b"111111"
    assert len(ssc32.ask(b"VA XYZ VB\r", 2)) == 2


def _target(channel: int, us: float) -> bytes:
    q = round(us * 4)
    return bytes([0x84, channel, q & 0x7F, q >> 7])


def test_maestro_compact_protocol(maestro: Line) -> None:
    """Maestro guide 5.e "Serial Servo Commands", compact protocol: Set Target 0x84 in
    quarter-microseconds; Get Position 0x90 answers two bytes, low first; Get Moving State
    0x93 answers 0 when no servo moves; Get Errors 0xA1 two bytes, 0 when none."""
    maestro.send(_target(0, 1500))
    assert maestro.until(b"\x93", 1, b"\x00") == b"\x00"
    assert int.from_bytes(maestro.ask(b"\x90\x00", 2), "little") == 6000
    assert maestro.ask(b"\xa1", 2) == b"\x00\x00"


def test_maestro_pololu_protocol_and_script_status(maestro: Line) -> None:
    """5.c "Serial Protocols", Pololu protocol: 0xAA, device number 12, the command with
    its high bit cleared (another device number is another board's); 5.f: Get Script
    Status 0xAE answers 1 when no script runs."""
    q = 1600 * 4
    maestro.send(bytes([0xAA, 12, 0x04, 3, q & 0x7F, q >> 7]))
    maestro.send(bytes([0xAA, 13, 0x04, 4, q & 0x7F, q >> 7]))
    assert maestro.until(b"\x93", 1, b"\x00") == b"\x00"
    assert int.from_bytes(maestro.ask(bytes([0xAA, 12, 0x10, 3]), 2), "little") == q
    assert int.from_bytes(maestro.ask(b"\x90\x04", 2), "little") == 0
    assert maestro.ask(b"\xae", 1) == b"\x01"
