"""What every kind of object on the table is to the rest of armkit: one protocol.

A kind of object (a board, a cube, a sheet, a xylophone, ...) is one module that
holds its dataclass, how it is read from a scene file, the solids the clearance
check keeps the arm out of, the surfaces a cube can rest on and the primitives a
view draws; the registry (``_kinds.OBJECT_KINDS``) lists the kinds. Clearance,
support and the views iterate over ``Scene.objects()`` and ask each object, instead
of branching per kind. A kind's code sees the scene as ``Placed`` (the table and the
objects on it), never the ``Scene`` class that holds the kinds.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Generic, Protocol, TypeVar

import numpy as np
from numpy.typing import NDArray

from .._primitives import Primitive
from ._rect import Rect

F64 = NDArray[np.float64]
T = TypeVar("T")


@dataclass(frozen=True)
class Solid:
    """A box the arm must stay out of, in the scene frame [m].

    Attributes:
        center: its centre, shape (3,).  rotation: its axes as columns, shape (3, 3).
        half: its half sizes along those axes, shape (3,).
    """

    center: F64
    rotation: F64
    half: F64

    @classmethod
    def upright(cls, center: F64, size: Any) -> Solid:
        """A box of ``size`` (3,) [m] with its sides along the scene axes."""
        return cls(np.asarray(center, dtype=np.float64), np.eye(3), np.asarray(size) / 2.0)


@dataclass(frozen=True)
class Support:
    """A surface under a footprint: its height [m], what it is, and whether the
    footprint's centre is over it (stable)."""

    z: float
    on: str
    stable: bool


class SceneObject(Protocol):
    """An object on the table."""

    @property
    def name(self) -> str:
        """Unique in its scene."""
        ...

    def solids(self) -> tuple[Solid, ...]:
        """What the arm must not enter (none for what it touches on purpose: a sheet, an
        instrument, a pen, a place)."""
        ...

    def supports(self, foot: Rect) -> tuple[Support, ...]:
        """The surfaces it offers a cube whose footprint is ``foot`` (none: nothing
        rests on it)."""
        ...

    def primitives(self, scene: Placed) -> list[Primitive]:
        """How a view draws it (``scene``: where it stands, for what it depends on)."""
        ...

    def listed(self, scene: Placed) -> tuple[str, str]:
        """The heading ``armkit scene show`` lists it under (``"cubes"``) and its line
        there, in millimetres and degrees (``scene``: where it stands)."""
        ...


class Placed(Protocol):
    """The scene as a kind's code reads it: the table and the objects on it."""

    @property
    def table_z(self) -> float:
        """Height of the table's surface [m]."""
        ...

    def objects(self) -> tuple[SceneObject, ...]:
        """Every object on the table."""
        ...


def support_under(scene: Placed, foot: Rect, below: float) -> Support:
    """The highest surface under ``foot`` no higher than ``below`` + 1 mm [m] (the
    table, else the first of the highest the objects offer)."""
    best = Support(scene.table_z, "table", True)
    for obj in scene.objects():
        for found in obj.supports(foot):
            if found.z <= below + 1e-3 and found.z > best.z:
                best = found
    return best


@dataclass(frozen=True)
class ObjectKind(Generic[T]):
    """One kind of object as a scene file holds it.

    Attributes:
        section: the file's array of tables (``[[cubes]]``).
        load: reads that section (``load(path, data, scene)``: ``data`` the whole file,
            ``scene`` what is read before it) and returns its objects (SceneError naming
            the field).
        keep: where a scene keeps them (returns the scene with them added).
    """

    section: str
    load: Callable[[Path, dict[str, Any], Placed], tuple[T, ...]]
    keep: Callable[[Any, tuple[T, ...]], Any]
