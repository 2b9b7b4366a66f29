"""The geometric Jacobian of the tool point, in the world frame."""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..model import ArmModel
from ._chain import chain_of
from ._fk import _assemble, _modified_step, _standard_step
from ._validate import joint_array

F64 = NDArray[np.float64]


def jacobian(model: ArmModel, q: ArrayLike) -> F64:
    """Geometric Jacobian of the tool frame in the world frame.

    Args:
        q: joint angles [rad], shape (dof,) or (N, dof).

    Returns:
        J, shape (6, dof) or (N, 6, dof): rows 0-2 the tool point's linear
        velocity [m/rad], rows 3-5 the tool's angular velocity [rad/rad], per
        unit of each joint's angle.
    """
    qa = joint_array(model, q, "q")
    single = qa.ndim == 1
    J, _ = jacobian_and_pose(model, qa.reshape(-1, model.dof))
    return J[0] if single else J


def jacobian_and_pose(model: ArmModel, q: F64) -> tuple[F64, F64]:
    """Batch Jacobian (N, 6, dof) and tool pose (N, 4, 4) for q [rad], shape (N, dof)."""
    chain = chain_of(model)
    n = q.shape[0]
    theta = (q * chain.sign + chain.offset).T
    ct, st = np.cos(theta), np.sin(theta)
    r0, r1, r2, p = (np.zeros((3, n)) for _ in range(4))
    r0[0], r1[1], r2[2] = 1.0, 1.0, 1.0
    axes, origins = [], []
    step = _modified_step if chain.modified else _standard_step
    for i in range(model.dof):
        if not chain.modified:
            axes.append(r2)
            origins.append(p)
        r0, r1, r2, p = step(chain, i, ct[i], st[i], r0, r1, r2, p)
        if chain.modified:
            axes.append(r2)
            origins.append(p)
    pose = _assemble(chain.T_tool, r0, r1, r2, p)
    tip = pose[:, :3, 3].T
    J = np.empty((n, 6, model.dof))
    for i in range(model.dof):
        z = axes[i] * chain.sign[i]
        J[:, :3, i] = np.cross(z, tip - origins[i], axis=0).T
        J[:, 3:, i] = z.T
    return J, pose
