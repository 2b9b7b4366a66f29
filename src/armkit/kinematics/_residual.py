"""The task residual e(q) and its masked Jacobian, for the three task masks.

    position         e = p* - p                              (3 rows)
    position+pitch   e = [p* - p, w (pitch* - pitch)]        (4 rows)
    pose             e = [p* - p, w log(R* R^T)]             (6 rows)

Angles are weighted by a length ``w`` [m/rad] so that one damped step mixes
metres and radians sensibly; the errors reported (and the tolerances) are the
unweighted distance [m] and angle [rad]. Written once over lanes, as the chain
state is (``_state``): every quantity a float (one target, the scalar solvers)
or an array of shape (k,) (k targets, the batch solver).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Generic

import numpy as np
from numpy.typing import NDArray

from ._lanes import FLOATS, LANES, Ops
from ._pose import pitch_lanes, pitch_scalar
from ._state import ChainState, N, Vec3

F64 = NDArray[np.float64]


@dataclass(frozen=True, slots=True)
class Task(Generic[N]):
    """A target prepared for the solvers: one (floats) or k (lanes (k,)).

    Attributes:
        p: target tool point [m].
        pitch: target pitch [rad] or None.
        R: target rotation R_world_tool, row-major 9 values, or None.
        weight: metres per radian for the angle rows [m/rad].
    """

    p: tuple[N, N, N]
    pitch: N | None
    R: tuple[N, ...] | None
    weight: float

    @property
    def ops(self) -> Ops:
        """``FLOATS`` for one target, ``LANES`` for k."""
        return FLOATS if type(self.p[0]) is float else LANES

    def take(self: Task[F64], idx: Any) -> Task[F64]:
        """The targets at ``idx`` (indices or a slice) of a task of lanes."""
        x, y, z = self.p
        pitch = None if self.pitch is None else self.pitch[idx]
        R = None if self.R is None else tuple(v[idx] for v in self.R)
        return Task((x[idx], y[idx], z[idx]), pitch, R, self.weight)


@dataclass(slots=True)
class Residual(Generic[N]):
    """e, the masked weighted Jacobian (or None), and the unweighted errors.
    (Not frozen: a frozen dataclass costs a microsecond more to build, and the
    solvers build one per iteration.)

    Attributes:
        e: residual, 3/4/6 values.  cols: J by columns, per joint a tuple as long as e.
        cost: |e|^2 (weighted).
        position_error: [m].  angle_error: [rad] (0 for position-only tasks).
    """

    e: list[N]
    cols: list[tuple[N, ...]] | None
    position_error: N
    angle_error: N
    cost: N


def residual(task: Task[N], st: ChainState[N], jac: bool = True) -> Residual[N]:
    """Residual of the chain state ``st`` for ``task``; the Jacobian rows if ``jac``."""
    p, ops = st.p, task.ops
    e0, e1, e2 = task.p[0] - p[0], task.p[1] - p[1], task.p[2] - p[2]
    pos2 = e0 * e0 + e1 * e1 + e2 * e2
    cols = task_jacobian(task, st) if jac else None
    if task.pitch is not None:
        d = wrap(task.pitch - _pitch(st, ops))
        wd = task.weight * d
        return Residual([e0, e1, e2, wd], cols, ops.sqrt(pos2), abs(d), pos2 + wd * wd)
    if task.R is not None:
        w = task.weight
        r0, r1, r2 = rotation_log(task.R, st.R, ops)
        e = [e0, e1, e2, w * r0, w * r1, w * r2]
        ang2 = r0 * r0 + r1 * r1 + r2 * r2
        return Residual(e, cols, ops.sqrt(pos2), ops.sqrt(ang2), pos2 + w * w * ang2)
    return Residual([e0, e1, e2], cols, ops.sqrt(pos2), 0.0 * pos2, pos2)


def task_jacobian(task: Task[N], st: ChainState[N]) -> list[tuple[N, ...]]:
    """The task's weighted Jacobian by columns: per joint, as many values as e has rows."""
    w, jv = task.weight, st.jv
    if task.pitch is not None:
        gradient = pitch_gradient(st, task.ops)
        return [(x, y, z, w * g) for (x, y, z), g in zip(jv, gradient, strict=True)]
    if task.R is not None:
        return [
            (x, y, z, w * a, w * b, w * c) for (x, y, z), (a, b, c) in zip(jv, st.jw, strict=True)
        ]
    return jv  # type: ignore[return-value]


