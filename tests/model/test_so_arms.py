"""The SO-101 and SO-100 models against TheRobotStudio's URDFs (github.com/TheRobotStudio/
SO-ARM100, commit fda892c: Simulation/SO101/so101_new_calib.urdf, Simulation/SO100/
so100.urdf): FK equal to yourdfpy's on the URDF's own numbers to 1e-9 m over 1,000 random
joint vectors, armkit's world a fixed transform from the URDF's root link.

The URDF numbers below are a second transcription (kinematic elements only, no meshes),
independent of the model files' (which quote them in comments)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from armkit.kinematics import fk
from armkit.model import load_model

yourdfpy = pytest.importorskip("yourdfpy")

LEROBOT_NAMES = ("shoulder_pan", "shoulder_lift", "elbow_flex", "wrist_flex", "wrist_roll")

# (name, parent, child, xyz, rpy, axis, lower, upper); a fixed joint has axis None
SO101 = (
    ("shoulder_pan", "base_link", "shoulder_link", "0.0388353 -8.97657e-09 0.0624",
     "3.14159 4.18253e-17 -3.14159", "0 0 1", -1.91986, 1.91986),
    ("shoulder_lift", "shoulder_link", "upper_arm_link", "-0.0303992 -0.0182778 -0.0542",
     "-1.5708 -1.5708 0", "0 0 1", -1.74533, 1.74533),
    ("elbow_flex", "upper_arm_link", "lower_arm_link", "-0.11257 -0.028 1.73763e-16",
     "-3.63608e-16 8.74301e-16 1.5708", "0 0 1", -1.69, 1.69),
    ("wrist_flex", "lower_arm_link", "wrist_link", "-0.1349 0.0052 3.62355e-17",
     "4.02456e-15 8.67362e-16 -1.5708", "0 0 1", -1.65806, 1.65806),
    ("wrist_roll", "wrist_link", "gripper_link", "5.55112e-17 -0.0611 0.0181",
     "1.5708 0.0486795 3.14159", "0 0 1", -2.74385, 2.84121),
    ("gripper_frame_joint", "gripper_link", "gripper_frame_link", "-0.0079 -0.000218121 -0.0981274",
     "0 3.14159 0", None, 0.0, 0.0),
)  # fmt: skip
SO100 = (
    ("shoulder_pan", "base", "shoulder", "0 -0.0452 0.0165", "1.57079 0 0", "0 1 0", -2.0, 2.0),
    ("shoulder_lift", "shoulder", "upper_arm", "0 0.1025 0.0306", "-1.8 0 0", "1 0 0", 0.0, 3.5),
    ("elbow_flex", "upper_arm", "lower_arm", "0 0.11257 0.028", "1.57079 0 0", "1 0 0",
     -3.14158, 0.0),
    ("wrist_flex", "lower_arm", "wrist", "0 0.0052 0.1349", "-1 0 0", "1 0 0", -2.5, 1.2),
    ("wrist_roll", "wrist", "gripper", "0 -0.0601 0", "0 1.57079 0", "0 1 0", -3.14158, 3.14158),
)  # fmt: skip


def _urdf(name: str, joints: tuple[tuple[object, ...], ...]) -> str:
    links = {j[1] for j in joints} | {j[2] for j in joints}
    out = [f'<robot name="{name}">'] + [f'<link name="{link}"/>' for link in sorted(links)]
    for jn, parent, child, xyz, rpy, axis, lo, hi in joints:
        kind = "fixed" if axis is None else "revolute"
        out.append(f'<joint name="{jn}" type="{kind}"><parent link="{parent}"/>'
                   f'<child link="{child}"/><origin xyz="{xyz}" rpy="{rpy}"/>')  # fmt: skip
        if axis is not None:
            out.append(
                f'<axis xyz="{axis}"/><limit lower="{lo}" upper="{hi}" effort="10" velocity="10"/>'
            )
        out.append("</joint>")
    return "\n".join([*out, "</robot>"])


def _rz(deg: float) -> np.ndarray:
    c, s = math.cos(math.radians(deg)), math.sin(math.radians(deg))
    return np.array([[c, -s, 0, 0], [s, c, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1.0]])


def _ry(deg: float) -> np.ndarray:
    c, s = math.cos(math.radians(deg)), math.sin(math.radians(deg))
    return np.array([[c, 0, s, 0], [0, 1, 0, 0], [-s, 0, c, 0], [0, 0, 0, 1.0]])


def _shift(x: float, y: float, z: float) -> np.ndarray:
    T = np.eye(4)
    T[:3, 3] = (x, y, z)
    return T


# arm, URDF joints, root, tip, T_world_root, T_tip_tool (the tool's x along the approach)
def _upright(T_world_root: np.ndarray, axis: np.ndarray, point: np.ndarray) -> np.ndarray:
    """T_world_root turned (the least rotation) and shifted so that the pan axis (``axis``
    through ``point``, in the root frame) is the world's z axis."""
    a = T_world_root[:3, :3] @ axis
    t = np.array([0.0, 0.0, math.copysign(1.0, a[2])])
    v, c = np.cross(a, t), float(a @ t)
    K = np.array([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]])
    R = np.eye(4)
    R[:3, :3] = np.eye(3) + K + K @ K / (1.0 + c)
    T = R @ T_world_root
    T[:2, 3] -= (T @ np.append(point, 1.0))[:2]
    return T


