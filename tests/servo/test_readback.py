"""Read-back of hobby-servo arms: the angle asked for, where the controller reports its pulse.

The SSC-32's ``QP`` answers one byte per servo, pulse / 10 µs (user guide, "Query Pulse
Width"), so the pulse read back is up to 5 µs from the one sent (~3 mm at an AL5D's
gripper). A servo whose move from this driver has ended and whose reading's 10 µs bin
holds the pulse it was sent reads as the angle asked for; any other reads as reported.
"""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import numpy as np
import pytest
from numpy.typing import NDArray

from armkit.connect import open_driver
from armkit.devices.maestro import Maestro
from armkit.devices.ssc32 import SSC32
from armkit.drivers.servo import ServoArmDriver
from armkit.drivers.servo._bus import MAESTRO_READBACK, SSC32_READBACK
from armkit.kinematics import fk, ik, pitch_of
from armkit.model import load_model

F64 = NDArray[np.float64]
SETUPS = [("al5d", "sim", None), ("lynx6", "sim", None), ("lynx6", "maestro", "emu")]


def open_servo_arm(arm: str, driver: str, port: str | None) -> ServoArmDriver:
    """The arm's own servo driver on a simulated controller (virtual time)."""
    opened = open_driver(load_model(arm), driver, port)
    assert isinstance(opened, ServoArmDriver)
    return opened


@pytest.fixture
def ssc32_al5d() -> Iterator[ServoArmDriver]:
    driver = open_servo_arm("al5d", "sim", None)
    driver.move(driver.model.home)
    yield driver
    driver.close()


def reported_angles(driver: ServoArmDriver) -> F64:
    """The joint angles [rad] of the pulses the controller reports, taken as they are."""
    pulses = driver.bus.read([t.channel for t in driver.joints])
    return np.array([t.to_value(pulses[t.channel]) for t in driver.joints])


def at_pulse(driver: ServoArmDriver, joint: int, pulse_us: float) -> F64:
    """Home, with ``joint`` at the angle [rad] of ``pulse_us`` [µs]."""
    q = driver.model.home.copy()
    q[joint] = driver.joints[joint].to_value(pulse_us)
    return q


@pytest.mark.parametrize(("arm", "driver", "port"), SETUPS)
def test_read_is_the_asked_angles_at_every_target(arm: str, driver: str, port: str | None) -> None:
    servo_arm = open_servo_arm(arm, driver, port)
    model, rng = servo_arm.model, np.random.default_rng(20261126)
    coarse_m = 0.0
    try:
        for _ in range(8):
            pose = fk(model, model.lower + (model.upper - model.lower) * rng.uniform(0.1, 0.9))
            target, pitch = pose[:3, 3], float(pitch_of(pose))
            q = ik(model, target, pitch, servo_arm.read()).q
            servo_arm.move(q)
            read = servo_arm.read()
            assert np.max(np.abs(read - q)) <= 1e-9
            assert np.linalg.norm(fk(model, read)[:3, 3] - target) <= 1e-6
            coarse = fk(model, reported_angles(servo_arm))[:3, 3]
            coarse_m = max(coarse_m, float(np.linalg.norm(coarse - target)))
    finally:
        servo_arm.close()
    if driver == "sim":  # the SSC-32's reply alone is millimetres off: the rule does the work
        assert coarse_m > 1e-3


def test_a_pulse_set_by_another_program_reads_as_reported(ssc32_al5d: ServoArmDriver) -> None:
    asked = at_pulse(ssc32_al5d, 0, 1503.0)
    ssc32_al5d.move(asked)
    assert ssc32_al5d.read()[0] == asked[0]
    device = ssc32_al5d.bus.device  # type: ignore[attr-defined]
    assert isinstance(device, SSC32)
    device.move(ssc32_al5d.joints[0].channel, 1511)  # reads 1510: 7 µs from 1503, 1 from 1511
    assert ssc32_al5d.bus.read([ssc32_al5d.joints[0].channel]) == {0: 1510.0}
    assert ssc32_al5d.read()[0] == ssc32_al5d.joints[0].to_value(1510.0)


