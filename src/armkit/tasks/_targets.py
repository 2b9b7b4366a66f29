"""Where a task puts a cube: a named place, a board socket, on top of a cube,
into a container, or a point in millimetres."""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from .._errors import InputError
from ..scene import Scene

F64 = NDArray[np.float64]
MAX_INDEX_DIGITS = 6  # a board's row or column as written (no board has a million rows)
_SOCKET = re.compile(r"^\s*([\w-]+)\s*\[\s*(\d+)\s*,\s*(\d+)\s*\]\s*$")


@dataclass(frozen=True)
class Destination:
    """Where the lowest face's centre of a cube goes (scene frame) [m], (3,), how
    to say it (``"in board[0, 1]"``), and the pitch the scene asks for [rad] or None."""

    bottom: F64
    label: str
    pitch: float | None = None


def resolve(scene: Scene, to: str | Sequence[float]) -> Destination:
    """A target from a name in the scene (a place, ``board[row, col]``, a cube to
    stack on, a container) or from ``(x, y, z)`` [mm] in the scene frame.

    Raises:
        ValueError: unknown name (the message lists what there is) or a bad point.
    """
    if not isinstance(to, str):
        p = np.asarray(to, dtype=np.float64)
        if p.shape != (3,) or not np.all(np.isfinite(p)) or np.any(np.abs(p) > 10_000):
            raise InputError(f"a target point is 3 finite coordinates in mm, got {to!r}")
        return Destination(p / 1000.0, "at ({:.1f}, {:.1f}, {:.1f}) mm".format(*p))
    socket = _SOCKET.match(to)
    if socket:
        board = scene.board(socket.group(1))
        if any(len(socket.group(k)) > MAX_INDEX_DIGITS for k in (2, 3)):  # int() refuses thousands
            raise InputError(
                f"board {board.name!r} has sockets rows 0..{board.rows - 1}, "
                f"cols 0..{board.cols - 1}; got a row or column of more than {MAX_INDEX_DIGITS} digits"
            )
        row, col = int(socket.group(2)), int(socket.group(3))
        return Destination(board.socket(row, col), f"in {board.name}[{row}, {col}]")
    for place in scene.places:
        if place.name == to:
            return Destination(place.position, f"at {to}", place.pitch)
    for cube in scene.cubes:
        if cube.name == to:
            return Destination(cube.position + np.array([0.0, 0.0, cube.size]), f"on {to}")
    for box in scene.containers:
        if box.name == to:
            return Destination(np.array([*box.position[:2], box.floor_z]), f"in {to}")
    for board in scene.boards:
        if board.name == to:
            raise InputError(
                f"{to} is a board: say which socket, {to}[ROW, COL] (rows 0..{board.rows - 1}, "
                f"columns 0..{board.cols - 1})"
            )
    raise InputError(
        f"scene {scene.name!r} has no place, cube or container {to!r} "
        f"(and it is not board[row, col]); it has: {', '.join(scene.names()) or 'nothing'}"
    )


def taken_by(scene: Scene, target: Destination, moving: str | None) -> str | None:
    """The cube (other than ``moving``) that stands where ``target`` puts a cube's bottom
    (its own bottom within 1 mm of that height, overlapping it), or None if it is free."""
    size = next((c.size for c in scene.cubes if c.name == moving), 0.0)
    for cube in scene.cubes:
        if cube.name == moving:
            continue
        dx, dy, dz = cube.position - target.bottom
        if abs(dz) < 1e-3 and np.hypot(dx, dy) < (cube.size + size) / 2:
            return cube.name
    return None
