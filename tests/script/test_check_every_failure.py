"""Issue 28's smaller items about ``armkit check``: it reports every failing line where
the lines after it can still be checked (a refused line changes nothing, so the check
goes on from the state it would have left unchanged), and it times a script that draws
or plays as it runs (it gave 11-12 % of the run's time)."""

from __future__ import annotations

import warnings
from pathlib import Path

import pytest

from armkit import Arm
from armkit.script import Source, check_source, run_source

HERE = Path(__file__).resolve().parents[2] / "examples" / "scripts"


def _errors(text: str) -> list[tuple[int, str]]:
    result = check_source(Source("job.arm", text))
    return [(d.loc.line, d.message) for d in result.diagnostics if d.severity == "error"]


def test_every_failing_task_is_reported() -> None:
    # line 3 is refused, so red is still held at line 4, whose socket is taken too;
    # line 5 is refused as it would be after line 4
    text = "scene board_001\npick red\nplace board[0,1]\nplace board[0,2]\nmove 200 0 -20\n"
    found = _errors(text)
    assert [line for line, _ in found] == [3, 4, 5]
    assert "board[0, 2] is taken by blue" in found[1][1]


def test_after_a_failing_line_the_tasks_are_planned_from_where_it_left_things() -> None:
    # red stays in the gripper after line 3's refusal, goes to the table at line 4, and
    # blue on it (lines 5-6): so red is under blue at line 7, which only a check that
    # goes on planning after line 3 knows
    text = (
        "scene board_001\npick red\nplace board[0,1]\nplace xyz 180 -100 0\n"
        "pick blue\nplace red\npick red\n"
    )
    found = _errors(text)
    assert [line for line, _ in found] == [3, 7]
    assert "under blue" in found[1][1]


@pytest.mark.parametrize(
    ("scene", "job"),
    [
        ("drawing", "draw square.svg on A5"),
        ("xylophone", "play ode.txt tempo 90%"),
    ],
)
def test_a_script_that_draws_or_plays_is_timed_as_it_runs(scene: str, job: str) -> None:
    text = f"arm openmanipulator_x\nscene {scene}\nmove 200 0 150\n{job}\nhome\n"
    with warnings.catch_warnings(), Arm("openmanipulator_x", "sim") as arm:
        warnings.simplefilter("ignore")
        checked = check_source(Source(str(HERE / "job.arm"), text), arm=arm)
        t0 = arm.clock.now()
        run_source(arm, Source(str(HERE / "job.arm"), text))
        took = arm.clock.now() - t0
    assert checked.timetable.unknown == 0
    assert checked.timetable.total == pytest.approx(took, rel=0.01)
