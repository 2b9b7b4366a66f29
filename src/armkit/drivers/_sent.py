"""What a driver of smart servos last told them: the profile in flight, for reading and timing.

The servos' encoders lag behind their profiles, so a move sent while another is in
flight starts from where the profile has the joints (not where the encoders read),
and a servo resting on the tick of the goal it was sent reads as that goal (the
angle asked for), while the profile itself runs to the goal's tick (``end``).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

F64 = NDArray[np.float64]
I64 = NDArray[np.int64]


@dataclass(frozen=True)
class SentProfile:
    """A time-based profile sent at ``t0`` [s] for the angles ``goal`` [rad], shape (dof,),
    as goal ``ticks`` (the angles ``end`` [rad]): from ``start`` [rad], lasting ``total`` [s]."""

    start: F64
    goal: F64
    end: F64
    ticks: I64
    t0: float
    total: float

    def where(self, now: float) -> F64:
        """Where the profile has the joints at ``now`` [s] (straight-line estimate) [rad]."""
        frac = min(1.0, max(0.0, (now - self.t0) / self.total)) if self.total > 0 else 1.0
        return self.start + (self.end - self.start) * frac

    def done(self, now: float) -> bool:
        """Whether the profile has ended at ``now`` [s]."""
        return now - self.t0 >= self.total

    def reading(self, ticks: I64, angles: F64) -> F64:
        """``angles`` [rad] read at ``ticks``, with every servo on its goal tick reading as
        the goal's angle (the tick holds it to within half a tick either way)."""
        out = angles.copy()
        on_goal = ticks == self.ticks
        out[on_goal] = self.goal[on_goal]
        return out
