"""Is a gripper target reachable and clear?  The check behind the view's target marker.

001's Unity simulation showed a green dot when the gripper could be there, marked
whether it was on the cube, and flagged range violations. Here a target (in the
arm's base frame) is checked by inverse kinematics (reach and joint limits,
``armkit.ik``) and then every solution by the scene's clearance check
(``armkit.scene.check_clear``: the links against the table, the boards, the
cubes and containers). A target inside a cube is "on" it: the gripper may close
around that cube, so it is not an obstacle for that check.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .._errors import UnreachableError
from ..kinematics import ik
from ..model import ArmModel
from ..scene import Scene, check_clear

F64 = NDArray[np.float64]

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
        on: the cube the target is on (inside), or "".
    """

    position: F64
    pitch: float | None
    q: F64 | None
    reason: str
    on: str = ""

    @property
    def ok(self) -> bool:
        """True when the target is reachable and clear."""
        return self.q is not None


def check_target(
    model: ArmModel,
    position: ArrayLike,
    pitch: float | None = None,
    q_seed: ArrayLike | None = None,
    scene: Scene | None = None,
) -> TargetCheck:
    """Check the gripper target ``position`` [m] (arm base frame), shape (3,), at
    ``pitch`` [rad] (None: any): every IK solution (nearest ``q_seed`` first) goes
    through ``check_clear`` against ``scene`` (None: the table plane only); the
    first clear one wins."""
    p = np.asarray(position, dtype=np.float64)
    on = cube_at(scene, p) if scene is not None else ""
    try:
        found = ik(model, p, pitch, q_seed)
    except UnreachableError as exc:
        return TargetCheck(p, pitch, None, REASONS.get(exc.reason, str(exc)), on)
    first_problem = ""
    ignore = frozenset({on}) if on else frozenset()
    for q in found.solutions:
        hit = check_clear(model, q, scene, ignore=ignore)
        if hit is None:
            return TargetCheck(p, pitch, q.copy(), "", on)
        first_problem = first_problem or hit.describe()
    return TargetCheck(p, pitch, None, first_problem, on)


def cube_at(scene: Scene, p: F64) -> str:
    """The cube whose box holds the point ``p`` [m] (arm base frame), shape (3,), or ""."""
    in_scene = scene.T_world_base[:3, :3] @ p + scene.T_world_base[:3, 3]
    for cube in scene.cubes:
        local = cube.T[:3, :3].T @ (in_scene - cube.center)
        if np.all(np.abs(local) <= cube.size / 2 + 1e-9):
            return cube.name
    return ""


def describe_target(check: TargetCheck) -> str:
    """One line for people: where the target is [mm], pitch [deg], and the verdict."""
    x, y, z = (check.position * 1000).tolist()
    pitch = "any pitch" if check.pitch is None else f"pitch {math.degrees(check.pitch):.0f} deg"
    verdict = "reachable and clear" if check.ok else check.reason
    if check.on:
        verdict = f"on {check.on}, {verdict}"
    return f"target ({x:.0f}, {y:.0f}, {z:.0f}) mm, {pitch}: {verdict}"
