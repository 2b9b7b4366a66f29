"""The drawing job on the simulated arms: the pen picked up and put back, what
the pen drew measured within the issue's targets, bad input moving nothing."""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from armkit import Arm
from armkit._errors import ArmkitError, InputError
from armkit.drawing import DrawingError, DrawOptions, Fit, draw, plan_draw
from armkit.drawing._segments_job import GripMove
from armkit.scene import Cube, Scene, load_scene
from armkit.sim import World

SQUARE = (
    '<svg xmlns="http://www.w3.org/2000/svg" width="40mm" height="40mm" viewBox="0 0 40 40">'
    '<rect x="0" y="0" width="40" height="40" fill="none" stroke="black"/>'
    '<circle cx="20" cy="20" r="10" fill="none" stroke="black"/></svg>'
)


@pytest.fixture
def square(tmp_path: Path) -> Path:
    p = tmp_path / "square.svg"
    p.write_text(SQUARE)
    return p


@pytest.fixture(scope="module")
def scene() -> Scene:
    return load_scene("drawing")


@pytest.mark.parametrize(
    "arm_name,held", [("openmanipulator_x", False), ("lynx6", False), ("lynx6", True)]
)
def test_drawn_within_the_targets(arm_name: str, held: bool, square: Path, scene: Scene) -> None:
    arm = Arm(arm_name, "sim", world=World())
    job = draw(arm, scene, square, "A5", options=DrawOptions(held=held), fit=Fit(scale=1.0))
    m = job.metrics
    assert m is not None
    assert m.hausdorff <= 1e-3 and m.rms_cross_track <= 0.3e-3
    assert m.pen_lifts == len(job.plan.strokes) == 2
    assert abs(m.pen_down_length - job.plan.pen_down_length) < 0.1 * job.plan.pen_down_length
    grips = [s for s in job.segments if isinstance(s, GripMove)]
    if held:
        assert grips == []
    else:  # picked up, then put back
        assert [g.holds for g in grips] == [False, True, False]


def test_pen_tool_length_is_001s_on_the_openmanipulator(scene: Scene, square: Path) -> None:
    arm = Arm("openmanipulator_x", "sim", world=World())
    job = plan_draw(arm, scene, square, "A5")
    assert job.tip.tool_length == pytest.approx(0.116)


def test_out_of_reach_is_cut_with_a_note(scene: Scene, square: Path) -> None:
    sheet = scene.sheets[0]
    far = replace(sheet, origin=sheet.origin + np.array([0.10, 0.0, 0.0]))
    arm = Arm("openmanipulator_x", "sim", world=World())
    job = plan_draw(arm, replace(scene, sheets=(far,)), square, "A5", fit=True)
    assert any("cannot reach" in n for n in job.plan.notes)
    gone = replace(sheet, origin=sheet.origin + np.array([0.6, 0.0, 0.0]))
    q0 = arm.driver.read()
    with pytest.raises(DrawingError, match="reaches none"):
        draw(arm, replace(scene, sheets=(gone,)), square, "A5")
    assert np.array_equal(arm.driver.read(), q0)


def test_a_collision_moves_nothing(scene: Scene, square: Path) -> None:
    block = Cube("block", 0.08, np.array([0.184, 0.0, 0.0]), 0.0, "+z")
    arm = Arm("openmanipulator_x", "sim", world=World())
    q0 = arm.driver.read()
    with pytest.raises(ArmkitError, match="block"):
        draw(arm, replace(scene, cubes=(block,)), square, "A5", fit=Fit(scale=1.0))
    assert np.array_equal(arm.driver.read(), q0)


def test_names_checked_before_anything(scene: Scene, square: Path, tmp_path: Path) -> None:
    arm = Arm("openmanipulator_x", "sim", world=World())
    with pytest.raises(DrawingError, match=r"no sheet .A4..*A5"):
        draw(arm, scene, square, "A4")
    with pytest.raises(DrawingError, match="no pen 'marker'"):
        draw(arm, scene, square, pen="marker")
    with pytest.raises(InputError, match="does not exist"):
        draw(arm, scene, square, result=tmp_path / "no" / "r.png")
