"""Would closing the jaws grasp a cube? Tolerances from the jaw geometry and the
cube's size: the cube must lie between the open jaws, turned no more than the
jaws can square up, and the pads must cover at least half their length and
width of its faces (001's "is the end effector on the cube?")."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from ..model import Gripper
from ._cube import Cube
from ._rotations import pose, rot_axis

F64 = NDArray[np.float64]
SQUARE_MAX = math.radians(20.0)  # closing jaws square up a cube turned this much
MIN_COVER = 0.5  # fraction of each pad's length and width that must be on the cube
AXIS_NAMES = ("approach", "across", "jaw")


@dataclass(frozen=True)
class Grasp:
    """The outcome of closing the jaws on a cube.

    Attributes:
        ok: the cube is held.
        T_tool_object: the cube's centre pose in the tool frame once held, squared
            up and centred between the jaws (4, 4) [m]; None if missed.
        offset: the cube's centre relative to the tool point, tool frame [m], (3,).
        miss: how far outside the tolerance it was [m] (0 when held).
        reason: why it missed ("" when held).
        turn: how much the jaws turned it to square it up [rad].
    """

    ok: bool
    T_tool_object: F64 | None
    offset: F64
    miss: float
    reason: str
    turn: float


def _axes(gripper: Gripper) -> tuple[int, int]:
    """Tool-frame indices of the jaw axis and of the pads' width axis."""
    return (2, 1) if gripper.jaw_axis == "z" else (1, 2)


def grasp(gripper: Gripper, T_tool: F64, opening: float, cube: Cube) -> Grasp:
    """Close jaws opened to ``opening`` [m], tool pose ``T_tool`` (4, 4), on ``cube``."""
    jaw, across = _axes(gripper)
    R = T_tool[:3, :3].T @ cube.T[:3, :3]  # cube axes in the tool frame
    c = T_tool[:3, :3].T @ (cube.center - T_tool[:3, 3])
    extent = cube.size / 2.0 * np.sum(np.abs(R), axis=1)  # half extents along tool axes
    face = int(np.argmax(np.abs(R[jaw])))
    turn = math.acos(min(1.0, abs(float(R[jaw, face]))))
    if turn > SQUARE_MAX:
        why = f"it is turned {math.degrees(turn):.1f} deg to the jaws (they square up 20)"
        return Grasp(False, None, c, 0.0, why, turn)
    checks = (
        (abs(c[jaw]) + extent[jaw] - opening / 2.0, "not between the jaws"),
        (
            _uncovered(c[0], extent[0], gripper.finger_length),
            "the pads are off it along the approach",
        ),
        (
            _uncovered(c[across], extent[across], gripper.finger_width),
            "the pads are off it sideways",
        ),
    )
    misses = [(m, why) for m, why in checks if m > 1e-9]
    if misses:
        miss, why = max(misses)
        return Grasp(False, None, c, miss, f"{why} (by {miss * 1000:.1f} mm)", turn)
    v = R[:, face] * math.copysign(1.0, float(R[jaw, face]))
    e = np.eye(3)[jaw]
    axis = np.cross(v, e)
    square = rot_axis(axis, turn) if float(np.linalg.norm(axis)) > 1e-12 else np.eye(3)
    held = c.copy()
    held[jaw] = 0.0
    return Grasp(True, pose(square @ R, held), c, 0.0, "", turn)


def _uncovered(c: float, half: float, pad: float) -> float:
    """How far [m] the pad (length ``pad`` centred on the tool point) must move along
    one axis so that ``MIN_COVER`` of it lies on an object centred at ``c`` of half
    extent ``half``; <= 0 when it already does."""
    overlap = min(pad / 2.0, c + half) - max(-pad / 2.0, c - half)
    return MIN_COVER * pad - overlap
