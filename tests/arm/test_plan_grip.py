"""``plan_grip`` as the arm carries the command out: a timed gripper (the OWI's) is timed
by what its driver knows, not by the jaws' true opening; a held cube the jaws let go is
in the plan's end scene where it comes to rest (as the simulator's physics drops it)."""

from __future__ import annotations

import warnings

import numpy as np
import pytest

from armkit import Arm
from armkit.arm import Start, plan_grip
from armkit.kinematics import fk
from armkit.model import load_model
from armkit.scene import load_scene
from armkit.tasks import pick


def test_a_timed_gripper_is_timed_as_its_driver_runs_it() -> None:
    # the simulated OWI's jaws start closed, but its driver does not know it and runs
    # the gripper: the plan said 0 s, the run took the gripper's whole period
    with warnings.catch_warnings(), Arm("owi535", "sim") as arm:
        warnings.simplefilter("ignore")
        plan = plan_grip(arm.start(), 0.0)
        t0 = arm.clock.now()
        arm.run(plan)
        took = arm.clock.now() - t0
        assert plan.seconds > 1.0 and plan.seconds == pytest.approx(took, rel=0.01)
        again = plan_grip(arm.start(), 0.0)  # now it knows: nothing to run
        assert again.seconds == 0.0


def test_a_cube_let_go_is_where_it_comes_to_rest() -> None:
    model, scene = load_model("openmanipulator_x"), load_scene("board_001")
    picked = pick(Start(model, model.home, scene=scene), scene, "red")
    held = picked.end.held
    assert held is not None and "red" not in picked.end.scene.names()  # held: left out
    let_go = plan_grip(picked.end, model.gripper.width_max)
    assert let_go.end.held is None
    red = let_go.end.scene.cube("red")
    tool = fk(picked.end.kin, picked.end.q)
    below = (scene.T_world_base @ tool @ held.T_tool_object)[:3, 3]
    assert red.position[:2] == pytest.approx(below[:2], abs=1e-9)  # straight down
    assert red.position[2] == pytest.approx(scene.cube("red").position[2], abs=1e-9)
    closed = plan_grip(picked.end, model.gripper.width_min)  # holds it still
    assert closed.end.held is held and np.array_equal(
        [c.name for c in closed.end.scene.cubes], [c.name for c in picked.end.scene.cubes]
    )
