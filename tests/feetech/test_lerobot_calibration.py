"""LeRobot's calibration files (issue 31 item 4): a file in LeRobot's format read and
written back is the same text; the joint angles armkit reads through it are LeRobot's;
``armkit --arm so101 calibrate`` writes one by LeRobot's procedure.

The format and the conversion are LeRobot's (huggingface/lerobot): ``MotorCalibration``
(id, drive_mode, homing_offset, range_min, range_max) per motor name, saved by
``draccus.dump(self.calibration, f, indent=4)`` (``Robot._save_calibration``); a body
joint's degrees ``(present - (range_min + range_max) / 2) * 360 / 4095`` and back
``int(degrees * 4095 / 360 + mid)`` (``SerialMotorsBus._normalize``/``_unnormalize``,
``MotorNormMode.DEGREES``); Feetech's bus applies no drive mode.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest

from armkit._errors import ModelError
from armkit.cli import main
from armkit.connect import forecaster, open_driver
from armkit.drivers.feetech import (
    FeetechDriver,
    FeetechForecaster,
    calibrate_feetech,
    calibrated,
    calibration_path,
    calibration_text,
    read_calibration,
    write_calibration,
)
from armkit.model import FEETECH_SECTION, load_model
from armkit.sim import World
from armkit.sim.feetech import SimFeetechBus
from armkit.sim.feetech_operator import FeetechOperator

MODEL = load_model("so101")
# An SO-101 follower's file as LeRobot writes it (ranges of a unit published in the
# SO-ARM101 community notes; the offsets as set_half_turn_homings leaves them).
LEROBOT = {
    "shoulder_pan": {"id": 1, "drive_mode": 0, "homing_offset": -1013, "range_min": 884, "range_max": 3320},
    "shoulder_lift": {"id": 2, "drive_mode": 0, "homing_offset": 1225, "range_min": 756, "range_max": 3353},
    "elbow_flex": {"id": 3, "drive_mode": 0, "homing_offset": -1108, "range_min": 868, "range_max": 3061},
    "wrist_flex": {"id": 4, "drive_mode": 0, "homing_offset": -1181, "range_min": 805, "range_max": 3153},
    "wrist_roll": {"id": 5, "drive_mode": 0, "homing_offset": 1400, "range_min": 0, "range_max": 4095},
    "gripper": {"id": 6, "drive_mode": 0, "homing_offset": 1397, "range_min": 1899, "range_max": 3363},
}  # fmt: skip
TEXT = json.dumps(LEROBOT, indent=4)  # what draccus.dump(..., indent=4) writes


def test_a_lerobot_file_read_and_written_back_is_the_same_text(tmp_path: Path) -> None:
    source = tmp_path / "follower.json"
    source.write_text(TEXT, encoding="utf-8")
    calibration = read_calibration(source, MODEL)
    assert calibration_text(calibration) == TEXT
    copy = tmp_path / "copy.json"
    write_calibration(copy, calibration)
    assert copy.read_bytes() == source.read_bytes()
    assert read_calibration(copy, MODEL) == calibration


def test_the_joint_angles_are_lerobots_for_the_same_file(tmp_path: Path) -> None:
    (tmp_path / "f.json").write_text(TEXT, encoding="utf-8")
    cal = read_calibration(tmp_path / "f.json", MODEL)
    unit = FeetechForecaster(MODEL, calibrated(FEETECH_SECTION.of(MODEL), cal, MODEL))
    rng = np.random.default_rng(4)
    names = MODEL.joint_names
    mids = np.array([(cal[n].range_min + cal[n].range_max) / 2 for n in names])
    for _ in range(500):
        present = np.array([rng.integers(cal[n].range_min, cal[n].range_max + 1) for n in names])
        lerobot_deg = (present - mids) * 360 / 4095  # _normalize, DEGREES
        assert np.allclose(np.degrees(unit.angles(present)), lerobot_deg, rtol=0, atol=1e-12)
        back = [int(d * 4095 / 360 + m) for d, m in zip(lerobot_deg, mids, strict=True)]
        assert np.abs(unit.ticks(np.radians(lerobot_deg)) - back).max() <= 1  # LeRobot truncates
    assert unit.config.ids == (1, 2, 3, 4, 5) and unit.config.gripper_id == 6


@pytest.mark.parametrize(
    ("change", "words"),
    [
        (lambda d: d.pop("gripper"), "names ['shoulder_pan'"),
        (lambda d: d["elbow_flex"].pop("drive_mode"), "elbow_flex must have exactly"),
        (lambda d: d["wrist_flex"].update(range_min=3200), "range_min < range_max"),
        (lambda d: d["shoulder_pan"].update(id=1.5), "shoulder_pan.id must be an integer"),
        (lambda d: d["gripper"].update(homing_offset=3000), "homing_offset must be -2047..2047"),
    ],
)
def test_a_file_not_in_lerobots_format_is_refused_naming_the_field(
    tmp_path: Path, change: object, words: str
) -> None:
    data = json.loads(TEXT)
    change(data)  # type: ignore[operator]
    path = tmp_path / "bad.json"
    path.write_text(json.dumps(data, indent=4), encoding="utf-8")
    with pytest.raises(ModelError, match=words.replace("[", r"\[")):
        read_calibration(path, MODEL)


def test_calibrate_on_the_simulator_is_lerobots_procedure() -> None:
    world = World()
    driver = open_driver(MODEL, "sim", world=world)
    assert isinstance(driver, FeetechDriver)
    bus = world.arm().device
    assert isinstance(bus, SimFeetechBus)
    said: list[str] = []
    try:
        path = calibrate_feetech(MODEL, driver, FeetechOperator(world.arm()).ask, said.append)
    finally:
        driver.close()
    assert path == calibration_path(MODEL)
    cal = read_calibration(path, MODEL)
    assert path.read_text(encoding="utf-8") == calibration_text(cal)  # LeRobot's text
    for m in cal.values():
        servo = bus.servos[m.id]
        assert servo.value("Homing Offset") == m.homing_offset  # written to the servo
        assert (servo.value("Min Position Limit"), servo.value("Max Position Limit")) == (
            m.range_min,
            m.range_max,
        )
        assert m.drive_mode == 0 and m.range_min < m.range_max
    # the middle pose (every joint 0) reads the half turn; a joint's ends are its limits
    per_step = 2 * math.pi / 4096
    for j, name in enumerate(MODEL.joint_names[:4]):
        m = cal[name]
        assert m.range_min == pytest.approx(2047 + MODEL.lower[j] / per_step, abs=1)
        assert m.range_max == pytest.approx(2047 + MODEL.upper[j] / per_step, abs=1)
    assert (cal["wrist_roll"].range_min, cal["wrist_roll"].range_max) == (0, 4095)


def test_the_unit_file_calibrates_the_real_ports_driver_not_the_simulator(
    config_dir: Path,
) -> None:
    calibration_path(MODEL).parent.mkdir(parents=True, exist_ok=True)
    calibration_path(MODEL).write_text(TEXT, encoding="utf-8")
    real = forecaster(MODEL, "feetech", port="/dev/ttyACM0")
    sim = forecaster(MODEL, "sim")
    assert isinstance(real, FeetechForecaster) and isinstance(sim, FeetechForecaster)
    assert real.config.centers[0] == (884 + 3320) / 2 and real.config.ticks_per_turn == 4095
    assert sim.config.centers[0] == 2048 and sim.config.ticks_per_turn == 4096


def test_the_cli_calibrates_the_simulated_so101(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["--arm", "so101", "calibrate"]) == 0
    out = capsys.readouterr().out
    assert "wrote" in out and "so101_feetech.json" in out
    assert read_calibration(calibration_path(MODEL), MODEL)["wrist_roll"].range_max == 4095
