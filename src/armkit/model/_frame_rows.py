"""A model file's chain as URDF-style joint frames (``dh_convention = "frames"``).

Each ``[[joints]]`` entry then has ``frame = { xyz_mm, rpy_deg, axis }`` instead of
``dh``: the joint's origin in the previous joint's frame (URDF's ``<origin xyz rpy>``,
in mm and degrees, R = Rz(yaw) Ry(pitch) Rx(roll)) and its axis (URDF's ``<axis>``).
An optional ``[base] xyz_mm, rpy_deg`` places the chain's root (the URDF's root link)
in armkit's world frame, so a URDF is transcribed number for number while the world
origin stays at the centre of the base on the table.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from numpy.typing import NDArray

from ._check import MAX_LENGTH_MM, Checker
from ._types import JointFrame

F64 = NDArray[np.float64]
FRAME = {"xyz_mm": list, "rpy_deg": list, "axis": list}
BASE = {"xyz_mm": list, "rpy_deg": list}


def pose(check: Checker, data: Any, where: str) -> F64:
    """The 4x4 transform [m] of a table with ``xyz_mm`` and ``rpy_deg`` (both optional)."""
    xyz = check.numbers(data.get("xyz_mm", [0, 0, 0]), f"{where}.xyz_mm", 3)
    rpy = check.numbers(data.get("rpy_deg", [0, 0, 0]), f"{where}.rpy_deg", 3)
    for k in range(3):
        # a coordinate, not a length: a CAD export's 1e-13 mm is kept as written
        check.within(xyz[k], f"{where}.xyz_mm[{k}]", -MAX_LENGTH_MM, MAX_LENGTH_MM, "mm")
        check.angle(rpy[k], f"{where}.rpy_deg[{k}]")
    T = np.eye(4)
    T[:3, :3] = rpy_matrix(*(math.radians(v) for v in rpy))
    T[:3, 3] = np.array(xyz) / 1000.0
    return T


def rpy_matrix(roll: float, pitch: float, yaw: float) -> F64:
    """R = Rz(yaw) Ry(pitch) Rx(roll) [rad], shape (3, 3) (URDF's fixed-axis rpy)."""
    cr, sr, cp, sp = math.cos(roll), math.sin(roll), math.cos(pitch), math.sin(pitch)
    cy, sy = math.cos(yaw), math.sin(yaw)
    return np.array(
        [
            [cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
            [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
            [-sp, cp * sr, cp * cr],
        ]
    )


def joint_frame(check: Checker, data: Any, where: str) -> JointFrame:
    """One joint's ``frame`` table: its origin [m] and unit axis."""
    check.table(data, where, FRAME, ("axis",))
    axis = check.numbers(data["axis"], f"{where}.axis", 3)
    norm = math.sqrt(sum(a * a for a in axis))
    if not math.isfinite(norm) or norm < 1e-9:
        raise check.fail(f"{where}.axis", f"must be a nonzero vector, got {axis}")
    unit = (axis[0] / norm, axis[1] / norm, axis[2] / norm)
    return JointFrame(pose(check, data, where), unit)


def chain_frames(check: Checker, joints: list[Any], base: Any) -> tuple[JointFrame, ...]:
    """Every joint's frame, the first one's origin given in the world (``[base]`` first)."""
    check.table(base, "base", BASE, ())
    frames = [
        joint_frame(check, j.get("frame"), f"joints[{k}].frame") for k, j in enumerate(joints)
    ]
    first = frames[0]
    frames[0] = JointFrame(pose(check, base, "base") @ first.origin, first.axis)
    return tuple(frames)
