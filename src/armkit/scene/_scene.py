"""The scene: the table, where the arm's base stands, and everything on the table."""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from functools import cached_property
from pathlib import Path
from typing import TypeVar

import numpy as np
from numpy.typing import NDArray

from .._errors import InputError
from ._board import Board
from ._container import Container
from ._cube import Cube
from ._hand import Hand
from ._instruments import Instrument
from ._object import SceneObject
from ._pen import Pen, PenStand
from ._place import Place
from ._surfaces import Sheet

F64 = NDArray[np.float64]
PHYSICS = ("rules", "mujoco")  # what may move a simulated scene's objects


@dataclass(frozen=True, eq=False)
class Scene:
    """What is on the table, in the scene's (table's) frame, SI units.

    Attributes:
        name: the scene's name.
        table_z: height of the table's surface [m].
        T_world_base: the arm's base frame in the scene frame, shape (4, 4): arm
            coordinates p_base map to scene coordinates ``T_world_base @ p_base``.
        boards, cubes, containers, pens, pen_stands, sheets, instruments, places:
            the objects, each name unique across the scene.
        hands: hands held out to shake (003), after ``source`` so that positional
            construction stays as it was.
        physics: what moves the objects in the simulator: ``"rules"`` (armkit's own
            rules, the default) or ``"mujoco"`` (MuJoCo, ``armkit.physics``).
        others: objects of kinds no job looks up by kind (a kind added to
            ``OBJECT_KINDS`` whose loader puts its objects here needs no field of its own).
        source: the file it was loaded from, or None.
    """

    name: str
    table_z: float = 0.0
    T_world_base: F64 = field(default_factory=lambda: np.eye(4))
    boards: tuple[Board, ...] = ()
    cubes: tuple[Cube, ...] = ()
    containers: tuple[Container, ...] = ()
    pens: tuple[Pen, ...] = ()
    pen_stands: tuple[PenStand, ...] = ()
    sheets: tuple[Sheet, ...] = ()
    instruments: tuple[Instrument, ...] = ()
    places: tuple[Place, ...] = ()
    source: Path | None = None
    hands: tuple[Hand, ...] = ()
    others: tuple[SceneObject, ...] = ()
    physics: str = "rules"

    def objects(self) -> tuple[SceneObject, ...]:
        """Every object, in file order by kind (what clearance and the views iterate)."""
        groups: tuple[tuple[SceneObject, ...], ...] = (
            self.boards,
            self.cubes,
            self.containers,
            self.places,
            self.pens,
            self.pen_stands,
            self.sheets,
            self.instruments,
            self.hands,
            self.others,
        )
        return tuple(obj for group in groups for obj in group)

    def names(self) -> tuple[str, ...]:
        """Every object's name, in file order by kind."""
        return tuple(obj.name for obj in self.objects())

    def cube(self, name: str) -> Cube:
        """The cube called ``name``; ValueError lists the cubes."""
        return _find(self.cubes, name, "cube", self.name)

    def board(self, name: str) -> Board:
        """The board called ``name``; ValueError lists the boards."""
        return _find(self.boards, name, "board", self.name)

    def place(self, name: str) -> Place:
        """The named place ``name``; ValueError lists the places."""
        return _find(self.places, name, "place", self.name)

    def container(self, name: str) -> Container:
        """The container called ``name``; ValueError lists the containers."""
        return _find(self.containers, name, "container", self.name)

    def hand(self, name: str) -> Hand:
        """The hand called ``name``; ValueError lists the hands."""
        return _find(self.hands, name, "hand", self.name)

    def with_cube(self, cube: Cube) -> Scene:
        """The same scene with the cube of ``cube.name`` replaced by ``cube``."""
        self.cube(cube.name)
        cubes = tuple(cube if c.name == cube.name else c for c in self.cubes)
        return replace(self, cubes=cubes)

    def without_cube(self, name: str) -> Scene:
        """The same scene without the cube ``name`` (while it is held)."""
        return replace(self, cubes=tuple(c for c in self.cubes if c.name != name))

    @cached_property
    def T_base_world(self) -> F64:
        """The inverse of ``T_world_base``, shape (4, 4)."""
        R, t = self.T_world_base[:3, :3], self.T_world_base[:3, 3]
        T = np.eye(4)
        T[:3, :3], T[:3, 3] = R.T, -R.T @ t
        return T

    def to_base(self, p: F64) -> F64:
        """Scene point(s) [m], shape (..., 3), in the arm's base frame."""
        T = self.T_base_world
        out: F64 = np.asarray(p) @ T[:3, :3].T + T[:3, 3]
        return out

    def to_scene(self, p: F64) -> F64:
        """Base-frame point(s) [m], shape (..., 3), in the scene frame."""
        T = self.T_world_base
        out: F64 = np.asarray(p) @ T[:3, :3].T + T[:3, 3]
        return out


_Named = TypeVar("_Named", Board, Cube, Place, Container, Hand)


def _find(items: tuple[_Named, ...], name: str, kind: str, scene: str) -> _Named:
    for item in items:
        if item.name == name:
            return item
    known = ", ".join(i.name for i in items) or "none"
    raise InputError(f"scene {scene!r} has no {kind} {name!r}; its {kind}s: {known}")
