"""The arm as primitives: the clearance capsules, the jaws, the capsule mesh."""

from __future__ import annotations

import numpy as np
import pytest

import armkit
from armkit.viz import Box, Capsule, arm_primitives, link_capsules, pose, table_primitive
from armkit.viz._primitives import capsule_mesh, segment_frame

ARMS = ["openmanipulator_x", "owi535", "lynx6", "al5d", "puma560", "planar2"]


def _random_q(model: armkit.ArmModel, rng: np.random.Generator) -> np.ndarray:
    return rng.uniform(model.lower, model.upper)


@pytest.mark.parametrize("name", ARMS)
def test_link_capsules_join_consecutive_frame_origins(name: str) -> None:
    model = armkit.load_model(name)
    rng = np.random.default_rng(14)
    for _ in range(20):
        q = _random_q(model, rng)
        origins = armkit.fk_frames(model, q)[:, :3, 3]
        caps = link_capsules(model, q)
        assert caps.p0.shape == caps.p1.shape == (model.dof + 1, 3)
        np.testing.assert_allclose(caps.p0, origins[:-1])
        np.testing.assert_allclose(caps.p1, origins[1:])
        np.testing.assert_allclose(caps.radii, model.link_radii)


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


def test_table_top_is_the_models_table_plane() -> None:
    model = armkit.load_model("openmanipulator_x")
    table = table_primitive(model)
    assert table.T[2, 3] + table.size[2] / 2 == pytest.approx(model.table_z)


def test_pose_rejects_bad_positions() -> None:
    with pytest.raises(ValueError, match="position"):
        pose((0.0, float("nan"), 0.0))
