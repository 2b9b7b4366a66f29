"""The task residual and masked Jacobian of ``_residual`` for N joint vectors at once."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from .._pose import pitch_of
from ._residual import rotation_log, wrap

F64 = NDArray[np.float64]


@dataclass(frozen=True)
class BatchTask:
    """N targets prepared for the batch solver.

    Attributes:
        P: tool points [m], shape (N, 3).
        pitch: pitches [rad], shape (N,), or None.
        R: rotations R_world_tool, shape (N, 3, 3), or None.
        weight: metres per radian for the angle rows [m/rad].
    """

    P: F64
    pitch: F64 | None
    R: F64 | None
    weight: float

    def take(self, idx: NDArray[np.intp]) -> BatchTask:
        """The targets at indices ``idx``."""
        pitch = None if self.pitch is None else self.pitch[idx]
        return BatchTask(self.P[idx], pitch, None if self.R is None else self.R[idx], self.weight)


@dataclass(frozen=True)
class BatchResidual:
    """Residuals e (k, m), masked weighted Jacobians (k, m, dof), errors [m], [rad] (k,)."""

    e: F64
    J: F64
    position_error: F64
    angle_error: F64

    @property
    def cost(self) -> F64:
        """|e|^2 per target, shape (k,)."""
        return np.asarray(np.einsum("km,km->k", self.e, self.e), dtype=np.float64)


def residual_batch(task: BatchTask, J: F64, T: F64) -> BatchResidual:
    """Residuals of poses T (k, 4, 4) with geometric Jacobians J (k, 6, dof)."""
    e, pos, ang = _errors(task, T)
    w = task.weight
    if task.pitch is not None:
        Jm = np.concatenate([J[:, :3], w * _pitch_gradient(J, T)[:, None]], axis=1)
    elif task.R is not None:
        Jm = np.concatenate([J[:, :3], w * J[:, 3:]], axis=1)
    else:
        Jm = J[:, :3]
    return BatchResidual(e, Jm, pos, ang)


def task_cost(task: BatchTask, T: F64) -> F64:
    """|e|^2 per pose T (k, 4, 4) [m^2], without the Jacobian (to rank candidates)."""
    e = _errors(task, T)[0]
    return np.asarray(np.einsum("km,km->k", e, e), dtype=np.float64)


def _errors(task: BatchTask, T: F64) -> tuple[F64, F64, F64]:
    """e (k, m) of poses T (k, 4, 4), and the unweighted position [m] and angle [rad]
    errors, shape (k,) each."""
    e_pos = task.P - T[:, :3, 3]
    pos = np.sqrt(np.einsum("ki,ki->k", e_pos, e_pos))
    if task.pitch is not None:
        d = wrap(task.pitch - pitch_of(T))
        return np.concatenate([e_pos, task.weight * d[:, None]], axis=1), pos, np.abs(d)
    if task.R is not None:
        rv = _rotation_log(task.R, T[:, :3, :3])
        ang = np.sqrt(np.einsum("ki,ki->k", rv, rv))
        return np.concatenate([e_pos, task.weight * rv], axis=1), pos, ang
    return e_pos, pos, np.zeros_like(pos)


def _pitch_gradient(J: F64, T: F64) -> F64:
    """d pitch / dq [rad/rad], shape (k, dof) (as ``pitch_gradient``)."""
    a, p = T[:, :3, 0], T[:, :3, 3]
    ax, ay, az, px, py = a[:, 0:1], a[:, 1:2], a[:, 2:3], p[:, 0:1], p[:, 1:2]
    rho = np.maximum(np.hypot(px, py), 1e-9)
    h = (ax * px + ay * py) / rho
    Jv, Jw = J[:, :3], J[:, 3:]
    wx, wy, wz = Jw[:, 0], Jw[:, 1], Jw[:, 2]
    dax, day, daz = wy * az - wz * ay, wz * ax - wx * az, wx * ay - wy * ax  # w x a
    vx, vy = Jv[:, 0], Jv[:, 1]
    dh = (dax * px + ax * vx + day * py + ay * vy) / rho - h * (px * vx + py * vy) / (rho * rho)
    return np.asarray((h * daz - az * dh) / np.maximum(az * az + h * h, 1e-300))


def _rotation_log(R_goal: F64, R: F64) -> F64:
    """Rotation vectors [rad] of R_goal R^T, shape (k, 3)."""
    E = R_goal @ R.transpose(0, 2, 1)
    v = np.stack(
        [E[:, 2, 1] - E[:, 1, 2], E[:, 0, 2] - E[:, 2, 0], E[:, 1, 0] - E[:, 0, 1]], axis=1
    )
    s = 0.5 * np.sqrt(np.einsum("ki,ki->k", v, v))
    c = 0.5 * (np.trace(E, axis1=1, axis2=2) - 1.0)
    theta = np.arctan2(s, c)
    f = np.where(s < 1e-12, 0.5, theta / (2.0 * np.maximum(s, 1e-300)))
    out = f[:, None] * v
    for i in np.flatnonzero((s <= 1e-6) & (c <= 0.0)):
        cols = (tuple(R[i, :, 0]), tuple(R[i, :, 1]), tuple(R[i, :, 2]))
        out[i] = rotation_log(tuple(R_goal[i].ravel()), cols)  # type: ignore[arg-type]
    return out
