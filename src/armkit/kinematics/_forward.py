"""Forward kinematics, frames and the geometric Jacobian: one vectorised sweep.

``sweep`` walks the chain's steps once over N joint vectors ((3, N) columns and
origin): the reference, which a single pose's scalar fast path (``_scalar``) is pinned to.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .._errors import InputError
from .._inputs import joints
from ..model import ArmModel
from ._chain import Chain, chain_of
from ._scalar import ChainState
from ._steps import Fixed, Terms

F64 = NDArray[np.float64]
Cols = list[F64]
CHUNK = 4096  # poses per pass: keeps every temporary array in the CPU cache


@dataclass(frozen=True)
class Sweep:
    """Tool poses T (N, 4, 4) [m]; Jacobians J (N, 6, dof) or None; frames (N, dof + 2, 4, 4) or None."""

    T: F64
    J: F64 | None
    frames: F64 | None


def fk(model: ArmModel, q: ArrayLike) -> F64:
    """Tool pose ``T_world_tool`` for joint angles ``q``.

    Args:
        model: the arm.
        q: joint angles [rad], shape (dof,) or (N, dof).

    Returns:
        Homogeneous transform(s) [m], shape (4, 4) or (N, 4, 4). The tool frame's
        x axis is the approach direction.
    """
    chain = chain_of(model)
    qa = joints(q, chain.dof)
    if qa.ndim == 1:
        return pose_of(chain.state(qa.tolist()))
    if len(qa) <= CHUNK:
        return sweep(chain, qa).T
    out = np.empty((len(qa), 4, 4))
    for start in range(0, len(qa), CHUNK):
        out[start : start + CHUNK] = sweep(chain, qa[start : start + CHUNK]).T
    return out


def fk_frames(model: ArmModel, q: ArrayLike) -> F64:
    """Every frame of the chain for one pose: world, one per joint, then the tool.

    Args:
        q: joint angles [rad], shape (dof,).

    Returns:
        Transforms [m], shape (dof + 2, 4, 4): index 0 is the world (base) frame,
        index i + 1 joint i's frame (for DH models the frame after DH row i), the
        last the tool frame.
    """
    chain = chain_of(model)
    qa = joints(q, chain.dof, batch=False)
    frames = sweep(chain, qa[None, :], frames=True).frames
    assert frames is not None
    out: F64 = frames[0]
    return out


def jacobian(model: ArmModel, q: ArrayLike) -> F64:
    """Geometric Jacobian of the tool frame in the world frame.

    Args:
        q: joint angles [rad], shape (dof,) or (N, dof).

    Returns:
        J, shape (6, dof) or (N, 6, dof): rows 0-2 the tool point's linear
        velocity [m/rad], rows 3-5 the tool's angular velocity [rad/rad], per
        unit of each joint's angle.
    """
    chain = chain_of(model)
    qa = joints(q, chain.dof)
    J = sweep(chain, qa.reshape(-1, chain.dof), jacobian=True).J
    assert J is not None
    out: F64 = J[0] if qa.ndim == 1 else J
    return out


def pose_of(st: ChainState) -> F64:
    """The 4x4 tool pose [m] of a scalar chain state."""
    (ax, ay, az), (bx, by, bz), (cx, cy, cz) = st.R
    px, py, pz = st.p
    return np.array([[ax, bx, cx, px], [ay, by, cy, py], [az, bz, cz, pz], [0.0, 0.0, 0.0, 1.0]])


def sweep(chain: Chain, q: F64, *, jacobian: bool = False, frames: bool = False) -> Sweep:
    """Tool poses of q (N, dof) [rad], and the Jacobians and frames if asked for."""
    n = q.shape[0]
    if q.shape[1:] != (chain.dof,):
        raise InputError(f"q must have shape (N, {chain.dof}), got shape {q.shape}")
    theta = (q * chain.signs + chain.offsets).T
    c, s = np.cos(theta), np.sin(theta)
    cols: Cols = [np.zeros((3, n)) for _ in range(3)]
    cols[0][0], cols[1][1], cols[2][2] = 1.0, 1.0, 1.0
    p = np.zeros((3, n))
    axes, origins, links = [], [], []
    for i, step in enumerate(chain.steps):
        cols, p = _apply(step.before, cols, p)
        axes.append(cols[2] if step.sign > 0 else -cols[2])
        origins.append(p)
        cols = [c[i] * cols[0] + s[i] * cols[1], c[i] * cols[1] - s[i] * cols[0], cols[2]]
        if frames:
            links.append(_assemble(cols, p) @ step.link)
    T = _assemble(*_apply(chain.tool, cols, p))
    J = _jacobian(T, axes, origins) if jacobian else None
    F = np.stack([np.broadcast_to(np.eye(4), (n, 4, 4)), *links, T], axis=1) if frames else None
    return Sweep(T, J, F)


def _combine(terms: Terms, cols: Cols) -> F64:
    """sum_k coefficient_k * cols[k]; unit coefficients cost no multiplication."""
    out: F64 | None = None
    for k, v in terms:
        term = cols[k] if v == 1.0 else (-cols[k] if v == -1.0 else v * cols[k])
        out = term if out is None else out + term
    assert out is not None
    return out


def _apply(F: Fixed, cols: Cols, p: F64) -> tuple[Cols, F64]:
    """Right-multiply the frame (columns, origin) by the fixed transform F."""
    if F.shift:
        p = p + _combine(F.shift, cols)
    return [cols[j] if t is None else _combine(t, cols) for j, t in enumerate(F.columns)], p


def _assemble(cols: Cols, p: F64) -> F64:
    """Columns and origin (3, N) each -> transforms (N, 4, 4)."""
    out = np.zeros((p.shape[1], 4, 4))
    for j, col in enumerate((*cols, p)):
        out[:, :3, j] = col.T
    out[:, 3, 3] = 1.0
    return out


def _jacobian(T: F64, axes: Cols, origins: Cols) -> F64:
    """J (N, 6, dof): per joint, axis x (tool point - point on the axis) and the axis."""
    tip = T[:, :3, 3].T
    Jt = np.empty((len(axes), 6, T.shape[0]))
    for i, (z, o) in enumerate(zip(axes, origins, strict=True)):
        d = tip - o
        Jt[i, 0] = z[1] * d[2] - z[2] * d[1]
        Jt[i, 1] = z[2] * d[0] - z[0] * d[2]
        Jt[i, 2] = z[0] * d[1] - z[1] * d[0]
        Jt[i, 3:] = z
    return np.ascontiguousarray(Jt.transpose(2, 1, 0))
