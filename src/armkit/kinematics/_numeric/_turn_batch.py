"""The first joint's best turn for N joint vectors at once: the batch LM's warm start.

The vectorised ``_turn.best_turn`` for joint 0 (see there for the formula).
Joint 0's axis never moves, so it is found once from the chain. As in the
scalar solver's ``_turn_first_joint``: a row is turned where that lowers the
task cost; where the best angle is outside the limits, the joint faces the
opposite way instead (if that is inside them), to reach back over the base.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from .._chain import Chain
from .._forward import sweep
from ._residual_batch import BatchTask, task_cost

F64 = NDArray[np.float64]


def turn_first_joint(chain: Chain, task: BatchTask, q: F64) -> F64:
    """q (k, dof) [rad] with joint 0 turned to its best angle where that helps."""
    T = sweep(chain, q).T
    st = chain.state(list(chain.home))  # joint 0's axis never moves
    z, o = np.array(st.jw[0]), np.array(st.origins[0])
    u, v = _reject(T[:, :3, 3] - o, z), _reject(task.P - o, z)
    num, den = _triple(z, u, v), np.einsum("ki,ki->k", u, v)
    w2 = task.weight * task.weight
    for a, b in _axis_pairs(task, T):
        a, b = _reject(a, z), _reject(b, z)
        num += w2 * _triple(z, a, b)
        den += w2 * np.einsum("ki,ki->k", a, b)
    lo, hi = chain.lower[0], chain.upper[0]
    turned = q.copy()
    turned[:, 0] += np.arctan2(num, den)
    flip = (turned[:, 0] < lo) | (turned[:, 0] > hi)
    turned[flip, 0] += np.where(turned[flip, 0] > hi, -np.pi, np.pi)
    inside = (turned[:, 0] >= lo) & (turned[:, 0] <= hi)
    better = task_cost(task, sweep(chain, turned).T) < task_cost(task, T)
    return np.where((inside & (flip | better))[:, None], turned, q)


def _axis_pairs(task: BatchTask, T: F64) -> list[tuple[F64, F64]]:
    """(tool axis, target axis) pairs, each shape (k, 3), for the angular part of the task."""
    if task.R is not None:
        return [(T[:, :3, k], task.R[:, :, k]) for k in range(3)]
    if task.pitch is None:
        return []
    a = T[:, :3, 0]
    horizontal = task.P[:, :2].copy()
    rho = np.hypot(horizontal[:, 0], horizontal[:, 1])
    on_axis = rho < 1e-9
    horizontal[on_axis] = a[on_axis, :2]
    rho = np.maximum(np.hypot(horizontal[:, 0], horizontal[:, 1]), 1e-12)
    c, s = np.cos(task.pitch), np.sin(task.pitch)
    b = np.column_stack([c * horizontal[:, 0] / rho, c * horizontal[:, 1] / rho, s])
    return [(a, b)]


def _reject(a: F64, z: F64) -> F64:
    """Rows of a (k, 3) minus their components along the unit vector z (3,)."""
    return a - np.outer(a @ z, z)


def _triple(z: F64, a: F64, b: F64) -> F64:
    """z . (a x b) per row, shape (k,)."""
    return np.asarray(
        z[0] * (a[:, 1] * b[:, 2] - a[:, 2] * b[:, 1])
        + z[1] * (a[:, 2] * b[:, 0] - a[:, 0] * b[:, 2])
        + z[2] * (a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0]),
        dtype=np.float64,
    )
