"""Primitives onto a viser scene: add a node the first time, move it afterwards.

Each primitive's ``name`` is its node. A node is re-created only when its
geometry changes (a capsule's length, a box's size); otherwise a frame only
sends the new pose and colour, which keeps a 30 Hz view cheap.
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from dataclasses import dataclass
from typing import Any

import numpy as np
import viser
from numpy.typing import NDArray

from ..._primitives import (
    Axes,
    Box,
    Capsule,
    Cylinder,
    Label,
    Polyline,
    Primitive,
    Sphere,
)
from .._meshes import capsule_mesh, segment_frame

F64 = NDArray[np.float64]
GEOMETRY_TOLERANCE = 1e-6  # [m] a change of shape below this keeps the node


@dataclass
class _Node:
    handle: Any
    shape: tuple[Any, ...]
    color: tuple[int, int, int] | None
    T: F64 | None = None  # the pose last sent (a frame sends only the poses that changed)


class Renderer:
    """Keeps a viser scene in step with lists of primitives (see the module doc)."""

    def __init__(self, scene: viser.SceneApi) -> None:
        self.scene = scene
        self._nodes: dict[str, _Node] = {}

    @property
    def names(self) -> tuple[str, ...]:
        """Names of the nodes drawn so far."""
        return tuple(self._nodes)

    def draw(self, primitives: Iterable[Primitive]) -> None:
        """Add or update every primitive."""
        for prim in primitives:
            self.draw_one(prim)

    def remove(self, name: str) -> None:
        """Remove the node called ``name`` (no error if absent)."""
        node = self._nodes.pop(name, None)
        if node is not None:
            node.handle.remove()

    def draw_one(self, prim: Primitive) -> None:
        """Add ``prim``, or move and recolour the node that shows it."""
        shape, T = _shape_and_pose(prim)
        node = self._nodes.get(prim.name)
        if node is None or not _same_shape(node.shape, shape):
            self.remove(prim.name)
            node = _Node(_add(self.scene, prim, shape), shape, _colour(prim))
            self._nodes[prim.name] = node
        elif node.color != _colour(prim):
            _recolour(node.handle, prim)
            node.color = _colour(prim)
        if isinstance(prim, Polyline | Label):
            _update_content(node.handle, prim)
        if T is not None and (node.T is None or not np.array_equal(node.T, T)):
            node.handle.position = T[:3, 3]
            node.handle.wxyz = quaternion_wxyz(T)
            node.T = T


def quaternion_wxyz(T: F64) -> tuple[float, float, float, float]:
    """The unit quaternion (w, x, y, z) of the rotation in ``T`` (4, 4) or (3, 3), as
    ``viser.transforms.SO3.from_matrix(R).wxyz`` up to sign, in floats: a view frame
    turns a few nodes, and numpy's per-call cost was most of it (Shepperd's method)."""
    (a, b, c), (d, e, f), (g, h, i) = T[0, :3].tolist(), T[1, :3].tolist(), T[2, :3].tolist()
    trace = a + e + i
    if trace > 0.0:
        s = 2.0 * math.sqrt(trace + 1.0)
        return (0.25 * s, (h - f) / s, (c - g) / s, (d - b) / s)
    if a > e and a > i:
        s = 2.0 * math.sqrt(1.0 + a - e - i)
        return ((h - f) / s, 0.25 * s, (b + d) / s, (c + g) / s)
    if e > i:
        s = 2.0 * math.sqrt(1.0 + e - a - i)
        return ((c - g) / s, (b + d) / s, 0.25 * s, (f + h) / s)
    s = 2.0 * math.sqrt(1.0 + i - a - e)
    return ((d - b) / s, (c + g) / s, (f + h) / s, 0.25 * s)


def _colour(prim: Primitive) -> tuple[int, int, int] | None:
    return None if isinstance(prim, Axes) else prim.color


def _recolour(handle: Any, prim: Primitive) -> None:
    if isinstance(prim, Polyline):
        handle.colors = np.array(prim.color, dtype=np.uint8)
    elif not isinstance(prim, Axes | Label):
        handle.color = prim.color


def _shape_and_pose(prim: Primitive) -> tuple[tuple[Any, ...], F64 | None]:
    """What makes the node's geometry, and where it sits (None: in world coordinates)."""
    if isinstance(prim, Capsule):
        T, length = segment_frame(prim.p0, prim.p1)
        return ("capsule", length, prim.radius), T
    if isinstance(prim, Box):
        return ("box", *prim.size.tolist(), prim.opacity), prim.T
    if isinstance(prim, Cylinder):
        return ("cylinder", prim.radius, prim.height, prim.opacity), prim.T
    if isinstance(prim, Sphere):
        T = np.eye(4)
        T[:3, 3] = prim.center
        return ("sphere", prim.radius), T
    if isinstance(prim, Axes):
        return ("axes", prim.length), prim.T
    if isinstance(prim, Label):
        T = np.eye(4)
        T[:3, 3] = prim.position
        return ("label",), T
    return ("polyline", prim.width), None


def _same_shape(a: tuple[Any, ...], b: tuple[Any, ...]) -> bool:
    if len(a) != len(b) or a[0] != b[0]:
        return False
    return all(abs(x - y) <= GEOMETRY_TOLERANCE for x, y in zip(a[1:], b[1:], strict=True))


def _add(scene: viser.SceneApi, prim: Primitive, shape: tuple[Any, ...]) -> Any:
    name = prim.name
    if isinstance(prim, Capsule):
        vertices, faces = capsule_mesh(shape[1], prim.radius)
        return scene.add_mesh_simple(name, vertices, faces, color=prim.color, flat_shading=False)
    if isinstance(prim, Box):
        opacity = None if prim.opacity >= 1.0 else prim.opacity
        return scene.add_box(name, color=prim.color, dimensions=prim.size, opacity=opacity)
    if isinstance(prim, Cylinder):
        opacity = None if prim.opacity >= 1.0 else prim.opacity
        return scene.add_cylinder(
            name, radius=prim.radius, height=prim.height, color=prim.color, opacity=opacity
        )
    if isinstance(prim, Sphere):
        return scene.add_icosphere(name, radius=prim.radius, color=prim.color, subdivisions=3)
    if isinstance(prim, Axes):
        return scene.add_frame(name, axes_length=prim.length, axes_radius=prim.length / 20)
    if isinstance(prim, Label):
        return scene.add_label(name, prim.text, anchor="bottom-left")
    return scene.add_line_segments(
        name, _segments(prim.points), prim.color, thickness=prim.width, thickness_units="screen"
    )


def _update_content(handle: Any, prim: Polyline | Label) -> None:
    if isinstance(prim, Label):
        if handle.text != prim.text:
            handle.text = prim.text
        return
    handle.points = _segments(prim.points)


def _segments(points: F64) -> F64:
    """(N, 3) points -> (N - 1, 2, 3) segments (one degenerate segment for N < 2)."""
    pts = np.asarray(points, dtype=np.float64).reshape(-1, 3)
    if len(pts) < 2:
        pts = np.repeat(pts if len(pts) else np.zeros((1, 3)), 2, axis=0)
    return np.stack([pts[:-1], pts[1:]], axis=1).astype(np.float32)
