"""Levenberg-Marquardt (damped least squares) IK with joint limits in the step.

Each step solves (J J^T + lam I) y = e, dq = J^T y for the task's masked,
weighted Jacobian; joints sitting at a limit and pushed outwards are frozen
and the step recomputed without them (an active-set projection), then the
new q is clamped into the box. lam = mu |e|^2 (Sugihara's choice) with mu
adapted Marquardt-style: accepted steps shrink it, rejected ones grow it.
A run that stops improving is restarted from a seeded random q inside the
limits. Plain-float arithmetic (see ``_scalar_chain``): tens of microseconds
per call on a 4-joint arm.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ...model import ArmModel
from ._dls import dls_step
from ._outcome import Attempt, beyond_reach, within
from ._residual import Residual, Task, residual
from ._sampling import JointSampler, clamp_to_limits
from ._scalar_chain import ScalarChain, chain_state, scalar_chain


@dataclass(frozen=True, slots=True)
class LMSettings:
    """Budgets of the LM solver.

    Attributes:
        run_iterations: iterations per run before it counts as stalled.
        stall_iterations: iterations without a 5 % improvement that end a run.
        max_restarts: restarts from random seeds after the first run.
        max_step: largest joint change per step [rad].
        mu: initial damping factor, lam = mu |e|^2.
        mu_down, mu_up: factors on mu after an accepted / a rejected step.
    """

    run_iterations: int = 20
    stall_iterations: int = 4
    max_restarts: int = 60
    max_step: float = 1.0
    mu: float = 0.1
    mu_down: float = 0.1
    mu_up: float = 8.0


DEFAULT_SETTINGS = LMSettings()
CANDIDATES = 8  # random joint vectors drawn per restart; the best one starts the run


DEFAULT_SETTINGS = LMSettings()
CANDIDATES = 8  # random joint vectors drawn per restart; the best one starts the run


@dataclass(frozen=True, slots=True)
class _Problem:
    sc: ScalarChain
    task: Task
    lower: list[float]
    upper: list[float]
    tol_pos: float
    tol_ang: float
    settings: LMSettings


def solve_lm(
    model: ArmModel, task: Task, q_seed: list[float], tol_pos: float, tol_ang: float, rng_seed: int
) -> Attempt:
    """LM from ``q_seed`` [rad] (clamped into the limits), restarting when stalled.

    Returns:
        The converged ``Attempt``, or the best one found when the budget ran out.
    """
    settings = DEFAULT_SETTINGS
    prob = _Problem(scalar_chain(model), task, *_limits(model), tol_pos, tol_ang, settings)
    restarts = settings.max_restarts if not beyond_reach(model, task) else 0
    q = clamp_to_limits(model, q_seed)
    best: Attempt | None = None
    sampler: JointSampler | None = None
    total = 0
    for k in range(restarts + 1):
        if k == 1:
            sampler = JointSampler(model, rng_seed)
        q, res, its = lm_run(prob, q if sampler is None else _best_sample(prob, sampler))
        total += its
        done = within(res, tol_pos, tol_ang)
        if best is None or done or res.cost < best.residual.cost:
            best = Attempt(q, res, total, k, done)
        if done:
            break
    assert best is not None
    return Attempt(best.q, best.residual, total, best.restarts, best.converged)


def _best_sample(prob: _Problem, sampler: JointSampler) -> list[float]:
    """The lowest-cost of CANDIDATES random joint vectors inside the limits."""
    best, cost = sampler.sample(), math.inf
    for _ in range(CANDIDATES):
        q = sampler.sample()
        c = residual(prob.task, chain_state(prob.sc, q), jac=False).cost
        if c < cost:
            best, cost = q, c
    return best


def lm_run(prob: _Problem, q: list[float]) -> tuple[list[float], Residual, int]:
    """One LM run from q [rad]: (final q, its residual, iterations)."""
    res = residual(prob.task, chain_state(prob.sc, q))
    settings = prob.settings
    mu, best, since = settings.mu, res.cost, 0
    for it in range(prob.settings.run_iterations):
        if within(res, prob.tol_pos, prob.tol_ang):
            return q, res, it
        trial = _step(prob, q, res, mu * res.cost + 1e-12)
        new = residual(prob.task, chain_state(prob.sc, trial))
        if new.cost < res.cost:
            q, res, mu = trial, new, max(mu * settings.mu_down, 1e-4)
        else:
            mu = mu * settings.mu_up
        since = 0 if res.cost < 0.95 * best else since + 1
        best = min(best, res.cost)
        if since >= prob.settings.stall_iterations:
            return q, res, it + 1
    return q, res, prob.settings.run_iterations


def _step(prob: _Problem, q: list[float], res: Residual, lam: float) -> list[float]:
    """q + the damped step, with outward-pushing joints at a limit frozen, clamped."""
    assert res.cols is not None
    n = len(q)
    lo, hi = prob.lower, prob.upper
    free = [True] * n
    dq = dls_step(res.cols, res.e, lam, free)
    for i in range(n):
        if (q[i] <= lo[i] and dq[i] < 0.0) or (q[i] >= hi[i] and dq[i] > 0.0):
            free[i] = False
    if not all(free):
        dq = dls_step(res.cols, res.e, lam, free)
    biggest = max(abs(v) for v in dq)
    scale = prob.settings.max_step / biggest if biggest > prob.settings.max_step else 1.0
    return [min(max(q[i] + scale * dq[i], lo[i]), hi[i]) for i in range(n)]


def _limits(model: ArmModel) -> tuple[list[float], list[float]]:
    """Lower and upper joint limits [rad] as Python floats (numpy scalars are slow here)."""
    return [j.lower for j in model.joints], [j.upper for j in model.joints]
