"""Rotations and poses used by the scene: yaw about z, which face of a cube is up."""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import NDArray

F64 = NDArray[np.float64]

FACES = ("+z", "-z", "+x", "-x", "+y", "-y")
_NORMALS = {
    "+x": (1.0, 0.0, 0.0),
    "-x": (-1.0, 0.0, 0.0),
    "+y": (0.0, 1.0, 0.0),
    "-y": (0.0, -1.0, 0.0),
    "+z": (0.0, 0.0, 1.0),
    "-z": (0.0, 0.0, -1.0),
}


def rot_z(yaw: float) -> F64:
    """Rotation about z by ``yaw`` [rad], shape (3, 3)."""
    c, s = math.cos(yaw), math.sin(yaw)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


def rot_axis(axis: F64, angle: float) -> F64:
    """Rotation about the unit vector ``axis`` (3,) by ``angle`` [rad] (Rodrigues), (3, 3)."""
    k = np.asarray(axis, dtype=np.float64) / float(np.linalg.norm(axis))
    K = np.array([[0.0, -k[2], k[1]], [k[2], 0.0, -k[0]], [-k[1], k[0], 0.0]])
    rotation: F64 = np.eye(3) + math.sin(angle) * K + (1.0 - math.cos(angle)) * (K @ K)
    return rotation


def face_up(face: str) -> F64:
    """The rotation that turns a body's ``face`` (``"+x"`` ... ``"-z"``) to point up,
    shape (3, 3): a fixed choice per face, so that ``R = rot_z(yaw) @ face_up(face)``."""
    n = np.array(_NORMALS[face])
    if face == "+z":
        return np.eye(3)
    if face == "-z":
        return rot_axis(np.array([1.0, 0.0, 0.0]), math.pi)
    axis = np.cross(n, np.array([0.0, 0.0, 1.0]))
    return rot_axis(axis, math.pi / 2.0)


def yaw_and_face(R: F64) -> tuple[float, str, float]:
    """Split an orientation ``R`` (3, 3) into (yaw [rad], the face nearest up, tilt [rad]):
    the tilt is the angle between that face's normal and the vertical."""
    up_in_body = R[2, :]  # world z expressed in the body frame
    face = max(FACES, key=lambda f: float(np.dot(_NORMALS[f], up_in_body)))
    tilt = math.acos(min(1.0, float(np.dot(_NORMALS[face], up_in_body))))
    Rz = R @ face_up(face).T
    yaw = math.atan2(Rz[1, 0] - Rz[0, 1], Rz[0, 0] + Rz[1, 1])
    return yaw, face, tilt


def pose(R: F64, p: F64) -> F64:
    """Homogeneous transform from a rotation (3, 3) and a translation (3,), shape (4, 4)."""
    T = np.eye(4)
    T[:3, :3] = R
    T[:3, 3] = p
    return T


def wrap(angle: float) -> float:
    """``angle`` [rad] wrapped to [-pi, pi)."""
    return (angle + math.pi) % (2.0 * math.pi) - math.pi
