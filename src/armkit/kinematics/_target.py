"""What an IK call asks for: a position, optionally a pitch or a full orientation."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

F64 = NDArray[np.float64]


@dataclass(frozen=True)
class Target:
    """An IK target in the world frame.

    Attributes:
        position: tool point [m], shape (3,).
        pitch: approach angle above the horizontal [rad] (see ``pitch_of``), or None.
        orientation: full tool orientation R_world_tool, shape (3, 3), or None.
            At most one of pitch and orientation is set.
    """

    position: F64
    pitch: float | None = None
    orientation: F64 | None = None

    @property
    def mask(self) -> str:
        """``"position"``, ``"position+pitch"`` or ``"pose"``."""
        if self.orientation is not None:
            return "pose"
        return "position" if self.pitch is None else "position+pitch"
