"""A hand held out to shake (003's reach)."""

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
HAND_COLOUR: RGB = (225, 180, 150)  # skin
KEYS = ("name", "position_mm", "size_mm")


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

    def solids(self) -> tuple[Solid, ...]:
        """The hand's box: the arm reaches to it, never into it."""
        return (Solid.upright(self.position, self.size),)

    def supports(self, foot: Rect) -> tuple[Support, ...]:
        """None: a hand is held out to shake."""
        return ()

    def listed(self, scene: Placed) -> tuple[str, str]:
        """Its size and centre."""
        return "hands", f"{self.name}: {size_text(self.size)}, centre {mm(self.position)}"

    def primitives(self, scene: Placed) -> list[Primitive]:
        """The hand's box, skin coloured."""
        return [Box(f"/scene/{self.name}", np.array(self.size), placed(self.position), HAND_COLOUR)]


def load_hands(path: Path, data: dict[str, Any], scene: Placed) -> tuple[Hand, ...]:
    """``[[hands]]``: a centre and a size."""
    return tuple(_hand(e) for e in entries(path, data, "hands", KEYS))


def _hand(e: Entry) -> Hand:
    size = e.sizes_mm("size_mm", 3)
    return Hand(e.name(), e.point_mm("position_mm"), (size[0], size[1], size[2]))
