"""The shapes armkit drew before SVG and G-code (line, arc, circle, rectangle,
polyline), as exact curves in a sheet's own coordinates u, v [m].

Each function returns one ``FigurePath``; ``figure(*paths)`` makes a drawing of
them for ``plan_drawing`` (with ``Fit.as_is()`` they stay where they are). The
sheet carries them onto its plane, so a circle is a circle on a tilted board too.
Seed 001's task is ``figure(line(..), line(..), line(..), circle(..))``.
"""

from __future__ import annotations

import itertools
import math

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .._errors import InputError
from .._inputs import array
from ._errors import DrawingError
from ._figure import Figure
from ._segments import EllipticArc, FigurePath, Line

F64 = NDArray[np.float64]


def line(start: ArrayLike, end: ArrayLike) -> FigurePath:
    """Straight line from ``start`` to ``end`` (u, v) [m]."""
    return FigurePath((Line(uv_point(start, "start"), uv_point(end, "end")),))


def polyline(vertices: ArrayLike, closed: bool = False) -> FigurePath:
    """Straight pieces through ``vertices`` [m], shape (M, 2), M >= 2; ``closed``
    adds the piece back to the first vertex."""
    v = np.asarray(vertices, dtype=np.float64)
    if v.ndim != 2 or v.shape[1] != 2 or len(v) < 2 or not np.all(np.isfinite(v)):
        raise DrawingError(f"vertices must be finite, shape (M, 2) with M >= 2, got {v.shape}")
    if closed:
        v = np.vstack([v, v[:1]])
    return FigurePath(tuple(Line(a, b) for a, b in itertools.pairwise(v)))


def arc(center: ArrayLike, radius: float, start_angle: float, sweep: float) -> FigurePath:
    """Arc of a circle: ``center`` (u, v) [m], ``radius`` [m], from ``start_angle``
    [rad] (0 along +u, counter-clockwise towards +v) through ``sweep`` [rad]
    (negative: clockwise)."""
    c = uv_point(center, "center")
    if not (math.isfinite(radius) and radius > 0):
        raise DrawingError(f"radius must be > 0 m, got {radius}")
    if not (math.isfinite(start_angle) and math.isfinite(sweep) and sweep != 0):
        raise DrawingError(f"start angle and sweep must be finite, the sweep non-zero, got {sweep}")
    return FigurePath((EllipticArc(c, radius, radius, 0.0, start_angle, sweep),))


def circle(center: ArrayLike, radius: float, start_angle: float = 0.0) -> FigurePath:
    """Full circle, counter-clockwise, starting and ending at ``start_angle`` [rad]."""
    return arc(center, radius, start_angle, 2.0 * math.pi)


def rectangle(center: ArrayLike, width: float, height: float) -> FigurePath:
    """Closed rectangle: ``width`` along u, ``height`` along v [m], counter-clockwise
    from the corner at (-u, -v)."""
    c = uv_point(center, "center")
    if not (width > 0 and height > 0 and math.isfinite(width) and math.isfinite(height)):
        raise DrawingError(f"width and height must be > 0 m, got {width}, {height}")
    w, h = width / 2.0, height / 2.0
    return polyline(c + np.array([[-w, -h], [w, -h], [w, h], [-w, h]]), closed=True)


def figure(*paths: FigurePath, source: str = "shapes") -> Figure:
    """A drawing of these paths, in metres (u, v)."""
    if not paths:
        raise DrawingError("figure() needs at least one shape")
    return Figure(tuple(paths), np.eye(3), source=source)


def uv_point(p: ArrayLike, name: str) -> F64:
    """``p`` as 2 finite sheet coordinates (u, v) [m] (DrawingError naming ``name``)."""
    try:
        return array(p, name, ((2,),), "m")
    except InputError as e:
        raise DrawingError(f"{e}; give 2 sheet coordinates (u, v)") from None
