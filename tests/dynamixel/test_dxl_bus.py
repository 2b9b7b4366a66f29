"""DynamixelBus over the emulator: open errors, scan, torque, modes, profiles, sync transfers."""

from __future__ import annotations

import subprocess
import sys
import time

import pytest

from armkit._errors import DeviceError
from armkit.devices.dynamixel import DynamixelBus
from armkit.sim.emulators import DynamixelEmulator

OMX = [11, 12, 13, 14]


def test_importing_armkit_does_not_import_the_sdk() -> None:
    code = (
        "import sys, armkit, armkit.devices.dynamixel, armkit.drivers.dynamixel;"
        "print('dynamixel_sdk' in sys.modules)"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "False"


def test_missing_port_is_a_device_error_that_names_it() -> None:
    with pytest.raises(DeviceError, match=r"/dev/ttyNOPE0.*plugged in"):
        DynamixelBus("/dev/ttyNOPE0")


def test_unsupported_baud_is_refused(emu: DynamixelEmulator) -> None:
    with pytest.raises(DeviceError, match="baud rate 4500000 is not supported"):
        DynamixelBus(emu.port, 4_500_000)


def test_scan_and_model_check(emu: DynamixelEmulator, bus: DynamixelBus) -> None:
    assert bus.scan(range(10, 17)) == {sid: 1020 for sid in (11, 12, 13, 14, 15)}
    bus.check_models(OMX)
    with emu.lock:
        emu.servos[13].set("Model Number", 1060)
    with pytest.raises(DeviceError, match="servo 13 is model 1060, expected 1020"):
        bus.check_models(OMX)


def test_missing_servo_is_named(bus: DynamixelBus) -> None:
    bus.retries = 1
    with pytest.raises(DeviceError, match=r"servo 21: PING failed after 2 tries: no reply"):
        bus.ping(21)


def test_torque_context_restores_each_servo(bus: DynamixelBus) -> None:
    bus.set_torque([11], True)
    with bus.torque([11, 12], False):
        assert [bus.read(s, "Torque Enable") for s in (11, 12)] == [0, 0]
    assert [bus.read(s, "Torque Enable") for s in (11, 12)] == [1, 0]


def test_eeprom_settings_switch_torque_off_around_the_write(bus: DynamixelBus) -> None:
    bus.set_torque([15], True)
    bus.set_operating_mode(15, 5)
    bus.set_time_based([15], True)
    assert bus.read(15, "Operating Mode") == 5
    assert bus.read(15, "Drive Mode") == 4
    assert bus.read(15, "Torque Enable") == 1
    bus.set_time_based([15], False)
    assert bus.read(15, "Drive Mode") == 0


def test_refused_write_names_servo_and_error(bus: DynamixelBus) -> None:
    bus.set_torque([11], True)
    with pytest.raises(DeviceError, match="servo 11: WRITE Operating Mode=4 refused: access error"):
        bus.write(11, "Operating Mode", 4)


def test_sync_write_goals_and_signed_sync_read(emu: DynamixelEmulator, bus: DynamixelBus) -> None:
    bus.set_time_based(OMX, True)
    bus.set_torque(OMX, True)
    bus.set_profiles({sid: (100, 400) for sid in OMX})  # 0.1 s ramps, 0.4 s total
    bus.sync_write("Goal Position", {11: 1024, 12: 3072, 13: 2048, 14: 100})
    time.sleep(0.15)
    states = bus.read_states(OMX)
    assert states[11].velocity < 0 and states[11].current < 0  # moving down: negative
    assert states[12].velocity > 0 and states[12].current > 0
    assert states[13].velocity == 0
    while any(bus.sync_read("Moving", OMX).values()):
        time.sleep(0.01)
    assert bus.sync_read("Present Position", OMX) == {11: 1024, 12: 3072, 13: 2048, 14: 100}
    assert [emu.servos[s].plans for s in OMX] == [1, 1, 0, 1]  # 13 was already there


def test_sync_write_group_is_cleared_every_cycle(emu: DynamixelEmulator, bus: DynamixelBus) -> None:
    bus.set_torque(OMX, True)
    bus.sync_write("Goal Position", {11: 2000, 12: 2000})
    bus.sync_write("Goal Position", {13: 2100})
    time.sleep(0.05)
    assert [emu.servos[s].plans for s in OMX] == [1, 1, 1, 0]  # 11, 12 not re-sent


def test_hardware_error_read_and_reboot(emu: DynamixelEmulator, bus: DynamixelBus) -> None:
    bus.set_torque([12], True)
    emu.inject(12, "overload")
    assert bus.hardware_error(12) == 0x20
    with pytest.raises(DeviceError, match="servo 12: hardware error: overload"):
        bus.read(12, "Present Position")
    bus.reboot(12)
    assert bus.hardware_error(12) == 0
    assert bus.read(12, "Torque Enable") == 0


def test_velocity_based_profile_units(emu: DynamixelEmulator, bus: DynamixelBus) -> None:
    bus.set_time_based([11], False)
    bus.set_torque([11], True)
    bus.set_profiles({11: (50, 100)})  # 50 x 214.577 rev/min^2, 100 x 0.229 rev/min
    bus.sync_write("Goal Position", {11: 3048})
    assert bus.read(11, "Goal Position") == 3048  # the round trip orders it after the write
    velocity, accel = 100 * 0.229 * 4096 / 60, 50 * 214.577 * 4096 / 3600  # tick/s, tick/s^2
    with emu.lock:
        profile = emu.servos[11].motion
    assert profile.ramp == pytest.approx(velocity / accel)
    assert profile.total == pytest.approx(1000 / velocity + velocity / accel)
