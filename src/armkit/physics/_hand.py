"""The hand in MuJoCo: the palm cut behind the jaws, and a scissor gripper's jaws
moving along the approach as they open (the Lynx6's grip length law).

armkit's clearance capsules reach the tool point (they keep the arm's links away
from the table with a cube held), so as bodies they would stand round a grasped
cube. Here the tool's link (and a link the tool only rolls about, as the Lynx6's
wrist link under its hand roll) ends a pad's length behind the tool point.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import NDArray

from ..model import ArmModel

F64 = NDArray[np.float64]
ROLL = 0.999  # |cos| between a joint's axis and the approach: the joint rolls the tool


def _rotation(mj: Any, quat: Any) -> F64:
    R = np.zeros(9)
    mj.mju_quat2Mat(R, np.asarray(quat, dtype=np.float64))
    return R.reshape(3, 3)


def hand_bodies(mj: Any, m: Any) -> list[tuple[int, F64, F64]]:
    """The bodies that carry the tool point without moving it off the approach: the
    site ``tool``'s body, then each parent the tool only rolls about. Per body its id,
    the approach (unit, body frame) and the tool point (body frame) [m]."""
    site = int(m.site("tool").id)
    body = int(m.site_bodyid[site])
    R, p = _rotation(mj, m.site_quat[site]), np.array(m.site_pos[site], dtype=np.float64)
    out = [(body, R[:, 0].copy(), p.copy())]
    while m.body_jntnum[body] == 1 and body > 0:
        joint = int(m.body_jntadr[body])
        if m.jnt_type[joint] != mj.mjtJoint.mjJNT_HINGE:
            break
        if abs(float(np.asarray(m.jnt_axis[joint]) @ R[:, 0])) < ROLL:
            break
        R_pb = _rotation(mj, m.body_quat[body])  # the body in its parent, the joint at 0
        R, p = R_pb @ R, R_pb @ p + np.asarray(m.body_pos[body])
        body = int(m.body_parentid[body])
        out.append((body, R[:, 0].copy(), p.copy()))
    return out


def clip_hand(mj: Any, m: Any, pads: float) -> None:
    """Cut the hand's capsules at ``pads`` [m] plus their radius behind the tool point
    along the approach (the fingers' roots); a capsule wholly in front touches nothing."""
    for body, approach, tool in hand_bodies(mj, m):
        for g in np.flatnonzero(m.geom_bodyid == body):
            if not m.geom(int(g)).name:  # the links' clearance capsules (a held pen has a name)
                _clip(mj, m, int(g), approach, tool, pads)


def _clip(mj: Any, m: Any, g: int, approach: F64, tool: F64, pads: float) -> None:
    axis = _rotation(mj, m.geom_quat[g])[:, 2]
    centre = np.array(m.geom_pos[g], dtype=np.float64)
    radius = float(m.geom_size[g, 0])
    half = float(m.geom_size[g, 1]) if m.geom_type[g] == mj.mjtGeom.mjGEOM_CAPSULE else 0.0
    ends = [centre - half * axis, centre + half * axis]
    limit = -pads - radius  # along the approach from the tool point [m]
    depth = [float((e - tool) @ approach) for e in ends]
    if min(depth) > limit:  # all of it among the pads
        m.geom_contype[g] = m.geom_conaffinity[g] = 0
        return
    if max(depth) <= limit or half == 0.0:
        return
    far = int(np.argmax(depth))
    near = ends[1 - far]
    cut = near + (ends[far] - near) * (limit - depth[1 - far]) / (depth[far] - depth[1 - far])
    m.geom_pos[g] = (near + cut) / 2.0
    m.geom_size[g, 1] = float(np.linalg.norm(cut - near)) / 2.0


@dataclass
class Scissor:
    """A gripper whose grip length changes with its opening (``Gripper.length_at``):
    its jaws are moved along the approach to where the linkage puts them (the MJCF
    has them at the closed gripper's tip). A kinematic move of the jaws' mounting,
    at the gripper's speed; the jaws' own slide joints still squeeze."""

    model: ArmModel
    bodies: tuple[int, ...]
    at_closed: tuple[F64, ...]  # each jaw body's position in its parent, closed [m]
    approach: F64  # in the parent's frame
    opening: float = -1.0

    @classmethod
    def of(cls, mj: Any, m: Any, model: ArmModel) -> Scissor | None:
        """The scissor of ``model`` in MuJoCo model ``m``; None for a parallel gripper."""
        if not model.gripper.length_poly:
            return None
        body, approach, _ = hand_bodies(mj, m)[0]
        jaws = (int(m.body("jaw_left").id), int(m.body("jaw_right").id))
        assert all(int(m.body_parentid[j]) == body for j in jaws)
        closed = tuple(np.array(m.body_pos[j], dtype=np.float64) for j in jaws)
        return cls(model, jaws, closed, approach)

    def follow(self, m: Any, opening: float) -> None:
        """Put the jaws where the linkage has them at ``opening`` [m]."""
        if abs(opening - self.opening) < 1e-5:
            return
        self.opening = opening
        g = self.model.gripper
        shorter = (g.length_at(opening) or 0.0) - (g.length_at(g.width_min) or 0.0)
        for body, at in zip(self.bodies, self.at_closed, strict=True):
            m.body_pos[body] = at + shorter * self.approach
