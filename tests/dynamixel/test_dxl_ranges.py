"""Every writable XM430-W350 register refuses what the e-Manual's Range column refuses,
with the Protocol 2.0 error number, through the official SDK's packet handler.

The ranges below are copied from the ROBOTIS e-Manual, "XM430-W350", "Control Table
of EEPROM Area" / "Control Table of RAM Area" (Range column), independently of
armkit's own table, so a wrong rule there fails here. Errors: "DYNAMIXEL Protocol
2.0", Status Packet, Error (4 Data Range, 5 Data Length, 6 Data Limit, 7 Access,
2 Instruction).
"""

from __future__ import annotations

import pytest
from dxl_bench import GOAL, OK, PRESENT, TORQUE, Bench, sdk

# (name, address, size, low, high, safe): the manual's Range column. ``safe``: writing
# the ends is harmless to the next request (not the ID, the baud rate, the protocol,
# the status level, or a torque the next write would need off).
RANGE_COLUMN = [
    ("ID", 7, 1, 0, 252, False),
    ("Baud Rate", 8, 1, 0, 7, False),
    ("Return Delay Time", 9, 1, 0, 254, True),
    ("Protocol Type", 13, 1, 1, 2, False),
    ("Homing Offset", 20, 4, -1_044_479, 1_044_479, True),
    ("Moving Threshold", 24, 4, 0, 1_023, True),
    ("Temperature Limit", 31, 1, 0, 100, True),
    ("Max Voltage Limit", 32, 2, 95, 160, True),
    ("Min Voltage Limit", 34, 2, 95, 160, True),
    ("PWM Limit", 36, 2, 0, 885, True),
    ("Current Limit", 38, 2, 0, 1_193, True),
    ("Velocity Limit", 44, 4, 0, 1_023, True),
    ("Max Position Limit", 48, 4, 0, 4_095, True),
    ("Min Position Limit", 52, 4, 0, 4_095, True),
    ("Torque Enable", 64, 1, 0, 1, False),
    ("LED", 65, 1, 0, 1, True),
    ("Status Return Level", 68, 1, 0, 2, False),
    ("Velocity I Gain", 76, 2, 0, 16_383, True),
    ("Velocity P Gain", 78, 2, 0, 16_383, True),
    ("Position D Gain", 80, 2, 0, 16_383, True),
    ("Position I Gain", 82, 2, 0, 16_383, True),
    ("Position P Gain", 84, 2, 0, 16_383, True),
    ("Feedforward 2nd Gain", 88, 2, 0, 16_383, True),
    ("Feedforward 1st Gain", 90, 2, 0, 16_383, True),
    ("Bus Watchdog", 98, 1, 0, 127, True),
    ("Profile Acceleration", 108, 4, 0, 32_767, True),
    ("Profile Velocity", 112, 4, 0, 32_767, True),
    ("Indirect Address 1", 168, 2, 64, 661, True),
    ("Indirect Address 56", 632, 2, 64, 661, True),
]


@pytest.mark.parametrize(("name", "address", "size", "low", "high", "safe"), RANGE_COLUMN)
def test_the_range_column(
    name: str, address: int, size: int, low: int, high: int, safe: bool
) -> None:
    """XM430-W350 control table, Range column: one beyond either end is a Data Range
    Error (4) and changes nothing; the ends themselves are taken."""
    b = Bench()
    before = b.r(11, address, size)
    for beyond in (low - 1, high + 1):
        if beyond.bit_length() < 8 * size:  # one that the register's bytes can carry
            assert b.w(11, address, size, beyond) == (OK, 4), beyond
    assert b.r(11, address, size) == before
    if safe:
        for end in (low, high):
            assert b.w(11, address, size, end) == (OK, 0)
            assert b.r(11, address, size) == end


@pytest.mark.parametrize(
    ("name", "address", "value"),
    [("ID", 7, 254), ("ID", 7, 253), ("Baud Rate", 8, 8), ("Torque Enable", 64, 2),
     ("Status Return Level", 68, 3), ("Return Delay Time", 9, 255), ("Bus Watchdog", 98, 128),
     ("Operating Mode", 11, 2), ("Operating Mode", 11, 17), ("Drive Mode", 10, 0x02),
     ("Drive Mode", 10, 0x10), ("Startup Configuration", 60, 0x04)],
)  # fmt: skip
def test_values_that_would_lose_the_servo_are_refused(name: str, address: int, value: int) -> None:
    """XM430-W350 "ID (7)" 0 ~ 252 (254 is the broadcast ID), "Baud Rate (8)" 0 ~ 7,
    "Operating Mode (11)" 0, 1, 3, 4, 5, 16, "Drive Mode (10)" bits 0, 2, 3 (the others
    unused, always 0), ...: refused with Data Range Error, and the servo still answers
    at its ID and rate."""
    b = Bench()
    assert b.w(11, address, 1, value) == (OK, 4)
    assert b.ph.ping(b.port, 11) == (1020, OK, 0)
    assert b.r(11, address, 1) != value


