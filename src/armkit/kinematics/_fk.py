"""Forward kinematics: joint angles [rad] to the tool pose [m], one or a batch."""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..model import ArmModel
from ._chain import Chain, chain_of
from ._validate import joint_array

F64 = NDArray[np.float64]


def fk(model: ArmModel, q: ArrayLike) -> F64:
    """Tool pose ``T_world_tool`` for joint angles ``q``.

    Args:
        model: the arm.
        q: joint angles [rad], shape (dof,) or (N, dof).

    Returns:
        Homogeneous transform(s) [m], shape (4, 4) or (N, 4, 4). The tool frame's
        x axis is the approach direction.
    """
    qa = joint_array(model, q, "q")
    single = qa.ndim == 1
    poses = _fk_batch(chain_of(model), qa.reshape(-1, model.dof))
    return poses[0] if single else poses


def fk_frames(model: ArmModel, q: ArrayLike) -> F64:
    """Every frame of the chain for one pose: world, one per DH row, then the tool.

    Args:
        q: joint angles [rad], shape (dof,).

    Returns:
        Transforms [m], shape (dof + 2, 4, 4): index 0 is the world (base) frame,
        index i the frame after DH row i, the last the tool frame.
    """
    qa = joint_array(model, q, "q")
    if qa.ndim != 1:
        raise ValueError(f"q must have shape ({model.dof},) for fk_frames, got {qa.shape}")
    chain = chain_of(model)
    frames = [np.eye(4)]
    for i, theta in enumerate(chain.sign * qa + chain.offset):
        frames.append(frames[-1] @ _dh_matrix(chain, i, float(theta)))
    frames.append(frames[-1] @ chain.T_tool)
    return np.stack(frames)


def _dh_matrix(chain: Chain, i: int, theta: float) -> F64:
    a, d, ca, sa = chain.a[i], chain.d[i], chain.ca[i], chain.sa[i]
    ct, st = np.cos(theta), np.sin(theta)
    if chain.modified:
        rows = [[ct, -st, 0, a], [st * ca, ct * ca, -sa, -sa * d], [st * sa, ct * sa, ca, ca * d]]
    else:
        rows = [[ct, -st * ca, st * sa, a * ct], [st, ct * ca, -ct * sa, a * st], [0, sa, ca, d]]
    return np.array([*rows, [0.0, 0.0, 0.0, 1.0]])


def _fk_batch(chain: Chain, q: F64) -> F64:
    """Batch FK on columns: r0, r1, r2, p are the rotation columns and origin, (3, N)."""
    n = q.shape[0]
    theta = (q * chain.sign + chain.offset).T
    ct, st = np.cos(theta), np.sin(theta)
    r0 = np.zeros((3, n))
    r1 = np.zeros((3, n))
    r2 = np.zeros((3, n))
    r0[0], r1[1], r2[2] = 1.0, 1.0, 1.0
    p = np.zeros((3, n))
    step = _modified_step if chain.modified else _standard_step
    for i in range(chain.a.shape[0]):
        r0, r1, r2, p = step(chain, i, ct[i], st[i], r0, r1, r2, p)
    return _assemble(chain.T_tool, r0, r1, r2, p)


Cols = tuple[F64, F64, F64, F64]


def _standard_step(chain: Chain, i: int, c: F64, s: F64, r0: F64, r1: F64, r2: F64, p: F64) -> Cols:
    """Right-multiply by Rz(theta) Tz(d) Tx(a) Rx(alpha)."""
    a, d, ca, sa = chain.a[i], chain.d[i], chain.ca[i], chain.sa[i]
    x = c * r0 + s * r1
    y = c * r1 - s * r0
    p = p + d * r2 + a * x if a else p + d * r2
    if sa == 0.0:
        return x, (y if ca > 0 else -y), (r2 if ca > 0 else -r2), p
    return x, ca * y + sa * r2, ca * r2 - sa * y, p


def _modified_step(chain: Chain, i: int, c: F64, s: F64, r0: F64, r1: F64, r2: F64, p: F64) -> Cols:
    """Right-multiply by Rx(alpha) Tx(a) Rz(theta) Tz(d)."""
    a, d, ca, sa = chain.a[i], chain.d[i], chain.ca[i], chain.sa[i]
    if a:
        p = p + a * r0
    if sa != 0.0:
        r1, r2 = ca * r1 + sa * r2, ca * r2 - sa * r1
    elif ca < 0:
        r1, r2 = -r1, -r2
    x = c * r0 + s * r1
    y = c * r1 - s * r0
    if d:
        p = p + d * r2
    return x, y, r2, p


def _assemble(T_tool: F64, r0: F64, r1: F64, r2: F64, p: F64) -> F64:
    """Stack columns into (N, 4, 4) and apply the tool transform."""
    n = p.shape[1]
    out = np.empty((n, 4, 4))
    t = T_tool
    for k in range(3):
        out[:, :3, k] = (r0 * t[0, k] + r1 * t[1, k] + r2 * t[2, k]).T
    out[:, :3, 3] = (p + r0 * t[0, 3] + r1 * t[1, 3] + r2 * t[2, 3]).T
    out[:, 3, :3] = 0.0
    out[:, 3, 3] = 1.0
    return out
