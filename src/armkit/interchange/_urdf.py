"""An arm as URDF text: revolute joints with limits, each link's capsules as its
visual and collision geometry (a cylinder and two spheres) and its mass properties.

Links ``base_link``, ``link1``.. (after each joint), and ``tool`` at the tool point
(a fixed joint). Every link has an ``<inertial>``, from its capsules and a density
(``interchange._bodies``; the ``tool`` link's is massless), so physics engines (MuJoCo, pybullet)
load the file as it is; a ``<mujoco>`` element asks MuJoCo to keep the ``tool``
link as a body (other readers ignore it).
"""

from __future__ import annotations

from xml.sax.saxutils import quoteattr

import numpy as np

from ..model import ArmModel
from ._attributes import F64, numbers, pose, urdf_origin, z_onto
from ._bodies import Capsule, Link, bodies_of
from ._inertia import DENSITY


def urdf_of(model: ArmModel, density: float = DENSITY) -> str:
    """The URDF text of ``model``, its links of ``density`` [kg/m^3]."""
    bodies = bodies_of(model, density)
    links = bodies.links
    out = ['<?xml version="1.0"?>', f"<robot name={quoteattr(model.name)}>"]
    out += ["  <mujoco>", '    <compiler fusestatic="false"/>', "  </mujoco>"]
    out += _link(links[0])
    for i, (joint, frame) in enumerate(zip(model.joints, bodies.frames, strict=True)):
        out += [
            f'  <joint name={quoteattr(joint.name)} type="revolute">',
            f"    <parent link={quoteattr(links[i].name)}/>",
            f"    <child link={quoteattr(links[i + 1].name)}/>",
            f"    {urdf_origin(frame.origin)}",
            f'    <axis xyz="{numbers(frame.axis)}"/>',
            f'    <limit lower="{joint.lower!r}" upper="{joint.upper!r}" effort="0" '
            f'velocity="{joint.max_velocity!r}"/>',
            "  </joint>",
        ]
        out += _link(links[i + 1])
    out += [
        '  <joint name="tool_joint" type="fixed">',
        f"    <parent link={quoteattr(links[-1].name)}/>",
        '    <child link="tool"/>',
        f"    {urdf_origin(bodies.tool)}",
        "  </joint>",
        '  <link name="tool">',  # massless (pybullet would give a link without one 1 kg)
        '    <inertial><mass value="0.0"/>',
        '      <inertia ixx="0.0" ixy="0.0" ixz="0.0" iyy="0.0" iyz="0.0" izz="0.0"/>',
        "    </inertial>",
        "  </link>",
        "</robot>",
    ]
    return "\n".join(out) + "\n"


def _link(link: Link) -> list[str]:
    out = [f"  <link name={quoteattr(link.name)}>"]
    m = link.inertial
    if m.mass > 0.0:
        out += [
            "    <inertial>",
            f"      {urdf_origin(pose(np.eye(3), m.com))}",
            f'      <mass value="{float(m.mass)!r}"/>',
            f"      <inertia {_inertia(m.inertia)}/>",
            "    </inertial>",
        ]
    for c in link.capsules:
        out += _capsule(c)
    return [*out, "  </link>"]


def _inertia(J: F64) -> str:
    names = ("ixx", "ixy", "ixz", "iyy", "iyz", "izz")
    values = (J[0, 0], J[0, 1], J[0, 2], J[1, 1], J[1, 2], J[2, 2])
    return " ".join(f'{n}="{float(v)!r}"' for n, v in zip(names, values, strict=True))


def _capsule(c: Capsule) -> list[str]:
    """A cylinder from a to b [m] and a sphere at each end, as visual and collision."""
    r = c.radius
    shapes: list[tuple[F64, str]] = [
        (pose(np.eye(3), c.a), f'<sphere radius="{float(r)!r}"/>'),
        (pose(np.eye(3), c.b), f'<sphere radius="{float(r)!r}"/>'),
    ]
    length = float(np.linalg.norm(c.b - c.a))
    if length > 1e-12:
        R = z_onto((c.b - c.a) / length)
        cylinder = f'<cylinder radius="{r!r}" length="{length!r}"/>'
        shapes.append((pose(R, 0.5 * (c.a + c.b)), cylinder))
    out = []
    for T, shape in shapes:
        for kind in ("visual", "collision"):
            out += [
                f"    <{kind}>",
                f"      {urdf_origin(T)}",
                f"      <geometry>{shape}</geometry>",
                f"    </{kind}>",
            ]
    return out
