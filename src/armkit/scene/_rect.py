"""Rectangles in the table's plane: footprints and the surfaces under them."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

F64 = NDArray[np.float64]


@dataclass(frozen=True)
class Rect:
    """A rectangle in the horizontal plane: centre (2,) [m], half sizes [m], angle [rad]."""

    center: F64
    half: tuple[float, float]
    angle: float

    def _axes(self) -> F64:
        c, s = math.cos(self.angle), math.sin(self.angle)
        return np.array([[c, s], [-s, c]])

    def corners(self) -> F64:
        """Corners [m], shape (4, 2)."""
        hx, hy = self.half
        local = np.array([[hx, hy], [-hx, hy], [-hx, -hy], [hx, -hy]])
        out: F64 = self.center + local @ self._axes()
        return out

    def contains_points(self, pts: F64, slack: float = 1e-6) -> bool:
        """True if every point (N, 2) lies inside (within ``slack`` [m])."""
        local = (pts - self.center) @ self._axes().T
        return bool(np.all(np.abs(local) <= np.array(self.half) + slack))

    def overlaps(self, other: Rect, slack: float = 1e-6) -> bool:
        """True if the two rectangles overlap by more than ``slack`` [m] (separating axes)."""
        for axes in (self._axes(), other._axes()):
            for axis in axes:
                a, b = self.corners() @ axis, other.corners() @ axis
                if a.max() <= b.min() + slack or b.max() <= a.min() + slack:
                    return False
        return True
