"""The official dynamixel-sdk, unmodified, talks to the emulator through the pty's path."""

from __future__ import annotations

import time
from collections.abc import Iterator
from typing import Any

import pytest

from armkit.devices import _dxl_packet as pkt
from armkit.sim.emulators import DynamixelEmulator
from armkit.sim.xm430 import XM430, Profile, velocity_profile_times

sdk = pytest.importorskip("dynamixel_sdk")


@pytest.fixture
def sdk_port(emu: DynamixelEmulator) -> Iterator[tuple[Any, Any]]:
    port = sdk.PortHandler(emu.port)
    assert port.openPort() and port.setBaudRate(1_000_000)
    yield port, sdk.PacketHandler(2.0)
    port.closePort()


def test_sdk_ping_write_goal_and_sync_read(emu: DynamixelEmulator, sdk_port: Any) -> None:
    port, ph = sdk_port
    assert ph.ping(port, 11) == (1020, sdk.COMM_SUCCESS, 0)
    assert ph.ping(port, 1)[1] == sdk.COMM_RX_TIMEOUT  # nobody at ID 1
    assert ph.write1ByteTxRx(port, 12, 10, 4) == (sdk.COMM_SUCCESS, 0)  # time-based profile
    assert ph.write4ByteTxRx(port, 12, 112, 100) == (sdk.COMM_SUCCESS, 0)  # 100 ms
    assert ph.write1ByteTxRx(port, 12, 64, 1) == (sdk.COMM_SUCCESS, 0)
    assert ph.write4ByteTxRx(port, 12, 116, 1000) == (sdk.COMM_SUCCESS, 0)
    while ph.read1ByteTxRx(port, 12, 122)[0]:
        time.sleep(0.01)
    group = sdk.GroupSyncRead(port, ph, 132, 4)
    for sid in (11, 12, 13, 14):
        group.addParam(sid)
    assert group.txRxPacket() == sdk.COMM_SUCCESS
    assert [group.getData(sid, 132, 4) for sid in (11, 12, 13, 14)] == [2048, 1000, 2048, 2048]


def test_sdk_sync_write_moves_only_servos_with_torque(
    emu: DynamixelEmulator, sdk_port: Any
) -> None:
    port, ph = sdk_port
    for sid in (11, 13):
        ph.write1ByteTxRx(port, sid, 64, 1)
    group = sdk.GroupSyncWrite(port, ph, 116, 4)
    for sid, goal in ((11, 2100), (13, 2000), (14, 3000)):
        group.addParam(sid, list(goal.to_bytes(4, "little")))
    assert group.txPacket() == sdk.COMM_SUCCESS
    time.sleep(0.05)
    with emu.lock:
        assert emu.servos[11].get("Goal Position") == 2100
        assert emu.servos[13].get("Goal Position") == 2000
        assert emu.servos[14].get("Goal Position") == 3000  # stored, but torque is off:
        assert emu.servos[14].get("Present Position") == 2048  # no motion
        assert emu.servos[14].plans == 0


def test_sdk_broadcast_ping_and_reboot(sdk_port: Any) -> None:
    port, ph = sdk_port
    found, result = ph.broadcastPing(port)
    assert result == sdk.COMM_SUCCESS and sorted(found) == [11, 12, 13, 14, 15]
    assert ph.reboot(port, 15) == (sdk.COMM_SUCCESS, 0)


def test_eeprom_is_locked_while_torque_is_on(sdk_port: Any) -> None:
    port, ph = sdk_port
    ph.write1ByteTxRx(port, 11, 64, 1)
    assert ph.write1ByteTxRx(port, 11, 11, 5) == (sdk.COMM_SUCCESS, 7)  # access error
    assert ph.write1ByteTxRx(port, 11, 132, 5) == (sdk.COMM_SUCCESS, 7)  # read-only
    assert ph.write4ByteTxRx(port, 11, 116, 5000) == (sdk.COMM_SUCCESS, 6)  # beyond Max Position


def test_emulator_ignores_frames_with_a_bad_crc(emu: DynamixelEmulator, sdk_port: Any) -> None:
    port, ph = sdk_port
    frame = pkt.write(11, 64, b"\x01")
    port.writePort(frame[:-1] + bytes([frame[-1] ^ 0xFF]))
    time.sleep(0.05)
    assert ph.read1ByteTxRx(port, 11, 64) == (0, sdk.COMM_SUCCESS, 0)  # ignored, stream in sync
    port.writePort(frame)
    time.sleep(0.05)
    assert ph.read1ByteTxRx(port, 11, 64) == (1, sdk.COMM_SUCCESS, 0)


def test_time_based_profile_shape() -> None:
    now = [0.0]
    servo = XM430(11, lambda: now[0])
    servo.set("Drive Mode", 4)
    servo.set("Profile Velocity", 1000)  # 1 s
    servo.set("Profile Acceleration", 250)  # 0.25 s ramps
    assert servo.write(64, b"\x01") == 0
    assert servo.write(116, (3048).to_bytes(4, "little")) == 0
    now[0] = 0.5
    assert servo.get("Present Position") == 2548 and servo.get("Moving") == 1
    now[0] = 0.25
    assert servo.get("Present Position") == 2048 + round(1000 / 0.75 * 0.125)
    now[0] = 1.0
    assert servo.get("Present Position") == 3048 and servo.get("Moving") == 0


def test_velocity_profile_is_triangular_when_short() -> None:
    ramp, total = velocity_profile_times(100.0, velocity=1000.0, accel=1000.0)
    assert total == pytest.approx(2 * ramp) and ramp == pytest.approx(0.316227766)
    ramp, total = velocity_profile_times(3000.0, velocity=1000.0, accel=1000.0)
    assert (ramp, total) == (1.0, 4.0)
    assert Profile(0.0, 100.0, 0.0, 0.0, 0.1).at(0.05) == (50.0, 1000.0)


def test_moving_backwards_reads_negative_velocity_and_current() -> None:
    now = [0.0]
    servo = XM430(11, lambda: now[0])
    servo.write(64, b"\x01")
    servo.write(116, (1048).to_bytes(4, "little"))
    now[0] = 0.1
    assert servo.get("Present Velocity") < 0 and servo.get("Present Current") < 0


def test_close_is_idempotent_and_frees_the_pty() -> None:
    emu = DynamixelEmulator([1])
    emu.close()
    emu.close()
    with pytest.raises(ValueError, match="fault"):
        emu.inject(1, "explode")
