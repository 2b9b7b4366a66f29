"""Cyclic coordinate descent (CCD), the classic per-joint IK that seed 000 points to.

Sweep the joints from the tool back to the base; turn each one, alone, to the
angle that best aligns the tool with the target (in closed form, see
``_turn``), clamped into its limits.
No restarts: CCD is shown as it is, local minima included.
"""

from __future__ import annotations

from .._chain import Chain
from ._outcome import Attempt, within
from ._residual import Task, residual
from ._sampling import clamp
from ._turn import best_turn

MAX_SWEEPS = 200


def solve_ccd(
    chain: Chain, task: Task, q_seed: list[float], tol_pos: float, tol_ang: float, rng_seed: int
) -> Attempt:
    """CCD from ``q_seed`` [rad]; ``rng_seed`` is unused (CCD is deterministic)."""
    state = chain.state
    q = clamp(q_seed, chain.lower, chain.upper)
    res = residual(task, state(q), jac=False)
    for sweep in range(MAX_SWEEPS):
        if within(res, tol_pos, tol_ang):
            return Attempt(q, res, sweep, 0, True)
        for i in reversed(range(len(q))):
            turned = q[i] + best_turn(task, state(q), i)
            q[i] = min(max(turned, chain.lower[i]), chain.upper[i])
        res = residual(task, state(q), jac=False)
    return Attempt(q, res, MAX_SWEEPS, 0, within(res, tol_pos, tol_ang))
