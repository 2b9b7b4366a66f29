"""``armkit check`` plans a script's ``draw`` from the arm as the check knows it, as
``drawing.plan_draw`` plans it before it moves. It only planned the file on the sheet,
so reach was never checked: with the sheet moved out of reach (a scene file next to the
script), or the pen's stand, the script passed its check, then ``run`` moved the lines
before it and stopped at the job ("reaches none of the drawing", "pick up pen: step
'pick pen: above' is unreachable"). Now the check refuses them at the job's line and
nothing moves; strokes cut for reach (what ``plan_draw`` does with a sheet partly out
of reach) are said as a ``DrawingWarning``, by check and run alike."""

from __future__ import annotations

import warnings
from pathlib import Path

import numpy as np
import pytest

import armkit.scene
from armkit import Arm, ArmkitError
from armkit.arm import Start
from armkit.drawing import DrawingWarning, plan_draw
from armkit.kinematics import ik
from armkit.model import load_model
from armkit.scene import load_scene
from armkit.script import ScriptCheckError, Source, check_file, run_source
from armkit.script._job_checks import check_draw
from armkit.script._job_plans import plan_job
from armkit.sim import World

SHIPPED = Path(armkit.scene.__file__).parent / "scenes" / "drawing.toml"
SQUARE = Path(__file__).parents[2] / "examples" / "scripts" / "square.svg"
SHEET = "origin_mm = [110.0, -105.0, 0.0]"
STAND = "position_mm = [166.3, 237.6, 30.0]"
MOVED = {  # the shipped drawing scene with one thing moved
    "far": (SHEET, "origin_mm = [710.0, -105.0, 0.0]"),  # the sheet 600 mm further out
    "near": (SHEET, "origin_mm = [210.0, -105.0, 0.0]"),  # 100 mm further: partly reached
    "stand": (STAND, "position_mm = [466.3, 437.6, 30.0]"),  # the pen's stand out of reach
}
NONE = "square.svg: the openmanipulator_x reaches none of the drawing with the pen"
STAND_OUT = "draw: pick up pen: step 'pick pen: above' is unreachable: openmanipulator_x"
CUT = "square.svg: cut 287.8 mm of 753.2 mm of line that the openmanipulator_x cannot reach"


def _write(tmp_path: Path, scene: str) -> Path:
    """The scene file ``scene``.toml and a script drawing on it after one move."""
    old, new = MOVED[scene]
    text = SHIPPED.read_text()
    assert old in text
    (tmp_path / f"{scene}.toml").write_text(text.replace(old, new))
    (tmp_path / "square.svg").write_text(SQUARE.read_text())
    script = tmp_path / "job.arm"
    script.write_text(_script(scene))
    return script


def _script(scene: str) -> str:
    return (
        f'arm openmanipulator_x\nscene "{scene}.toml"\nmove xyz 150 0 100 pitch -90\n'
        "draw square.svg on A5 fit\n"  # scaled to the sheet (default: its real 60 mm)
    )


def _errors(script: Path) -> list[tuple[int, int, str]]:
    result = check_file(script)
    return [(d.loc.line, d.loc.col, d.message) for d in result.diagnostics if d.severity == "error"]


@pytest.mark.parametrize("scene,start", [("far", NONE), ("stand", STAND_OUT)], ids=["far", "stand"])
def test_a_draw_the_arm_cannot_make_is_an_error_at_its_line(
    tmp_path: Path, scene: str, start: str
) -> None:
    errors = _errors(_write(tmp_path, scene))
    assert [(line, col) for line, col, _ in errors] == [(4, 1)]
    assert start in errors[0][2]


@pytest.mark.parametrize("scene,match", [("far", "reaches none"), ("stand", "pick up pen")])
def test_run_refuses_it_before_the_first_move(tmp_path: Path, scene: str, match: str) -> None:
    script = _write(tmp_path, scene)
    world = World()
    scene_now = load_scene(tmp_path / f"{scene}.toml")
    with Arm("openmanipulator_x", "sim", world=world, scene=scene_now) as arm:
        before, start = world.arm().q().copy(), world.now()
        with pytest.raises(ScriptCheckError, match=match):
            run_source(arm, Source(str(script), script.read_text()), base_dir=tmp_path)
        assert np.array_equal(world.arm().q(), before) and world.now() == start


def test_strokes_cut_for_reach_are_said_as_plan_draw_says_them(tmp_path: Path) -> None:
    script = _write(tmp_path, "near")
    with pytest.warns(DrawingWarning) as said:
        assert _errors(script) == []
    cuts = [str(w.message) for w in said if "cannot reach" in str(w.message)]
    assert len(cuts) == 1 and CUT in cuts[0]
    model, scene = load_model("openmanipulator_x"), load_scene(tmp_path / "near.toml")
    q = np.asarray(ik(model, np.array([0.15, 0.0, 0.10]), np.radians(-90.0), model.home).q)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", DrawingWarning)
        job = plan_draw(Start(model, q), scene, tmp_path / "square.svg", "A5", fit=True)
    assert [n for n in job.plan.notes if "cannot reach" in n] == cuts  # the same note


def test_plan_draw_from_a_start_is_the_plan_from_an_arm_there() -> None:
    scene = load_scene("drawing")
    with Arm("openmanipulator_x", "sim", world=World(), scene=scene) as arm:
        from_arm = plan_draw(arm, scene, SQUARE, "A5")
        q = arm.driver.read()
    from_start = plan_draw(Start(load_model("openmanipulator_x"), q), scene, SQUARE, "A5")
    assert np.array_equal(from_start.q_start, from_arm.q_start)
    assert len(from_start.segments) == len(from_arm.segments)
    assert from_start.lines() == from_arm.lines()


def test_a_draw_is_planned_from_the_start(tmp_path: Path) -> None:
    # check and run plan a script's draw alike (script._job_plans), from where the arm is
    _write(tmp_path, "far")
    model, scene = load_model("openmanipulator_x"), load_scene(tmp_path / "far.toml")
    svg = tmp_path / "square.svg"
    check_draw(scene, svg, "A5", fit=True)  # its arguments: the file on the sheet only
    with pytest.raises(ArmkitError, match="reaches none of the drawing"):
        start = Start(model, model.home, scene=scene)
        plan_job(start, scene, "draw", {"file": svg, "sheet": "A5", "fit": True})
