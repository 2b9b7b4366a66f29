"""Task plans: the expected steps, 001's pitch choice, calibration offsets, and
refusals that name the step before anything moves."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from scene_fakes import FakeDriver, FakeWorld

from armkit import Arm, InputError, ik, load_model, tasks
from armkit.scene import load_scene
from armkit.scene._load import build_scene
from armkit.tasks import Calibration, CalibrationError, TaskError, load_calibration

OMX = load_model("openmanipulator_x")


def _arm() -> tuple[Arm, FakeDriver]:
    driver = FakeDriver(FakeWorld(OMX, OMX.home))
    return Arm(OMX, driver), driver


def _table_scene(*cubes: tuple[str, float, float], extra: str = "") -> object:
    text = 'name = "t"\n' + "".join(
        f'[[cubes]]\nname = "{n}"\nsize_mm = 25.0\nposition_mm = [{x}, {y}, 0.0]\n'
        for n, x, y in cubes
    )
    import tomllib

    return build_scene(tomllib.loads(text + extra), Path("t.toml"))


def test_pick_is_001s_approach_close_and_leave() -> None:
    arm, driver = _arm()
    plan = tasks.pick(arm, load_scene("board_001"), "green", dry_run=True)
    labels = [s.label for s in plan.steps]
    assert labels == [
        "open to 45 mm",
        "pick green from the top: above",
        "pick green from the top: down 1/3",
        "pick green from the top: down 2/3",
        "pick green from the top: down 3/3",
        "close on green",
        "pick green from the top: up 1/3",
        "pick green from the top: up 2/3",
        "pick green from the top: up 3/3",
    ]
    z = [s.point[2] * 1000 for s in plan.steps if s.point is not None]
    assert z == pytest.approx([45.5, 35.5, 25.5, 15.5, 25.5, 35.5, 45.5])  # 30 mm, 3 waypoints
    assert all(s.pitch == pytest.approx(-math.pi / 2) for s in plan.steps if s.pitch is not None)
    assert [s.grip for s in plan.steps if s.grip is not None] == pytest.approx([0.045, 0.020])
    assert plan.after.cube("green").position[2] * 1000 == pytest.approx(3.0 + 30.0)  # held, up
    assert driver.commands == 0  # a dry run moves nothing
    assert "pick green (openmanipulator_x, scene board_001): 9 steps, 7 moves" in str(plan)


def test_clearance_is_a_parameter() -> None:
    arm, _ = _arm()
    plan = tasks.pick(arm, load_scene("board_001"), "green", clearance=45, dry_run=True)
    z = [s.point[2] * 1000 for s in plan.steps if s.point is not None]
    assert z[:4] == pytest.approx([60.5, 45.5, 30.5, 15.5])
    with pytest.raises(ValueError, match="at least 30"):
        tasks.pick(arm, load_scene("board_001"), "green", clearance=20, dry_run=True)


def test_pitch_from_the_side_where_the_top_is_out_of_reach() -> None:
    arm, _ = _arm()
    near = tasks.pick(arm, _table_scene(("near", 200.0, 0.0)), "near", dry_run=True)
    assert near.steps[1].label == "pick near from the top: above"
    far = tasks.pick(arm, _table_scene(("far", 300.0, 0.0)), "far", dry_run=True)
    assert far.steps[1].label == "pick far from the side: above"
    grasp = far.steps[4]
    assert grasp.label.endswith("down 3/3") and grasp.pitch == 0.0
    # shifted up: the wrist's 15 mm radius and 2 mm over the table, not the centre (12.5)
    assert grasp.point * 1000 == pytest.approx([300.0, 0.0, 17.0])


def test_rotations_turn_the_cube_each_way() -> None:
    arm, _ = _arm()
    scene = load_scene("board_001")
    fwd = tasks.rotate_cube(arm, scene, "green", "forward", dry_run=True)
    back = tasks.rotate_cube(arm, scene, "green", "backward", dry_run=True)
    pitches = [math.degrees(s.pitch) for s in fwd.steps if s.label.endswith("down 3/3")]
    assert pitches == pytest.approx(
        [0.0, -90.0]
    )  # 001: picked from the side, put down from the top
    assert fwd.after.cube("green").up_face == "-x"  # its top now faces away from the arm
    assert back.after.cube("green").up_face == "+x"
    for plan in (fwd, back):
        assert plan.after.cube("green").position * 1000 == pytest.approx(
            [220.0, 0.0, 3.0], abs=1e-6
        )
    side = next(s for s in fwd.steps if s.label == "pick green from the side: down 3/3")
    assert side.point[2] * 1000 == pytest.approx(8.0 + 15.0 + 2.0)  # clear of the holders


def test_stack_of_one_name_says_it_needs_two_cubes() -> None:
    arm, _ = _arm()
    with pytest.raises(InputError, match=r"two or more different cubes, got \['red'\]"):
        tasks.stack(arm, load_scene("board_001"), "red", dry_run=True)  # not its letters


def test_stack_rotates_all_then_stacks_one_cube_higher_each() -> None:
    arm, _ = _arm()
    plan = tasks.stack(arm, load_scene("board_001"), ["green", "red", "blue"], dry_run=True)
    closes = [s.label for s in plan.steps if s.label.startswith("close on")]
    assert closes == [
        "close on green",
        "close on red",
        "close on blue",
        "close on red",
        "close on blue",
    ]
    z = [plan.after.cube(n).position[2] * 1000 for n in ("green", "red", "blue")]
    assert z == pytest.approx([3.0, 28.0, 53.0], abs=1e-6)
    for name in ("red", "blue"):
        assert plan.after.cube(name).position[:2] * 1000 == pytest.approx([220.0, 0.0], abs=1e-6)


def test_unreachable_step_is_named_and_nothing_moves() -> None:
    arm, driver = _arm()
    scene = _table_scene(("far", 500.0, 0.0))
    with pytest.raises(TaskError, match=r"^pick far: cannot pick far from the top: too far from the arm \(500 mm out, 42 mm up\); move it nearer the arm$") as info:  # fmt: skip
        tasks.pick(arm, scene, "far")
    assert info.value.step == "pick far from the top: above"
    assert driver.commands == 0


def test_colliding_step_names_step_link_and_object() -> None:
    arm, driver = _arm()
    box = '[[containers]]\nname = "box"\nposition_mm = [190.0, 0.0, 0.0]\nsize_mm = [40.0, 40.0, 40.0]\nwall_mm = 3.0\n'
    scene = _table_scene(("behind", 260.0, 0.0), extra=box)  # the box is between arm and cube
    with pytest.raises(TaskError) as info:
        tasks.pick(arm, scene, "behind", pitch=0)
    err = info.value
    assert err.step.startswith("pick behind from the side") and err.object == "box"
    assert err.link == "gripper"
    assert "the gripper would be" in str(err) and "into the box" in str(err)
    assert driver.commands == 0


def test_too_high_to_hold_from_the_side() -> None:
    arm, _ = _arm()
    box = '[[containers]]\nname = "box"\nposition_mm = [260.0, 0.0, 0.0]\nsize_mm = [40.0, 40.0, 60.0]\nwall_mm = 3.0\n'
    scene = _table_scene(("inside", 260.0, 0.0), extra=box)
    with pytest.raises(TaskError, match=r"must stay 77\.0 mm high to clear the box rim"):
        tasks.pick(arm, scene, "inside", pitch=0)


def test_place_and_targets() -> None:
    arm, _ = _arm()
    scene = _table_scene(
        ("a", 200.0, 0.0), extra='[[places]]\nname = "B"\nposition_mm = [200.0, 80.0, 0.0]\n'
    )
    plan = tasks.place(arm, scene, "a", "B", dry_run=True)
    assert plan.steps[-4].label == "release a"
    assert plan.after.cube("a").position * 1000 == pytest.approx([200.0, 80.0, 0.0], abs=1e-6)
    plan = tasks.place(arm, scene, "a", (180.0, -60.0, 0.0), dry_run=True)
    assert plan.after.cube("a").position * 1000 == pytest.approx([180.0, -60.0, 0.0], abs=1e-6)
    with pytest.raises(ValueError, match=r"no place, cube or container 'C'.*it has: a, B"):
        tasks.place(arm, scene, "a", "C", dry_run=True)
    with pytest.raises(TaskError, match="would be dropped"):
        tasks.place(arm, scene, "a", (200.0, 80.0, 30.0), dry_run=True)


def test_move_item_lifts_before_travelling() -> None:
    arm, _ = _arm()
    scene = _table_scene(
        ("a", 200.0, -60.0), extra='[[places]]\nname = "B"\nposition_mm = [200.0, 60.0, 0.0]\n'
    )
    plan = tasks.move_item(arm, scene, "a", "B", lift=50, dry_run=True)
    close = next(k for k, s in enumerate(plan.steps) if s.label == "close on a")
    lifted = plan.steps[close + 3]
    assert lifted.label.endswith("up 3/3") and lifted.point[2] * 1000 == pytest.approx(12.5 + 50.0)
    assert plan.after.cube("a").position * 1000 == pytest.approx([200.0, 60.0, 0.0], abs=1e-6)


def test_calibration_offsets_move_the_commanded_points(tmp_path: Path) -> None:
    arm, _ = _arm()
    scene = load_scene("board_001")
    cal = Calibration(height=2.0, perpendicular=-3.0)  # mm
    plain = tasks.pick(arm, scene, "red", dry_run=True)
    shifted = tasks.pick(arm, scene, "red", calibration=cal, dry_run=True)
    for a, b in zip(plain.steps, shifted.steps, strict=True):
        assert a.label == b.label and (a.point is None or np.allclose(a.point, b.point))
        if a.q is None:
            continue
        radial = a.point[:2] / np.linalg.norm(a.point[:2])
        target = np.array([*(a.point[:2] - 0.003 * radial), a.point[2] + 0.002])
        assert b.q == pytest.approx(ik(OMX, target, a.pitch, a.q).q, abs=1e-9)
    path = tmp_path / "cal.toml"
    path.write_text("height_offset_mm = 2.0\nperpendicular_offset_mm = -3.0\n")
    assert load_calibration(path) == cal
    assert tasks.pick(arm, scene, "red", calibration=path, dry_run=True).steps[
        4
    ].q == pytest.approx(shifted.steps[4].q)
    path.write_text("height_offset_mm = 200.0\n")
    with pytest.raises(CalibrationError, match="field 'height_offset_mm': must be within"):
        load_calibration(path)


def test_tilted_grasp_where_neither_top_nor_side_reaches() -> None:
    lynx = load_model("lynx6")
    arm = Arm(lynx, FakeDriver(FakeWorld(lynx, lynx.home)))
    plan = tasks.move_item(arm, load_scene("search_002"), "object", "bin", dry_run=True)
    grasp = next(s for s in plan.steps if s.label.endswith("down 3/3"))
    assert grasp.label == "pick object at pitch -75: down 3/3"
    moved = plan.after.cube("object")
    assert moved.position * 1000 == pytest.approx([100.0, 175.0, 3.0], abs=1e-6)  # on the floor
    assert moved.up_face == "+z"
