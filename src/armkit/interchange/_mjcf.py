"""An arm (and optionally its scene) as a MuJoCo MJCF model: ``mjcf_of(model, scene)``.

The bodies are the URDF's (``interchange._bodies``): ``base_link``, ``link1``..,
each with its capsules as geoms and its mass properties from a density; a hinge
joint per joint with its limits; a site ``tool`` at the tool point (MuJoCo's FK of
that site is armkit's ``fk``). Each joint has a position actuator of its name
whose stiffness kp [N m/rad] gives the joint its maximum acceleration plus the
gravity torque of what it carries (at q = 0) at an error of ``STIFF_AT``, with
critical damping on the joint. The gripper's two jaws are boxes on slide joints
``jaw_left`` and ``jaw_right`` (the right one follows the left by an equality),
each joint's value how far its jaw has opened from the closed gripper [m]
(opening = width_min + 2 q), driven by the position actuator ``gripper``. The arm's
geoms collide with the scene's, never with each other.
A scene adds its table and objects (``interchange._mjcf_scene``), the arm's base
where the scene puts it. A keyframe ``home`` holds the joints' home angles.
"""

from __future__ import annotations

import math
from xml.sax.saxutils import quoteattr

import numpy as np

from ..model import ArmModel
from ..scene import Scene
from ._attributes import F64, mjcf_pose, numbers, pose
from ._bodies import Bodies, Link, bodies_of, link_poses
from ._inertia import DENSITY, Inertial, box_inertial
from ._mjcf_scene import scene_bodies, scene_geoms, scene_qpos

GRAVITY = 9.81  # [m/s^2]
STIFF_AT = 0.01  # [rad]: the error at which an actuator gives its joint's max acceleration
JAW_THICKNESS = 0.006  # [m], as the 3D view draws the jaws
JAW_KP = 50.0  # [N/m]
# The arm's geoms touch the scene's (contype 1) but not each other: the clearance capsules
# overlap at every joint, and the arm's own parts never meet.
ARM_GEOM = 'contype="2" conaffinity="1"'


def mjcf_of(model: ArmModel, scene: Scene | None = None, density: float = DENSITY) -> str:
    """The MJCF text of ``model`` (links of ``density`` [kg/m^3]) on ``scene``'s table."""
    bodies = bodies_of(model, density)
    T_base = np.eye(4) if scene is None else scene.T_world_base
    out = [
        f"<mujoco model={quoteattr(model.name)}>",
        '  <compiler angle="radian" autolimits="true"/>',
        '  <option timestep="0.002" integrator="implicitfast"/>',
        "  <worldbody>",
    ]
    out += _arm(model, bodies, T_base, depth=2)
    if scene is not None:
        out += scene_geoms(scene, indent=4) + scene_bodies(scene, indent=4)
    out += ["  </worldbody>", *_actuators(model, bodies)]
    home = [*model.home, *([0.0, 0.0] if model.gripper.present else [])]
    if scene is not None:
        home += scene_qpos(scene)
    out += ["  <keyframe>", f'    <key name="home" qpos="{numbers(home)}"/>', "  </keyframe>"]
    return "\n".join([*out, "</mujoco>"]) + "\n"


def _arm(model: ArmModel, bodies: Bodies, T_base: F64, depth: int) -> list[str]:
    """The nested bodies from the base to the jaws."""
    kps = stiffness(model, bodies)
    out = [f'{"  " * depth}<body name="base_link" {mjcf_pose(T_base)}>']
    out += _geoms(bodies.links[0], "  " * (depth + 1))
    for i, (joint, frame) in enumerate(zip(model.joints, bodies.frames, strict=True)):
        pad = "  " * (depth + i + 1)
        link = bodies.links[i + 1]
        kp, inertia = kps[i]
        damping = 2.0 * math.sqrt(kp * inertia)
        out += [
            f"{pad}<body name={quoteattr(link.name)} {mjcf_pose(frame.origin)}>",
            f'{pad}  <joint name={quoteattr(joint.name)} type="hinge" axis="{numbers(frame.axis)}" '
            f'range="{numbers((joint.lower, joint.upper))}" damping="{damping!r}"/>',
            f"{pad}  {_inertial(link.inertial)}",
            *_geoms(link, pad + "  "),
        ]
    pad = "  " * (depth + model.dof + 1)
    out.append(f'{pad}<site name="tool" {mjcf_pose(bodies.tool)} size="0.002"/>')
    if model.gripper.present:
        out += _jaws(model, bodies.tool, pad)
    for k in range(model.dof, -1, -1):
        out.append(f"{'  ' * (depth + k)}</body>")
    return out


