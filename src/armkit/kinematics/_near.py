"""A family arm up to rounding, whose last joint is a roll that carries the tool point
beside its axis: the chain the closed form solves before Newton's method polishes.

A URDF's numbers are rounded (1.5708 for pi/2, 3.14159 for pi), so its axes sit a few
micro-radians off parallel and ``_family.detect``'s exact tests refuse the arm; and a
wrist roll whose axis is the approach line's direction but not through the tool point
(the SO-101's tool point is 7.9 mm beside its wrist_roll axis) moves the tool point, so
it is no trailing roll. Such an arm is solved (``_near_ik``) on its *idealised* chain:

- every fixed rotation's entries within ``SNAP`` of 0 set to 0, then the nearest
  rotation taken (a rounded right angle made exact; a real angle such as the SO-101's
  2.79 deg roll offset is kept), the first axis put through the world origin if it
  passes within ``SNAP`` m of it;
- the roll frozen at an angle: the arm without its last joint, the tool carried by the
  roll's frame turned by that angle (``Near.at``), which is a base yaw + planar chain
  whose tool point sits beside the plane (``PlanarFamily.lateral``): the closed form.

Only the last joint is a roll here, and its axis must be the approach's direction on
the idealised chain (then the roll moves the tool point, never its pitch).
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from numpy.typing import NDArray

from ..model import ArmModel, JointFrame
from ._steps import frames_of, rot, steps_of

F64 = NDArray[np.float64]
SNAP = 1e-5  # [1] rotation entries, and [m] the first axis's distance from the origin
NEAR = 1e-4  # [m]: the idealised chain's tool point stays this near the true one's
PARALLEL = 1e-9  # [1]: 1 - |cos| between the roll axis and the approach on the ideal chain


@dataclass(frozen=True, eq=False)
class Near:
    """The idealised chain of a model, split before its last joint (the roll).

    Attributes:
        model: the true model (its joints, limits and names).
        frames: the idealised frames of every joint but the roll (axes along their z).
        roll: the roll's idealised frame (origin, axis along its z).
        tool: the tool in the roll's frame, idealised, shape (4, 4) [m].
        deviation: the largest distance [m] between the idealised and the true tool point
            over a few poses (a measure of what the polish corrects).
        chains: per roll [rad], the closed form's compiled chain there, kept by
            ``_near_ik.chain_at`` (a bounded number).
    """

    model: ArmModel
    frames: tuple[JointFrame, ...]
    roll: JointFrame
    tool: F64
    deviation: float
    chains: dict[float | None, Any] = field(default_factory=dict, repr=False)

    def flange(self, roll: float) -> F64:
        """The tool in the last frame before the roll, the roll at ``roll`` [rad], (4, 4)."""
        return self.roll.origin @ rot("z", self.roll.axis[2] * roll) @ self.tool

    def at(self, roll: float) -> ArmModel:
        """The idealised arm without its roll, the roll frozen at ``roll`` [rad] (its tool
        carried by the roll's frame turned by ``roll``)."""
        m = self.model
        return dataclasses.replace(
            m,
            convention="frames",
            dh=(),
            joints=m.joints[:-1],
            frames=self.frames,
            T_flange_tool=self.flange(roll),
            link_radii=m.link_radii[:-1],
            source=None,
        )

    def tool_at_zero(self, roll: float) -> F64:
        """The tool point [m] with every joint before the roll at 0, the roll at ``roll``."""
        T = np.eye(4)
        for f in self.frames:
            T = T @ f.origin
        return (T @ self.flange(roll))[:3, 3]


def near_of(model: ArmModel) -> Near | None:
    """The idealised chain of ``model`` split before its last joint, or None: fewer than
    3 joints, the roll's axis not the approach's direction, or the idealised chain more
    than ``NEAR`` from the true one (then it is not a rounding)."""
    if model.dof < 3:
        return None
    steps, tool = steps_of(model)
    frames = [JointFrame(_ideal(f.origin), f.axis) for f in frames_of(steps)]
    first = frames[0].origin
    if abs(abs(first[2, 2]) - 1.0) < 1e-15 and math.hypot(first[0, 3], first[1, 3]) < SNAP:
        first = first.copy()
        first[:2, 3] = 0.0  # a vertical first axis a rounding beside the world origin
        frames[0] = JointFrame(first, frames[0].axis)
    T_tool = _ideal(tool.T)
    at_zero = np.eye(4)
    for f in frames:
        at_zero = at_zero @ f.origin
    roll_axis = at_zero[:3, :3] @ np.array(frames[-1].axis)
    approach = (at_zero @ T_tool)[:3, 0]
    if 1.0 - abs(float(roll_axis @ approach)) > PARALLEL:
        return None
    ideal = dataclasses.replace(model, convention="frames", dh=(), frames=tuple(frames))
    deviation = _deviation(model, ideal, T_tool)
    if deviation > NEAR:
        return None
    return Near(model, tuple(frames[:-1]), frames[-1], T_tool, deviation)


def _ideal(T: F64) -> F64:
    """``T`` with its rotation's entries within ``SNAP`` of 0 set to 0, then the nearest
    rotation (the polar factor of the SVD); the translation kept."""
    R = np.array(T[:3, :3], dtype=np.float64)
    R[np.abs(R) < SNAP] = 0.0
    U, _, Vt = np.linalg.svd(R)
    out = np.array(T, dtype=np.float64)
    out[:3, :3] = U @ Vt
    out[np.abs(out) < 1e-15] = 0.0
    return out


def _deviation(model: ArmModel, ideal: ArmModel, T_tool: F64) -> float:
    """The largest distance [m] between the true and the idealised tool point at home,
    zero and the joints' limits."""
    true_steps, true_tool = steps_of(model)
    ideal_frames = ideal.frames
    poses = [model.home, np.zeros(model.dof), model.lower, model.upper]
    worst = 0.0
    for q in poses:
        a, b = np.eye(4), np.eye(4)
        for s, f, v in zip(true_steps, ideal_frames, q, strict=True):
            a = a @ s.before.T @ rot("z", s.sign * float(v) + s.offset)
            b = b @ f.origin @ rot("z", f.axis[2] * float(v))
        a, b = a @ true_tool.T, b @ T_tool
        worst = max(worst, float(np.linalg.norm(a[:3, 3] - b[:3, 3])))
    return worst
