"""Tasks carried out on a fake World of the contract with the scene's physics
attached: every cube ends within 1 mm (and 1 deg) of where the plan expects it,
grasped and put down without a miss, a drop or a tip."""

from __future__ import annotations

import math
from collections.abc import Callable
from pathlib import Path

import numpy as np
import pytest
from scene_fakes import FakeDriver, FakeWorld

from armkit import Arm, ArmkitError, load_model, tasks
from armkit.scene import Scene, load_scene
from armkit.scene._load import build_scene
from armkit.scene._physics import ScenePhysics
from armkit.tasks import Plan, TaskError
from armkit.tasks._plan import pose_error

OMX = load_model("openmanipulator_x")


def _run(scene: Scene, task: Callable[[Arm, Scene], Plan]) -> tuple[Plan, ScenePhysics, FakeDriver]:
    world = FakeWorld(OMX, OMX.home)
    physics = ScenePhysics(scene)
    world.attach(physics)
    world.step()
    driver = FakeDriver(world)
    plan = task(Arm(OMX, driver), scene)
    return plan, physics, driver


def _assert_as_planned(plan: Plan, physics: ScenePhysics) -> None:
    for cube in plan.after.cubes:
        distance, turn = pose_error(physics.cube(cube.name), cube)
        assert distance < 1e-3 and turn < math.radians(1.0), cube.name
    kinds = {e.kind for e in physics.events}
    assert kinds <= {"grasped", "placed"}, [e.detail for e in physics.events]


def test_rotate_forward_and_backward() -> None:
    scene = load_scene("board_001")
    plan, physics, _ = _run(scene, lambda a, s: tasks.rotate_cube(a, s, "green", "forward"))
    _assert_as_planned(plan, physics)
    assert physics.cube("green").up_face == "-x"
    plan, physics, _ = _run(scene, lambda a, s: tasks.rotate_cube(a, s, "red", "backward"))
    _assert_as_planned(plan, physics)
    assert physics.cube("red").up_face == "+x"
    assert [e.kind for e in physics.events] == ["grasped", "placed"]


def test_the_001_board_task_rotate_and_stack_three_cubes() -> None:
    scene = load_scene("board_001")
    plan, physics, _ = _run(scene, lambda a, s: tasks.stack(a, s, ["green", "red", "blue"]))
    _assert_as_planned(plan, physics)
    assert [e.kind for e in physics.events] == ["grasped", "placed"] * 5
    z = [physics.cube(n).position[2] * 1000 for n in ("green", "red", "blue")]
    assert z == pytest.approx([3.0, 28.0, 53.0], abs=1.0)
    assert "on red" in physics.events[-1].detail


def test_move_item_between_places_and_into_a_container() -> None:
    text = """name = "t"
[[cubes]]
name = "a"
size_mm = 25.0
position_mm = [200.0, -60.0, 0.0]
[[places]]
name = "B"
position_mm = [190.0, 70.0, 0.0]
[[containers]]
name = "bin"
position_mm = [150.0, 150.0, 0.0]
size_mm = [60.0, 60.0, 30.0]
wall_mm = 3.0
"""
    import tomllib

    scene = build_scene(tomllib.loads(text), Path("t.toml"))
    plan, physics, _ = _run(scene, lambda a, s: tasks.move_item(a, s, "a", "B"))
    _assert_as_planned(plan, physics)
    assert physics.cube("a").position * 1000 == pytest.approx([190.0, 70.0, 0.0], abs=1.0)
    plan, physics, _ = _run(scene, lambda a, s: tasks.move_item(a, s, "a", "bin"))
    _assert_as_planned(plan, physics)
    assert "on bin" in physics.events[-1].detail


def test_pick_then_place_as_two_tasks() -> None:
    scene = load_scene("board_001")
    world = FakeWorld(OMX, OMX.home)
    physics = ScenePhysics(scene)
    world.attach(physics)
    arm = Arm(OMX, FakeDriver(world))
    picked = tasks.pick(arm, scene, "blue", pitch=0.0)  # from the side: it goes on red upright
    assert physics.holding is not None
    held = physics.cube("blue")
    assert pose_error(held, picked.after.cube("blue"))[0] < 1e-3
    placed = tasks.place(arm, scene, "blue", "red")
    _assert_as_planned(placed, physics)
    assert physics.cube("blue").position * 1000 == pytest.approx([220.0, 45.0, 28.0], abs=1.0)


def test_a_refused_task_moves_nothing_in_the_world() -> None:
    scene = load_scene("board_001")
    world = FakeWorld(OMX, OMX.home)
    driver = FakeDriver(world)
    with pytest.raises(TaskError):
        tasks.move_item(Arm(OMX, driver), scene, "red", (400.0, 0.0, 0.0))
    assert driver.commands == 0 and np.allclose(world.sim.q(), OMX.home)


def test_the_plan_refuses_to_run_from_elsewhere() -> None:
    scene = load_scene("board_001")
    world = FakeWorld(OMX, OMX.home)
    driver = FakeDriver(world)
    arm = Arm(OMX, driver)
    plan = tasks.pick(arm, scene, "green", dry_run=True)
    arm.move_joints({"waist": 10.0})
    moved = driver.commands
    with pytest.raises(ArmkitError, match=r"moved 10\.0 deg since the plan 'pick green' was made"):
        tasks.run_plan(arm, plan)
    assert driver.commands == moved
