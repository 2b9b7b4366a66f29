"""Transforms and numbers as the attribute text of URDF and MJCF elements.

Numbers are written with ``repr`` (the shortest text that reads back as the same
float), so a file read back gives the chain to the last bit.
"""

from __future__ import annotations

import math
from collections.abc import Iterable

import numpy as np
from numpy.typing import NDArray

F64 = NDArray[np.float64]


def numbers(values: Iterable[float]) -> str:
    """``"x y z"``: floats separated by spaces, each exact."""
    return " ".join(repr(float(x)) for x in values)


def rpy(R: F64) -> tuple[float, float, float]:
    """URDF's (roll, pitch, yaw) [rad] of a rotation, R = Rz(yaw) Ry(pitch) Rx(roll)."""
    pitch = math.atan2(-R[2, 0], math.hypot(R[0, 0], R[1, 0]))
    if math.hypot(R[0, 0], R[1, 0]) > 1e-12:
        return math.atan2(R[2, 1], R[2, 2]), pitch, math.atan2(R[1, 0], R[0, 0])
    return math.atan2(-R[1, 2], R[1, 1]), pitch, 0.0  # pitch +-90 deg: roll - yaw only


def urdf_origin(T: F64) -> str:
    """``<origin xyz rpy>`` of a transform [m]."""
    return f'<origin xyz="{numbers(T[:3, 3])}" rpy="{numbers(rpy(T[:3, :3]))}"/>'


def quaternion(R: F64) -> tuple[float, float, float, float]:
    """The unit quaternion (w, x, y, z) of a rotation matrix, w >= 0 (Shepperd's method)."""
    t = R[0, 0] + R[1, 1] + R[2, 2]
    if t > 0.0:
        s = 2.0 * math.sqrt(1.0 + t)
        w, x, y, z = (
            s / 4,
            (R[2, 1] - R[1, 2]) / s,
            (R[0, 2] - R[2, 0]) / s,
            (R[1, 0] - R[0, 1]) / s,
        )
    elif R[0, 0] >= R[1, 1] and R[0, 0] >= R[2, 2]:
        s = 2.0 * math.sqrt(1.0 + R[0, 0] - R[1, 1] - R[2, 2])
        w, x, y, z = (
            (R[2, 1] - R[1, 2]) / s,
            s / 4,
            (R[0, 1] + R[1, 0]) / s,
            (R[0, 2] + R[2, 0]) / s,
        )
    elif R[1, 1] >= R[2, 2]:
        s = 2.0 * math.sqrt(1.0 + R[1, 1] - R[0, 0] - R[2, 2])
        w, x, y, z = (
            (R[0, 2] - R[2, 0]) / s,
            (R[0, 1] + R[1, 0]) / s,
            s / 4,
            (R[1, 2] + R[2, 1]) / s,
        )
    else:
        s = 2.0 * math.sqrt(1.0 + R[2, 2] - R[0, 0] - R[1, 1])
        w, x, y, z = (
            (R[1, 0] - R[0, 1]) / s,
            (R[0, 2] + R[2, 0]) / s,
            (R[1, 2] + R[2, 1]) / s,
            s / 4,
        )
    sign = -1.0 if w < 0.0 else 1.0
    return sign * w, sign * x, sign * y, sign * z


def mjcf_pose(T: F64) -> str:
    """``pos="..." quat="..."`` of a transform [m] (MuJoCo's quaternion is w x y z)."""
    return f'pos="{numbers(T[:3, 3])}" quat="{numbers(quaternion(T[:3, :3]))}"'


def pose(R: F64, p: F64) -> F64:
    """The 4x4 transform of a rotation ``R`` (3, 3) and a translation ``p`` (3,) [m]."""
    T = np.eye(4)
    T[:3, :3], T[:3, 3] = R, p
    return T


def z_onto(v: F64) -> F64:
    """A rotation (3, 3) taking the z axis onto the unit vector ``v``."""
    z = np.array([0.0, 0.0, 1.0])
    c, w = float(z @ v), np.cross(z, v)
    if np.linalg.norm(w) < 1e-12:
        return np.eye(3) if c > 0 else np.diag([1.0, -1.0, -1.0])
    K = np.array([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]])
    R: F64 = np.eye(3) + K + K @ K / (1.0 + c)
    return R
