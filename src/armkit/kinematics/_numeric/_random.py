"""Seed 003's random search: nudge every joint by a small random amount, keep
the new angles only if the tool got closer, until close enough or out of tries.

As 003 says, it gets stuck where one joint would have to move away from the
target to let another one move (a local minimum); that is kept, not fixed.
The one liberty taken: the nudge shrinks with the remaining error (a fixed
nudge could never land within 0.01 mm), sigma = clip(error / reach, 1e-7, 0.1) rad.
"""

from __future__ import annotations

import random

from ...model import ArmModel
from ._outcome import Attempt, within
from ._residual import Task, reach_bound, residual
from ._sampling import clamp_to_limits
from ._scalar_chain import chain_state, scalar_chain

MAX_TRIES = 2000
MAX_SIGMA = 0.1  # [rad]


def solve_random(
    model: ArmModel, task: Task, q_seed: list[float], tol_pos: float, tol_ang: float, rng_seed: int
) -> Attempt:
    """Random search from ``q_seed`` [rad], reproducible from ``rng_seed``."""
    sc = scalar_chain(model)
    rnd = random.Random(rng_seed)
    bounds = [(j.lower, j.upper) for j in model.joints]
    reach = reach_bound(model)
    q = clamp_to_limits(model, q_seed)
    res = residual(task, chain_state(sc, q), jac=False)
    for it in range(MAX_TRIES):
        if within(res, tol_pos, tol_ang):
            return Attempt(q, res, it, 0, True)
        sigma = min(max(res.cost**0.5 / reach, 1e-7), MAX_SIGMA)
        trial = [
            min(max(v + rnd.gauss(0.0, sigma), lo), hi)
            for v, (lo, hi) in zip(q, bounds, strict=True)
        ]
        new = residual(task, chain_state(sc, trial), jac=False)
        if new.cost < res.cost:
            q, res = trial, new
    return Attempt(q, res, MAX_TRIES, 0, within(res, tol_pos, tol_ang))
