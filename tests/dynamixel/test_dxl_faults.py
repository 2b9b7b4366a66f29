"""Each injected fault: bounded retries, then a DeviceError naming the servo and the fault;
never a double move."""

from __future__ import annotations

import time

import pytest

from armkit._errors import DeviceError
from armkit.devices.dynamixel import DynamixelBus
from armkit.sim.emulators import DynamixelEmulator

OMX = [11, 12, 13, 14]


@pytest.mark.parametrize("fault", ["drop", "corrupt", "late"])
def test_one_bad_reply_is_retried(emu: DynamixelEmulator, bus: DynamixelBus, fault: str) -> None:
    emu.inject(13, fault)
    assert bus.read(13, "Present Position") == 2048
    emu.inject(13, fault)
    assert bus.sync_read("Present Position", OMX)[13] == 2048
    emu.inject(13, fault)
    assert bus.ping(13) == 1020


@pytest.mark.parametrize(
    ("fault", "text"),
    [("drop", "no reply"), ("corrupt", "corrupt reply"), ("late", "no reply")],
)
def test_persistent_fault_gives_up_naming_servo_and_fault(
    emu: DynamixelEmulator, bus: DynamixelBus, fault: str, text: str
) -> None:
    bus.retries = 2
    emu.inject(14, fault, times=10)
    with pytest.raises(
        DeviceError, match=f"servo 14: SYNC_READ at 132 failed after 3 tries: {text}"
    ):
        bus.sync_read("Present Position", OMX)
    with pytest.raises(DeviceError, match=f"servo 14: READ Moving failed after 3 tries: {text}"):
        bus.read(14, "Moving")


def test_vanished_servo_is_named(emu: DynamixelEmulator, bus: DynamixelBus) -> None:
    bus.retries = 1
    emu.inject(12, "vanish")
    with pytest.raises(
        DeviceError, match="servo 12: SYNC_READ at 132 failed after 2 tries: no reply"
    ):
        bus.sync_read("Present Position", OMX)
    emu.revive(12)
    assert bus.sync_read("Present Position", OMX)[12] == 2048


def test_overload_is_reported_as_a_hardware_error(
    emu: DynamixelEmulator, bus: DynamixelBus
) -> None:
    emu.inject(11, "overload")
    with pytest.raises(DeviceError, match=r"servo 11: hardware error: overload \(.*0x20\)"):
        bus.sync_read("Moving", OMX)


@pytest.mark.parametrize("fault", ["drop", "corrupt", "late"])
def test_a_write_whose_reply_is_lost_is_not_sent_twice(
    emu: DynamixelEmulator, bus: DynamixelBus, fault: str
) -> None:
    bus.set_torque([11], True)
    emu.inject(11, fault)
    bus.write(11, "Goal Position", 2500)  # executed once; only the status was lost
    time.sleep(0.01)
    assert emu.servos[11].plans == 1
    assert bus.read(11, "Goal Position") == 2500


def test_a_write_that_never_lands_is_retried_then_refused(
    emu: DynamixelEmulator, bus: DynamixelBus
) -> None:
    bus.retries = 1
    emu.inject(11, "vanish")
    with pytest.raises(DeviceError, match="servo 11"):
        bus.write(11, "Goal Position", 2500)
    emu.revive(11)
    assert emu.servos[11].plans == 0
