"""Protocol 2.0 instructions on simulated XM430s as the ROBOTIS e-Manual gives them
("DYNAMIXEL Protocol 2.0", Instruction Details; "XM430-W350" for the Secondary ID),
through the official SDK and against the manual's example packets."""

from __future__ import annotations

import pytest
from dxl_bench import OK, PRESENT, TORQUE, Bench, sdk

from armkit.devices import dxl_packet as pkt
from armkit.sim import World
from armkit.sim.dynamixel import SimDynamixelBus


def manual_example_bus() -> SimDynamixelBus:
    """The Fast Sync/Bulk Read examples' servos: ID 3 at Present Position 166, ID 7 at
    2,079 with Present PWM 421, ID 4 at 1,023 with Present Temperature 31 [deg C]."""
    world = World()
    bus = SimDynamixelBus((3, 7, 4), clock=world.now)
    for sid, tick in ((3, 166), (7, 2079), (4, 1023)):
        bus.servos[sid].hold_at(tick)
    bus.servos[4].set("Present Temperature", 31)
    seven = bus.servos[7]
    seven.write(11, b"\x10")  # PWM Control Mode, Goal PWM 421: Present PWM 421
    seven.write(64, b"\x01")
    seven.write(100, (421).to_bytes(2, "little"))
    return bus


def answer(bus: SimDynamixelBus, frame: bytes) -> bytes:
    bus.receive(frame, 0.0)
    return bus.outbox.take(1.0)


def test_fast_sync_read_is_the_manuals_example() -> None:
    """ "Fast Sync Read (0x8A)" example: Present Position of IDs 3, 7, 4 in ONE status
    packet, each part ERR ID DATA CRC, not byte-stuffed (bytes as in the manual)."""
    bus = manual_example_bus()
    bus.servos[7].hold_at(2079)
    frame = pkt.encode(pkt.BROADCAST_ID, 0x8A, bytes((0x84, 0, 4, 0, 3, 7, 4)))
    expected = bytes.fromhex(
        "FF FF FD 00 FE 19 00 55 00 03 A6 00 00 00 84 08"
        " 00 07 1F 08 00 00 16 CA 00 04 FF 03 00 00 D1 9E"
    )
    assert answer(bus, frame) == expected


def test_fast_bulk_read_is_the_manuals_example() -> None:
    """ "Fast Bulk Read (0x9A)" example: ID 3 Present Position (132, 4 bytes) = 166, ID 7
    Present PWM (124, 2) = 421, ID 4 Present Temperature (146, 1) = 31, one packet."""
    bus = manual_example_bus()
    params = bytes.fromhex("03 84 00 04 00 07 7C 00 02 00 04 92 00 01 00")
    expected = bytes.fromhex(
        "FF FF FD 00 FE 14 00 55 00 03 A6 00 00 00 67 A4 00 07 A5 01 24 74 00 04 1F D9 C1"
    )
    assert answer(bus, pkt.encode(pkt.BROADCAST_ID, 0x9A, params)) == expected


def test_fast_bulk_and_sync_read_through_the_sdk() -> None:
    """The SDK's GroupBulkRead.fastBulkRead and GroupSyncRead.fastSyncRead read what the
    registers hold."""
    b = Bench()
    bulk = sdk.GroupBulkRead(b.port, b.ph)
    assert bulk.addParam(11, PRESENT, 4) and bulk.addParam(12, 0, 2) and bulk.addParam(13, 7, 1)
    assert bulk.fastBulkRead() == OK
    assert bulk.getData(11, PRESENT, 4) == 2048 and bulk.getData(12, 0, 2) == 1020
    assert bulk.getData(13, 7, 1) == 13
    sync = sdk.GroupSyncRead(b.port, b.ph, 7, 1)
    for sid in (11, 12, 14):
        sync.addParam(sid)
    assert sync.fastSyncRead() == OK
    assert [sync.getData(sid, 7, 1) for sid in (11, 12, 14)] == [11, 12, 14]


def test_fast_reads_need_firmware_45() -> None:
    """ "Fast Sync Read", "Fast Bulk Read": X430 series from firmware v45; older servos do
    not take part (here: no status packet at all)."""
    b = Bench(firmware=44)
    bulk = sdk.GroupBulkRead(b.port, b.ph)
    bulk.addParam(11, PRESENT, 4)
    assert bulk.fastBulkRead() == sdk.COMM_RX_TIMEOUT


