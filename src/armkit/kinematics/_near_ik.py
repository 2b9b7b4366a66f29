"""IK of a near-family arm (``_near``): the closed form on the idealised chain with the
roll kept at the seed's angle, then Newton's method on the true chain.

Per roll the idealised arm is a base yaw + planar chain whose tool point sits beside the
plane: only its last link and its ``lateral`` offset depend on the roll, so its closed
form is the home roll's with those two replaced (``chain_at``; no compile per roll).
Where no solution fits at the seed's roll (a target at the edge of the reach, where the
7.9 mm the roll swings the tool point matter), the rolls of ``ROLLS`` are tried, the
nearest the seed's first.

Each closed-form solution is a few micrometres from the target on the true chain (the
rounding the idealised chain removed). Newton's method on the joints before the roll,
the roll held, removes it: with a pitch, the square system position (3) + pitch (1)
(``_residual``'s rows, the pitch as ``pitch_of`` measures it, smooth even straight down);
without, position only, the least-norm step over the joints the closed form did not put
on a limit (its pitch was chosen at a limit or at the edge of the reach: the pitch gives
way instead). Two or three steps reach the float floor (about 1e-16 m).
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Callable, Iterator
from typing import Any

import numpy as np
from numpy.typing import NDArray

from .._errors import UnreachableError
from ._boundary_fast import pack_boundary
from ._chain import Chain, _solvers, chain_of
from ._closed_scalar import family_ik
from ._family import joint_ranges
from ._near import Near
from ._residual import Task, residual
from ._result import IKBatchResult, IKResult

F64 = NDArray[np.float64]
Q = tuple[float, ...]
P3 = tuple[float, float, float]
SolveBatch = Callable[..., IKBatchResult]  # its batch (``_ik._closed_batch``)
ROLLS = 96  # rolls tried, spread over the roll's range, where the seed's fits nowhere
KEEP = 128  # per-roll chains kept
STEPS = 10  # Newton steps at most (two or three are needed)
DONE_M = 1e-15  # [m], [rad]: errors this small end the polish (the float floor)
ACCEPT_M = 1e-10  # [m] position error of a polished solution, at most
ACCEPT_RAD = 1e-10  # [rad] its pitch error, at most
SLACK = 1e-9  # [rad] a joint this far beyond a limit counts as at it (as ``_closed``)


def chain_at(near: Near, roll: float) -> Chain:
    """The closed form's chain of ``near`` with the roll at ``roll`` [rad]."""
    got: Chain | None = near.chains.get(roll)
    if got is not None:
        return got
    base: Chain = near.chains.get(None) or chain_of(near.at(near.model.joints[-1].home))
    fam = base.family
    assert fam is not None  # (``Chain.near`` is set only where it is)
    t = near.tool_at_zero(roll)
    er = (math.cos(fam.azimuth_r), math.sin(fam.azimuth_r))
    (c1x, c1z), (v1, v2, _) = fam.c1, fam.links
    x3, z3 = c1x + v1[0] + v2[0], c1z + v1[1] + v2[1]
    last = (float(t[0] * er[0] + t[1] * er[1]) - x3, float(t[2]) - z3)
    lateral = float(t @ np.array(fam.u))
    fam = dataclasses.replace(
        fam, links=(v1, v2, last), lateral=lateral if abs(lateral) > 1e-12 else 0.0
    )
    lower, upper = base.lower, base.upper
    fixed, free = _solvers(
        fam, lower, upper, base.wrist_reach, (base.home, base.home_pitch, base.state, (0.0, 0.0))
    )
    ranges = joint_ranges(fam, lower, upper)
    got = dataclasses.replace(
        base, family=fam, fixed=fixed, free=free, ranges=ranges,
        boundary=pack_boundary(fam, lower, upper, ranges) if free else None,
    )  # fmt: skip
    if len(near.chains) > KEEP:
        near.chains.pop(next(k for k in near.chains if k is not None))
    near.chains[None] = base  # the home roll's, which every other is built from
    near.chains[roll] = got
    return got


def roll_of(chain: Chain, seed: Q) -> float:
    """The roll [rad] a solution keeps: the seed's, moved into the roll's limits."""
    return min(max(seed[-1], chain.lower[-1]), chain.upper[-1])


