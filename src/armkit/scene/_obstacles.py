"""The scene's solids (``SceneObject.solids``: a board's slab and the walls between
its sockets, a cube, a container's floor and walls, a hand) packed as arrays of
oriented boxes for the clearance check. Sheets, pens and instruments have none:
drawing and playing touch them on purpose."""

from __future__ import annotations

import weakref
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

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
    boxes = [
        (s.center, s.rotation, s.half, obj.name) for obj in scene.objects() for s in obj.solids()
    ]
    if not boxes:
        return _pack(np.zeros((0, 3)), np.zeros((0, 3, 3)), np.zeros((0, 3)), ())
    c, R, h, names = zip(*boxes, strict=True)
    return _pack(np.array(c), np.array(R), np.array(h), tuple(names))


def _pack(c: F64, R: F64, h: F64, owners: tuple[str, ...]) -> Obstacles:
    extent = np.einsum("mij,mj->mi", np.abs(R), h)
    return Obstacles(c, R, h, owners, c - extent, c + extent)
