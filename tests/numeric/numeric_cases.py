"""Shared helpers for the numeric IK tests: reachable targets and their check."""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from armkit.kinematics import IKResult, Target, fk, pitch_of
from armkit.kinematics._chain import chain_of
from armkit.kinematics._numeric import solve_one
from armkit.model import ArmModel

ARMS = ("owi535", "openmanipulator_x", "lynx6", "planar2", "al5d", "puma560")
TOL_POS = 1e-5  # [m] = 0.01 mm
TOL_ANG = np.radians(0.01)  # [rad]


def target_for(model: ArmModel, q: NDArray[np.float64], mask: str) -> Target:
    """The target reached by q [rad] for a task mask."""
    T = fk(model, q)
    if mask == "pose":
        return Target(T[:3, 3].copy(), None, T[:3, :3].copy())
    pitch = float(pitch_of(T)) if mask == "position+pitch" else None
    return Target(T[:3, 3].copy(), pitch)


def assert_reaches(
    model: ArmModel, q: NDArray[np.float64], target: Target, tol_pos: float, tol_ang: float
) -> None:
    """fk(q) meets the target within the tolerances (tool included) and q is inside the limits."""
    assert model.within_limits(q, slack=0.0), f"limits violated: {q}"
    T = fk(model, q)
    assert np.linalg.norm(T[:3, 3] - target.position) <= tol_pos * 1.0001
    if target.pitch is not None:
        d = abs(np.remainder(float(pitch_of(T)) - target.pitch + np.pi, 2 * np.pi) - np.pi)
        assert d <= tol_ang * 1.0001
    if target.orientation is not None:
        E = target.orientation @ T[:3, :3].T
        angle = np.arccos(np.clip((np.trace(E) - 1) / 2, -1, 1))
        assert angle <= tol_ang * 1.0001 + 1e-7


def solve(
    method: str, model: ArmModel, target: Target, seed: NDArray[np.float64], tol_pos: float,
    tol_ang: float, rng_seed: int = 0,
) -> IKResult:  # fmt: skip
    """A numeric method on a valid target, with the restarts' random seed given."""
    p = tuple(np.asarray(target.position, dtype=float).tolist())
    R = None if target.orientation is None else tuple(np.ravel(target.orientation).tolist())
    goal = (p, target.pitch, R)
    return solve_one(method, chain_of(model), goal, seed.tolist(), tol_pos, tol_ang, rng_seed)  # type: ignore[arg-type]


def joint_vectors(model: ArmModel, n: int, seed: int) -> NDArray[np.float64]:
    """n random joint vectors inside the limits [rad], shape (n, dof)."""
    return np.random.default_rng(seed).uniform(model.lower, model.upper, size=(n, model.dof))


def masks_for(model: ArmModel) -> tuple[str, ...]:
    """The task masks an arm's targets can be given in (a planar 2-link has no pitch)."""
    return ("position", "pose") if model.dof < 3 else ("position", "position+pitch", "pose")
