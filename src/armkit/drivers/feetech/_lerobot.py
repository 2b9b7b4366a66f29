"""LeRobot's calibration files for a Feetech arm (the SO-101, SO-100): read, write, apply.

LeRobot (huggingface/lerobot, ``lerobot/motors/motors_bus.py``) keeps a unit's
calibration as one JSON object per motor name, each a ``MotorCalibration``: ``id``,
``drive_mode``, ``homing_offset``, ``range_min``, ``range_max`` (integers, in that order),
written by ``draccus.dump(calibration, f, indent=4)`` (``Robot._save_calibration``): 4
spaces, no newline at the end. ``homing_offset`` is what LeRobot wrote into each
servo's Homing Offset register (the servo then reports Present Position = its encoder
minus it); ``range_min``/``range_max`` are Present Positions, also written as the
servo's Min/Max Position Limit.

The joint angle LeRobot gives a body joint in degrees (``MotorNormMode.DEGREES``, the
URDF's "new calibration") is ``(present - mid) * 360 / 4095`` with ``mid = (range_min +
range_max) / 2`` (``SerialMotorsBus._normalize``; 4095 = the STS3215's resolution - 1);
its Feetech bus does not apply ``drive_mode``. ``calibrated`` gives armkit's
``[drivers.feetech]`` the same mapping: each joint's centre step is its ``mid``, 4095
steps per turn; the gripper's shut jaws at its ``range_min``.
"""

from __future__ import annotations

import dataclasses
import json
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from ..._errors import ModelError
from ..._files import config_dir, write_atomic
from ...model import ArmModel, FeetechSection

FIELDS = ("id", "drive_mode", "homing_offset", "range_min", "range_max")
LEROBOT_STEPS_PER_TURN = 4095  # LeRobot's degrees: 360 / (resolution - 1) per step
GRIPPER = "gripper"


@dataclass(frozen=True)
class MotorCalibration:
    """One motor of a LeRobot calibration file (LeRobot's own names and meanings).

    Attributes:
        id: the servo's ID.  drive_mode: 0 or 1 (LeRobot's Feetech bus ignores it).
        homing_offset: written to the servo's Homing Offset [step].
        range_min, range_max: the joint's range in Present Position steps.
    """

    id: int
    drive_mode: int
    homing_offset: int
    range_min: int
    range_max: int


Calibration = dict[str, MotorCalibration]


def calibration_path(model: ArmModel) -> Path:
    """Where a unit's calibration is kept: ``<config>/<arm>_feetech.json``."""
    return config_dir() / f"{model.name}_feetech.json"


def calibration_text(calibration: Calibration) -> str:
    """The file's text as LeRobot writes it (``draccus.dump(..., indent=4)``)."""
    return json.dumps({name: dataclasses.asdict(m) for name, m in calibration.items()}, indent=4)


def write_calibration(path: Path, calibration: Calibration) -> None:
    """Write ``calibration`` to ``path`` (atomically) in LeRobot's format."""
    write_atomic(path, calibration_text(calibration))


def read_calibration(path: Path, model: ArmModel) -> Calibration:
    """A LeRobot calibration file for ``model`` (its joints' names and ``gripper``).

    Raises:
        ModelError: unreadable, not LeRobot's format, or a value out of range (named).
    """
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, UnicodeDecodeError, ValueError) as exc:
        raise ModelError(f"{path}: cannot read a LeRobot calibration file ({exc})") from None
    names = [*model.joint_names, GRIPPER] if model.gripper.width_max > 0 else [*model.joint_names]
    if not isinstance(data, dict) or sorted(data) != sorted(names):
        got = sorted(data) if isinstance(data, dict) else type(data).__name__
        raise ModelError(
            f"{path}: a LeRobot calibration of the {model.name} names {names}, got {got}"
        )
    return {name: _motor(path, name, data[name]) for name in names}


def _motor(path: Path, name: str, data: Any) -> MotorCalibration:
    where = f"{path}: {name}"
    if not isinstance(data, dict) or sorted(data) != sorted(FIELDS):
        raise ModelError(f"{where} must have exactly {list(FIELDS)}, got {data!r}")
    for field in FIELDS:
        if type(data[field]) is not int:
            raise ModelError(f"{where}.{field} must be an integer, got {data[field]!r}")
    m = MotorCalibration(**data)
    checks = (
        (0 <= m.id <= 253, "id must be 0..253"),
        (m.drive_mode in (0, 1), "drive_mode must be 0 or 1"),
        (-2047 <= m.homing_offset <= 2047, "homing_offset must be -2047..2047 steps"),
        (0 <= m.range_min < m.range_max <= 4095, "needs 0 <= range_min < range_max <= 4095"),
    )
    for ok, why in checks:
        if not ok:
            raise ModelError(f"{where}: {why}, got {dataclasses.asdict(m)}")
    return m


def calibrated(config: FeetechSection, calibration: Calibration, model: ArmModel) -> FeetechSection:
    """``config`` with a unit's LeRobot calibration: its IDs, each joint's centre step
    the middle of its range, LeRobot's 4095 steps per turn, the jaws shut at the
    gripper's ``range_min``."""
    joints = [calibration[name] for name in model.joint_names]
    grip = calibration.get(GRIPPER)
    return dataclasses.replace(
        config,
        ids=tuple(m.id for m in joints),
        gripper_id=grip.id if grip is not None else config.gripper_id,
        ticks_per_turn=LEROBOT_STEPS_PER_TURN,
        center_ticks=tuple((m.range_min + m.range_max) / 2 for m in joints),
        direction=(1,) * len(joints),
        gripper_zero_tick=grip.range_min if grip is not None else config.gripper_zero_tick,
        gripper_direction=1,
    )


def unit_config(model: ArmModel, config: FeetechSection) -> FeetechSection:
    """``config`` with this unit's calibration file applied where there is one."""
    path = calibration_path(model)
    return calibrated(config, read_calibration(path, model), model) if path.exists() else config
