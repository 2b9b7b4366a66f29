"""The OpenManipulator-X driver on the emulator: ticks, limits, profiles, gripper, faults."""

from __future__ import annotations

import math
import threading
import time
from collections.abc import Iterator

import numpy as np
import pytest

from armkit._errors import DeviceError, JointLimitError, ModelError
from armkit.connect import open_driver as open_any
from armkit.devices.dynamixel import DynamixelBus
from armkit.drivers._driver import Driver
from armkit.drivers.dynamixel import DynamixelDriver, open_dynamixel
from armkit.model import ArmModel, load_model
from armkit.model._limits import shortest_time
from armkit.sim.emulators import DynamixelEmulator

OMX = [11, 12, 13, 14]


@pytest.fixture(scope="module")
def model() -> ArmModel:
    return load_model("openmanipulator_x")


@pytest.fixture
def drv(model: ArmModel, emu: DynamixelEmulator) -> Iterator[DynamixelDriver]:
    bus = DynamixelBus(emu.port, 1_000_000, retries=3)
    bus.settle_s = 0.15
    driver = DynamixelDriver(model, bus)
    yield driver
    driver.close()


def goals(emu: DynamixelEmulator) -> list[int]:
    with emu.lock:
        return [emu.servos[s].get("Goal Position") for s in OMX]


def test_setup_puts_the_servos_in_their_modes(emu: DynamixelEmulator, drv: DynamixelDriver) -> None:
    assert isinstance(drv, Driver)
    with emu.lock:
        assert [emu.servos[s].get("Operating Mode") for s in (*OMX, 15)] == [3, 3, 3, 3, 5]
        assert [emu.servos[s].get("Drive Mode") & 4 for s in OMX] == [4, 4, 4, 4]
        assert [emu.servos[s].get("Torque Enable") for s in (*OMX, 15)] == [1] * 5


def test_angles_to_ticks_and_back(drv: DynamixelDriver) -> None:
    q = np.radians([0.0, 90.0, -45.0, 180.0])
    assert drv.to_ticks(q).tolist() == [2048, 3072, 1536, 4095]  # +180 deg clipped by one tick
    rng = np.random.default_rng(3)
    q = rng.uniform(-3.0, 3.0, size=(50, 4))
    back = np.array([drv.to_angles(drv.to_ticks(row)) for row in q])
    assert np.max(np.abs(back - q)) <= math.pi / 4096 + 1e-12


def test_limit_is_refused_before_a_byte(emu: DynamixelEmulator, drv: DynamixelDriver) -> None:
    before = emu.received
    with pytest.raises(
        JointLimitError, match=r"elbow 90.00 deg is outside its limits -85.94..80.21 deg"
    ):
        drv.move(np.radians([0.0, 0.0, 90.0, 0.0]))
    with pytest.raises(ValueError, match="speed"):
        drv.move(np.zeros(4), speed=1.5)
    with pytest.raises(ValueError, match="4 finite joint angles"):
        drv.move(np.zeros(3))
    with pytest.raises(ValueError, match=r"grip width 90\.0 mm"):
        drv.grip(0.090)
    time.sleep(0.02)
    assert emu.received == before


def test_move_with_a_duration_uses_one_time_profile(
    emu: DynamixelEmulator, drv: DynamixelDriver
) -> None:
    target = np.radians([10.0, -5.0, 5.0, 0.0])
    drv.move(target, duration=0.4)
    with emu.lock:
        assert [emu.servos[s].get("Profile Velocity") for s in OMX] == [400] * 4
        ramps = {emu.servos[s].get("Profile Acceleration") for s in OMX}
        assert [emu.servos[s].plans for s in OMX] == [1, 1, 0 + 1, 0]  # wrist did not move
    assert len(ramps) == 1 and 0 < ramps.pop() <= 200
    assert np.max(np.abs(drv.read() - target)) <= math.pi / 4096


def test_slower_speed_means_a_longer_profile(emu: DynamixelEmulator, drv: DynamixelDriver) -> None:
    drv.move(np.radians([10.0, 0.0, 0.0, 0.0]), speed=1.0)
    fast = emu.servos[11].get("Profile Velocity")
    drv.move(np.radians([0.0, 0.0, 0.0, 0.0]), speed=0.5)
    slow = emu.servos[11].get("Profile Velocity")
    assert slow > fast
    total = shortest_time(drv.model, np.zeros(4), np.radians([10.0, 0.0, 0.0, 0.0]))
    assert fast == math.ceil(total * 1000)  # the shared rule's time, rounded up to 1 ms
    assert 0 < emu.servos[11].get("Profile Acceleration") <= fast / 2


