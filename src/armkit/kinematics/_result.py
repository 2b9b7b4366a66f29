"""The typed results every IK method returns."""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import cached_property
from typing import Literal

import numpy as np
from numpy.typing import NDArray

from ._chain import Chain
from ._target import Goal, errors

F64 = NDArray[np.float64]
Method = Literal["analytic", "lm", "ccd", "jacobian", "random"]
METHODS: tuple[Method, ...] = ("analytic", "lm", "ccd", "jacobian", "random")


@dataclass(frozen=True, eq=False)
class IKResult:
    """What an IK solver found.

    Attributes:
        q: the best solution, joint angles [rad], shape (dof,).
        solutions: every solution found, best first, shape (k, dof), k >= 1.
            Best = nearest to the seed (or to home) in joint space.
        method: the solver that produced it.
        iterations: solver iterations (0 for the closed form).
        restarts: restarts from new seeds (0 for the closed form).
        goal: the target as solved (position [m], pitch [rad] or None, rotation or None).
        position_error: distance from the tool point of ``q`` to the target [m],
            measured by forward kinematics when first read.
        angle_error: pitch or orientation error of ``q`` [rad] (0 when none was asked for).
    """

    q: F64
    solutions: F64
    method: Method
    iterations: int
    restarts: int
    goal: Goal
    chain: Chain = field(repr=False)

    @cached_property
    def _errors(self) -> tuple[float, float]:
        return errors(self.goal, self.chain.state(self.q.tolist()))

    @property
    def position_error(self) -> float:
        """Distance from the tool point of ``q`` to the target [m]."""
        return self._errors[0]

    @property
    def angle_error(self) -> float:
        """Pitch or orientation error of ``q`` [rad]."""
        return self._errors[1]

    def __repr__(self) -> str:
        q = np.round(np.degrees(self.q), 3).tolist()
        return f"IKResult(q_deg={q}, solutions={len(self.solutions)}, method={self.method!r})"


@dataclass(frozen=True, slots=True)
class IKBatchResult:
    """What a batch IK solver found for N targets.

    Attributes:
        q: best solution per target [rad], shape (N, dof); NaN rows where it failed.
        ok: True where a solution within the limits was found, shape (N,).
        reason: '' where ok, else why not (an ``armkit.Reason``: ``"too_far"``,
            ``"too_close"``, ``"joint_limit"``, ``"off_plane"``, ``"pitch"``,
            ``"no_convergence"``), shape (N,).
        method: the solver used.
    """

    q: F64
    ok: NDArray[np.bool_]
    reason: NDArray[np.str_]
    method: Method
