"""The textbook numeric methods, shown as they are (no restarts, local minima
included): cyclic coordinate descent (seed 000), Jacobian pseudo-inverse
iteration and seed 003's random search. Each is one move from (q, residual)
to the next; ``descend`` repeats it from the clamped seed until the errors are
within the tolerances or the budget is spent.
"""

from __future__ import annotations

import random
from collections.abc import Callable

from .._chain import Chain
from .._residual import Residual, Task, residual
from ._dls import advance, dls_step
from ._outcome import Attempt, within
from ._sampling import clamp
from ._turn import best_turn

Move = Callable[[list[float], Residual[float]], tuple[list[float], Residual[float]]]
CCD_SWEEPS = 200
JACOBIAN_ITERATIONS = 300
JACOBIAN_STEP = 0.2  # [rad]
JACOBIAN_EPS = 1e-9  # [task unit^2]
RANDOM_TRIES = 2000
RANDOM_MAX_SIGMA = 0.1  # [rad]


def descend(
    chain: Chain, task: Task[float], q_seed: list[float], tol: tuple[float, float], budget: int,
    move: Move, jac: bool = False,
) -> Attempt:  # fmt: skip
    """``move`` repeated from ``q_seed`` [rad] (clamped into the limits) until the position
    [m] and angle [rad] errors are within ``tol`` or ``budget`` moves are made."""
    q = clamp(q_seed, chain.lower, chain.upper)
    res = residual(task, chain.state(q), jac)
    for it in range(budget):
        if within(res, *tol):
            return Attempt(q, res, it, 0, True)
        q, res = move(q, res)
    return Attempt(q, res, budget, 0, within(res, *tol))


def solve_ccd(
    chain: Chain, task: Task[float], q_seed: list[float], tol_pos: float, tol_ang: float,
    rng_seed: int,
) -> Attempt:  # fmt: skip
    """CCD from ``q_seed`` [rad]: sweep the joints from the tool back to the base, turning
    each one alone to the angle that best aligns the tool with the target (in closed
    form, see ``_turn``), clamped into its limits. ``rng_seed`` is unused."""

    def sweep(q: list[float], res: Residual[float]) -> tuple[list[float], Residual[float]]:
        for i in reversed(range(len(q))):
            turned = q[i] + best_turn(task, chain.state(q), i)
            q[i] = min(max(turned, chain.lower[i]), chain.upper[i])
        return q, residual(task, chain.state(q), jac=False)

    return descend(chain, task, q_seed, (tol_pos, tol_ang), CCD_SWEEPS, sweep)


def solve_jacobian(
    chain: Chain, task: Task[float], q_seed: list[float], tol_pos: float, tol_ang: float,
    rng_seed: int,
) -> Attempt:  # fmt: skip
    """Resolved-rate iteration from ``q_seed`` [rad]: dq = J^+ e with J^+ = J^T (J J^T +
    eps I)^-1 (eps tiny, only to survive singular poses), shortened to at most
    ``JACOBIAN_STEP``, q clamped into the limits; no damping schedule, no line search:
    the method LM improves on. ``rng_seed`` is unused."""

    def move(q: list[float], res: Residual[float]) -> tuple[list[float], Residual[float]]:
        assert res.cols is not None
        dq = dls_step(res.cols, res.e, JACOBIAN_EPS, None)
        q = advance(q, dq, JACOBIAN_STEP, chain.lower, chain.upper)
        return q, residual(task, chain.state(q))

    return descend(chain, task, q_seed, (tol_pos, tol_ang), JACOBIAN_ITERATIONS, move, jac=True)


def solve_random(
    chain: Chain, task: Task[float], q_seed: list[float], tol_pos: float, tol_ang: float,
    rng_seed: int,
) -> Attempt:  # fmt: skip
    """Seed 003's random search from ``q_seed`` [rad], reproducible from ``rng_seed``: nudge
    every joint by a small random amount, keep the new angles only if the tool got closer.

    As 003 says, it gets stuck where one joint would have to move away from the
    target to let another one move (a local minimum); that is kept, not fixed.
    The one liberty taken: the nudge shrinks with the remaining error (a fixed
    nudge could never land within 0.01 mm), sigma = clip(error / reach, 1e-7, 0.1) rad.
    """
    gauss = random.Random(rng_seed).gauss

    def nudge(q: list[float], res: Residual[float]) -> tuple[list[float], Residual[float]]:
        sigma = min(max(res.cost**0.5 / chain.reach, 1e-7), RANDOM_MAX_SIGMA)
        trial = clamp([v + gauss(0.0, sigma) for v in q], chain.lower, chain.upper)
        new = residual(task, chain.state(trial), jac=False)
        return (trial, new) if new.cost < res.cost else (q, res)

    return descend(chain, task, q_seed, (tol_pos, tol_ang), RANDOM_TRIES, nudge)
