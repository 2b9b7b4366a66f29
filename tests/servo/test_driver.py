"""The Lynx6 servo driver on the SSC-32 and Maestro emulators."""

from __future__ import annotations

import math
from collections.abc import Iterator
from pathlib import Path

import numpy as np
import pytest

from armkit._errors import DeviceError, JointLimitError, ModelError
from armkit.drivers import Driver
from armkit.drivers.servo import ServoArmDriver, open_maestro, open_ssc32
from armkit.model import ArmModel
from armkit.sim.emulators import MaestroEmulator, SSC32Emulator

deg = np.radians


@pytest.fixture
def arm(lynx6: ArmModel, ssc32_emu: SSC32Emulator) -> Iterator[ServoArmDriver]:
    driver = open_ssc32(lynx6, ssc32_emu.port)
    driver.move(lynx6.home)
    yield driver
    driver.close()


def moves(emu: SSC32Emulator, driver: ServoArmDriver) -> list[bytes]:
    """The move lines the emulator has received (after a query, so it has read them all)."""
    driver.bus.read([0])
    return [line for line in emu.received if line.startswith(b"#")]


def test_it_is_a_driver(arm: ServoArmDriver) -> None:
    assert isinstance(arm, Driver)
    assert arm.joint_names == ("base", "shoulder", "elbow", "wrist", "hand")


def test_home_is_1500_us_on_every_joint(arm: ServoArmDriver, ssc32_emu: SSC32Emulator) -> None:
    assert moves(ssc32_emu, arm) == [b"#0P1500#1P1500#2P1500#3P1500#4P1500\r"]


def test_read_returns_the_commanded_angles(arm: ServoArmDriver) -> None:
    q = deg([100.0, 80.0, 95.5, 91.0, 33.3])
    arm.move(q)
    assert arm.read() == pytest.approx(q, abs=1e-12)


def test_read_converts_pulses_it_did_not_send(
    arm: ServoArmDriver, ssc32_emu: SSC32Emulator
) -> None:
    arm.bus.device.move(0, 1600)  # type: ignore[attr-defined]
    assert math.degrees(arm.read()[0]) == pytest.approx(99.0)


def test_a_refused_angle_sends_no_byte(arm: ServoArmDriver, ssc32_emu: SSC32Emulator) -> None:
    before = list(ssc32_emu.received)
    with pytest.raises(
        JointLimitError, match=r"elbow 170\.00 deg is outside its limits 0\.00\.\.160\.00 deg"
    ):
        arm.move(deg([90.0, 90.0, 170.0, 90.0, 90.0]))
    with pytest.raises(ValueError, match="5 finite joint angles"):
        arm.move(deg([90.0, 90.0]))
    with pytest.raises(ValueError, match="speed"):
        arm.move(deg([90.0] * 5), speed=1.5)
    with pytest.raises(JointLimitError, match="grip"):
        arm.grip(0.06)
    assert ssc32_emu.received == before


def test_group_move_arrives_together_and_no_servo_is_too_fast(
    arm: ServoArmDriver, ssc32_emu: SSC32Emulator, lynx6: ArmModel
) -> None:
    target = deg([100.0, 84.0, 99.0, 85.0, 100.0])
    arm.move(target, speed=1.0)
    record = ssc32_emu.history[-1]
    assert sorted(record.servos) == [0, 1, 2, 3, 4]  # one group move, one duration
    speeds = []
    for table, joint in zip(arm.joints, lynx6.joints, strict=True):
        start, end = record.servos[table.channel]
        turn = abs(table.to_value(end) - table.to_value(start))
        speeds.append(turn / record.duration_s / joint.max_velocity)
    assert max(speeds) <= 1.0 + 1e-9
    assert max(speeds) > 0.95  # the slowest servo sets the time: not needlessly slow


def test_speed_fraction_and_duration_stretch_the_move(
    arm: ServoArmDriver, ssc32_emu: SSC32Emulator
) -> None:
    arm.move(deg([96.0, 90.0, 90.0, 90.0, 90.0]), speed=0.5, wait=False)  # base 6° at 45°/s
    assert moves(ssc32_emu, arm)[-1] == b"#0P1567#1P1500#2P1500#3P1500#4P1500T134\r"
    arm.move(deg([96.0, 91.0, 90.0, 90.0, 90.0]), duration=0.2, wait=False)
    assert moves(ssc32_emu, arm)[-1].endswith(b"T200\r")
    arm.stop()


def test_a_steep_table_segment_slows_the_move(
    lynx6: ArmModel, ssc32_emu: SSC32Emulator, config_dir: Path
) -> None:
    config_dir.mkdir()
    (config_dir / "lynx6-ssc32.toml").write_text(
        "[servos.base]\nangles_deg = [15, 90, 165]\npulses_us = [600, 1500, 1600]\n"
    )
    driver = open_ssc32(lynx6, ssc32_emu.port)
    driver.move(deg([85.0, 90.0, 90.0, 90.0, 90.0]))
    driver.move(deg([95.0, 90.0, 90.0, 90.0, 90.0]), wait=False)
    # 66.7 µs of pulse, crossing into a segment of 0.75°/µs: 50° worth of pulse speed at 90°/s
    assert moves(ssc32_emu, driver)[-1] == b"#0P1507#1P1500#2P1500#3P1500#4P1500T556\r"
    driver.close()


def test_grip_width_goes_through_the_gripper_table(
    arm: ServoArmDriver, ssc32_emu: SSC32Emulator
) -> None:
    arm.grip(0.0254)  # 1.0 in of 2.0 in
    assert moves(ssc32_emu, arm)[-1] == b"#5P1500\r"


