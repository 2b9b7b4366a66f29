"""The web view's renderer sends a node's pose only when it changed, as viser's own
quaternion (issue 28: following a job under load reached the page at 14.7 states/s; a
frame's CPU is now about two thirds of what it was, see benchmarks/view.py)."""

from __future__ import annotations

import numpy as np
import pytest
import viser
import viser.transforms as vtf

from armkit._primitives import Box
from armkit.viz.web._render import Renderer, quaternion_wxyz


def _rotation(rng: np.random.Generator) -> np.ndarray:
    q, r = np.linalg.qr(rng.normal(size=(3, 3)))
    q = q @ np.diag(np.sign(np.diag(r)))
    return q if np.linalg.det(q) > 0 else -q


def test_the_quaternion_is_viser_s_up_to_sign() -> None:
    rng = np.random.default_rng(28)
    special = [np.eye(3), np.diag([1.0, -1.0, -1.0]), np.diag([-1.0, 1.0, -1.0])]
    special.append(np.diag([-1.0, -1.0, 1.0]))
    for R in special + [_rotation(rng) for _ in range(2000)]:
        ours, theirs = np.array(quaternion_wxyz(R)), vtf.SO3.from_matrix(R).wxyz
        assert np.linalg.norm(ours) == pytest.approx(1.0, abs=1e-12)
        assert min(np.abs(ours - theirs).max(), np.abs(ours + theirs).max()) < 1e-9


def test_an_unchanged_pose_is_not_sent_again() -> None:
    server = viser.ViserServer(host="127.0.0.1", port=0, verbose=False)
    try:
        renderer = Renderer(server.scene)
        T = np.eye(4)
        T[:3, 3] = (0.1, 0.2, 0.3)
        renderer.draw_one(Box("/b", np.array([0.01, 0.02, 0.03]), T, (1, 2, 3)))
        handle = renderer._nodes["/b"].handle
        sets: list[str] = []
        original = type(handle).__setattr__

        def spy(self: object, name: str, value: object) -> None:
            sets.append(name)
            original(self, name, value)

        type(handle).__setattr__ = spy  # type: ignore[method-assign,assignment]
        try:
            renderer.draw_one(Box("/b", np.array([0.01, 0.02, 0.03]), T.copy(), (1, 2, 3)))
            assert "position" not in sets and "wxyz" not in sets
            moved = T.copy()
            moved[:3, :3] = vtf.SO3.from_z_radians(0.3).as_matrix()
            renderer.draw_one(Box("/b", np.array([0.01, 0.02, 0.03]), moved, (1, 2, 3)))
            assert "position" in sets and "wxyz" in sets
            np.testing.assert_allclose(handle.wxyz, vtf.SO3.from_z_radians(0.3).wxyz, atol=1e-12)
        finally:
            type(handle).__setattr__ = original  # type: ignore[method-assign]
    finally:
        server.stop()
