"""Levenberg-Marquardt for N targets at once: all iterate together in numpy.

The method of ``_lm`` on arrays of runs, one per target from its seed to begin
with; a target is done when any of its runs converges. Once few targets
remain, each gets several runs side by side (nearly free in numpy).
"""

from __future__ import annotations

from dataclasses import dataclass, fields

import numpy as np
from numpy.typing import NDArray

from .._chain import Chain
from .._forward import chunks
from .._residual import Task, costs, residual
from ._dls import damped_steps
from ._lm import CANDIDATES, LMSettings
from ._turn import turn_first_joint

F64 = NDArray[np.float64]
IDX = NDArray[np.intp]
# Shorter runs than the scalar solver's (a restart is cheap here), and a larger
# restart budget, since parallel runs spend it several at a time.
BATCH_SETTINGS = LMSettings(run_iterations=15, stall_iterations=3, max_restarts=240)
FEW_ROWS = 256  # once fewer runs than this are left, add parallel runs up to it
MAX_RUNS = 32  # parallel runs per target at most


@dataclass
class _Runs:
    """One row per LM run: its target (owner), q (r, dof), residual, damping, progress."""

    owner: IDX
    q: F64
    e: F64
    J: F64
    cost: F64
    pos: F64
    ang: F64
    mu: F64
    best: F64
    since: NDArray[np.int64]
    its: NDArray[np.int64]

    def keep(self, mask: NDArray[np.bool_]) -> _Runs:
        """The runs where ``mask`` is True."""
        return _Runs(**{f.name: getattr(self, f.name)[mask] for f in fields(self)})

    def join(self, other: _Runs) -> _Runs:
        """These runs followed by ``other``."""
        return _Runs(
            **{
                f.name: np.concatenate([getattr(self, f.name), getattr(other, f.name)])
                for f in fields(self)
            }
        )


@dataclass(frozen=True)
class BatchResidual:
    """Residuals e (k, m), masked weighted Jacobians J (k, m, dof), errors [m], [rad] and
    costs |e|^2 (k,): ``_residual``'s lanes as arrays, one row per run."""

    e: F64
    J: F64
    position_error: F64
    angle_error: F64
    cost: F64


@dataclass(frozen=True)
class BatchOutcome:
    """q [rad] (N, dof), converged (N,), restarts (N,), and far (N,): True where the
    target is beyond the chain's reach."""

    q: F64
    converged: NDArray[np.bool_]
    restarts: NDArray[np.int64]
    far: NDArray[np.bool_]


def solve_lm_batch(
    chain: Chain, task: Task[F64], q0: F64, tol_pos: float, tol_ang: float, rng_seed: int
) -> BatchOutcome:
    """LM on N targets (lanes (N,)) from seeds q0 [rad], shape (N, dof) (clamped into the
    limits)."""
    (x, y, z), st, n = task.p, BATCH_SETTINGS, len(q0)
    rng = np.random.default_rng(rng_seed)
    far = np.sqrt(x * x + y * y + z * z) > chain.reach
    out = BatchOutcome(q0.copy(), np.zeros(n, bool), np.zeros(n, np.int64), far)
    budget = np.where(far, 0, st.max_restarts)
    q = turn_first_joint(chain, task, np.clip(q0, chain.lower_a, chain.upper_a))
    runs = _new_runs(np.arange(n), q, _evaluate(chain, task, q), st)
    while runs.owner.size:
        conv = (runs.pos <= tol_pos) & (runs.ang <= tol_ang)
        out.converged[runs.owner[conv]] = True
        out.q[runs.owner[conv]] = runs.q[conv]
        if conv.any():
            runs = runs.keep(~out.converged[runs.owner])
        if not runs.owner.size:
            break
        _iterate(chain, task.take(runs.owner), runs, st)
        runs = _respawn(chain, task, runs, out, budget, rng, st)
    return out


def _evaluate(chain: Chain, task: Task[F64], q: F64) -> BatchResidual:
    """The residuals of q (k, dof) [rad] for the k targets of ``task``, chunk by chunk."""
    k, m = len(q), 3 + (task.pitch is not None) + 3 * (task.R is not None)
    e, J, errors = np.empty((k, m)), np.empty((k, m, chain.dof)), np.empty((3, k))
    for at in chunks(k):
        r = residual(task.take(at), chain.lanes(list(q[at].T)))
        assert r.cols is not None
        for i, v in enumerate(r.e):
            e[at, i] = v
        for j, col in enumerate(r.cols):
            for i, v in enumerate(col):
                J[at, i, j] = v
        errors[:, at] = r.position_error, r.angle_error, r.cost
    return BatchResidual(e, J, errors[0], errors[1], errors[2])


