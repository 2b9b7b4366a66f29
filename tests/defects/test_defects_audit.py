"""The new-user audit: wrong input to the API is refused with an ArmkitError naming the
argument (never a bare AttributeError/TypeError/IndexError/ValueError from inside),
options before any work, bools are not numbers, the OWI closes twice, planar2's
pitch follows from the position."""

from __future__ import annotations

import math
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np
import pytest

import armkit
from armkit import Arm, ArmkitError, InputError, drawing, music, tasks
from armkit.arm import _arm as arm_module
from armkit.drawing import shapes
from armkit.kinematics import fk, ik, pitch_of
from armkit.scene import load_scene

SVG = '<svg xmlns="http://www.w3.org/2000/svg" width="10mm" height="10mm"><path d="M0 0 L10 10"/></svg>'


def _refused(call: Callable[[], Any], *words: str) -> str:
    with pytest.raises(ArmkitError) as caught:
        call()
    assert isinstance(caught.value, ValueError)
    text = str(caught.value)
    for word in words:
        assert word in text, text
    return text


def test_ik_with_a_name_for_the_model_says_load_model() -> None:
    _refused(
        lambda: armkit.ik("openmanipulator_x", (0.2, 0, 0.05)),  # type: ignore[arg-type]
        "model must be an ArmModel",
        "armkit.load_model('openmanipulator_x')",
    )
    _refused(lambda: fk(None, [0, 0, 0, 0]), "model must be an ArmModel")  # type: ignore[arg-type]


def test_arm_refuses_a_bad_driver_and_world_and_loads_a_scene_name() -> None:
    _refused(lambda: Arm("lynx6", driver=None), "driver")  # type: ignore[arg-type]
    _refused(lambda: Arm("lynx6", world="x"), "world must be a World")  # type: ignore[arg-type]
    _refused(lambda: Arm("lynx6", scene=3), "scene", "load_scene")  # type: ignore[arg-type]
    with Arm("lynx6", scene="board_001") as arm:
        assert arm.scene is not None and arm.scene.name == load_scene("board_001").name
        arm.move_to(200, 0, 100)


def test_tasks_refuse_bad_arguments_before_anything_moves() -> None:
    scene = load_scene("board_001")
    with Arm("openmanipulator_x", scene=scene) as arm:
        before = arm.angles()
        _refused(lambda: tasks.run_plan(arm, None), "plan must be a Plan")  # type: ignore[arg-type]
        _refused(lambda: tasks.pick(arm, None, "red"), "scene must be a Scene", "load_scene")  # type: ignore[arg-type]
        _refused(lambda: tasks.pick(arm, scene, "red", clearance="x"), "clearance", "'x'")  # type: ignore[arg-type]
        _refused(lambda: tasks.pick(arm, scene, "red", pitch="x"), "pitch", "'x'")  # type: ignore[arg-type]
        _refused(lambda: tasks.stack(arm, scene, None), "stack", "names")  # type: ignore[arg-type]
        _refused(lambda: tasks.stack(arm, scene, [1, 2]), "stack")  # type: ignore[list-item]
        _refused(lambda: tasks.reach(arm, scene, shakes="x"), "shakes")  # type: ignore[arg-type]
        _refused(lambda: tasks.reach(arm, scene, shakes=True), "shakes")
        assert arm.angles() == before
        assert tasks.stack_names(["red", "green"]) == ["red", "green"]


def test_music_names_and_numbers_are_refused_with_their_kind() -> None:
    _refused(lambda: music.parse_pitch(None), "note name", "string")  # type: ignore[arg-type]
    _refused(lambda: music.frequency("A4"), "MIDI note number", "parse_pitch")  # type: ignore[arg-type]
    _refused(lambda: music.note_name("x"), "MIDI note number")  # type: ignore[arg-type]
    _refused(lambda: music.note_name(True), "MIDI note number")
    assert music.frequency(69) == 440.0 and music.note_name(60) == "C4"
    assert music.parse_pitch("A4") == 69


def test_pitch_of_refuses_a_rotation_for_a_pose() -> None:
    _refused(lambda: pitch_of(np.eye(3)), "shape (4, 4)")
    _refused(lambda: pitch_of("x"), "T (a tool pose)")  # type: ignore[arg-type]
    assert float(pitch_of(np.eye(4))) == 0.0
    assert float(pitch_of(np.eye(4).tolist())) == 0.0  # type: ignore[arg-type]


