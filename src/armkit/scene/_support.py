"""What an object rests on: the highest surface under its footprint (table, board
top, socket floor, container floor, another cube), and where a released cube settles."""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING, Literal

import numpy as np
from numpy.typing import NDArray

from ._rotations import yaw_and_face

if TYPE_CHECKING:  # the kinds' modules read a scene file with ``support_under``
    from ._board import Board
    from ._cube import Cube
    from ._scene import Scene

F64 = NDArray[np.float64]
FLAT_TILT = math.radians(10.0)  # a cube released tilted less than this lands flat
DROP_HEIGHT = 0.005  # [m]: released higher than this above its support = dropped
Outcome = Literal["placed", "dropped", "tipped"]


@dataclass(frozen=True)
class Rect:
    """A rectangle in the horizontal plane: centre (2,) [m], half sizes [m], angle [rad]."""

    center: F64
    half: tuple[float, float]
    angle: float

    def _axes(self) -> F64:
        c, s = math.cos(self.angle), math.sin(self.angle)
        return np.array([[c, s], [-s, c]])

    def corners(self) -> F64:
        """Corners [m], shape (4, 2)."""
        hx, hy = self.half
        local = np.array([[hx, hy], [-hx, hy], [-hx, -hy], [hx, -hy]])
        out: F64 = self.center + local @ self._axes()
        return out

    def contains_points(self, pts: F64, slack: float = 1e-6) -> bool:
        """True if every point (N, 2) lies inside (within ``slack`` [m])."""
        local = (pts - self.center) @ self._axes().T
        return bool(np.all(np.abs(local) <= np.array(self.half) + slack))

    def overlaps(self, other: Rect, slack: float = 1e-6) -> bool:
        """True if the two rectangles overlap by more than ``slack`` [m] (separating axes)."""
        for axes in (self._axes(), other._axes()):
            for axis in axes:
                a, b = self.corners() @ axis, other.corners() @ axis
                if a.max() <= b.min() + slack or b.max() <= a.min() + slack:
                    return False
        return True


@dataclass(frozen=True)
class Support:
    """The surface under a footprint: its height [m], what it is, and whether the
    footprint's centre is over it (stable)."""

    z: float
    on: str
    stable: bool


@dataclass(frozen=True)
class Settled:
    """Where a released cube ends: the cube at rest, ``outcome`` (placed, dropped
    from more than 5 mm, tipped), what it rests on, and how far it fell [m]."""

    cube: Cube
    outcome: Outcome
    on: str
    fall: float


def footprint(cube: Cube) -> Rect:
    """The cube's footprint on the table, snapped flat."""
    return Rect(cube.position[:2].copy(), (cube.size / 2, cube.size / 2), cube.yaw)


def support_under(scene: Scene, foot: Rect, below: float) -> Support:
    """The highest surface under ``foot`` no higher than ``below`` + 1 mm [m]."""
    best = Support(scene.table_z, "table", True)
    for found in _candidates(scene, foot):
        if found.z <= below + 1e-3 and found.z > best.z:
            best = found
    return best


def _candidates(scene: Scene, foot: Rect) -> list[Support]:
    out: list[Support] = []
    centre = foot.center[None, :]
    for board in scene.boards:
        out.extend(_board_support(board, foot))
    for cube in scene.cubes:
        top = footprint(cube)
        if top.overlaps(foot):
            out.append(Support(cube.top_z, cube.name, top.contains_points(centre)))
    for box in scene.containers:
        inner = Rect(box.position[:2], (box.size[0] / 2 - box.wall, box.size[1] / 2 - box.wall), 0)
        outer = Rect(box.position[:2], (box.size[0] / 2, box.size[1] / 2), 0.0)
        if inner.contains_points(foot.corners()):
            out.append(Support(box.floor_z, box.name, True))
        elif outer.overlaps(foot):
            out.append(Support(box.rim_z, f"{box.name} rim", False))
    return out


def _board_support(board: Board, foot: Rect) -> list[Support]:
    plate = Rect(board.origin[:2], (board.size[0] / 2, board.size[1] / 2), board.yaw)
    if not plate.overlaps(foot):
        return []
    where = board.socket_at(np.array([*foot.center, board.top_z]))
    if where is not None:
        hole = Rect(board.socket(*where)[:2], (board.socket_size / 2,) * 2, board.yaw)
        if hole.contains_points(foot.corners()):
            return [Support(board.socket(*where)[2], f"{board.name}[{where[0]}, {where[1]}]", True)]
    return [Support(board.top_z, board.name, plate.contains_points(foot.center[None, :]))]


def settle(scene: Scene, cube: Cube, T: F64) -> Settled:
    """Where ``cube``, released with its centre at ``T`` (4, 4) in ``scene`` (which
    must not contain it), comes to rest: straight down onto the highest surface
    under it, turned to the nearest face down."""
    _, _, tilt = yaw_and_face(T[:3, :3])
    flat = cube.moved(T)
    bottom = float(T[2, 3]) - cube.size / 2
    below = support_under(scene, footprint(flat), bottom)
    rest = replace(flat, position=np.array([*flat.position[:2], below.z]))
    fall = bottom - below.z
    outcome: Outcome = "placed"
    if tilt > FLAT_TILT or not below.stable:
        outcome = "tipped"
    elif fall > DROP_HEIGHT:
        outcome = "dropped"
    return Settled(rest, outcome, below.on, fall)
