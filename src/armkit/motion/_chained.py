"""IK along a sequence of points, each solution nearest the previous one's, in a
few batches instead of one ``ik`` call per point.

The reference is the loop ``seed = ik(model, p[i], pitch, seed).q``. With a closed
form at a given pitch, whether a point is reachable does not depend on the seed,
and the seed only picks the branch; so every point is solved in one ``ik_batch``
seeded by the start, then again seeded by the previous point's solution, until
the solutions no longer change: that fixed point is the loop's answer (point 0 is
seeded as the loop seeds it, and point i's seed is the loop's q[i - 1] by
induction). Where it does not settle in ``ROUNDS`` batches, or the arm has no
closed form at a fixed pitch, the caller runs the loop (``None``).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from ..kinematics import ik_batch, why_no_closed_form
from ..model import ArmModel

F64 = NDArray[np.float64]
Bools = NDArray[np.bool_]
ROUNDS = 4


def batchable(model: ArmModel, pitch: float | None) -> bool:
    """Whether ``chained_ik`` can answer for this arm: a closed form at a fixed pitch."""
    fixed = pitch is not None or model.default_pitch is not None
    return fixed and model.dof > 2 and not why_no_closed_form(model)


def reachable_at(model: ArmModel, points: F64, pitch: float) -> Bools:
    """Which points (N, 3) [m] ``ik`` solves at ``pitch`` [rad] (any seed), shape (N,)."""
    if len(points) == 0:
        return np.zeros(0, dtype=bool)
    return np.asarray(ik_batch(model, points, pitch).ok, dtype=bool)


def chained_ik(model: ArmModel, points: F64, pitch: float, q_start: F64) -> F64 | None:
    """Joints (N, dof) [rad] for points (N, 3) [m], every one reachable at ``pitch``
    [rad], point 0's nearest ``q_start`` and each next one's nearest the previous
    one's, as the loop of ``ik`` gives them; None where this cannot say (some point
    unreachable, no fixed point): run the loop."""
    n = len(points)
    if n == 0:
        return np.zeros((0, len(q_start)))
    start = np.asarray(q_start, dtype=np.float64)[None, :]
    got = ik_batch(model, points, pitch, start[0])
    if not bool(np.all(got.ok)):
        return None
    q = got.q
    for _ in range(ROUNDS):
        again = ik_batch(model, points, pitch, np.vstack([start, q[:-1]]))
        if not bool(np.all(again.ok)):
            return None
        if np.array_equal(again.q, q):
            return q
        q = again.q
    return None
