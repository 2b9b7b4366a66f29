"""The simulated servo arm's record of true joint angles over simulated time."""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

F64 = NDArray[np.float64]


@dataclass(frozen=True)
class Recording:
    """True joint angles sampled once per simulation step.

    Attributes:
        joint_names: the joints, in model order.
        t: sample times [s], shape (N,).
        q: true joint angles [rad], shape (N, dof).
    """

    joint_names: tuple[str, ...]
    t: F64
    q: F64

    def between(self, t0: float, t1: float) -> Recording:
        """The samples with t0 <= t <= t1 [s]."""
        keep = (self.t >= t0 - 1e-9) & (self.t <= t1 + 1e-9)
        return Recording(self.joint_names, self.t[keep], self.q[keep])

    def write_csv(self, path: str | Path) -> int:
        """Write ``t_s,<joint>_deg,...`` and one row per sample; returns the row count."""
        header = ",".join(["t_s", *(f"{n}_deg" for n in self.joint_names)])
        table = np.column_stack([self.t, np.degrees(self.q)])
        np.savetxt(Path(path), table, fmt="%.6f", delimiter=",", header=header, comments="")
        return int(table.shape[0])


class Recorder:
    """Collects one (t, q) sample per call; ``recording()`` stacks them."""

    def __init__(self, joint_names: tuple[str, ...]) -> None:
        self.joint_names = joint_names
        self._t: list[float] = []
        self._q: list[F64] = []

    def add(self, t: float, q: F64) -> None:
        """Append the sample at time ``t`` [s], angles ``q`` [rad], shape (dof,)."""
        self._t.append(t)
        self._q.append(q)

    def recording(self) -> Recording:
        """Everything recorded so far."""
        dof = len(self.joint_names)
        q = np.array(self._q) if self._q else np.zeros((0, dof))
        return Recording(self.joint_names, np.array(self._t, dtype=np.float64), q)


def rounded_steps(seconds: float, dt: float) -> int:
    """Whole simulation steps of ``dt`` in ``seconds`` (at least 0)."""
    return max(0, math.ceil(seconds / dt - 1e-6))
