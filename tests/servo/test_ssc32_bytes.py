"""SSC-32 command bytes, exactly as the SSC-32U user guide writes them."""

from __future__ import annotations

import pytest

from armkit.devices.ssc32 import (
    group_move_bytes,
    parse_pulses,
    parse_status,
    query_pulse_bytes,
    stop_bytes,
)


def test_single_move_with_speed_is_the_guides_example_1() -> None:
    assert group_move_bytes({5: 1500}, speeds={5: 750}) == b"#5P1500S750\r"


def test_single_move_with_time_is_the_guides_example_2() -> None:
    assert group_move_bytes({3: 1600}, time_ms=1000) == b"#3P1600T1000\r"


def test_group_move_has_one_clause_per_servo_and_one_time() -> None:
    data = group_move_bytes({5: 1600, 17: 750, 2: 2250}, time_ms=2000, speeds={17: 500})
    assert data == b"#5P1600#17P750S500#2P2250T2000\r"


def test_pulse_query_asks_every_channel_on_one_line() -> None:
    assert query_pulse_bytes([0, 1, 31]) == b"QP0QP1QP31\r"


def test_stop_names_the_channel() -> None:
    assert stop_bytes(4) == b"STOP4\r"


@pytest.mark.parametrize(
    ("pulses", "time_ms", "speeds", "words"),
    [
        ({0: 499}, None, None, "499"),
        ({0: 2501}, None, None, "2501"),
        ({32: 1500}, None, None, "channel 32"),
        ({-1: 1500}, None, None, "channel -1"),
        ({0: 1500}, 0, None, "move time 0"),
        ({0: 1500}, 65536, None, "65536"),
        ({0: 1500}, None, {0: 0}, "speed of channel 0"),
        ({0: 1500}, None, {1: 100}, "channel 1, which is not in the move"),
        ({}, None, None, "at least one servo"),
        ({0: 1500.5}, None, None, "1500.5"),
    ],
)
def test_out_of_range_values_are_refused_with_the_value_named(
    pulses: dict[int, int], time_ms: int | None, speeds: dict[int, int] | None, words: str
) -> None:
    with pytest.raises(ValueError, match=words):
        group_move_bytes(pulses, time_ms, speeds)


def test_status_reply_dot_means_done_plus_means_moving() -> None:
    assert parse_status(b".") is False
    assert parse_status(b"+") is True
    with pytest.raises(ValueError):
        parse_status(b"\xff")


def test_pulse_reply_is_ten_microseconds_per_unit() -> None:
    assert parse_pulses(bytes([150, 0, 250]), [0, 1, 2]) == {0: 1500, 1: 0, 2: 2500}
    with pytest.raises(ValueError):
        parse_pulses(bytes([255]), [0])
    with pytest.raises(ValueError):
        parse_pulses(bytes([150]), [0, 1])
