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
from ._lm import solve_lm, solve_lm_batch
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
    """N checked targets at once by LM (the compiled kernel, one call): positions P (N, 3) [m], pitches (N,)
    [rad] or orientations (N, 3, 3) or neither, seeds (N, dof) [rad].

    Returns:
        q (N, dof) with NaN rows where no solution was found, ``ok``, ``reason``
        (``"too_far"`` or ``"no_convergence"`` where not ok).
    """
    out = solve_lm_batch(chain, P, pitch, R, seeds, tol_pos, tol_ang, rng_seed)
    reason = np.where(out.converged, "", np.where(out.far, "too_far", "no_convergence"))
    q = np.where(out.converged[:, None], out.q, np.nan)
    return IKBatchResult(q=q, ok=out.converged.copy(), reason=reason.astype(np.str_), method="lm")


__all__ = ["SOLVERS", "solve_many", "solve_one"]
