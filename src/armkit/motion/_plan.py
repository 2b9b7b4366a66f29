"""Cartesian path -> joint path: IK at every point on one branch, the whole path
checked before anything moves.

Each point's solution is the one nearest the previous point's (the first point's:
nearest the arm's current angles), so the elbow never flips mid-path. Between
two samples the arm moves in joint space; the check evaluates FK halfway
between them and refuses the path if the arm would leave the straight piece by
more than ``tolerance`` (a branch flip, a singularity, too coarse a spacing).

Without a pitch (and no default one) an arm solved in closed form keeps one
pitch throughout: the first point's own (the one nearest the arm's), else the
nearest to it in 5 deg steps at which every point is reachable and the arm does
not flip. Only where no such pitch is found does each point get its own, the
nearest the previous point's at which the arm fits. One pitch is what a pen
wants, and it keeps the wrist from racing: on the OpenManipulator-X a 40 mm
circle took 5.7 s at one pitch and 34 s with the pitch chosen point by point.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .._errors import InputError, Reason, UnreachableError
from .._inputs import mm
from ..kinematics import fk, ik, ik_batch, pitch_of, why_no_closed_form
from ..model import ArmModel

F64 = NDArray[np.float64]
DEFAULT_TOLERANCE = 0.2e-3  # [m]
PITCH_STEP = math.radians(5.0)  # between the pitches tried for a whole path
PITCHES_TRIED = 8  # reachable ones, nearest first, before the path is refused
FLIP_TURN = math.radians(45.0)  # a joint turning more between two points: a flip, not spacing


@dataclass(frozen=True)
class JointPath:
    """A Cartesian path and the joint angles that follow it.

    Attributes:
        points: tool points [m], shape (N, 3).
        q: joint angles [rad], shape (N, dof), one branch throughout.
    """

    points: F64
    q: F64


class PathError(UnreachableError):
    """A path cannot be followed; ``index`` is the first point that fails."""

    def __init__(self, message: str, *, reason: Reason, index: int) -> None:
        super().__init__(message, reason=reason)
        self.index = index


def plan_path(
    model: ArmModel,
    points: ArrayLike,
    pitch: float | None,
    q_start: ArrayLike,
    tolerance: float = DEFAULT_TOLERANCE,
) -> JointPath:
    """Joint angles for every point of ``points`` [m], shape (N, 3), at ``pitch``
    [rad] (None: the model's default, else chosen: see the module docstring),
    starting on the branch nearest ``q_start`` [rad], shape (dof,).

    Raises:
        PathError: naming the first point that is unreachable or where the arm
            would leave the path by more than ``tolerance`` [m], and why.
    """
    p = np.asarray(points, dtype=np.float64)
    if p.ndim != 2 or p.shape[1] != 3 or p.shape[0] < 1 or not np.all(np.isfinite(p)):
        raise InputError(f"points must be finite, shape (N, 3), got {p.shape}")
    start = np.asarray(q_start, dtype=np.float64)
    chosen = pitch is None and _chooses_pitch(model)
    for one in _whole_path_pitches(model, p, start)[:PITCHES_TRIED] if chosen else ():
        try:
            return _plan(model, p, one, start, tolerance)
        except PathError:
            continue
    return _plan(model, p, pitch, start, tolerance)


def _plan(model: ArmModel, p: F64, pitch: float | None, start: F64, tolerance: float) -> JointPath:
    """``plan_path`` at ``pitch`` [rad] (None: each point's, as ``ik`` chooses it)."""
    q, failure = _solve_all(model, p, pitch, start)
    _check_between(model, p[: q.shape[0]], q, tolerance, free=pitch is None)
    if failure is not None:
        raise failure
    return JointPath(p, q)


def _chooses_pitch(model: ArmModel) -> bool:
    """Whether a path without a pitch gets one for the whole path (see the module
    docstring): no default pitch, a pitch to choose, and a closed form, quick to search."""
    return model.default_pitch is None and model.dof > 2 and not why_no_closed_form(model)


def _whole_path_pitches(model: ArmModel, p: F64, start: F64) -> list[float]:
    """Pitches [rad] at which every point of ``p`` [m] is reachable: the first point's
    chosen pitch, then the others in ``PITCH_STEP``s, the nearest to it first."""
    try:
        first = float(pitch_of(fk(model, ik(model, p[0], None, start).q)))
    except UnreachableError:
        return []  # the point by point plan says why
    grid = np.concatenate([[first], np.arange(-math.pi, math.pi, PITCH_STEP)])
    gap = np.abs(np.remainder(grid - first + math.pi, 2 * math.pi) - math.pi)
    grid = grid[np.argsort(gap, kind="stable")]
    every = ik_batch(model, np.tile(p, (len(grid), 1)), np.repeat(grid, len(p)), start)
    return [float(a) for a in grid[every.ok.reshape(len(grid), len(p)).all(axis=1)]]


def _solve_all(
    model: ArmModel, p: F64, pitch: float | None, seed: F64
) -> tuple[F64, PathError | None]:
    """Solutions up to the first unreachable point, shape (k, dof), and its error."""
    out = np.empty((p.shape[0], model.dof))
    for i, point in enumerate(p):
        try:
            seed = ik(model, point, pitch, seed).q
        except UnreachableError as exc:
            message = f"point {i} of {p.shape[0]} at {mm(point)} is unreachable: {exc}"
            return out[:i], PathError(message, reason=exc.reason or "unreachable", index=i)
        out[i] = seed
    return out, None


def _check_between(model: ArmModel, p: F64, q: F64, tolerance: float, free: bool) -> None:
    """Refuse the path where FK halfway between samples strays from the segment; ``free``:
    no pitch was given (the solver chose one per point)."""
    if p.shape[0] < 2:
        return
    off = deviation(model, p, q)
    bad = np.flatnonzero(off > tolerance)
    if bad.size:
        i = int(bad[0])
        turn = np.abs(q[i + 1] - q[i])
        j = int(np.argmax(turn))
        why, fix = "an elbow flip or a singularity", "use a smaller spacing or another path"
        apart = float(np.linalg.norm(p[i + 1] - p[i]))
        if turn[j] < FLIP_TURN:  # a plain turn: the points are far apart for joint moves
            why = f"the points are {apart * 1000:.1f} mm apart and the arm moves in joint space between them"
            fix = "add points in between (armkit.motion.line, e.g. every 5 mm)"
        if free and _chooses_pitch(model):  # point by point, after no whole-path pitch fit
            a, b = np.degrees(pitch_of(fk(model, q[i : i + 2])))
            why += f", at the pitches it chose there, {a:.1f} and {b:.1f} deg"
            fix = "no pitch for the whole path fits either: try another pitch, a smaller spacing or another path"
        raise PathError(
            f"between point {i} at {mm(p[i])} and point {i + 1} the arm would leave the path "
            f"by {off[i] * 1000:.2f} mm (the {model.joint_names[j]} turns "
            f"{math.degrees(turn[j]):.1f} deg: {why}); {fix}",
            reason="discontinuous",
            index=i,
        )


def deviation(model: ArmModel, p: F64, q: F64) -> F64:
    """How far [m] the tool strays, halfway in joint space between samples, from each
    piece of the path ``p`` (N, 3) [m] followed with joints ``q`` (N, dof): shape (N - 1,)."""
    mid = fk(model, (q[:-1] + q[1:]) / 2.0)[:, :3, 3]
    return _distance_to_segments(mid, p[:-1], p[1:])


def _distance_to_segments(x: F64, a: F64, b: F64) -> F64:
    """Distance [m] from each point x[i] to the segment a[i]-b[i]; shapes (N, 3) -> (N,)."""
    ab = b - a
    length2 = np.sum(ab * ab, axis=1)
    s = np.sum((x - a) * ab, axis=1) / np.where(length2 > 0, length2, 1.0)
    closest = a + np.clip(s, 0.0, 1.0)[:, None] * ab
    return np.asarray(np.linalg.norm(x - closest, axis=1))
