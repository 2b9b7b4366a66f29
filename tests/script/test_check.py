"""The whole-script check: every mistake with its line and column, nothing else."""

from __future__ import annotations

import math

import numpy as np
import pytest

from armkit.arm import Start
from armkit.model import load_model
from armkit.script import ScriptCheckError, Source, _walk, check_source
from budget import cases

MISTAKES = """\
pose above = xyz 180 0 80 pitch -90
mvoe above
move abve
turn wirst by 10
wait 2deg
grip 300
move xyz 900 0 50
move xyz 180 0 -30 pitch -90
repeat 2
  move above
"""


def _errors(text: str, **options: object) -> list[tuple[int, int, str]]:
    result = check_source(Source("job.arm", text), **options)  # type: ignore[arg-type]
    return [(d.loc.line, d.loc.col, d.message) for d in result.diagnostics if d.severity == "error"]


def test_several_mistakes_each_with_line_and_column() -> None:
    errors = _errors(MISTAKES)
    where = [(line, col) for line, col, _ in errors]
    assert where == [(2, 1), (3, 6), (4, 6), (5, 6), (6, 6), (7, 1), (8, 1), (9, 1)]
    text = " | ".join(m for _, _, m in errors)
    assert "unknown command 'mvoe'; did you mean 'move'?" in text
    assert "undefined pose 'abve'" in text and "did you mean 'above'?" in text
    assert "no joint 'wirst'" in text and "did you mean 'wrist'?" in text
    assert "2deg is an angle, but a time is needed" in text
    assert "grip 300 mm is outside openmanipulator_x's 20..75 mm" in text
    assert "cannot reach (900.0, 0.0, 50.0) mm" in text
    assert "30.0 mm into the table" in text  # as Arm refuses it (scene.move_refusal)
    assert "this repeat has no 'end'" in text


def test_report_shows_the_line_and_a_caret() -> None:
    result = check_source(Source("job.arm", MISTAKES))
    report = ScriptCheckError(result.program.source, result.diagnostics).report()
    lines = report.splitlines()
    k = lines.index(
        "job.arm:3:6: error: undefined pose 'abve' (define it with 'pose abve = ...'); did you mean 'above'?"
    )
    assert lines[k + 1] == "    move abve"
    assert lines[k + 2] == "         ^"
    with pytest.raises(
        ScriptCheckError,
        match=r"job.arm:2:1: unknown command 'mvoe'.*\(8 errors in job.arm; nothing moved\)",
    ):
        result.raise_if_failed()


def test_a_good_script_has_a_plan_and_a_time() -> None:
    text = "pose above = xyz 180 0 80 pitch -90\nmove above\nline 180 0 40\nwait 2s\nhome\n"
    result = check_source(Source("ok.arm", text))
    assert result.ok and result.diagnostics == []
    durations = [s.duration for s in result.timetable.rows]
    assert len(durations) == 4 and durations[2] == pytest.approx(2.0)  # a pose takes no time
    assert all(d is not None and d >= 0 for d in durations)
    assert result.timetable.total == pytest.approx(sum(d for d in durations if d is not None))
    assert result.timetable.rows[-1].q == pytest.approx(load_model("openmanipulator_x").home)


def test_structure_errors_are_reported_once_without_cascades() -> None:
    text = "end\ndefine a(x, x)\n  move x\nend\nrepeat 3x\n  home\nend\nrepeat\nend\na 1\n"
    errors = _errors(text)
    assert [(line, m.split(";")[0]) for line, _, m in errors] == [
        (1, "'end' without a 'repeat' or 'define' to close"),
        (2, "parameter 'x' is named twice"),
        (5, "a count takes no unit, got 3x"),
        (8, "expected a repeat count here"),
    ]


def test_headers_come_first_and_once() -> None:
    errors = _errors("arm openmanipulator_x\nhome\narm lynx6\ndriver sim\n")
    assert [line for line, _, _ in errors] == [3, 4]
    assert _errors("arm openmanipulatr_x\nhome\n")[0][2].startswith(
        "unknown arm 'openmanipulatr_x'; did you mean 'openmanipulator_x'?"
    )
    assert "did you mean 'ssc32'" in _errors("driver ssc3\n")[0][2]


def test_the_arm_line_must_match_the_arm_it_runs_on() -> None:
    errors = _errors("arm lynx6\nhome\n", model=load_model("openmanipulator_x"))
    assert errors[0][:2] == (1, 5) and "for lynx6, but the arm is openmanipulator_x" in errors[0][2]


def test_joint_limits_and_joint_counts() -> None:
    text = "joints 0 -60 20\nturn waist 190\njoints 0 -60 20 40 0\nhome\nturn wrist by -200deg\n"
    errors = _errors(text)
    assert [line for line, _, _ in errors] == [1, 2, 3, 5]
    assert "has 4 joints (waist, shoulder, elbow, wrist), got 3 angles" in errors[0][2]
    assert "waist 190.00 deg is outside its limits -180.00..180.00 deg" in errors[1][2]


