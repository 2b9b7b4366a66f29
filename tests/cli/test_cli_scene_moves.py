"""With ``--scene``, a plain move is checked against the scene's objects as a task is:
``armkit --scene board_001 move 220 0 20 --pitch -90`` put the gripper 8 mm into the
green cube (the Arm of the motion commands was opened without the scene). The check
is the one ``Arm`` makes (``scene.move_refusal``), against the objects where a simulated
arm kept between commands (``--port FILE``) has them; a refused move moves nothing."""

from __future__ import annotations

from pathlib import Path

import pytest

from armkit.cli import main


def test_a_move_into_a_cube_is_refused_and_nothing_moves(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    kept = ["--scene", "board_001", "--port", str(tmp_path / "arm.json")]
    assert main([*kept, "where"]) == 0
    before = capsys.readouterr().out
    assert main([*kept, "move", "220", "0", "20", "--pitch", "-90"]) == 2
    err = capsys.readouterr().err
    assert err == (
        "armkit: error: move refused: there, the gripper would be 8.0 mm into the green; "
        "choose a higher point or another way\n"
    )
    assert main([*kept, "where"]) == 0
    assert capsys.readouterr().out == before


def test_moves_are_checked_against_the_cubes_where_they_are_now(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    kept = ["--scene", "board_001", "--port", str(tmp_path / "arm.json")]
    assert main([*kept, "pick", "red"]) == 0
    assert main([*kept, "place", "red", "--xyz", "180", "-100", "0"]) == 0
    capsys.readouterr()
    assert main([*kept, "move", "180", "-100", "20", "--pitch", "-90"]) == 2  # red is there
    assert "5.0 mm into the red" in capsys.readouterr().err
    assert main([*kept, "move", "220", "-45", "20", "--pitch", "-90"]) == 0  # where it stood


def test_without_a_scene_only_the_table_and_the_base_are_checked(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    port = ["--port", str(tmp_path / "arm.json")]
    assert main([*port, "move", "220", "0", "20", "--pitch", "-90"]) == 0
    assert main([*port, "move", "0", "0", "5"]) == 2
    assert "into the base column" in capsys.readouterr().err
