"""The task residual e(q) and its masked Jacobian, for the three task masks.

    position         e = p* - p                              (3 rows)
    position+pitch   e = [p* - p, w (pitch* - pitch)]        (4 rows)
    pose             e = [p* - p, w log(R* R^T)]             (6 rows)

Angles are weighted by a length ``w`` [m/rad] so that one damped step mixes
metres and radians sensibly; the errors reported (and the tolerances) are the
unweighted distance [m] and angle [rad]. Scalar (one q) here; the vectorised
version for the batch solver is in ``_residual_batch``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TypeVar

import numpy as np
from numpy.typing import NDArray

from .._pose import pitch_scalar
from .._state import ChainState, Vec3

A = TypeVar("A", float, NDArray[np.float64])


@dataclass(frozen=True, slots=True)
class Task:
    """A target prepared for the solvers.

    Attributes:
        p: target tool point [m].
        pitch: target pitch [rad] or None.
        R: target rotation R_world_tool, row-major 9 floats, or None.
        weight: metres per radian for the angle rows [m/rad].
    """

    p: Vec3
    pitch: float | None
    R: tuple[float, ...] | None
    weight: float


@dataclass(slots=True)
class Residual:
    """e, the masked weighted Jacobian (or None), and the unweighted errors.
    (Not frozen: a frozen dataclass costs a microsecond more to build, and the
    solvers build one per iteration.)

    Attributes:
        e: residual, 3/4/6 floats.  cols: J by columns, per joint a tuple as long as e.
        cost: |e|^2 (weighted).
        position_error: [m].  angle_error: [rad] (0 for position-only tasks).
    """

    e: list[float]
    cols: list[tuple[float, ...]] | None
    position_error: float
    angle_error: float
    cost: float


def residual(task: Task, st: ChainState[float], jac: bool = True) -> Residual:
    """Residual of the chain state ``st`` for ``task``; the Jacobian rows if ``jac``."""
    p = st.p
    e0, e1, e2 = task.p[0] - p[0], task.p[1] - p[1], task.p[2] - p[2]
    pos2 = e0 * e0 + e1 * e1 + e2 * e2
    cols = task_jacobian(task, st) if jac else None
    if task.pitch is not None:
        d = wrap(task.pitch - pitch_scalar(st.R[0], p))
        wd = task.weight * d
        return Residual([e0, e1, e2, wd], cols, math.sqrt(pos2), abs(d), pos2 + wd * wd)
    if task.R is not None:
        w = task.weight
        r0, r1, r2 = rotation_log(task.R, st.R)
        e = [e0, e1, e2, w * r0, w * r1, w * r2]
        ang2 = r0 * r0 + r1 * r1 + r2 * r2
        return Residual(e, cols, math.sqrt(pos2), math.sqrt(ang2), pos2 + w * w * ang2)
    return Residual([e0, e1, e2], cols, math.sqrt(pos2), 0.0, pos2)


def task_jacobian(task: Task, st: ChainState[float]) -> list[tuple[float, ...]]:
    """The task's weighted Jacobian by columns: per joint, as many floats as e has rows."""
    w = task.weight
    if task.pitch is not None:
        return [(*v, w * g) for v, g in zip(st.jv, pitch_gradient(st), strict=True)]
    if task.R is not None:
        return [(*v, w * u[0], w * u[1], w * u[2]) for v, u in zip(st.jv, st.jw, strict=True)]
    return st.jv  # type: ignore[return-value]


def wrap(angle: A) -> A:
    """angle [rad] wrapped into [-pi, pi): a float, or an array of any shape."""
    return (angle + math.pi) % (2.0 * math.pi) - math.pi


def pitch_gradient(st: ChainState[float]) -> list[float]:
    """d pitch / dq [rad/rad], one float per joint."""
    (ax, ay, az), (px, py, _) = st.R[0], st.p
    rho = max(math.hypot(px, py), 1e-9)
    h = (ax * px + ay * py) / rho
    den = max(az * az + h * h, 1e-300)
    out = []
    for (wx, wy, wz), (vx, vy, _) in zip(st.jw, st.jv, strict=True):
        dax, day, daz = wy * az - wz * ay, wz * ax - wx * az, wx * ay - wy * ax
        dh = (dax * px + ax * vx + day * py + ay * vy) / rho - h * (px * vx + py * vy) / (rho * rho)
        out.append((h * daz - az * dh) / den)
    return out


def rotation_log(R_goal: tuple[float, ...], cols: tuple[Vec3, Vec3, Vec3]) -> Vec3:
    """Rotation vector [rad] of R_goal R^T (world frame), R given by its columns."""
    E = [
        [sum(R_goal[3 * i + k] * cols[k][j] for k in range(3)) for j in range(3)] for i in range(3)
    ]
    vx, vy, vz = E[2][1] - E[1][2], E[0][2] - E[2][0], E[1][0] - E[0][1]
    s = 0.5 * math.sqrt(vx * vx + vy * vy + vz * vz)
    c = 0.5 * (E[0][0] + E[1][1] + E[2][2] - 1.0)
    theta = math.atan2(s, c)
    if s > 1e-6 or c > 0.0:
        f = 0.5 if s < 1e-12 else theta / (2.0 * s)
        return (f * vx, f * vy, f * vz)
    return _log_near_pi(E, theta, c, (vx, vy, vz))


def _log_near_pi(E: list[list[float]], theta: float, c: float, v: Vec3) -> Vec3:
    """Rotation vector of a rotation by about pi: the axis from the symmetric part,
    (E + E^T) / 2 - cos(theta) I = (1 - cos(theta)) u u^T."""
    k = max(range(3), key=lambda i: E[i][i])
    col = [0.5 * (E[i][k] + E[k][i]) for i in range(3)]
    col[k] = E[k][k] - c
    norm = math.sqrt(sum(x * x for x in col)) or 1.0
    sign = -1.0 if sum(c * x for c, x in zip(col, v, strict=True)) < 0 else 1.0
    return (
        sign * theta * col[0] / norm,
        sign * theta * col[1] / norm,
        sign * theta * col[2] / norm,
    )