def rolls(chain: Chain, first: float) -> Iterator[float]:
    """``first`` [rad], then ``ROLLS`` rolls spread over the roll's range, nearest first,
    then the rolls that put the tool point in the arm's plane (a target nearer the base
    axis than the tool's offset from the plane is reachable only near those); the others
    worked out only when ``first`` does not do."""
    yield first
    lo, hi = chain.lower[-1], chain.upper[-1]
    spread = [lo + (hi - lo) * (k + 0.5) / ROLLS for k in range(ROLLS)]
    yield from sorted(spread, key=lambda r: abs(r - first))
    yield from in_plane(chain)


def in_plane(chain: Chain) -> list[float]:
    """The rolls [rad] within the limits at which the tool point's offset from the arm's
    plane is 0 (see ``offset``)."""
    a, b, c = offset(chain)
    amp = math.hypot(a, b)
    if amp < 1e-12 or abs(c) > amp:
        return []
    phase, turn = math.atan2(b, a), math.acos(-c / amp)
    out = []
    for r in (phase + turn, phase - turn):
        for k in (-1, 0, 1):
            v = r + 2 * math.pi * k
            if chain.lower[-1] <= v <= chain.upper[-1]:
                out.append(v)
    return out


def offset(chain: Chain) -> tuple[float, float, float]:
    """The tool point's offset from the arm's plane [m] as a function of the roll:
    a cos(roll) + b sin(roll) + c, (a, b, c) measured at three rolls."""
    near = chain.near
    assert near is not None
    fam = chain_at(near, near.model.joints[-1].home).family
    assert fam is not None
    u = np.array(fam.u)
    at = [float(near.tool_at_zero(r) @ u) for r in (0.0, 0.5 * math.pi, math.pi)]
    c = 0.5 * (at[0] + at[2])
    return at[0] - c, at[1] - c, c


def near_ik(
    chain: Chain, p: P3, pitch: float | None, seed: Q, numeric: Callable[[], IKResult],
) -> IKResult:  # fmt: skip
    """Every solution for tool point p [m] at ``pitch`` [rad] (None: the closed form's
    choice, nearest the seed's), polished on the true chain; the roll the seed's, else
    the nearest of ``rolls`` at which the closed form finds one. Where the polish leaves
    none, ``numeric``'s solution polished. Raises the seed roll's UnreachableError."""
    near = chain.near
    assert near is not None
    first: UnreachableError | None = None
    for roll in rolls(chain, roll_of(chain, seed)):
        try:
            got = family_ik(chain_at(near, roll), p, pitch, seed[:-1])
        except UnreachableError as e:
            first = first or e
            continue
        ranked = []
        for _, q in got.ranked:
            if (done := polish(chain, p, pitch, [*q, roll])) is not None:
                ranked.append((_distance(done, seed), done))
        if ranked:
            return IKResult.of(ranked, (p, pitch, None), chain)
        break
    else:  # no roll fits the closed form: the numeric solver on the true chain (a
        # target whose rolls are a narrow window at the edge of the reach), else why not
        assert first is not None
        raise first
    return polished(chain, p, pitch, seed, numeric())


def polished(chain: Chain, p: P3, pitch: float | None, seed: Q, got: IKResult) -> IKResult:
    """A numeric solver's solution polished as the closed form's are (else as it was)."""
    q = tuple(got.q.tolist())
    done = polish(chain, p, pitch, list(q))
    if done is None:
        return got
    return IKResult(
        [(_distance(done, seed), done)], got.goal, chain, got.method, got.iterations, got.restarts
    )


