"""The best turn of one joint alone: the step of CCD, and the LM solvers' warm start.

For a joint with unit axis z, rotating by t moves a vector u to R(t) u, and
sum_k w_k |R(t) u_k - v_k|^2 is smallest at t = atan2(sum w_k z.(u_k x v_k),
sum w_k u_k.v_k) with u, v projected onto the plane normal to z. The pairs
are (tool point, target point) about the joint, plus the tool's approach axis
and the target approach (pitch), or all three tool axes (pose), weighted by
w^2 [m^2/rad^2]. Exact for any angle: no linearisation. ``turn_angle`` is
written once over lanes: vectors are 3-tuples of floats (one target,
``best_turn``) or of arrays of shape (k,) (k targets).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any

import numpy as np
from numpy.typing import NDArray

from .._lanes import Ops
from .._residual import Task
from .._state import ChainState, N

F64 = NDArray[np.float64]
V = tuple[Any, Any, Any]  # a vector: three floats, or three arrays (k,) of one component each


def best_turn(task: Task[N], st: ChainState[N], i: int) -> N:
    """The turn of joint i [rad] that best aligns the tool with the task (floats or lanes)."""
    R, ops = task.R, task.ops
    goal_axes = None if R is None else tuple((R[k], R[3 + k], R[6 + k]) for k in range(3))
    pairs = axis_pairs(st.R, goal_axes, task.pitch, task.p, ops)
    turn: N = turn_angle(st.jw[i], st.origins[i], st.p, task.p, task.weight, pairs, ops.atan2)
    return turn


def turn_angle(
    z: V, o: V, p: V, goal: V, weight: float, pairs: list[tuple[V, V]],
    atan2: Callable[[Any, Any], Any],
) -> Any:  # fmt: skip
    """The best turn [rad] about the axis z through o of tool point p towards ``goal`` [m],
    with the (tool axis, target axis) ``pairs`` weighted by weight^2 [m^2/rad^2]."""
    u = _reject(_sub(p, o), z)  # tool point about the axis
    v = _add(u, _reject(_sub(goal, p), z))
    num, den = _dot(z, _cross(u, v)), _dot(u, v)
    w2 = weight * weight
    for a, b in pairs:
        a, b = _reject(a, z), _reject(b, z)
        num = num + w2 * _dot(z, _cross(a, b))
        den = den + w2 * _dot(a, b)
    return atan2(num, den)


def axis_pairs(
    tool: Sequence[V], goal: Sequence[V] | None, pitch: Any, p: V, ops: Ops
) -> list[tuple[V, V]]:
    """(tool axis, target axis) pairs for the angular part of the task, over lanes.

    Args:
        tool: the tool's axes x, y, z (its rotation's columns), as vectors.
        goal: the target's axes, or None; pitch: the target pitch [rad] or None.
        p: the target point [m]. ops: ``FLOATS`` or ``LANES``.
    """
    if goal is not None:
        return list(zip(tool, goal, strict=True))
    if pitch is None:
        return []
    a = tool[0]  # the approach axis; its horizontal part stands in on the base axis
    on_axis = ops.hypot(p[0], p[1]) < 1e-9
    hx, hy = p[0] + on_axis * (a[0] - p[0]), p[1] + on_axis * (a[1] - p[1])
    rho = ops.hypot(hx, hy) + 1e-300  # 0 only with a vertical approach on the base axis
    c, s = ops.cos(pitch), ops.sin(pitch)
    return [(a, (c * hx / rho, c * hy / rho, s))]


def _sub(a: V, b: V) -> V:
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def _add(a: V, b: V) -> V:
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2])


def _dot(a: V, b: V) -> Any:
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def _cross(a: V, b: V) -> V:
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def _reject(a: V, z: V) -> V:
    """a minus its component along the unit vector z."""
    k = _dot(a, z)
    return (a[0] - k * z[0], a[1] - k * z[1], a[2] - k * z[2])
