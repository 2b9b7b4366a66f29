"""Levenberg-Marquardt (damped least squares) IK with joint limits in the step.

Each step solves (J J^T + lam I) y = e, dq = J^T y for the task's masked,
weighted Jacobian; joints sitting at a limit and pushed outwards are frozen
and the step recomputed without them (an active-set projection), then the
new q is clamped into the box. lam = mu |e|^2 (Sugihara's choice) with mu
adapted Marquardt-style: accepted steps shrink it, rejected ones grow it.
A run that stops improving is restarted from a seeded random q inside the
limits (alternately the best of a few samples and a plain one). Plain-float
arithmetic (see ``_scalar_chain``): about a hundred microseconds per call on
a 4-joint arm.
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
    max_restarts: int = 150
    max_step: float = 1.0
    mu: float = 0.1
    mu_down: float = 0.1
    mu_up: float = 8.0


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
        q, res, its = lm_run(prob, q if sampler is None else _restart_point(prob, sampler, k))
        total += its
        done = within(res, tol_pos, tol_ang)
        if best is None or done or res.cost < best.residual.cost:
            best = Attempt(q, res, total, k, done)
        if done:
            break
    assert best is not None
    return Attempt(best.q, best.residual, total, best.restarts, best.converged)


def _restart_point(prob: _Problem, sampler: JointSampler, k: int) -> list[float]:
    """Where restart k begins: odd k, the lowest-cost of CANDIDATES random joint
    vectors (finds the right neighbourhood fast); even k, one uniform sample
    (reaches basins that look bad from afar, such as corners of the limits)."""
    best, cost = sampler.sample(), math.inf
    if k % 2 == 0:
        return best
    for _ in range(CANDIDATES):
        q = sampler.sample()
        c = residual(prob.task, chain_state(prob.sc, q), jac=False).cost
        if c < cost:
            best, cost = q, c
    return best


def lm_run(prob: _Problem, q: list[float]) -> tuple[list[float], Residual, int]:
    """One LM run from q [rad]: (final q, its residual, iterations)."""
    task, sc, settings = prob.task, prob.sc, prob.settings
    tol_pos, tol_ang = prob.tol_pos, prob.tol_ang
    res = residual(task, chain_state(sc, q))
    mu, best, since = settings.mu, res.cost, 0
    for it in range(settings.run_iterations):
        if res.position_error <= tol_pos and res.angle_error <= tol_ang:
            return q, res, it
        trial = _step(prob, q, res, mu * res.cost + 1e-12)
        new = residual(task, chain_state(sc, trial))
        if new.cost < res.cost:
            q, res, mu = trial, new, max(mu * settings.mu_down, 1e-4)
        else:
            mu = mu * settings.mu_up
        if res.cost < 0.95 * best:
            best, since = res.cost, 0
        else:
            since += 1
            if since >= settings.stall_iterations:
                return q, res, it + 1
    return q, res, settings.run_iterations


def _step(prob: _Problem, q: list[float], res: Residual, lam: float) -> list[float]:
    """q + the damped step, with outward-pushing joints at a limit frozen, clamped."""
    assert res.cols is not None
    lo, hi = prob.lower, prob.upper
    dq = dls_step(res.cols, res.e, lam, None)
    free = [
        not ((v <= a and d < 0.0) or (v >= b and d > 0.0))
        for v, d, a, b in zip(q, dq, lo, hi, strict=True)
    ]
    if not all(free):
        dq = dls_step(res.cols, res.e, lam, free)
    biggest = max(map(abs, dq))
    k = prob.settings.max_step / biggest if biggest > prob.settings.max_step else 1.0
    return [min(max(v + k * d, a), b) for v, d, a, b in zip(q, dq, lo, hi, strict=True)]


def _limits(model: ArmModel) -> tuple[list[float], list[float]]:
    """Lower and upper joint limits [rad] as Python floats (numpy scalars are slow here)."""
    return [j.lower for j in model.joints], [j.upper for j in model.joints]
