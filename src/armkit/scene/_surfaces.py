"""Sheets of paper: a rectangle on any plane (drawing on the table, on a wall, tilted)."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .._errors import InputError
from .._inputs import mm
from .._primitives import RGB, Box, Primitive
from ._fields import Entry, entries
from ._object import Placed, Solid, Support
from ._rect import Rect

F64 = NDArray[np.float64]
SHEET_COLOUR: RGB = (250, 250, 250)
THIN = 0.001  # [m] thickness of paper in a view
KEYS = ("name", "size", "width_mm", "height_mm", "landscape", "origin_mm", "u", "v")

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

    def solids(self) -> tuple[Solid, ...]:
        """None: drawing touches the sheet on purpose."""
        return ()

    def supports(self, foot: Rect) -> tuple[Support, ...]:
        """None: a sheet is drawn on."""
        return ()

    def listed(self, scene: Placed) -> tuple[str, str]:
        """Its size, corner and normal."""
        return "sheets", (
            f"{self.name}: {self.width * 1000:.1f} x {self.height * 1000:.1f} mm, corner "
            f"{mm(self.origin)}, normal {np.round(self.normal, 3).tolist()}"
        )

    def primitives(self, scene: Placed) -> list[Primitive]:
        """A thin white box on its plane."""
        T = np.eye(4)
        T[:3, :3] = np.column_stack([self.u, self.v, self.normal])
        T[:3, 3] = self.center - self.normal * THIN / 2
        size = np.array([self.width, self.height, THIN])
        return [Box(f"/scene/{self.name}", size, T, SHEET_COLOUR)]


def load_sheets(path: Path, data: dict[str, Any], scene: Placed) -> tuple[Sheet, ...]:
    """``[[sheets]]``: a preset ``size`` (A3..A6, ``landscape = true`` to turn it) or
    ``width_mm``/``height_mm``; ``origin_mm`` a corner; ``u``, ``v`` its edge
    directions (default: along x and y, lying on the table)."""
    return tuple(_sheet(e) for e in entries(path, data, "sheets", KEYS))


def _sheet(e: Entry) -> Sheet:
    if e.has("size") == (e.has("width_mm") or e.has("height_mm")):
        raise e.fail("size", "give either size (A3, A4, A5, A6) or width_mm and height_mm")
    if e.has("size"):
        width, height = PAPER_SIZES[e.text("size", choices=tuple(PAPER_SIZES))]
    else:
        width, height = e.positive_mm("width_mm"), e.positive_mm("height_mm")
    landscape = e.data.get("landscape", False)
    if not isinstance(landscape, bool):
        raise e.fail("landscape", f"must be true or false, got {landscape!r}")
    if landscape:
        width, height = height, width
    u, v = e.direction("u", [1.0, 0.0, 0.0]), e.direction("v", [0.0, 1.0, 0.0])
    if abs(float(u @ v)) > 1e-6:
        raise e.fail("v", f"must be at right angles to u, got u = {u.tolist()}, v = {v.tolist()}")
    return Sheet(e.name(), e.point_mm("origin_mm"), u, v, width, height)
