"""``armkit urdf -o FILE``: the arm as a URDF file, its links as the clearance capsules.

Each joint becomes a revolute joint (origin, axis, limits, speed) between
links named after the joints; the tool point is a fixed joint to the link
``tool``. Every capsule of ``ArmModel.link_radii`` (capsule i joins the origins
of frames i and i + 1 of ``fk_frames``) becomes the collision and visual
geometry (a cylinder and two spheres) of the link that carries it, so the arm
opens in RViz, MeshCat or any URDF viewer as the clearance check sees it.
"""

from __future__ import annotations

import argparse
import math
from typing import Any
from xml.sax.saxutils import quoteattr

import numpy as np
from numpy.typing import NDArray

from .._files import check_output_path, write_atomic
from ..kinematics import fk_frames, joint_frames
from ..model import ArmModel, load_model

F64 = NDArray[np.float64]


def add_commands(sub: argparse._SubParsersAction[Any]) -> None:
    """Add ``urdf``."""
    p = sub.add_parser(
        "urdf",
        help="write the arm as a URDF file (links as the clearance capsules)",
        description="Write the arm (--arm) as URDF: revolute joints with their limits [rad] and "
        "speeds [rad/s], lengths in metres (URDF's units), the tool point as the link 'tool', "
        "each link's capsule (radius from the model's [links] radius_mm) as its geometry.",
    )
    p.add_argument("-o", "--output", required=True, metavar="FILE", help="the .urdf file to write")
    p.set_defaults(func=run_urdf)


def run_urdf(args: argparse.Namespace) -> int:
    """Check the output path, then write the file."""
    path = check_output_path(args.output, "-o/--output")
    model = load_model(args.arm)
    write_atomic(path, urdf_of(model))
    print(f"wrote {path} ({model.dof} joints, {len(model.link_radii)} link capsules)")
    return 0


def urdf_of(model: ArmModel) -> str:
    """The URDF text of ``model``: links ``base_link``, ``link1``.. (after each joint), ``tool``."""
    frames, tool = joint_frames(model)
    links = ["base_link", *(f"link{i + 1}" for i in range(model.dof))]
    geometry = _capsules(model, frames)
    out = ['<?xml version="1.0"?>', f"<robot name={quoteattr(model.name)}>"]
    out += _link(links[0], geometry.get(0, []))
    for i, (joint, frame) in enumerate(zip(model.joints, frames, strict=True)):
        out += [
            f'  <joint name={quoteattr(joint.name)} type="revolute">',
            f"    <parent link={quoteattr(links[i])}/>",
            f"    <child link={quoteattr(links[i + 1])}/>",
            f"    {_origin(frame.origin)}",
            f'    <axis xyz="{_xyz(frame.axis)}"/>',
            f'    <limit lower="{joint.lower!r}" upper="{joint.upper!r}" effort="0" '
            f'velocity="{joint.max_velocity!r}"/>',
            "  </joint>",
        ]
        out += _link(links[i + 1], geometry.get(i + 1, []))
    out += [
        '  <joint name="tool_joint" type="fixed">',
        f"    <parent link={quoteattr(links[-1])}/>",
        '    <child link="tool"/>',
        f"    {_origin(tool)}",
        "  </joint>",
        '  <link name="tool"/>',
        "</robot>",
    ]
    return "\n".join(out) + "\n"


