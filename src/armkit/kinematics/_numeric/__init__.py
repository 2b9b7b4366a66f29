"""Numeric IK for any serial arm: LM (damped least squares), CCD, Jacobian
iteration and 003's random search, one target or (LM) N targets at once.

``armkit.kinematics.ik`` / ``ik_batch`` check the input and dispatch here.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
from numpy.typing import NDArray

from .._chain import Chain
from .._residual import Task
from .._result import IKBatchResult, IKResult, Method
from .._target import Aim
from ._baselines import solve_ccd, solve_jacobian, solve_random
from ._lm import solve_lm
from ._lm_batch import solve_lm_batch
from ._outcome import Attempt, finish

F64 = NDArray[np.float64]
Solver = Callable[[Chain, Task[float], list[float], float, float, int], Attempt]
SOLVERS: dict[Method, Solver] = {
    "lm": solve_lm,
    "ccd": solve_ccd,
    "jacobian": solve_jacobian,
    "random": solve_random,
}


def solve_one(
    method: Method, chain: Chain, goal: Aim, seed: list[float], tol_pos: float, tol_ang: float,
    rng_seed: int = 0,
) -> IKResult:  # fmt: skip
    """One checked target by a numeric method, from ``seed`` [rad] (clamped into the limits).

    Raises:
        UnreachableError: reason ``"too_far"``; NoSolutionError: ``"no_convergence"``;
            both with ``closest``, the best joint vector found [rad].
    """
    task = Task(*goal, chain.weight)
    attempt = SOLVERS[method](chain, task, seed, tol_pos, tol_ang, rng_seed)
    return finish(chain, method, task, attempt)


def solve_many(
    chain: Chain, P: F64, pitch: F64 | None, R: F64 | None, seeds: F64, tol_pos: float,
    tol_ang: float, rng_seed: int = 0,
) -> IKBatchResult:  # fmt: skip
    """N checked targets at once by vectorised LM: positions P (N, 3) [m], pitches (N,)
    [rad] or orientations (N, 3, 3) or neither, seeds (N, dof) [rad].

    Returns:
        q (N, dof) with NaN rows where no solution was found, ``ok``, ``reason``
        (``"too_far"`` or ``"no_convergence"`` where not ok).
    """
    x, y, z = np.ascontiguousarray(P.T)
    R9 = None if R is None else tuple(np.ascontiguousarray(R.reshape(len(P), 9).T))
    task = Task((x, y, z), pitch, R9, chain.weight)
    out = solve_lm_batch(chain, task, seeds, tol_pos, tol_ang, rng_seed)
    reason = np.where(out.converged, "", np.where(out.far, "too_far", "no_convergence"))
    q = np.where(out.converged[:, None], out.q, np.nan)
    return IKBatchResult(q=q, ok=out.converged.copy(), reason=reason.astype(np.str_), method="lm")


__all__ = ["SOLVERS", "solve_many", "solve_one"]
