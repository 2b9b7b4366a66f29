"""The IK entry points: one target or a batch, every method behind one call."""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..model import ArmModel
from . import _analytic
from ._analytic_batch import solve_batch as solve_batch_analytic
from ._family import PlanarFamily, family_of, why_not_family
from ._fast import fast_solver
from ._fk import CHUNK, fk
from ._free_pitch_batch import free_pitch_batch
from ._numeric import solve_batch, solve_task
from ._numeric._inputs import numeric_task, tolerances
from ._pose import pitch_of
from ._result import IKBatchResult, IKResult
from ._validate import joint_array, point_array

F64 = NDArray[np.float64]
METHODS = ("auto", "analytic", "lm", "ccd", "jacobian", "random")


def ik(
    model: ArmModel,
    position: ArrayLike,
    pitch: float | None = None,
    q_seed: ArrayLike | None = None,
    *,
    orientation: ArrayLike | None = None,
    method: str = "auto",
    tol_mm: float = 0.01,
    tol_deg: float = 0.01,
) -> IKResult:
    """Joint angles that put the tool at ``position``.

    Args:
        model: the arm.
        position: tool point in the world frame [m], shape (3,).
        pitch: approach angle above the horizontal [rad] (-pi/2 = pointing
            down), or None: the model's default pitch, else any pitch (the one
            nearest the seed's).
        q_seed: joint angles [rad], shape (dof,), that solutions are ranked by
            (nearest first) and numeric solvers start from; default home.
        orientation: full tool orientation R_world_tool, shape (3, 3) (numeric methods).
        method: ``"auto"`` (closed form where the arm's shape allows, else
            ``"lm"``), ``"analytic"``, ``"lm"``, ``"ccd"``, ``"jacobian"``, ``"random"``.
        tol_mm: position tolerance of numeric methods [mm].
        tol_deg: pitch/orientation tolerance of numeric methods [deg].

    Returns:
        IKResult with ``q`` the best solution and ``solutions`` every one found.

    Raises:
        UnreachableError: no solution inside the limits (``reason`` says why).
        ValueError: malformed input, naming the argument.
    """
    if isinstance(position, tuple) and len(position) == 3:  # the common case, without a call
        x, y, z = float(position[0]), float(position[1]), float(position[2])
        if not (math.isfinite(x) and math.isfinite(y) and math.isfinite(z)):
            raise ValueError(f"position must be finite, got {(x, y, z)}")
    else:
        x, y, z = _point(position)
    cache = model._cache
    seed = cache.get("home") or _seed(model, None) if q_seed is None else _seed(model, q_seed)
    if pitch is not None:
        pitch = pitch if type(pitch) is float and math.isfinite(pitch) else _finite(pitch, "pitch")
    elif model.default_pitch is not None and orientation is None:
        pitch = model.default_pitch
    if orientation is None and (method == "auto" or method == "analytic"):
        fast = cache["fast"] if "fast" in cache else fast_solver(model)
        found = fast(x, y, z, pitch, seed) if fast is not None else None
        if found is not None:
            return IKResult.closed_form(found[0], found[1], (model, (x, y, z), pitch))
    p = (x, y, z)
    fam = family_of(model)
    use = _choose(model, fam, method, orientation)
    if use == "analytic":
        assert fam is not None
        return _closed_form(model, fam, p, pitch, seed)
    tol_pos, tol_ang = tolerances(tol_mm / 1000.0, math.radians(tol_deg))
    task = numeric_task(model, p, pitch, orientation)
    return solve_task(use, model, task, list(seed), tol_pos, tol_ang)


def _choose(model: ArmModel, fam: PlanarFamily | None, method: str, orientation: Any) -> str:
    if method not in METHODS:
        raise ValueError(f"method must be one of {', '.join(METHODS)}, got {method!r}")
    if method == "analytic" and (fam is None or orientation is not None):
        why = (
            why_not_family(model)
            or "the closed form takes a position and a pitch, not an orientation"
        )
        raise ValueError(f"method 'analytic' does not apply: {why}")
    if method == "auto":
        return "analytic" if fam is not None and orientation is None else "lm"
    return method


def _closed_form(
    model: ArmModel,
    fam: PlanarFamily,
    p: tuple[float, ...],
    pitch: float | None,
    seed: tuple[float, ...],
) -> IKResult:
    sols = _analytic.solve(model, fam, p, pitch, seed)
    ranked = [(float(k), q) for k, q in enumerate(sols)]  # already best first
    return IKResult.closed_form(sols[0], ranked, (model, p, pitch))


def measure_error(
    model: ArmModel, p: tuple[float, ...], pitch: float | None, q: F64
) -> tuple[float, float]:
    """Position [m] and pitch [rad] error of joint angles q [rad] for a target, by FK."""
    T = fk(model, q)
    pos = float(np.linalg.norm(T[:3, 3] - np.asarray(p)))
    if pitch is None:
        return pos, 0.0
    return pos, abs(math.remainder(float(pitch_of(T)) - pitch, 2 * math.pi))


def _point(position: ArrayLike) -> tuple[float, float, float]:
    """``position`` as three finite floats; ValueError naming it otherwise."""
    if isinstance(position, np.ndarray):
        if position.shape != (3,):
            raise ValueError(f"position must have shape (3,), got {position.shape}")
        position = position.tolist()
    try:
        x, y, z = position  # type: ignore[misc, str-unpack]
        out = (float(x), float(y), float(z))  # type: ignore[arg-type]
    except (TypeError, ValueError):
        raise ValueError(
            f"position must be three numbers (x, y, z) [m], got {position!r}"
        ) from None
    if not (math.isfinite(out[0]) and math.isfinite(out[1]) and math.isfinite(out[2])):
        raise ValueError(f"position must be finite, got {out}")
    return out


