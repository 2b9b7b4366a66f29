"""A cube (001's 25 mm cubes): the one kind of object a gripper picks up and moves."""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from pathlib import Path
from typing import Any, Literal

import numpy as np
from numpy.typing import NDArray

from .._inputs import deg_text, mm
from .._primitives import RGB, Box, Primitive
from ._board import Board
from ._fields import Entry, entries
from ._object import Placed, SceneObject, Solid, Support, support_under
from ._rect import Rect
from ._rotations import FACES, face_up, pose, rot_z, yaw_and_face

F64 = NDArray[np.float64]
FLAT_TILT = math.radians(10.0)  # a cube released tilted less than this lands flat
DROP_HEIGHT = 0.005  # [m]: released higher than this above its support = dropped
Outcome = Literal["placed", "dropped", "tipped"]
KEYS = ("name", "size_mm", "position_mm", "socket", "on", "yaw_deg", "up_face")
REST_TOLERANCE = 0.5e-3  # [m] a cube's bottom must be this close to what it stands on
# Cubes named after a colour are drawn in it; other cubes take the palette in turn.
NAMED_COLOURS: dict[str, RGB] = {
    "red": (215, 25, 25),
    "green": (20, 170, 40),
    "blue": (25, 70, 230),
    "yellow": (230, 200, 20),
    "magenta": (200, 20, 180),
    "cyan": (20, 180, 180),
    "teal": (20, 180, 180),
}
PALETTE: tuple[RGB, ...] = ((200, 20, 180), (25, 70, 230), (20, 180, 180), (230, 200, 20))


@dataclass(frozen=True, eq=False)
class Cube:
    """A cube (001's 25 mm cubes).

    Attributes:
        size: edge [m].
        position: centre of the face it stands on [m], shape (3,).
        yaw: turn about z [rad].
        up_face: which of its faces points up: ``"+z"`` (as made), ``"-z"``, ``"+x"``,
            ``"-x"``, ``"+y"``, ``"-y"`` (faces named in the cube's own frame).
    """

    name: str
    size: float
    position: F64
    yaw: float = 0.0
    up_face: str = "+z"

    @property
    def T(self) -> F64:
        """Pose of the cube's centre and axes in the scene frame, shape (4, 4)."""
        R = rot_z(self.yaw) @ face_up(self.up_face)
        return pose(R, self.position + np.array([0.0, 0.0, self.size / 2.0]))

    @property
    def center(self) -> F64:
        """Centre of the cube [m], shape (3,)."""
        centre: F64 = self.position + np.array([0.0, 0.0, self.size / 2.0])
        return centre

    @property
    def top_z(self) -> float:
        """Height of its top face [m]."""
        return float(self.position[2]) + self.size

    def moved(self, T: F64) -> Cube:
        """The same cube with its centre at ``T`` (4, 4), snapped to the nearest face up."""
        yaw, face, _ = yaw_and_face(T[:3, :3])
        bottom = T[:3, 3] - np.array([0.0, 0.0, self.size / 2.0])
        return Cube(self.name, self.size, bottom, yaw, face)

    def footprint(self) -> Rect:
        """Its footprint on the table, snapped flat."""
        return Rect(self.position[:2].copy(), (self.size / 2, self.size / 2), self.yaw)

    def solids(self) -> tuple[Solid, ...]:
        """The cube itself."""
        T = self.T
        return (Solid(T[:3, 3], T[:3, :3], np.full(3, self.size / 2)),)

    def supports(self, foot: Rect) -> tuple[Support, ...]:
        """Its top, under a footprint it overlaps (stable where ``foot``'s centre is over it)."""
        top = self.footprint()
        if not top.overlaps(foot):
            return ()
        return (Support(self.top_z, self.name, top.contains_points(foot.center[None, :])),)

    def listed(self, scene: Placed) -> tuple[str, str]:
        """Its size, position, yaw, face up and the board socket it stands in."""
        where = ""
        for b in (obj for obj in scene.objects() if isinstance(obj, Board)):
            found = b.socket_at(self.position)
            if found is not None and abs(b.socket(*found)[2] - self.position[2]) < 1e-4:
                where = f", in {b.name}[{found[0]}, {found[1]}]"
        return "cubes", (
            f"{self.name}: {self.size * 1000:.1f} mm at {mm(self.position)}, "
            f"yaw {deg_text(self.yaw)}, {self.up_face} up{where}"
        )

    def primitives(self, scene: Placed) -> list[Primitive]:
        """The cube as a box in its colour (``cube_colour``)."""
        return [cube_primitive(self, scene)]


def footprint(cube: Cube) -> Rect:
    """The cube's footprint on the table, snapped flat."""
    return cube.footprint()


@dataclass(frozen=True)
class Settled:
    """Where a released cube ends: the cube at rest, ``outcome`` (placed, dropped
    from more than 5 mm, tipped), what it rests on, and how far it fell [m]."""

    cube: Cube
    outcome: Outcome
    on: str
    fall: float


