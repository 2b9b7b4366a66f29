"""The scene's solid objects as oriented boxes for the clearance check: boards
(a slab under the sockets and the walls between them), cubes, containers (floor
and four walls), hands. Sheets, pens and instruments are not obstacles: drawing and
playing touch them on purpose."""

from __future__ import annotations

import weakref
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from ._objects import Board, Container
from ._rotations import rot_z
from ._scene import Scene

F64 = NDArray[np.float64]


@dataclass(frozen=True)
class Obstacles:
    """M boxes: centres (M, 3) [m], rotations (M, 3, 3) (columns = box axes), half
    sizes (M, 3) [m], the owning object's name for each, and each box's axis-aligned
    bounds lo, hi (M, 3) [m]. Scene frame."""

    centers: F64
    rotations: F64
    halves: F64
    owners: tuple[str, ...]
    lo: F64
    hi: F64

    def without(self, names: frozenset[str]) -> Obstacles:
        """The boxes whose owner is not in ``names``."""
        keep = np.array([o not in names for o in self.owners], dtype=bool)
        return _pack(
            self.centers[keep],
            self.rotations[keep],
            self.halves[keep],
            tuple(o for o, k in zip(self.owners, keep, strict=True) if k),
        )


_CACHE: weakref.WeakKeyDictionary[Scene, Obstacles] = weakref.WeakKeyDictionary()


def obstacles(scene: Scene) -> Obstacles:
    """The scene's boxes (computed once per Scene object)."""
    found = _CACHE.get(scene)
    if found is None:
        found = _CACHE[scene] = _build(scene)
    return found


def _build(scene: Scene) -> Obstacles:
    boxes: list[tuple[F64, F64, F64, str]] = []
    for board in scene.boards:
        boxes.extend(_board_boxes(board))
    for cube in scene.cubes:
        T = cube.T
        boxes.append((T[:3, 3], T[:3, :3], np.full(3, cube.size / 2), cube.name))
    for box in scene.containers:
        boxes.extend(_container_boxes(box))
    for hand in scene.hands:
        boxes.append((hand.position, np.eye(3), np.array(hand.size) / 2, hand.name))
    if not boxes:
        return _pack(np.zeros((0, 3)), np.zeros((0, 3, 3)), np.zeros((0, 3)), ())
    c, R, h, names = zip(*boxes, strict=True)
    return _pack(np.array(c), np.array(R), np.array(h), tuple(names))


def _pack(c: F64, R: F64, h: F64, owners: tuple[str, ...]) -> Obstacles:
    extent = np.einsum("mij,mj->mi", np.abs(R), h)
    return Obstacles(c, R, h, owners, c - extent, c + extent)


def _board_boxes(board: Board) -> list[tuple[F64, F64, F64, str]]:
    """A slab from the table to the socket floors, then the walls between the
    sockets from the floors to the top face: strips across the board between the
    rows, and pieces between the sockets of each row."""
    R = rot_z(board.yaw)
    L, W = board.size
    top, depth = board.top_z, board.socket_depth
    floor = top - depth
    out = []

    def add(x0: float, x1: float, y0: float, y1: float, z0: float, z1: float) -> None:
        if x1 - x0 > 1e-9 and y1 - y0 > 1e-9 and z1 - z0 > 1e-9:
            local = np.array([(x0 + x1) / 2, (y0 + y1) / 2, 0.0])
            centre = board.origin + R @ local
            centre[2] = (z0 + z1) / 2
            out.append(
                (centre, R, np.array([(x1 - x0) / 2, (y1 - y0) / 2, (z1 - z0) / 2]), board.name)
            )

    add(-L / 2, L / 2, -W / 2, W / 2, top - board.thickness, floor)
    if depth <= 0:
        return out
    s = board.socket_size / 2
    rows = [(r - (board.rows - 1) / 2) * board.pitch for r in range(board.rows)]
    cols = [(c - (board.cols - 1) / 2) * board.pitch for c in range(board.cols)]
    xs = [-L / 2] + [v for x in rows for v in (x - s, x + s)] + [L / 2]
    ys = [-W / 2] + [v for y in cols for v in (y - s, y + s)] + [W / 2]
    for k in range(0, len(xs), 2):  # strips between rows, full width
        add(xs[k], xs[k + 1], -W / 2, W / 2, floor, top)
    for x in rows:  # pieces between the sockets of one row
        for k in range(0, len(ys), 2):
            add(x - s, x + s, ys[k], ys[k + 1], floor, top)
    return out


def _container_boxes(box: Container) -> list[tuple[F64, F64, F64, str]]:
    (L, W, H), w = box.size, box.wall
    c = box.position
    parts = [
        (np.array([0, 0, w / 2]), np.array([L / 2, W / 2, w / 2])),
        (np.array([L / 2 - w / 2, 0, H / 2]), np.array([w / 2, W / 2, H / 2])),
        (np.array([-L / 2 + w / 2, 0, H / 2]), np.array([w / 2, W / 2, H / 2])),
        (np.array([0, W / 2 - w / 2, H / 2]), np.array([L / 2, w / 2, H / 2])),
        (np.array([0, -W / 2 + w / 2, H / 2]), np.array([L / 2, w / 2, H / 2])),
    ]
    return [(c + offset, np.eye(3), half, box.name) for offset, half in parts]
