"""The sensor's narrow beam: where it starts and points on the hand, and the
nearest thing along it in a scene (cubes, boards, containers as boxes; the table).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from ..scene import Scene

F64 = NDArray[np.float64]
FAR = 0.8  # [m] farther than this the sensor sees nothing


@dataclass(frozen=True)
class SensorMount:
    """Where the sensor sits on the hand.

    Attributes:
        back: from the tool point back along the fingers [m].
        up: above the fingers (towards the sky when the hand is level) [m].
        tilt: its beam turned up from the fingers' direction [rad] (the scan pitch's
            opposite makes it look level while scanning).
        spread: half-angle of its beam [rad] (narrow: 2 deg).
    """

    back: float = 0.0
    up: float = 0.0
    tilt: float = 0.0
    spread: float = math.radians(2.0)

    def beam(self, T_tool: F64) -> tuple[F64, F64]:
        """The beam's origin [m] (3,) and unit direction (3,) for the tool pose ``T_tool``."""
        a = T_tool[:3, 0]
        sky = np.array([0.0, 0.0, 1.0]) - a[2] * a
        n = float(np.linalg.norm(sky))
        u = sky / n if n > 1e-9 else -T_tool[:3, 2]
        origin = T_tool[:3, 3] - self.back * a + self.up * u
        direction = math.cos(self.tilt) * a + math.sin(self.tilt) * u
        return origin, direction / float(np.linalg.norm(direction))

    def rays(self, T_tool: F64) -> tuple[F64, F64]:
        """The origin (3,) and five directions (5, 3): the centre and four at ``spread``."""
        origin, d = self.beam(T_tool)
        side = np.cross(d, np.array([0.0, 0.0, 1.0]))
        side = side / max(float(np.linalg.norm(side)), 1e-9)
        up = np.cross(side, d)
        c, s = math.cos(self.spread), math.sin(self.spread)
        dirs = [d] + [c * d + s * e for e in (side, -side, up, -up)]
        return origin, np.array(dirs)


def boxes(scene: Scene) -> list[tuple[F64, F64]]:
    """Every object as a box: (pose (4, 4), half extents (3,)) [m]."""
    out: list[tuple[F64, F64]] = []
    for c in scene.cubes:
        out.append((c.T, np.full(3, c.size / 2.0)))
    for b in scene.boards:
        T = np.eye(4)
        cy, sy = math.cos(b.yaw), math.sin(b.yaw)
        T[:3, :3] = [[cy, -sy, 0.0], [sy, cy, 0.0], [0.0, 0.0, 1.0]]
        T[:3, 3] = b.origin - np.array([0.0, 0.0, b.thickness / 2.0])
        out.append((T, np.array([b.size[0] / 2.0, b.size[1] / 2.0, b.thickness / 2.0])))
    for h in scene.hands:
        T = np.eye(4)
        T[:3, 3] = h.position
        out.append((T, np.array(h.size) / 2.0))
    for k in scene.containers:
        T = np.eye(4)
        T[:3, 3] = k.position + np.array([0.0, 0.0, k.size[2] / 2.0])
        out.append((T, np.array(k.size) / 2.0))
    return out


def nearest(scene: Scene, origin: F64, directions: F64) -> float:
    """The nearest hit [m] of any of ``directions`` (K, 3) from ``origin`` (3,) on the
    scene's boxes or the table; FAR if none is nearer."""
    best = FAR
    for d in directions:
        if d[2] < -1e-9:
            best = min(best, (scene.table_z - float(origin[2])) / float(d[2]))
        for T, half in boxes(scene):
            best = min(best, _box_hit(T, half, origin, d))
    return max(best, 0.0)


def _box_hit(T: F64, half: F64, origin: F64, d: F64) -> float:
    """Slab test: distance along ``d`` to the box, or FAR."""
    R = T[:3, :3]
    o = R.T @ (origin - T[:3, 3])
    v = R.T @ d
    lo, hi = -math.inf, math.inf
    for k in range(3):
        if abs(v[k]) < 1e-12:
            if abs(o[k]) > half[k]:
                return FAR
            continue
        t1, t2 = (-half[k] - o[k]) / v[k], (half[k] - o[k]) / v[k]
        lo, hi = max(lo, min(t1, t2)), min(hi, max(t1, t2))
    if hi < max(lo, 0.0):
        return FAR
    return float(max(lo, 0.0))
