"""Objects in the simulation, on a fake World of the contract: the jaws grasp a
cube between them (and stop at its width), carry it, let it settle; misses are
reported with their offset."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scene_fakes import FakeWorld

from armkit import fk, ik, load_model
from armkit.scene import load_scene
from armkit.scene._physics import ScenePhysics

OMX = load_model("openmanipulator_x")
TOP = -math.pi / 2


def _world() -> tuple[FakeWorld, ScenePhysics]:
    world = FakeWorld(OMX, OMX.home)
    physics = ScenePhysics(load_scene("board_001"))
    world.attach(physics)
    world.step()
    return world, physics


def _to(world: FakeWorld, xyz_mm: tuple[float, float, float], pitch: float = TOP) -> None:
    world.move(ik(OMX, np.array(xyz_mm) / 1000.0, pitch, world.sim.q()).q)


def test_grasp_carry_and_put_back() -> None:
    world, physics = _world()
    world.set_grip(0.045)
    _to(world, (220, 0, 15.5))
    world.set_grip(0.020)
    assert [e.kind for e in physics.events] == ["grasped"]
    assert world.sim.grip() == pytest.approx(0.025)  # the jaws stop at the cube
    assert physics.events[0].offset == pytest.approx([0, 0, 0], abs=1e-9)
    _to(world, (220, 0, 65.5))
    assert physics.cube("green").position * 1000 == pytest.approx([220, 0, 53], abs=1e-6)
    _to(world, (220, 0, 15.5))
    world.set_grip(0.045)
    assert [e.kind for e in physics.events] == ["grasped", "placed"]
    assert "on board[0, 1]" in physics.events[-1].detail
    assert physics.cube("green").position * 1000 == pytest.approx([220, 0, 3], abs=1e-6)
    assert physics.holding is None and world.sim.grip() == pytest.approx(0.045)


def test_released_high_it_drops_released_turned_it_tips() -> None:
    world, physics = _world()
    world.set_grip(0.045)
    _to(world, (220, 0, 15.5))
    world.set_grip(0.020)
    _to(world, (220, 0, 65.5))
    world.set_grip(0.045)
    assert physics.events[-1].kind == "dropped"
    assert "fell 50.0 mm" in physics.events[-1].detail
    assert physics.cube("green").position * 1000 == pytest.approx([220, 0, 3], abs=1e-6)
    _to(world, (220, 0, 15.5))
    world.set_grip(0.020)
    assert physics.events[-1].kind == "grasped"
    _to(world, (200, 0, 60), pitch=math.radians(-45))
    world.set_grip(0.045)
    assert physics.events[-1].kind == "tipped"


def test_a_miss_is_reported_with_its_offset() -> None:
    world, physics = _world()
    world.set_grip(0.045)
    _to(world, (220, 15, 15.5))  # 15 mm to the side: a jaw lands on the cube
    world.set_grip(0.020)
    event = physics.events[-1]
    assert event.kind == "missed" and event.object == "green"
    # 15 mm off along the jaws; the cube, turned 3.9 deg to them, is 26.7 mm across them
    assert "not between the jaws (by 5.8 mm)" in event.detail
    assert abs(event.offset[2]) == pytest.approx(0.015, abs=1e-4)  # along the jaw axis
    assert world.sim.grip() == pytest.approx(0.020)  # nothing stopped the jaws
    assert physics.cube("green").position * 1000 == pytest.approx([220, 0, 3])


def test_pads_must_cover_the_cube() -> None:
    world, physics = _world()
    world.set_grip(0.045)
    _to(world, (220, 0, 40))  # jaws' pads only 2.5 mm over the cube's top
    world.set_grip(0.020)
    assert physics.events[-1].kind == "missed"
    assert "off it along the approach" in physics.events[-1].detail


def test_jaws_square_up_a_turned_cube() -> None:
    world, physics = _world()
    world.set_grip(0.045)
    _to(world, (220, 45, 15.5))  # red, 11.6 deg off the arm's line
    world.set_grip(0.020)
    assert physics.events[-1].kind == "grasped"
    assert "squared up by 11.6 deg" in physics.events[-1].detail
    T = load_scene("board_001").T_world_base @ fk(OMX, world.sim.q())
    yaw_tool = math.atan2(T[1, 2], T[0, 2])  # the jaw axis, level
    cube = physics.cube("red")
    turn = (cube.yaw - yaw_tool) % (math.pi / 2)
    assert min(turn, math.pi / 2 - turn) == pytest.approx(0.0, abs=1e-9)


def test_nothing_happens_while_the_jaws_stay() -> None:
    world, physics = _world()
    _to(world, (220, 0, 15.5))
    for _ in range(50):
        world.step()
    assert physics.events == []
