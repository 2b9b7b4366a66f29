"""A serial chain as steps: per joint a fixed transform F, then a turn about its z axis.

Every chain (DH rows in either convention, URDF joint frames) becomes the same
list of ``Step``s: T_world_tool(q) = F_0 Rz(th_0) F_1 Rz(th_1) ... F_n-1 Rz(th_n-1) F_tool,
th_i = sign_i q_i + offset_i. A joint whose axis is not its frame's z axis
is turned onto it (the turn is folded into F and undone in the next F).
Entries within 1e-15 of 0 or +-1 are snapped to them, so the evaluators can
drop terms: a DH chain stays as sparse as its rows.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from ..model import ArmModel, JointFrame

F64 = NDArray[np.float64]
Terms = tuple[tuple[int, float], ...]  # a column or a point as (input column k, coefficient)


@dataclass(frozen=True)
class Fixed:
    """A fixed transform, 4x4, and its sparse form.

    Attributes:
        T: the transform, shape (4, 4) [m].
        columns: per rotation column j, the terms of sum_k T[k, j] * column_k (None: unchanged).
        shift: the translation as terms of sum_k T[k, 3] * column_k [m].
    """

    T: F64
    columns: tuple[Terms | None, Terms | None, Terms | None]
    shift: Terms


@dataclass(frozen=True)
class Step:
    """One joint: ``before`` (F), then Rz(sign q + offset); ``link``: joint frame to the
    frame ``fk_frames`` reports for it (DH: the frame after the row; URDF: identity)."""

    before: Fixed
    sign: float
    offset: float
    link: F64


def fixed(T: F64) -> Fixed:
    """``T`` with its entries snapped and its nonzero terms listed."""
    T = np.array(T, dtype=np.float64)
    T[np.abs(T) < 1e-15] = 0.0
    T[np.abs(T - 1.0) < 1e-15] = 1.0
    T[np.abs(T + 1.0) < 1e-15] = -1.0
    columns = []
    for j in range(3):
        terms = tuple((k, float(T[k, j])) for k in range(3) if T[k, j] != 0.0)
        columns.append(None if terms == ((j, 1.0),) else terms)
    shift = tuple((k, float(T[k, 3])) for k in range(3) if T[k, 3] != 0.0)
    return Fixed(T, (columns[0], columns[1], columns[2]), shift)


def rot(axis: str, angle: float) -> F64:
    """A rotation about x or z by ``angle`` [rad], 4x4."""
    c, s = math.cos(angle), math.sin(angle)
    T = np.eye(4)
    i, j = (1, 2) if axis == "x" else (0, 1)
    T[i, i], T[i, j], T[j, i], T[j, j] = c, -s, s, c
    return T


def shift(x: float = 0.0, z: float = 0.0) -> F64:
    """A translation along x and z [m], 4x4."""
    T = np.eye(4)
    T[0, 3], T[2, 3] = x, z
    return T


def steps_of(model: ArmModel) -> tuple[tuple[Step, ...], Fixed]:
    """The model's steps and its tool transform, from DH rows or joint frames."""
    if model.convention == "frames":
        return _from_frames(model.frames, model.T_flange_tool)
    modified = model.convention == "modified"
    steps: list[Step] = []
    carry = np.eye(4)  # what the previous row leaves after its joint turn
    for r in model.dh:
        before = carry @ (rot("x", r.alpha) @ shift(x=r.a) if modified else np.eye(4))
        after = shift(z=r.d) if modified else shift(z=r.d) @ shift(x=r.a) @ rot("x", r.alpha)
        steps.append(Step(fixed(before), r.sign, r.theta_offset, after))
        carry = after
    return tuple(steps), fixed(carry @ model.T_flange_tool)


def _from_frames(frames: tuple[JointFrame, ...], T_tool: F64) -> tuple[tuple[Step, ...], Fixed]:
    steps: list[Step] = []
    carry = np.eye(4)
    for f in frames:
        a = np.asarray(f.axis, dtype=np.float64)
        a = a / np.linalg.norm(a)
        on_z = abs(a[0]) < 1e-15 and abs(a[1]) < 1e-15
        sign = float(np.sign(a[2])) if on_z else 1.0
        turn = np.eye(4) if on_z else _z_onto(a)
        steps.append(Step(fixed(carry @ f.origin @ turn), sign, 0.0, turn.T))
        carry = turn.T
    return tuple(steps), fixed(carry @ T_tool)


def _z_onto(a: F64) -> F64:
    """A rotation (4x4) whose z axis is the unit vector ``a``."""
    helper = np.array([1.0, 0.0, 0.0]) if abs(a[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
    x = np.cross(helper, a)
    x /= np.linalg.norm(x)
    T = np.eye(4)
    T[:3, 0], T[:3, 1], T[:3, 2] = x, np.cross(a, x), a
    return T


def frames_of(steps: tuple[Step, ...]) -> tuple[JointFrame, ...]:
    """The chain as URDF-style joint frames: origin = F Rz(offset), axis = sign z."""
    return tuple(
        JointFrame(s.before.T @ rot("z", s.offset), (0.0, 0.0, float(s.sign))) for s in steps
    )


def dense_frames(steps: tuple[Step, ...], tool: Fixed, q: F64) -> F64:
    """Every frame (world, one per joint, the tool) of joint angles q (N, dof) [rad], shape
    (N, dof + 2, 4, 4) [m]: the steps' transforms multiplied out, rotation and
    translation apart (the reference the generated code is pinned to)."""
    n = len(q)
    out = np.zeros((n, len(steps) + 2, 4, 4))
    out[:, :, 3, 3] = 1.0
    out[:, 0, :3, :3] = np.eye(3)
    R, p = np.broadcast_to(np.eye(3), (n, 3, 3)), np.zeros((n, 3))

    def times(R: F64, M: F64) -> F64:  # R (n, 3, 3) times M (3, 3) or (3,): one product
        return (R.reshape(3 * n, 3) @ M).reshape(n, 3, *M.shape[1:])

    for i, (step, v) in enumerate(zip(steps, q.T, strict=True), 1):
        B, L = step.before.T, step.link
        p, Rb = p + times(R, B[:3, 3]), times(R, B[:3, :3])
        theta = step.sign * v + step.offset
        c, s = np.cos(theta)[:, None], np.sin(theta)[:, None]
        x, y = Rb[:, :, 0], Rb[:, :, 1]
        R = np.stack([c * x + s * y, c * y - s * x, Rb[:, :, 2]], axis=2)  # R_b Rz(theta)
        out[:, i, :3, :3], out[:, i, :3, 3] = times(R, L[:3, :3]), p + times(R, L[:3, 3])
    T = tool.T
    out[:, -1, :3, :3], out[:, -1, :3, 3] = times(R, T[:3, :3]), p + times(R, T[:3, 3])
    return out
