"""A job is declared once (issue 26 point 4): one JobSpec gives both the CLI's
sub-command (in ``armkit --help``, its own ``--help`` naming units and defaults) and the
script's statement, checked and run on the simulator, in the same units. The specs'
defaults are the functions' own, so the CLI (which passes them) and a script (which
leaves them to the function) do the same job."""

from __future__ import annotations

import inspect
from pathlib import Path
from typing import Any

import pytest

from armkit.cli import main
from armkit.jobs import CLI_JOBS, JOBS, JobParam, JobSpec, as_function_gets
from armkit.script import check_file


def _wave_spec(calls: list[dict[str, Any]]) -> JobSpec:
    def wave(arm: Any, scene: Any, **arguments: Any) -> None:
        calls.append(arguments)
        arm.move_joints(arm.angles())  # a real (zero-length) motion on the simulator

    params = (
        JobParam("times", "count", help="how many waves", metavar="N"),
        JobParam("height", "length", keyword="up", option="--up", required=False,
                 default=20.0, low=0.0, high=100.0, help="how high the gripper rises"),
        JobParam("pace", "percent", keyword="pace", option="--pace", required=False,
                 default=50.0, help="of the arm's wave speed"),
    )  # fmt: skip
    return JobSpec(params, wave, "wave the gripper at the audience")


def test_a_job_declared_once_is_a_cli_command_and_a_script_statement(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    calls: list[dict[str, Any]] = []
    monkeypatch.setitem(JOBS, "wave", _wave_spec(calls))

    assert main(["--help"]) == 0
    assert "wave the gripper at the audience" in capsys.readouterr().out
    assert main(["wave", "--help"]) == 0
    usage = " ".join(capsys.readouterr().out.split())
    assert "--up MM how high the gripper rises [mm], 0..100 (default 20)" in usage
    assert "--pace PERCENT of the arm's wave speed [%] (default 50)" in usage

    assert main(["--scene", "empty", "wave", "3", "--up", "25", "--pace", "40%"]) == 0
    assert calls.pop() == {"times": 3, "height": pytest.approx(25.0), "pace": pytest.approx(0.4)}
    assert (
        main(["--scene", "empty", "wave", "2"]) == 0
    )  # the spec's defaults, in the function's units
    assert calls.pop() == {"times": 2, "height": pytest.approx(20.0), "pace": pytest.approx(0.5)}
    assert (
        main(["--scene", "empty", "wave", "2", "--up", "300"]) == 2
    )  # the spec's bounds: nothing done
    assert "--up: must be 0..100 mm, got 300" in capsys.readouterr().err and not calls

    path = tmp_path / "wave.arm"
    path.write_text("arm openmanipulator_x\nwave 3 up 2.5cm pace 40%\n", encoding="utf-8")
    assert check_file(path).ok
    assert main(["run", str(path)]) == 0, capsys.readouterr().err
    assert calls == [{"times": 3, "height": pytest.approx(25.0), "pace": pytest.approx(0.4)}]
    path.write_text("arm openmanipulator_x\nwave 3 up 2 s\n", encoding="utf-8")
    bad = check_file(path)  # a time is not a length: refused by the script as by the CLI
    assert not bad.ok and "length" in bad.diagnostics[0].message, bad.diagnostics


def _functions() -> dict[str, Any]:
    from armkit import drawing, music, tasks

    return {
        "pick": tasks.pick, "place": tasks.place, "move-item": tasks.move_item,
        "rotate-cube": tasks.rotate_cube, "stack": tasks.stack, "search": tasks.search,
        "reach": tasks.reach, "draw": drawing.draw, "play": music.play,
    }  # fmt: skip


@pytest.mark.parametrize("name", sorted({**JOBS, **CLI_JOBS}))
def test_every_spec_names_its_function_s_parameters_and_defaults(name: str) -> None:
    spec = {**JOBS, **CLI_JOBS}[name]
    signature = inspect.signature(_functions()[name]).parameters
    for p in spec.cli_params:
        if not p.passed:
            continue
        assert p.name in signature, f"{name}: {p.name} is not a parameter of its function"
        want = signature[p.name].default
        if p.default is not None and want is not inspect.Parameter.empty and want is not None:
            assert as_function_gets(p.kind, p.default) == pytest.approx(want), (name, p.name)


def test_one_unit_per_quantity_on_both_surfaces() -> None:
    """A tempo is a percentage on the CLI as in a script (was a factor on the CLI)."""
    from armkit.music._score import MAX_TEMPO, MIN_TEMPO

    tempo = next(p for p in JOBS["play"].parameters if p.name == "tempo")
    assert (tempo.kind, tempo.unit, tempo.keyword, tempo.option) == ("percent", "%", "tempo", "--tempo")  # fmt: skip
    assert (tempo.low, tempo.high) == pytest.approx((MIN_TEMPO * 100, MAX_TEMPO * 100))
    search = {p.name: p for p in JOBS["search"].parameters}
    assert {search[k].unit for k in ("start", "stop", "step")} == {"deg"}
