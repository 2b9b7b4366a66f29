"""The check plans a script's tasks as they will run: a ``place`` that cannot be done
(it would tip the cube, or hit one) was passed by ``armkit check`` and refused by
``armkit run`` only after the lines before it had moved the arm. Now the check plans
every task (``pick``, ``place``, ``move-item``, ``rotate-cube``, ``stack``) from where
the arm will be, with the cubes where the tasks before it leave them (on a simulated
arm: where they are now), and refuses the script at the task's line; nothing moves."""

from __future__ import annotations

import re
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from script_arms import counting_arm

import armkit.tasks
from armkit import Arm
from armkit.cli import main
from armkit.motion import trapezoid
from armkit.script import ScriptCheckError, Source, check_source, run_source
from armkit.tasks import Start

TIPS = "scene board_001\nmove 200 0 150\npick red\nplace board[0,1]\nhome\n"


def _check(text: str) -> Any:
    return check_source(Source("job.arm", text))


def test_a_place_that_cannot_be_planned_fails_the_check_at_its_line() -> None:
    result = _check(TIPS)
    assert not result.ok
    (d,) = result.diagnostics
    assert d.loc.line == 4
    assert "place red: board[0, 1] is taken by green" in d.message
    (d,) = _check(TIPS.replace("board[0,1]", "xyz 400 0 0")).diagnostics
    assert d.loc.line == 4 and "place red: cannot put red at (400.0, 0.0, 0.0) mm" in d.message


def test_run_refuses_it_before_the_first_line_moves() -> None:
    arm, driver = counting_arm()
    before = arm.driver.read()
    with pytest.raises(ScriptCheckError, match=r"job.arm:4:1: place red: board\[0, 1\] is taken"):
        run_source(arm, Source("job.arm", TIPS))
    assert driver.sent == 0
    np.testing.assert_array_equal(arm.driver.read(), before)


def test_the_check_follows_the_cubes_from_task_to_task() -> None:
    # red goes onto green; green is then under red, which only a check that carries the
    # cubes from one task to the next knows (the scene file has green free)
    result = _check("scene board_001\npick red\nplace green\npick green\n")
    (d,) = result.diagnostics
    assert d.loc.line == 4 and "under red" in d.message
    assert _check("scene board_001\npick red\nplace board[1,0]\npick blue\nplace red\n").ok


def test_after_a_task_the_arm_is_where_its_plan_ends() -> None:
    result = _check("scene board_001\npick red\nhome\n")
    pick, home = result.timetable.rows
    assert pick.note == "pick: 9 steps" and pick.q is not None  # planned and timed
    assert home.duration is not None and home.duration > 0.0  # timed from the plan's end


@pytest.mark.parametrize(
    "jobs",
    ["pick red\nplace green", "rotate-cube red backward", "move-item blue to xyz 180 -100 0"],
)
def test_the_check_times_the_tasks_as_the_simulator_runs_them(jobs: str) -> None:
    # moves at full speed; around each gripper command the simulator waits until the
    # gripper has moved (hardware: tasks.GRIP_S before and after)
    arm = counting_arm()[0]
    t0 = arm.clock.now()
    result = run_source(arm, Source("job.arm", f"scene board_001\n{jobs}\nhome\n"))
    took = arm.clock.now() - t0
    assert result.timetable.unknown == 0
    # within 3 %: closing on a cube is forecast as a full close (the jaws stop at the cube)
    assert result.timetable.total == pytest.approx(took, rel=0.03)


def test_on_a_simulated_arm_the_check_plans_with_the_cubes_where_they_are() -> None:
    arm, driver = counting_arm()
    run_source(arm, Source("a.arm", "scene board_001\npick red\nplace green\n"))
    sent = driver.sent
    with pytest.raises(ScriptCheckError, match=r"b.arm:2:1: pick green: .*under red"):
        run_source(arm, Source("b.arm", "scene board_001\npick green\n"))
    assert driver.sent == sent


