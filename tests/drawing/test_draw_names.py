"""Which sheet and pen: a scene with none says so and names one that has them."""

from __future__ import annotations

from pathlib import Path

import pytest

from armkit.cli import main
from armkit.drawing import DrawingError
from armkit.drawing._job import find_pen, find_sheet
from armkit.scene import load_scene


def test_a_scene_without_a_sheet_suggests_the_drawing_scene(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    path = tmp_path / "a.gcode"
    path.write_text("G21\nG1 Z-1\nG1 X10\n")
    assert main(["--scene", "board_001", "draw", "gcode", str(path), "--dry-run"]) == 2
    assert capsys.readouterr().err == (
        "armkit: error: scene board_001 has no sheet of paper to draw on; draw in a scene "
        "with a sheet and a pen, such as the shipped one: --scene drawing\n"
    )
    board = load_scene("board_001")
    with pytest.raises(DrawingError, match=r"^scene board_001 has no pen to draw with; "):
        find_pen(board, None)
    with pytest.raises(DrawingError, match=r"no sheet of paper"):
        find_sheet(board, "A5")
    with pytest.raises(DrawingError, match=r"^no sheet 'A4' in scene drawing; its sheets: A5$"):
        find_sheet(load_scene("drawing"), "A4")
