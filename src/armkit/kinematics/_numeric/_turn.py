"""The best turn of one joint alone: the step of CCD, and LM's warm start.

For a joint with unit axis z, rotating by t moves a vector u to R(t) u, and
sum_k w_k |R(t) u_k - v_k|^2 is smallest at t = atan2(sum w_k z.(u_k x v_k),
sum w_k u_k.v_k) with u, v projected onto the plane normal to z. The pairs
are (tool point, target point) about the joint, plus the tool's approach axis
and the target approach (pitch), or all three tool axes (pose), weighted by
w^2 [m^2/rad^2]. Exact for any angle: no linearisation.
"""

from __future__ import annotations

import math

from .._scalar import ChainState, Vec3
from ._residual import Task


def best_turn(task: Task, st: ChainState, i: int) -> float:
    """The turn of joint i [rad] that best aligns the tool with the task."""
    z, o, p = st.jw[i], st.origins[i], st.p
    u = _reject((p[0] - o[0], p[1] - o[1], p[2] - o[2]), z)  # tool point about the axis
    d = (task.p[0] - p[0], task.p[1] - p[1], task.p[2] - p[2])
    v = _add(u, _reject(d, z))
    num, den = _dot(z, _cross(u, v)), _dot(u, v)
    w2 = task.weight * task.weight
    for a, b in _axis_pairs(task, st):
        a, b = _reject(a, z), _reject(b, z)
        num += w2 * _dot(z, _cross(a, b))
        den += w2 * _dot(a, b)
    return math.atan2(num, den)


def _axis_pairs(task: Task, st: ChainState) -> list[tuple[Vec3, Vec3]]:
    """(tool axis, target axis) pairs for the angular part of the task."""
    if task.R is not None:
        R = task.R
        return [(st.R[k], (R[k], R[3 + k], R[6 + k])) for k in range(3)]
    if task.pitch is None:
        return []
    px, py = task.p[0], task.p[1]
    rho = math.hypot(px, py)
    if rho < 1e-9:
        px, py, rho = st.R[0][0], st.R[0][1], max(math.hypot(st.R[0][0], st.R[0][1]), 1e-12)
    c, s = math.cos(task.pitch), math.sin(task.pitch)
    return [(st.R[0], (c * px / rho, c * py / rho, s))]


def _dot(a: Vec3, b: Vec3) -> float:
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def _cross(a: Vec3, b: Vec3) -> Vec3:
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def _add(a: Vec3, b: Vec3) -> Vec3:
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2])


def _reject(a: Vec3, z: Vec3) -> Vec3:
    """a minus its component along the unit vector z."""
    k = _dot(a, z)
    return (a[0] - k * z[0], a[1] - k * z[1], a[2] - k * z[2])
