"""The typed results every IK method returns."""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from functools import partial
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

F64 = NDArray[np.float64]
Checker = Callable[[F64], tuple[float, float]] | tuple[Any, tuple[float, ...], float | None]


class IKResult:
    """What an IK solver found.

    Attributes:
        q: the best solution, joint angles [rad], shape (dof,).
        solutions: every solution found, best first, shape (k, dof), k >= 1.
            Best = nearest to the seed (or to home) in joint space.
        method: the solver that produced it (``"analytic"``, ``"lm"``, ...).
        iterations: solver iterations (0 for the closed form).
        restarts: restarts from new seeds (0 for the closed form).
        position_error: distance from the tool point of ``q`` to the target [m].
        angle_error: pitch or orientation error of ``q`` [rad] (0 when none was asked for).

    The closed form builds the arrays and measures the errors (by forward
    kinematics) only when they are read, which keeps a call to microseconds.
    """

    __slots__ = ("_check", "_errors", "_q", "_solutions", "iterations", "method", "restarts")

    def __init__(
        self,
        q: ArrayLike,
        solutions: ArrayLike | Sequence[Sequence[float]],
        method: str,
        iterations: int = 0,
        restarts: int = 0,
        position_error: float | None = None,
        angle_error: float | None = None,
        *,
        check: Checker | None = None,
    ) -> None:
        self._q: ArrayLike = q
        self._solutions: ArrayLike | Sequence[Sequence[float]] = solutions
        self.method = method
        self.iterations = iterations
        self.restarts = restarts
        known = position_error is not None and angle_error is not None
        self._errors = (float(position_error), float(angle_error)) if known else None  # type: ignore[arg-type]
        self._check = check

    @property
    def q(self) -> F64:
        """Best solution [rad], shape (dof,)."""
        if not isinstance(self._q, np.ndarray):
            self._q = np.array(self._q, dtype=np.float64)
        return self._q

    @property
    def solutions(self) -> F64:
        """Every solution [rad], best first, shape (k, dof)."""
        if not isinstance(self._solutions, np.ndarray):
            sols: Any = self._solutions
            if isinstance(self, _ClosedForm):  # (distance, solution) pairs: best first
                sols = [q for _, q in sorted(sols, key=lambda pair: pair[0])]
            self._solutions = np.array(sols, dtype=np.float64)
        return self._solutions

    @property
    def position_error(self) -> float:
        """Distance from the tool point of ``q`` to the target [m]."""
        return self._measured()[0]

    @property
    def angle_error(self) -> float:
        """Pitch or orientation error of ``q`` [rad]."""
        return self._measured()[1]

    def _measured(self) -> tuple[float, float]:
        if self._errors is None:
            self._errors = _measure(self._check, self.q)
        return self._errors

    @staticmethod
    def closed_form(
        best: tuple[float, ...], ranked: list[tuple[float, tuple[float, ...]]], check: Checker
    ) -> IKResult:
        """A closed-form result from (distance, solution) pairs in any order; they are
        sorted, and the errors measured, only when read."""
        self = _new_closed()
        self._q, self._solutions, self._errors, self._check = best, ranked, None, check
        return self

    def __repr__(self) -> str:
        q = np.round(np.degrees(self.q), 3).tolist()
        return f"IKResult(q_deg={q}, solutions={len(self.solutions)}, method={self.method!r})"


class _ClosedForm(IKResult):
    """A closed-form IKResult: method, iterations and restarts are fixed for the class."""

    __slots__ = ()
    method = "analytic"  # type: ignore[assignment]
    iterations = 0  # type: ignore[assignment]
    restarts = 0  # type: ignore[assignment]


_new_closed = partial(object.__new__, _ClosedForm)


def _measure(check: Checker | None, q: F64) -> tuple[float, float]:
    """Errors of q: by the solver's callable, or by FK for a (model, position, pitch) target."""
    if check is None:
        return math.nan, math.nan
    if callable(check):
        return check(q)
    from ._ik import measure_error

    return measure_error(check[0], check[1], check[2], q)


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
