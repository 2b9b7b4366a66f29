"""A scene's table and objects as MJCF: the table a plane, boards plates with their
sockets cut out (boxes around the holes), containers a floor and four walls, hands
boxes (all fixed), and each cube a free body with its mass (``CUBE_DENSITY``).
Pens, pen stands, sheets, instruments and places are not written."""

from __future__ import annotations

from xml.sax.saxutils import quoteattr

import numpy as np

from ..scene import Board, Container, Scene
from ._attributes import F64, mjcf_pose, numbers, pose, quaternion
from ._inertia import box_inertial

CUBE_DENSITY = 700.0  # [kg/m^3]: wooden toy blocks


def scene_geoms(scene: Scene, indent: int) -> list[str]:
    """The fixed geoms: the table, boards, containers, hands."""
    pad = " " * indent
    out = [f'{pad}<geom name="table" type="plane" pos="0 0 {scene.table_z!r}" size="0 0 0.05"/>']
    for b in scene.boards:
        out += [_box(f"{b.name}_{k}", T, half, pad) for k, (T, half) in enumerate(board_boxes(b))]
    for c in scene.containers:
        out += [_box(f"{c.name}_{k}", T, h, pad) for k, (T, h) in enumerate(container_boxes(c))]
    for h in scene.hands:
        out.append(_box(h.name, pose(np.eye(3), h.position), np.array(h.size) / 2.0, pad))
    return out


def scene_bodies(scene: Scene, indent: int) -> list[str]:
    """Each cube as a body on a free joint, its mass from ``CUBE_DENSITY``."""
    pad = " " * indent
    out = []
    for c in scene.cubes:
        m = box_inertial((c.size, c.size, c.size), CUBE_DENSITY)
        out += [
            f"{pad}<body name={quoteattr(c.name)} {mjcf_pose(c.T)}>",
            f"{pad}  <freejoint name={quoteattr(c.name)}/>",
            f'{pad}  <geom type="box" size="{numbers([c.size / 2.0] * 3)}" mass="{m.mass!r}"/>',
            f"{pad}</body>",
        ]
    return out


def scene_qpos(scene: Scene) -> list[float]:
    """The cubes' free joints where the scene has them: position [m] and quaternion each."""
    out: list[float] = []
    for c in scene.cubes:
        out += [*c.T[:3, 3], *quaternion(c.T[:3, :3])]
    return out


def board_boxes(b: Board) -> list[tuple[F64, F64]]:
    """A board as boxes (pose, half extents [m]): the plate under the sockets, and the top
    layer around them (strips between socket rows, pieces between sockets in a row)."""
    R = np.array(
        [[np.cos(b.yaw), -np.sin(b.yaw), 0.0], [np.sin(b.yaw), np.cos(b.yaw), 0.0], [0, 0, 1]]
    )
    L, W = b.size
    floor = b.thickness - b.socket_depth
    out = []
    if floor > 0.0:
        out.append(((-L / 2, L / 2), (-W / 2, W / 2), (-b.thickness, -b.socket_depth)))
    top = (-b.socket_depth, 0.0)
    s = b.socket_size / 2.0
    rows = [(r - (b.rows - 1) / 2.0) * b.pitch for r in range(b.rows)]
    cols = [(c - (b.cols - 1) / 2.0) * b.pitch for c in range(b.cols)]
    for x in _gaps(rows, s, L / 2):
        out.append((x, (-W / 2, W / 2), top))
    for r in rows:
        for y in _gaps(cols, s, W / 2):
            out.append(((r - s, r + s), y, top))
    boxes = []
    for (x0, x1), (y0, y1), (z0, z1) in out:
        centre = np.array([(x0 + x1) / 2, (y0 + y1) / 2, (z0 + z1) / 2])
        half = np.array([(x1 - x0) / 2, (y1 - y0) / 2, (z1 - z0) / 2])
        boxes.append((pose(R, b.origin + R @ centre), half))
    return boxes


def _gaps(centres: list[float], half: float, edge: float) -> list[tuple[float, float]]:
    """The intervals of -edge..edge outside the holes ``centre +- half`` (empty ones left out)."""
    cuts = [-edge, *(v for c in centres for v in (c - half, c + half)), edge]
    return [(cuts[k], cuts[k + 1]) for k in range(0, len(cuts), 2) if cuts[k + 1] - cuts[k] > 1e-9]


def container_boxes(c: Container) -> list[tuple[F64, F64]]:
    """A container as a floor and four walls (pose, half extents [m])."""
    x, y, z = c.size
    w = c.wall
    parts = [
        ((0.0, 0.0, w / 2), (x / 2, y / 2, w / 2)),
        ((x / 2 - w / 2, 0.0, z / 2), (w / 2, y / 2, z / 2)),
        ((-x / 2 + w / 2, 0.0, z / 2), (w / 2, y / 2, z / 2)),
        ((0.0, y / 2 - w / 2, z / 2), (x / 2, w / 2, z / 2)),
        ((0.0, -y / 2 + w / 2, z / 2), (x / 2, w / 2, z / 2)),
    ]
    return [(pose(np.eye(3), c.position + np.array(at)), np.array(h)) for at, h in parts]


def _box(name: str, T: F64, half: F64, pad: str) -> str:
    return f'{pad}<geom name={quoteattr(name)} type="box" {mjcf_pose(T)} size="{numbers(half)}"/>'