def test_time_based_profiles_stop_at_32737() -> None:
    """XM430-W350 "Profile Velocity (112)", "Profile Acceleration (108)": time-based
    profile (Drive Mode bit 2): 0 ~ 32,737 [ms]; velocity-based: 0 ~ 32,767."""
    b = Bench()
    assert b.w(11, 112, 4, 32_767) == (OK, 0)
    assert b.w(11, 10, 1, 4) == (OK, 0)
    for address in (108, 112):
        assert b.w(11, address, 4, 32_738) == (OK, 4)
        assert b.w(11, address, 4, 32_737) == (OK, 0)


def test_goal_position_in_position_mode_is_within_the_position_limits() -> None:
    """XM430-W350 "Goal Position (116)": in Position Control Mode, Min Position Limit (52)
    ~ Max Position Limit (48); beyond: Data Limit Error (6)."""
    b = Bench()
    assert b.w(11, 48, 4, 3000) == (OK, 0) and b.w(11, 52, 4, 1000) == (OK, 0)
    b.w(11, TORQUE, 1, 1)
    assert b.w(11, GOAL, 4, 3001) == (OK, 6) and b.w(11, GOAL, 4, 999) == (OK, 6)
    assert b.w(11, GOAL, 4, 3000) == (OK, 0)


def test_a_write_shorter_than_its_register_is_a_data_length_error() -> None:
    """Protocol 2.0 Status Packet, Error 5 Data Length Error: "when you attempt to only use
    2 bytes of an item that has been defined as 4 bytes"; the register keeps its value."""
    b = Bench()
    assert b.raw(11, GOAL, b"\x00\x01") == (OK, 5)  # 2 of Goal Position's 4 bytes
    assert b.raw(11, GOAL + 1, b"\x00\x01\x00") == (OK, 5)  # starting inside it
    assert b.raw(11, 108, b"\x00\x00\x00\x00\x01") == (OK, 5)  # one byte into the next
    assert b.r(11, GOAL, 4) == 2048
    assert b.raw(11, 65, b"\x01") == (OK, 0)


def test_indirect_data_must_cover_the_whole_register() -> None:
    """XM430-W350 "Indirect Address", NOTE: an item longer than a byte needs all its
    addresses allocated; one byte of Goal Position through Indirect Data 1 is a partial
    write (Data Length Error)."""
    b = Bench()
    assert b.w(11, 168, 2, GOAL) == (OK, 0)  # Indirect Data 1 -> Goal Position's first byte
    assert b.w(11, 224, 1, 7) == (OK, 5)


def test_indirect_address_cannot_point_into_the_eeprom() -> None:
    """XM430-W350 "Indirect Address": 64 ~ 661, "EEPROM address can't be assigned"."""
    b = Bench()
    for eeprom in (7, 8, 11, 63):
        assert b.w(11, 168, 2, eeprom) == (OK, 4)
    assert b.r(11, 168, 2) == 224


def test_access_errors() -> None:
    """Protocol 2.0 Error 7 Access Error: a read-only address, an undefined one, and the
    EEPROM area with torque on ("XM430-W350", CAUTION: EEPROM writable only with Torque
    Enable 0)."""
    b = Bench()
    assert b.w(11, PRESENT, 4, 0) == (OK, 7)  # read-only
    assert b.w(11, 0, 2, 1) == (OK, 7)  # Model Number
    assert b.w(11, 14, 1, 0) == (OK, 7)  # 14..19: no register
    b.w(11, TORQUE, 1, 1)
    assert b.w(11, 9, 1, 100) == (OK, 7)
    assert b.r(11, 9, 1) == 250


def test_undefined_instruction_and_action_without_reg_write() -> None:
    """Protocol 2.0 Error 2 Instruction Error: "Undefined Instruction has been used",
    "Action has been used without Reg Write"."""
    b = Bench()
    undefined = [0] * 10
    undefined[sdk.PKT_ID], undefined[sdk.PKT_LENGTH_L], undefined[sdk.PKT_INSTRUCTION] = 11, 3, 0x07
    _, result, error = b.ph.txRxPacket(b.port, undefined)
    assert (result, error) == (OK, 2)
    assert action_status(b, 11) == 2
    b.ph.regWriteTxRx(b.port, 11, 65, 1, [1])
    assert action_status(b, 11) == 0 and b.r(11, 65, 1) == 1
    assert action_status(b, 11) == 2  # the registered write was used up


def action_status(b: Bench, sid: int) -> int:
    """ACTION to ``sid`` and its status packet's error (the SDK's action() does not read
    the status: its own txPacket/rxPacket do)."""
    packet = [0] * 10
    packet[sdk.PKT_ID], packet[sdk.PKT_LENGTH_L], packet[sdk.PKT_INSTRUCTION] = sid, 3, 0x05
    assert b.ph.txPacket(b.port, packet) == OK
    b.port.setPacketTimeout(11)
    status, result = b.ph.rxPacket(b.port, False)
    b.port.is_using = False
    assert result == OK
    return int(status[sdk.PKT_ERROR])
