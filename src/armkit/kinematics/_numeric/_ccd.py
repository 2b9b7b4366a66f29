"""Cyclic coordinate descent (CCD), the classic per-joint IK that seed 000 points to.

Sweep the joints from the tool back to the base; turn each one, alone, to the
angle that best aligns the tool with the target (in closed form, see
``_turn``), clamped into its limits.
No restarts: CCD is shown as it is, local minima included.
"""

from __future__ import annotations

from ...model import ArmModel
from ._outcome import Attempt, within
from ._residual import Task, residual
from ._sampling import clamp_to_limits
from ._scalar_chain import chain_state, scalar_chain
from ._turn import best_turn

MAX_SWEEPS = 200


def solve_ccd(
    model: ArmModel, task: Task, q_seed: list[float], tol_pos: float, tol_ang: float, rng_seed: int
) -> Attempt:
    """CCD from ``q_seed`` [rad]; ``rng_seed`` is unused (CCD is deterministic)."""
    sc = scalar_chain(model)
    q = clamp_to_limits(model, q_seed)
    res = residual(task, chain_state(sc, q), jac=False)
    for sweep in range(MAX_SWEEPS):
        if within(res, tol_pos, tol_ang):
            return Attempt(q, res, sweep, 0, True)
        for i in reversed(range(len(q))):
            st = chain_state(sc, q)
            j = model.joints[i]
            q[i] = min(max(q[i] + best_turn(task, st, i), j.lower), j.upper)
        res = residual(task, chain_state(sc, q), jac=False)
    return Attempt(q, res, MAX_SWEEPS, 0, within(res, tol_pos, tol_ang))
