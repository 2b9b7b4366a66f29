"""The scene loader refuses two cubes in one socket (issue 28: it accepted them, and the
simulator then had two bodies in one place); cubes side by side or one on another load."""

from __future__ import annotations

from pathlib import Path

import pytest

from armkit.scene import SceneError, load_scene

BOARD = """name = "t"
[[boards]]
name = "board"
origin_mm = [200.0, 0.0, 8.0]
rows = 2
cols = 2
pitch_mm = 45.0
socket_size_mm = 34.0
socket_depth_mm = 5.0
thickness_mm = 8.0
size_mm = [100.0, 100.0]
"""


def _cube(name: str, where: str) -> str:
    return f'[[cubes]]\nname = "{name}"\nsize_mm = 25.0\n{where}\n'


def _load(tmp_path: Path, *cubes: str) -> object:
    path = tmp_path / "t.toml"
    path.write_text(BOARD + "".join(cubes))
    return load_scene(path)


def test_two_cubes_in_one_socket_are_refused(tmp_path: Path) -> None:
    socket = 'socket = { board = "board", row = 0, col = 0 }'
    with pytest.raises(
        SceneError, match=r"field 'cubes\[1\]\.socket': blue would stand inside red"
    ):
        _load(tmp_path, _cube("red", socket), _cube("blue", socket))


def test_two_cubes_at_one_place_on_the_table_are_refused(tmp_path: Path) -> None:
    with pytest.raises(SceneError, match=r"green would stand inside red \(centres 10\.0 mm apart"):
        _load(
            tmp_path,
            _cube("red", "position_mm = [100.0, 100.0, 0.0]"),
            _cube("green", "position_mm = [110.0, 100.0, 0.0]"),
        )


def test_cubes_side_by_side_and_stacked_load(tmp_path: Path) -> None:
    scene = _load(
        tmp_path,
        _cube("red", 'socket = { board = "board", row = 0, col = 0 }'),
        _cube("green", 'socket = { board = "board", row = 0, col = 1 }'),
        _cube("blue", 'on = "red"'),
        _cube("a", "position_mm = [100.0, 100.0, 0.0]"),
        _cube("b", "position_mm = [125.0, 100.0, 0.0]"),  # touching, not inside
    )
    assert [c.name for c in scene.cubes] == ["red", "green", "blue", "a", "b"]  # type: ignore[attr-defined]
