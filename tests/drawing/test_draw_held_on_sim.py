"""``held`` says the pen is in the gripper already; on a simulated arm whose scene has
the pen in its stand the gripper holds nothing, yet the job 'drew' and reported the
ink it measured. It is refused before anything moves; a dry run still plans it."""

from __future__ import annotations

from pathlib import Path

import pytest

from armkit import Arm
from armkit.drawing import DrawingError, DrawOptions, draw
from armkit.scene import load_scene

SQUARE = Path(__file__).parents[2] / "examples" / "scripts" / "square.svg"


def test_held_with_the_pen_in_its_stand_is_refused_on_the_simulator() -> None:
    arm, scene = Arm("openmanipulator_x"), load_scene("drawing")
    before = arm.driver.read()
    with pytest.raises(DrawingError, match="held: on the simulator pen stands in stand"):
        draw(arm, scene, SQUARE, options=DrawOptions(held=True))
    assert (arm.driver.read() == before).all()
    job = draw(arm, scene, SQUARE, options=DrawOptions(held=True), dry_run=True)
    assert job.plan.strokes
