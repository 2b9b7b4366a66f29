"""Things on the table: boards with sockets, cubes, containers, named places,
pens and their stands. Frozen dataclasses in SI units (metres, radians), in the
scene's (table's) frame: x forward, y left, z up."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from .._errors import InputError
from ._rotations import face_up, pose, rot_z, yaw_and_face

F64 = NDArray[np.float64]


@dataclass(frozen=True, eq=False)
class Board:
    """A plate with a grid of square sockets (001's acrylic board of cube holders).

    Attributes:
        name: unique in the scene.
        origin: centre of the board's top face [m], shape (3,).
        yaw: turn of the board about z [rad]; rows run along the board's x axis,
            columns along its y axis.
        rows, cols: socket grid.  pitch: distance between socket centres [m].
        socket_size: side of each square socket [m] (< pitch).
        socket_depth: depth of the sockets below the top face [m] (<= thickness).
        thickness: from the table to the top face [m].
        size: (length along the board's x, width along its y) [m].
    """

    name: str
    origin: F64
    yaw: float
    rows: int
    cols: int
    pitch: float
    socket_depth: float
    thickness: float
    size: tuple[float, float]
    socket_size: float

    @property
    def top_z(self) -> float:
        """Height of the top face [m]."""
        return float(self.origin[2])

    def socket(self, row: int, col: int) -> F64:
        """Centre of the floor of socket (``row``, ``col``) [m], shape (3,), scene frame.

        Raises:
            ValueError: the row or column is outside the grid.
        """
        if not (0 <= row < self.rows and 0 <= col < self.cols):
            raise InputError(
                f"board {self.name!r} has sockets rows 0..{self.rows - 1}, "
                f"cols 0..{self.cols - 1}; got ({row}, {col})"
            )
        local = np.array(
            [
                (row - (self.rows - 1) / 2.0) * self.pitch,
                (col - (self.cols - 1) / 2.0) * self.pitch,
                -self.socket_depth,
            ]
        )
        centre: F64 = self.origin + rot_z(self.yaw) @ local
        return centre

    def socket_at(self, point: F64) -> tuple[int, int] | None:
        """The socket whose hole contains ``point``'s (x, y) [m], or None."""
        local = rot_z(self.yaw).T @ (np.asarray(point, dtype=np.float64) - self.origin)
        row = round(local[0] / self.pitch + (self.rows - 1) / 2.0)
        col = round(local[1] / self.pitch + (self.cols - 1) / 2.0)
        if not (0 <= row < self.rows and 0 <= col < self.cols):
            return None
        d = rot_z(self.yaw).T @ (np.asarray(point) - self.socket(row, col))
        half = self.socket_size / 2.0
        return (row, col) if abs(d[0]) <= half and abs(d[1]) <= half else None


@dataclass(frozen=True, eq=False)
class Cube:
    """A cube (001's 25 mm cubes).

    Attributes:
        size: edge [m].
        position: centre of the face it stands on [m], shape (3,).
        yaw: turn about z [rad].
        up_face: which of its faces points up: ``"+z"`` (as made), ``"-z"``, ``"+x"``,
            ``"-x"``, ``"+y"``, ``"-y"`` (faces named in the cube's own frame).
    """

    name: str
    size: float
    position: F64
    yaw: float = 0.0
    up_face: str = "+z"

    @property
    def T(self) -> F64:
        """Pose of the cube's centre and axes in the scene frame, shape (4, 4)."""
        R = rot_z(self.yaw) @ face_up(self.up_face)
        return pose(R, self.position + np.array([0.0, 0.0, self.size / 2.0]))

    @property
    def center(self) -> F64:
        """Centre of the cube [m], shape (3,)."""
        centre: F64 = self.position + np.array([0.0, 0.0, self.size / 2.0])
        return centre

    @property
    def top_z(self) -> float:
        """Height of its top face [m]."""
        return float(self.position[2]) + self.size

    def moved(self, T: F64) -> Cube:
        """The same cube with its centre at ``T`` (4, 4), snapped to the nearest face up."""
        yaw, face, _ = yaw_and_face(T[:3, :3])
        bottom = T[:3, 3] - np.array([0.0, 0.0, self.size / 2.0])
        return Cube(self.name, self.size, bottom, yaw, face)


@dataclass(frozen=True, eq=False)
class Container:
    """An open box (002's central container), its sides along the scene axes.

    Attributes:
        position: centre of the floor's underside, on the table [m], shape (3,).
        size: outer (length x, width y, height z) [m].
        wall: wall and floor thickness [m].
    """

    name: str
    position: F64
    size: tuple[float, float, float]
    wall: float

    @property
    def floor_z(self) -> float:
        """Height of the inside of the floor [m]."""
        return float(self.position[2]) + self.wall

    @property
    def rim_z(self) -> float:
        """Height of the top of the walls [m]."""
        return float(self.position[2]) + self.size[2]


@dataclass(frozen=True, eq=False)
class Hand:
    """A hand held out to shake (003's reach): a box, its sides along the scene axes.

    Attributes:
        position: centre of the hand [m], shape (3,).
        size: (x, y, z) extent [m]: thin along x for a palm facing the arm.
    """

    name: str
    position: F64
    size: tuple[float, float, float]


@dataclass(frozen=True, eq=False)
class Place:
    """A named point on the table (000's A and B).

    Attributes:
        position: the point [m], shape (3,): where an object's bottom goes.
        pitch: the gripper pitch to use there [rad], or None (the task chooses).
    """

    name: str
    position: F64
    pitch: float | None = None


@dataclass(frozen=True, eq=False)
class Pen:
    """A pen the gripper can hold (001's drawing task).

    Attributes:
        length: the pen's length [m].
        holder_length: how much of it stands inside its stand [m].
        tip_offset: from the gripper's tool point to the pen's tip while held [m]:
            the tool gets this much longer.
        diameter: where the jaws close on it (its holder) [m]: the grip width.
        tool_lengths: (arm name, tool length [m]) pairs: the tool length while held
            on that arm, from its last joint frame to the tip (001's pen holder on
            the OpenManipulator-X: 0.116 m); other arms: their own + ``tip_offset``.
    """

    name: str
    length: float
    holder_length: float
    tip_offset: float
    diameter: float = 0.024
    tool_lengths: tuple[tuple[str, float], ...] = ()

    def tool_length(self, arm: str, own: float) -> float:
        """The tool length [m] of arm ``arm`` holding this pen (``own``: its own [m])."""
        return dict(self.tool_lengths).get(arm, own + self.tip_offset)


@dataclass(frozen=True, eq=False)
class PenStand:
    """Where a pen stands when not held.

    Attributes:
        position: centre of the stand's opening [m], shape (3,).
        pen: the name of the pen in it.
        pitch: the pen's axis from the opening to its tip, above the horizontal,
            in the vertical plane through the arm's base [rad]: -pi/2 upright, tip
            down (a pot); 0 lying, tip pointing away from the arm (a cradle).
    """

    name: str
    position: F64
    pen: str
    pitch: float = -math.pi / 2
