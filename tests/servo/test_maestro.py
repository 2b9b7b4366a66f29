"""Pololu Maestro compact protocol: bytes, and the real Maestro class against its emulator."""

from __future__ import annotations

from collections.abc import Iterator

import pytest

from armkit._errors import DeviceError
from armkit.devices.maestro import (
    Maestro,
    acceleration_bytes,
    parse_moving,
    parse_position,
    position_query_bytes,
    speed_bytes,
    speed_units,
    target_bytes,
)
from armkit.sim.emulators import PROTOCOL_ERROR, MaestroEmulator


@pytest.fixture
def maestro(maestro_emu: MaestroEmulator) -> Iterator[Maestro]:
    with Maestro(maestro_emu.port, timeout_s=0.1) as device:
        yield device


def test_set_target_is_quarter_microseconds_in_two_seven_bit_bytes() -> None:
    # Pololu's example: 1500 µs = 6000 quarter-µs = 0x1770 -> lo 0x70, hi 0x2E
    assert target_bytes(0, 1500) == bytes([0x84, 0x00, 0x70, 0x2E])
    assert target_bytes(5, 1500.25) == bytes([0x84, 0x05, 0x71, 0x2E])


def test_speed_acceleration_and_queries() -> None:
    assert speed_bytes(1, 140) == bytes([0x87, 0x01, 0x0C, 0x01])
    assert acceleration_bytes(2, 4) == bytes([0x89, 0x02, 0x04, 0x00])
    assert position_query_bytes(3) == bytes([0x90, 0x03])


@pytest.mark.parametrize(("channel", "pulse"), [(0, 499.0), (0, 2500.5), (24, 1500.0), (-1, 1500)])
def test_out_of_range_targets_are_refused(channel: int, pulse: float) -> None:
    with pytest.raises(ValueError):
        target_bytes(channel, pulse)


def test_replies_are_parsed_and_impossible_ones_refused() -> None:
    assert parse_position(bytes([0x70, 0x17])) == 1500.0
    assert parse_moving(b"\x01") is True
    with pytest.raises(ValueError):
        parse_position(b"\xff\xff")
    with pytest.raises(ValueError):
        parse_moving(b"\x02")


def test_speed_units_never_exceed_the_asked_rate() -> None:
    assert speed_units(100.0, 1.0) == 4  # 100 µs/s = 4 x 25 µs/s
    assert speed_units(110.0, 1.0) == 4  # rounded down: slower, never faster
    assert speed_units(1.0, 10.0) == 1  # never 0, which would mean unlimited


def test_targets_and_positions_round_trip(maestro: Maestro, maestro_emu: MaestroEmulator) -> None:
    assert maestro.get_position(4) == 0.0
    maestro.set_target(4, 1234.75)
    assert maestro.get_position(4) == 1234.75
    assert maestro_emu.received == [b"\x90\x04", b"\x84\x04\x4b\x26", b"\x90\x04"]


def test_group_move_sets_speeds_so_servos_arrive_together(
    maestro: Maestro, maestro_emu: MaestroEmulator
) -> None:
    maestro.group_move({0: 1000, 1: 2000})
    maestro.group_move({0: 1100, 1: 1500}, time_ms=100)
    maestro.is_moving()  # a reply: the emulator has read everything before it
    assert maestro_emu.speed[:2] == [40, 200]  # 1000 and 5000 µs/s in 25 µs/s units
    assert [r.duration_s for r in maestro_emu.history[-2:]] == [pytest.approx(0.1)] * 2
    maestro.wait(timeout_s=2.0)
    assert not maestro.is_moving()
    assert (maestro.get_position(0), maestro.get_position(1)) == (1100.0, 1500.0)


def test_stop_holds_where_the_servo_is(maestro: Maestro) -> None:
    maestro.set_target(0, 1000)
    maestro.set_speed(0, 1)
    maestro.set_target(0, 2000)
    maestro.stop([0])
    maestro.wait(timeout_s=1.0)
    held = maestro.get_position(0)
    assert 1000 <= held < 1010
    assert maestro.get_position(0) == held


@pytest.mark.parametrize("fault", ["drop", "late", "garbage"])
def test_one_bad_reply_is_retried(
    maestro: Maestro, maestro_emu: MaestroEmulator, fault: str
) -> None:
    maestro.set_target(2, 1600)
    maestro_emu.inject(fault, delay_s=0.15)
    assert maestro.get_position(2) == 1600.0


def test_bad_replies_every_time_raise(maestro: Maestro, maestro_emu: MaestroEmulator) -> None:
    maestro_emu.inject("garbage", count=3)
    with pytest.raises(DeviceError, match=r"Maestro .* after 3 tries"):
        maestro.is_moving()


def test_a_broken_packet_sets_the_protocol_error_and_resyncs(
    maestro: Maestro, maestro_emu: MaestroEmulator
) -> None:
    maestro._link.write(bytes([0x84, 0x00]))  # a target cut short
    assert maestro.get_position(0) == 0.0
    assert maestro.errors() == PROTOCOL_ERROR
    assert maestro.errors() == 0
