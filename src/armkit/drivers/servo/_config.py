"""Where a servo arm's tables come from: the model's defaults, then the unit's own file.

The model file's ``[drivers.<name>]`` section (``ssc32`` or ``maestro``; the
Maestro falls back to the SSC-32's) gives:

    channels      one per joint, then the gripper's (optional)
    baudrate      serial speed (default 9600)
    center_deg    per joint: the joint angle at 1500 µs (default 90, as 002)
    direction     per joint: +1, or -1 for a servo mounted the other way round
    grip_pulse_us [closed, open] gripper pulses [µs] (default [500, 2500])
    settle_ms     how long the servos take to catch up with their pulses after a move
                  [ms] (default 100): the controller cannot tell, so a waiting move waits

A unit's measured tables (written by ``calibrate_servos``) live in
``<config dir>/<arm>-<driver>.toml``; the config dir is ``$ARMKIT_CONFIG_DIR``, else
``$XDG_CONFIG_HOME/armkit``, else ``~/.config/armkit``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from ..._errors import ModelError
from ..._files import config_dir
from ..._toml_files import read_toml
from ...model import ArmModel, ServoSection, servo_section
from ._table import ServoCalibration, ideal_grip, ideal_joint

_SCALE = {"deg": math.radians(1.0), "mm": 0.001}  # shown value -> SI
_VALUE_KEY = {"deg": "angles_deg", "mm": "widths_mm"}


@dataclass(frozen=True)
class ServoSetup:
    """Everything a servo driver needs to know before it opens a port.

    Attributes:
        joints: one table per joint, model order.  grip: the gripper's table, or None.
        baudrate: serial speed.  unit_file: the unit's calibration file (it may not exist yet).
        settle_s: time the servos need to reach their pulses after a move ends [s].
    """

    joints: tuple[ServoCalibration, ...]
    grip: ServoCalibration | None
    baudrate: int
    unit_file: Path
    settle_s: float = 0.1


def driver_section(model: ArmModel, driver: str) -> ServoSection:
    """The model's ``[drivers.<driver>]`` table, typed (the Maestro may use the SSC-32's)."""
    for name in (driver, "ssc32"):
        if isinstance(model.drivers.get(name), dict):
            return servo_section(model, name)
    raise ModelError(
        f"{model.name} has no [drivers.{driver}] section; add one with channels = [...] "
        "(one channel per joint, then the gripper's)"
    )


def load_setup(model: ArmModel, driver: str) -> ServoSetup:
    """The tables for ``model`` on ``driver``: model defaults overridden by the unit's file.

    Raises:
        ModelError: the driver section or the unit file is wrong (names the field).
    """
    section = driver_section(model, driver)
    joints, grip = _defaults(model, section, f"{model.name} [drivers.{driver}]")
    unit_file = config_dir() / f"{model.name}-{driver}.toml"
    if unit_file.is_file():
        joints, grip = _apply_unit_file(unit_file, joints, grip)
    return ServoSetup(joints, grip, section.baudrate, unit_file, section.settle_ms / 1000.0)


def _defaults(
    model: ArmModel, section: ServoSection, where: str
) -> tuple[tuple[ServoCalibration, ...], ServoCalibration | None]:
    """002's ideal tables from the section (checked when the model loaded)."""
    dof, channels = model.dof, section.channels
    try:
        joints = tuple(
            ideal_joint(j.name, ch, j.lower, j.upper, center, direction)
            for j, ch, center, direction in zip(
                model.joints, channels, section.center_deg, section.direction, strict=False
            )
        )
        g = model.gripper
        grip = (
            ideal_grip(channels[dof], g.width_min, g.width_max, section.grip_pulse_us)
            if len(channels) > dof
            else None
        )
    except (ValueError, TypeError) as exc:
        raise ModelError(f"{where}: {exc}") from None
    return joints, grip


def _apply_unit_file(
    path: Path, joints: tuple[ServoCalibration, ...], grip: ServoCalibration | None
) -> tuple[tuple[ServoCalibration, ...], ServoCalibration | None]:
    servos = read_toml(path, ModelError, "calibration")[0].get("servos", {})
    if not isinstance(servos, dict):
        raise ModelError(f"{path}: [servos] must be tables [servos.NAME]")
    by_name = {c.name: c for c in (*joints, *([grip] if grip else []))}
    for name, entry in servos.items():
        if name not in by_name:
            raise ModelError(
                f"{path}: [servos.{name}] is not a servo of this arm ({', '.join(by_name)})"
            )
        by_name[name] = _entry_to_table(path, name, entry, by_name[name])
    return tuple(by_name[c.name] for c in joints), (by_name["grip"] if grip else None)


def _entry_to_table(
    path: Path, name: str, entry: Any, default: ServoCalibration
) -> ServoCalibration:
    key = _VALUE_KEY[default.unit]
    try:
        values = tuple(float(v) * _SCALE[default.unit] for v in entry[key])
        pulses = tuple(float(p) for p in entry["pulses_us"])
        channel = int(entry.get("channel", default.channel))
        return ServoCalibration(name, channel, values, pulses, default.unit)
    except (KeyError, TypeError, ValueError) as exc:
        raise ModelError(
            f"{path}: [servos.{name}] needs {key} and pulses_us lists of numbers: {exc}"
        ) from None


def table_to_toml(cal: ServoCalibration) -> str:
    """One ``[servos.<name>]`` TOML table for ``cal``, in degrees or millimetres."""
    values = ", ".join(f"{cal.shown(v):.3f}" for v in cal.values)
    pulses = ", ".join(f"{p:.1f}" for p in cal.pulses_us)
    return (
        f"[servos.{cal.name}]\nchannel = {cal.channel}\n"
        f"{_VALUE_KEY[cal.unit]} = [{values}]\npulses_us = [{pulses}]\n"
    )
