"""A simulated arm kept between commands keeps its cubes for every command and script.

With ``--scene``, a plain move is checked against the scene's objects as a task is:
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
    assert main([*kept, "grip", "20"]) == 0  # closed: open jaws would pass over the cube
    capsys.readouterr()
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
    assert main([*kept, "grip", "20"]) == 0
    capsys.readouterr()
    assert main([*kept, "move", "180", "-100", "20", "--pitch", "-90"]) == 2  # red is there
    assert "5.0 mm into the red" in capsys.readouterr().err
    assert main([*kept, "move", "220", "45", "60", "--pitch", "-90"]) == 0  # over green
    assert main([*kept, "move", "220", "45", "20", "--pitch", "-90"]) == 0  # where it stood


def test_without_a_scene_only_the_table_and_the_base_are_checked(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    port = ["--port", str(tmp_path / "arm.json")]
    assert main([*port, "move", "220", "0", "20", "--pitch", "-90"]) == 0
    assert main([*port, "move", "0", "0", "5"]) == 2
    assert "into the base column" in capsys.readouterr().err


def _where(kept: list[str], capsys: pytest.CaptureFixture[str]) -> str:
    capsys.readouterr()
    assert main([*kept, "where"]) == 0
    return capsys.readouterr().out


def test_place_with_nothing_in_the_gripper_is_refused_before_moving(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    # it ran all its steps, then found the cube had not come along
    kept = ["--scene", "board_001", "--port", str(tmp_path / "arm.json")]
    before = _where(kept, capsys)
    assert main([*kept, "place", "red", "--xyz", "150", "-150", "0"]) == 2
    assert "place red: the gripper holds nothing; pick red up first" in capsys.readouterr().err
    assert _where(kept, capsys) == before


def test_scripts_and_commands_share_the_kept_cubes(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    # scripts opened the arm without the scene's kept objects: red picked by a command
    # was picked again from its socket by a script
    port = str(tmp_path / "arm.json")
    kept = ["--scene", "board_001", "--port", port]
    assert main([*kept, "pick", "red"]) == 0
    script = tmp_path / "s.arm"
    script.write_text("scene board_001\nmove 200 0 150\npick red\n")
    before = _where(kept, capsys)
    assert main(["--port", port, "run", str(script)]) == 2
    assert "s.arm:3:1: error: pick red: the gripper holds red" in capsys.readouterr().err
    assert _where(kept, capsys) == before  # refused by the check: nothing moved
    script.write_text("scene board_001\nplace xyz 180 -100 0\nhome\n")
    assert main(["--port", port, "run", "-q", str(script)]) == 0
    assert main([*kept, "grip", "20"]) == 0
    assert main([*kept, "move", "180", "-100", "20", "--pitch", "-90"]) == 2  # red is there
    assert "into the red" in capsys.readouterr().err


def test_scene_show_shows_the_cubes_as_kept(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    # it printed the scene file: red 'in board[0, 0]' while the gripper held it
    kept = ["--scene", "board_001", "--port", str(tmp_path / "arm.json")]
    assert main([*kept, "pick", "red"]) == 0
    capsys.readouterr()
    assert main([*kept, "scene", "show", "--no-picture"]) == 0
    out = capsys.readouterr().out
    assert out.startswith("as kept for the simulated openmanipulator_x (")
    assert out.endswith("in the gripper:\n  red\n") and "board[0, 0]" not in out
    assert main([*kept, "place", "red", "--xyz", "180", "-100", "0"]) == 0
    capsys.readouterr()
    assert main([*kept, "scene", "show", "--no-picture"]) == 0
    assert "red: 25.0 mm at (179.8, -100.0, 0.0) mm" in capsys.readouterr().out


def test_open_jaws_pass_over_a_cube_to_take_it_by_hand_and_lift_off_it(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    # after moves were checked against the cubes, lowering open jaws over green (as pick
    # does) was refused, and so was every move after letting a cube go by hand
    kept = ["--scene", "board_001", "--port", str(tmp_path / "arm.json")]
    assert main([*kept, "grip", "70"]) == 0
    assert main([*kept, "move", "220", "0", "60", "--pitch", "-90"]) == 0
    assert main([*kept, "move", "220", "0", "16", "--pitch", "-90"]) == 0  # jaws around green
    assert main([*kept, "grip", "20"]) == 0
    capsys.readouterr()
    assert main([*kept, "scene", "show", "--no-picture"]) == 0
    assert capsys.readouterr().out.endswith("in the gripper:\n  green\n")
    assert main([*kept, "grip", "45"]) == 0  # let go: back in its socket
    assert main([*kept, "move", "220", "0", "60", "--pitch", "-90"]) == 0  # lifted off it
    assert main([*kept, "grip", "20"]) == 0  # closed jaws: green is in the way again
    capsys.readouterr()
    assert main([*kept, "move", "220", "0", "16", "--pitch", "-90"]) == 2
    assert "into the green" in capsys.readouterr().err
