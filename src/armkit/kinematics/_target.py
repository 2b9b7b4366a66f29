"""What an IK call asks for: the public ``Target``, and the checked ``Aim``."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from numpy.typing import ArrayLike

from .._errors import InputError
from .._inputs import angle, array, rotation


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

    def __post_init__(self) -> None:  # InputError naming the field; the values kept as given
        if self.pitch is not None and self.orientation is not None:
            raise InputError("give pitch or orientation, not both")
        P = array(self.position, "position", ((3,), (None, 3)), "m")
        n = None if P.ndim == 1 else len(P)
        if self.pitch is not None and n is None:
            angle(self.pitch, "pitch")
        elif self.pitch is not None:
            array(self.pitch, "pitch", ((), (n,)), "rad")
        if self.orientation is not None:
            rotation(self.orientation, "orientation", n)

    @property
    def mask(self) -> str:
        """``"position"``, ``"position+pitch"`` or ``"pose"``."""
        if self.orientation is not None:
            return "pose"
        return "position" if self.pitch is None else "position+pitch"


Aim = tuple[tuple[float, float, float], "float | None", "tuple[float, ...] | None"]
"""A checked single target in plain floats: p [m], pitch [rad] or None, R row-major or None
(a bare tuple: the closed form builds one per call)."""
