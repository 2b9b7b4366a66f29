"""Turning a solver's best joint vector into an ``IKResult`` or the error saying why not."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..._errors import NoSolutionError, UnreachableError
from .._chain import Chain
from .._residual import Residual, Task
from .._result import IKResult, Method


@dataclass(slots=True)
class Attempt:
    """What one numeric solver ended with.

    Attributes:
        q: best joint angles found [rad], inside the limits.
        residual: its residual.  iterations: total iterations.  restarts: restarts used.
        converged: True if the errors are within the tolerances.
    """

    q: list[float]
    residual: Residual[float]
    iterations: int
    restarts: int
    converged: bool


def within(res: Residual[float], tol_pos: float, tol_ang: float) -> bool:
    """True when the position [m] and angle [rad] errors are inside the tolerances."""
    return res.position_error <= tol_pos and res.angle_error <= tol_ang


def beyond_reach(chain: Chain, task: Task[float]) -> bool:
    """True when the target point is farther from the base than any pose can reach."""
    return math.sqrt(sum(v * v for v in task.p)) > chain.reach


def finish(chain: Chain, method: Method, task: Task[float], attempt: Attempt) -> IKResult:
    """The ``IKResult`` of a converged attempt; raises otherwise.

    Raises:
        UnreachableError: reason ``"too_far"``, the target is out of reach.
        NoSolutionError: reason ``"no_convergence"``, the solver stopped short.
        Both carry the closest joint vector found in ``closest``.
    """
    res = attempt.residual
    if attempt.converged:  # q's arrays are built when read (see IKResult)
        goal = (task.p, task.pitch, task.R)
        ranked = ((0.0, tuple(attempt.q)),)
        return IKResult(ranked, goal, chain, method, attempt.iterations, attempt.restarts)
    q = np.array(attempt.q)
    miss = f"{res.position_error * 1000:.3f} mm, {math.degrees(res.angle_error):.3f} deg"
    if beyond_reach(chain, task):
        raise UnreachableError(
            f"target is out of {chain.name}'s reach (closest pose found misses by {miss}); "
            "move the target closer to the base",
            reason="too_far",
            closest=q,
        )
    hint = "another q_seed" if method == "lm" else "method='lm'"
    raise NoSolutionError(
        f"{method} did not converge for {chain.name} after {attempt.iterations} iterations and "
        f"{attempt.restarts} restarts (closest pose misses by {miss}); the target may be outside "
        f"the joint limits, or try {hint}",
        reason="no_convergence",
        closest=q,
    )
