"""Family recognition is invariant to where the chain's root frame sits: ROBOTIS's own
OpenManipulator-X URDF (its base axis 12 mm from the root, issue 27) gets the closed form.

The URDF below carries the joint origins, axes and limits of ROBOTIS's
open_manipulator_x.urdf (open_manipulator_description, Apache-2.0), without meshes
and inertials; the gripper's prismatic joint branches off link5 as there.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from armkit import fk, ik, ik_batch, load_model, pitch_of
from armkit.cli import main
from armkit.kinematics import why_no_closed_form


def _joint(name: str, parent: str, child: str, xyz: str, axis: str, lo: float, hi: float) -> str:
    return (
        f'<joint name="{name}" type="revolute"><parent link="{parent}"/><child link="{child}"/>'
        f'<origin rpy="0 0 0" xyz="{xyz}"/><axis xyz="{axis}"/>'
        f'<limit effort="1" lower="{lo}" upper="{hi}" velocity="4.8"/></joint><link name="{child}"/>'
    )


def robotis_urdf(root_xyz: str = "0 0 0", root_rpy: str = "0 0 0") -> str:
    """ROBOTIS's OpenManipulator-X chain; ``root_*``: a fixed joint before it."""
    return (
        '<?xml version="1.0"?><robot name="open_manipulator_x"><link name="world"/>'
        f'<joint name="world_fixed" type="fixed"><origin rpy="{root_rpy}" xyz="{root_xyz}"/>'
        '<parent link="world"/><child link="link1"/></joint><link name="link1"/>'
        + _joint("joint1", "link1", "link2", "0.012 0.0 0.017", "0 0 1", -math.pi, math.pi)
        + _joint("joint2", "link2", "link3", "0.0 0.0 0.0595", "0 1 0", -1.5, 1.5)
        + _joint("joint3", "link3", "link4", "0.024 0 0.128", "0 1 0", -1.5, 1.4)
        + _joint("joint4", "link4", "link5", "0.124 0.0 0.0", "0 1 0", -1.7, 1.97)
        + '<joint name="gripper_left_joint" type="prismatic"><parent link="link5"/>'
        '<child link="gripper_left_link"/><origin rpy="0 0 0" xyz="0.0817 0.021 0.0"/>'
        '<axis xyz="0 1 0"/><limit effort="1" lower="-0.011" upper="0.02" velocity="4.8"/>'
        '</joint><link name="gripper_left_link"/>'
        '<joint name="end_effector_joint" type="fixed"><parent link="link5"/>'
        '<child link="end_effector_link"/><origin rpy="0 0 0" xyz="0.126 0.0 0.0"/></joint>'
        '<link name="end_effector_link"/></robot>'
    )


ROOTS = [("0 0 0", "0 0 0"), ("0.3 -0.2 0.05", "0 0 0.7"), ("0 0 0", "3.141592653589793 0 0")]


@pytest.mark.parametrize(("xyz", "rpy"), ROOTS)
def test_robotis_urdf_solves_every_reachable_target_by_the_closed_form(
    xyz: str, rpy: str, tmp_path: Path
) -> None:
    path = tmp_path / "omx.urdf"
    path.write_text(robotis_urdf(xyz, rpy))
    m = load_model(f"{path}#end_effector_link")
    assert why_no_closed_form(m) == ""
    q = np.random.default_rng(27).uniform(m.lower, m.upper, (1000, m.dof))
    T = fk(m, q)
    P, pitch = T[:, :3, 3], pitch_of(T)
    for i in range(1000):  # every target, position + pitch, one call each
        res = ik(m, tuple(P[i].tolist()), float(pitch[i]))
        got = fk(m, res.q)
        assert res.method == "analytic" and m.within_limits(res.q)
        assert np.abs(got[:3, 3] - P[i]).max() < 1e-9
        assert abs(math.remainder(float(pitch_of(got)) - pitch[i], 2 * math.pi)) < 1e-9
    for given in (pitch, None):  # the batch, and position only (the pitch chosen)
        out = ik_batch(m, P, given)
        assert out.ok.all() and out.method == "analytic"
        assert np.abs(fk(m, out.q)[:, :3, 3] - P).max() < 1e-9
    for i in range(0, 1000, 10):
        assert np.abs(fk(m, ik(m, tuple(P[i].tolist())).q)[:3, 3] - P[i]).max() < 1e-9


def test_the_cli_reports_the_closed_form_for_robotis_urdf(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    path = tmp_path / "omx.urdf"
    path.write_text(robotis_urdf())
    assert main(["--arm", str(path), "show"]) == 0
    assert "inverse kinematics: closed form" in capsys.readouterr().out


def test_a_tilted_root_is_solved_numerically_and_says_why(tmp_path: Path) -> None:
    """A base axis that is not vertical has no pitch plane: the numeric solver, a reason."""
    path = tmp_path / "omx.urdf"
    path.write_text(robotis_urdf("0.1 0 0", "0.4 0 0"))
    m = load_model(f"{path}#end_effector_link")
    assert "base yaw" in why_no_closed_form(m)
    target = fk(m, np.array([0.3, 0.2, 0.4, -0.5]))[:3, 3]
    res = ik(m, tuple(target.tolist()))
    assert res.method == "lm" and np.abs(fk(m, res.q)[:3, 3] - target).max() < 1e-5
