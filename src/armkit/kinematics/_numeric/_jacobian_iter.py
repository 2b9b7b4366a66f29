"""Jacobian pseudo-inverse iteration: the textbook resolved-rate IK.

dq = J^+ e with J^+ = J^T (J J^T + eps I)^-1 (eps tiny, only to survive
singular poses), the step shortened to at most ``MAX_STEP`` and q clamped
into the limits; no damping schedule, no line search, no restarts. It is the
method LM improves on, shown as it is.
"""

from __future__ import annotations

from .._chain import Chain
from ._dls import dls_step
from ._outcome import Attempt, within
from ._residual import Task, residual
from ._sampling import clamp

MAX_ITERATIONS = 300
MAX_STEP = 0.2  # [rad]
EPS = 1e-9  # [task unit^2]


def solve_jacobian(
    chain: Chain, task: Task, q_seed: list[float], tol_pos: float, tol_ang: float, rng_seed: int
) -> Attempt:
    """Pseudo-inverse iteration from ``q_seed`` [rad]; ``rng_seed`` is unused."""
    lo, hi = chain.lower, chain.upper
    q = clamp(q_seed, lo, hi)
    res = residual(task, chain.state(q))
    for it in range(MAX_ITERATIONS):
        if within(res, tol_pos, tol_ang):
            return Attempt(q, res, it, 0, True)
        assert res.cols is not None
        dq = dls_step(res.cols, res.e, EPS, None)
        big = max(abs(v) for v in dq)
        k = MAX_STEP / big if big > MAX_STEP else 1.0
        q = [min(max(v + k * d, a), b) for v, d, a, b in zip(q, dq, lo, hi, strict=True)]
        res = residual(task, chain.state(q))
    return Attempt(q, res, MAX_ITERATIONS, 0, within(res, tol_pos, tol_ang))
