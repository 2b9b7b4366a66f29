"""Sheets of paper: a rectangle on any plane (drawing on the table, on a wall, tilted)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .._errors import InputError

F64 = NDArray[np.float64]

# ISO 216 sizes, portrait (width, height) [m].
PAPER_SIZES: dict[str, tuple[float, float]] = {
    "A3": (0.297, 0.420),
    "A4": (0.210, 0.297),
    "A5": (0.148, 0.210),
    "A6": (0.105, 0.148),
}


@dataclass(frozen=True, eq=False)
class Sheet:
    """A rectangle on a plane.

    Attributes:
        origin: one corner [m], shape (3,): (u, v) = (0, 0).
        u, v: unit vectors along the sheet's width and height, orthogonal, shape (3,).
        width, height: along u and v [m].
    """

    name: str
    origin: F64
    u: F64
    v: F64
    width: float
    height: float

    @property
    def normal(self) -> F64:
        """Unit normal u x v, shape (3,) (up for a sheet lying on the table with v left of u)."""
        n: F64 = np.cross(self.u, self.v)
        return n

    @property
    def center(self) -> F64:
        """Centre of the sheet [m], shape (3,)."""
        c: F64 = self.origin + self.u * self.width / 2.0 + self.v * self.height / 2.0
        return c

    def to_world(self, uv: ArrayLike) -> F64:
        """Points on the sheet (u, v) [m], shape (N, 2), to the scene frame [m], shape (N, 3).

        Raises:
            ValueError: ``uv`` is not finite or not of shape (N, 2).
        """
        a = np.asarray(uv, dtype=np.float64)
        if a.ndim != 2 or a.shape[1] != 2 or not np.all(np.isfinite(a)):
            raise InputError(f"uv must be finite, shape (N, 2), got shape {a.shape}")
        world: F64 = self.origin + a[:, :1] * self.u + a[:, 1:] * self.v
        return world

    def contains(self, uv: ArrayLike) -> NDArray[np.bool_]:
        """True where (u, v) [m], shape (N, 2), lies on the sheet, shape (N,)."""
        a = np.asarray(uv, dtype=np.float64)
        inside: NDArray[np.bool_] = (
            (a[:, 0] >= 0) & (a[:, 0] <= self.width) & (a[:, 1] >= 0) & (a[:, 1] <= self.height)
        )
        return inside

    def corners(self) -> F64:
        """The four corners [m], shape (4, 3), counter-clockwise from the origin."""
        uv = np.array([[0, 0], [self.width, 0], [self.width, self.height], [0, self.height]])
        return self.to_world(uv)
