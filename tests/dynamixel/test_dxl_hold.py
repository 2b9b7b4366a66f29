"""Issue 10, servo buses: after a failed or stopped move every Dynamixel servo holds, and
holding does not depend on reading the servo that failed (simulated XM430s, faults injected)."""

from __future__ import annotations

import numpy as np
import pytest

from armkit._errors import DeviceError
from armkit.connect import open_driver
from armkit.drivers.dynamixel import DynamixelDriver
from armkit.model import load_model
from armkit.sim import World
from armkit.sim.dynamixel import SimDynamixelBus

JOINTS = (11, 12, 13, 14)


def arm() -> tuple[World, DynamixelDriver, SimDynamixelBus]:
    world = World()
    driver = open_driver(load_model("openmanipulator_x"), "sim", world=world)
    assert isinstance(driver, DynamixelDriver)
    bus = world.arm().device
    assert isinstance(bus, SimDynamixelBus)
    return world, driver, bus


@pytest.mark.parametrize("faults", [{13: "corrupt"}, {13: "corrupt", 12: "late"}, {13: "drop"}])
def test_stop_holds_every_servo_even_those_whose_replies_fail(faults: dict[int, str]) -> None:
    world, driver, bus = arm()
    final = driver.to_ticks(np.radians([40.0, 30.0, -30.0, 40.0]))
    driver.move(np.radians([40.0, 30.0, -30.0, 40.0]), duration=2.0, wait=False)
    world.advance(0.5)
    for sid, fault in faults.items():
        bus.inject(sid, fault, times=50)
    with pytest.raises(DeviceError, match=r"servos \[(12, )?13\] did not confirm") as info:
        driver.stop()
    world.advance(1.0)
    for sid, goal in zip(JOINTS, final.tolist(), strict=True):
        servo = bus.servos[sid]
        assert servo.get("Moving") == 0
        assert servo.get("Goal Position") != goal  # the abandoned goal is not finished
        assert abs(servo.get("Present Position") - servo.get("Goal Position")) <= 2
    assert "13" in str(info.value) and "11" not in str(info.value)
    driver.close()


def test_stop_with_healthy_servos_says_nothing_and_holds() -> None:
    world, driver, bus = arm()
    driver.move(np.radians([40.0, 30.0, -30.0, 40.0]), duration=2.0, wait=False)
    world.advance(0.5)
    driver.stop()
    world.advance(1.0)
    assert all(bus.servos[sid].get("Moving") == 0 for sid in JOINTS)
    driver.close()


def test_connect_writes_drive_mode_and_uses_robotis_gripper_ticks() -> None:
    """Issue 10: direction never depends on the unit's history (a gripper left in reverse
    Drive Mode, bit 0); the gripper's ticks are ROBOTIS's (ticks fall as the jaws open)."""
    from armkit.connect._rigs import dynamixel_rig
    from armkit.devices._dxl_protocol import PortHandler
    from armkit.devices.dynamixel import DynamixelBus
    from armkit.sim._wire import Wire, serial_port

    world = World()
    model = load_model("openmanipulator_x")
    rig = dynamixel_rig(model, world, None)
    bus = rig.device
    assert isinstance(bus, SimDynamixelBus)
    bus.servos[15].set("Drive Mode", 1)  # reversed by a previous owner
    bus.servos[12].set("Drive Mode", 1)
    wire = Wire(bus, world, baudrate=rig.baudrate, timeout=0)
    port = DynamixelBus.on_port(PortHandler(serial_port(wire), world.clock), clock=world.clock)
    driver = DynamixelDriver(model, port, config=rig.config, clock=world.clock)
    assert bus.servos[15].value("Drive Mode") == 0
    assert [bus.servos[s].value("Drive Mode") for s in JOINTS] == [4, 4, 4, 4]
    driver.grip(0.075)
    assert bus.servos[15].value("Goal Position") == 1613
    driver.grip(0.020)
    assert bus.servos[15].value("Goal Position") == 2483
    driver.close()