def _geoms(link: Link, pad: str) -> list[str]:
    """A capsule per capsule of ``link`` (a sphere where its ends meet)."""
    out = []
    for c in link.capsules:
        r = float(c.radius)
        if float(np.linalg.norm(c.b - c.a)) > 1e-9:
            out.append(
                f'{pad}<geom type="capsule" fromto="{numbers([*c.a, *c.b])}" size="{r!r}" {ARM_GEOM}/>'
            )
        else:
            out.append(f'{pad}<geom type="sphere" pos="{numbers(c.a)}" size="{r!r}" {ARM_GEOM}/>')
    return out


def _inertial(m: Inertial) -> str:
    J = m.inertia
    full = (J[0, 0], J[1, 1], J[2, 2], J[0, 1], J[0, 2], J[1, 2])
    return (
        f'<inertial pos="{numbers(m.com)}" mass="{float(m.mass)!r}" fullinertia="{numbers(full)}"/>'
    )


def _jaws(model: ArmModel, T_tool: F64, pad: str) -> list[str]:
    """Two jaw bodies at the tool point, closed, each sliding outwards along the jaw axis."""
    g = model.gripper
    across = np.array([0.0, 1.0, 0.0]) if g.jaw_axis == "y" else np.array([0.0, 0.0, 1.0])
    half = [g.finger_length / 2.0, 0.0, 0.0]
    half[1 if g.jaw_axis == "y" else 2] = JAW_THICKNESS / 2.0
    half[2 if g.jaw_axis == "y" else 1] = g.finger_width / 2.0
    size = tuple(2.0 * h for h in half)
    mass = box_inertial((size[0], size[1], size[2]), DENSITY)
    travel = (g.width_max - g.width_min) / 2.0
    out = []
    for side, sign in (("left", 1.0), ("right", -1.0)):
        at = T_tool @ pose(np.eye(3), sign * across * (g.width_min / 2.0 + JAW_THICKNESS / 2.0))
        out += [
            f'{pad}<body name="jaw_{side}" {mjcf_pose(at)}>',
            f'{pad}  <joint name="jaw_{side}" type="slide" axis="{numbers(sign * across)}" '
            f'range="0 {travel!r}" damping="{2.0 * math.sqrt(JAW_KP * mass.mass)!r}"/>',
            f"{pad}  {_inertial(mass)}",
            f'{pad}  <geom type="box" size="{numbers(half)}" {ARM_GEOM}/>',
            f"{pad}</body>",
        ]
    return out


def _actuators(model: ArmModel, bodies: Bodies) -> list[str]:
    out = ["  <actuator>"]
    for joint, (kp, _) in zip(model.joints, stiffness(model, bodies), strict=True):
        out.append(
            f"    <position name={quoteattr(joint.name)} joint={quoteattr(joint.name)} "
            f'kp="{kp!r}" ctrlrange="{numbers((joint.lower, joint.upper))}"/>'
        )
    out.append("  </actuator>")
    if not model.gripper.present:
        return out
    travel = (model.gripper.width_max - model.gripper.width_min) / 2.0
    out.insert(
        -1,
        f'    <position name="gripper" joint="jaw_left" kp="{JAW_KP!r}" ctrlrange="0 {travel!r}"/>',
    )
    out += ["  <equality>", '    <joint joint1="jaw_right" joint2="jaw_left"/>', "  </equality>"]
    return out


def stiffness(model: ArmModel, bodies: Bodies) -> list[tuple[float, float]]:
    """Per joint, its actuator's kp [N m/rad] and the inertia it moves about its axis at
    q = 0 [kg m^2]: kp = (inertia x max acceleration + gravity torque) / ``STIFF_AT``,
    the gravity torque bounded by the carried masses times their distance from the joint."""
    world = link_poses(bodies, np.zeros(model.dof))
    out = []
    for j, (joint, frame) in enumerate(zip(model.joints, bodies.frames, strict=True)):
        at = world[j] @ frame.origin
        axis, point = at[:3, :3] @ np.asarray(frame.axis), at[:3, 3]
        inertia, torque = 1e-6, 0.0  # a floor: a massless joint still gets a finite kp
        for T, link in zip(world[j + 1 :], bodies.links[j + 1 :], strict=True):
            m = link.inertial
            com = T[:3, :3] @ m.com + T[:3, 3]
            moved = Inertial(m.mass, com, T[:3, :3] @ m.inertia @ T[:3, :3].T)
            inertia += float(axis @ moved.about(point) @ axis)
            torque += GRAVITY * m.mass * float(np.linalg.norm(com - point))
        out.append(((inertia * joint.max_acceleration + torque) / STIFF_AT, inertia))
    return out
