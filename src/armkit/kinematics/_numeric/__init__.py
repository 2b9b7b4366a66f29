"""Numeric IK for any serial arm: LM (damped least squares), CCD, Jacobian
iteration and 003's random search, one target or (LM) N targets at once.

``armkit.kinematics.ik`` / ``ik_batch`` dispatch here for the numeric methods.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ...model import ArmModel
from .._result import IKBatchResult, IKResult
from .._target import Target
from ._ccd import solve_ccd
from ._inputs import checked_target, finite_array, rotation, seeds, tolerances
from ._jacobian_iter import solve_jacobian
from ._lm import solve_lm
from ._lm_batch import solve_lm_batch
from ._outcome import Attempt, finish
from ._random import solve_random
from ._residual import Task, angle_weight, reach_bound, task_of
from ._residual_batch import BatchTask

METHODS = {"lm": solve_lm, "ccd": solve_ccd, "jacobian": solve_jacobian, "random": solve_random}
F64 = NDArray[np.float64]


def solve(
    method: str,
    model: ArmModel,
    target: Target,
    q_seed: ArrayLike,
    tol_pos_m: float,
    tol_ang_rad: float,
    rng_seed: int = 0,
) -> IKResult:
    """Joint angles for one target by a numeric method.

    Args:
        method: ``"lm"``, ``"ccd"``, ``"jacobian"`` or ``"random"``.
        model: the arm.
        target: position [m], and pitch [rad] or orientation (3, 3), or neither.
        q_seed: start [rad], shape (dof,); clamped into the limits.
        tol_pos_m: position tolerance [m] on the distance to the target.
        tol_ang_rad: pitch or orientation tolerance [rad] on the angle error.
        rng_seed: seed of the random restarts (same seed, same answer).

    Returns:
        IKResult: q inside the limits whose tool pose meets both tolerances.

    Raises:
        ValueError: unknown method, malformed target, seed or tolerance.
        UnreachableError: reason ``"too_far"``; NoSolutionError: ``"no_convergence"``;
            both with ``closest``, the best joint vector found [rad].
    """
    if method not in METHODS:
        raise ValueError(f"method must be one of {', '.join(METHODS)}, got {method!r}")
    tol_pos, tol_ang = tolerances(tol_pos_m, tol_ang_rad)
    task = task_of(model, checked_target(target))
    q0 = seeds(model, q_seed, None).tolist()
    return solve_task(method, model, task, q0, tol_pos, tol_ang, rng_seed)


def solve_task(
    method: str,
    model: ArmModel,
    task: Task,
    q0: list[float],
    tol_pos: float,
    tol_ang: float,
    rng_seed: int = 0,
) -> IKResult:
    """``solve`` for inputs already checked (as ``armkit.kinematics.ik`` does): a known
    method, a ``Task`` of finite floats, q0 [rad] as dof floats, tolerances > 0 [m], [rad]."""
    attempt: Attempt = METHODS[method](model, task, q0, tol_pos, tol_ang, rng_seed)
    return finish(model, method, task, attempt)


def solve_batch(
    model: ArmModel,
    positions: ArrayLike,
    pitches: ArrayLike | None,
    orientations: ArrayLike | None,
    q_seed: ArrayLike,
    tol_pos_m: float,
    tol_ang_rad: float,
    rng_seed: int = 0,
) -> IKBatchResult:
    """Joint angles for N targets at once by vectorised LM.

    Args:
        positions: tool points [m], shape (N, 3).
        pitches: [rad], shape (N,), or None.  orientations: shape (N, 3, 3), or None.
        q_seed: start [rad], shape (dof,) or (N, dof).
        tol_pos_m, tol_ang_rad: tolerances [m], [rad].  rng_seed: seed of the restarts.

    Returns:
        IKBatchResult: q (N, dof) with NaN rows where no solution was found, ``ok``,
        ``reason`` (``"too_far"`` or ``"no_convergence"`` where not ok).
    """
    task = batch_task(model, positions, pitches, orientations)
    n = len(task.P)
    tol_pos, tol_ang = tolerances(tol_pos_m, tol_ang_rad)
    out = solve_lm_batch(model, task, seeds(model, q_seed, n), tol_pos, tol_ang, rng_seed)
    far = np.linalg.norm(task.P, axis=1) > reach_bound(model)
    reason = np.where(out.converged, "", np.where(far, "too_far", "no_convergence"))
    q = np.where(out.converged[:, None], out.q, np.nan)
    return IKBatchResult(q=q, ok=out.converged.copy(), reason=reason.astype(np.str_), method="lm")


def batch_task(
    model: ArmModel, positions: ArrayLike, pitches: ArrayLike | None, orientations: ArrayLike | None
) -> BatchTask:
    """Checked N targets; ValueError naming ``positions``, ``pitches`` or ``orientations``."""
    P = np.asarray(positions, dtype=np.float64) if positions is not None else None
    if P is None or P.ndim != 2:
        raise ValueError(f"positions must have shape (N, 3), got {np.shape(positions)}")
    P = finite_array(P, "positions", (len(P), 3))
    pitch = None if pitches is None else finite_array(pitches, "pitches", (len(P),))
    R = None if orientations is None else rotation(orientations, "orientations", len(P))
    if pitch is not None and R is not None:
        raise ValueError("give pitches or orientations, not both")
    return BatchTask(P, pitch, R, angle_weight(model))


__all__ = ["METHODS", "Task", "batch_task", "solve", "solve_batch", "solve_task"]