def test_secondary_id_rules() -> None:
    """ "Secondary(Shadow) ID (12)": packets for it are executed without a status packet;
    the EEPROM area cannot be modified through it; 253 ~ 255 switch it off."""
    b = Bench()
    for sid in (11, 12):
        assert b.w(sid, 12, 1, 5) == (OK, 0)
    assert b.ph.write1ByteTxRx(b.port, 5, 65, 1)[0] == sdk.COMM_RX_TIMEOUT  # no status...
    assert (b.r(11, 65, 1), b.r(12, 65, 1), b.r(13, 65, 1)) == (1, 1, 0)  # ...but executed
    b.ph.write1ByteTxRx(b.port, 5, 9, 10)  # Return Delay Time: EEPROM, torque off
    assert (b.r(11, 9, 1), b.r(12, 9, 1)) == (250, 250)  # not executed
    assert b.w(11, 12, 1, 253) == (OK, 0)
    b.ph.write1ByteTxRx(b.port, 253, 65, 0)
    b.ph.write1ByteTxRx(b.port, 5, 65, 0)
    assert (b.r(11, 65, 1), b.r(12, 65, 1)) == (1, 0)


def test_broadcast_factory_reset_all_is_ignored_from_firmware_42() -> None:
    """ "Factory Reset (0x06)": with the Broadcast ID and option 0xFF (Reset all) it is
    not executed (MX(2.0) and X series firmware 42 or above); 0x01 still is."""
    b = Bench()
    b.w(11, 9, 1, 0)
    assert b.ph.factoryReset(b.port, sdk.BROADCAST_ID, 0xFF)[0] == OK
    assert b.r(11, 9, 1) == 0 and b.ph.ping(b.port, 12)[1] == OK
    assert b.ph.factoryReset(b.port, sdk.BROADCAST_ID, 0x02)[0] == OK
    assert b.r(11, 9, 1) == 250 and b.r(11, 7, 1) == 11


def test_broadcast_factory_reset_all_before_firmware_42() -> None:
    """The same broadcast on firmware 41 resets every servo to ID 1 at 57,600 bps."""
    b = Bench(firmware=41)
    b.ph.factoryReset(b.port, sdk.BROADCAST_ID, 0xFF)
    assert all(s.value("ID") == 1 and s.baudrate == 57_600 for s in b.bus.servos.values())
    assert b.ph.ping(b.port, 11)[1] == sdk.COMM_RX_TIMEOUT


def test_factory_reset_with_an_unknown_option() -> None:
    """ "Factory Reset (0x06)": options 0xFF, 0x01, 0x02; another: Data Range Error."""
    b = Bench()
    assert b.ph.factoryReset(b.port, 11, 0x03) == (OK, 4)
    assert b.r(11, 7, 1) == 11


def backup(b: Bench, sid: int, option: int, key: bytes = b"CTRL") -> tuple[int, int]:
    packet = [0] * 15
    packet[sdk.PKT_ID], packet[sdk.PKT_LENGTH_L], packet[sdk.PKT_INSTRUCTION] = sid, 8, 0x20
    packet[sdk.PKT_PARAMETER0 : sdk.PKT_PARAMETER0 + 5] = [option, *key]
    _, result, error = b.ph.txRxPacket(b.port, packet)
    return result, error


def test_control_table_backup_and_restore() -> None:
    """ "Control Table Backup (0x20)": needs torque off (else Result Fail); 0x01 stores
    (Backup Ready (147) reads 1), 0x02 restores the EEPROM area and reboots."""
    b = Bench()
    b.w(11, TORQUE, 1, 1)
    assert backup(b, 11, 0x01) == (OK, 1)
    b.w(11, TORQUE, 1, 0)
    assert b.r(11, 147, 1) == 0
    b.w(11, 9, 1, 100), b.w(11, 84, 2, 900)
    assert backup(b, 11, 0x01) == (OK, 0) and b.r(11, 147, 1) == 1
    b.w(11, 9, 1, 20), b.w(11, 65, 1, 1)
    assert backup(b, 11, 0x02) == (OK, 0)
    assert b.r(11, 9, 1) == 100 and b.r(11, 65, 1) == 0  # EEPROM back; rebooted (LED off)
    assert backup(b, 11, 0x03) == (OK, 4) and backup(b, 11, 0x01, b"XXXX") == (OK, 4)


@pytest.mark.parametrize("firmware", [44])
def test_backup_needs_firmware_45(firmware: int) -> None:
    """ "Control Table Backup (0x20)": X430 series from firmware v45; before, the
    instruction is undefined (Instruction Error)."""
    b = Bench(firmware=firmware)
    assert backup(b, 11, 0x01) == (OK, 2)
