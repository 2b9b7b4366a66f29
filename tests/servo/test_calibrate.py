"""Calibration with scripted answers against the SSC-32 emulator."""

from __future__ import annotations

import math
import os
import tomllib
from collections.abc import Iterator
from pathlib import Path

import numpy as np
import pytest

from armkit._errors import DeviceError
from armkit.drivers.servo import ServoArmDriver, calibrate_servos, open_ssc32
from armkit.model import ArmModel
from armkit.sim import World
from armkit.sim._pulses import MoveRecord, VirtualServo
from armkit.sim._wire import Wire, serial_port
from armkit.sim.ssc32 import SimSSC32


class Board:
    """A simulated SSC-32 in a virtual-time world: the calibration (every table point at
    half speed: 40 s on a real arm) runs in simulated time, the driver's clock the world's."""

    def __init__(self) -> None:
        self.world, self.device = World(), SimSSC32(9600)

    def open(self, model: ArmModel) -> ServoArmDriver:
        line = serial_port(Wire(self.device, self.world, baudrate=9600, timeout=0.1))
        return open_ssc32(model, line, clock=self.world.clock)

    @property
    def history(self) -> list[MoveRecord]:
        return list(self.device.history)

    @property
    def servos(self) -> list[VirtualServo]:
        return self.device.servos

    def pulse(self, channel: int) -> float:
        return self.device.pulse(channel, self.world.now())


@pytest.fixture
def ssc32_emu() -> Iterator[Board]:
    yield Board()


def ideal_deg(pulse: float) -> float:
    return (pulse - 500.0) * 180.0 / 2000.0


class Person:
    """Reads the servo that moved last off a 'real' arm whose servos are 2 % off and
    shifted by -1° (gripper: 2 % and -0.5 mm)."""

    def __init__(self, emu: Board, answers: list[str] | None = None) -> None:
        self.emu, self.answers = emu, answers
        self.prompts: list[str] = []

    def true_value(self, channel: int, pulse: float) -> float:
        if channel == 5:
            return 1.02 * ideal_deg(pulse) / 180.0 * 50.8 - 0.5
        return 1.02 * ideal_deg(pulse) - 1.0

    def __call__(self, prompt: str) -> str:
        self.prompts.append(prompt)
        if self.answers is not None:
            return self.answers.pop(0) if self.answers else ""
        (channel,) = self.emu.history[-1].servos
        return f"{self.true_value(channel, self.emu.pulse(channel)):.4f}"


def test_measured_tables_make_the_real_arm_reach_the_asked_angles(
    lynx6: ArmModel, ssc32_emu: Board, config_dir: Path
) -> None:
    person, said = Person(ssc32_emu), list[str]()
    driver = ssc32_emu.open(lynx6)
    path = calibrate_servos(lynx6, driver, person, said.append)
    driver.close()
    assert path == config_dir / "lynx6-ssc32.toml"
    assert path.stat().st_mode & 0o777 == 0o644
    assert len(person.prompts) == 7 + 7 + 7 + 7 + 7 + 5
    assert tomllib.loads(path.read_text())["servos"]["base"]["angles_deg"][:2] == [15.0, 30.0]
    again = ssc32_emu.open(lynx6)  # loads the unit's file
    q = np.radians([40.0, 120.0, 10.0, 170.0, 77.0])
    again.grip(0.030)
    again.move(q, wait=False)
    again.bus.read([0])  # the emulator has read the move
    for table, want in zip(again.tables, [*np.degrees(q), 30.0], strict=True):
        got = person.true_value(table.channel, ssc32_emu.servos[table.channel].target_us)
        assert got == pytest.approx(want, abs=0.1)  # 1 µs rounding ~ 0.09°
    again.close()


def test_enter_keeps_the_point_and_bad_input_is_asked_again(
    lynx6: ArmModel, ssc32_emu: Board
) -> None:
    person = Person(ssc32_emu, answers=["fifteen", "15"])
    driver = ssc32_emu.open(lynx6)
    path = calibrate_servos(lynx6, driver, person, lambda _: None)
    driver.close()
    assert "not a number" in person.prompts[1]
    base = tomllib.loads(path.read_text())["servos"]["base"]
    assert base["pulses_us"] == [666.7, 833.3, 1166.7, 1500.0, 1833.3, 2166.7, 2333.3]


