"""The simulated XM430-W350 against the ROBOTIS e-Manual, driven by the official
dynamixel-sdk (its PacketHandler and group classes, unmodified) over a simulated line.

Sections cited: e-Manual "XM430-W350" (Control Table) and "DYNAMIXEL Protocol 2.0"
(Instruction, Status Packet).
"""

from __future__ import annotations

import pytest
from dxl_bench import GOAL, MOVING_STATUS, OK, PRESENT, TORQUE, Bench, sdk


@pytest.fixture
def b() -> Bench:
    return Bench()


def test_moving_status_bits_during_and_after_a_profile(b: Bench) -> None:
    """XM430-W350 "Moving Status (123)": bit 0 in-position, bit 1 profile ongoing,
    bits 5..4 velocity profile type (3 trapezoidal, 2 triangular, 1 rectangular)."""
    b.w(11, 108, 4, 20), b.w(11, 112, 4, 100), b.w(11, TORQUE, 1, 1)
    b.w(11, GOAL, 4, 3048)
    during = b.r(11, MOVING_STATUS, 1)
    assert during & 0x02 and not during & 0x01 and during >> 4 == 3
    b.world.advance(5.0)
    after = b.r(11, MOVING_STATUS, 1)
    assert after & 0x01 and not after & 0x02 and after >> 4 == 3
    b.w(11, 108, 4, 0)
    b.w(11, GOAL, 4, 2048)  # no acceleration: rectangular
    assert b.r(11, MOVING_STATUS, 1) >> 4 == 1
    b.world.advance(5.0)
    b.w(11, 108, 4, 20), b.w(11, GOAL, 4, 2060)  # too short to reach the velocity
    assert b.r(11, MOVING_STATUS, 1) >> 4 == 2


def test_realtime_tick_counts_milliseconds_modulo_32768(b: Bench) -> None:
    """XM430-W350 "Realtime Tick (120)": 0..32,767 ms, then from 0 again."""
    first = b.r(11, 120, 2)
    b.world.advance(0.25)
    assert (b.r(11, 120, 2) - first) % 32768 in range(249, 253)
    b.world.advance(32.768)
    assert (b.r(11, 120, 2) - first) % 32768 in range(249, 256)


def test_velocity_and_position_trajectory_follow_the_profile(b: Bench) -> None:
    """XM430-W350 "Velocity Trajectory (136)", "Position Trajectory (140)": the desired
    velocity and position the profile generates."""
    b.w(11, 10, 1, 4), b.w(11, 108, 4, 200), b.w(11, 112, 4, 1000), b.w(11, TORQUE, 1, 1)
    b.w(11, GOAL, 4, 3048)  # 1000 ticks in 1 s, 0.2 s ramps: peak 1250 tick/s
    b.world.advance(0.5)
    assert abs(b.r(11, 140, 4) - 2548) <= 2
    assert abs(b.r(11, 136, 4) - round(1250 / (0.229 * 4096 / 60))) <= 1
    b.world.advance(1.0)
    assert b.r(11, 140, 4) == 3048 and b.r(11, 136, 4) == 0


def test_homing_offset_is_added_to_present_position(b: Bench) -> None:
    """XM430-W350 "Homing Offset (20)": Present Position = actual position + Homing Offset."""
    assert b.r(12, PRESENT, 4) == 2048
    assert b.w(12, 20, 4, 1000) == (OK, 0)
    assert b.r(12, PRESENT, 4) == 3048
    assert b.w(12, 20, 4, -48) == (OK, 0)
    assert b.r(12, PRESENT, 4) == 2000


@pytest.mark.parametrize(("mode", "goal", "error"), [
    (3, 4096, 6), (3, 4095, 0), (4, 1_048_575, 0), (4, 1_048_576, 6),
    (5, -1_048_575, 0), (5, -1_048_576, 6),
])  # fmt: skip
def test_goal_position_limits_per_operating_mode(
    b: Bench, mode: int, goal: int, error: int
) -> None:
    """XM430-W350 "Goal Position (116)": Min/Max Position Limit in position control mode;
    -1,048,575..1,048,575 in extended and current-based position control mode;
    outside: Data Limit Error (6)."""
    assert b.w(13, 11, 1, mode) == (OK, 0)
    b.w(13, TORQUE, 1, 1)
    assert b.w(13, GOAL, 4, goal) == (OK, error)


