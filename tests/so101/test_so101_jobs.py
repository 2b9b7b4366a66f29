"""Every job on the simulated SO-101 (issue 31 item 6): the board task, pick and place,
drawing and music run through the Feetech driver on the emulated STS3215 bus, as on the
OpenManipulator-X. Home holds the jaws level, across the arm's plane (wrist_roll 92.79
deg: the URDF's 2.79 deg roll offset), as the tasks' grasps and the pen want them.

What the SO-101's geometry does not allow is refused with its numbers: 001's turn in
place (pick from the side at pitch 0, put down from the top at -90) needs a cube both
within the side reach (290..425 mm out at board_001's cube height) and the top reach
(100..265 mm): never both, so ``stack`` on board_001 runs with ``rotate_first=None``.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from armkit import Arm, tasks
from armkit.drawing import DrawOptions, draw, ink
from armkit.music import load_score, play
from armkit.scene import load_scene
from armkit.sim import World
from armkit.tasks import Plan, TaskError
from armkit.tasks._plan import pose_error

EXAMPLES = Path(__file__).parents[2] / "examples"


def _as_planned(arm: Arm, plan: Plan) -> None:
    physics = tasks.attached(arm)
    assert physics is not None
    for cube in plan.after.cubes:
        distance, turn = pose_error(physics.cube(cube.name), cube)
        assert distance < 1e-3 and turn < math.radians(1.0), cube.name


def test_the_so101_stacks_the_001_cubes_on_the_board() -> None:
    with Arm("so101", "sim", world=World()) as arm:
        assert type(arm.driver).__name__ == "FeetechDriver"
        plan = tasks.stack(
            arm, load_scene("board_001"), ["red", "green", "blue"], rotate_first=None
        )
        _as_planned(arm, plan)
        physics = tasks.attached(arm)
        assert physics is not None
        z = [physics.cube(n).position[2] * 1000 for n in ("red", "green", "blue")]
        assert z == pytest.approx([3.0, 28.0, 53.0], abs=1.0)


def test_the_turn_in_place_is_refused_with_the_reach_and_nothing_moves() -> None:
    world = World()
    with Arm("so101", "sim", world=world) as arm:
        before = world.arm().q().copy()
        with pytest.raises(TaskError, match=r"from the side 290\.\.425 mm out, from the top "
                           r"100\.\.265 mm out, never both"):  # fmt: skip
            tasks.stack(arm, load_scene("board_001"), ["red", "green", "blue"])
        assert np.array_equal(world.arm().q(), before)


def test_pick_and_place_on_the_so101() -> None:
    scene = load_scene("board_001")
    with Arm("so101", "sim", world=World()) as arm:
        _as_planned(arm, tasks.pick(arm, scene, "green"))
        _as_planned(arm, tasks.place(arm, scene, "green", "board[1,1]"))
        _as_planned(arm, tasks.move_item(arm, scene, "red", "board[2,0]"))


def test_the_so101_draws_a_40_mm_circle_40_mm_wide_with_the_pen_in_its_jaws(
    tmp_path: Path,
) -> None:
    """The drawing scene's pen stand is out of reach: its pick point is 270 mm out at
    50 mm, the SO-101 reaches that height from the side 275..430 mm out."""
    svg = tmp_path / "circle.svg"
    svg.write_text(
        '<svg xmlns="http://www.w3.org/2000/svg" width="40mm" height="40mm" viewBox="0 0 40 40">'
        '<circle cx="20" cy="20" r="20" fill="none" stroke="black"/></svg>'
    )
    scene = load_scene("drawing")
    with Arm("so101", "sim", world=World(), scene=scene) as arm:
        job = draw(arm, scene, svg, options=DrawOptions(held=True))
    assert job.trace is not None and job.metrics is not None
    drawn = np.vstack(ink(job.trace, job.sheet))
    assert np.allclose(np.ptp(drawn, axis=0), 0.040, atol=0.6e-3)  # what the pen put down
    assert job.metrics.hausdorff < 1.0e-3  # [m] the ink against the plan


def test_the_so101_plays_the_xylophone_on_the_beat() -> None:
    scene = load_scene("xylophone")
    tune = EXAMPLES / "music" / "twinkle.rtttl"
    with Arm("so101", "sim", world=World(), scene=scene) as arm:
        played = play(arm, scene, tune)
    assert [c.note for c in played.contacts] == [n.pitch for n in load_score(tune).notes]
    assert played.stats is not None and not played.stats.missed and not played.stats.extra
    assert played.stats.max < 5e-3  # [s] simulated time


def test_a_grip_takes_its_forecast() -> None:
    """The gripper servo at its full speed (Goal Velocity 0), then the poll that sees it
    stopped: the forecast is the run within one poll (simulated time; it was the generic
    50 mm/s jaws, 1.2 s forecast for a 0.17 s close)."""
    world = World()
    with Arm("so101", "sim", world=world) as arm:
        for width in (20.0, 60.0, 0.0, 80.0, 45.0):
            plan = arm.plan_grip(width)
            start = world.now()
            arm.run(plan)
            assert abs(plan.seconds - (world.now() - start)) <= 0.005, width
