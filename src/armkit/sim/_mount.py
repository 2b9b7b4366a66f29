"""How a servo is mounted: its controller channel's units <-> the joint angle it turns
[rad] (or the gripper opening [m]), piecewise linear through measured points."""

from __future__ import annotations

import bisect
import functools
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

F64 = NDArray[np.float64]
GRIPPER = -1  # Mount.joint of the gripper's servo


@dataclass(frozen=True)
class Mount:
    """One controller channel turning one joint (``joint`` index) or the gripper (GRIPPER).

    ``units`` (device units, strictly monotonic) and ``values`` ([rad] or [m],
    increasing) are corresponding points; between and beyond them the relation is
    linear (the end segments extend).
    """

    channel: int
    joint: int
    units: tuple[float, ...]
    values: tuple[float, ...]

    def __post_init__(self) -> None:
        if len(self.units) < 2 or len(self.units) != len(self.values):
            raise ValueError(f"channel {self.channel}: a mount needs >= 2 matching points")

    def to_si(self, unit: float) -> float:
        """Device units -> [rad] or [m]."""
        xs, ys = self._rising()
        return _interp(unit, xs, ys)

    def to_si_many(self, units: F64) -> F64:
        """``to_si`` of every element of ``units``, shape (N,): the same arithmetic, so
        each equals the scalar's to the bit."""
        xs, ys = self._rising()
        x = np.asarray(units, dtype=np.float64)
        i = np.clip(np.searchsorted(xs, x, side="right"), 1, len(xs) - 1)
        x0, x1 = np.array(xs)[i - 1], np.array(xs)[i]
        y0, y1 = np.array(ys)[i - 1], np.array(ys)[i]
        flat = x1 == x0  # a degenerate table: its start
        out: F64 = np.where(flat, y0, y0 + (y1 - y0) * (x - x0) / np.where(flat, 1.0, x1 - x0))
        return out

    def from_si(self, value: float) -> float:
        """[rad] or [m] -> device units."""
        return _interp(value, self.values, self.units)

    @property
    def slope(self) -> float:
        """Device units per [rad] or [m] (of the first segment)."""
        return (self.units[1] - self.units[0]) / (self.values[1] - self.values[0])

    def _rising(self) -> tuple[Sequence[float], Sequence[float]]:
        return self._table

    @functools.cached_property
    def _table(self) -> tuple[Sequence[float], Sequence[float]]:
        """(units, values) with the units rising (computed once: every step asks)."""
        xs, ys = self.units, self.values
        return (xs[::-1], ys[::-1]) if xs[0] > xs[-1] else (xs, ys)


def _interp(x: float, xs: Sequence[float], ys: Sequence[float]) -> float:
    i = min(max(bisect.bisect_right(xs, x), 1), len(xs) - 1)
    x0, x1, y0, y1 = xs[i - 1], xs[i], ys[i - 1], ys[i]
    if x1 == x0:  # a degenerate table (a gripper 0..0 mm wide, that never opens): its start
        return y0
    return y0 + (y1 - y0) * (x - x0) / (x1 - x0)
