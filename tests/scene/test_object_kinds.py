"""Scene objects through one protocol (``armkit.scene.SceneObject``): every kind is one
module and one entry of ``OBJECT_KINDS``; clearance and the views ask each object for
its solids and its primitives, so a kind added by its own module and one entry is
read from a scene file, keeps the arm out and is drawn, with nothing else touched."""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from armkit._primitives import Box, Primitive
from armkit.model import load_model
from armkit.scene import (
    OBJECT_KINDS,
    ObjectKind,
    Placed,
    Rect,
    Scene,
    Solid,
    Support,
    check_clear,
    load_scene,
    shipped_scenes,
)
from armkit.scene import _kinds as registry
from armkit.scene._fields import entries
from armkit.viz import scene_primitives

F64 = np.ndarray[Any, np.dtype[np.float64]]


def test_every_kind_is_in_a_shipped_scene_and_answers_the_protocol() -> None:
    scenes = [load_scene(name) for name in shipped_scenes()]
    sections = {kind.section for kind in OBJECT_KINDS}
    found = {type(obj).__name__ for scene in scenes for obj in scene.objects()}
    assert len(sections) == len(OBJECT_KINDS) and len(found) >= 9, found
    for scene in scenes:
        for obj in scene.objects():
            assert all(isinstance(s, Solid) for s in obj.solids()), obj.name
            everywhere = Rect(np.zeros(2), (1.0, 1.0), 0.0)  # a 2 m footprint
            assert all(isinstance(s, Support) for s in obj.supports(everywhere)), obj.name
            drawn = obj.primitives(scene)
            assert all(p.name.startswith("/scene/") for p in drawn), obj.name


def test_the_view_draws_every_object_as_it_draws_itself() -> None:
    scene = load_scene("board_001")
    names = {p.name for p in scene_primitives(scene)}
    for obj in scene.objects():
        assert {p.name for p in obj.primitives(scene)} <= names
        if obj.primitives(scene):
            assert any(n.split("/")[2].startswith(obj.name) for n in names)


# A kind added by its own module (here) and one registry entry: a wall.


@dataclass(frozen=True, eq=False)
class Wall:
    name: str
    center: F64
    size: tuple[float, float, float]

    def solids(self) -> tuple[Solid, ...]:
        return (Solid.upright(self.center, self.size),)

    def supports(self, foot: Rect) -> tuple[Support, ...]:
        return ()

    def primitives(self, scene: Placed) -> list[Primitive]:
        T = np.eye(4)
        T[:3, 3] = self.center
        return [Box(f"/scene/{self.name}", np.array(self.size), T, (128, 128, 128))]


def load_walls(path: Path, data: dict[str, Any], scene: Placed) -> tuple[Wall, ...]:
    return tuple(
        Wall(e.name(), e.point_mm("center_mm"), tuple(e.sizes_mm("size_mm", 3)))  # type: ignore[arg-type]
        for e in entries(path, data, "walls", ("name", "center_mm", "size_mm"))
    )


def keep_walls(scene: Scene, walls: tuple[Wall, ...]) -> Scene:
    return dataclasses.replace(scene, others=(*scene.others, *walls))


WALL_SCENE = """\
name = "walled"
[[walls]]
name = "wall"
center_mm = [200, 0, 100]
size_mm = [20, 300, 200]
"""


@pytest.fixture
def walls(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(
        registry,
        "OBJECT_KINDS",
        (*registry.OBJECT_KINDS, ObjectKind("walls", load_walls, keep_walls)),
    )


def test_a_kind_added_by_one_entry_is_loaded_kept_out_of_and_drawn(
    walls: None, tmp_path: Path
) -> None:
    path = tmp_path / "walled.toml"
    path.write_text(WALL_SCENE)
    scene = load_scene(path)
    assert scene.names() == ("wall",)
    model = load_model("openmanipulator_x")
    hit = check_clear(model, np.radians([0.0, 30.0, 0.0, 0.0]), scene)
    assert hit is not None and hit.object == "wall"
    assert check_clear(model, np.radians([180.0, 0.0, 0.0, 0.0]), scene) is None
    assert "/scene/wall" in {p.name for p in scene_primitives(scene)}
    assert scene.names() == ("wall",) and scene.others[0].solids()


def test_a_kind_not_in_the_registry_is_an_unknown_section(tmp_path: Path) -> None:
    path = tmp_path / "walled.toml"
    path.write_text(WALL_SCENE)
    with pytest.raises(ValueError, match="walls"):
        load_scene(path)
