"""The arm and the scene as primitives: the clearance capsules, the jaws, the
objects, moved primitives, the capsule mesh, the offscreen renderer."""

from __future__ import annotations

import numpy as np
import pytest

import armkit
from armkit.scene import arm_capsules, load_scene, shipped_scenes
from armkit.viz import (
    Box,
    Capsule,
    arm_primitives,
    moved,
    pose,
    scene_primitives,
    table_primitive,
)
from armkit.viz._arm_shapes import TABLE_DROP
from armkit.viz._meshes import capsule_mesh, segment_frame

ARMS = ["openmanipulator_x", "owi535", "lynx6", "al5d", "puma560", "planar2"]


def _random_q(model: armkit.ArmModel, rng: np.random.Generator) -> np.ndarray:
    return rng.uniform(model.lower, model.upper)


@pytest.mark.parametrize("name", ARMS)
def test_the_links_drawn_are_the_clearance_checks_capsules(name: str) -> None:
    model = armkit.load_model(name)
    rng = np.random.default_rng(14)
    for _ in range(20):
        q = _random_q(model, rng)
        caps = arm_capsules(model, q)
        drawn = [s for s in arm_primitives(model, q) if isinstance(s, Capsule)]
        assert len(drawn) == model.dof + 1
        np.testing.assert_allclose([c.p0 for c in drawn], caps.p0)
        np.testing.assert_allclose([c.p1 for c in drawn], caps.p1)
        np.testing.assert_allclose([c.radius for c in drawn], caps.radii)


def test_arm_primitives_are_the_capsules_then_jaws_then_frames() -> None:
    model = armkit.load_model("openmanipulator_x")
    shapes = arm_primitives(model, model.home, 0.04, frames=True)
    caps = [s for s in shapes if isinstance(s, Capsule)]
    assert [c.name for c in caps] == [f"/arm/link_{i}" for i in range(model.dof + 1)]
    tool = armkit.fk(model, model.home)
    jaws = {s.name: s for s in shapes if isinstance(s, Box)}
    left, right = jaws["/arm/jaw_l"].T[:3, 3], jaws["/arm/jaw_r"].T[:3, 3]
    # jaws face each other across the tool's y axis, 40 mm apart (inner faces)
    gap = float(np.dot(left - right, tool[:3, 1])) - jaws["/arm/jaw_l"].size[1]
    assert gap == pytest.approx(0.04)
    assert sum(1 for s in shapes if s.name.startswith("/arm/frame_")) == model.dof + 2


def test_capsule_mesh_lies_on_the_capsule_surface() -> None:
    vertices, faces = capsule_mesh(0.13, 0.015)
    # distance of each vertex to the segment (0,0,0)-(0,0,0.13) is the radius
    z = np.clip(vertices[:, 2], 0.0, 0.13)
    d = np.linalg.norm(vertices - np.column_stack([np.zeros_like(z), np.zeros_like(z), z]), axis=1)
    np.testing.assert_allclose(d, 0.015, atol=1e-12)
    assert faces.min() == 0 and faces.max() == len(vertices) - 1


def test_segment_frame_points_z_from_p0_to_p1() -> None:
    rng = np.random.default_rng(3)
    for _ in range(50):
        p0, p1 = rng.normal(size=3), rng.normal(size=3)
        T, length = segment_frame(p0, p1)
        assert length == pytest.approx(np.linalg.norm(p1 - p0))
        np.testing.assert_allclose(T[:3, 3] + T[:3, 2] * length, p1, atol=1e-12)
        np.testing.assert_allclose(T[:3, :3] @ T[:3, :3].T, np.eye(3), atol=1e-12)
        assert np.linalg.det(T[:3, :3]) == pytest.approx(1.0)


def test_table_top_is_the_models_table_plane_drawn_just_below_it() -> None:
    model = armkit.load_model("openmanipulator_x")
    table = table_primitive(model)
    assert table.T[2, 3] + table.size[2] / 2 == pytest.approx(model.table_z - TABLE_DROP)
    assert 0.0 < TABLE_DROP <= 0.001  # below what the eye sees, above the depth buffer's step