def test_stop_holds_every_servo(arm: ServoArmDriver, ssc32_emu: SSC32Emulator) -> None:
    arm.move(deg([150.0, 90.0, 90.0, 90.0, 90.0]), wait=False)
    arm.stop()
    held = math.degrees(arm.read()[0])  # a reply: the board has read every line before it
    stops = [line for line in ssc32_emu.received if line.startswith(b"STOP")]
    assert stops == [b"STOP%d\r" % ch for ch in range(6)]
    assert 90.0 <= held < 150.0


def test_a_dead_controller_is_a_device_error_after_bounded_retries(
    arm: ServoArmDriver, ssc32_emu: SSC32Emulator
) -> None:
    ssc32_emu.inject("drop", count=3)
    with pytest.raises(DeviceError, match=r"QP\) of channel 0, 1, 2, 3, 4: no reply after 3 tries"):
        arm.read()


def test_emu_port_is_this_driver_on_a_simulated_board(lynx6: ArmModel) -> None:
    from armkit.connect import open_driver

    driver = open_driver(lynx6, "ssc32", "emu")
    assert type(driver) is ServoArmDriver
    driver.move(deg([95.0, 90.0, 90.0, 90.0, 90.0]))
    assert math.degrees(driver.read()[0]) == pytest.approx(95.0)
    driver.close()
    driver.close()


def test_no_port_is_a_clear_error(lynx6: ArmModel) -> None:
    with pytest.raises(DeviceError, match="--port"):
        open_ssc32(lynx6, None)


def test_the_maestro_drives_the_same_arm(lynx6: ArmModel, maestro_emu: MaestroEmulator) -> None:
    driver = open_maestro(lynx6, maestro_emu.port)
    driver.move(lynx6.home)
    q = deg([100.0, 84.0, 99.0, 85.0, 100.0])
    driver.move(q)
    assert driver.read() == pytest.approx(q, abs=1e-12)
    for table, joint in zip(driver.joints, lynx6.joints, strict=True):
        record = [r for r in maestro_emu.history if table.channel in r.servos][-1]
        start, end = record.servos[table.channel]
        turn = abs(table.to_value(end) - table.to_value(start))
        assert turn / record.duration_s <= joint.max_velocity * (1 + 1e-9)
    driver.close()


def test_a_model_without_a_driver_section_is_refused(config_dir: Path) -> None:
    from armkit.model import load_model

    with pytest.raises(ModelError, match=r"\[drivers.ssc32\]"):
        open_ssc32(load_model("openmanipulator_x"), "emu")


def test_a_maestro_move_that_cannot_start_moves_nothing(
    lynx6: ArmModel, maestro_emu: MaestroEmulator
) -> None:
    driver = open_maestro(lynx6, maestro_emu.port)
    driver.move(lynx6.home)
    maestro_emu.inject("drop", count=3)
    with pytest.raises(DeviceError, match="position of channel 0: no reply"):
        driver.move(deg([100.0, 84.0, 99.0, 85.0, 100.0]))
    driver.read()
    assert [p[:2] for p in maestro_emu.received if p[0] == 0x84][-5:] == [
        bytes([0x84, ch]) for ch in range(5)
    ]
    assert len([p for p in maestro_emu.received if p[0] == 0x84]) == 5  # only the home move
    driver.close()


def test_the_factory_opens_both_drivers_on_simulated_controllers(lynx6: ArmModel) -> None:
    from armkit.connect import open_driver

    for name in ("ssc32", "maestro"):
        driver = open_driver(lynx6, name, "emu")
        driver.move(lynx6.home)
        assert driver.read() == pytest.approx(lynx6.home)
        driver.close()


def test_importing_armkit_and_the_servo_modules_does_not_import_pyserial() -> None:
    import subprocess
    import sys

    code = (
        "import sys, armkit, armkit.drivers.servo, armkit.devices.ssc32, armkit.devices.maestro, "
        "armkit.sim.emulators; "
        "assert 'serial' not in sys.modules, 'serial imported'"
    )
    subprocess.run([sys.executable, "-c", code], check=True)


def test_a_new_target_mid_move_is_timed_from_where_the_servo_is(
    arm: ServoArmDriver, ssc32_emu: SSC32Emulator, lynx6: ArmModel
) -> None:
    arm.move(deg([150.0, 90.0, 90.0, 90.0, 90.0]), wait=False)
    arm.move(deg([140.0, 90.0, 90.0, 90.0, 90.0]), wait=False)  # 10° from 150, ~50° from here
    arm.bus.read([0])
    record = ssc32_emu.history[-1]
    start, end = record.servos[0]
    turn = abs(arm.joints[0].to_value(end) - arm.joints[0].to_value(start))
    assert turn > math.radians(30.0)
    assert turn / record.duration_s <= lynx6.joints[0].max_velocity * (1 + 1e-9)
    arm.stop()


@pytest.mark.parametrize("channels", [[0, 1, 2, 3], [0, 1, 2, 3, 3], [0, 1, 2, 3, 40], "0 1 2 3 4"])
def test_a_wrong_channel_list_is_a_model_error(lynx6: ArmModel, channels: object) -> None:
    from dataclasses import replace

    model = replace(lynx6, drivers={"ssc32": {"channels": channels}})
    with pytest.raises(ModelError, match=r"field 'drivers\.ssc32\.channels(\[4\])?': "):
        open_ssc32(model, "emu")