def settle(scene: Placed, cube: Cube, T: F64) -> Settled:
    """Where ``cube``, released with its centre at ``T`` (4, 4) in ``scene`` (which
    must not contain it), comes to rest: straight down onto the highest surface
    under it, turned to the nearest face down."""
    _, _, tilt = yaw_and_face(T[:3, :3])
    flat = cube.moved(T)
    bottom = float(T[2, 3]) - cube.size / 2
    below = support_under(scene, flat.footprint(), bottom)
    rest = replace(flat, position=np.array([*flat.position[:2], below.z]))
    fall = bottom - below.z
    outcome: Outcome = "placed"
    if tilt > FLAT_TILT or not below.stable:
        outcome = "tipped"
    elif fall > DROP_HEIGHT:
        outcome = "dropped"
    return Settled(rest, outcome, below.on, fall)


def cube_colour(name: str, scene: Placed | None = None) -> RGB:
    """The colour a cube is drawn in: its name's colour, else the palette by its place
    in ``scene``."""
    if name in NAMED_COLOURS:
        return NAMED_COLOURS[name]
    names = [c.name for c in _cubes(scene)] if scene is not None else []
    k = names.index(name) if name in names else sum(map(ord, name))
    return PALETTE[k % len(PALETTE)]


def cube_primitive(cube: Cube, scene: Placed | None = None, T: F64 | None = None) -> Box:
    """``cube`` as a box at its pose (or at the centre pose ``T`` (4, 4) [m], held)."""
    where = cube.T if T is None else T
    return Box(f"/scene/{cube.name}", np.full(3, cube.size), where, cube_colour(cube.name, scene))


def _cubes(scene: Placed) -> list[Cube]:
    return [obj for obj in scene.objects() if isinstance(obj, Cube)]


@dataclass(frozen=True)
class _With:
    """A scene and the cubes read so far (``Placed``)."""

    scene: Placed
    cubes: tuple[Cube, ...]

    @property
    def table_z(self) -> float:
        return self.scene.table_z

    def objects(self) -> tuple[SceneObject, ...]:
        return (*self.scene.objects(), *self.cubes)


def load_cubes(path: Path, data: dict[str, Any], placed: Placed) -> tuple[Cube, ...]:
    """``[[cubes]]`` in file order (a cube may stand ``on`` one listed before it); each
    must rest on the table, a socket floor, a board, a container or a cube."""
    scene = _With(placed, ())
    for e in entries(path, data, "cubes", KEYS):
        cube = _cube(e, scene)
        under = support_under(scene, cube.footprint(), float(cube.position[2]))
        if abs(under.z - cube.position[2]) > REST_TOLERANCE:
            raise e.fail(
                "position_mm",
                f"the cube's bottom is at z = {cube.position[2] * 1000:.1f} mm but the surface "
                f"under it ({under.on}) is at {under.z * 1000:.1f} mm; cubes rest on something",
            )
        _check_apart(e, tuple(_cubes(scene)), cube)
        scene = _With(placed, (*scene.cubes, cube))
    return scene.cubes


def _check_apart(e: Entry, cubes: tuple[Cube, ...], cube: Cube) -> None:
    """SceneError if ``cube`` would stand inside one listed before it (two cubes in one
    socket or at one place): their bodies overlap in height and their centres are
    nearer than half their sizes added (each one's inscribed circle)."""
    for other in cubes:
        low, high = cube.position[2], cube.position[2] + cube.size
        if min(high, other.top_z) - max(low, other.position[2]) <= REST_TOLERANCE:
            continue  # one above the other
        apart = float(np.linalg.norm(cube.position[:2] - other.position[:2]))
        if apart < (cube.size + other.size) / 2 - REST_TOLERANCE:
            key = next(k for k in ("socket", "position_mm", "on") if e.has(k))
            raise e.fail(
                key,
                f"{cube.name} would stand inside {other.name} (centres {apart * 1000:.1f} mm "
                "apart); give each cube its own socket or place, or stand it on the other",
            )


def _cube(e: Entry, scene: Placed) -> Cube:
    where = [k for k in ("position_mm", "socket", "on") if e.has(k)]
    if len(where) != 1:
        raise e.fail("position_mm", "give exactly one of position_mm, socket, on")
    size = e.positive_mm("size_mm")
    yaw, face = e.deg("yaw_deg", 0.0), e.text("up_face", "+z", FACES)
    if where[0] == "position_mm":
        position = e.point_mm("position_mm")
    elif where[0] == "socket":
        board, position = _socket_floor(e, scene)
        yaw = e.deg("yaw_deg", np.degrees(board.yaw))
    else:
        below = e.text("on")
        cubes = {c.name: c for c in _cubes(scene)}
        if below not in cubes:
            raise e.fail("on", f"no cube {below!r} listed before this one")
        position = cubes[below].position + np.array([0.0, 0.0, cubes[below].size])
        yaw = e.deg("yaw_deg", np.degrees(cubes[below].yaw))
    return Cube(e.name(), size, position, yaw, face)


def _socket_floor(e: Entry, scene: Placed) -> tuple[Board, F64]:
    """The board of the cube's ``socket`` and the floor of that socket [m], shape (3,)."""
    spec = Entry(e.path, f"{e.where}.socket", e.data["socket"], ("board", "row", "col"))
    name = spec.text("board")
    boards = {b.name: b for b in scene.objects() if isinstance(b, Board)}
    if name not in boards:
        raise spec.fail("board", f"no board {name!r}; boards: {', '.join(boards) or 'none'}")
    board = boards[name]
    row = spec.integer("row", hi=board.rows - 1)
    col = spec.integer("col", hi=board.cols - 1)
    return board, board.socket(row, col)
