"""A board: a plate with a grid of square sockets (001's acrylic board of cube holders)."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
from numpy.typing import NDArray

from .._errors import InputError
from .._inputs import deg_text, mm, size_text
from .._primitives import RGB, Box, Primitive
from .._primitives import pose as placed
from ._fields import Entry, entries
from ._object import Placed, Solid, Support
from ._rect import Rect
from ._rotations import rot_z

F64 = NDArray[np.float64]
BOARD_COLOUR: RGB = (150, 110, 70)  # brown
SOCKET_COLOUR: RGB = (70, 48, 30)
THIN = 0.001  # [m] thickness of the socket marks in a view
KEYS = (
    "name", "origin_mm", "yaw_deg", "rows", "cols", "pitch_mm", "socket_size_mm",
    "socket_depth_mm", "thickness_mm", "size_mm",
)  # fmt: skip


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

    def solids(self) -> tuple[Solid, ...]:
        """A slab from the table to the socket floors, then the walls between the
        sockets from the floors to the top face: strips across the board between the
        rows, and pieces between the sockets of each row."""
        R = rot_z(self.yaw)
        L, W = self.size
        top, depth = self.top_z, self.socket_depth
        floor = top - depth
        out: list[Solid] = []

        def add(x0: float, x1: float, y0: float, y1: float, z0: float, z1: float) -> None:
            if x1 - x0 > 1e-9 and y1 - y0 > 1e-9 and z1 - z0 > 1e-9:
                centre = self.origin + R @ np.array([(x0 + x1) / 2, (y0 + y1) / 2, 0.0])
                centre[2] = (z0 + z1) / 2
                out.append(Solid(centre, R, np.array([x1 - x0, y1 - y0, z1 - z0]) / 2))

        add(-L / 2, L / 2, -W / 2, W / 2, top - self.thickness, floor)
        if depth <= 0:
            return tuple(out)
        s = self.socket_size / 2
        rows = [(r - (self.rows - 1) / 2) * self.pitch for r in range(self.rows)]
        cols = [(c - (self.cols - 1) / 2) * self.pitch for c in range(self.cols)]
        xs = [-L / 2] + [v for x in rows for v in (x - s, x + s)] + [L / 2]
        ys = [-W / 2] + [v for y in cols for v in (y - s, y + s)] + [W / 2]
        for k in range(0, len(xs), 2):  # strips between rows, full width
            add(xs[k], xs[k + 1], -W / 2, W / 2, floor, top)
        for x in rows:  # pieces between the sockets of one row
            for k in range(0, len(ys), 2):
                add(x - s, x + s, ys[k], ys[k + 1], floor, top)
        return tuple(out)

    def supports(self, foot: Rect) -> tuple[Support, ...]:
        """The floor of the socket that holds ``foot`` whole, else the top (stable where
        ``foot``'s centre is over the plate)."""
        plate = Rect(self.origin[:2], (self.size[0] / 2, self.size[1] / 2), self.yaw)
        if not plate.overlaps(foot):
            return ()
        where = self.socket_at(np.array([*foot.center, self.top_z]))
        if where is not None:
            hole = Rect(self.socket(*where)[:2], (self.socket_size / 2,) * 2, self.yaw)
            if hole.contains_points(foot.corners()):
                on = f"{self.name}[{where[0]}, {where[1]}]"
                return (Support(self.socket(*where)[2], on, True),)
        return (Support(self.top_z, self.name, plate.contains_points(foot.center[None, :])),)

    def listed(self, scene: Placed) -> tuple[str, str]:
        """Its sockets, top centre, yaw and size."""
        return "boards", (
            f"{self.name}: {self.rows} x {self.cols} sockets {self.socket_size * 1000:.1f} mm "
            f"wide, {self.socket_depth * 1000:.1f} mm deep, {self.pitch * 1000:.1f} mm apart; "
            f"top centre {mm(self.origin)}, yaw {deg_text(self.yaw)}, "
            f"{size_text((*self.size, self.thickness))}"
        )

    def primitives(self, scene: Placed) -> list[Primitive]:
        """The plate (its top at ``top_z``) and a dark square in every socket."""
        T = placed(self.origin - np.array([0.0, 0.0, self.thickness / 2]), self.yaw)
        size = np.array([self.size[0], self.size[1], self.thickness])
        shapes: list[Primitive] = [Box(f"/scene/{self.name}", size, T, BOARD_COLOUR)]
        hole = np.array([self.socket_size, self.socket_size, THIN])
        for row in range(self.rows):
            for col in range(self.cols):
                floor = self.socket(row, col) + np.array([0.0, 0.0, self.socket_depth + THIN / 2])
                name = f"/scene/{self.name}_sockets/{row}_{col}"  # not under the board: its frame
                shapes.append(Box(name, hole, placed(floor, self.yaw), SOCKET_COLOUR))
        return shapes


def load_boards(path: Path, data: dict[str, Any], scene: Placed) -> tuple[Board, ...]:
    """``[[boards]]``: each a grid of sockets that fits its plate."""
    return tuple(_board(e) for e in entries(path, data, "boards", KEYS))


def _board(e: Entry) -> Board:
    rows, cols = e.integer("rows", lo=1, hi=50), e.integer("cols", lo=1, hi=50)
    pitch, hole = e.positive_mm("pitch_mm"), e.positive_mm("socket_size_mm")
    depth, thick = e.mm("socket_depth_mm"), e.positive_mm("thickness_mm")
    size = e.sizes_mm("size_mm", 2)
    if hole >= pitch and rows * cols > 1:
        raise e.fail(
            "socket_size_mm", f"must be < pitch_mm ({pitch * 1000:g}), got {hole * 1000:g}"
        )
    if not 0.0 <= depth <= thick:
        raise e.fail(
            "socket_depth_mm", f"must be 0..thickness_mm ({thick * 1000:g}), got {depth * 1000:g}"
        )
    for k, n in enumerate((rows, cols)):
        if size[k] < (n - 1) * pitch + hole:
            need = ((n - 1) * pitch + hole) * 1000
            raise e.fail(
                f"size_mm[{k}]", f"must hold the sockets: >= {need:g}, got {size[k] * 1000:g}"
            )
    origin = e.point_mm("origin_mm")
    yaw = e.deg("yaw_deg", 0.0)
    return Board(e.name(), origin, yaw, rows, cols, pitch, depth, thick, (size[0], size[1]), hole)