def test_grip_maps_width_to_ticks(emu: DynamixelEmulator, drv: DynamixelDriver) -> None:
    assert drv.grip_ticks(0.020) == 2483 and drv.grip_ticks(0.075) == 1613
    drv.grip(0.075)
    assert emu.servos[15].get("Present Position") == 1613


def test_stop_holds_every_servo_where_it_is(emu: DynamixelEmulator, drv: DynamixelDriver) -> None:
    drv.move(np.radians([30.0, 20.0, -20.0, 30.0]), duration=2.0, wait=False)
    time.sleep(0.1)
    drv.stop()
    time.sleep(0.3)  # the hold profile settles in 0.1 s
    with emu.lock:
        for sid in OMX:
            servo = emu.servos[sid]
            assert servo.get("Moving") == 0
            assert servo.get("Goal Position") == servo.get("Present Position")
    assert goals(emu) != [2389, 2276, 1820, 2389]


def test_failure_part_way_leaves_every_servo_holding(
    emu: DynamixelEmulator, drv: DynamixelDriver
) -> None:
    drv.bus.retries = 1
    timer = threading.Timer(0.15, emu.inject, (13, "vanish"))
    timer.start()
    with pytest.raises(
        DeviceError,
        match=r"servo 13: .*no reply.*servos \[11, 12, 14\] hold where they were; servos \[13\] "
        "did not confirm that they hold",
    ):
        drv.move(np.radians([30.0, 20.0, 0.0, 30.0]), duration=2.0)
    timer.join()
    time.sleep(0.3)  # the hold profile settles in 0.1 s
    with emu.lock:
        for sid in (11, 12, 14):
            servo = emu.servos[sid]
            assert servo.get("Moving") == 0
            assert servo.get("Goal Position") == servo.get("Present Position") != 2048


def test_overloaded_servo_stops_the_move_before_it_starts(
    emu: DynamixelEmulator, drv: DynamixelDriver
) -> None:
    emu.inject(12, "overload")
    with pytest.raises(DeviceError, match="servo 12: hardware error: overload"):
        drv.move(np.radians([10.0, 10.0, 10.0, 10.0]))
    assert [emu.servos[s].plans for s in OMX] == [0, 0, 0, 0]


def test_lost_replies_during_a_move_do_not_move_twice(
    emu: DynamixelEmulator, drv: DynamixelDriver
) -> None:
    for fault in ("drop", "corrupt"):
        emu.inject(12, fault)
    drv.move(np.radians([5.0, 5.0, 5.0, 5.0]), duration=0.3)
    assert [emu.servos[s].plans for s in OMX] == [1, 1, 1, 1]
    assert goals(emu) == drv.to_ticks(np.radians([5.0, 5.0, 5.0, 5.0])).tolist()


def test_close_keeps_torque_on_and_is_idempotent(
    emu: DynamixelEmulator, drv: DynamixelDriver
) -> None:
    drv.close()
    drv.close()
    drv.stop()  # no-op once closed
    assert [emu.servos[s].get("Torque Enable") for s in (*OMX, 15)] == [1] * 5


def test_relax_turns_torque_off(emu: DynamixelEmulator, drv: DynamixelDriver) -> None:
    drv.relax()
    assert [emu.servos[s].get("Torque Enable") for s in (*OMX, 15)] == [0] * 5


def test_port_emu_is_this_driver_on_simulated_servos(model: ArmModel) -> None:
    driver = open_any(model, "dynamixel", "emu")
    assert type(driver) is DynamixelDriver
    world = driver.clock.world  # type: ignore[attr-defined]
    driver.move(np.radians([0.0, 5.0, 0.0, 0.0]))
    assert world.arm().q()[1] == pytest.approx(math.radians(5.0), abs=math.radians(0.1))
    driver.close()
    assert not driver.bus.is_open


def test_open_driver_needs_a_port_and_a_dynamixel_model(model: ArmModel) -> None:
    with pytest.raises(DeviceError, match="needs a port"):
        open_dynamixel(model, None)
    with pytest.raises(ModelError, match=r"no \[drivers\.dynamixel\]"):
        open_dynamixel(load_model("lynx6"), "emu")


def test_a_move_longer_than_a_profile_must_wait(
    emu: DynamixelEmulator, drv: DynamixelDriver
) -> None:
    with pytest.raises(ValueError, match=r"at most 32\.737 s, so it goes in pieces and must wait"):
        drv.move(np.radians([170.0, 0.0, 0.0, 0.0]), speed=0.01, wait=False)
    assert [emu.servos[s].plans for s in OMX] == [0, 0, 0, 0]
