"""The real SSC32 class (pyserial) against the emulator on a pseudo-terminal."""

from __future__ import annotations

from collections.abc import Iterator

import pytest

from armkit._errors import DeviceError
from armkit.devices.ssc32 import SSC32
from armkit.sim.emulators import SSC32Emulator


@pytest.fixture
def board(ssc32_emu: SSC32Emulator) -> Iterator[SSC32]:
    with SSC32(ssc32_emu.port, 9600, timeout_s=0.1) as device:
        yield device


def test_bytes_on_the_wire_are_exactly_the_commands(board: SSC32, ssc32_emu: SSC32Emulator) -> None:
    board.group_move({0: 1500, 1: 1000})
    board.group_move({0: 1600, 1: 1200}, 20, {1: 10000})
    board.query_pulses([0, 1])
    assert ssc32_emu.received == [b"#0P1500#1P1000\r", b"#0P1600#1P1200S10000T20\r", b"QP0QP1\r"]
    assert ssc32_emu.errors == []


def test_a_servo_never_commanded_reads_zero_then_its_pulse(board: SSC32) -> None:
    assert board.query_pulses([7]) == {7: 0}
    board.move(7, 1730)
    assert board.query_pulses([7]) == {7: 1730}


def test_group_move_starts_and_finishes_together(board: SSC32, ssc32_emu: SSC32Emulator) -> None:
    board.group_move({0: 1000, 1: 2000})
    board.group_move({0: 1100, 1: 1500}, time_ms=50)
    board.wait(timeout_s=2.0)
    record = ssc32_emu.history[-1]
    assert record.duration_s == pytest.approx(0.05)
    assert record.servos == {0: (1000, 1100), 1: (2000, 1500)}
    assert board.query_pulses([0, 1]) == {0: 1100, 1: 1500}


def test_a_speed_limit_stretches_the_group_time(board: SSC32, ssc32_emu: SSC32Emulator) -> None:
    board.group_move({0: 1000, 1: 1000})
    board.group_move({0: 1010, 1: 1500}, time_ms=10, speeds={1: 10000})
    board.is_moving()  # a reply: the emulator has read everything before it
    assert ssc32_emu.history[-1].duration_s == pytest.approx(0.05)  # 500 µs at 10000 µs/s


def test_query_reports_moving_until_the_time_is_up(board: SSC32) -> None:
    board.move(0, 1500)
    board.move(0, 1600, time_ms=300)
    assert board.is_moving() is True
    board.wait(timeout_s=2.0)
    assert board.is_moving() is False


def test_wait_gives_up_with_a_device_error(board: SSC32) -> None:
    board.move(0, 1500)
    board.move(0, 2500, time_ms=5000)
    with pytest.raises(DeviceError, match="still moving"):
        board.wait(timeout_s=0.05)
    board.stop([0])


def test_stop_holds_the_servo_part_way(board: SSC32) -> None:
    board.move(0, 1000)
    board.move(0, 2000, time_ms=10000)
    board.stop([0])
    held = board.query_pulses([0])[0]
    assert 1000 <= held < 1100
    assert board.query_pulses([0])[0] == held


def test_version_is_text(board: SSC32) -> None:
    assert board.version().startswith("SSC32")


@pytest.mark.parametrize("fault", ["drop", "late", "garbage"])
def test_one_bad_reply_is_retried(board: SSC32, ssc32_emu: SSC32Emulator, fault: str) -> None:
    board.move(3, 1200)
    ssc32_emu.inject(fault, delay_s=0.15)
    assert board.query_pulses([3]) == {3: 1200}
    assert ssc32_emu.received.count(b"QP3\r") == 2


@pytest.mark.parametrize("fault", ["drop", "late", "garbage"])
def test_bad_replies_every_time_raise_after_bounded_tries(
    board: SSC32, ssc32_emu: SSC32Emulator, fault: str
) -> None:
    ssc32_emu.inject(fault, count=3, delay_s=0.15)
    with pytest.raises(DeviceError, match=r"status query \(Q\): .* after 3 tries"):
        board.is_moving()
    assert ssc32_emu.received.count(b"Q\r") == 3


def test_moves_are_never_repeated_by_retries(board: SSC32, ssc32_emu: SSC32Emulator) -> None:
    ssc32_emu.inject("drop", count=3)
    board.move(0, 1500)
    with pytest.raises(DeviceError):
        board.query_pulses([0])
    assert ssc32_emu.received.count(b"#0P1500\r") == 1


@pytest.mark.parametrize("baud", [9600, 38400, 115200])
def test_the_baud_rate_must_match_the_board(baud: int) -> None:
    with SSC32Emulator(baud) as emu:
        with SSC32(emu.port, baud) as board:
            assert board.query_pulses([0]) == {0: 0}
        other = 9600 if baud != 9600 else 115200
        with (
            SSC32(emu.port, other, retries=0, timeout_s=0.05) as board,
            pytest.raises(DeviceError, match=f"baud rate \\({other}\\)"),
        ):
            board.is_moving()


def test_an_impossible_baud_rate_is_refused_before_opening() -> None:
    with pytest.raises(ValueError, match="19200"):
        SSC32("/nonexistent", 19200)


def test_a_missing_port_is_a_device_error() -> None:
    with pytest.raises(DeviceError, match="cannot open SSC-32 on /nonexistent"):
        SSC32("/nonexistent", 9600)
