"""A named place on the table (000's A and B)."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
from numpy.typing import NDArray

from .._inputs import deg_text, mm
from .._primitives import RGB, Label, Primitive
from ._fields import Entry, entries
from ._object import Placed, Solid, Support
from ._rect import Rect

F64 = NDArray[np.float64]
PLACE_COLOUR: RGB = (60, 60, 60)
KEYS = ("name", "position_mm", "pitch_deg")


@dataclass(frozen=True, eq=False)
class Place:
    """A named point on the table (000's A and B).

    Attributes:
        position: the point [m], shape (3,): where an object's bottom goes.
        pitch: the gripper pitch to use there [rad], or None (the task chooses).
    """

    name: str
    position: F64
    pitch: float | None = None

    def solids(self) -> tuple[Solid, ...]:
        """None: a place is where things go."""
        return ()

    def supports(self, foot: Rect) -> tuple[Support, ...]:
        """None: a place is a point."""
        return ()

    def listed(self, scene: Placed) -> tuple[str, str]:
        """The point and the pitch to use there, if given."""
        pitch = "" if self.pitch is None else f", pitch {deg_text(self.pitch)}"
        return "places", f"{self.name}: {mm(self.position)}{pitch}"

    def primitives(self, scene: Placed) -> list[Primitive]:
        """Its name, at the point."""
        return [Label(f"/scene/{self.name}", self.position, self.name, PLACE_COLOUR)]


def load_places(path: Path, data: dict[str, Any], scene: Placed) -> tuple[Place, ...]:
    """``[[places]]``: a point and, if given, the pitch to use there (-90..90 deg)."""
    return tuple(_place(e) for e in entries(path, data, "places", KEYS))


def _place(e: Entry) -> Place:
    pitch = e.deg("pitch_deg") if e.has("pitch_deg") else None
    if pitch is not None and not -np.pi / 2 - 1e-9 <= pitch <= np.pi / 2 + 1e-9:
        raise e.fail("pitch_deg", "must be -90..90")
    return Place(e.name(), e.point_mm("position_mm"), pitch)