def near_batch(
    chain: Chain, P: F64, pitch: F64 | None, seed: F64, solve: SolveBatch,
    one: Callable[[P3, float | None, Q], IKResult],
) -> IKBatchResult:  # fmt: skip
    """``near_ik`` for targets P (N, 3) [m] at pitches (N,) [rad] or None from seeds
    (N, dof) [rad]: the closed form's batch per seed roll, each solution polished; a
    target that fails there is solved by ``one`` (``ik``: the other rolls, the numeric
    solver), its reason kept where that refuses it too."""
    near = chain.near
    assert near is not None
    n, dof = len(P), chain.dof
    q, ok = np.full((n, dof), np.nan), np.zeros(n, dtype=bool)
    reason = np.full(n, "", dtype="<U14")
    roll_per = np.clip(seed[:, -1], chain.lower[-1], chain.upper[-1])
    for roll in np.unique(roll_per).tolist():
        rows = np.flatnonzero(roll_per == roll)
        got = solve(
            chain_at(near, roll), P[rows], None if pitch is None else pitch[rows], seed[rows, :-1]
        )
        for k, i in enumerate(rows.tolist()):
            p = (float(P[i, 0]), float(P[i, 1]), float(P[i, 2]))
            at = None if pitch is None else float(pitch[i])
            done = polish(chain, p, at, [*got.q[k].tolist(), roll]) if got.ok[k] else None
            if done is None:
                try:
                    done = tuple(one(p, at, tuple(seed[i].tolist())).q.tolist())
                except UnreachableError as e:
                    reason[i] = got.reason[k] or e.reason
                    continue
            q[i], ok[i] = done, True
    return IKBatchResult(q, ok, reason, "analytic")


def polish(chain: Chain, p: P3, pitch: float | None, q: list[float]) -> Q | None:
    """Joint angles q [rad] (the roll last, held) moved by Newton's method until the true
    chain's tool point is p [m] (and its pitch ``pitch`` [rad]; None: the pitch gives way,
    joints on a limit held); None if that fails or leaves the limits."""
    task: Task[float] = Task(p, pitch, None, 1.0)
    moving = list(range(chain.dof - 1))
    if pitch is None:
        moving = [j for j in moving if chain.lower[j] + SLACK < q[j] < chain.upper[j] - SLACK]
    r = residual(task, chain.state(q), True)
    for _ in range(STEPS):
        if r.position_error <= DONE_M and r.angle_error <= DONE_M:
            break
        cols: Any = r.cols
        J = [cols[j] for j in moving]  # per moving joint, its column: x, y, z (, pitch)
        step = _newton_step(J, r.e)
        if step is None:
            return None
        for j, d in zip(moving, step, strict=True):
            q[j] += d
        r = residual(task, chain.state(q), True)
    if not (r.position_error <= ACCEPT_M and r.angle_error <= ACCEPT_RAD):
        return None
    for j, (lo, hi) in enumerate(zip(chain.lower, chain.upper, strict=True)):
        if not lo - SLACK <= q[j] <= hi + SLACK:
            return None
        q[j] = min(max(q[j], lo), hi)
    return tuple(q)


def _newton_step(cols: list[tuple[float, ...]], e: list[float]) -> list[float] | None:
    """dq with J dq = e, J given by its columns: exactly where J is square, else the
    least-norm dq = J^T (J J^T)^-1 e; None where J is singular. Plain floats (a 4x4
    solve in floats is tens of times quicker than numpy's per-call overhead)."""
    rows = len(e)
    if len(cols) == rows:
        A = [[cols[k][i] for k in range(rows)] for i in range(rows)]
        return _solve(A, list(e))
    G = [[sum(c[i] * c[k] for c in cols) for k in range(rows)] for i in range(rows)]
    y = _solve(G, list(e))
    return None if y is None else [sum(c[i] * y[i] for i in range(rows)) for c in cols]


def _solve(A: list[list[float]], b: list[float]) -> list[float] | None:
    """x with A x = b (n x n, Gaussian elimination with partial pivoting); None if A is
    singular. A and b are overwritten."""
    n = len(b)
    for c in range(n):
        k = max(range(c, n), key=lambda i: abs(A[i][c]))
        if abs(A[k][c]) < 1e-300:
            return None
        A[c], A[k], b[c], b[k] = A[k], A[c], b[k], b[c]
        pivot = A[c][c]
        for i in range(c + 1, n):
            f = A[i][c] / pivot
            if f:
                row, top = A[i], A[c]
                for m in range(c, n):
                    row[m] -= f * top[m]
                b[i] -= f * b[c]
    x = [0.0] * n
    for i in range(n - 1, -1, -1):
        x[i] = (b[i] - sum(A[i][m] * x[m] for m in range(i + 1, n))) / A[i][i]
    return x


def _distance(q: Q, seed: Q) -> float:
    """Squared joint distance [rad^2]."""
    return sum((a - b) * (a - b) for a, b in zip(q, seed, strict=True))
