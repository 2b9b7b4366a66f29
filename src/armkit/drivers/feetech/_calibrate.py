"""``armkit calibrate`` for a Feetech arm: LeRobot's calibration, asked the armkit way.

As LeRobot's ``calibrate`` of an SO-101 does it (``so101_follower.py``: torque off, the
arm to the middle of its range, ``set_half_turn_homings``, the range of each joint,
``write_calibration``, ``_save_calibration``): every servo's Homing Offset is reset to 0,
then set so that the pose a person holds the arm in reads the half turn (step 2047);
each joint but ``wrist_roll`` is moved by hand to both ends of its range (LeRobot
samples while the person sweeps; here the person says when each end is reached),
``wrist_roll`` turns fully (0..4095, as LeRobot's); Min and Max Position Limit are
written to each servo and the file in LeRobot's format to ``<config>/<arm>_feetech.json``
(the same file works back in LeRobot). The arm then holds where it is.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

from ..._errors import DeviceError
from ...model import ArmModel
from ._driver import FeetechDriver
from ._lerobot import GRIPPER, MotorCalibration, calibration_path, write_calibration

HALF_TURN = 2047  # LeRobot's half turn: int((4096 - 1) / 2)
FULL_TURN = "wrist_roll"  # LeRobot's full_turn_motor: its range is the whole turn
MIDDLE = "Move the arm by hand to the middle of its range of motion, then press Enter"
END = "Move {name} by hand to {which} end of its range, then press Enter"


def calibrate_feetech(
    model: ArmModel, driver: object, ask: Callable[[str], str], say: Callable[[str], None]
) -> Path:
    """Calibrate the unit as LeRobot does; return the file written."""
    if not isinstance(driver, FeetechDriver):
        raise DeviceError(f"the Feetech calibration needs the feetech driver, got {driver!r}")
    bus, cfg = driver.bus, driver.forecaster().config
    names = list(model.joint_names)
    ids = list(cfg.ids)
    if cfg.gripper_id is not None:
        names.append(GRIPPER)
        ids.append(cfg.gripper_id)
    say(f"calibrating the {model.name}: its torque goes off, support the arm")
    driver.relax()
    ask(MIDDLE)
    for sid in ids:
        bus.set_eeprom(sid, "Homing Offset", 0)
        bus.set_eeprom(sid, "Min Position Limit", 0)
        bus.set_eeprom(sid, "Max Position Limit", 4095)
    present = bus.sync_read("Present Position", ids)
    offsets = {sid: present[sid] - HALF_TURN for sid in ids}
    for sid in ids:
        bus.set_eeprom(sid, "Homing Offset", offsets[sid])
    calibration: dict[str, MotorCalibration] = {}
    for name, sid in zip(names, ids, strict=True):
        low, high = (0, 4095) if name == FULL_TURN else _ends(bus, sid, name, ask)
        bus.set_eeprom(sid, "Min Position Limit", low)
        bus.set_eeprom(sid, "Max Position Limit", high)
        calibration[name] = MotorCalibration(sid, 0, offsets[sid], low, high)
        say(f"{name}: servo {sid}, homing offset {offsets[sid]}, range {low}..{high}")
    path = calibration_path(model)
    write_calibration(path, calibration)
    driver.stiffen()
    return path


def _ends(bus: object, sid: int, name: str, ask: Callable[[str], str]) -> tuple[int, int]:
    """The joint's two ends, as a person moves it there [Present Position steps]."""
    seen = []
    for which in ("one", "the other"):
        ask(END.format(name=name, which=which))
        seen.append(bus.read(sid, "Present Position"))  # type: ignore[attr-defined]
    low, high = min(seen), max(seen)
    if low == high:
        raise DeviceError(f"{name} (servo {sid}) read step {low} at both ends: it did not move")
    return low, high
