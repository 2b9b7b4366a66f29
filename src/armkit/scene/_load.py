"""Load and validate scene files (TOML, millimetres and degrees)."""

from __future__ import annotations

import tomllib
from dataclasses import replace
from pathlib import Path
from typing import Any

import numpy as np

from .._toml_files import resolve, shipped
from ._bars import xylophones
from ._errors import SceneError
from ._fields import Entry, entries
from ._objects import Board, Container, Cube, Hand, Pen, PenStand, Place
from ._rotations import FACES, pose, rot_z
from ._scene import Scene
from ._sections import drums, sheets
from ._support import footprint, support_under

_TOP = (
    "name", "description", "table_z_mm", "base", "boards", "cubes", "containers",
    "places", "pens", "pen_stands", "sheets", "xylophones", "drums", "hands",
)  # fmt: skip
_HAND = ("name", "position_mm", "size_mm")
_BOARD = (
    "name", "origin_mm", "yaw_deg", "rows", "cols", "pitch_mm", "socket_size_mm",
    "socket_depth_mm", "thickness_mm", "size_mm",
)  # fmt: skip
_CUBE = ("name", "size_mm", "position_mm", "socket", "on", "yaw_deg", "up_face")
REST_TOLERANCE = 0.5e-3  # [m] a cube's bottom must be this close to what it stands on


def shipped_scenes() -> list[str]:
    """Names of the scenes shipped with armkit, sorted."""
    return shipped("armkit.scene", "scenes")


def load_scene(name_or_path: str | Path) -> Scene:
    """Load a shipped scene by name (``"board_001"``) or a scene file by path.

    Raises:
        SceneError: the file is missing, not TOML, or a field is wrong; the message
            names the file, the field and what is allowed.
    """
    path = _resolve(name_or_path)
    try:
        data = tomllib.loads(path.read_text(encoding="utf-8"))
    except tomllib.TOMLDecodeError as exc:
        raise SceneError(f"{path}: not valid TOML: {exc}") from None
    except UnicodeDecodeError:
        raise SceneError(f"{path}: not a UTF-8 text file") from None
    except OSError as exc:
        raise SceneError(f"{path}: cannot read: {exc.strerror}") from None
    return build_scene(data, path)


def _resolve(name_or_path: str | Path) -> Path:
    return resolve(name_or_path, "armkit.scene", "scenes", SceneError, kind="scene", noun="scene")


def build_scene(data: dict[str, Any], path: Path) -> Scene:
    """A Scene from a parsed scene file, every field checked."""
    top = Entry(path, "", data, _TOP)
    table_z = top.mm("table_z_mm", 0.0)
    base = Entry(path, "base", data.get("base", {}), ("xyz_mm", "yaw_deg"))
    xyz = base.point_mm("xyz_mm", [0.0, 0.0, table_z * 1000.0])
    scene = Scene(
        name=top.name(),
        table_z=table_z,
        T_world_base=pose(rot_z(base.deg("yaw_deg", 0.0)), xyz),
        boards=tuple(_board(e) for e in entries(path, data, "boards", _BOARD)),
        containers=tuple(_container(e) for e in entries(path, data, "containers", _CONTAINER)),
        places=tuple(_place(e) for e in entries(path, data, "places", _PLACE)),
        pens=tuple(_pen(e) for e in entries(path, data, "pens", _PEN)),
        sheets=sheets(path, data),
        instruments=(*xylophones(path, data), *drums(path, data)),
        source=path,
        hands=tuple(_hand(e) for e in entries(path, data, "hands", _HAND)),
    )
    scene = _with_cubes(scene, entries(path, data, "cubes", _CUBE))
    pen_names = {p.name for p in scene.pens}
    stands = tuple(_pen_stand(e, pen_names) for e in entries(path, data, "pen_stands", _STAND))
    scene = replace(scene, pen_stands=stands)
    _check_unique(scene, path)
    return scene


def _board(e: Entry) -> Board:
    rows, cols = e.integer("rows", lo=1, hi=50), e.integer("cols", lo=1, hi=50)
    pitch, hole = e.positive_mm("pitch_mm"), e.positive_mm("socket_size_mm")
    depth, thick = e.mm("socket_depth_mm"), e.positive_mm("thickness_mm")
    size = e.sizes_mm("size_mm", 2)
    if hole >= pitch and rows * cols > 1:
        raise e.fail(
            "socket_size_mm", f"must be < pitch_mm ({pitch * 1000:g}), got {hole * 1000:g}"
        )
    if not 0.0 <= depth <= thick:
        raise e.fail(
            "socket_depth_mm", f"must be 0..thickness_mm ({thick * 1000:g}), got {depth * 1000:g}"
        )
    for k, n in enumerate((rows, cols)):
        if size[k] < (n - 1) * pitch + hole:
            need = ((n - 1) * pitch + hole) * 1000
            raise e.fail(
                f"size_mm[{k}]", f"must hold the sockets: >= {need:g}, got {size[k] * 1000:g}"
            )
    origin = e.point_mm("origin_mm")
    yaw = e.deg("yaw_deg", 0.0)
    return Board(e.name(), origin, yaw, rows, cols, pitch, depth, thick, (size[0], size[1]), hole)


_CONTAINER = ("name", "position_mm", "size_mm", "wall_mm")
_PLACE = ("name", "position_mm", "pitch_deg")
_PEN = ("name", "length_mm", "holder_length_mm", "tip_offset_mm", "diameter_mm", "tool_length_mm")
_STAND = ("name", "position_mm", "pen", "pitch_deg")


