"""Scene files: the shipped scenes, the geometry of boards, sheets and instruments,
and every mistake named by file and field."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from armkit import ModelError
from armkit.scene import (
    Board,
    Drum,
    SceneError,
    Sheet,
    Xylophone,
    load_scene,
    shipped_scenes,
)

BOARD = """
name = "t"
[[boards]]
name = "b"
origin_mm = [200.0, 0.0, 8.0]
rows = 2
cols = 3
pitch_mm = 40.0
socket_size_mm = 30.0
socket_depth_mm = 5.0
thickness_mm = 8.0
size_mm = [100.0, 140.0]
[[cubes]]
name = "c"
size_mm = 25.0
socket = { board = "b", row = 1, col = 2 }
"""


def _write(tmp_path: Path, text: str) -> Path:
    path = tmp_path / "scene.toml"
    path.write_text(text)
    return path


def test_shipped_scenes_load() -> None:
    assert {"empty", "board_001", "search_002"} <= set(shipped_scenes())
    assert load_scene("empty").names() == ()
    board = load_scene("board_001")
    assert [c.name for c in board.cubes] == ["red", "green", "blue"]
    assert all(c.size == pytest.approx(0.025) for c in board.cubes)  # 001's cubes
    search = load_scene("search_002")
    assert search.container("bin").floor_z == pytest.approx(0.003)


def test_board_sockets_and_cubes_in_them(tmp_path: Path) -> None:
    scene = load_scene(_write(tmp_path, BOARD))
    b = scene.board("b")
    assert b.socket(0, 0) * 1000 == pytest.approx([180.0, -40.0, 3.0])
    assert b.socket(1, 2) * 1000 == pytest.approx([220.0, 40.0, 3.0])
    assert scene.cube("c").position == pytest.approx(b.socket(1, 2))
    assert b.socket_at(b.socket(1, 2) + np.array([0.01, -0.01, 0])) == (1, 2)
    assert b.socket_at(b.socket(1, 2) + np.array([0.018, 0, 0])) is None  # on the wall
    with pytest.raises(ValueError, match=r"rows 0..1, cols 0..2; got \(2, 0\)"):
        b.socket(2, 0)


@settings(max_examples=60, derandomize=True, deadline=None)
@given(
    st.integers(1, 6),
    st.integers(1, 6),
    st.floats(0.02, 0.08),
    st.floats(-math.pi, math.pi),
)
def test_sockets_are_a_grid_on_the_board(rows: int, cols: int, pitch: float, yaw: float) -> None:
    size = (rows * pitch + 0.01, cols * pitch + 0.01)
    b = Board(
        "b", np.array([0.2, 0.05, 0.01]), yaw, rows, cols, pitch, 0.004, 0.01, size, pitch * 0.8
    )
    centres = np.array([b.socket(r, c) for r in range(rows) for c in range(cols)])
    local = (centres[:, :2] - b.origin[:2]) @ np.array(
        [[math.cos(yaw), -math.sin(yaw)], [math.sin(yaw), math.cos(yaw)]]
    )
    assert np.all(np.abs(local) <= np.array(size) / 2)
    assert centres[:, 2] == pytest.approx(0.006)
    if cols > 1:
        assert np.linalg.norm(b.socket(0, 1) - b.socket(0, 0)) == pytest.approx(pitch)
    assert np.mean(centres[:, :2], axis=0) == pytest.approx(b.origin[:2])


@pytest.mark.parametrize(
    ("change", "field", "why"),
    [
        (("size_mm = 25.0", "size_mm = -25.0"), "cubes[0].size_mm", "> 0"),
        (("rows = 2", "rows = 2\ncolour = 3"), "boards[0].colour", "unknown key"),
        (("row = 1, col = 2", "row = 2, col = 2"), "cubes[0].socket.row", "0..1"),
        (
            ("socket_size_mm = 30.0", "socket_size_mm = 45.0"),
            "boards[0].socket_size_mm",
            "< pitch_mm",
        ),
        (
            ("socket_depth_mm = 5.0", "socket_depth_mm = 9.0"),
            "boards[0].socket_depth_mm",
            "thickness",
        ),
        (
            ("size_mm = [100.0, 140.0]", "size_mm = [60.0, 140.0]"),
            "boards[0].size_mm[0]",
            "hold the sockets",
        ),
        (
            ("origin_mm = [200.0, 0.0, 8.0]", "origin_mm = [200.0, 0.0]"),
            "boards[0].origin_mm",
            "3 numbers",
        ),
        (('name = "c"', 'name = "b"'), "", "used twice"),
        (('name = "c"', 'name = "../c"'), "cubes[0].name", "letters"),
        (
            ('socket = { board = "b", row = 1, col = 2 }', "position_mm = [300.0, 0.0, 20.0]"),
            "cubes[0].position_mm",
            "rest on",
        ),
        (("pitch_mm = 40.0", "pitch_mm = nan"), "boards[0].pitch_mm", "got nan"),
    ],
)
def test_mistakes_name_file_and_field(
    tmp_path: Path, change: tuple[str, str], field: str, why: str
) -> None:
    path = _write(tmp_path, BOARD.replace(*change, 1))
    with pytest.raises(SceneError, match=why) as info:
        load_scene(path)
    assert str(path) in str(info.value)
    assert f"field '{field}'" in str(info.value) or not field
    assert isinstance(info.value, ModelError) and isinstance(info.value, ValueError)


def test_unreadable_files(tmp_path: Path) -> None:
    with pytest.raises(SceneError, match="no such scene file"):
        load_scene(tmp_path / "none.toml")
    with pytest.raises(SceneError, match=r"unknown scene 'nope'.*board_001"):
        load_scene("nope")
    bad = tmp_path / "bad.toml"
    bad.write_bytes(b'name = "\xff\xfe"\n')
    with pytest.raises(SceneError, match=r"bad.toml:1:9: not UTF-8 text \(byte ff\)"):
        load_scene(bad)
    bad.write_text("name = [")
    with pytest.raises(SceneError, match=r"bad.toml:1:9: not valid TOML"):
        load_scene(bad)


def test_cubes_stack_on_cubes_and_base_pose(tmp_path: Path) -> None:
    text = (
        BOARD
        + '[[cubes]]\nname = "d"\nsize_mm = 25.0\non = "c"\n[base]\nxyz_mm = [10.0, 20.0, 0.0]\nyaw_deg = 90.0\n'
    )
    scene = load_scene(_write(tmp_path, text))
    assert scene.cube("d").position * 1000 == pytest.approx([220.0, 40.0, 28.0])
    assert scene.to_base(np.array([10.0, 21.0, 0.0]) / 1000) * 1000 == pytest.approx(
        [1.0, 0.0, 0.0], abs=1e-9
    )
    p = np.array([0.1, 0.2, 0.3])
    assert scene.to_scene(scene.to_base(p)) == pytest.approx(p)


def test_sheets_any_plane_and_presets(tmp_path: Path) -> None:
    text = """name = "d"