def test_drawing_refuses_a_named_sheet_and_text_coordinates(tmp_path: Path) -> None:
    svg = tmp_path / "a.svg"
    svg.write_text(SVG)
    _refused(lambda: drawing.plan_drawing(svg, "A5"), "sheet must be")  # type: ignore[arg-type]
    _refused(lambda: drawing.plan_drawing(svg, (0.2, 0.1), start="x"), "start", "(u, v)")
    _refused(lambda: drawing.plan_drawing(svg, (0.2, "y")), "sheet")  # type: ignore[arg-type]
    _refused(lambda: drawing.plan_drawing(svg, (0.2, 0.1), tolerance="x"), "tolerance")  # type: ignore[arg-type]
    _refused(lambda: shapes.line("a", (0, 0)), "start", "(u, v)")  # type: ignore[arg-type]
    _refused(lambda: shapes.line((True, 0), (0, 0)), "start")
    plan = drawing.plan_drawing(svg, (0.2, 0.1), start=(0.0, 0.0))
    assert plan.strokes


def test_options_are_checked_before_ik(monkeypatch: pytest.MonkeyPatch) -> None:
    solved: list[object] = []
    monkeypatch.setattr(arm_module, "ik", lambda *a, **k: solved.append(a))
    with Arm("puma560") as arm:
        before = arm.angles()
        for options, word in (
            ({"speed": "fast"}, "speed"),
            ({"speed": 2.0}, "speed"),
            ({"duration": -1}, "duration"),
            ({"timeout": 0}, "timeout"),
            ({"wait": "no"}, "wait"),
        ):
            _refused(lambda o=options: arm.move_to(150, 0, 100, **o), word)  # type: ignore[misc]
        assert solved == []  # refused before any IK is solved (no 1500 LM iterations first)
        _refused(lambda: arm.home(speed="fast"), "speed")  # type: ignore[arg-type]
        assert arm.angles() == before


def test_bools_are_not_numbers() -> None:
    model = armkit.load_model("openmanipulator_x")
    _refused(lambda: fk(model, [True, False, False, False]), "True or False")
    _refused(lambda: fk(model, np.array([True, False, False, False])), "True or False")
    _refused(lambda: ik(model, (True, 0.0, 0.1)), "position")
    with Arm("lynx6") as arm:
        before = arm.angles()
        _refused(lambda: arm.move_to(True, 0, 100), "x, y, z", "True or False")
        _refused(lambda: arm.grip(True), "grip width", "a number", "True or False")
        _refused(lambda: arm.move_joints([True, 0, 0, 0, 0]), "True or False")
        assert arm.angles() == before


def test_a_huge_grip_width_is_shown_briefly() -> None:
    with Arm("lynx6") as arm:
        text = _refused(lambda: arm.grip(1e308), "grip width")
    assert len(text) < 120, text


def test_owi_closes_twice_silently() -> None:
    with Arm("owi535") as arm:
        arm.close()
    arm.close()
    arm.stop()


def test_planar2_retreats_after_approach_and_takes_a_typed_pitch() -> None:
    with Arm("planar2") as arm:
        arm.approach(180, 0, 40)
        arm.retreat()
        x, _, z, _ = arm.position()
        assert abs(x - 180) < 1.0 and abs(z - 70) < 1.0
    model = armkit.load_model("planar2")
    assert armkit.kinematics.pitch_follows(model)
    assert not armkit.kinematics.pitch_follows(armkit.load_model("openmanipulator_x"))
    q = ik(model, (0.75, 0.0, 0.433013), 0.0).q  # implies a pitch a hair off 0
    assert np.allclose(np.degrees(q), [30.0, -60.0], atol=1e-3)
    off = math.radians(0.1)
    with pytest.raises(armkit.UnreachableError, match="leave the pitch out"):
        ik(model, (0.75, 0.0, 0.433013), off)
    batch = armkit.ik_batch(model, np.array([[0.75, 0.0, 0.433013]] * 2), np.array([0.0, off]))
    assert batch.ok.tolist() == [True, False]


def test_cli_planar2_ik_takes_a_pitch_typed_to_a_few_digits(
    capsys: pytest.CaptureFixture[str],
) -> None:
    from armkit.cli import main

    assert main(["--arm", "planar2", "ik", "750", "0", "433.013", "--pitch", "0.0"]) == 0
    assert "30.00" in capsys.readouterr().out


def test_a_refused_input_is_an_input_error() -> None:
    with pytest.raises(InputError):
        armkit.ik("planar2", (0.2, 0, 0.05))  # type: ignore[arg-type]