def _container(e: Entry) -> Container:
    size = e.sizes_mm("size_mm", 3)
    wall = e.positive_mm("wall_mm")
    if 2 * wall >= min(size[0], size[1]) or wall >= size[2]:
        raise e.fail("wall_mm", f"must leave room inside the box, got {wall * 1000:g}")
    return Container(e.name(), e.point_mm("position_mm"), (size[0], size[1], size[2]), wall)


def _hand(e: Entry) -> Hand:
    size = e.sizes_mm("size_mm", 3)
    return Hand(e.name(), e.point_mm("position_mm"), (size[0], size[1], size[2]))


def _place(e: Entry) -> Place:
    pitch = e.deg("pitch_deg") if e.has("pitch_deg") else None
    if pitch is not None and not -np.pi / 2 - 1e-9 <= pitch <= np.pi / 2 + 1e-9:
        raise e.fail("pitch_deg", "must be -90..90")
    return Place(e.name(), e.point_mm("position_mm"), pitch)


def _pen(e: Entry) -> Pen:
    length, holder = e.positive_mm("length_mm"), e.positive_mm("holder_length_mm")
    if holder >= length:
        raise e.fail("holder_length_mm", f"must be < length_mm ({length * 1000:g})")
    diameter = e.positive_mm("diameter_mm", 24.0)
    lengths = e.data.get("tool_length_mm", {})
    if not isinstance(lengths, dict) or not all(
        isinstance(v, int | float) and not isinstance(v, bool) and 0 < v < 1000
        for v in lengths.values()
    ):
        raise e.fail("tool_length_mm", "must be a table of arm = length in mm (0..1000)")
    tools = tuple((str(k), float(v) / 1000.0) for k, v in lengths.items())
    return Pen(e.name(), length, holder, e.mm("tip_offset_mm"), diameter, tools)


def _pen_stand(e: Entry, pens: set[str]) -> PenStand:
    pen = e.text("pen")
    if pen not in pens:
        raise e.fail(
            "pen", f"no pen {pen!r} in [[pens]]; pens: {', '.join(sorted(pens)) or 'none'}"
        )
    pitch = e.deg("pitch_deg", -90.0)
    if not -np.pi / 2 - 1e-9 <= pitch <= 1e-9:
        raise e.fail("pitch_deg", "must be -90 (upright) .. 0 (lying)")
    return PenStand(e.name(), e.point_mm("position_mm"), pen, pitch)


def _with_cubes(scene: Scene, items: list[Entry]) -> Scene:
    """Add the cubes in file order (a cube may stand ``on`` one listed before it);
    each must rest on the table, a socket floor, a board, a container or a cube."""
    for e in items:
        cube = _cube(e, scene)
        foot = footprint(cube)
        under = support_under(scene, foot, float(cube.position[2]))
        if abs(under.z - cube.position[2]) > REST_TOLERANCE:
            raise e.fail(
                "position_mm",
                f"the cube's bottom is at z = {cube.position[2] * 1000:.1f} mm but the surface "
                f"under it ({under.on}) is at {under.z * 1000:.1f} mm; cubes rest on something",
            )
        _check_apart(e, scene.cubes, cube)
        scene = replace(scene, cubes=(*scene.cubes, cube))
    return scene


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


def _cube(e: Entry, scene: Scene) -> Cube:
    where = [k for k in ("position_mm", "socket", "on") if e.has(k)]
    if len(where) != 1:
        raise e.fail("position_mm", "give exactly one of position_mm, socket, on")
    size = e.positive_mm("size_mm")
    yaw, face = e.deg("yaw_deg", 0.0), e.text("up_face", "+z", FACES)
    if where[0] == "position_mm":
        position = e.point_mm("position_mm")
    elif where[0] == "socket":
        position = _socket_floor(e, scene)
        yaw = e.deg("yaw_deg", np.degrees(scene.board(_socket_board(e)).yaw))
    else:
        below = e.text("on")
        cubes = {c.name: c for c in scene.cubes}
        if below not in cubes:
            raise e.fail("on", f"no cube {below!r} listed before this one")
        position = cubes[below].position + np.array([0.0, 0.0, cubes[below].size])
        yaw = e.deg("yaw_deg", np.degrees(cubes[below].yaw))
    return Cube(e.name(), size, position, yaw, face)


def _socket_board(e: Entry) -> str:
    spec = Entry(e.path, f"{e.where}.socket", e.data["socket"], ("board", "row", "col"))
    return spec.text("board")


def _socket_floor(e: Entry, scene: Scene) -> np.ndarray[Any, np.dtype[np.float64]]:
    spec = Entry(e.path, f"{e.where}.socket", e.data["socket"], ("board", "row", "col"))
    name = spec.text("board")
    boards = {b.name: b for b in scene.boards}
    if name not in boards:
        raise spec.fail("board", f"no board {name!r}; boards: {', '.join(boards) or 'none'}")
    board = boards[name]
    row = spec.integer("row", hi=board.rows - 1)
    col = spec.integer("col", hi=board.cols - 1)
    return board.socket(row, col)


def _check_unique(scene: Scene, path: Path) -> None:
    seen: set[str] = set()
    for name in scene.names():
        if name in seen:
            raise SceneError(f"{path}: name {name!r} is used twice; every object needs its own")
        seen.add(name)
