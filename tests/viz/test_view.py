"""The view and the teach panel on a viser server (no browser: see test_browser.py)."""

from __future__ import annotations

import math
from collections.abc import Iterator

import numpy as np
import pytest

import armkit
from armkit.scene import ScenePhysics, load_scene
from armkit.viz import ArmSource, WorldSource
from armkit.viz.web import Teach, View

BOARD = load_scene("board_001")


@pytest.fixture
def arm() -> Iterator[armkit.Arm]:
    with armkit.Arm("openmanipulator_x") as arm:
        yield arm


@pytest.fixture
def view(arm: armkit.Arm) -> Iterator[View]:
    with View(ArmSource(arm), scene=BOARD, port=0) as view:
        yield view


def test_the_page_is_served_on_loopback_only(view: View) -> None:
    assert view.url.startswith("http://127.0.0.1:")
    import urllib.request

    with urllib.request.urlopen(view.url, timeout=5) as reply:
        assert b"<html" in reply.read(2000).lower()


def test_update_draws_the_arm_and_sends_only_changes(view: View, arm: armkit.Arm) -> None:
    assert view.update()
    names = view.renderer.names
    assert "/table" in names and {"/scene/red", "/scene/green", "/scene/blue"} <= set(names)
    assert "/scene/board" in names and "/scene/board_sockets/2_2" in names
    assert {f"/arm/link_{i}" for i in range(5)} <= set(names)
    assert not view.update()  # nothing moved
    arm.move_joints([30.0, 0.0, 0.0, 0.0])
    assert view.update()
    assert view.state is not None
    assert arm.world is not None  # the view shows the simulated arm's truth
    np.testing.assert_array_equal(view.state.q, arm.world.arm().q())
    np.testing.assert_allclose(view.state.q, arm.driver.read(), atol=math.radians(0.1))
    assert view.stats().updates == 2 and view.stats().reads == 3


def test_the_trail_follows_the_tool(view: View, arm: armkit.Arm) -> None:
    view.update()
    for waist in (10.0, 20.0, 30.0):
        arm.move_joints([waist, 0.0, 0.0, 0.0])
        view.update()
    assert "/trail/0" in view.renderer.names
    view.clear_trail()
    assert not [n for n in view.renderer.names if n.startswith("/trail")]


def test_target_marker_is_green_or_red_with_the_reason(view: View) -> None:
    good = view.set_target((0.2, 0.0, 0.06), -math.pi / 2)
    assert good.ok
    bad = view.set_target((0.2, 0.0, -0.01), -math.pi / 2)
    assert not bad.ok and "table" in bad.reason
    assert view.target is bad


def test_teach_moves_the_arm_and_records_poses(view: View, arm: armkit.Arm) -> None:
    teach = Teach(view, arm, echo=False)
    try:
        assert teach.drag_target((0.2, 0.05, 0.08), -90.0)
        assert teach.mover.wait_idle(30.0)
        np.testing.assert_allclose(
            armkit.fk(arm.model, arm.driver.read())[:3, 3], (0.2, 0.05, 0.08), atol=2e-4
        )
        pose = teach.record("above_b")
        assert pose.position.z == pytest.approx(80.0, abs=0.2)
        assert set(pose.angles) == set(arm.model.joint_names)
        assert teach.poses == {"above_b": pose} and "above_b" in teach.status
        assert not teach.drag_target((0.6, 0.0, 0.05), None)
        assert "out of reach" in teach.status
        with pytest.raises(ValueError, match="pose name"):
            teach.record("no spaces")
    finally:
        teach.close()


def test_a_bad_port_is_refused() -> None:
    arm = armkit.Arm("openmanipulator_x")
    with pytest.raises(ValueError, match="port"):
        View(ArmSource(arm), port=70000)


def test_a_grasped_cube_moves_with_the_gripper_on_the_page() -> None:
    with armkit.Arm("openmanipulator_x") as arm:  # no clearance check: it goes into the cube
        assert arm.world is not None
        physics = ScenePhysics(BOARD)
        arm.world.attach(physics)
        source = WorldSource(arm.world, physics=physics)
        with View(source, scene=BOARD, port=0) as view:
            red = BOARD.cube("red")
            x, y, z = (red.center * 1000).tolist()
            arm.grip(arm.model.gripper.width_max * 1000)
            arm.move_to(x, y, z + 40, -90)
            view.update()
            node = view.renderer._nodes["/scene/red"].handle
            before = np.array(node.position)
            np.testing.assert_allclose(before, red.center, atol=1e-9)
            arm.move_to(x, y, z, -90)
            arm.grip(arm.model.gripper.width_min * 1000)
            assert physics.holding is not None and physics.holding.cube.name == "red"
            arm.move_to(x, y, z + 30, -90)
            assert view.update()
            after = np.array(node.position)
            assert after[2] - before[2] == pytest.approx(0.03, abs=2e-3)
            assert [o.name for o in view.state.objects] == ["green", "blue", "red"]  # type: ignore[union-attr]


def test_what_the_tool_draws_on_paper_is_inked() -> None:
    from armkit.scene import Scene, Sheet

    paper = Sheet("paper", np.array([0.13, -0.05, 0.0]), np.array([1.0, 0.0, 0.0]), np.array([0.0, 1.0, 0.0]), 0.1, 0.1)  # fmt: skip
    scene = Scene("drawing", sheets=(paper,))
    with armkit.Arm("openmanipulator_x") as arm, View(ArmSource(arm), scene=scene, port=0) as view:  # fmt: skip
        arm.move_to(180, -20, 30, -90)
        view.update()
        assert not [n for n in view.renderer.names if n.startswith("/ink/")]  # in the air
        for y in (-20.0, -10.0, 0.0, 10.0):
            arm.move_to(180, y, 0.5, -90)
            view.update()
        arm.move_to(180, 10, 30, -90)
        view.update()
        assert [n for n in view.renderer.names if n.startswith("/ink/")] == ["/ink/paper/1/0"]
        ((sheet, line),) = view.ink.strokes
        assert sheet is paper and len(line.points) >= 4
        np.testing.assert_allclose(
            np.array(line.points)[:, 1], [-0.02, -0.01, 0.0, 0.01], atol=5e-4
        )
