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
from armkit.drivers.servo import open_ssc32, run_calibration
from armkit.model import ArmModel
from armkit.sim.emulators import SSC32Emulator


@pytest.fixture
def ssc32_emu() -> Iterator[SSC32Emulator]:
    """An emulator whose servos move 100 times faster than real ones (the calibration
    steps through every table point at half speed: 40 s on a real arm)."""
    with SSC32Emulator(9600, time_scale=100.0) as emu:
        yield emu


def ideal_deg(pulse: float) -> float:
    return (pulse - 500.0) * 180.0 / 2000.0


class Person:
    """Reads the servo that moved last off a 'real' arm whose servos are 2 % off and
    shifted by -1° (gripper: 2 % and -0.5 mm)."""

    def __init__(self, emu: SSC32Emulator, answers: list[str] | None = None) -> None:
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
    lynx6: ArmModel, ssc32_emu: SSC32Emulator, config_dir: Path
) -> None:
    person, said = Person(ssc32_emu), list[str]()
    driver = open_ssc32(lynx6, ssc32_emu.port)
    path = run_calibration(lynx6, driver, person, said.append)
    driver.close()
    assert path == config_dir / "lynx6-ssc32.toml"
    assert path.stat().st_mode & 0o777 == 0o644
    assert len(person.prompts) == 7 + 7 + 7 + 7 + 7 + 5
    assert tomllib.loads(path.read_text())["servos"]["base"]["angles_deg"][:2] == [15.0, 30.0]
    again = open_ssc32(lynx6, ssc32_emu.port)  # loads the unit's file
    q = np.radians([40.0, 120.0, 10.0, 170.0, 77.0])
    again.grip(0.030)
    again.move(q, wait=False)
    again.bus.read([0])  # the emulator has read the move
    for table, want in zip(again.tables, [*np.degrees(q), 30.0], strict=True):
        got = person.true_value(table.channel, ssc32_emu.servos[table.channel].target_us)
        assert got == pytest.approx(want, abs=0.1)  # 1 µs rounding ~ 0.09°
    again.close()


def test_enter_keeps_the_point_and_bad_input_is_asked_again(
    lynx6: ArmModel, ssc32_emu: SSC32Emulator
) -> None:
    person = Person(ssc32_emu, answers=["fifteen", "15"])
    driver = open_ssc32(lynx6, ssc32_emu.port)
    path = run_calibration(lynx6, driver, person, lambda _: None)
    driver.close()
    assert "not a number" in person.prompts[1]
    base = tomllib.loads(path.read_text())["servos"]["base"]
    assert base["pulses_us"] == [666.7, 833.3, 1166.7, 1500.0, 1833.3, 2166.7, 2333.3]


def test_no_number_after_three_tries_writes_nothing(
    lynx6: ArmModel, ssc32_emu: SSC32Emulator, config_dir: Path
) -> None:
    driver = open_ssc32(lynx6, ssc32_emu.port)
    with pytest.raises(ValueError, match="no number for base after 3 tries"):
        run_calibration(lynx6, driver, Person(ssc32_emu, ["x", "y", "z"]), lambda _: None)
    driver.close()
    assert not config_dir.exists()


def test_measurements_that_go_backwards_are_refused(
    lynx6: ArmModel, ssc32_emu: SSC32Emulator
) -> None:
    driver = open_ssc32(lynx6, ssc32_emu.port)
    with pytest.raises(ValueError, match="must increase"):
        run_calibration(lynx6, driver, Person(ssc32_emu, ["15", "10"]), lambda _: None)
    driver.close()


def test_the_file_is_replaced_atomically(
    lynx6: ArmModel, ssc32_emu: SSC32Emulator, config_dir: Path, monkeypatch: pytest.MonkeyPatch
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
    driver = open_ssc32(lynx6, ssc32_emu.port)
    with pytest.raises(OSError, match="disk full"):
        run_calibration(lynx6, driver, Person(ssc32_emu), lambda _: None)
    driver.close()
    assert calls == [("fsync", ""), ("replace", str(config_dir))]
    assert old.read_text() == "# the old calibration\n"
    assert sorted(p.name for p in config_dir.iterdir()) == ["lynx6-ssc32.toml"]


def test_only_a_servo_driver_can_be_calibrated(lynx6: ArmModel) -> None:
    with pytest.raises(DeviceError, match="--driver ssc32"):
        run_calibration(lynx6, object(), input, print)


def test_a_broken_unit_file_names_the_field(
    lynx6: ArmModel, ssc32_emu: SSC32Emulator, config_dir: Path
) -> None:
    from armkit._errors import ModelError

    config_dir.mkdir()
    (config_dir / "lynx6-ssc32.toml").write_text("[servos.knee]\nangles_deg = [0, 1]\n")
    with pytest.raises(ModelError, match=r"\[servos.knee\] is not a servo of this arm"):
        open_ssc32(lynx6, ssc32_emu.port)
    (config_dir / "lynx6-ssc32.toml").write_text("[servos.base]\nangles_deg = [0, 1]\n")
    with pytest.raises(ModelError, match=r"\[servos.base\] needs angles_deg and pulses_us"):
        open_ssc32(lynx6, ssc32_emu.port)
    assert math.isfinite(1.0)
