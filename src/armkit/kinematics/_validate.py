"""Input checks shared by the kinematics functions: shapes and finiteness."""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..model import ArmModel


def joint_array(model: ArmModel, q: ArrayLike, name: str) -> NDArray[np.float64]:
    """``q`` as float64 of shape (dof,) or (N, dof); ValueError naming ``name`` otherwise."""
    try:
        qa = np.asarray(q, dtype=np.float64)
    except (TypeError, ValueError):
        raise ValueError(f"{name} must be numbers, got {q!r}") from None
    if qa.ndim not in (1, 2) or qa.shape[-1] != model.dof:
        raise ValueError(
            f"{name} must have shape ({model.dof},) or (N, {model.dof}) for {model.name}, "
            f"got {qa.shape}"
        )
    if not np.all(np.isfinite(qa)):
        raise ValueError(f"{name} must be finite, got NaN or infinity")
    return qa


def point_array(p: ArrayLike, name: str, batch: bool) -> NDArray[np.float64]:
    """``p`` as float64 of shape (3,) or, with ``batch``, (N, 3); ValueError otherwise."""
    try:
        pa = np.asarray(p, dtype=np.float64)
    except (TypeError, ValueError):
        raise ValueError(f"{name} must be numbers, got {p!r}") from None
    want = 2 if batch else 1
    if pa.ndim != want or pa.shape[-1] != 3:
        shape = "(N, 3)" if batch else "(3,)"
        raise ValueError(f"{name} must have shape {shape}, got {pa.shape}")
    if not np.all(np.isfinite(pa)):
        raise ValueError(f"{name} must be finite, got NaN or infinity")
    return pa
