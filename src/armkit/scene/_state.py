"""The simulated objects' state kept between processes (what ``--driver sim`` does
for the arm, done for the scene): where every cube rests now and which one is in
the gripper, so ``armkit --scene board_001 pick green`` in one process and
``armkit --scene board_001 place green red`` in the next see the same table.

One JSON file per scene file and simulated arm in the config directory:
``scene_<scene>-<10 hex of the file's text>_<arm key>.json``; a changed scene file
gets a fresh state. Millimetres and degrees in the file.
"""

from __future__ import annotations

import hashlib
import json
import math
from dataclasses import replace
from pathlib import Path

import numpy as np

from .._errors import DeviceError
from .._files import config_dir, write_atomic
from ._cube import Cube
from ._physics import ScenePhysics
from ._scene import Scene

VERSION = 1


def scene_state_file(scene: Scene, arm_key: str) -> Path:
    """Where the objects of ``scene`` handled by the simulated arm ``arm_key`` are kept."""
    text = scene.source.read_bytes() if scene.source is not None else scene.name.encode()
    digest = hashlib.sha256(text).hexdigest()[:10]
    return config_dir() / f"scene_{scene.name}-{digest}_{arm_key}.json"


def rest_scene(physics: ScenePhysics) -> Scene:
    """The objects at rest, a held cube shown where it was picked from (what a task plans
    with: ``place`` takes the held cube from where the scene has it)."""
    held = physics.holding
    if held is None:
        return physics.scene
    return replace(physics.scene, cubes=(*physics.scene.cubes, held.cube))


def save_physics(path: Path, physics: ScenePhysics) -> None:
    """Write the cubes at rest and the held cube of ``physics`` to ``path`` (atomic)."""
    write_atomic(path, physics_text(physics), durable=False)


def physics_text(physics: ScenePhysics) -> str:
    """The cubes at rest and the held cube of ``physics`` as the state file's JSON text."""
    held = physics.holding
    data = {
        "version": VERSION,
        "scene": physics.scene.name,
        "cubes": [_cube(c) for c in physics.scene.cubes],
        "held": None
        if held is None
        else {"cube": _cube(held.cube), "T_tool_object": held.T_tool_object.tolist()},
    }
    return json.dumps(data, indent=1) + "\n"


def load_physics(path: Path, scene: Scene) -> ScenePhysics:
    """A ScenePhysics for ``scene`` with the cubes where ``path`` has them (as loaded if
    there is no file).

    Raises:
        DeviceError: the file is unreadable or names cubes the scene does not have
            (the message names the file and says to delete it).
    """
    physics = ScenePhysics(scene)
    if not path.exists():
        return physics
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
        cubes = {c.name: c for c in scene.cubes}
        if int(data["version"]) != VERSION:
            raise _unreadable(path, f"version {data['version']}")
        rest = tuple(_uncube(path, d, cubes) for d in data["cubes"])
        held = data["held"]
        physics.scene = replace(scene, cubes=rest)
        if held is not None:
            T = np.array(held["T_tool_object"], dtype=np.float64).reshape(4, 4)
            physics.restore(_uncube(path, held["cube"], cubes), T)
    except (OSError, ValueError, KeyError, TypeError) as exc:
        raise _unreadable(path, str(exc)) from None
    return physics


def _unreadable(path: Path, why: str) -> DeviceError:
    return DeviceError(f"{path}: unreadable simulated scene state ({why}); delete the file")


def _cube(c: Cube) -> dict[str, object]:
    return {
        "name": c.name,
        "position_mm": [round(float(v) * 1000.0, 6) for v in c.position],
        "yaw_deg": round(math.degrees(c.yaw), 6),
        "up_face": c.up_face,
    }


def _uncube(path: Path, d: dict[str, object], cubes: dict[str, Cube]) -> Cube:
    name = str(d["name"])
    if name not in cubes:
        raise _unreadable(path, f"no cube {name!r} in the scene")
    pos = np.array(d["position_mm"], dtype=np.float64).reshape(3) / 1000.0
    yaw = math.radians(float(d["yaw_deg"]))  # type: ignore[arg-type]
    return Cube(name, cubes[name].size, pos, yaw, str(d["up_face"]))