def wrap(angle: N) -> N:
    """angle [rad] wrapped into [-pi, pi): a float, or an array of any shape."""
    return (angle + math.pi) % (2.0 * math.pi) - math.pi


def _pitch(st: ChainState[Any], ops: Ops) -> Any:
    """The tool's pitch [rad] (``pitch_of``), of one state or of lanes."""
    a, p = st.R[0], st.p
    return pitch_scalar(a, p) if ops is FLOATS else pitch_lanes(a, (p[0], p[1]))


def pitch_gradient(st: ChainState[N], ops: Ops = FLOATS) -> list[N]:
    """d pitch / dq [rad/rad], one value per joint."""
    (ax, ay, az), (px, py, _) = st.R[0], st.p
    rho = ops.maximum(ops.hypot(px, py), 1e-9)
    h = (ax * px + ay * py) / rho
    den = ops.maximum(az * az + h * h, 1e-300)
    out = []
    for (wx, wy, wz), (vx, vy, _) in zip(st.jw, st.jv, strict=True):
        dax, day, daz = wy * az - wz * ay, wz * ax - wx * az, wx * ay - wy * ax
        dh = (dax * px + ax * vx + day * py + ay * vy) / rho - h * (px * vx + py * vy) / (rho * rho)
        out.append((h * daz - az * dh) / den)
    return out


def rotation_log(
    R_goal: tuple[Any, ...], cols: tuple[tuple[Any, Any, Any], ...], ops: Ops = FLOATS
) -> tuple[Any, Any, Any]:
    """Rotation vector [rad] of R_goal R^T (world frame), R_goal row-major, R given by its
    columns; rotations by about pi from the symmetric part (``_log_near_pi``)."""
    g, rows = R_goal, tuple(zip(*cols, strict=True))  # R's rows
    E = [[g[i] * x + g[i + 1] * y + g[i + 2] * z for x, y, z in rows] for i in (0, 3, 6)]
    vx, vy, vz = E[2][1] - E[1][2], E[0][2] - E[2][0], E[1][0] - E[0][1]
    s = 0.5 * ops.sqrt(vx * vx + vy * vy + vz * vz)
    c = 0.5 * (E[0][0] + E[1][1] + E[2][2] - 1.0)
    theta = ops.atan2(s, c)
    if ops is FLOATS:
        if s > 1e-6 or c > 0.0:
            f = 0.5 if s < 1e-12 else theta / (2.0 * s)
            return (f * vx, f * vy, f * vz)
        return _log_near_pi(E, theta, c, (vx, vy, vz))
    f = np.where(s < 1e-12, 0.5, theta / (2.0 * np.maximum(s, 1e-300)))
    out = (f * vx, f * vy, f * vz)
    near = np.flatnonzero((s <= 1e-6) & (c <= 0.0))
    if near.size:  # about pi: those lanes one by one, in floats
        G = np.broadcast_arrays(*R_goal, s)[:9]
        C = np.broadcast_arrays(*(v for col in cols for v in col), s)[:9]
        for i in near.tolist():
            one = rotation_log(
                tuple(float(g[i]) for g in G),
                tuple((float(C[k][i]), float(C[k + 1][i]), float(C[k + 2][i])) for k in (0, 3, 6)),
            )
            for k in range(3):
                out[k][i] = one[k]
    return out


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
