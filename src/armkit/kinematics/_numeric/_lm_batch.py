"""Levenberg-Marquardt for N targets at once: all iterate together in numpy.

The same method as ``_lm`` (damped step with outward-pushing joints at a limit
frozen, clamping, lam = mu |e|^2 with Marquardt's mu, seeded restarts inside
the limits) on arrays of shape (k, ...): converged targets drop out, stalled
ones restart from random joint vectors in the same loop. When only a handful
remain, numpy's per-call overhead would dominate, so the scalar solver of
``_lm`` finishes them from where they are.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from ...model import ArmModel
from .._jacobian import jacobian_and_pose
from ._lm import CANDIDATES, DEFAULT_SETTINGS, LMSettings, solve_lm
from ._residual import Task, reach_bound
from ._residual_batch import BatchResidual, BatchTask, residual_batch

F64 = NDArray[np.float64]
IDX = NDArray[np.intp]
TAIL = 12  # below this many active targets, the scalar solver takes over


@dataclass
class _State:
    """Per-target solver state, arrays of length N (J: (N, m, dof))."""

    q: F64
    e: F64
    J: F64
    cost: F64
    pos: F64
    ang: F64
    mu: F64
    best: F64
    since: NDArray[np.int64]
    run_its: NDArray[np.int64]
    iterations: NDArray[np.int64]
    restarts: NDArray[np.int64]
    max_restarts: NDArray[np.int64]
    active: NDArray[np.bool_]


@dataclass(frozen=True)
class BatchOutcome:
    """q [rad] (N, dof), converged (N,), iterations (N,), restarts (N,)."""

    q: F64
    converged: NDArray[np.bool_]
    iterations: NDArray[np.int64]
    restarts: NDArray[np.int64]


def solve_lm_batch(
    model: ArmModel, task: BatchTask, q0: F64, tol_pos: float, tol_ang: float, rng_seed: int
) -> BatchOutcome:
    """LM on N targets from seeds q0 [rad], shape (N, dof) (clamped into the limits)."""
    settings = DEFAULT_SETTINGS
    lo, hi = model.lower, model.upper
    s = _initial(model, task, np.clip(q0, lo, hi), settings)
    rng = np.random.default_rng(rng_seed)
    for _ in range(settings.run_iterations * (settings.max_restarts + 1)):
        s.active &= ~((s.pos <= tol_pos) & (s.ang <= tol_ang))
        idx = np.flatnonzero(s.active)
        if idx.size <= TAIL:
            break
        _iterate(model, task.take(idx), s, idx, settings)
        _restart_stalled(model, task, s, idx, rng, settings)
    _finish_tail(model, task, s, tol_pos, tol_ang, rng_seed)
    converged = (s.pos <= tol_pos) & (s.ang <= tol_ang)
    return BatchOutcome(s.q, converged, s.iterations, s.restarts)


def _evaluate(model: ArmModel, task: BatchTask, q: F64) -> BatchResidual:
    J, T = jacobian_and_pose(model, q)
    return residual_batch(task, J, T)


def _initial(model: ArmModel, task: BatchTask, q: F64, settings: LMSettings) -> _State:
    r = _evaluate(model, task, q)
    n = len(q)
    zeros = np.zeros(n, dtype=np.int64)
    far = np.linalg.norm(task.P, axis=1) > reach_bound(model)
    return _State(
        q=q, e=r.e, J=r.J, cost=r.cost, pos=r.position_error, ang=r.angle_error,
        mu=np.full(n, settings.mu), best=r.cost, since=zeros.copy(), run_its=zeros.copy(),
        iterations=zeros.copy(), restarts=zeros.copy(),
        max_restarts=np.where(far, 0, settings.max_restarts), active=np.ones(n, dtype=bool),
    )  # fmt: skip


def damped_steps(J: F64, e: F64, lam: F64, free: NDArray[np.bool_] | None = None) -> F64:
    """Damped least-squares steps dq [rad], shape (k, dof), for J (k, m, dof), e (k, m).

    Joints where ``free`` (k, dof) is False get no motion.
    """
    if free is not None:
        J = J * free[:, None, :]
    m, n = J.shape[1], J.shape[2]
    Jt = J.transpose(0, 2, 1)
    if m == 3 and n >= 3:
        A = J @ Jt
        A[:, [0, 1, 2], [0, 1, 2]] += lam[:, None]
        return np.einsum("kjm,km->kj", Jt, solve3(A, e))
    if m <= n:
        A = J @ Jt + lam[:, None, None] * np.eye(m)
        return np.asarray((Jt @ np.linalg.solve(A, e[:, :, None]))[:, :, 0], dtype=np.float64)
    A = Jt @ J + lam[:, None, None] * np.eye(n)
    return np.asarray(np.linalg.solve(A, (Jt @ e[:, :, None]))[:, :, 0], dtype=np.float64)


def solve3(A: F64, b: F64) -> F64:
    """x with A x = b for k symmetric 3 x 3 matrices A (k, 3, 3), b (k, 3), by the adjugate."""
    a, d, f = A[:, 0, 0], A[:, 0, 1], A[:, 0, 2]
    c, g, h = A[:, 1, 1], A[:, 1, 2], A[:, 2, 2]
    i00, i01, i02 = c * h - g * g, f * g - d * h, d * g - c * f
    i11, i12, i22 = a * h - f * f, d * f - a * g, a * c - d * d
    det = np.maximum(a * i00 + d * i01 + f * i02, 1e-300)
    b0, b1, b2 = b[:, 0], b[:, 1], b[:, 2]
    x = np.stack(
        [
            i00 * b0 + i01 * b1 + i02 * b2,
            i01 * b0 + i11 * b1 + i12 * b2,
            i02 * b0 + i12 * b1 + i22 * b2,
        ],
        axis=1,
    )
    return np.asarray(x / det[:, None], dtype=np.float64)


def _iterate(model: ArmModel, task: BatchTask, s: _State, idx: IDX, st: LMSettings) -> None:
    """One damped step for the targets idx; accept where the cost fell."""
    lo, hi = model.lower, model.upper
    q, J, e = s.q[idx], s.J[idx], s.e[idx]
    lam = s.mu[idx] * s.cost[idx] + 1e-12
    dq = damped_steps(J, e, lam)
    frozen = ((q <= lo) & (dq < 0.0)) | ((q >= hi) & (dq > 0.0))
    rows = np.flatnonzero(frozen.any(axis=1))
    if rows.size:
        dq[rows] = damped_steps(J[rows], e[rows], lam[rows], ~frozen[rows])
    big = np.abs(dq).max(axis=1)
    dq *= np.minimum(1.0, st.max_step / np.maximum(big, 1e-300))[:, None]
    trial = np.clip(q + dq, lo, hi)
    r = _evaluate(model, task, trial)
    acc = r.cost < s.cost[idx]
    a = idx[acc]
    s.q[a], s.e[a], s.J[a], s.cost[a] = trial[acc], r.e[acc], r.J[acc], r.cost[acc]
    s.pos[a], s.ang[a] = r.position_error[acc], r.angle_error[acc]
    s.mu[idx] = np.where(acc, np.maximum(s.mu[idx] * st.mu_down, 1e-4), s.mu[idx] * st.mu_up)
    better = s.cost[idx] < 0.95 * s.best[idx]
    s.since[idx] = np.where(better, 0, s.since[idx] + 1)
    s.best[idx] = np.minimum(s.best[idx], s.cost[idx])
    s.iterations[idx] += 1
    s.run_its[idx] += 1


def _restart_stalled(
    model: ArmModel, task: BatchTask, s: _State, idx: IDX, rng: np.random.Generator, st: LMSettings
) -> None:
    """Restart stalled targets from random q inside the limits; give up when out of restarts."""
    stalled = idx[(s.since[idx] >= st.stall_iterations) | (s.run_its[idx] >= st.run_iterations)]
    spent = stalled[s.restarts[stalled] >= s.max_restarts[stalled]]
    s.active[spent] = False
    go = stalled[s.restarts[stalled] < s.max_restarts[stalled]]
    if go.size == 0:
        return
    q, r = _best_of_samples(model, task.take(go), rng)
    s.q[go], s.e[go], s.J[go], s.cost[go] = q, r.e, r.J, r.cost
    s.pos[go], s.ang[go] = r.position_error, r.angle_error
    s.mu[go], s.best[go], s.since[go], s.run_its[go] = st.mu, s.cost[go], 0, 0
    s.restarts[go] += 1


def _best_of_samples(
    model: ArmModel, task: BatchTask, rng: np.random.Generator
) -> tuple[F64, BatchResidual]:
    """Per target, the lowest-cost of CANDIDATES random joint vectors inside the limits."""
    k, c = len(task.P), CANDIDATES
    q = rng.uniform(model.lower, model.upper, size=(k * c, model.dof))
    r = _evaluate(model, task.take(np.repeat(np.arange(k), c)), q)
    pick = np.arange(k) * c + r.cost.reshape(k, c).argmin(axis=1)
    best = BatchResidual(r.e[pick], r.J[pick], r.position_error[pick], r.angle_error[pick])
    return q[pick], best


def _finish_tail(
    model: ArmModel, task: BatchTask, s: _State, tol_pos: float, tol_ang: float, rng_seed: int
) -> None:
    """The scalar solver continues each target still active."""
    for i in np.flatnonzero(s.active):
        R = None if task.R is None else tuple(float(v) for v in task.R[i].ravel())
        pitch = None if task.pitch is None else float(task.pitch[i])
        one = Task(tuple(float(v) for v in task.P[i]), pitch, R, task.weight)  # type: ignore[arg-type]
        out = solve_lm(model, one, s.q[i].tolist(), tol_pos, tol_ang, rng_seed + 1 + int(i))
        s.q[i] = out.q
        s.pos[i], s.ang[i] = out.residual.position_error, out.residual.angle_error
        s.iterations[i] += out.iterations
        s.restarts[i] += out.restarts
        s.active[i] = False
