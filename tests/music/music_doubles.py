"""Small stand-ins for the scene's Xylophone and Drum (same fields and methods as
the contract in plan/CONTRACT.md), until the scene package lands."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

F64 = NDArray[np.float64]


@dataclass(frozen=True)
class Xylophone:
    """Bars from ``first_bar`` to ``last_bar`` (top centres [m]), one per semitone."""

    name: str
    first_bar: tuple[float, float, float]
    last_bar: tuple[float, float, float]
    lowest_note: int
    bar_count: int

    @property
    def notes(self) -> range:
        return range(self.lowest_note, self.lowest_note + self.bar_count)

    def bar_top(self, note: int) -> F64:
        if note not in self.notes:
            raise ValueError(f"{self.name} has no bar for note {note}")
        share = (note - self.lowest_note) / max(self.bar_count - 1, 1)
        first, last = np.array(self.first_bar), np.array(self.last_bar)
        top: F64 = first + share * (last - first)
        return top


@dataclass(frozen=True)
class Drum:
    """A drum: centre ``position`` [m] on the table, head at ``top_z`` [m]."""

    name: str
    position: tuple[float, float, float]
    radius: float
    top_z: float
    note: int


def omx_layout() -> tuple[Xylophone, Drum]:
    """A two-octave xylophone (C5..B6) across the OpenManipulator-X's front and a
    snare on its left."""
    xylo = Xylophone("xylophone", (0.16, -0.12, 0.02), (0.16, 0.12, 0.02), 72, 24)
    return xylo, Drum("snare", (0.10, 0.15, 0.0), 0.05, 0.03, 38)