def test_the_sheet_is_not_drawn_in_the_tables_plane() -> None:
    """The sheet and the table were drawn at the same height in the 3D view: their faces
    flickered through each other (z-fighting) as the view turned (issue 28)."""
    scene = load_scene("drawing")
    model = armkit.load_model("openmanipulator_x")
    table = table_primitive(model, scene)
    (sheet,) = [p for p in scene_primitives(scene) if p.name == "/scene/A5"]
    table_top = table.T[2, 3] + table.size[2] / 2
    sheet_top = sheet.T[2, 3] + sheet.size[2] / 2
    sheet_bottom = sheet.T[2, 3] - sheet.size[2] / 2
    assert sheet_top > table_top + 1e-4 and abs(sheet_bottom - table_top) > 1e-4


def test_pose_rejects_bad_positions() -> None:
    with pytest.raises(ValueError, match="position"):
        pose((0.0, float("nan"), 0.0))


@pytest.mark.parametrize("name", shipped_scenes())
def test_every_object_of_a_shipped_scene_is_drawn(name: str) -> None:
    scene = load_scene(name)
    drawn = {p.name.split("/")[2] for p in scene_primitives(scene)}
    # a pen with no stand (the xylophone's mallet) starts in the gripper: the arm carries it
    held = {pen.name for pen in scene.pens} - {stand.pen for stand in scene.pen_stands}
    assert set(scene.names()) - held <= drawn


def test_a_board_has_a_socket_at_each_socket_floor() -> None:
    scene = load_scene("board_001")
    board = scene.board("board")
    shapes = {p.name: p for p in scene_primitives(scene)}
    socket = shapes["/scene/board_sockets/1_2"]
    assert isinstance(socket, Box)
    np.testing.assert_allclose(socket.T[:2, 3], board.socket(1, 2)[:2])
    assert socket.T[2, 3] > board.socket(1, 2)[2]  # drawn on the board's top, over the hole
    # no primitive is named under another one (a web view would nest it in that one's frame)
    names = set(shapes)
    assert not [n for n in names if any(n.startswith(m + "/") for m in names)]


def test_moved_carries_every_kind_of_primitive() -> None:
    T = pose((0.1, 0.2, 0.3), 0.5)
    model = armkit.load_model("lynx6")
    for prim in arm_primitives(model, model.home, frames=True):
        out = moved(prim, T)
        assert out.name == prim.name
        if isinstance(prim, Capsule) and isinstance(out, Capsule):
            np.testing.assert_allclose(out.p1, T[:3, :3] @ prim.p1 + T[:3, 3])
    shifted = arm_primitives(model, model.home, T_world_base=T)
    plain = arm_primitives(model, model.home)
    assert isinstance(shifted[0], Capsule) and isinstance(plain[0], Capsule)
    np.testing.assert_allclose(shifted[0].p0, T[:3, 3] + T[:3, :3] @ plain[0].p0)


def test_the_offscreen_renderer_paints_the_cubes_in_their_colours() -> None:
    from armkit.viz._raster import look_from_front_right, render

    scene = load_scene("board_001")
    model = armkit.load_model("openmanipulator_x")
    camera = look_from_front_right(np.zeros(3), 0.38, 320, 240)
    image = np.asarray(render([table_primitive(model), *scene_primitives(scene)], camera))
    for cube in scene.cubes:
        (u, v), _ = (a[0] for a in camera.project(cube.center[None, :] + [[0, 0, 0.012]]))
        patch = image[round(v) - 1 : round(v) + 2, round(u) - 1 : round(u) + 2].reshape(-1, 3)
        colour = {"red": 0, "green": 1, "blue": 2}[cube.name]
        assert all(int(np.argmax(p)) == colour for p in patch), (cube.name, patch)