[[sheets]]
name = "a4"
size = "A4"
origin_mm = [100.0, -105.0, 0.0]
[[sheets]]
name = "wall"
size = "A6"
landscape = true
origin_mm = [300.0, 0.0, 50.0]
u = [0.0, 1.0, 0.0]
v = [0.0, 0.0, 1.0]
"""
    scene = load_scene(_write(tmp_path, text))
    a4, wall = scene.sheets
    assert (a4.width, a4.height) == pytest.approx((0.210, 0.297))
    assert a4.normal == pytest.approx([0, 0, 1])
    assert a4.to_world([[0.21, 0.297]]) == pytest.approx(np.array([[0.31, 0.192, 0.0]]))
    assert (wall.width, wall.height) == pytest.approx((0.148, 0.105))
    assert wall.normal == pytest.approx([1, 0, 0])
    assert wall.to_world([[0.1, 0.05]]) == pytest.approx(np.array([[0.3, 0.1, 0.1]]))
    assert wall.contains(np.array([[0.1, 0.05], [0.2, 0.0]])).tolist() == [True, False]
    with pytest.raises(SceneError, match="right angles"):
        load_scene(_write(tmp_path, text.replace("v = [0.0, 0.0, 1.0]", "v = [0.0, 1.0, 1.0]")))


def test_instruments() -> None:
    xylo = Xylophone.interpolated(
        "x", np.array([0.2, -0.1, 0.05]), np.array([0.2, 0.1, 0.05]), 72, 8, (0.06, 0.02)
    )
    assert list(xylo.notes) == list(range(72, 80))
    assert xylo.bar_top(72) == pytest.approx([0.2, -0.1, 0.05])
    assert xylo.bar_top(79) == pytest.approx([0.2, 0.1, 0.05])
    assert xylo.bar_top(75)[1] == pytest.approx(-0.1 + 3 / 7 * 0.2)
    with pytest.raises(ValueError, match=r"no note 80 \(G#5\); it plays C5..G5"):
        xylo.bar_top(80)
    drum = Drum("snare", np.array([0.15, 0.15, 0.0]), 0.06, 0.08, 38)
    assert drum.head == pytest.approx([0.15, 0.15, 0.08])
    sheet = Sheet("s", np.zeros(3), np.array([1.0, 0, 0]), np.array([0, 1.0, 0]), 0.1, 0.1)
    with pytest.raises(ValueError, match=r"shape \(N, 2\)"):
        sheet.to_world([1.0, 2.0])


def test_a_shipped_file_name_not_found_here_is_the_shipped_scene(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """``--scene xylophone.toml`` means the shipped scene unless a file of that name is here."""
    monkeypatch.chdir(tmp_path)
    assert load_scene("xylophone.toml").name == "xylophone"
    (tmp_path / "xylophone.toml").write_text('name = "mine"\n', encoding="utf-8")
    assert load_scene("xylophone.toml").name == "mine"
    with pytest.raises(SceneError, match="no such scene file"):
        load_scene("sub/xylophone.toml")


def test_a_directory_is_no_scene_file(tmp_path: Path) -> None:
    with pytest.raises(SceneError, match=r": is a directory; give a .toml file$"):
        load_scene(tmp_path)
