"""Seed 003's random search: nudge every joint by a small random amount, keep
the new angles only if the tool got closer, until close enough or out of tries.

As 003 says, it gets stuck where one joint would have to move away from the
target to let another one move (a local minimum); that is kept, not fixed.
The one liberty taken: the nudge shrinks with the remaining error (a fixed
nudge could never land within 0.01 mm), sigma = clip(error / reach, 1e-7, 0.1) rad.
"""

from __future__ import annotations

import random

from .._chain import Chain
from ._outcome import Attempt, within
from ._residual import Task, residual
from ._sampling import clamp

MAX_TRIES = 2000
MAX_SIGMA = 0.1  # [rad]


def solve_random(
    chain: Chain, task: Task, q_seed: list[float], tol_pos: float, tol_ang: float, rng_seed: int
) -> Attempt:
    """Random search from ``q_seed`` [rad], reproducible from ``rng_seed``."""
    rnd = random.Random(rng_seed)
    bounds = list(zip(chain.lower, chain.upper, strict=True))
    reach, state = chain.reach, chain.state
    q = clamp(q_seed, chain.lower, chain.upper)
    res = residual(task, state(q), jac=False)
    for it in range(MAX_TRIES):
        if within(res, tol_pos, tol_ang):
            return Attempt(q, res, it, 0, True)
        sigma = min(max(res.cost**0.5 / reach, 1e-7), MAX_SIGMA)
        trial = [
            min(max(v + rnd.gauss(0.0, sigma), lo), hi)
            for v, (lo, hi) in zip(q, bounds, strict=True)
        ]
        new = residual(task, state(trial), jac=False)
        if new.cost < res.cost:
            q, res = trial, new
    return Attempt(q, res, MAX_TRIES, 0, within(res, tol_pos, tol_ang))
