"""Forward kinematics, frames and the geometric Jacobian, of one pose or of N.

One pose runs the chain's generated code on floats, N poses the same code on
numpy lanes (``_state``), over cache-sized chunks. ``fk_frames`` multiplies the
steps' dense 4x4 transforms: the reference the tests pin both to.
"""

from __future__ import annotations

from collections.abc import Iterator

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .._inputs import joints
from ..model import ArmModel
from ._chain import _CHAINS, Chain, chain_of
from ._steps import dense_frames

F64 = NDArray[np.float64]
CHUNK = 4096  # poses per pass: keeps every temporary array in the CPU cache


def chunks(n: int) -> Iterator[slice]:
    """Slices of at most ``CHUNK`` rows that cover rows 0..n-1 in order."""
    return (slice(s, s + CHUNK) for s in range(0, n, CHUNK))


def fk(model: ArmModel, q: ArrayLike) -> F64:
    """Tool pose ``T_world_tool`` for joint angles ``q``.

    Args:
        model: the arm.
        q: joint angles [rad], shape (dof,) or (N, dof).

    Returns:
        Homogeneous transform(s) [m], shape (4, 4) or (N, 4, 4). The tool frame's
        x axis is the approach direction.
    """
    chain = _CHAINS.get(id(model)) or chain_of(model)
    if q.__class__ is np.ndarray and q.shape == (chain.dof,) and q.dtype == np.float64:  # type: ignore[union-attr]
        v = q.tolist()  # type: ignore[union-attr]
        s = sum(v)
        if s - s == 0.0:  # every angle finite (checked in full below where not)
            return np.array(chain.pose(v)).reshape(4, 4)
    qa = joints(q, chain.dof)
    if qa.ndim == 1:
        return np.array(chain.pose(qa.tolist())).reshape(4, 4)
    return poses(chain, qa)


def fk_frames(model: ArmModel, q: ArrayLike) -> F64:
    """Every frame of the chain: world, one per joint, then the tool.

    Args:
        q: joint angles [rad], shape (dof,) or (N, dof).

    Returns:
        Transforms [m], shape (dof + 2, 4, 4) or (N, dof + 2, 4, 4): index 0 is the
        world (base) frame, index i + 1 joint i's frame (for DH models the frame
        after DH row i), the last the tool frame.
    """
    chain = chain_of(model)
    qa = joints(q, chain.dof)
    out = dense_frames(chain.steps, chain.tool, np.atleast_2d(qa))
    return out[0] if qa.ndim == 1 else out


def frames_on_base_axis(model: ArmModel) -> int:
    """How many frames of ``fk_frames``, from the world frame on, keep their origin on the
    vertical axis through the base origin at every pose: the base column's frames (a DH
    arm with a base yaw: 2, the world and the frame after row 0)."""
    return chain_of(model).on_axis


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
    J = jacobians(chain, qa.reshape(-1, chain.dof))[1]
    return J[0] if qa.ndim == 1 else J


def poses(chain: Chain, q: F64) -> F64:
    """Tool poses T (N, 4, 4) [m] of joint angles q (N, dof) [rad]."""
    return _evaluate(chain, q, None)


def jacobians(chain: Chain, q: F64) -> tuple[F64, F64]:
    """Tool poses T (N, 4, 4) [m] and Jacobians J (N, 6, dof) of q (N, dof) [rad]."""
    J = np.empty((len(q), 6, chain.dof))
    return _evaluate(chain, q, J), J


def _evaluate(chain: Chain, q: F64, J: F64 | None) -> F64:
    """The poses (N, 4, 4), chunk by chunk on lanes; the Jacobians into J if given."""
    T = np.zeros((len(q), 4, 4))
    T[:, 3, 3] = 1.0
    for at in chunks(len(q)):
        st = chain.lanes(list(q[at].T))
        for j, col in enumerate((*st.R, st.p)):
            for i in range(3):
                T[at, i, j] = col[i]
        if J is not None:
            for k, (v, w) in enumerate(zip(st.jv, st.jw, strict=True)):
                for i in range(3):
                    J[at, i, k], J[at, 3 + i, k] = v[i], w[i]
    return T
