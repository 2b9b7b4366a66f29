"""The 3D view shows the physics (issue 32 item 4): cubes as MuJoCo has them, and with
``--contacts`` where MuJoCo's bodies touch (orange dots)."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

pytest.importorskip("mujoco")
pytest.importorskip("viser")

from armkit import Arm, tasks
from armkit.cli._app import build_parser
from armkit.scene import load_scene
from armkit.viz import WorldSource
from armkit.viz.web import View


def test_the_view_draws_mujoco_s_contacts_on_request(closes: object) -> None:
    scene = replace(load_scene("board_001"), physics="mujoco")
    arm = closes(Arm("openmanipulator_x"))  # type: ignore[operator]
    physics = tasks.attach_scene(arm, scene)
    arm.world.advance(0.2)
    assert WorldSource(arm.world, physics=physics).state().contacts is None  # not asked for
    source = WorldSource(arm.world, physics=physics, contacts=True)
    points = source.state().contacts
    assert points is not None and points.shape[1] == 3
    assert len(points) >= 12  # three cubes standing on their holders' floors, 4+ each
    assert np.allclose(points[:, 2], 0.003, atol=0.5e-3)  # on the floors, 3 mm up [m]
    with View(source, scene=scene, port=0) as view:
        assert view.update()
        drawn = [n for n in view.renderer.names if n.startswith("/contacts/")]
        assert len(drawn) == len(points)


def test_contacts_is_an_option_of_view_and_of_every_watched_job() -> None:
    parser = build_parser()
    assert parser.parse_args(["view", "--contacts"]).contacts
    args = parser.parse_args(["stack", "red", "green", "--view", "--contacts"])
    assert args.contacts and args.view
