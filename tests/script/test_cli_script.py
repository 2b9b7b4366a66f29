"""``armkit check``, ``armkit run`` (and ``--dry-run``, ``--repeat``) through ``main``."""

from __future__ import annotations

import math
import re
from pathlib import Path

import pytest

from armkit.cli import main

GOOD = """\
# a dip above the table
pose above = xyz 180 0 80 pitch -90
move above
line 180 0 40
move above
"""
BAD = """\
pose above = xyz 180 0 80 pitch -90
mvoe above
turn waist by 10s
move xyz 600 0 0
"""


def _script(tmp_path: Path, text: str, name: str = "job.arm") -> str:
    path = tmp_path / name
    path.write_text(text)
    return str(path)


def test_check_lists_every_error_and_moves_nothing(
    tmp_path: Path, config_dir: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    path = _script(tmp_path, BAD)
    assert main(["check", path]) == 2
    err = capsys.readouterr().err.splitlines()
    heads = [line for line in err if ": error: " in line and not line.startswith("armkit:")]
    assert [h.split(": error: ")[0] for h in heads] == [
        f"{path}:2:1",
        f"{path}:3:15",
        f"{path}:4:1",
    ]
    assert (
        err[-1]
        == f"armkit: error: {path}:2:1: unknown command 'mvoe'; did you mean 'move'? (3 errors in {path}; nothing moved)"
    )
    assert not config_dir.exists() or not any(config_dir.iterdir())


def test_run_refuses_a_bad_script_before_moving(
    tmp_path: Path, config_dir: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    assert main(["run", _script(tmp_path, BAD)]) == 2
    assert "nothing moved" in capsys.readouterr().err
    assert not (config_dir / "sim_openmanipulator_x.json").exists()


def test_check_ok_and_plan(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    path = _script(tmp_path, GOOD)
    assert main(["check", path, "--plan"]) == 0
    out = capsys.readouterr().out
    assert f"{path}: ok for openmanipulator_x: 3 steps" in out
    assert "line 180 0 40" in out and "total " in out


def test_dry_run_prints_the_plan_and_moves_nothing(
    tmp_path: Path, config_dir: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    assert main(["run", _script(tmp_path, GOOD), "--dry-run", "--repeat", "3"]) == 0
    out = capsys.readouterr().out
    assert "dry run: nothing moved" in out and "[1/3]" in out
    assert not (config_dir / "sim_openmanipulator_x.json").exists()


def test_run_moves_and_the_next_command_sees_it(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    assert main(["run", _script(tmp_path, GOOD)]) == 0
    out = capsys.readouterr().out
    assert "    3  move above" in out and "done:" in out
    assert main(["where"]) == 0
    # a new process reads the simulated XM430s' ticks: within a tick of the pose (0.5 mm)
    found = re.search(r"x (\S+) y (\S+) z (\S+) mm", capsys.readouterr().out)
    assert found is not None
    assert math.dist([float(v) for v in found.groups()], (180, 0, 80)) < 0.5


def test_the_script_chooses_the_arm_unless_told_otherwise(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    path = _script(tmp_path, "arm lynx6\nturn base by 10\n")
    assert main(["check", path]) == 0
    assert "ok for lynx6" in capsys.readouterr().out
    assert main(["--arm", "al5d", "check", path]) == 2
    assert "the script chooses arm lynx6 but --arm says al5d" in capsys.readouterr().err


def test_repeat_must_be_positive_and_files_must_exist(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    assert main(["run", _script(tmp_path, GOOD), "--repeat", "0"]) == 2
    assert "--repeat must be 1..10000, got 0" in capsys.readouterr().err
    assert main(["check", str(tmp_path / "none.arm")]) == 2
    assert "cannot read the script" in capsys.readouterr().err