def _capsules(model: ArmModel, frames: tuple[Any, ...]) -> dict[int, list[str]]:
    """Per link (0 = base, i + 1 = after joint i), the geometry of the capsules it carries.

    A capsule belongs to the link after the last joint that moves either of its ends.
    """
    q = np.linspace(0.3, 0.9, model.dof) * (model.upper - model.lower) + model.lower
    ends = fk_frames(model, q)[:, :3, 3]
    world = [np.eye(4)]  # each link's frame in the world at q
    for f, qi in zip(frames, q, strict=True):
        world.append(world[-1] @ f.origin @ _turn(np.asarray(f.axis), qi))
    out: dict[int, list[str]] = {}
    for k, radius in enumerate(model.link_radii):
        body = 0
        for j in range(model.dof):
            moved = fk_frames(model, q + np.eye(model.dof)[j] * 0.1)[:, :3, 3]
            if np.abs(moved[k : k + 2] - ends[k : k + 2]).max() > 1e-9:
                body = j + 1
        inv = np.linalg.inv(world[body])
        a, b = (inv[:3, :3] @ p + inv[:3, 3] for p in ends[k : k + 2])
        out.setdefault(body, []).extend(_capsule(a, b, radius))
    return out


def _capsule(a: F64, b: F64, radius: float) -> list[str]:
    """A cylinder from a to b [m] and a sphere at each end, as visual and collision."""
    shapes = [
        (a, f'<sphere radius="{radius!r}"/>', np.eye(3)),
        (b, f'<sphere radius="{radius!r}"/>', np.eye(3)),
    ]
    length = float(np.linalg.norm(b - a))
    if length > 1e-12:
        T = np.eye(4)
        T[:3, :3] = _turn(np.cross([0.0, 0.0, 1.0], (b - a) / length), 0.0, (b - a) / length)[
            :3, :3
        ]
        shapes.append(
            (0.5 * (a + b), f'<cylinder radius="{radius!r}" length="{length!r}"/>', T[:3, :3])
        )
    out = []
    for centre, shape, R in shapes:
        T = np.eye(4)
        T[:3, :3], T[:3, 3] = R, centre
        for kind in ("visual", "collision"):
            out += [
                f"    <{kind}>",
                f"      {_origin(T)}",
                f"      <geometry>{shape}</geometry>",
                f"    </{kind}>",
            ]
    return out


def _turn(axis: F64, angle: float, to: F64 | None = None) -> F64:
    """4x4 rotation by ``angle`` about ``axis``; with ``to``, the rotation taking z onto it."""
    T = np.eye(4)
    if to is not None:
        z = np.array([0.0, 0.0, 1.0])
        c, v = float(z @ to), np.cross(z, to)
        if np.linalg.norm(v) < 1e-12:
            T[:3, :3] = np.eye(3) if c > 0 else np.diag([1.0, -1.0, -1.0])
            return T
        K = np.array([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]])
        T[:3, :3] = np.eye(3) + K + K @ K / (1.0 + c)
        return T
    u = axis / np.linalg.norm(axis)
    K = np.array([[0, -u[2], u[1]], [u[2], 0, -u[0]], [-u[1], u[0], 0]])
    T[:3, :3] = np.eye(3) + math.sin(angle) * K + (1 - math.cos(angle)) * K @ K
    return T


def _xyz(v: Any) -> str:
    return " ".join(repr(float(x)) for x in v)


def _origin(T: F64) -> str:
    """``<origin xyz rpy>`` of a transform, R = Rz(yaw) Ry(pitch) Rx(roll)."""
    R = T[:3, :3]
    pitch = math.atan2(-R[2, 0], math.hypot(R[0, 0], R[1, 0]))
    if math.hypot(R[0, 0], R[1, 0]) > 1e-12:
        roll, yaw = math.atan2(R[2, 1], R[2, 2]), math.atan2(R[1, 0], R[0, 0])
    else:  # pitch at +-90 deg: only roll - yaw (or roll + yaw) is defined
        roll, yaw = math.atan2(-R[1, 2], R[1, 1]), 0.0
    return f'<origin xyz="{_xyz(T[:3, 3])}" rpy="{_xyz((roll, pitch, yaw))}"/>'


def _link(name: str, geometry: list[str]) -> list[str]:
    if not geometry:
        return [f"  <link name={quoteattr(name)}/>"]
    return [f"  <link name={quoteattr(name)}>", *geometry, "  </link>"]
