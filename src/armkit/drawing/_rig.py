"""Planning the pen's moves over the sheet: each stroke as one Cartesian path
(down onto the paper, along the stroke, up to the pen-up height), and between
strokes a joint move where its sweep keeps the tip clear of the paper, else a
straight pen-up line. Every path is solved and its links checked for clearance."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from .._errors import UnreachableError
from ..kinematics import fk, ik
from ..model import ArmModel
from ..motion import JointPath, PathError, plan_path
from ..scene import Collision, Scene, Sheet, check_clear, joint_sweep
from ._errors import DrawingError
from ._reach import Run, densify
from ._rig_batch import strokes_at_once
from ._segments_job import JointMove, PathMove, Segment, end_q, stack

F64 = NDArray[np.float64]
STEP = 0.001  # [m] between the points of a pen-up or pen-down line
TURN = math.radians(1.0)  # a pen-up line must start where the arm is, within this


@dataclass(frozen=True)
class Rig:
    """The arm holding the pen: ``tip`` (tool point = the pen's tip, for IK and the
    trace), ``jaws`` (tool point = the jaws, for the clearance check), the scene and
    sheet, the pen's ``pitch`` [rad], the pen-up height [m] and the clearance margin [m]."""

    tip: ArmModel
    jaws: ArmModel
    scene: Scene
    sheet: Sheet
    pitch: float
    pen_up: float
    margin: float

    def height(self, q: F64) -> F64:
        """The tip's height above the sheet's plane [m] for joints (N, dof)."""
        T = fk(self.tip, np.atleast_2d(q))
        p = np.asarray(self.scene.to_scene(T[:, :3, 3]))
        h: F64 = (p - self.sheet.origin) @ self.sheet.normal
        return h

    def tip_at(self, q: F64) -> F64:
        """The tip [m], scene frame, shape (3,)."""
        out: F64 = np.asarray(self.scene.to_scene(fk(self.tip, q)[:3, 3]))
        return out


def plan_strokes(rig: Rig, runs: list[Run], q0: F64) -> list[Segment]:
    """Transit and stroke for every run, in order, from joints ``q0`` [rad]: in
    batches where they answer (``strokes_at_once``), else ``plan_strokes_loop``."""
    fast = strokes_at_once(rig, runs, q0)
    return fast if fast is not None else plan_strokes_loop(rig, runs, q0)


def plan_strokes_loop(rig: Rig, runs: list[Run], q0: F64) -> list[Segment]:
    """``plan_strokes`` one stroke at a time (the reference; it says why a plan fails)."""
    segments: list[Segment] = []
    for k, run in enumerate(runs, 1):
        above = run.world[0] + rig.sheet.normal * rig.pen_up
        segments += transit(rig, end_q(segments, q0), above, f"pen up to stroke {k}")
        segments.append(_stroke(rig, run, end_q(segments, q0), f"stroke {k}/{len(runs)}"))
    return segments


def transit(rig: Rig, q: F64, target: F64, label: str) -> list[Segment]:
    """From joints ``q`` to the tip at ``target`` (scene frame) [m]: a joint move if
    its sweep keeps the tip at least half the pen-up height above the paper and the
    links clear, else a straight line of the tip."""
    here = float(rig.height(q[None, :])[0])
    if here < rig.pen_up / 2 - 1e-6:  # the pen on the paper (a drawing cut short): up first
        lift = _lift(rig, q, rig.tip_at(q) + rig.sheet.normal * (rig.pen_up - here), label)
        if lift is not None:
            return [lift, *transit(rig, lift.path.q[-1], target, label)]
    goal = _solve(rig, target, q, label)
    sweep = joint_sweep(q, goal[None, :])
    low = min(float(rig.height(sweep).min()), float(rig.height(q[None, :])[0]))
    hit = _clear(rig, sweep)
    if low >= rig.pen_up / 2 - 1e-6 and hit is None:
        return [JointMove(label, goal)]
    start = rig.tip_at(q)
    n = max(1, math.ceil(float(np.linalg.norm(target - start)) / STEP))
    points = start + (target - start) * (np.arange(0, n + 1) / n)[:, None]
    why = (
        hit.describe()
        if hit is not None
        else f"the pen would come {low * 1e3:.1f} mm near the paper"
    )
    try:
        path = _path(rig, points, q, label)
    except DrawingError as exc:
        raise DrawingError(f"{label}: in joint space {why}; in a line: {exc}") from None
    if float(np.max(np.abs(path.q[0] - q))) > TURN:
        raise DrawingError(f"{label}: in joint space {why}; a line would start turning the pen")
    return [PathMove(label, path, False)]


def _lift(rig: Rig, q: F64, target: F64, label: str) -> PathMove | None:
    """The tip straight up from where joints ``q`` put it to ``target`` [m] at the
    drawing's pitch, or None: the pen is not held at that pitch there, or cannot."""
    start = rig.tip_at(q)
    n = max(1, math.ceil(float(np.linalg.norm(target - start)) / STEP))
    points = start + (target - start) * (np.arange(0, n + 1) / n)[:, None]
    try:
        path = _path(rig, points, q, label)
    except DrawingError:
        return None
    if float(np.max(np.abs(path.q[0] - q))) > TURN:
        return None
    return PathMove(f"{label}: pen up", path, False)


def _stroke(rig: Rig, run: Run, q: F64, label: str) -> PathMove:
    n = rig.sheet.normal * rig.pen_up
    down = densify(np.array([run.world[0] + n, run.world[0]]), STEP)
    up = densify(np.array([run.world[-1], run.world[-1] + n]), STEP)
    points = stack([down, densify(run.world, STEP), up])
    return PathMove(label, _path(rig, points, q, label), True)


def _path(rig: Rig, points: F64, q: F64, label: str) -> JointPath:
    try:
        path = plan_path(rig.tip, rig.scene.to_base(points), rig.pitch, q, tolerance=2e-4)
    except PathError as exc:
        raise DrawingError(f"{label}: {exc}") from None
    hit = _clear(rig, path.q)
    if hit is not None:
        raise DrawingError(f"{label}: {hit.describe()}; move the sheet or try another --pitch")
    return path


def _clear(rig: Rig, q: F64) -> Collision | None:
    return check_clear(rig.jaws, q, rig.scene, margin=rig.margin)


def _solve(rig: Rig, target: F64, seed: F64, label: str) -> F64:
    try:
        q: F64 = ik(rig.tip, rig.scene.to_base(target), rig.pitch, seed).q
    except UnreachableError as exc:
        raise DrawingError(f"{label}: {exc}") from None
    return q
