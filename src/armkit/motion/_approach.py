"""Coming down onto a point from above and leaving the same way (seed 001's
pick and place: first at least 30 mm above, then three waypoints down)."""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .._errors import InputError
from ._paths import point3

F64 = NDArray[np.float64]
MIN_HEIGHT = 0.030  # [m], 001's clearance above the target


def approach(target: ArrayLike, height: float = MIN_HEIGHT, steps: int = 3) -> F64:
    """Waypoints [m], shape (steps + 1, 3): ``height`` [m] straight above ``target``,
    then ``steps`` waypoints down, evenly spaced, the last the target itself."""
    p = point3(target, "target")
    if not height >= MIN_HEIGHT:
        raise InputError(f"approach height must be >= 30 mm, got {height * 1000:.1f} mm")
    if steps < 1:
        raise InputError(f"steps must be >= 1, got {steps}")
    offsets = np.linspace(height, 0.0, steps + 1)
    up: F64 = p + offsets[:, None] * np.array([0.0, 0.0, 1.0])
    return up


def retreat(target: ArrayLike, height: float = MIN_HEIGHT, steps: int = 3) -> F64:
    """The approach reversed: from ``target`` up to ``height`` [m] above it, (steps + 1, 3)."""
    return approach(target, height, steps)[::-1].copy()
