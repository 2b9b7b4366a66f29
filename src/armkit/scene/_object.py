"""What every kind of object on the table is to the rest of armkit: one protocol.

A kind of object (a board, a cube, a sheet, a xylophone, ...) is one module that
holds its dataclass, how it is read from a scene file, the solids the clearance
check keeps the arm out of, and the primitives a view draws; the registry
(``_kinds.OBJECT_KINDS``) lists the kinds. Clearance and the views iterate over
``Scene.objects()`` and ask each object, instead of branching per kind.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, Protocol

import numpy as np
from numpy.typing import NDArray

from .._primitives import Primitive

if TYPE_CHECKING:
    from pathlib import Path

    from ._scene import Scene

F64 = NDArray[np.float64]


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

    def primitives(self, scene: Scene) -> list[Primitive]:
        """How a view draws it (``scene``: where it stands, for what it depends on)."""
        ...


class Loader(Protocol):
    """Reads one kind's section of a scene file (``data``, the whole file, from ``path``)
    and returns ``scene`` with its objects added (SceneError naming the field)."""

    def __call__(self, path: Path, data: dict[str, Any], scene: Scene) -> Scene: ...


@dataclass(frozen=True)
class ObjectKind:
    """One kind of object as a scene file holds it.

    Attributes:
        section: the file's array of tables (``[[cubes]]``).
        load: reads that section into the scene (``Loader``).
    """

    section: str
    load: Loader
