"""A vector drawing before flattening: paths of lines, Bézier curves and arcs.

A ``Figure`` is what every reader (SVG, G-code, shapes) produces. Its segments
are in the source's own units; ``to_metres`` maps them to metres with y up
(SVG's y points down, so its map flips y). ``flatten`` turns it into polylines.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from numpy.typing import NDArray

from ._flatten import flatten_paths
from ._segments import Cubic, FigurePath, Line, Quad

F64 = NDArray[np.float64]


@dataclass(frozen=True)
class Figure:
    """A vector drawing: ``paths`` in source units, ``to_metres`` (3, 3) the affine
    map from source units to metres with y up (a uniform scale, maybe a flip),
    ``source`` the file's name or a label, ``notes`` what the reader left out,
    ``dwell`` the total pause the source asks for [s] (G-code G4)."""

    paths: tuple[FigurePath, ...]
    to_metres: F64
    source: str = ""
    notes: tuple[str, ...] = ()
    dwell: float = 0.0
    scale: float = field(init=False)

    def __post_init__(self) -> None:
        # metres per source unit: the map's uniform scale
        object.__setattr__(
            self, "scale", float(np.sqrt(abs(np.linalg.det(self.to_metres[:2, :2]))))
        )

    def extent(self) -> float:
        """The diagonal of the box around every end and control point [m] (0 if empty)."""
        pts = [np.asarray(p, dtype=np.float64).reshape(-1, 2) for p in _control_points(self.paths)]
        if not pts:
            return 0.0
        allp = np.vstack(pts)
        return float(np.linalg.norm(np.ptp(allp, axis=0))) * self.scale

    def flatten(self, tolerance: float) -> tuple[F64, ...]:
        """Polylines in metres (y up), shape (N, 2) each, within ``tolerance`` [m]
        of the true curves; one per path with at least one segment."""
        strokes = flatten_paths(self.paths, tolerance / self.scale)
        A, b = self.to_metres[:2, :2], self.to_metres[:2, 2]
        return tuple(s @ A.T + b for s in strokes)


def _control_points(paths: tuple[FigurePath, ...]) -> list[F64]:
    out: list[F64] = []
    for path in paths:
        for seg in path.segments:
            if isinstance(seg, Line):
                out.append(np.vstack([seg.start, seg.end]))
            elif isinstance(seg, Quad | Cubic):
                out.append(seg.p)
            else:
                r = max(abs(seg.rx), abs(seg.ry))
                out.append(np.vstack([seg.center - r, seg.center + r]))
    return out