def test_straight_line_checked_point_by_point() -> None:
    text = "move xyz 150 0 60 pitch -90\nline xyz 150 0 60 pitch 0\nline xyz 420 0 60 pitch -90\n"
    errors = _errors(text)
    assert [line for line, _, _ in errors] == [3]
    assert "unreachable" in errors[0][2] or "cannot reach" in errors[0][2]


def test_relative_turns_accumulate_through_repeats() -> None:
    errors = _errors("repeat 40\n  turn waist by 10\nend\n")
    assert len(errors) == 1 and "waist 190.00 deg is outside" in errors[0][2]
    result = check_source(Source("r.arm", "repeat 40\n  turn waist by 10\nend\n"))
    assert "repeat iteration 19 of 40 (line 1)" in result.diagnostics[0].notes


def test_a_steady_repeat_is_checked_quickly_and_timed_whole() -> None:
    text = "pose a = xyz 180 0 80 pitch -90\npose b = xyz 180 60 80 pitch -90\n"
    text += "repeat 10000\n  move a\n  move b\nend\n"
    result = check_source(Source("r.arm", text))
    assert result.ok
    d = [s.duration or 0.0 for s in result.timetable.rows]
    assert len(d) == 5  # two iterations, then one row for the 9998 alike
    assert result.timetable.total == pytest.approx(d[0] + d[1] + (d[2] + d[3]) * 9_999)


def test_an_endless_drift_is_cut_at_the_budget_with_a_warning(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    # the checker's own budget (20 000 statements) under ARMKIT_PROFILE=ci, a tenth of it
    # in make test: the same cut and warning, in a tenth of the time
    monkeypatch.setattr(_walk, "CHECK_BUDGET", cases(full=_walk.CHECK_BUDGET, quick=2_000))
    drift = "  turn waist by 0.00001\n" * 3  # 30 000 statements: over the budget
    result = check_source(Source("r.arm", f"repeat 10000\n{drift}end\n"))
    warnings = [d for d in result.diagnostics if d.severity == "warning"]
    assert result.ok and len(warnings) == 1
    assert "iterations only" in warnings[0].message


def test_procedures_with_parameters() -> None:
    text = """\
pose above = xyz 180 0 80 pitch -90
define dip(spot, depth)
  move spot
  line xyz 180 0 depth pitch -90
  wait 250ms
end
dip above 30
dip above 3cm
dip above -40
dip 30 above
dop above 30
dip above
"""
    errors = _errors(text)
    assert [(line, col) for line, col, _ in errors] == [(3, 8), (4, 3), (4, 18), (11, 1), (12, 1)]
    result = check_source(Source("p.arm", text))
    found = {(d.loc.line, d.loc.col): d for d in result.diagnostics}
    assert found[3, 8].message == "spot is the number 30, but a name is needed"
    assert found[3, 8].notes == ("in dip called at line 10",)
    assert "into the table" in found[4, 3].message
    assert found[4, 3].notes == ("in dip called at line 9",)
    assert found[4, 18].message == "depth is 'above', a name, but a length is needed"
    assert "did you mean 'dip'?" in found[11, 1].message
    assert "dip takes 2 arguments (spot, depth), got 1" in found[12, 1].message


def test_a_procedure_never_called_is_still_checked_for_names() -> None:
    errors = _errors("define f(a)\n  move nowhere\n  turn elbw by a\n  wait a\nend\n")
    assert [(line, col) for line, col, _ in errors] == [(2, 8), (3, 8)]


def test_recursion_is_refused() -> None:
    errors = _errors("define f\n  g\nend\ndefine g\n  f\nend\nf\n")
    assert errors and "more than 50 deep" in errors[0][2]


def test_start_pose_matters_for_relative_moves() -> None:
    model = load_model("openmanipulator_x")
    q0 = model.home.copy()
    q0[0] = math.radians(175)
    assert _errors("turn waist by 10\n", start=Start(model, q0))[0][2].startswith(
        "waist 185.00 deg"
    )
    assert _errors("turn waist by 10\n", start=Start(model, np.zeros(4))) == []


def test_run_and_light_need_timed_motors() -> None:
    errors = _errors("run shoulder forward 1s\nlight on\n")
    assert len(errors) == 2 and all("timed motors (the OWI-535)" in m for _, _, m in errors)
    owi = load_model("owi535")
    assert _errors("run shoulder forward 1.5s\nrun base left 500ms\nlight on\n", model=owi) == []
    bad = _errors("run base forward 1s\nrun elbow left 1s\nrun wrist forward 0s\n", model=owi)
    assert [m for _, _, m in bad] == [
        "the base turns left or right, not forward",
        "the elbow turns forward or backward, not left",
        "run needs a time in (0, 60] s, got 0 s",
    ]


def test_speed_and_wait_ranges() -> None:
    errors = _errors("speed 150%\nspeed 0\nspeed 2000 mm/s\nwait -1\nspeed 40 mm/s\nspeed 50\n")
    assert [line for line, _, _ in errors] == [1, 2, 3, 4]