@pytest.mark.parametrize(
    ("address", "size", "limit_address"), [(104, 4, 44), (102, 2, 38), (100, 2, 36)]
)
def test_goal_velocity_current_pwm_beyond_their_limits_answer_error_6(
    b: Bench, address: int, size: int, limit_address: int
) -> None:
    """XM430-W350 "Goal Velocity (104)", "Goal Current (102)", "Goal PWM (100)": bounded by
    Velocity Limit (44), Current Limit (38), PWM Limit (36); beyond: Data Limit Error."""
    limit = b.r(14, limit_address, 4 if limit_address == 44 else 2)
    assert b.w(14, address, size, limit) == (OK, 0)
    assert b.w(14, address, size, -limit) == (OK, 0)
    assert b.w(14, address, size, limit + 1) == (OK, 6)
    assert b.r(14, address, size) == -limit  # the refused write changed nothing


def test_status_return_level_0_and_1(b: Bench) -> None:
    """XM430-W350 "Status Return Level (68)": 0 answers PING only; 1 PING and READ; 2 all."""
    assert b.w(11, 68, 1, 1)[0] == sdk.COMM_RX_TIMEOUT  # already at level 1 when it answers
    assert b.r(11, PRESENT, 4) == 2048
    assert b.ph.write1ByteTxRx(b.port, 11, 65, 1)[0] == sdk.COMM_RX_TIMEOUT  # no status...
    assert b.bus.servos[11].value("LED") == 1  # ...but executed
    assert b.ph.write1ByteTxRx(b.port, 11, 68, 0)[0] == sdk.COMM_RX_TIMEOUT
    assert b.ph.read4ByteTxRx(b.port, 11, PRESENT)[1] == sdk.COMM_RX_TIMEOUT
    assert b.ph.ping(b.port, 11) == (1020, OK, 0)


def test_secondary_id_executes_without_status(b: Bench) -> None:
    """XM430-W350 "Secondary ID (12)": servos sharing a Secondary ID execute packets for it
    together, and return no status packet for them."""
    for sid in (11, 12):
        assert b.w(sid, 12, 1, 5) == (OK, 0)
    assert b.ph.write1ByteTxRx(b.port, 5, 65, 1)[0] == sdk.COMM_RX_TIMEOUT
    assert [b.bus.servos[s].value("LED") for s in (11, 12, 13)] == [1, 1, 0]


def test_baud_rate_register_is_the_rate_answered_and_a_wrong_rate_gets_nothing() -> None:
    """XM430-W350 "Baud Rate (8)": 3 = 1 Mbps, 1 = 57,600 bps; a host at another rate is
    not understood."""
    b = Bench()
    assert b.r(11, 8, 1) == 3
    assert b.w(11, 8, 1, 1) == (OK, 0)  # the status still goes out at the old rate
    assert b.ph.ping(b.port, 11)[1] == sdk.COMM_RX_TIMEOUT
    assert b.ph.ping(b.port, 12) == (1020, OK, 0)
    slow = Bench(baudrate=57_600)
    assert slow.ph.ping(slow.port, 11)[1] == sdk.COMM_RX_TIMEOUT and slow.wire.misheard > 0


def test_bulk_read_and_bulk_write(b: Bench) -> None:
    """Protocol 2.0 "Bulk Read (0x92)", "Bulk Write (0x93)": a block per ID in one packet."""
    write = sdk.GroupBulkWrite(b.port, b.ph)
    assert write.addParam(11, 65, 1, [1]) and write.addParam(
        12, 20, 4, list((100).to_bytes(4, "little"))
    )
    assert write.txPacket() == OK
    read = sdk.GroupBulkRead(b.port, b.ph)
    assert read.addParam(11, 65, 1) and read.addParam(12, PRESENT, 4) and read.addParam(13, 0, 2)
    assert read.txRxPacket() == OK
    assert read.getData(11, 65, 1) == 1 and read.getData(12, PRESENT, 4) == 2148
    assert read.getData(13, 0, 2) == 1020


def test_fast_sync_read_one_status_packet(b: Bench) -> None:
    """Protocol 2.0 "Fast Sync Read (0x8A)": one status packet (ID 0xFE) holding every
    servo's ERR, ID, data and CRC."""
    b.w(13, 20, 4, 7)
    group = sdk.GroupSyncRead(b.port, b.ph, PRESENT, 4)
    for sid in (11, 13, 15):
        group.addParam(sid)
    assert group.fastSyncRead() == OK
    assert [group.getData(s, PRESENT, 4) for s in (11, 13, 15)] == [2048, 2055, 2048]
    assert b.bus.frames[-1][7] == 0x8A


