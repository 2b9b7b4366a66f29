"""The 001 board task on the real simulator: the OpenManipulator-X's own driver on its
simulated XM430s, the scene's physics attached to the arm's World as an observer.
Every cube ends within 1 mm and 1 deg of where the plan expects it, grasped and put
down five times without a miss, a drop or a tip (tests/tasks/test_tasks_world.py does
the same on a fake World of the contract)."""

from __future__ import annotations

import math

from armkit import Arm, tasks
from armkit.scene import load_scene
from armkit.scene._physics import ScenePhysics
from armkit.sim import World
from armkit.tasks._plan import pose_error


def test_the_001_board_task_on_the_simulated_servos() -> None:
    scene = load_scene("board_001")
    world = World()
    with Arm("openmanipulator_x", "sim", world=world) as arm:
        physics = ScenePhysics(scene)
        detach = world.attach(physics)
        plan = tasks.stack(arm, scene, ["green", "red", "blue"], dry_run=True)
        tasks.run_plan(arm, plan)
        detach()
    for cube in plan.after.cubes:
        distance, turn = pose_error(physics.cube(cube.name), cube)
        assert distance < 1e-3 and turn < math.radians(1.0), cube.name
    assert [e.kind for e in physics.events] == ["grasped", "placed"] * 5
