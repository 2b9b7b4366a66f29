"""Is a gripper target reachable and clear?  The check behind the view's target marker.

001's Unity simulation showed a green dot when the gripper could be there and
flagged range violations. Here a target is checked by inverse kinematics (reach
and joint limits, ``armkit.ik``) and then every solution's link capsules
against the table plane ``model.table_z``; further checks (the scene's boards
and objects) plug in as ``Clearance`` functions.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .._errors import UnreachableError
from ..kinematics import ik
from ..model import ArmModel
from ._arm_shapes import link_capsules

F64 = NDArray[np.float64]
# A clearance check: joint angles [rad] -> None when clear, else why not (one line).
Clearance = Callable[[ArmModel, F64], str | None]

REASONS = {
    "too_far": "out of reach (too far)",
    "too_close": "too close to the base",
    "joint_limit": "a joint limit is in the way",
    "off_plane": "off the arm's plane",
    "pitch": "that pitch cannot be reached there",
    "no_convergence": "no solution found",
}


@dataclass(frozen=True, eq=False)
class TargetCheck:
    """The verdict on one target.

    Attributes:
        position: the target [m], shape (3,).  pitch: asked pitch [rad] or None (any).
        q: joint angles that reach it and are clear [rad], shape (dof,), or None.
        reason: "" when ``q`` is good, else why not (one line, for people).
    """

    position: F64
    pitch: float | None
    q: F64 | None
    reason: str

    @property
    def ok(self) -> bool:
        """True when the target is reachable and clear."""
        return self.q is not None


def table_clearance(model: ArmModel, q: F64) -> str | None:
    """None when no link but the base column dips below the table plane, else which."""
    caps = link_capsules(model, q)
    low = np.minimum(caps.p0[:, 2], caps.p1[:, 2]) - caps.radii - model.table_z
    low[0] = 0.0  # the base column stands on the table
    i = int(np.argmin(low))
    if low[i] >= -1e-6:
        return None
    return f"the table is in the way: link {i} would go {-low[i] * 1000:.1f} mm into it"


def check_target(
    model: ArmModel,
    position: ArrayLike,
    pitch: float | None = None,
    q_seed: ArrayLike | None = None,
    clearances: Sequence[Clearance] = (table_clearance,),
) -> TargetCheck:
    """Check the gripper target ``position`` [m], shape (3,), at ``pitch`` [rad]
    (None: any): every IK solution (nearest ``q_seed`` first) is tried against
    ``clearances``; the first clear one wins."""
    p = np.asarray(position, dtype=np.float64)
    try:
        found = ik(model, p, pitch, q_seed)
    except UnreachableError as exc:
        return TargetCheck(p, pitch, None, REASONS.get(exc.reason, str(exc)))
    first_problem = ""
    for q in found.solutions:
        problems = [why for check in clearances if (why := check(model, q)) is not None]
        if not problems:
            return TargetCheck(p, pitch, q.copy(), "")
        first_problem = first_problem or problems[0]
    return TargetCheck(p, pitch, None, first_problem)


def describe(check: TargetCheck) -> str:
    """One line for people: where the target is [mm], pitch [deg], and the verdict."""
    x, y, z = (check.position * 1000).tolist()
    pitch = "any pitch" if check.pitch is None else f"pitch {math.degrees(check.pitch):.0f} deg"
    verdict = "reachable and clear" if check.ok else check.reason
    return f"target ({x:.0f}, {y:.0f}, {z:.0f}) mm, {pitch}: {verdict}"