def _finite(value: Any, name: str) -> float:
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise ValueError(f"{name} must be a number, got {value!r}") from None
    if not math.isfinite(v):
        raise ValueError(f"{name} must be finite, got {v}")
    return v


def _seed(model: ArmModel, q_seed: ArrayLike | None) -> tuple[float, ...]:
    if q_seed is None:
        home: tuple[float, ...] | None = model._cache.get("home")
        if home is None:
            home = tuple(j.home for j in model.joints)
            model._cache["home"] = home
        return home
    qa = np.asarray(q_seed, dtype=np.float64)
    q = qa.tolist() if qa.shape == (model.dof,) else None
    if q is None or not all(map(math.isfinite, q)):
        raise ValueError(
            f"q_seed must be {model.dof} finite joint angles [rad], got shape {qa.shape}"
        )
    return tuple(q)


def ik_batch(
    model: ArmModel,
    positions: ArrayLike,
    pitches: ArrayLike | None = None,
    q_seed: ArrayLike | None = None,
    *,
    orientations: ArrayLike | None = None,
    method: str = "auto",
    tol_mm: float = 0.01,
    tol_deg: float = 0.01,
) -> IKBatchResult:
    """Joint angles for N targets at once, vectorised in numpy.

    Args:
        positions: tool points [m], shape (N, 3).
        pitches: pitch [rad], a number or shape (N,), or None (the model's
            default pitch, else free: nearest the seed's).
        q_seed: [rad], shape (dof,) or (N, dof); default home.
        orientations: full tool orientations R_world_tool, shape (N, 3, 3)
            (numeric methods; instead of pitches).
        method: ``"auto"``, ``"analytic"`` or ``"lm"``.

    Returns:
        IKBatchResult: best solution per target (NaN rows where none), ``ok`` and ``reason``.
    """
    P = point_array(positions, "positions", batch=True)
    seed = _batch_seed(model, q_seed, len(P))
    pitch = _batch_pitch(model, pitches, len(P))
    fam = family_of(model)
    use = _choose(model, fam, method, orientations)
    if use != "analytic":
        if orientations is not None and pitch is not None:
            raise ValueError("give pitches or orientations, not both")
        tol_pos, tol_ang = tol_mm / 1000.0, math.radians(tol_deg)
        return solve_batch(model, P, pitch, orientations, seed, tol_pos, tol_ang)
    assert fam is not None
    if pitch is None and len(fam.planar) == 3:
        return _free_pitch_batch(model, fam, P, seed)
    q, ok, reason = _analytic_chunks(model, fam, P, pitch, seed)
    return IKBatchResult(q=q, ok=ok, reason=reason, method="analytic")


def _analytic_chunks(
    model: ArmModel, fam: PlanarFamily, P: F64, pitch: F64 | None, seed: F64
) -> tuple[F64, NDArray[np.bool_], NDArray[np.str_]]:
    """The vectorised closed form over cache-sized chunks of targets."""
    parts = [
        solve_batch_analytic(
            model,
            fam,
            P[s : s + CHUNK],
            None if pitch is None else pitch[s : s + CHUNK],
            seed[s : s + CHUNK],
        )
        for s in range(0, len(P), CHUNK)
    ]
    if len(parts) == 1:
        return parts[0]
    q, ok, reason = zip(*parts, strict=True)
    return np.concatenate(q), np.concatenate(ok), np.concatenate(reason)


def _free_pitch_batch(model: ArmModel, fam: PlanarFamily, P: F64, seed: F64) -> IKBatchResult:
    """Position-only targets: the pitch nearest each seed's that fits (see _free_pitch_batch)."""

    def solve(p: F64, pitch: F64, s: F64) -> tuple[F64, NDArray[np.bool_], NDArray[np.str_]]:
        return _analytic_chunks(model, fam, p, pitch, s)

    q, ok, reason = free_pitch_batch(model, fam, P, seed, solve)
    return IKBatchResult(q=q, ok=ok, reason=reason, method="analytic")


def _batch_seed(model: ArmModel, q_seed: ArrayLike | None, n: int) -> F64:
    if q_seed is None:
        return np.repeat(model.home[None, :], n, axis=0)
    qa = joint_array(model, q_seed, "q_seed")
    if qa.ndim == 2 and qa.shape[0] != n:
        raise ValueError(
            f"q_seed must have shape ({model.dof},) or ({n}, {model.dof}), got {qa.shape}"
        )
    return np.broadcast_to(qa, (n, model.dof)).copy()


def _batch_pitch(model: ArmModel, pitches: ArrayLike | None, n: int) -> F64 | None:
    if pitches is None:
        return None if model.default_pitch is None else np.full(n, model.default_pitch)
    pa = np.asarray(pitches, dtype=np.float64)
    if pa.ndim == 0:
        pa = np.full(n, float(pa))
    if pa.shape != (n,) or not np.all(np.isfinite(pa)):
        raise ValueError(
            f"pitches must be a finite number or shape ({n},) [rad], got shape {pa.shape}"
        )
    return pa