def test_a_move_still_running_reads_as_reported(ssc32_al5d: ServoArmDriver) -> None:
    asked = at_pulse(ssc32_al5d, 0, 1503.0)  # 3 µs from home: always in home's 10 µs bin
    ssc32_al5d.move(asked, duration=2.0, wait=False)
    assert ssc32_al5d.read()[0] == ssc32_al5d.joints[0].to_value(1500.0)
    ssc32_al5d.clock.sleep(2.5)
    assert ssc32_al5d.read()[0] == asked[0]


def test_a_servo_stopped_short_reads_as_reported(ssc32_al5d: ServoArmDriver) -> None:
    ssc32_al5d.move(at_pulse(ssc32_al5d, 0, 2003.0), wait=False)
    ssc32_al5d.clock.sleep(0.2)
    ssc32_al5d.stop()
    ssc32_al5d.clock.sleep(1.0)
    held = reported_angles(ssc32_al5d)[0]
    assert ssc32_al5d.read()[0] == held
    assert ssc32_al5d.joints[0].to_value(1510.0) < held < ssc32_al5d.joints[0].to_value(1990.0)


def test_a_maestro_pulse_set_by_another_program_reads_as_reported() -> None:
    driver = open_servo_arm("lynx6", "maestro", "emu")
    try:
        asked = at_pulse(driver, 0, 1600.0)
        driver.move(asked)
        assert driver.read()[0] == asked[0]
        device = driver.bus.device  # type: ignore[attr-defined]
        assert isinstance(device, Maestro)
        device.set_target(driver.joints[0].channel, 1600.5)
        driver.clock.sleep(1.0)
        assert driver.read()[0] == pytest.approx(driver.joints[0].to_value(1600.5), abs=1e-12)
    finally:
        driver.close()


def test_a_new_driver_reads_what_the_controller_reports(tmp_path: Path) -> None:
    """What one driver asked is not known to the next (a new ``armkit`` command): it
    reads the SSC-32's 10 µs reply, within half a step of the pulse sent."""
    state, model = str(tmp_path / "al5d.json"), load_model("al5d")
    first = open_servo_arm("al5d", "sim", state)
    asked = at_pulse(first, 0, 1503.0)
    first.move(asked)
    first.close()
    second = open_servo_arm("al5d", "sim", state)
    try:
        assert second.read()[0] == second.joints[0].to_value(1500.0)
        assert second.read()[1:] == pytest.approx(model.home[1:], abs=0.6 * np.radians(1.0))
    finally:
        second.close()


@pytest.mark.parametrize(
    ("sent", "read", "reports"),
    [
        (1503.0, 1500.0, True),
        (1505.0, 1500.0, True),
        (1506.0, 1500.0, False),
        (1494.0, 1500.0, False),
        (1495.0, 1500.0, True),
        (1502.6, 1500.0, True),  # 1503 on the wire
        (1505.4, 1500.0, True),  # 1505 on the wire
        (1505.6, 1500.0, False),  # 1506 on the wire
        (1503.0, 1510.0, False),
    ],
)
def test_an_ssc32_reading_holds_the_pulses_of_its_10_us_bin(
    sent: float, read: float, reports: bool
) -> None:
    """A command goes out in whole µs (round half to even); the reading is the nearest
    10 µs to the pulse on the wire."""
    assert SSC32_READBACK.reports(sent, read) is reports


def test_a_maestro_reading_is_the_quarter_microsecond_sent() -> None:
    assert MAESTRO_READBACK.reports(1500.1, 1500.0)
    assert MAESTRO_READBACK.reports(1500.2, 1500.25)
    assert not MAESTRO_READBACK.reports(1500.2, 1500.0)