# the pan axis in the root frame: the first joint's origin rotation times its axis
def _pan_axis(rpy: tuple[float, float, float], axis: tuple[float, float, float]) -> np.ndarray:
    (cr, sr), (cp, sp), (cy, sy) = ((math.cos(a), math.sin(a)) for a in rpy)
    Rx = np.array([[1, 0, 0], [0, cr, -sr], [0, sr, cr]])
    Ry = np.array([[cp, 0, sp], [0, 1, 0], [-sp, 0, cp]])
    Rz = np.array([[cy, -sy, 0], [sy, cy, 0], [0, 0, 1]])
    return Rz @ Ry @ Rx @ np.array(axis)


_PAN_101 = _pan_axis((3.14159, 4.18253e-17, -3.14159), (0.0, 0.0, 1.0))
_PAN_100 = _pan_axis((1.57079, 0.0, 0.0), (0.0, 1.0, 0.0))
# arm, URDF joints, root, tip, T_world_root, T_tip_tool (the tool's x along the approach)
CASES = {
    "so101": (SO101, "base_link", "gripper_frame_link",
              _upright(_shift(-0.0388353, 8.97657e-09, 0.0024), _PAN_101,
                       np.array([0.0388353, -8.97657e-09, 0.0624])), _ry(-90.0)),
    "so100": (SO100, "base", "gripper",
              _upright(_rz(90.0) @ _shift(0.0, 0.0452, 0.0), _PAN_100,
                       np.array([0.0, -0.0452, 0.0165])),
              _shift(0.0, -0.0981274, 0.0) @ _rz(-90.0)),
}  # fmt: skip


@pytest.mark.parametrize("arm", sorted(CASES))
def test_fk_equals_the_urdf_to_a_nanometre(arm: str, tmp_path) -> None:
    joints, root, tip, T_world_root, T_tip_tool = CASES[arm]
    path = tmp_path / f"{arm}.urdf"
    path.write_text(_urdf(arm, joints))
    robot = yourdfpy.URDF.load(str(path), load_meshes=False, load_collision_meshes=False)
    model = load_model(arm)
    assert model.joint_names == LEROBOT_NAMES
    moving = [j for j in joints if j[5] is not None]
    assert np.allclose(model.lower, [j[6] for j in moving], atol=1e-12)
    assert np.allclose(model.upper, [j[7] for j in moving], atol=1e-12)
    rng = np.random.default_rng(31)
    for q in rng.uniform(model.lower, model.upper, size=(1000, model.dof)):
        robot.update_cfg(dict(zip(LEROBOT_NAMES, q, strict=True)))
        want = T_world_root @ robot.get_transform(tip, root) @ T_tip_tool
        got = fk(model, q)
        assert np.abs(got[:3, 3] - want[:3, 3]).max() < 1e-9
        assert np.abs(got[:3, :3] - want[:3, :3]).max() < 1e-9


@pytest.mark.parametrize("arm", sorted(CASES))
def test_the_world_origin_is_on_the_pan_axis_on_the_table(arm: str) -> None:
    """DESIGN.md: origin at the centre of the base on the table, x forward, z up: turning
    shoulder_pan moves no point of its axis, which is the world's z axis; at pan 0 the
    arm faces +x (the wrist_roll at 0: there the tool point is in the arm's plane)."""
    model = load_model(arm)
    q = model.home.copy()
    q[0] = q[-1] = 0.0
    tool = fk(model, q)[:3, 3]
    assert tool[0] > 0.1 and abs(tool[1]) < 1e-3
    for pan in np.linspace(model.lower[0], model.upper[0], 7):
        q[0] = pan
        moved = fk(model, q)[:3, 3]
        assert math.hypot(*moved[:2]) == pytest.approx(math.hypot(*tool[:2]), abs=1e-9)
        assert moved[2] == pytest.approx(tool[2], abs=1e-9)
