"""The pen on the simulated paper: an observer of the World that records the pen's
tip while the pen is held, and calls it ink where the tip is no higher than
``contact`` above the sheet's plane (at or below it: the pen presses on the paper)."""

from __future__ import annotations

from typing import Protocol

import numpy as np
from numpy.typing import NDArray

from ..kinematics import fk
from ..model import ArmModel
from ..scene import Sheet
from ._metrics import PenTrace

F64 = NDArray[np.float64]
CONTACT = 0.5e-3  # [m]: the tip within this of the paper leaves ink (the 0.5 mm)


class _SimArm(Protocol):
    def q(self) -> F64: ...

    def recent(self, count: int) -> F64: ...


class _World(Protocol):
    def arm(self, name: str | None = None) -> _SimArm: ...


class PenTracer:
    """``armkit.sim.Observer``: the tip of the pen held by arm ``arm`` (None: the only
    arm), ``tip`` the arm's model with the pen as its tool, ``T_scene_base`` (4, 4)
    the arm's base in the sheet's frame. Records while ``holding`` is True."""

    def __init__(
        self,
        tip: ArmModel,
        sheet: Sheet,
        T_scene_base: F64,
        arm: str | None = None,
        contact: float = CONTACT,
    ) -> None:
        self.tip, self.sheet, self.T, self.arm = tip, sheet, T_scene_base, arm
        self.contact = contact
        self.holding = False
        self._t: list[float] = []
        self._p: list[F64] = []

    def on_step(self, world: _World, t: float) -> None:
        """Record the tip at simulated time ``t`` [s] if the pen is held."""
        if self.holding:
            self._t.append(t)
            self._p.append((self.T @ fk(self.tip, world.arm(self.arm).q()))[:3, 3])

    def on_steps(self, world: _World, times: F64) -> None:
        """Record the tip at every step of a stretch (times [s], shape (N,)) if the pen is
        held: the angles each step recorded, the tips in one batch."""
        if self.holding:
            q = world.arm(self.arm).recent(len(times))
            self._t.extend(times.tolist())
            self._p.extend(list((self.T @ fk(self.tip, q))[:, :3, 3]))

    def trace(self) -> PenTrace | None:
        """What was recorded, or None if nothing."""
        if not self._t:
            return None
        p = np.array(self._p)
        height = (p - self.sheet.origin) @ self.sheet.normal
        inside = self.sheet.contains(
            (p - self.sheet.origin) @ np.column_stack([self.sheet.u, self.sheet.v])
        )
        return PenTrace(np.array(self._t), p, (height <= self.contact) & inside)
