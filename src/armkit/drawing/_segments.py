"""The pieces of a vector drawing: lines, Bézier curves, elliptic arcs, and
paths of them (one pen-down run each)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

F64 = NDArray[np.float64]


@dataclass(frozen=True)
class Line:
    """Straight segment from ``start`` to ``end``, shape (2,) each."""

    start: F64
    end: F64


@dataclass(frozen=True)
class Quad:
    """Quadratic Bézier curve through control points ``p``, shape (3, 2)."""

    p: F64


@dataclass(frozen=True)
class Cubic:
    """Cubic Bézier curve through control points ``p``, shape (4, 2)."""

    p: F64


@dataclass(frozen=True)
class EllipticArc:
    """Arc of an ellipse: ``center`` (2,), semi-axes ``rx``, ``ry`` along the axes
    turned by ``rotation`` [rad]; the point at parameter t is
    center + R(rotation) (rx cos t, ry sin t), t from ``t0`` through ``sweep`` [rad]
    (negative: clockwise). A circle has rx == ry and t is its angle."""

    center: F64
    rx: float
    ry: float
    rotation: float
    t0: float
    sweep: float


Segment = Line | Quad | Cubic | EllipticArc


@dataclass(frozen=True)
class FigurePath:
    """One pen-down run: segments joined end to end (the pen stays down between them)."""

    segments: tuple[Segment, ...]
