"""The typed result every IK method returns."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

F64 = NDArray[np.float64]


@dataclass(frozen=True, slots=True)
class IKResult:
    """What an IK solver found.

    Attributes:
        q: the best solution, joint angles [rad], shape (dof,).
        solutions: every solution found, best first, shape (k, dof), k >= 1.
            Best = nearest to the seed (or to home) in joint space.
        method: the solver that produced it (``"analytic"``, ``"lm"``, ...).
        iterations: solver iterations (0 for the closed form).
        restarts: restarts from new seeds (0 for the closed form).
        position_error: distance from the tool point to the target [m].
        angle_error: pitch or orientation error [rad] (0 when not asked for).
    """

    q: F64
    solutions: F64
    method: str
    iterations: int = 0
    restarts: int = 0
    position_error: float = 0.0
    angle_error: float = 0.0


@dataclass(frozen=True, slots=True)
class IKBatchResult:
    """What a batch IK solver found for N targets.

    Attributes:
        q: best solution per target [rad], shape (N, dof); NaN rows where it failed.
        ok: True where a solution within the limits was found, shape (N,).
        reason: '' where ok, else why not (``"too_far"``, ``"too_close"``,
            ``"joint_limit"``, ``"off_plane"``, ``"pitch"``, ``"no_convergence"``), shape (N,).
        method: the solver used.
    """

    q: F64
    ok: NDArray[np.bool_]
    reason: NDArray[np.str_]
    method: str