def _new_runs(owner: IDX, q: F64, r: BatchResidual, st: LMSettings) -> _Runs:
    k = len(owner)
    zeros = np.zeros(k, dtype=np.int64)
    return _Runs(
        owner, q, r.e, r.J, r.cost, r.position_error, r.angle_error,
        np.full(k, st.mu), r.cost.copy(), zeros, zeros.copy(),
    )  # fmt: skip


def _iterate(chain: Chain, task: Task[F64], s: _Runs, st: LMSettings) -> None:
    """One damped step for every run (in place); accepted where the cost fell."""
    lo, hi = chain.lower_a, chain.upper_a
    lam = s.mu * s.cost + 1e-12
    dq = damped_steps(s.J, s.e, lam)
    frozen = ((s.q <= lo) & (dq < 0.0)) | ((s.q >= hi) & (dq > 0.0))
    rows = np.flatnonzero(frozen.any(axis=1))
    if rows.size:
        dq[rows] = damped_steps(s.J[rows], s.e[rows], lam[rows], ~frozen[rows])
    big = np.abs(dq).max(axis=1)
    dq *= np.minimum(1.0, st.max_step / np.maximum(big, 1e-300))[:, None]
    trial = np.clip(s.q + dq, lo, hi)
    r = _evaluate(chain, task, trial)
    acc = r.cost < s.cost
    s.q[acc], s.e[acc], s.J[acc], s.cost[acc] = trial[acc], r.e[acc], r.J[acc], r.cost[acc]
    s.pos[acc], s.ang[acc] = r.position_error[acc], r.angle_error[acc]
    s.mu[:] = np.where(acc, np.maximum(s.mu * st.mu_down, 1e-4), s.mu * st.mu_up)
    better = s.cost < 0.95 * s.best
    s.since[:] = np.where(better, 0, s.since + 1)
    np.minimum(s.best, s.cost, out=s.best)
    s.its += 1


def _respawn(
    chain: Chain,
    task: Task[F64],
    runs: _Runs,
    out: BatchOutcome,
    budget: NDArray[np.int64],
    rng: np.random.Generator,
    st: LMSettings,
) -> _Runs:
    """Drop stalled runs; restart their targets (while restarts last), with extra
    parallel runs once few runs are left."""
    stalled = (runs.since >= st.stall_iterations) | (runs.its >= st.run_iterations)
    if not stalled.any() and runs.owner.size >= FEW_ROWS:
        return runs
    waiting = runs.owner[stalled]
    runs = runs.keep(~stalled)
    live = np.bincount(runs.owner, minlength=len(out.q))
    owners = _restart_owners(waiting, live, budget - out.restarts)
    if owners.size == 0:
        return runs
    np.add.at(out.restarts, owners, 1)
    q, r = _restart_points(chain, task.take(owners), out.restarts[owners], rng)
    return runs.join(_new_runs(owners, q, r, st))


def _restart_owners(waiting: IDX, live: NDArray[np.int64], left: NDArray[np.int64]) -> IDX:
    """Targets to start new runs for: each stalled run's target, and while fewer than
    FEW_ROWS runs exist, more runs for every unfinished target (up to MAX_RUNS each)."""
    want = np.bincount(waiting, minlength=len(live))
    unfinished = np.flatnonzero((live + want) > 0)
    total = live.sum() + want.sum()
    if unfinished.size and total < FEW_ROWS:
        per = min(MAX_RUNS, FEW_ROWS // unfinished.size)
        want[unfinished] = np.maximum(want[unfinished], per - live[unfinished])
    want = np.minimum(want, np.maximum(left, 0))
    return np.repeat(np.arange(len(live)), want)


def _restart_points(
    chain: Chain, task: Task[F64], restarts: NDArray[np.int64], rng: np.random.Generator
) -> tuple[F64, BatchResidual]:
    """Per run, where it begins (as ``_lm._restart_point``): the lowest-cost of CANDIDATES
    random joint vectors for an odd restart count, else one uniform sample."""
    k, c = len(restarts), CANDIDATES
    q = rng.uniform(chain.lower_a, chain.upper_a, size=(k, c, chain.dof))
    cost = costs(chain.lanes, task.take(np.repeat(np.arange(k), c)), q.reshape(k * c, -1))
    pick = np.where(restarts % 2 == 1, cost.reshape(k, c).argmin(axis=1), 0)
    start = q[np.arange(k), pick]
    return start, _evaluate(chain, task, start)
