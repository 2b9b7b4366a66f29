"""What has been drawn on the scene's sheets of paper: the tool point's path while it
touches a sheet (within ``TOUCH`` of its plane, inside its edges).

A stroke starts when the tool point comes down onto a sheet and ends when it
lifts; each stroke is a polyline named ``/ink/<sheet>/<k>`` just above the
paper (shown in chunks ``/ink/<sheet>/<k>/<j>``, ``ChunkedLine``), so the view shows
the drawing as it grows.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from .._primitives import RGB, Polyline
from ..scene import Sheet
from ._chunked import ChunkedLine

F64 = NDArray[np.float64]
TOUCH = 0.002  # [m] the tool point this close to a sheet's plane is drawing on it
STEP = 0.0005  # [m] a stroke grows when the point moved this far
INK_COLOUR: RGB = (20, 20, 90)
LIFT = 0.0003  # [m] ink is drawn this far above the paper (visible over it)


class Ink:
    """Strokes on ``sheets`` (see the module doc)."""

    def __init__(self, sheets: tuple[Sheet, ...]) -> None:
        self.sheets = sheets
        self.strokes: list[tuple[Sheet, ChunkedLine]] = []  # points lifted LIFT off the paper
        self._on: Sheet | None = None

    def add(self, point: F64) -> Polyline | None:
        """The tool point is at ``point`` [m] (scene frame), shape (3,): the node of the
        stroke it extends (``/ink/<sheet>/<k>/<j>``, its newest chunk; None if it draws
        nothing new)."""
        sheet = self._touched(point)
        if sheet is None:
            self._on = None
            return None
        if sheet is not self._on:
            self._on = sheet
            name = f"/ink/{sheet.name}/{len(self.strokes) + 1}"
            self.strokes.append((sheet, ChunkedLine(name, INK_COLOUR, 3.0)))
        line = self.strokes[-1][1]
        on_paper = point + sheet.normal * LIFT
        if line.points and float(np.linalg.norm(on_paper - line.points[-1])) < STEP:
            return None
        return line.add(on_paper)[0]

    def _touched(self, point: F64) -> Sheet | None:
        for sheet in self.sheets:
            rel = point - sheet.origin
            if abs(float(rel @ sheet.normal)) > TOUCH:
                continue
            uv = np.array([[float(rel @ sheet.u), float(rel @ sheet.v)]])
            if bool(sheet.contains(uv)[0]):
                return sheet
        return None
