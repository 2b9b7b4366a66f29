"""The simulated Mini Maestro 24 against the Pololu Maestro Servo Controller User's Guide,
spoken to by pyserial (through armkit's simulated line) in raw bytes."""

from __future__ import annotations

from typing import Any

import pytest

from armkit.sim import World
from armkit.sim._wire import Wire, serial_port
from armkit.sim.maestro import SimMaestro

pytest.importorskip("serial")


class Board:
    def __init__(self) -> None:
        self.world = World()
        self.device = SimMaestro()
        self.port: Any = serial_port(Wire(self.device, self.world, baudrate=9600, timeout=0.05))

    def send(self, *data: int) -> None:
        self.port.write(bytes(data))

    def target(self, ch: int, us: float) -> None:
        q = round(us * 4)
        self.send(0x84, ch, q & 0x7F, q >> 7)

    def position(self, ch: int) -> float:
        self.send(0x90, ch)
        return int.from_bytes(self.port.read(2), "little") / 4.0


@pytest.fixture
def b() -> Board:
    return Board()


def test_pololu_protocol_with_device_number(b: Board) -> None:
    """5.c "Serial Protocols", Pololu protocol: 0xAA, device number (factory 12), the
    command with its high bit cleared; other device numbers are for other boards."""
    q = 1600 * 4
    b.send(0xAA, 12, 0x04, 3, q & 0x7F, q >> 7)
    b.send(0xAA, 13, 0x04, 4, q & 0x7F, q >> 7)
    b.send(0xAA, 12, 0x10, 3)  # Get Position, Pololu protocol
    assert int.from_bytes(b.port.read(2), "little") == q
    assert b.position(4) == 0.0


def test_mini_ssc_protocol(b: Board) -> None:
    """5.c, Mini SSC protocol: 0xFF, servo number, 8-bit target: 127 = neutral (1500 µs),
    254 = neutral + range (factory range 476.25 µs, clamped by the channel's range)."""
    b.send(0xFF, 2, 127)
    assert b.position(2) == 1500.0
    b.send(0xFF, 2, 0)
    assert b.position(2) == 1023.75


def test_set_multiple_targets(b: Board) -> None:
    """5.e "Set Multiple Targets" (0x9F): count, first channel, then each target."""
    data = [0x9F, 3, 5]
    for us in (1000, 1500, 1900):
        data += [(us * 4) & 0x7F, (us * 4) >> 7]
    b.send(*data)
    assert [b.position(ch) for ch in (5, 6, 7)] == [1000.0, 1500.0, 1900.0]


def test_factory_range_992_2000_clamps_unless_widened(b: Board) -> None:
    """4.b "Channel Settings": Min/Max (factory 992..2000 µs); a target outside is clamped."""
    b.target(0, 900)
    b.target(1, 2200)
    assert (b.position(0), b.position(1)) == (992.0, 2000.0)
    b.device.configure(0, 500.0, 2500.0)
    b.target(0, 900)
    assert b.position(0) == 900.0


def test_an_error_sends_servos_home_and_go_home_turns_pulses_off(b: Board) -> None:
    """4.b "Errors": on any error every servo goes to its home setting (factory "Off"; "Ignore"
    leaves it); 5.e "Go Home" (0xA2) does the same."""
    for ch in (0, 1, 2):
        b.target(ch, 1500)
    b.device.configure(1, 992.0, 2000.0, home="ignore")
    b.device.configure(2, 992.0, 2000.0, home=1200.0)
    b.send(0x05)  # a data byte without a command: serial protocol error
    assert [b.position(ch) for ch in (0, 1, 2)] == [0.0, 1500.0, 1200.0]
    b.send(0xA1)
    assert int.from_bytes(b.port.read(2), "little") == 1 << 4
    b.target(0, 1500)
    b.send(0xA2)
    assert b.position(0) == 0.0


def test_acceleration_ramps_the_speed(b: Board) -> None:
    """5.e "Set Acceleration": the speed grows by the limit (0.25 µs/10 ms/80 ms units) so
    the pulse starts slowly: a quarter of the way in time is less than a quarter of the way."""
    b.target(0, 1000)
    b.send(0x89, 0, 4, 0)  # 4 units = 1250 µs/s^2
    b.target(0, 1800)  # triangular: 2 x sqrt(800 / 1250) = 1.6 s
    b.world.advance(0.4)
    early = b.position(0) - 1000
    assert 0 < early < 0.25 * 800 * 0.6
    b.world.advance(1.3)
    assert b.position(0) == 1800.0


def test_script_commands_leave_the_servos_alone(b: Board) -> None:
    """5.f "Serial Script Commands": Stop Script 0xA4 (Pololu 0xAA, n, 0x24), Restart
    Script at Subroutine 0xA7 n, with Parameter 0xA8 n lo hi, Get Script Status 0xAE
    (0x00 running, 0x01 stopped). None is an error and no servo moves or goes off."""
    b.device.script_subroutines = 2
    b.target(0, 1600)
    b.send(0xAE)
    assert b.port.read(1) == b"\x01"  # factory: the script is stopped
    b.send(0xA7, 1)
    b.send(0xAE)
    assert b.port.read(1) == b"\x00"
    b.send(0xA4)
    b.send(0xAA, 12, 0x2E)
    assert b.port.read(1) == b"\x01"
    b.send(0xA8, 0, 16383 & 0x7F, 16383 >> 7)
    b.send(0xAA, 12, 0x2E)
    assert b.port.read(1) == b"\x00"
    assert b.device.script_stack == [16383]
    b.send(0xAA, 12, 0x24)
    b.send(0xAE)
    assert b.port.read(1) == b"\x01"
    assert b.position(0) == 1600.0
    b.send(0xA1)  # Get Errors: none
    assert b.port.read(2) == b"\x00\x00"


def test_a_subroutine_the_script_lacks_leaves_it_stopped(b: Board) -> None:
    """5.f: subroutines are numbered in the order the script defines them; the factory
    script defines none, so restarting at one leaves the script stopped (no error bit:
    the guide names none), and the servos as they were."""
    b.target(3, 1500)
    b.send(0xA7, 0)
    b.send(0xA8, 5, 1, 0)
    b.send(0xAE)
    assert b.port.read(1) == b"\x01"
    assert b.position(3) == 1500.0
    b.send(0xA1)
    assert b.port.read(2) == b"\x00\x00"
