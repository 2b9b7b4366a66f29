"""Tool poses and geometric Jacobians for k joint vectors, lean on numpy calls.

The same quantities as ``armkit.kinematics._jacobian.jacobian_and_pose``
(checked by tests), built with the forward-kinematics column steps of
``_fk`` and cross products written out per component: the batch solver calls
this once per iteration, often on a few dozen rows, where numpy's per-call
overhead (``np.cross`` alone costs tens of microseconds) would dominate.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from ...model import ArmModel
from .._chain import chain_of
from .._fk import _assemble, _modified_step, _standard_step

F64 = NDArray[np.float64]


def jacobian_and_pose_lean(model: ArmModel, q: F64) -> tuple[F64, F64]:
    """Jacobians J (k, 6, dof) [m/rad; rad/rad] and poses T (k, 4, 4) [m] for q (k, dof) [rad]."""
    chain = chain_of(model)
    k, n = q.shape
    theta = (q * chain.sign + chain.offset).T
    ct, st = np.cos(theta), np.sin(theta)
    r0, r1, r2, p = np.zeros((3, k)), np.zeros((3, k)), np.zeros((3, k)), np.zeros((3, k))
    r0[0], r1[1], r2[2] = 1.0, 1.0, 1.0
    axes, origins = [], []
    step = _modified_step if chain.modified else _standard_step
    for i in range(n):
        if not chain.modified:
            axes.append(r2 if chain.sign[i] > 0 else -r2)
            origins.append(p)
        r0, r1, r2, p = step(chain, i, ct[i], st[i], r0, r1, r2, p)
        if chain.modified:
            axes.append(r2 if chain.sign[i] > 0 else -r2)
            origins.append(p)
    T = _assemble(chain.T_tool, r0, r1, r2, p)
    tip = T[:, :3, 3].T
    Jt = np.empty((n, 6, k))
    for i in range(n):
        z, d = axes[i], tip - origins[i]
        Jt[i, 0] = z[1] * d[2] - z[2] * d[1]
        Jt[i, 1] = z[2] * d[0] - z[0] * d[2]
        Jt[i, 2] = z[0] * d[1] - z[1] * d[0]
        Jt[i, 3:] = z
    return np.ascontiguousarray(Jt.transpose(2, 1, 0)), T
