"""The typed results every IK method returns."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Literal

import numpy as np
from numpy.typing import NDArray

from ._chain import Chain
from ._residual import Residual, Task, residual
from ._target import Aim

F64 = NDArray[np.float64]
Ranked = Sequence[tuple[float, tuple[float, ...]]]  # (distance to the seed, q) pairs
Method = Literal["analytic", "lm", "ccd", "jacobian", "random"]
METHODS: tuple[Method, ...] = ("analytic", "lm", "ccd", "jacobian", "random")
_new = object.__new__


@dataclass(frozen=True, eq=False)
class IKResult:
    """What an IK solver found.

    Attributes:
        ranked: every solution found as (squared joint distance to the seed [rad^2],
            joint angles [rad]) pairs, in any order (see ``solutions``).
        goal: the target as solved (position [m], pitch [rad] or None, rotation or None).
        chain: the arm's compiled chain, to measure the errors.
        method: the solver that produced it.
        iterations: solver iterations (0 for the closed form).
        restarts: restarts from new seeds (0 for the closed form).

    The arrays and the errors are derived from these fields when read (``q``,
    ``solutions``, ``position_error``, ``angle_error``), so a closed-form call
    stays within microseconds; reading ``q`` costs about half a microsecond.
    """

    ranked: Ranked
    goal: Aim
    chain: Chain = field(repr=False)
    method: Method = "analytic"
    iterations: int = 0
    restarts: int = 0

    @classmethod
    def of(cls, ranked: Ranked, goal: Aim, chain: Chain) -> IKResult:
        """A closed-form result, as the constructor builds it but without the frozen
        dataclass's per-field ``object.__setattr__``: the defaults stay on the class
        (a fifth of a 3.5 us closed-form call saved)."""
        self = _new(cls)
        d = self.__dict__
        d["ranked"] = ranked
        d["goal"] = goal
        d["chain"] = chain
        return self

    @property
    def q(self) -> F64:
        """The best solution (nearest the seed), joint angles [rad], shape (dof,)."""
        return np.array(min(self.ranked)[1])

    @property
    def solutions(self) -> F64:
        """Every solution [rad], nearest the seed first, repeats dropped, shape (k, dof)."""
        unique: list[tuple[float, ...]] = []
        for _, q in sorted(self.ranked):
            if all(max(abs(a - b) for a, b in zip(q, u, strict=True)) > 1e-9 for u in unique):
                unique.append(q)
        return np.array(unique)

    @property
    def position_error(self) -> float:
        """Distance from the tool point of ``q`` to the target [m], by forward kinematics."""
        return self._residual().position_error

    @property
    def angle_error(self) -> float:
        """Pitch or orientation error of ``q`` [rad] (0 when none was asked for)."""
        return self._residual().angle_error

    def _residual(self) -> Residual[float]:
        """The residual of ``q`` for the goal (the errors only)."""
        p, pitch, R = self.goal
        return residual(Task(p, pitch, R, 1.0), self.chain.state(list(min(self.ranked)[1])), False)

    def __repr__(self) -> str:
        q = np.round(np.degrees(self.q), 3).tolist()
        return f"IKResult(q_deg={q}, solutions={len(self.ranked)}, method={self.method!r})"


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
