"""The Feetech driver's safety (issue 31 item 2), on the SO-101's emulated STS3215 bus
with faults injected: a failed or stopped move leaves every servo holding (the hold
does not depend on the servo that failed answering); limp and stiff on purpose.
(The port taken by a second process: tests/emulate/test_feetech_sdk.py.)"""

from __future__ import annotations

import numpy as np
import pytest

from armkit._errors import DeviceError
from armkit.connect import open_driver
from armkit.drivers.feetech import FeetechDriver
from armkit.model import load_model
from armkit.sim import World
from armkit.sim.feetech import SimFeetechBus

JOINTS = (1, 2, 3, 4, 5)
TARGET = np.radians([40.0, -30.0, 30.0, 40.0, 60.0])


def arm() -> tuple[World, FeetechDriver, SimFeetechBus]:
    world = World()
    driver = open_driver(load_model("so101"), "sim", world=world)
    assert isinstance(driver, FeetechDriver)
    bus = world.arm().device
    assert isinstance(bus, SimFeetechBus)
    return world, driver, bus


def holding(bus: SimFeetechBus, sid: int) -> bool:
    """Torque on, not moving, on its goal (within 2 steps)."""
    servo = bus.servos[sid]
    servo.refresh(servo.clock())
    return (
        servo.value("Torque Enable") == 1
        and servo.value("Moving") == 0
        and abs(servo.value("Present Position") - servo.value("Goal Position")) <= 2
    )


def test_a_move_that_fails_on_an_overloaded_servo_leaves_the_others_holding(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """Servo 3 overloads while the move runs (the fault injected as the driver starts to
    wait for the arrival; the driver finds it when it checks the arrival): the move is
    abandoned, every other servo holds and says so, servo 3 is named."""
    world, driver, bus = arm()
    sleep = driver.clock.sleep

    def overload_then_sleep(seconds: float) -> None:
        if bus.servos[3].value("Status") == 0:
            sleep(0.5)
            bus.inject(3, "overload")  # torque off, error bit 5 in every status
        sleep(seconds)

    monkeypatch.setattr(driver.clock, "sleep", overload_then_sleep)
    with pytest.raises(DeviceError, match="the move was abandoned") as info:
        driver.move(TARGET, duration=2.0)
    world.advance(1.0)
    assert "servo 3: overload" in str(info.value)
    assert "servos [1, 2, 4, 5] hold where they were" in str(info.value)
    assert all(holding(bus, sid) for sid in (1, 2, 4, 5))
    assert bus.servos[3].value("Torque Enable") == 0
    driver.close()


@pytest.mark.parametrize("faults", [{3: "corrupt"}, {3: "corrupt", 2: "late"}, {3: "drop"}])
def test_stop_holds_every_servo_even_those_whose_replies_fail(faults: dict[int, str]) -> None:
    world, driver, bus = arm()
    goals = driver.forecaster().ticks(TARGET)
    driver.move(TARGET, duration=2.0, wait=False)
    world.advance(0.5)
    for sid, fault in faults.items():
        bus.inject(sid, fault, times=50)
    with pytest.raises(DeviceError, match=r"servos \[(2, )?3\] did not confirm"):
        driver.stop()
    world.advance(1.0)
    for sid, goal in zip(JOINTS, goals.tolist(), strict=True):
        assert holding(bus, sid), sid  # the hold is one SYNC WRITE: no reply needed
        assert bus.servos[sid].value("Goal Position") != goal
    driver.close()


def test_a_vanished_servo_fails_the_move_before_it_starts_and_nothing_moves() -> None:
    world, driver, bus = arm()
    before = {sid: bus.servos[sid].value("Present Position") for sid in JOINTS}
    bus.inject(4, "vanish")
    with pytest.raises(DeviceError):
        driver.move(TARGET, duration=2.0)
    world.advance(1.0)
    assert {sid: bus.servos[sid].value("Present Position") for sid in JOINTS} == before
    bus.revive(4)
    driver.close()


def test_limp_then_stiff_where_the_arm_was_put() -> None:
    world, driver, bus = arm()
    driver.relax()
    assert all(bus.servos[sid].value("Torque Enable") == 0 for sid in (*JOINTS, 6))
    assert all(bus.setpoint(sid, world.device_time()) is None for sid in JOINTS)  # limp
    driver.stiffen()
    assert all(bus.servos[sid].value("Torque Enable") == 1 for sid in (*JOINTS, 6))
    assert all(holding(bus, sid) for sid in JOINTS)
    driver.move(TARGET, duration=1.0)  # and it moves again
    assert np.allclose(driver.read(), TARGET, atol=np.radians(0.2))
    driver.close()


def test_close_holds_with_the_torque_on() -> None:
    """An SO-101 with its torque off folds onto the table: closing keeps it holding."""
    world, driver, bus = arm()
    driver.move(TARGET, duration=2.0, wait=False)
    world.advance(0.5)
    driver.close()
    world.advance(1.0)
    assert all(holding(bus, sid) for sid in JOINTS)
