"""The shapes every picture of armkit is drawn from (pure data, SI units).

A view (the web page, a GIF; ``armkit.viz``) is a list of primitives; anything that
wants to be seen (an arm, a scene object, a trail, a target) turns itself into them:
they stand on the ground floor so that a scene object can (``armkit.scene``). Each
primitive has a ``name``: a path such as ``"/scene/cube_a"`` that stays the
same from one frame to the next, so a renderer moves what it has instead of
drawing it again. Colours are RGB in 0..255.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ._errors import InputError

F64 = NDArray[np.float64]
RGB = tuple[int, int, int]


def pose(position: ArrayLike = (0.0, 0.0, 0.0), yaw: float = 0.0) -> F64:
    """A transform [m], shape (4, 4): turned by ``yaw`` [rad] about z, then moved to
    ``position`` [m], shape (3,)."""
    T = np.eye(4)
    c, s = math.cos(yaw), math.sin(yaw)
    T[:2, :2] = [[c, -s], [s, c]]
    T[:3, 3] = vec3(position, "position")
    return T


@dataclass(frozen=True, eq=False)
class Box:
    """A box of ``size`` (x, y, z) [m], shape (3,), centred on the frame ``T`` (4, 4)."""

    name: str
    size: F64
    T: F64
    color: RGB
    opacity: float = 1.0

    def __post_init__(self) -> None:
        object.__setattr__(self, "size", _array(self.size, (3,), "size"))
        object.__setattr__(self, "T", _array(self.T, (4, 4), "T"))


@dataclass(frozen=True, eq=False)
class Cylinder:
    """A cylinder of ``radius`` and ``height`` [m] along the z axis of ``T`` (4, 4),
    centred on its origin."""

    name: str
    radius: float
    height: float
    T: F64
    color: RGB
    opacity: float = 1.0

    def __post_init__(self) -> None:
        object.__setattr__(self, "T", _array(self.T, (4, 4), "T"))


@dataclass(frozen=True, eq=False)
class Capsule:
    """Every point within ``radius`` [m] of the segment ``p0``-``p1`` [m], shape (3,)
    each: the link shape of the clearance check."""

    name: str
    p0: F64
    p1: F64
    radius: float
    color: RGB

    def __post_init__(self) -> None:
        object.__setattr__(self, "p0", _array(self.p0, (3,), "p0"))
        object.__setattr__(self, "p1", _array(self.p1, (3,), "p1"))


@dataclass(frozen=True, eq=False)
class Sphere:
    """A ball of ``radius`` [m] around ``center`` [m], shape (3,)."""

    name: str
    center: F64
    radius: float
    color: RGB

    def __post_init__(self) -> None:
        object.__setattr__(self, "center", _array(self.center, (3,), "center"))


@dataclass(frozen=True, eq=False)
class Polyline:
    """A line through ``points`` [m], shape (N, 3), ``width`` in screen pixels."""

    name: str
    points: F64
    color: RGB
    width: float = 2.0

    def __post_init__(self) -> None:
        object.__setattr__(self, "points", _array(self.points, (-1, 3), "points"))


@dataclass(frozen=True, eq=False)
class Axes:
    """The x, y, z axes of the frame ``T`` (4, 4) drawn red, green, blue, ``length`` [m]."""

    name: str
    T: F64
    length: float = 0.03

    def __post_init__(self) -> None:
        object.__setattr__(self, "T", _array(self.T, (4, 4), "T"))


@dataclass(frozen=True, eq=False)
class Label:
    """Text shown at ``position`` [m], shape (3,)."""

    name: str
    position: F64
    text: str
    color: RGB = field(default=(0, 0, 0))

    def __post_init__(self) -> None:
        object.__setattr__(self, "position", _array(self.position, (3,), "position"))


Primitive = Box | Cylinder | Capsule | Sphere | Polyline | Axes | Label


def vec3(value: ArrayLike, what: str) -> F64:
    """``value`` as 3 finite numbers [m], shape (3,), else InputError naming ``what``."""
    v = np.asarray(value, dtype=np.float64)
    if v.shape != (3,) or not np.all(np.isfinite(v)):
        raise InputError(f"{what} must be 3 finite numbers [m], got {value!r}")
    return v


def _array(value: ArrayLike, shape: tuple[int, ...], what: str) -> F64:
    """``value`` as a float array of ``shape`` (-1: any length), finite, else ValueError."""
    a = np.asarray(value, dtype=np.float64)
    ok = a.ndim == len(shape) and all(w in (-1, n) for w, n in zip(shape, a.shape, strict=True))
    if not ok or not np.all(np.isfinite(a)):
        raise InputError(f"{what} must be finite numbers of shape {shape}, got {value!r}")
    return a


def moved(prim: Primitive, T: F64) -> Primitive:
    """``prim`` carried by the transform ``T`` (4, 4) (same name, shape and colour)."""
    if np.array_equal(T, np.eye(4)):
        return prim
    R, t = T[:3, :3], T[:3, 3]
    if isinstance(prim, Box | Cylinder | Axes):
        return replace(prim, T=T @ prim.T)
    if isinstance(prim, Capsule):
        return replace(prim, p0=R @ prim.p0 + t, p1=R @ prim.p1 + t)
    if isinstance(prim, Sphere):
        return replace(prim, center=R @ prim.center + t)
    if isinstance(prim, Polyline):
        return replace(prim, points=prim.points @ R.T + t)
    return replace(prim, position=R @ prim.position + t)
