"""Triangle meshes and frames the renderers build from primitives (``armkit._primitives``)."""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .._primitives import vec3

F64 = NDArray[np.float64]


def capsule_mesh(length: float, radius: float, segments: int = 16) -> tuple[F64, NDArray[np.int32]]:
    """A capsule's triangle mesh along +z from 0 to ``length`` [m]: vertices (V, 3) [m]
    and faces (F, 3) (indices, counter-clockwise seen from outside)."""
    rings = segments // 2
    # latitude angles: bottom cap (-pi/2..0) at z = 0, top cap (0..pi/2) at z = length
    lat = np.concatenate(
        [np.linspace(-math.pi / 2, 0, rings + 1), np.linspace(0, math.pi / 2, rings + 1)]
    )
    z_off = np.concatenate([np.zeros(rings + 1), np.full(rings + 1, length)])
    lon = np.linspace(0, 2 * math.pi, segments, endpoint=False)
    cl, sl = np.cos(lat)[:, None], np.sin(lat)[:, None]
    x = radius * cl * np.cos(lon)[None, :]
    y = radius * cl * np.sin(lon)[None, :]
    z = radius * sl + z_off[:, None] + 0 * lon[None, :]
    vertices = np.stack([x, y, z], axis=-1).reshape(-1, 3)
    faces = []
    for i in range(len(lat) - 1):
        for j in range(segments):
            a, b = i * segments + j, i * segments + (j + 1) % segments
            c, d = a + segments, b + segments
            faces += [(a, b, d), (a, d, c)]
    return vertices, np.array(faces, dtype=np.int32)


def segment_frame(p0: ArrayLike, p1: ArrayLike) -> tuple[F64, float]:
    """The frame at ``p0`` whose z axis points to ``p1`` (4, 4), and the length [m]."""
    a, b = vec3(p0, "p0"), vec3(p1, "p1")
    axis = b - a
    length = float(np.linalg.norm(axis))
    z = axis / length if length > 1e-12 else np.array([0.0, 0.0, 1.0])
    helper = np.array([1.0, 0.0, 0.0]) if abs(z[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
    x = np.cross(helper, z)
    x /= np.linalg.norm(x)
    T = np.eye(4)
    T[:3, 0], T[:3, 1], T[:3, 2], T[:3, 3] = x, np.cross(z, x), z, a
    return T, length
