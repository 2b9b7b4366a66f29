"""A line that grows at its end (the tool's trail, a stroke of ink), shown as nodes of
``CHUNK`` segments each, ``<name>/<j>``: adding a point re-sends only the newest node,
so what a view sends per frame stays small however long the line gets (the whole
600-point trail, re-sent every frame, was most of a frame's bytes while following a
drawing); dropping the oldest points removes whole nodes.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from .._errors import InputError
from .._primitives import RGB, Polyline

F64 = NDArray[np.float64]
CHUNK = 32  # segments per node


class ChunkedLine:
    """A polyline named ``name`` (nodes ``name/0``, ``name/1``, ...) in ``colour``,
    ``width`` pixels wide, keeping its last ``keep`` points (None: all)."""

    def __init__(self, name: str, colour: RGB, width: float, keep: int | None = None) -> None:
        if keep is not None and keep <= CHUNK:
            raise InputError(f"keep must be more than {CHUNK} points, got {keep}")
        self.name, self.colour, self.width, self.keep = name, colour, width, keep
        self.points: list[F64] = []  # the points kept [m], (3,) each
        self.first = 0  # how many points were dropped before points[0]
        self.nodes: list[int] = []  # the chunks shown, oldest first

    def add(self, point: F64) -> tuple[Polyline | None, list[str]]:
        """Append ``point`` [m], shape (3,): the node to draw (its newest chunk; None
        while there is no segment yet) and the names of the nodes to remove."""
        self.points.append(np.array(point, dtype=np.float64))
        removed = self._trim()
        n = self.first + len(self.points)
        if n < 2:
            return None, removed
        j = (n - 2) // CHUNK  # the newest segment's chunk
        if not self.nodes or self.nodes[-1] != j:
            self.nodes.append(j)
        lo = max(j * CHUNK - self.first, 0)
        return Polyline(
            f"{self.name}/{j}", np.array(self.points[lo:]), self.colour, self.width
        ), removed

    def clear(self) -> list[str]:
        """Forget every point: the names of the nodes to remove."""
        names = [f"{self.name}/{j}" for j in self.nodes]
        self.points, self.first, self.nodes = [], 0, []
        return names

    def _trim(self) -> list[str]:
        if self.keep is None or len(self.points) <= self.keep:
            return []
        drop = len(self.points) - self.keep
        del self.points[:drop]
        self.first += drop
        gone = [j for j in self.nodes if (j + 1) * CHUNK < self.first]  # its last point dropped
        self.nodes = self.nodes[len(gone) :]
        return [f"{self.name}/{j}" for j in gone]
