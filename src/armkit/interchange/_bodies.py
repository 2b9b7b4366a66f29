"""An arm as rigid bodies: one per link, each with its capsules and mass properties.

Link 0 is the base (it does not move), link i + 1 the body after joint i. Every
capsule of ``ArmModel.link_radii`` (capsule k joins the origins of frames k and
k + 1 of ``fk_frames``) belongs to the link after the last joint that moves
either of its ends, written in that link's frame. A moving link that carries no
capsule (two joints at one point) gets a sphere of its neighbour's radius at its
origin, so every moving body has geometry and mass. Radii under ``MIN_RADIUS``
are raised to it (a body needs a volume).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from ..kinematics import fk_frames, joint_frames
from ..model import ArmModel, JointFrame
from ._inertia import DENSITY, Inertial, capsule_inertial, combined

F64 = NDArray[np.float64]

MIN_RADIUS = 0.001  # [m]


@dataclass(frozen=True, eq=False)
class Capsule:
    """A capsule from ``a`` to ``b`` [m] (in its link's frame) of ``radius`` [m]."""

    a: F64
    b: F64
    radius: float


@dataclass(frozen=True, eq=False)
class Link:
    """One rigid body: its name, capsules and mass properties (in its own frame)."""

    name: str
    capsules: tuple[Capsule, ...]
    inertial: Inertial


@dataclass(frozen=True, eq=False)
class Bodies:
    """The arm as bodies: ``links`` (dof + 1: base first), the joint ``frames`` (joint i
    joins link i to link i + 1) and ``tool``, the tool frame in the last link's frame."""

    links: tuple[Link, ...]
    frames: tuple[JointFrame, ...]
    tool: F64


def bodies_of(model: ArmModel, density: float = DENSITY) -> Bodies:
    """The links of ``model`` named ``base_link``, ``link1``.., of ``density`` [kg/m^3]."""
    frames, tool = joint_frames(model)
    per_link = _capsules(model, frames)
    radii = [max(r, MIN_RADIUS) for r in model.link_radii] or [0.02]
    links = []
    for i in range(model.dof + 1):
        caps = per_link.get(i, [])
        if not caps and i > 0:  # a moving link needs a body: a sphere at its origin
            r = radii[min(i, len(radii) - 1)]
            caps = [Capsule(np.zeros(3), np.zeros(3), r)]
        name = "base_link" if i == 0 else f"link{i}"
        parts = [capsule_inertial(c.a, c.b, c.radius, density) for c in caps]
        inertial = combined(parts) if parts else Inertial(0.0, np.zeros(3), np.zeros((3, 3)))
        links.append(Link(name, tuple(caps), inertial))
    return Bodies(tuple(links), frames, tool)


def link_poses(bodies: Bodies, q: F64) -> list[F64]:
    """Each link's frame in the world at joint angles ``q`` [rad], shape (4, 4) each."""
    world = [np.eye(4)]
    for f, qi in zip(bodies.frames, q, strict=True):
        world.append(world[-1] @ f.origin @ turn(np.asarray(f.axis), float(qi)))
    return world


def turn(axis: F64, angle: float) -> F64:
    """4x4 rotation by ``angle`` [rad] about the unit vector ``axis`` (Rodrigues)."""
    u = axis / np.linalg.norm(axis)
    K = np.array([[0, -u[2], u[1]], [u[2], 0, -u[0]], [-u[1], u[0], 0]])
    T = np.eye(4)
    T[:3, :3] = np.eye(3) + math.sin(angle) * K + (1 - math.cos(angle)) * K @ K
    return T


def _capsules(model: ArmModel, frames: tuple[JointFrame, ...]) -> dict[int, list[Capsule]]:
    """Per link, the capsules it carries, in its frame (see the module's docstring)."""
    q = np.linspace(0.3, 0.9, model.dof) * (model.upper - model.lower) + model.lower
    ends = fk_frames(model, q)[:, :3, 3]
    world = [np.eye(4)]
    for f, qi in zip(frames, q, strict=True):
        world.append(world[-1] @ f.origin @ turn(np.asarray(f.axis), qi))
    out: dict[int, list[Capsule]] = {}
    for k, radius in enumerate(model.link_radii):
        body = 0
        for j in range(model.dof):
            moved = fk_frames(model, q + np.eye(model.dof)[j] * 0.1)[:, :3, 3]
            if np.abs(moved[k : k + 2] - ends[k : k + 2]).max() > 1e-9:
                body = j + 1
        inv = np.linalg.inv(world[body])
        a, b = (inv[:3, :3] @ p + inv[:3, 3] for p in ends[k : k + 2])
        out.setdefault(body, []).append(Capsule(a, b, max(radius, MIN_RADIUS)))
    return out
