"""Issue 10, servo buses, on the simulated Maestro under the real driver: stop() needs no
reply; group moves arrive together and on time; a clamping channel range is reported."""

from __future__ import annotations

import random

import numpy as np
import pytest

from armkit._errors import DeviceError
from armkit.connect import open_driver
from armkit.devices.maestro import Maestro
from armkit.drivers.servo import ServoArmDriver
from armkit.model import load_model
from armkit.sim import World
from armkit.sim._wire import Wire
from armkit.sim.maestro import FACTORY_RANGE, SimMaestro


def lynx6() -> tuple[World, ServoArmDriver, SimMaestro]:
    world = World()
    driver = open_driver(load_model("lynx6"), "maestro", "emu", world=world)
    assert isinstance(driver, ServoArmDriver)
    device = world.arm().device
    assert isinstance(device, SimMaestro)
    return world, driver, device


def test_stop_holds_every_servo_with_no_replies() -> None:
    world, driver, device = lynx6()
    goal = np.radians([150.0, 90.0, 90.0, 90.0, 90.0])
    driver.move(np.radians([90.0, 90.0, 90.0, 90.0, 90.0]))  # a servo's first pulse jumps
    driver.move(goal, duration=2.0, wait=False)
    world.advance(0.5)
    device.outbox.inject("drop", count=100)  # the Maestro answers nothing any more
    driver.stop()
    world.advance(3.0)
    base = driver.joints[0]
    held = device.pulse(base.channel, world.now())
    assert device.servos[base.channel].target_us != pytest.approx(base.to_pulse(goal[0]))
    assert not device.servos[base.channel].moving(world.now())
    assert 90.0 < np.degrees(base.to_value(held)) < 150.0


def test_small_group_moves_arrive_together_and_on_time() -> None:
    """Every servo that needs at least the Maestro's smallest speed (25 µs/s) arrives no
    earlier than the group's time, on average within 3 % of it and never more than 12 %
    late (speeds floored to 25 µs/s units: up to 2 x late, 18 % on average here)."""
    rng = random.Random(20)
    world = World()
    device = SimMaestro()
    board = Maestro(Wire(device, world, baudrate=9600, timeout=0.05), clock=world.clock)
    board.group_move({ch: 1500.0 for ch in range(4)})
    lateness = []
    for _ in range(20):
        pulses = {ch: 1500.0 + rng.uniform(-60.0, 60.0) for ch in range(4)}
        seconds = rng.randint(150, 900) / 1000
        board.group_move(pulses, round(seconds * 1000))
        for record in list(device.history)[-4:]:
            ((start, end),) = record.servos.values()
            if abs(end - start) / seconds >= 25.0:
                lateness.append(record.duration_s / seconds - 1.0)
        world.advance(1.0)
    assert len(lateness) > 40
    assert min(lateness) >= -1e-9 and max(lateness) <= 0.12
    assert sum(lateness) / len(lateness) <= 0.03


def test_a_clamped_target_is_reported_with_how_to_widen_the_range() -> None:
    _, driver, device = lynx6()
    device.ranges = [FACTORY_RANGE] * len(device.ranges)  # a Maestro as it leaves the factory
    wrist = driver.joints[3]
    q = np.array(load_model("lynx6").home)
    q[3] = min(wrist.values[0], wrist.values[-1]) + 0.05  # a pulse near the table's end
    assert min(wrist.to_pulse(q[3]), 3000 - wrist.to_pulse(q[3])) < 992
    with pytest.raises(DeviceError, match=rf"channel {wrist.channel} sends .* widen channel"):
        driver.move(q)
