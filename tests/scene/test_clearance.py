"""Capsules, distances and the clearance check; every arm refuses the table."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from armkit import Arm, UnreachableError, fk_frames, ik, load_model
from armkit.cli import main
from armkit.scene import Held, arm_capsules, check_clear, joint_sweep, link_names, load_scene
from armkit.scene._distance import (
    box_box_gap,
    box_signed_distance,
    segment_box_distance,
    segment_segment_distance,
)
from armkit.scene._rotations import rot_axis
from budget import cases

ARMS = ["openmanipulator_x", "lynx6", "owi535", "al5d", "puma560"]


@pytest.mark.parametrize("name", ARMS)
def test_capsules_join_the_frames_one_pose_or_many(name: str) -> None:
    model = load_model(name)
    rng = np.random.default_rng(7)
    q = rng.uniform(model.lower, model.upper, (40, model.dof))
    many = arm_capsules(model, q)
    assert many.p0.shape == (40, model.dof + 1, 3) and many.radii.shape == (model.dof + 1,)
    for k in (0, 17, 39):
        origins = fk_frames(model, q[k])[:, :3, 3]
        one = arm_capsules(model, q[k])
        assert one.p0 == pytest.approx(origins[:-1], abs=1e-12)
        assert one.p1 == pytest.approx(origins[1:], abs=1e-12)
        assert many.p1[k] == pytest.approx(origins[1:], abs=1e-12)
    assert len(link_names(model)) == model.dof + 1


def test_segment_box_distance_against_sampling() -> None:
    rng = np.random.default_rng(3)
    a, b = rng.uniform(-0.2, 0.2, (300, 3)), rng.uniform(-0.2, 0.2, (300, 3))
    half = rng.uniform(0.01, 0.08, (300, 3))
    t = np.linspace(0.0, 1.0, 4001)[:, None]
    brute = [box_signed_distance(a[i] + t * (b[i] - a[i]), half[i]).min() for i in range(300)]
    assert segment_box_distance(a, b, half) == pytest.approx(np.array(brute), abs=1e-4)


def test_segment_segment_distance_against_sampling() -> None:
    """Random segments, points (zero length), parallel and collinear pairs: the closed form
    is never above the sampled minimum and within the sampling's resolution of it."""
    rng = np.random.default_rng(5)
    P = rng.uniform(-0.2, 0.2, (200 + cases(full=200, quick=50), 4, 3))  # 200: the cases below
    P[:40, 1] = P[:40, 0]  # p a point
    P[40:80, 3] = P[40:80, 2]  # q a point
    P[80:100, 1], P[80:100, 3] = P[80:100, 0], P[80:100, 2]  # both points
    P[100:160, 3] = P[100:160, 2] + 1.5 * (P[100:160, 1] - P[100:160, 0])  # parallel
    P[160:200, 2:] = P[160:200, :2] + P[160:200, 1:2] - P[160:200, :1]  # collinear, touching
    d = segment_segment_distance(P[:, 0], P[:, 1], P[:, 2], P[:, 3])
    t = np.linspace(0.0, 1.0, 801)[:, None]
    for i, (p0, p1, q0, q1) in enumerate(P):
        a, b = p0 + t * (p1 - p0), q0 + t * (q1 - q0)
        brute = np.linalg.norm(a[:, None] - b[None], axis=-1).min()
        assert brute - 4e-4 <= d[i] <= brute + 1e-12, i
    assert d[160:200] == pytest.approx(0.0, abs=1e-12)


def test_box_gap_never_misses_an_overlap() -> None:
    rng = np.random.default_rng(4)
    n = 300
    R1 = np.stack([rot_axis(rng.normal(size=3), rng.uniform(0, 3)) for _ in range(n)])
    R2 = np.stack([rot_axis(rng.normal(size=3), rng.uniform(0, 3)) for _ in range(n)])
    c1, c2 = rng.uniform(-0.08, 0.08, (n, 3)), rng.uniform(-0.08, 0.08, (n, 3))
    h1, h2 = rng.uniform(0.01, 0.04, (n, 3)), rng.uniform(0.01, 0.04, (n, 3))
    gap = box_box_gap(c1, R1, h1, c2, R2, h2)
    u = rng.uniform(-1, 1, (3000, 3))
    for i in range(n):
        inside = np.all(np.abs((c2[i] + (u * h2[i]) @ R2[i].T - c1[i]) @ R1[i]) <= h1[i], axis=1)
        assert not (inside.any() and gap[i] > 0)
    assert (gap < 0).sum() > 20


def test_table_below_a_pose_is_named() -> None:
    omx = load_model("openmanipulator_x")
    assert check_clear(omx, omx.home) is None
    hit = check_clear(omx, ik(omx, (0.2, 0.0, -0.05), -math.pi / 2).q)
    assert hit is not None and (hit.link, hit.object) == ("gripper", "table")
    assert hit.distance == pytest.approx(-0.05, abs=1e-3)
    assert "50.0 mm into the table" in hit.describe()
    # the gripper narrows to its tool point: that point may touch the table
    assert check_clear(omx, ik(omx, (0.2, 0.0, 0.0), -math.pi / 2).q) is None
    # a level gripper is thick: its wrist keeps its radius
    level = check_clear(omx, ik(omx, (0.25, 0.0, 0.005), 0.0).q)
    assert level is not None and level.object == "table"


