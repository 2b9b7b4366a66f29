"""Levenberg-Marquardt (damped least squares) IK with joint limits in the step, run by
the compiled kernel ``_lmc`` (``_lmc.c``): one target, or N targets in one call.

The method: each step solves (J J^T + lam I) y = e, dq = J^T y for the task's masked,
weighted Jacobian (or the n x n form when fewer joints than task rows); joints sitting
at a limit and pushed outwards are frozen and the step recomputed without them, then
the new q is clamped into the box. lam = mu |e|^2 (Sugihara's choice), mu adapted
Marquardt-style. Every run starts by turning the first joint alone to its exact best
angle (on even restarts stopping at its limit where the best angle is outside them);
a run that stops improving restarts from a seeded random q inside the limits
(splitmix64 from ``rng_seed``: the same seed, the same answer, and row i of a batch is
the single call on target i). Why compiled: each iteration of this method in Python
costs 20-40 us of interpreter time for under 1 us of arithmetic, 5-10x Robotics
Toolbox's C++ per call. tests/numeric/lm_reference.py is the same method in Python;
tests pin the kernel to it.
"""

from __future__ import annotations

import struct
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from ..._errors import ArmkitError
from .._chain import Chain
from .._residual import Residual, Task
from ._outcome import Attempt

try:
    from ._lmc import solve_many, solve_one
except ImportError:  # a source tree whose extension was not built: say so when LM is used
    KERNEL_MISSING = True
else:
    KERNEL_MISSING = False

F64 = NDArray[np.float64]
_TARGET = struct.Struct("13d")  # p (3) [m], pitch [rad], R (9, row-major)
_NO_R = (0.0,) * 9
MISSING = (
    "numeric IK (method 'lm') needs armkit's compiled solver (kinematics/_numeric/_lmc.c), "
    "which was not built when armkit was installed (no C compiler?); install a C compiler "
    "(e.g. `apt install gcc`) and reinstall armkit (`pip install -e .` or `make lint` in its "
    "folder); closed-form arms and the methods ccd, jacobian and random work without it"
)


def mode_of(pitch: object, R: object) -> int:
    """The kernel's task mode: 0 position, 1 position + pitch, 2 pose."""
    return 1 if pitch is not None else (2 if R is not None else 0)


def solve_lm(
    chain: Chain, task: Task[float], q_seed: list[float], tol_pos: float, tol_ang: float,
    rng_seed: int,
) -> Attempt:  # fmt: skip
    """LM from ``q_seed`` [rad] (clamped into the limits), restarting when stalled.

    Returns:
        The converged ``Attempt``, or the best one found when the budget ran out.
    """
    if KERNEL_MISSING:
        raise ArmkitError(MISSING)
    p, pitch, R = task.p, task.pitch, task.R
    target = _TARGET.pack(*p, 0.0 if pitch is None else pitch, *(_NO_R if R is None else R))
    q, ok, its, restarts, pos, ang, cost = solve_one(
        chain.packed, mode_of(pitch, R), target, q_seed, tol_pos, tol_ang, rng_seed
    )
    return Attempt(list(q), Residual([], None, pos, ang, cost), its, restarts, bool(ok))


@dataclass(frozen=True)
class BatchOutcome:
    """q [rad] (N, dof), converged (N,), restarts (N,), and far (N,): True where the
    target is beyond the chain's reach."""

    q: F64
    converged: NDArray[np.bool_]
    restarts: NDArray[np.int64]
    far: NDArray[np.bool_]


def solve_lm_batch(
    chain: Chain, P: F64, pitch: F64 | None, R: F64 | None, seeds: F64, tol_pos: float,
    tol_ang: float, rng_seed: int,
) -> BatchOutcome:  # fmt: skip
    """LM on N targets: positions P (N, 3) [m], pitches (N,) [rad] or orientations
    (N, 3, 3) or neither, from seeds (N, dof) [rad]; each target as ``solve_lm``'s."""
    if KERNEL_MISSING:
        raise ArmkitError(MISSING)
    n = len(P)
    targets = np.zeros((n, 13))
    targets[:, :3] = P
    if pitch is not None:
        targets[:, 3] = pitch
    if R is not None:
        targets[:, 4:] = R.reshape(n, 9)
    q = np.empty((n, chain.dof))
    info = np.empty((n, 5))
    seeds = np.ascontiguousarray(seeds, dtype=np.float64)
    solve_many(chain.packed, mode_of(pitch, R), targets, seeds, q, info, tol_pos, tol_ang, rng_seed)
    far = np.einsum("ij,ij->i", P, P) > chain.reach * chain.reach
    return BatchOutcome(q, info[:, 0] > 0.0, info[:, 2].astype(np.int64), far)