def test_on_hardware_each_task_plans_with_the_cubes_where_the_last_one_left_them(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    # without the scene's physics (as on hardware: the plans carried out by Arm.run
    # alone) the runner plans each task with the cubes where the plan before left them
    seen: list[Any] = []
    real = armkit.tasks.place

    def place(start: Any, scene: Any, **kw: Any) -> Any:
        seen.append(scene)
        return real(start, scene, **kw)

    monkeypatch.setattr(armkit.tasks, "place", place)
    monkeypatch.setattr(armkit.tasks, "run_verified", lambda arm, plan: arm.run(plan))
    arm: Arm = counting_arm()[0]
    run_source(
        arm,
        Source("job.arm", "scene board_001\npick red\nplace board[1,0]\npick blue\nplace red\n"),
    )
    assert len(seen) == 4  # two by the check, two by the run
    red_when_blue_goes_on_it = seen[3].cube("red")
    assert red_when_blue_goes_on_it.position == pytest.approx([0.175, 0.045, 0.003])


def test_a_search_is_planned_by_the_check_and_the_lines_after_it_from_its_end() -> None:
    # the scan's readings are predicted from the scene (tasks.plan_search), so the check
    # times the search and plans the next line from where the search leaves the arm
    result = check_source(Source("job.arm", "arm lynx6\nscene search_002\nsearch\nhome\n"))
    assert result.ok and result.timetable.unknown == 0
    search, home = result.timetable.rows
    assert search.duration is not None and search.duration > 0
    assert home.duration is not None and search.note.startswith("search: ")


def test_a_task_given_a_start_only_plans() -> None:
    arm, driver = counting_arm()
    scene = armkit.scene.load_scene("board_001")
    plan = armkit.tasks.pick(Start(arm.model, arm.model.home), scene, "red")
    assert driver.sent == 0 and plan.steps[-1].holding == "red"
    assert plan.rest.cube("red").position == pytest.approx(scene.cube("red").position)
    # the end is where the driver will read the arm: the last goal to the servos' tick
    np.testing.assert_allclose(plan.q_end, plan.steps[-1].q, atol=2 * np.pi / 4096)
    with pytest.raises(armkit.InputError, match=r"q must have shape \(4,\)"):
        Start(arm.model, np.zeros(3))
    with pytest.raises(armkit.InputError, match="Start needs an ArmModel"):
        Start("openmanipulator_x", np.zeros(4))  # type: ignore[arg-type]


def _task_plans(jobs: str) -> list[Any]:
    """The plans of the one task in ``jobs`` planned from home on board_001 (place: after
    the pick before it, from where its plan leaves the arm)."""
    model = armkit.load_model("openmanipulator_x")
    scene = armkit.scene.load_scene("board_001")
    first, *rest = jobs.split("\n")
    words = first.split()
    if words[0] == "pick":
        plan = armkit.tasks.pick(Start(model, model.home), scene, words[1])
        after = armkit.tasks.place(
            Start(model, plan.q_end), plan.rest, words[1], rest[0].split()[1]
        )
        return [plan, after]
    if words[0] == "rotate-cube":
        return [armkit.tasks.rotate_cube(Start(model, model.home), scene, words[1], words[2])]
    return [armkit.tasks.move_item(Start(model, model.home), scene, words[1], (180.0, -100.0, 0.0))]


def _task_steps(jobs: str) -> list[Any]:
    return [step for plan in _task_plans(jobs) for step in plan.steps]


def _moves_time(jobs: str) -> float:
    model = armkit.load_model("openmanipulator_x")
    took = 0.0
    for plan in _task_plans(jobs):
        q = plan.q_start
        for step in plan.steps:
            if step.q is not None:
                took += trapezoid(model, q, step.q, 1.0).duration
                q = step.q
    return took


@pytest.mark.parametrize(
    ("move", "hit"),
    [
        ("move 220 0 15", "the gripper would be 12.5 mm into the green"),
        ("move 242 0 4", "the gripper would be 16.0 mm into the board"),
        ("move 0 0 5", "the gripper would be 25.0 mm into the base column"),
    ],
)
def test_moves_are_checked_as_the_arm_checks_them(move: str, hit: str) -> None:
    # the checker had its own table test (frame origins only), so a script could pass
    # check with a link in the table or the gripper in a cube and be refused by run
    # (closed jaws: open ones pass over a cube narrower than their opening)
    arm, driver = counting_arm()
    text = f"scene board_001\nmove 200 0 150\ngrip 20\n{move}\n"
    with pytest.raises(ScriptCheckError, match=f"job.arm:4:1: move refused: there, {hit}"):
        run_source(arm, Source("job.arm", text))
    assert driver.sent == 0


def test_after_a_task_moves_are_checked_against_the_cubes_where_it_left_them() -> None:
    moved = "scene board_001\npick red\nplace xyz 180 -100 0\n"
    refused = _check(moved + "grip 20\nmove 180 -100 20 pitch -90\n")  # jaws closed
    assert "the gripper would be 5.0 mm into the red" in refused.diagnostics[0].message
    assert _check(
        moved + "move 220 45 60 pitch -90\nmove 220 45 20 pitch -90\n"
    ).ok  # red stood there


def test_opening_the_gripper_lets_the_held_cube_go() -> None:
    # the check kept the cube held after 'grip open', so a 'place' passed the check and
    # ran all its steps on a cube that had dropped
    dropped = _check("scene board_001\npick red\ngrip open\nplace xyz 150 -150 0\n")
    assert "no cube is picked here" in dropped.diagnostics[0].message
    assert _check("scene board_001\npick red\ngrip open\nhome\npick red\n").ok
    assert _check("scene board_001\npick red\ngrip 20mm\nplace xyz 150 -150 0\n").ok


def test_a_held_cube_is_checked_with_the_links() -> None:
    # the check and Arm left the held cube out: 'move ... 5 pitch -90' after 'pick red'
    # put red 7.5 mm into the table, in check and in run
    arm, driver = counting_arm()
    text = "scene board_001\npick red\nmove xyz 150 -150 5 pitch -90\ngrip open\n"
    with pytest.raises(ScriptCheckError, match=r"3:1: move refused: there, the held red "
                       r"would be 7\.5 mm into the table"):  # fmt: skip
        run_source(arm, Source("job.arm", text))
    assert driver.sent == 0
    run_source(arm, Source("job.arm", "scene board_001\npick red\n"))
    assert arm.held is not None and arm.held.cube.name == "red"
    with pytest.raises(armkit.UnreachableError, match="the held red would be 7"):
        arm.move_to(150, -150, 5, -90)
    arm.grip(75)  # lets it go
    assert arm.held is None


def test_a_cube_let_go_lands_where_the_check_says() -> None:
    # the check forgot where a released cube went (run knew): a move into it passed
    # check and was refused by run after moving; a place planned from it likewise
    arm, driver = counting_arm()
    dropped = "scene board_001\npick green\nmove 150 -120 40 pitch -90\ngrip 45\ngrip 20\n"
    with pytest.raises(ScriptCheckError, match=r"6:1: move refused: there, .*into the green"):
        run_source(arm, Source("job.arm", dropped + "move 150 -120 20 pitch -90\n"))
    assert driver.sent == 0
    run_source(
        arm, Source("job.arm", dropped.replace("grip 20\n", "") + "move 150 -120 20 pitch -90\n")
    )


def test_a_timed_motor_run_is_checked_against_the_table() -> None:
    # 'run shoulder forward 1s' took the OWI 23 mm below the table: check and run passed
    result = check_source(
        Source("o.arm", "arm owi535\nmove 200 -60 50 pitch -45\nrun shoulder forward 1s\n")
    )
    (d,) = result.diagnostics
    assert d.loc.line == 3 and "into the table" in d.message


def test_a_job_with_a_word_too_many_says_so() -> None:
    # 'place object bin' said "expected an argument keyword (), got 'bin'"
    (d,) = _check("scene board_001\npick red\nplace red board[1,1]\n").diagnostics
    assert (d.loc.line, d.loc.col) == (3, 11)
    assert d.message == "place takes nothing more, got 'board[1,1]'; usage: place TO"


def test_a_calibrated_owi_is_checked_with_its_own_timing(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    # the check inside run used the timing a new unit starts with: 22.47 s checked,
    # 31.74 s run on a calibrated simulated unit (the check now starts from the arm: its driver forecasts)
    assert main(["--arm", "owi535", "calibrate"]) == 0
    script = tmp_path / "o.arm"
    script.write_text("arm owi535\nmove 200 0 100\nhome\n")
    capsys.readouterr()
    assert main(["check", str(script)]) == 0  # from home, a new unit: it says so
    assert "timed as a new unit runs: 'armkit run --dry-run' times this unit" in (
        capsys.readouterr().out
    )
    assert main(["run", "--dry-run", str(script)]) == 0
    planned = re.search(r"total ([\d.]+) s", capsys.readouterr().out)
    assert main(["run", "-q", str(script)]) == 0
    took = re.search(r" in ([\d.]+) s", capsys.readouterr().out)
    assert planned and took
    assert float(planned.group(1)) == pytest.approx(float(took.group(1)), rel=0.02)
