"""Forward kinematics: joint angles [rad] to the tool pose [m], one or a batch."""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..model import ArmModel
from ._chain import Chain, chain_of
from ._validate import joint_array

F64 = NDArray[np.float64]
CHUNK = 4096  # poses per pass: keeps every temporary array in the CPU cache


def in_chunks(solve: Callable[[F64], F64], q: F64, shape: tuple[int, ...]) -> F64:
    """Apply ``solve`` to ``q`` (N, ...) in chunks of CHUNK rows; output (N, *shape)."""
    if len(q) <= CHUNK:
        return solve(q)
    out = np.empty((len(q), *shape))
    for start in range(0, len(q), CHUNK):
        out[start : start + CHUNK] = solve(q[start : start + CHUNK])
    return out


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
    if qa.ndim == 1:
        return _fk_single(chain_of(model), qa.tolist())
    return in_chunks(lambda part: _fk_batch(chain_of(model), part), qa, (4, 4))


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


def _fk_single(chain: Chain, q: list[float]) -> F64:
    """One pose in plain floats: rotation columns (a, b, c) and origin p."""
    cos, sin = math.cos, math.sin
    ax, ay, az, bx, by, bz, cx, cy, cz = 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0
    px = py = pz = 0.0
    for (a, d, ca, sa, off, sign), qi in zip(chain.rows, q, strict=True):
        th = sign * qi + off
        ct, st = cos(th), sin(th)
        if chain.modified:
            px, py, pz = px + a * ax, py + a * ay, pz + a * az
            bx, by, bz, cx, cy, cz = (
                ca * bx + sa * cx, ca * by + sa * cy, ca * bz + sa * cz,
                ca * cx - sa * bx, ca * cy - sa * by, ca * cz - sa * bz,
            )  # fmt: skip
            ax, ay, az, bx, by, bz = (
                ct * ax + st * bx, ct * ay + st * by, ct * az + st * bz,
                ct * bx - st * ax, ct * by - st * ay, ct * bz - st * az,
            )  # fmt: skip
            px, py, pz = px + d * cx, py + d * cy, pz + d * cz
        else:
            px, py, pz = px + d * cx, py + d * cy, pz + d * cz
            ax, ay, az, bx, by, bz = (
                ct * ax + st * bx, ct * ay + st * by, ct * az + st * bz,
                ct * bx - st * ax, ct * by - st * ay, ct * bz - st * az,
            )  # fmt: skip
            px, py, pz = px + a * ax, py + a * ay, pz + a * az
            bx, by, bz, cx, cy, cz = (
                ca * bx + sa * cx, ca * by + sa * cy, ca * bz + sa * cz,
                ca * cx - sa * bx, ca * cy - sa * by, ca * cz - sa * bz,
            )  # fmt: skip
    flange = np.array([[ax, bx, cx, px], [ay, by, cy, py], [az, bz, cz, pz], [0.0, 0.0, 0.0, 1.0]])
    return flange @ chain.T_tool


def _fk_batch(chain: Chain, q: F64) -> F64:
    """Batch FK on columns: r0, r1, r2, p are the rotation columns and origin, (3, N)."""
    theta = (q * chain.sign + chain.offset).T
    ct, st = np.cos(theta), np.sin(theta)
    r0, r1, r2, p = _first_row(chain, ct[0], st[0])
    step = _modified_step if chain.modified else _standard_step
    for i in range(1, chain.a.shape[0]):
        r0, r1, r2, p = step(chain, i, ct[i], st[i], r0, r1, r2, p)
    return _assemble(chain.T_tool, r0, r1, r2, p)


def _first_row(chain: Chain, c: F64, s: F64) -> Cols:
    """The first row's transform as columns (3, N), built directly (no product with I)."""
    zero = np.zeros_like(c)
    a, d = chain.a[0], chain.d[0]
    if chain.modified and not (chain.sa[0] == 0.0 and chain.ca[0] > 0):
        eye = [np.zeros((3, len(c))) for _ in range(4)]
        eye[0][0], eye[1][1], eye[2][2] = 1.0, 1.0, 1.0
        return _modified_step(chain, 0, c, s, *eye)
    r0, r1 = np.stack([c, s, zero]), np.stack([-s, c, zero])
    r2 = np.stack([zero, zero, zero + 1.0])
    if chain.modified:
        return r0, r1, r2, np.stack([zero + a, zero, zero + d])
    r1, r2 = _twist(chain, 0, r1, r2)
    return r0, r1, r2, np.stack([a * c, a * s, zero + d])


def _twist(chain: Chain, i: int, y: F64, z: F64) -> tuple[F64, F64]:
    """Rotate the y and z columns about x by alpha_i (exact for 0, +-90, 180 deg)."""
    ca, sa = chain.ca[i], chain.sa[i]
    if sa == 0.0:
        return (y, z) if ca > 0 else (-y, -z)
    if ca == 0.0:
        return (z, -y) if sa > 0 else (-z, y)
    return ca * y + sa * z, ca * z - sa * y


Cols = tuple[F64, F64, F64, F64]


def _standard_step(chain: Chain, i: int, c: F64, s: F64, r0: F64, r1: F64, r2: F64, p: F64) -> Cols:
    """Right-multiply by Rz(theta) Tz(d) Tx(a) Rx(alpha)."""
    a, d = chain.a[i], chain.d[i]
    x = c * r0 + s * r1
    y = c * r1 - s * r0
    if d:
        p = p + d * r2
    if a:
        p = p + a * x
    y, z = _twist(chain, i, y, r2)
    return x, y, z, p


def _modified_step(chain: Chain, i: int, c: F64, s: F64, r0: F64, r1: F64, r2: F64, p: F64) -> Cols:
    """Right-multiply by Rx(alpha) Tx(a) Rz(theta) Tz(d)."""
    a, d = chain.a[i], chain.d[i]
    if a:
        p = p + a * r0
    r1, r2 = _twist(chain, i, r1, r2)
    x = c * r0 + s * r1
    y = c * r1 - s * r0
    if d:
        p = p + d * r2
    return x, y, r2, p


def _assemble(T_tool: F64, r0: F64, r1: F64, r2: F64, p: F64) -> F64:
    """Stack columns into (N, 4, 4) and apply the tool transform."""
    n = p.shape[1]
    out = np.empty((n, 4, 4))
    cols = (r0, r1, r2)
    for k in range(4):
        acc = p if k == 3 else None
        for j in range(3):
            w = T_tool[j, k]
            if w:
                term = cols[j] if w == 1.0 else (-cols[j] if w == -1.0 else w * cols[j])
                acc = term if acc is None else acc + term
        out[:, :3, k] = 0.0 if acc is None else acc.T
    out[:, 3, :3] = 0.0
    out[:, 3, 3] = 1.0
    return out