def test_base_column_stands_on_the_table() -> None:
    omx = load_model("openmanipulator_x")
    assert arm_capsules(omx, omx.home).p0[0, 2] - omx.link_radii[0] < 0  # base column's cap
    assert check_clear(omx, omx.home) is None


def test_scene_objects_links_and_the_gripper_exception() -> None:
    omx, scene = load_model("openmanipulator_x"), load_scene("board_001")
    grasp = ik(omx, (0.22, 0.0, 0.0155), -math.pi / 2).q  # jaws round green
    hit = check_clear(omx, grasp, scene)
    assert hit is not None and (hit.link, hit.object) == ("gripper", "green")
    assert check_clear(omx, grasp, scene, ignore=frozenset({"green"})) is None
    low = ik(omx, (0.25, 0.0, 0.016), 0.0)  # level, low over the board
    hit = check_clear(omx, low.q, scene, ignore=frozenset({"green"}))
    assert hit is not None and hit.object == "board"


def test_held_cube_moves_with_the_gripper() -> None:
    omx, scene = load_model("openmanipulator_x"), load_scene("board_001")
    cube = scene.cube("green")
    empty = scene.without_cube("green")
    held = Held(cube, np.eye(4))  # its centre at the tool point
    above = ik(omx, (0.22, 0.0, 0.06), -math.pi / 2).q
    assert check_clear(omx, above, empty, held) is None
    on_board = ik(omx, (0.22, -0.0225, 0.015), -math.pi / 2).q  # over a wall between sockets
    hit = check_clear(omx, on_board, empty, held)
    assert hit is not None and (hit.link, hit.object) == ("held green", "board")


def test_joint_sweep() -> None:
    q0, q1 = np.zeros(4), np.radians([10.0, -3.0, 0.0, 2.0])
    sweep = joint_sweep(q0, q1)
    assert sweep.shape == (10, 4) and sweep[-1] == pytest.approx(q1)
    assert np.max(np.abs(np.diff(np.vstack([q0, sweep]), axis=0))) <= math.radians(1.0) + 1e-12
    assert joint_sweep(q0, np.vstack([q1, q0])).shape == (20, 4)


@pytest.mark.parametrize(
    ("arm", "args"), [("openmanipulator_x", ["200", "0", "-50"]), ("lynx6", ["150", "0", "-20"])]
)
def test_every_arm_refuses_the_table_and_stays(
    arm: str, args: list[str], tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    state = tmp_path / "state.json"
    assert main(["--arm", arm, "--port", str(state), "where"]) == 0
    before = capsys.readouterr().out
    assert main(["--arm", arm, "--port", str(state), "move", *args, "--pitch", "-90"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "move refused" in err[0] and "into the table" in err[0]
    assert main(["--arm", arm, "--port", str(state), "where"]) == 0
    assert capsys.readouterr().out == before


@pytest.mark.parametrize("args", [["0", "0", "5"], ["20", "0", "30", "--pitch", "-90"]])
def test_a_move_folding_into_the_base_is_refused_and_nothing_moves(
    args: list[str], tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """'armkit move 0 0 5' with no scene put the OpenManipulator-X's gripper inside its base
    column (the other arms' joint limits keep them out of it)."""
    state = tmp_path / "state.json"
    assert main(["--port", str(state), "where"]) == 0
    before = capsys.readouterr().out
    assert main(["--port", str(state), "move", *args]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "gripper would be" in err[0] and "into the base column" in err[0]
    assert "further from the base" in err[0]
    assert main(["--port", str(state), "where"]) == 0
    assert capsys.readouterr().out == before


def test_a_tool_point_inside_the_base_column_is_a_collision() -> None:
    """Random OpenManipulator-X poses (inside the limits, every joint above the table) whose
    tool point lies inside the base column collide with it (the other arms' limits keep
    the tool point out of theirs)."""
    name = "openmanipulator_x"
    model = load_model(name)
    q = np.random.default_rng(11).uniform(model.lower, model.upper, (20000, model.dof))
    frames = fk_frames(model, q)
    tip, top = frames[:, -1, :3, 3], frames[0, 1, 2, 3]
    inside = (np.hypot(tip[:, 0], tip[:, 1]) < 0.015) & (tip[:, 2] > 0.03) & (tip[:, 2] < top)
    inside &= frames[:, 1:, 2, 3].min(axis=1) > 0.03  # every link clear of the table
    assert inside.sum() >= 3
    for k in np.flatnonzero(inside):
        hit = check_clear(model, q[k])
        assert hit is not None and hit.object == "base column", (name, q[k], hit)


def test_the_links_on_top_of_the_column_do_not_count_as_folding_into_it() -> None:
    """At home and over a spread of ordinary poses no arm touches its own base column."""
    for name in ARMS:
        model = load_model(name)
        assert check_clear(model, model.home) is None, name


def test_arm_refuses_a_path_through_the_table_before_moving() -> None:
    with Arm("openmanipulator_x", "sim") as arm:
        before = arm.angles()
        with pytest.raises(UnreachableError, match="table") as info:
            arm.follow(np.linspace([200, 0, 50], [200, 0, -30], 41), pitch=-90)
        assert info.value.reason == "table"
        assert arm.angles() == before
        with pytest.raises(UnreachableError, match="into the board"):
            Arm("openmanipulator_x", arm.driver, scene=load_scene("board_001")).move_to(
                220, -22, 5, -90
            )
