"""A task's plan is an ``armkit.arm.Plan`` (every step solved and checked before anything
moves); what the tasks add: their error, and how far a cube ended from its plan."""

from __future__ import annotations

import math

import numpy as np

from .._errors import Reason, UnreachableError
from ..arm import Plan as Plan
from ..arm import Step as Step
from ..arm import cube_text as cube_text
from ..scene import Cube


class TaskError(UnreachableError):
    """A task cannot be done: a step is unreachable or would collide. Nothing moved.

    Attributes:
        step: the step's label (``"rotate red: pick from the top: down 3/3"``).
        link: the colliding link (``"gripper"``, ``"held red"``), or ``""``.
        object: what it would hit (``"board"``, ``"table"``), or ``""``.
        why: the reason in a few words (``"too far from the arm"``), "" if not known.
        remedy: what to do, in a few words (``"move it nearer the arm"``), or "".
        details: the whole story (``ArmkitError.details``).
    """

    def __init__(
        self,
        message: str,
        *,
        step: str = "",
        link: str = "",
        obj: str = "",
        reason: Reason | None = None,
        why: str = "",
        remedy: str = "",
        details: str = "",
    ) -> None:
        super().__init__(message, reason=reason or ("collision" if link else "unreachable"))
        self.step, self.link, self.object = step, link, obj
        self.why, self.remedy, self.details = why, remedy, details


def pose_error(a: Cube, b: Cube) -> tuple[float, float]:
    """Distance between two poses of a cube: centre [m] and turn [rad]."""
    d = float(np.linalg.norm(a.center - b.center))
    R = a.T[:3, :3].T @ b.T[:3, :3]
    angle = math.acos(max(-1.0, min(1.0, (float(np.trace(R)) - 1.0) / 2.0)))
    return d, angle
