"""Every job form of the scripts page (docs/scripts.md) RUNS on the simulator, not only
checks: the job table once passed argument names the tasks did not take ('pick red'
checked, then 'armkit run' died in a TypeError), which tests that only checked, or
ran the example scripts (no pick, no place), did not see. A job argument its
function would refuse is refused by the check, with file:line:col, before anything
moves."""

from __future__ import annotations

import re
import shutil
from pathlib import Path

import pytest

from armkit.cli import main
from armkit.script import check_file
from armkit.script._jobs import JOBS
from armkit.script._session import Session

ROOT = Path(__file__).parents[2]
EXAMPLES = ROOT / "examples" / "scripts"

# each documented job row -> scripts that run its forms (beyond examples/scripts/1*.arm)
FORMS: dict[str, list[str]] = {
    "pick CUBE / place WHERE": [
        "scene board_001\npick red\nplace board[0,0]",
        "scene board_001\npick red\nplace board[ 0 , 0 ]",
        "scene board_001\npick red\nplace green",
        "scene board_001\npick red\nplace xyz 180 -100 0",
        "scene board_001\npose spot = xyz 180 -100 0\npick red\nplace spot",
        "scene board_001\nrepeat 2\n  pick red\n  place board[0,0]\nend",
    ],
    "move-item WHAT to WHERE": ["scene board_001\nmove-item red to xyz 180 -100 0"],
    "rotate-cube CUBE [forward|backward]": [
        "scene board_001\nrotate-cube red",
        "scene board_001\nrotate-cube red backward",
    ],
    "stack CUBE CUBE ...": ["scene board_001\nstack green blue"],
    "search [from A] [to B] [step S] [into CONTAINER]": [
        "arm lynx6\nscene search_002\nsearch",
    ],
    "draw FILE.svg|.gcode [on SHEET] [with PEN]": [
        "scene drawing\ndraw square.svg on A5 with pen",
    ],
    "play FILE.mid|.rtttl|.txt [on INSTRUMENT] [tempo P%] [transpose N]": [
        "scene xylophone\nplay ode.txt on xylophone tempo 90% transpose 0",
    ],
}
CASES = [(row, text) for row, texts in FORMS.items() for text in texts]


def _documented_job_rows() -> list[str]:
    """The first column of the scripts page's jobs table, as written (backticks dropped)."""
    text = (ROOT / "docs" / "scripts.md").read_text(encoding="utf-8")
    table = text.split("| job | arguments |", 1)[1].split("\n\n", 1)[0]
    rows = [re.split(r"(?<!\\)\|", line)[1].strip() for line in table.splitlines()[2:]]
    return [row.replace("`", "").replace("\\|", "|") for row in rows]


def test_every_documented_job_row_has_forms_that_run() -> None:
    assert sorted(_documented_job_rows()) == sorted(FORMS)
    written = {re.split(r"\s", text.splitlines()[-1].strip())[0] for _, text in CASES}
    assert set(JOBS) <= written | {"place", "pick"}


def _script(tmp_path: Path, text: str) -> Path:
    for name in ("square.svg", "ode.txt"):
        shutil.copy(EXAMPLES / name, tmp_path / name)
    body = text if text.startswith("arm ") else "arm openmanipulator_x\n" + text
    path = tmp_path / "job.arm"
    path.write_text(body + "\n", encoding="utf-8")
    return path


@pytest.mark.parametrize(("row", "text"), CASES, ids=[t.replace("\n", "; ") for _, t in CASES])
def test_every_job_form_runs_on_the_simulator(
    row: str, text: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    path = _script(tmp_path, text)
    code = main(["run", str(path)])
    out, err = capsys.readouterr()
    assert code == 0, err
    assert f"done: {path}" in out and "Traceback" not in err


def test_pick_and_place_in_the_shell(tmp_path: Path) -> None:
    from armkit import Arm
    from armkit.script._ast import Loc
    from armkit.script._check import load_scene_info

    scene = load_scene_info("board_001", tmp_path, Loc(1, 1), [])
    with Arm("openmanipulator_x") as arm:
        s = Session(arm, scene=scene, base_dir=tmp_path)
        assert s.handle("pick red").text == ""
        assert "no cube is picked" not in s.handle("place board[0,0]").text
        reply = s.handle("place board[0,0]")  # nothing held now
        assert reply.text.startswith(
            "<shell>:3:1: error: place puts down the cube the script picked"
        )


@pytest.mark.parametrize(
    ("scene", "line", "col", "message"),
    [
        ("xylophone", "play ode.txt tempo 900%", 20, "tempo must be a factor 0.1..4"),
        ("xylophone", "play ode.txt tempo 0%", 20, "tempo must be a factor 0.1..4"),
        ("xylophone", "play ode.txt tempo -50%", 20, "tempo must be a factor 0.1..4"),
        ("xylophone", "play ode.txt transpose 100", 24, "transpose must be a whole number"),
        ("xylophone", "play ode.txt on mallet", 17, "has no instrument 'mallet'"),
        ("board_001", "stack red", 7, "stack needs two or more different cubes"),
        ("board_001", "stack red red", 7, "stack needs two or more different cubes"),
        ("board_001", "stack green blue on red", 18, "stack takes no 'on WHERE'"),
        ("board_001", "pick xyz 200 0 50", 6, "pick takes a cube of the scene by its name"),
        ("board_001", "pick board", 6, "has no cube 'board'"),
        ("board_001", "place board[0,1]", 1, "write 'pick CUBE' before it"),
        ("board_001", "move-item red to board[9,1]", 18, "rows 0..2"),
        ("board_001", "rotate-cube board", 13, "has no cube 'board'"),
        ("search_002", "search step 0", 13, "0 < step <= |to - from|"),
        ("search_002", "search step -5", 13, "0 < step <= |to - from|"),
        ("search_002", "search from 200 to 300", 13, "from and to 0..180 deg"),
        ("search_002", "search into rest", 13, "container"),
        ("drawing", "draw square.svg on A4", 20, "sheet"),
    ],
)
def test_a_job_argument_its_function_refuses_is_a_check_error_and_nothing_moves(
    scene: str,
    line: str,
    col: int,
    message: str,
    tmp_path: Path,
    capsys: pytest.CaptureFixture[str],
) -> None:
    arm = "lynx6" if scene == "search_002" else "openmanipulator_x"
    path = _script(tmp_path, f"arm {arm}\nscene {scene}\nmove xyz 200 0 100\n{line}")
    result = check_file(path)
    errors = [d for d in result.diagnostics if d.severity == "error"]
    assert len(errors) == 1, errors
    assert (errors[0].loc.line, errors[0].loc.col) == (4, col)
    assert message in errors[0].message
    assert main(["run", str(path)]) != 0  # refused whole: the move on line 3 is not made
    out, err = capsys.readouterr()
    assert f"job.arm:4:{col}: " in err and "nothing moved" in err
    assert "Traceback" not in err and "3  move" not in out


def test_shell_positions_count_every_line_typed(tmp_path: Path) -> None:
    from armkit import Arm

    with Arm("openmanipulator_x") as arm:
        s = Session(arm, base_dir=tmp_path)
        assert s.handle("where").text.startswith("gripper at")
        assert s.handle("").text == ""
        assert s.handle("mvoe 200 0 100").text.startswith("<shell>:3:1: error: unknown command")
        assert s.handle("repeat 2").more
        assert s.handle("  mvoe 1 2 3").more
        assert s.handle("end").text.startswith("<shell>:5:3: error: unknown command")
