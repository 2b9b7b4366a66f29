"""The simulated SSC-32U against the Lynxmotion SSC-32U user guide, spoken to by pyserial
(its SerialBase, through armkit's simulated line) in raw ASCII, as any program would."""

from __future__ import annotations

from typing import Any

import pytest

from armkit.sim import World
from armkit.sim._wire import Wire, serial_port
from armkit.sim.ssc32 import SimSSC32

pytest.importorskip("serial")


class Board:
    def __init__(self) -> None:
        self.world = World()
        self.device = SimSSC32(9600)
        self.port: Any = serial_port(Wire(self.device, self.world, baudrate=9600, timeout=0.05))

    def send(self, text: str) -> None:
        self.port.write(text.encode("ascii") + b"\r")

    def ask(self, text: str, size: int) -> bytes:
        self.send(text)
        return bytes(self.port.read(size))

    def qp(self, *channels: int) -> list[int]:
        return list(self.ask("".join(f"QP{c}" for c in channels), len(channels)))


@pytest.fixture
def b() -> Board:
    return Board()


def test_p0_turns_the_pulse_off_and_qp_reads_0(b: Board) -> None:
    """User guide, "Servo Move or Group Move": a pulse width of 0 stops the channel's pulses;
    "Query Pulse Width": one byte = pulse / 10 µs."""
    b.send("#5P1500")
    assert b.qp(5) == [150]
    b.send("#5P0")
    assert b.qp(5) == [0]
    assert b.device.setpoint(5, b.world.now()) is None  # the servo gets no pulse


def test_pulses_outside_500_2500_are_clamped_and_a_bad_clause_keeps_the_group(b: Board) -> None:
    """User guide, "Servo Move or Group Move": <pw> 500..2500 µs; the board clamps, and
    executes the clauses it can read."""
    b.send("#0P100#1P3000#2P1500")
    assert b.qp(0, 1, 2) == [50, 250, 150]
    b.send("#0P1000#99P1500#1P2000#3#2P1200")  # no channel 99; #3 says nothing
    assert b.qp(0, 1, 2) == [100, 200, 120]
    assert len(b.device.errors) == 2


def test_position_offset(b: Board) -> None:
    """User guide, "Position Offset": ``#<ch>PO<offset>``, -100..100 µs, added to the pulse."""
    b.send("#4P1500")
    b.send("#4PO-50")
    assert b.qp(4) == [145]
    b.send("#4PO150")  # outside the range: ignored
    assert b.qp(4) == [145] and b.device.offsets[4] == -50


def test_discrete_and_byte_outputs(b: Board) -> None:
    """User guide, "Discrete Output" (``#3H#4L``) and "Byte Output" (``#3:123``: bank 3 =
    pins 24..31, bit 0 the lowest)."""
    b.send("#3P1500")
    b.send("#3H#4L")
    assert b.device.levels == {3: True, 4: False} and b.qp(3) == [0]
    b.send("#3:123")
    assert [b.device.levels[24 + i] for i in range(8)] == [bool(123 >> i & 1) for i in range(8)]
    assert not b.device.levels[26] and not b.device.levels[31]


def test_digital_inputs_and_latches(b: Board) -> None:
    """User guide, "Digital Input": A..D read "0"/"1" (pulled up); AL..DL read "0" if the
    input went low since the last latched read, which resets the latch."""
    assert b.ask("ABCD", 4) == b"1111"
    b.device.set_input("B", False)
    b.device.set_input("B", True)  # a pulse low, gone by the time of the read
    assert b.ask("B", 1) == b"1"
    assert b.ask("ALBL", 2) == b"10"
    assert b.ask("BL", 1) == b"1"  # the latch was reset by the read
    b.device.set_input("C", False)
    assert b.ask("CCL", 2) == b"00"