def test_reg_write_waits_for_action(b: Bench) -> None:
    """Protocol 2.0 "Reg Write (0x04)" / "Action (0x05)": the write is held (Registered
    Instruction (69) = 1) until ACTION, then executed."""
    assert b.ph.regWriteTxRx(b.port, 11, 65, 1, [1]) == (OK, 0)
    assert b.r(11, 69, 1) == 1 and b.r(11, 65, 1) == 0
    assert b.ph.action(b.port, sdk.BROADCAST_ID) == OK
    assert b.r(11, 65, 1) == 1 and b.r(11, 69, 1) == 0


def test_factory_reset_options(b: Bench) -> None:
    """Protocol 2.0 "Factory Reset (0x06)": 0x02 keeps ID and Baud Rate, 0x01 keeps the ID,
    0xFF resets everything (ID 1, 57,600 bps)."""
    b.w(11, 9, 1, 0)
    assert b.ph.factoryReset(b.port, 11, 0x02) == (OK, 0)
    assert b.r(11, 9, 1) == 250 and b.r(11, 8, 1) == 3
    assert b.ph.factoryReset(b.port, 11, 0x01) == (OK, 0)
    assert b.ph.ping(b.port, 11)[1] == sdk.COMM_RX_TIMEOUT  # now at 57,600 bps
    assert b.ph.factoryReset(b.port, 12, 0xFF) == (OK, 0)
    assert b.bus.servos[12].value("ID") == 1 and b.bus.servos[12].baudrate == 57_600


def test_reboot_clears_the_error_and_the_ram(b: Bench) -> None:
    """Protocol 2.0 "Reboot (0x08)"; XM430-W350 RAM area back to its initial values."""
    b.w(11, TORQUE, 1, 1), b.w(11, 65, 1, 1)
    b.bus.inject(11, "overload")
    assert b.ph.reboot(b.port, 11) == (OK, sdk.ERRBIT_ALERT)
    assert b.r(11, 70, 1) == 0 and b.r(11, 65, 1) == 0 and b.r(11, TORQUE, 1) == 0


def test_clear_multi_turn(b: Bench) -> None:
    """Protocol 2.0 "Clear (0x10)": Present Position back within one turn; refused (Result
    Fail) while moving."""
    b.w(11, 11, 1, 4), b.w(11, TORQUE, 1, 1), b.w(11, GOAL, 4, 3 * 4096 + 100)
    assert b.ph.clearMultiTurn(b.port, 11) == (OK, 1)
    b.world.advance(10.0)
    assert b.r(11, PRESENT, 4) == 3 * 4096 + 100
    assert b.ph.clearMultiTurn(b.port, 11) == (OK, 0)
    assert b.r(11, PRESENT, 4) == 100 and b.r(11, GOAL, 4) == 100


def test_feedforward_gains_are_registers(b: Bench) -> None:
    """XM430-W350 "Feedforward 2nd Gain (88)", "Feedforward 1st Gain (90)": RAM, 0..16,383."""
    assert b.w(11, 88, 2, 1234) == (OK, 0) and b.w(11, 90, 2, 321) == (OK, 0)
    assert (b.r(11, 88, 2), b.r(11, 90, 2)) == (1234, 321)


def test_indirect_address_and_data_read_and_write_through(b: Bench) -> None:
    """XM430-W350 "Indirect Address, Indirect Data" (168..251, 578..661): Indirect Data n
    reads and writes the byte Indirect Address n names (ROBOTIS's software reads
    Present Position and writes Goal Position this way)."""
    for k in range(4):
        assert b.w(11, 168 + 2 * k, 2, PRESENT + k) == (OK, 0)  # Indirect Data 1..4
        assert b.w(11, 578 + 2 * k, 2, GOAL + k) == (OK, 0)  # Indirect Data 29..32
    b.w(11, TORQUE, 1, 1)
    assert b.r(11, 224, 4) == 2048
    assert b.w(11, 634, 4, 2500) == (OK, 0)  # a goal, through the indirect data
    b.world.advance(5.0)
    assert b.r(11, 224, 4) == 2500 and b.r(11, GOAL, 4) == 2500
    assert b.w(11, 634, 4, 5000) == (OK, 6)  # the goal's limits still apply
