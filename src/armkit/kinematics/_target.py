"""What an IK call asks for, and how far an answer is from it."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, NamedTuple

from numpy.typing import ArrayLike

from ._pose import pitch_scalar, rotation_angle
from ._state import ChainState


@dataclass(frozen=True, slots=True, eq=False)
class Target:
    """An IK target in the world frame: a position, optionally a pitch or an orientation.

    ``ik`` takes one target (position shape (3,), pitch a number), ``ik_batch`` N
    targets (positions (N, 3), pitches a number or (N,), orientations (N, 3, 3)).

    Attributes:
        position: tool point(s) [m].
        pitch: approach angle above the horizontal [rad] (see ``pitch_of``), or None.
        orientation: full tool orientation(s) R_world_tool, or None.
            At most one of pitch and orientation is set.
    """

    position: ArrayLike
    pitch: Any = None
    orientation: ArrayLike | None = None

    @property
    def mask(self) -> str:
        """``"position"``, ``"position+pitch"`` or ``"pose"``."""
        if self.orientation is not None:
            return "pose"
        return "position" if self.pitch is None else "position+pitch"


Aim = tuple[tuple[float, float, float], "float | None", "tuple[float, ...] | None"]
"""A checked single target in plain floats: p [m], pitch [rad] or None, R row-major or None
(the closed form passes a bare tuple: cheaper to build than a ``Goal``)."""


class Goal(NamedTuple):
    """An ``Aim`` with names."""

    p: tuple[float, float, float]
    pitch: float | None
    R: tuple[float, ...] | None


def errors(goal: Aim, st: ChainState[float]) -> tuple[float, float]:
    """Position [m] and pitch or orientation [rad] error of a chain state for ``goal``."""
    (px, py, pz), ((gx, gy, gz), pitch, R) = st.p, goal
    pos = math.sqrt((px - gx) ** 2 + (py - gy) ** 2 + (pz - gz) ** 2)
    if pitch is not None:
        return pos, abs(math.remainder(pitch_scalar(st.R[0], st.p) - pitch, 2 * math.pi))
    if R is not None:
        return pos, rotation_angle(R, st.R)
    return pos, 0.0