def test_no_number_after_three_tries_writes_nothing(
    lynx6: ArmModel, ssc32_emu: Board, config_dir: Path
) -> None:
    driver = ssc32_emu.open(lynx6)
    with pytest.raises(ValueError, match="no reading within 45 degrees of the point for base"):
        calibrate_servos(lynx6, driver, Person(ssc32_emu, ["x", "y", "z"]), lambda _: None)
    driver.close()
    assert not config_dir.exists()


def test_measurements_that_go_backwards_are_refused(lynx6: ArmModel, ssc32_emu: Board) -> None:
    driver = ssc32_emu.open(lynx6)
    with pytest.raises(ValueError, match="must increase"):
        calibrate_servos(lynx6, driver, Person(ssc32_emu, ["15", "10"]), lambda _: None)
    driver.close()


def test_the_file_is_replaced_atomically(
    lynx6: ArmModel, ssc32_emu: Board, config_dir: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    config_dir.mkdir()
    old = config_dir / "lynx6-ssc32.toml"
    old.write_text("# the old calibration\n")
    calls: list[tuple[str, str]] = []
    real_fsync = os.fsync

    def fsync(fd: int) -> None:
        calls.append(("fsync", ""))
        real_fsync(fd)

    def failing_replace(src: str, dst: Path) -> None:
        calls.append(("replace", str(Path(src).parent)))
        raise OSError("disk full")

    monkeypatch.setattr(os, "fsync", fsync)
    monkeypatch.setattr(os, "replace", failing_replace)
    driver = ssc32_emu.open(lynx6)
    with pytest.raises(OSError, match="disk full"):
        calibrate_servos(lynx6, driver, Person(ssc32_emu), lambda _: None)
    driver.close()
    assert calls == [("fsync", ""), ("replace", str(config_dir))]
    assert old.read_text() == "# the old calibration\n"
    assert sorted(p.name for p in config_dir.iterdir()) == ["lynx6-ssc32.toml"]


def test_only_a_servo_driver_can_be_calibrated(lynx6: ArmModel) -> None:
    with pytest.raises(DeviceError, match="--driver ssc32"):
        calibrate_servos(lynx6, object(), input, print)


def test_a_broken_unit_file_names_the_field(
    lynx6: ArmModel, ssc32_emu: Board, config_dir: Path
) -> None:
    from armkit._errors import ModelError

    config_dir.mkdir()
    (config_dir / "lynx6-ssc32.toml").write_text("[servos.knee]\nangles_deg = [0, 1]\n")
    with pytest.raises(ModelError, match=r"\[servos.knee\] is not a servo of this arm"):
        ssc32_emu.open(lynx6)
    (config_dir / "lynx6-ssc32.toml").write_text("[servos.base]\nangles_deg = [0, 1]\n")
    with pytest.raises(ModelError, match=r"\[servos.base\] needs angles_deg and pulses_us"):
        ssc32_emu.open(lynx6)
    assert math.isfinite(1.0)


def test_a_reading_far_from_its_point_is_asked_again(lynx6: ArmModel, ssc32_emu: Board) -> None:
    """The Lynx6 calibration accepted -500 deg for the 15 deg point (issue 28)."""
    person = Person(ssc32_emu, answers=["-500", "nan", "15"])
    driver = ssc32_emu.open(lynx6)
    path = calibrate_servos(lynx6, driver, person, lambda _: None)
    driver.close()
    assert "-500 degrees is more than 45 degrees from 15.0" in person.prompts[1]
    assert "more than 45 degrees" in person.prompts[2]  # nan: no number to keep either
    base = tomllib.loads(path.read_text())["servos"]["base"]
    assert base["pulses_us"] == [666.7, 833.3, 1166.7, 1500.0, 1833.3, 2166.7, 2333.3]
