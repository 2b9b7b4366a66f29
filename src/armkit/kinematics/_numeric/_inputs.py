"""Checks on what the numeric solvers are given: ValueError naming the argument."""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ...model import ArmModel
from .._target import Target
from ._residual import Task, angle_weight

F64 = NDArray[np.float64]


def checked_target(target: Target) -> Target:
    """``target`` with its fields as finite float64 of the right shapes.

    Raises:
        ValueError: names ``position``, ``pitch`` or ``orientation`` and what is allowed.
    """
    p = finite_array(target.position, "position", (3,))
    pitch = target.pitch
    if pitch is not None and not math.isfinite(float(pitch)):
        raise ValueError(f"pitch must be a finite angle [rad] or None, got {pitch!r}")
    R = None if target.orientation is None else rotation(target.orientation, "orientation")
    if pitch is not None and R is not None:
        raise ValueError("give pitch or orientation, not both")
    return Target(p, None if pitch is None else float(pitch), R)


def numeric_task(
    model: ArmModel,
    p: tuple[float, float, float],
    pitch: float | None,
    orientation: ArrayLike | None,
) -> Task:
    """The ``Task`` of a finite point p [m] and pitch [rad] (both already checked) or an
    orientation, checked to be a rotation; ValueError if both pitch and orientation."""
    if orientation is None:
        return Task(p, pitch, None, angle_weight(model))
    if pitch is not None:
        raise ValueError("give pitch or orientation, not both")
    R = rotation(orientation, "orientation")
    return Task(p, None, tuple(R.ravel().tolist()), angle_weight(model))


def finite_array(value: ArrayLike, name: str, shape: tuple[int, ...]) -> F64:
    """``value`` as float64 of exactly ``shape`` with finite entries; ValueError otherwise."""
    exact = isinstance(value, np.ndarray) and value.dtype == np.float64 and value.shape == shape
    if exact and value.size <= 9 and all(map(math.isfinite, value.flat)):  # type: ignore[union-attr]
        return value  # type: ignore[return-value]  # the common case, without numpy's overhead
    try:
        a = np.asarray(value, dtype=np.float64)
    except (TypeError, ValueError):
        raise ValueError(f"{name} must be numbers, got {value!r}") from None
    if a.shape != shape:
        raise ValueError(f"{name} must have shape {shape}, got {a.shape}")
    if not np.all(np.isfinite(a)):
        raise ValueError(f"{name} must be finite, got NaN or infinity")
    return a


def rotation(value: ArrayLike, name: str, batch: int | None = None) -> F64:
    """``value`` checked to be rotation matrices, shape (3, 3) or (batch, 3, 3)."""
    shape = (3, 3) if batch is None else (batch, 3, 3)
    R = finite_array(value, name, shape)
    RRt = np.einsum("...ij,...kj->...ik", R, R)
    if not np.allclose(RRt, np.eye(3), atol=1e-6) or np.any(np.linalg.det(R) < 0):
        raise ValueError(f"{name} must be a rotation matrix (orthonormal, determinant +1)")
    return R


def tolerances(tol_pos_m: float, tol_ang_rad: float) -> tuple[float, float]:
    """The two tolerances, checked to be finite and > 0 [m], [rad]."""
    for name, v in (("tol_pos_m", tol_pos_m), ("tol_ang_rad", tol_ang_rad)):
        if not (isinstance(v, (int, float)) and math.isfinite(v) and v > 0):
            raise ValueError(f"{name} must be a finite number > 0, got {v!r}")
    return float(tol_pos_m), float(tol_ang_rad)


def seeds(model: ArmModel, q_seed: ArrayLike, n: int | None) -> F64:
    """Seed(s) [rad]: shape (dof,) for one target; (dof,) or (n, dof) broadcast to (n, dof)."""
    dof = model.dof
    if n is None:
        return finite_array(q_seed, "q_seed", (dof,))
    a = np.asarray(q_seed, dtype=np.float64)
    shape = (dof,) if a.ndim == 1 else (n, dof)
    return np.broadcast_to(finite_array(a, "q_seed", shape), (n, dof)).copy()
