"""Load and validate scene files (TOML, millimetres and degrees)."""

from __future__ import annotations

import re
from pathlib import Path
from typing import Any

from .._input_limits import MAX_OBJECTS, position, where
from .._toml_files import read_toml, resolve
from .._toml_where import located
from . import _kinds
from ._errors import SceneError
from ._fields import Entry
from ._rotations import pose, rot_z
from ._scene import PHYSICS, Scene

_TOP = ("name", "description", "table_z_mm", "base", "physics")


def load_scene(name_or_path: str | Path) -> Scene:
    """Load a shipped scene by name (``"board_001"``) or a scene file by path.

    Raises:
        SceneError: the file is missing, not TOML, or a field is wrong; the message
            names the file, the field and what is allowed.
    """
    path = _resolve(name_or_path)
    data, text = read_toml(path, SceneError, "scene file")
    _count_objects(data, text, path)
    try:
        return build_scene(data, path)
    except SceneError as exc:
        raise located(exc, text) from None


def _count_objects(data: dict[str, Any], text: str, path: Path) -> None:
    """Refuse more than ``MAX_OBJECTS`` objects (every array of tables counted) at the
    line of the first one too many, before any is built."""
    count = sum(len(v) for v in data.values() if isinstance(v, list))
    if count > MAX_OBJECTS:
        headers = [m.start() for m in re.finditer(r"(?m)^[ \t]*\[\[", text)]
        line, column = (
            position(text, headers[MAX_OBJECTS]) if len(headers) > MAX_OBJECTS else (0, 0)
        )
        raise SceneError(
            f"{where(str(path), line, column)}: more than {MAX_OBJECTS} objects ({count}); "
            "a table holds fewer: split the scene or check the file"
        )


def _resolve(name_or_path: str | Path) -> Path:
    return resolve(name_or_path, "armkit.scene", "scenes", SceneError, kind="scene", noun="scene")


def build_scene(data: dict[str, Any], path: Path) -> Scene:
    """A Scene from a parsed scene file, every field checked: the table and the base,
    then each kind of object (``OBJECT_KINDS``, read now) in turn."""
    kinds = _kinds.OBJECT_KINDS
    top = Entry(path, "", data, (*_TOP, *(kind.section for kind in kinds)))
    table_z = top.mm("table_z_mm", 0.0)
    base = Entry(path, "base", data.get("base", {}), ("xyz_mm", "yaw_deg"))
    xyz = base.point_mm("xyz_mm", [0.0, 0.0, table_z * 1000.0])
    scene = Scene(
        name=top.name(),
        table_z=table_z,
        T_world_base=pose(rot_z(base.deg("yaw_deg", 0.0)), xyz),
        source=path,
        physics=top.text("physics", "rules", PHYSICS),
    )
    for kind in kinds:
        scene = kind.keep(scene, kind.load(path, data, scene))
    _check_unique(scene, path)
    return scene


def _check_unique(scene: Scene, path: Path) -> None:
    seen: set[str] = set()
    for name in scene.names():
        if name in seen:
            raise SceneError(f"{path}: name {name!r} is used twice; every object needs its own")
        seen.add(name)
