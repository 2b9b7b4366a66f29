"""A container: an open box on the table (002's central container)."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
from numpy.typing import NDArray

from .._inputs import mm, size_text
from .._primitives import RGB, Box, Primitive
from .._primitives import pose as placed
from ._fields import Entry, entries
from ._object import Placed, Solid, Support
from ._rect import Rect

F64 = NDArray[np.float64]
CONTAINER_COLOUR: RGB = (120, 150, 175)  # grey blue
KEYS = ("name", "position_mm", "size_mm", "wall_mm")


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

    def _parts(self) -> list[tuple[str, tuple[float, float, float], tuple[float, float, float]]]:
        """(name, size [m], centre from ``position`` [m]) of the floor and the four walls."""
        (L, W, H), w = self.size, self.wall
        return [
            ("floor", (L, W, w), (0.0, 0.0, w / 2)),
            ("wall_x0", (w, W, H), (-(L - w) / 2, 0.0, H / 2)),
            ("wall_x1", (w, W, H), ((L - w) / 2, 0.0, H / 2)),
            ("wall_y0", (L, w, H), (0.0, -(W - w) / 2, H / 2)),
            ("wall_y1", (L, w, H), (0.0, (W - w) / 2, H / 2)),
        ]

    def solids(self) -> tuple[Solid, ...]:
        """The floor and the four walls."""
        return tuple(Solid.upright(self.position + c, size) for _, size, c in self._parts())

    def supports(self, foot: Rect) -> tuple[Support, ...]:
        """Its floor for a footprint inside the walls, else its rim (never stable)."""
        (L, W, _), w = self.size, self.wall
        inner = Rect(self.position[:2], (L / 2 - w, W / 2 - w), 0)
        outer = Rect(self.position[:2], (L / 2, W / 2), 0.0)
        if inner.contains_points(foot.corners()):
            return (Support(self.floor_z, self.name, True),)
        if outer.overlaps(foot):
            return (Support(self.rim_z, f"{self.name} rim", False),)
        return ()

    def listed(self, scene: Placed) -> tuple[str, str]:
        """Its outside size, wall and floor centre."""
        return "containers", (
            f"{self.name}: {size_text(self.size)} outside, wall {self.wall * 1000:.1f} mm, "
            f"floor centre {mm(self.position)}"
        )

    def primitives(self, scene: Placed) -> list[Primitive]:
        """The floor and the four walls."""
        return [
            Box(
                f"/scene/{self.name}/{part}",
                np.array(size),
                placed(self.position + c),
                CONTAINER_COLOUR,
            )
            for part, size, c in self._parts()
        ]


def load_containers(path: Path, data: dict[str, Any], scene: Placed) -> tuple[Container, ...]:
    """``[[containers]]``: each with room inside its walls."""
    return tuple(_container(e) for e in entries(path, data, "containers", KEYS))


def _container(e: Entry) -> Container:
    size = e.sizes_mm("size_mm", 3)
    wall = e.positive_mm("wall_mm")
    if 2 * wall >= min(size[0], size[1]) or wall >= size[2]:
        raise e.fail("wall_mm", f"must leave room inside the box, got {wall * 1000:g}")
    return Container(e.name(), e.point_mm("position_mm"), (size[0], size[1], size[2]), wall)
