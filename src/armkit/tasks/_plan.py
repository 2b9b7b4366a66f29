"""A task's plan: every step solved and checked before anything moves."""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np
from numpy.typing import NDArray

from .._errors import Reason, UnreachableError
from .._terminal import count
from ..scene import Cube, Held, Scene

F64 = NDArray[np.float64]


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


@dataclass(frozen=True)
class Step:
    """One step of a plan: a joint move (``q``) or a gripper command (``grip``).

    Attributes:
        label: what it is for people (``"pick red: down 2/3"``).
        q: joint angles to move to [rad], shape (dof,), or None for a gripper step.
        grip: gripper opening to command [m], or None for a move.
        point: the tool point the move goes to, in the scene frame [m], (3,), or None.
        pitch: the tool's pitch there [rad], or None.
        holding: the cube in the gripper during the step, or None.
    """

    label: str
    q: F64 | None = None
    grip: float | None = None
    point: F64 | None = None
    pitch: float | None = None
    holding: str | None = None


@dataclass(frozen=True)
class Plan:
    """A whole task, planned: its steps, the arm's joints at the start [rad], the
    scene before and the scene expected after (every cube at rest), how long
    planning took [s], and the cube in the gripper at the end (``pick``) with its
    pose in the tool frame, or None."""

    task: str
    arm: str
    steps: tuple[Step, ...]
    q_start: F64
    before: Scene
    after: Scene
    planning_time: float
    held: Held | None = None

    @property
    def q_end(self) -> F64:
        """The arm's joints at the end of the plan [rad], shape (dof,)."""
        last = next((s.q for s in reversed(self.steps) if s.q is not None), self.q_start)
        return last.copy()

    @property
    def rest(self) -> Scene:
        """The scene the next task plans with (as ``armkit.scene.rest_scene`` gives a
        simulated one): ``after``, but a cube still held where it was picked from."""
        held = self.steps[-1].holding if self.steps else None
        if held is None:
            return self.after
        cubes = tuple(c for c in self.after.cubes if c.name != held)
        return replace(self.after, cubes=(*cubes, self.before.cube(held)))

    @property
    def moves(self) -> int:
        """Number of joint moves."""
        return sum(1 for s in self.steps if s.q is not None)

    def lines(self) -> list[str]:
        """The plan as text: one line per step, then the cubes that move."""
        head = (
            f"{self.task} ({self.arm}, scene {self.before.name}): "
            f"{count(len(self.steps), 'step')}, {count(self.moves, 'move')}, planned in {self.planning_time * 1000:.1f} ms"
        )
        out = [head]
        for k, step in enumerate(self.steps, 1):
            out.append(f"{k:3d}  {_step_text(step)}")
        moved = [c for c in self.after.cubes if _moved(self.before, c)]
        for cube in moved:
            out.append(f"  expected: {cube_text(cube)}")
        return out

    def __str__(self) -> str:
        return "\n".join(self.lines())


def _step_text(step: Step) -> str:
    if step.grip is not None:
        return f"{step.label:<40s} gripper {step.grip * 1000:.1f} mm"
    assert step.q is not None and step.point is not None and step.pitch is not None
    x, y, z = (float(v) * 1000 for v in step.point)
    joints = " ".join(f"{math.degrees(a):7.2f}" for a in step.q)
    pitch = math.degrees(step.pitch)
    return f"{step.label:<40s} ({x:6.1f}, {y:6.1f}, {z:6.1f}) mm pitch {pitch:5.1f}  [{joints}] deg"


def cube_text(cube: Cube) -> str:
    """``red at (220.0, -45.0, 3.0) mm, yaw 0.0 deg, +x up``."""
    x, y, z = (float(v) * 1000 for v in cube.position)
    return f"{cube.name} at ({x:.1f}, {y:.1f}, {z:.1f}) mm, yaw {round(math.degrees(cube.yaw), 1) + 0.0:.1f} deg, {cube.up_face} up"


def _moved(before: Scene, cube: Cube) -> bool:
    old = {c.name: c for c in before.cubes}.get(cube.name)
    if old is None:
        return True
    R_old, R_new = old.T[:3, :3], cube.T[:3, :3]
    turned = float(np.linalg.norm(R_old - R_new)) > 1e-6
    return turned or float(np.linalg.norm(old.position - cube.position)) > 1e-6


def pose_error(a: Cube, b: Cube) -> tuple[float, float]:
    """Distance between two poses of a cube: centre [m] and turn [rad]."""
    d = float(np.linalg.norm(a.center - b.center))
    R = a.T[:3, :3].T @ b.T[:3, :3]
    angle = math.acos(max(-1.0, min(1.0, (float(np.trace(R)) - 1.0) / 2.0)))
    return d, angle
