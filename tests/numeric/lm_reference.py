"""The reference of the compiled LM kernel (src/armkit/kinematics/_numeric/_lmc.c): the
same method in plain Python floats, step for step, with the same restart sequence
(splitmix64). Not a production path: tests pin the kernel to it (test_numeric_kernel.py).

Levenberg-Marquardt (damped least squares) IK with joint limits in the step.

Each step solves (J J^T + lam I) y = e, dq = J^T y for the task's masked,
weighted Jacobian; joints sitting at a limit and pushed outwards are frozen
and the step recomputed without them (an active-set projection), then the
new q is clamped into the box. lam = mu |e|^2 (Sugihara's choice) with mu
adapted Marquardt-style: accepted steps shrink it, rejected ones grow it.
Every run starts by turning the first joint alone to its exact best angle
(``_turn_first_joint``); a run that stops improving restarts from a seeded
random q inside the limits (on even restarts the first joint's turn stops at its limit). Plain floats on the chain's scalar fast path.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from operator import ge, le

from armkit.kinematics._chain import Chain
from armkit.kinematics._numeric._dls import advance, dls_step
from armkit.kinematics._numeric._outcome import Attempt, beyond_reach, within
from armkit.kinematics._numeric._sampling import clamp
from armkit.kinematics._numeric._turn import best_turn
from armkit.kinematics._residual import Residual, Task, residual, task_jacobian
from armkit.kinematics._state import ChainState, State

MASK = (1 << 64) - 1


def splitmix_sampler(chain: Chain, seed: int) -> Callable[[], list[float]]:
    """Uniform joint vectors inside the limits from splitmix64 (the kernel's generator):
    each joint lo + (hi - lo) * (53 random bits) / 2^53."""
    state = [seed & MASK]

    def uniform() -> float:
        state[0] = z = (state[0] + 0x9E3779B97F4A7C15) & MASK
        z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & MASK
        z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & MASK
        return ((z ^ (z >> 31)) >> 11) * (1.0 / 9007199254740992.0)

    bounds = list(zip(chain.lower, chain.upper, strict=True))
    return lambda: [lo + (hi - lo) * uniform() for lo, hi in bounds]


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


@dataclass(slots=True)
class _Problem:
    state: State
    task: Task[float]
    lower: tuple[float, ...]
    upper: tuple[float, ...]
    tol_pos: float
    tol_ang: float
    settings: LMSettings


def solve_lm(
    chain: Chain, task: Task[float], q_seed: list[float], tol_pos: float, tol_ang: float,
    rng_seed: int,
) -> Attempt:  # fmt: skip
    """LM from ``q_seed`` [rad] (clamped into the limits), restarting when stalled.

    Returns:
        The converged ``Attempt``, or the best one found when the budget ran out.
    """
    settings = DEFAULT_SETTINGS
    lower, upper = chain.lower, chain.upper
    prob = _Problem(chain.state, task, lower, upper, tol_pos, tol_ang, settings)
    q, res, total = lm_run(prob, clamp(q_seed, lower, upper))
    if within(res, tol_pos, tol_ang):
        return Attempt(q, res, total, 0, True)
    best = Attempt(q, res, total, 0, False)
    sample = splitmix_sampler(chain, rng_seed)
    restarts = settings.max_restarts if not beyond_reach(chain, task) else 0
    for k in range(1, restarts + 1):
        q, res, its = lm_run(prob, _restart_point(prob, sample, k), face_away=k % 2 == 1)
        total += its
        done = within(res, tol_pos, tol_ang)
        if done or res.cost < best.residual.cost:
            best = Attempt(q, res, total, k, done)
        if done:
            break
    best.iterations = total
    return best


def _restart_point(prob: _Problem, sample: Callable[[], list[float]], k: int) -> list[float]:
    """Where restart k begins: odd k, the lowest-cost of CANDIDATES random joint
    vectors (finds the right neighbourhood fast); even k, one uniform sample
    (reaches basins that look bad from afar, such as corners of the limits)."""
    best, cost = sample(), math.inf
    if k % 2 == 0:
        return best
    for _ in range(CANDIDATES):
        q = sample()
        c = residual(prob.task, prob.state(q), jac=False).cost
        if c < cost:
            best, cost = q, c
    return best


def lm_run(
    prob: _Problem, q: list[float], face_away: bool = True
) -> tuple[list[float], Residual[float], int]:
    """One LM run from q [rad] (first joint turned, see ``_turn_first_joint``):
    (final q, its residual, iterations)."""
    task, state, settings = prob.task, prob.state, prob.settings
    st = state(q)
    res = residual(task, st, jac=False)
    if not within(res, prob.tol_pos, prob.tol_ang):
        q, st, res = _turn_first_joint(prob, q, st, res, face_away)
    mu, best, since = settings.mu, res.cost, 0
    cols: list[tuple[float, ...]] | None = None  # the Jacobian at q, once needed
    for it in range(settings.run_iterations):
        if res.position_error <= prob.tol_pos and res.angle_error <= prob.tol_ang:
            return q, res, it
        if cols is None:
            cols = task_jacobian(task, st)
        trial = _step(prob, q, cols, res.e, mu * res.cost + 1e-12)
        trial_st = state(trial)
        new = residual(task, trial_st, jac=False)
        if new.cost < res.cost:
            q, st, res, cols = trial, trial_st, new, None
            mu = max(mu * settings.mu_down, 1e-4)
        else:
            mu = mu * settings.mu_up
        if res.cost < 0.95 * best:
            best, since = res.cost, 0
        else:
            since += 1
            if since >= settings.stall_iterations:
                return q, res, it + 1
    return q, res, settings.run_iterations


def _turn_first_joint(
    prob: _Problem, q: list[float], st: ChainState[float], res: Residual[float],
    face_away: bool = True,
) -> tuple[list[float], ChainState[float], Residual[float]]:  # fmt: skip
    """q with joint 0 alone turned to its best angle, if that lowers the cost.

    The turn is exact at any angle, where a linearised step is not: a target
    far round the base costs LM several short steps, and this one turn saves
    them (median iterations 7 -> 4 on the OpenManipulator-X from home). Where
    the best angle is outside the joint's limits, the joint faces the opposite
    way instead (if that is inside them): the arm must then reach back over
    its base, and LM finds that from there far more often than from the
    limit (first-run failures 14 % -> 3 % on the AL5D). Even restarts (``face_away``
    False) take the nearer limit instead: a target with joint 0 at a limit and the next
    joints folded (a corner of the box) is found from there.
    """
    lo, hi = prob.lower[0], prob.upper[0]
    turned = [q[0] + best_turn(prob.task, st, 0), *q[1:]]
    flip = not lo <= turned[0] <= hi
    if flip and not face_away:  # an even restart: the nearer limit (reaches corners)
        turned[0], flip = (hi if turned[0] > hi else lo), False
    elif flip:
        turned[0] += -math.pi if turned[0] > hi else math.pi
        if not lo <= turned[0] <= hi:
            return q, st, res
    turned_st = prob.state(turned)
    new = residual(prob.task, turned_st, jac=False)
    return (turned, turned_st, new) if flip or new.cost < res.cost else (q, st, res)


def _step(
    prob: _Problem, q: list[float], cols: list[tuple[float, ...]], e: list[float], lam: float
) -> list[float]:
    """q + the damped step [rad], with outward-pushing joints at a limit frozen, clamped."""
    lo, hi = prob.lower, prob.upper
    dq = dls_step(cols, e, lam, None)
    if any(map(le, q, lo)) or any(map(ge, q, hi)):  # some joint at a limit
        free = [
            not ((v <= a and d < 0.0) or (v >= b and d > 0.0))
            for v, d, a, b in zip(q, dq, lo, hi, strict=True)
        ]
        if not all(free):
            dq = dls_step(cols, e, lam, free)
    return advance(q, dq, prob.settings.max_step, lo, hi)
