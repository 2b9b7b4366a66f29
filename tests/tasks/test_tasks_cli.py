"""The scene and task commands: one line for every refusal, nothing moved, the
picture's path checked before anything else."""

from __future__ import annotations

from pathlib import Path

import pytest

from armkit.cli import main


def _where(state: Path, capsys: pytest.CaptureFixture[str]) -> str:
    assert main(["--port", str(state), "where"]) == 0
    return capsys.readouterr().out


def test_dry_run_prints_the_plan_and_moves_nothing(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    state = tmp_path / "omx.json"
    before = _where(state, capsys)
    assert (
        main(
            [
                "--port",
                str(state),
                "--scene",
                "board_001",
                "stack",
                "green",
                "red",
                "blue",
                "--dry-run",
            ]
        )
        == 0
    )
    out = capsys.readouterr().out
    assert out.startswith("stack green red blue (openmanipulator_x, scene board_001): 111 steps")
    assert "expected: blue at (220.0, 0.0, 53.0) mm" in out
    assert _where(state, capsys) == before


def test_a_task_runs_on_the_simulated_arm(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    state = tmp_path / "omx.json"
    assert main(["--port", str(state), "--scene", "board_001", "pick", "green"]) == 0
    out = capsys.readouterr().out
    assert "9/9  pick green from the top: up 3/3" in out
    assert "x 220.0 y 0.0 z 45.5 mm, pitch -90.0 deg" in _where(state, capsys)


@pytest.mark.parametrize(
    ("args", "says"),
    [
        (
            ["--scene", "board_001", "move-item", "red", "--xyz", "400", "0", "0"],
            "move red: cannot put red at (400.0, 0.0, 0.0) mm",
        ),
        (
            ["--scene", "board_001", "pick", "purple"],
            "no cube 'purple'; its cubes: red, green, blue",
        ),
        (["pick", "red"], "'pick' needs a scene: give --scene FILE|NAME"),
        (["--scene", "nosuch", "pick", "red"], "unknown scene 'nosuch'"),
        (["--scene", "board_001", "place", "red"], "needs TO"),
        (
            ["--scene", "board_001", "pick", "red", "--clearance", "10"],
            "--clearance: must be 30..500 mm",
        ),
        (["--scene", "board_001", "stack", "red"], "two or more different cubes"),
        (["--scene", "board_001", "pick", "red", "--pitch", "nan"], "--pitch: must be -90..90 deg"),
    ],
)
def test_refusals_are_one_line_and_move_nothing(
    args: list[str], says: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    state = tmp_path / "omx.json"
    before = _where(state, capsys)
    assert main(["--port", str(state), *args]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("armkit: error: ") and says in err[0]
    assert _where(state, capsys) == before


def test_scene_show_and_list(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    picture = tmp_path / "top.png"
    assert main(["--scene", "board_001", "scene", "show", "-o", str(picture)]) == 0
    out = capsys.readouterr().out
    assert "red: 25.0 mm at (220.0, 45.0, 3.0) mm, yaw 0.0 deg, +z up, in board[0, 0]" in out
    assert picture.stat().st_size > 10_000 and picture.read_bytes()[:4] == b"\x89PNG"
    assert main(["scene", "list"]) == 0
    assert "board_001" in capsys.readouterr().out


@pytest.mark.parametrize(
    ("name", "says"), [("nodir/top.png", "does not exist"), ("top.gif", "must end in one of .png")]
)
def test_scene_show_checks_the_picture_path_first(
    name: str, says: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    assert main(["--scene", "board_001", "scene", "show", "-o", str(tmp_path / name)]) == 2
    captured = capsys.readouterr()
    assert captured.out == "" and says in captured.err
