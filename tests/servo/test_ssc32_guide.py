"""The simulated SSC-32U's inputs and registers as the Lynxmotion SSC-32U user guide
gives them, in raw ASCII through pyserial (sections per test)."""

from __future__ import annotations

from typing import Any

import pytest

from armkit.devices.ssc32 import SSC32
from armkit.sim import World
from armkit.sim._wire import Wire, serial_port
from armkit.sim.ssc32 import SimSSC32

pytest.importorskip("serial")


class Board:
    def __init__(self) -> None:
        self.world = World()
        self.device = SimSSC32(9600)
        self.port: Any = serial_port(Wire(self.device, self.world, baudrate=9600, timeout=0.05))

    def ask(self, text: str, size: int = 64) -> bytes:
        self.port.write(text.encode("ascii") + b"\r")
        return bytes(self.port.read(size))


@pytest.fixture
def b() -> Board:
    return Board()


def test_digital_inputs_a_to_f_plain_and_latched(b: Board) -> None:
    """ "Digital Input": A B C D E F read "0"/"1"; AL .. FL read "0" if the input went low
    since the last latched read, which resets the latch; one character per input, no
    spaces."""
    assert b.ask("A B C D E F") == b"111111"
    b.device.set_input("E", False)
    b.device.set_input("E", True)  # a short low on E
    b.device.set_input("F", False)
    assert b.ask("E F EL FL") == b"1000"
    assert b.ask("EL FL") == b"10"  # E's latch was reset by the read; F is still low
    assert b.ask("ABEDL") == b"1111"  # the guide's example


def test_analog_inputs_va_to_vh_scale_5_256(b: Board) -> None:
    """ "Analog Inputs": VA .. VH one byte each; "multiply by 5/256" (255 = 4.98 V); the
    guide's example: 2 V and 3.5 V read 102 and 179."""
    for channel, volts in enumerate((2.0, 3.5, 0.0, 5.0, 2.0, 3.5, 4.98, 1.0)):
        b.device.analog[channel] = lambda v=volts: v
    assert list(b.ask("VA VB VC VD VE VF VG VH", 8)) == [102, 179, 0, 255, 102, 179, 254, 51]


def test_one_bad_query_does_not_silence_the_line(b: Board) -> None:
    """A line is a run of commands: a piece the board cannot read is skipped and the
    queries around it are answered (before, every query on such a line went unanswered)."""
    b.device.analog[0] = lambda: 2.0
    b.device.analog[1] = lambda: 3.5
    assert list(b.ask("VA XYZ VB", 2)) == [102, 179]
    assert b.ask("A ?? B") == b"11"
    assert len(b.device.errors) == 2


def test_register_read_write_and_defaults(b: Board) -> None:
    """ "Register Read/Write": R<r> displays the value in ASCII and CR; R<r>=<n> programs
    it (spaces optional: R32 = -50); RDFLT sets the defaults and answers OK CR; R4 holds
    the baud rate / 10 ("Baud")."""
    assert b.ask("R4") == b"960\r"
    assert b.ask("R0") == b"0\r"
    b.ask("R32 = -50")
    assert b.ask("R32") == b"-50\r"
    assert b.ask("R0=1023 R0") == b"1023\r"
    assert b.ask("RDFLT") == b"OK\r"
    assert b.ask("R32") == b"0\r" and b.ask("R1") == b"600\r"


def test_armkit_reads_ve_through_its_own_device_class(b: Board) -> None:
    """armkit's SSC32 device class converts a V* byte with 5/256 V per step."""
    b.device.analog[4] = lambda: 3.5
    board = SSC32(b.port, 9600)
    assert board.read_analog(4) == pytest.approx(179 * 5 / 256)
