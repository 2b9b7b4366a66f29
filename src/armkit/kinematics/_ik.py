"""The IK entry points: one target or a batch, every method behind one call."""

from __future__ import annotations

import math
from typing import Any, Literal

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .._errors import InputError
from .._inputs import angle, array, choice, joints, point, rotation, tolerance
from ..model import ArmModel
from ._chain import _CHAINS, Chain, chain_of
from ._closed import best, reasons, solve
from ._closed_scalar import family_ik, too_far, wrist_refusal
from ._family import base_pitch
from ._forward import chunks
from ._lanes import LANES
from ._near_ik import near_batch, near_ik
from ._numeric import solve_many, solve_one
from ._pitch_range import free_batch, preferred
from ._result import IKBatchResult, IKResult
from ._target import Target
from ._wrist_batch import solve_wrist_batch

F64 = NDArray[np.float64]
MethodName = Literal["auto", "analytic", "lm", "ccd", "jacobian", "random"]
METHOD_NAMES: tuple[MethodName, ...] = ("auto", "analytic", "lm", "ccd", "jacobian", "random")
TOL_M = 1e-5  # [m] = 0.01 mm
TOL_RAD = math.radians(0.01)
TOLS = (TOL_M, TOL_RAD)


def ik(
    model: ArmModel,
    position: ArrayLike | Target,
    pitch: float | None = None,
    q_seed: ArrayLike | None = None,
    *,
    orientation: ArrayLike | None = None,
    method: MethodName = "auto",
    tol_m: float = TOL_M,
    tol_rad: float = TOL_RAD,
) -> IKResult:
    """Joint angles that put the tool at ``position``.

    Args:
        model: the arm.
        position: tool point in the world frame [m], shape (3,), or a ``Target``
            (then pitch and orientation come from it).
        pitch: approach angle above the horizontal [rad] (-pi/2 = pointing
            down), or None: the model's default pitch, else any pitch (the one
            nearest the seed's).
        q_seed: joint angles [rad], shape (dof,), that solutions are ranked by
            (nearest first) and numeric solvers start from; default home.
        orientation: full tool orientation R_world_tool, shape (3, 3) (numeric methods).
        method: ``"auto"`` (closed form where the arm's shape allows, else
            ``"lm"``), ``"analytic"``, ``"lm"``, ``"ccd"``, ``"jacobian"``, ``"random"``.
        tol_m: position tolerance of numeric methods [m].
        tol_rad: pitch/orientation tolerance of numeric methods [rad].

    Returns:
        IKResult with ``q`` the best solution and ``solutions`` every one found.

    Raises:
        UnreachableError: no solution inside the limits (``reason`` says why).
        InputError: malformed input (a ValueError), naming the argument.
    """
    chain = _CHAINS.get(id(model)) or chain_of(model)
    if isinstance(position, tuple) and len(position) == 3:  # the common case, without a call
        p = x, y, z = position
        floats = type(x) is float and type(y) is float and type(z) is float
        if not (floats and x - x == 0.0 and y - y == 0.0 and z - z == 0.0):
            p = x, y, z = point(position)
    else:
        if isinstance(position, Target):
            position, pitch, orientation = _unpack(position, pitch, orientation)
        p = x, y, z = point(position)
    if pitch is not None and not (type(pitch) is float and pitch - pitch == 0.0):
        pitch = angle(pitch, "pitch")  # else: None or a finite float already
    seed = chain.home if q_seed is None else _seed(chain, q_seed)
    tols = TOLS
    if tol_m is not TOL_M or tol_rad is not TOL_RAD:  # checked as given, closed form or not
        tols = (tolerance(tol_m, "tol_m"), tolerance(tol_rad, "tol_rad"))
    wrist = chain.wrist_solve
    if wrist is not None and orientation is not None and (method == "auto" or method == "analytic"):
        R9 = _rotation9(orientation)
        if pitch is not None:
            raise InputError("give pitch or orientation, not both")
        if not (found := wrist(x, y, z, R9, seed, None)):
            if not x * x + y * y + z * z <= chain.reach2:
                raise too_far(chain, p, None)
            raise wrist_refusal(chain, p, R9, seed)
        return IKResult.of(found, (p, None, R9), chain)
    if (
        chain.fixed is not None
        and orientation is None
        and (method == "auto" or method == "analytic")
    ):
        return family_ik(chain, p, pitch, seed)
    if (
        chain.near is not None
        and orientation is None
        and (method == "auto" or method == "analytic")
    ):
        return near_ik(
            chain, p, pitch, seed,
            lambda: _numeric_ik(chain, p, pitch, seed, None, "lm", tols),
        )  # fmt: skip
    return _numeric_ik(chain, p, pitch, seed, orientation, method, tols)


def _rotation9(orientation: ArrayLike) -> tuple[float, ...]:
    """A rotation matrix checked as ``_inputs.rotation`` checks it, row-major: in plain
    floats for a (3, 3) float array (a microsecond, where numpy's check costs tens)."""
    if isinstance(orientation, np.ndarray) and orientation.shape == (3, 3):
        R = a, b, c, d, e, f, g, h, i = orientation.ravel().tolist()
        if (
            abs(a * a + b * b + c * c - 1.0) <= 1e-6
            and abs(d * d + e * e + f * f - 1.0) <= 1e-6
            and abs(g * g + h * h + i * i - 1.0) <= 1e-6
            and abs(a * d + b * e + c * f) <= 1e-6
            and abs(a * g + b * h + c * i) <= 1e-6
            and abs(d * g + e * h + f * i) <= 1e-6
            and a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g) > 0.0
        ):  # NaN fails every comparison: checked below, with the error
            return tuple(R)
    return tuple(rotation(orientation, "orientation").ravel().tolist())


def _seed(chain: Chain, q_seed: ArrayLike) -> tuple[float, ...]:
    """``q_seed`` [rad] checked: dof finite floats."""
    if isinstance(q_seed, np.ndarray) and q_seed.shape == (chain.dof,) and q_seed.dtype == float:
        seed = tuple(q_seed.tolist())  # the common case, checked without a new array
        if not all(v - v == 0.0 for v in seed):
            raise InputError("q_seed must be finite [rad], got NaN or infinity")
        return seed
    return tuple(joints(q_seed, chain.dof, "q_seed", False).tolist())


def _numeric_ik(
    chain: Chain, p: tuple[float, float, float], pitch: float | None, seed: tuple[float, ...],
    orientation: ArrayLike | None, method: Any, tols: tuple[float, float],
) -> IKResult:  # fmt: skip
    """``ik`` by a numeric method: tool point p [m], pitch [rad] or orientation."""
    if p[0] * p[0] + p[1] * p[1] + p[2] * p[2] > chain.reach2:
        raise too_far(chain, p, pitch)
    if orientation is None and pitch is None:
        pitch = chain.default_pitch
    use = _numeric_method(chain, method, orientation)
    R = None if orientation is None else rotation(orientation, "orientation")
    if R is not None and pitch is not None:
        raise InputError("give pitch or orientation, not both")
    goal = (p, pitch, None if R is None else tuple(R.ravel().tolist()))
    return solve_one(use, chain, goal, list(seed), *tols)


def why_no_closed_form(model: ArmModel) -> str:
    """'' if the yaw + planar closed form (position and pitch) applies to ``model``, else
    one line saying why not (see ``closed_form`` for the spherical wrist's)."""
    return chain_of(model).why_not


def closed_form(model: ArmModel) -> str:
    """The closed form that ``model`` gets: ``"base yaw + planar chain"`` (position, pitch),
    ``"spherical wrist"`` (full pose), or ``""`` (numeric only)."""
    chain = chain_of(model)
    if chain.family is not None or chain.near is not None:
        return "base yaw + planar chain"
    return "spherical wrist" if chain.wrist is not None else ""


def pitch_follows(model: ArmModel) -> bool:
    """Whether ``model``'s pitch follows from the position (a closed-form arm with two
    planar joints, planar2): ``ik`` then wants no pitch, or the one the position gives."""
    fam = chain_of(model).family
    return fam is not None and len(fam.planar) == 2


def _unpack(target: Target, pitch: Any, orientation: Any) -> tuple[Any, Any, Any]:
    if pitch is not None or orientation is not None:
        raise InputError("give a Target, or a position with pitch / orientation, not both")
    return target.position, target.pitch, target.orientation


def _numeric_method(
    chain: Chain, method: Any, orientation: Any
) -> Literal["lm", "ccd", "jacobian", "random"]:
    """The numeric method to use; InputError for an unknown one or 'analytic' that cannot apply."""
    name = choice(method, "method", METHOD_NAMES)
    if name == "analytic":
        why = chain.why_not or "the closed form takes a position and a pitch, not an orientation"
        if chain.wrist is not None:
            why = "the spherical-wrist closed form takes a full orientation"
        raise InputError(
            f"method 'analytic' does not apply: {why}; use a numeric method such as 'lm'"
        )
    return "lm" if name == "auto" else name  # type: ignore[return-value]


def ik_batch(
    model: ArmModel,
    positions: ArrayLike | Target,
    pitches: ArrayLike | None = None,
    q_seed: ArrayLike | None = None,
    *,
    orientations: ArrayLike | None = None,
    method: MethodName = "auto",
    tol_m: float = TOL_M,
    tol_rad: float = TOL_RAD,
) -> IKBatchResult:
    """Joint angles for N targets at once, vectorised in numpy.

    Args:
        positions: tool points [m], shape (N, 3) (N may be 0), or a ``Target`` of N targets.
        pitches: pitch [rad], a number or shape (N,), or None (the model's
            default pitch, else free: nearest the seed's).
        q_seed: [rad], shape (dof,) or (N, dof); default home.
        orientations: full tool orientations R_world_tool, shape (N, 3, 3)
            (numeric methods; instead of pitches).
        method: ``"auto"``, ``"analytic"`` or ``"lm"``.
        tol_m, tol_rad: tolerances of the numeric method [m], [rad].

    Returns:
        IKBatchResult: best solution per target (NaN rows where none), ``ok`` and ``reason``.
    """
    chain = chain_of(model)
    if isinstance(positions, Target):
        positions, pitches, orientations = _unpack(positions, pitches, orientations)
    P = array(positions, "positions", ((None, 3),), "m")  # type: ignore[arg-type]
    tol = (tolerance(tol_m, "tol_m"), tolerance(tol_rad, "tol_rad"))
    n = len(P)
    with np.errstate(over="ignore"):
        far = ~(np.einsum("ni,ni->n", P, P) <= chain.reach2)  # overflow counts as far
    if far.any():  # solve the others; the far ones are refused as such
        out = ik_batch(
            model, np.where(far[:, None], 0.0, P), pitches, q_seed, orientations=orientations,
            method=method, tol_m=tol_m, tol_rad=tol_rad,
        )  # fmt: skip
        out.q[far], out.ok[far] = np.nan, False
        reason = out.reason.astype("<U14")
        reason[far] = "too_far"
        return IKBatchResult(out.q, out.ok, reason, out.method)
    seed = _batch_seed(chain, q_seed, n)
    pitch = _batch_pitch(chain, pitches, n)
    name = choice(method, "method", METHOD_NAMES)
    fam = chain.family
    if fam is not None and orientations is None and name in ("auto", "analytic"):
        return _closed_batch(chain, fam, P, pitch, seed)
    if chain.near is not None and orientations is None and name in ("auto", "analytic"):
        return near_batch(
            chain, P, pitch, seed, lambda c, *a: _closed_batch(c, c.family, *a),
            lambda p, at, q: ik(model, p, at, q),
        )  # fmt: skip
    if chain.wrist is not None and orientations is not None and name in ("auto", "analytic"):
        if pitch is not None:
            raise InputError("give pitches or orientations, not both")
        Rw = rotation(orientations, "orientations", n)
        q, ok = solve_wrist_batch(chain.wrist, chain.lower, chain.upper, P, Rw, seed)
        reason = np.full(n, "", dtype="<U14")
        for i in np.flatnonzero(~ok).tolist():  # why not, as ``ik`` says it
            R9 = tuple(Rw[i].ravel().tolist())
            reason[i] = wrist_refusal(chain, tuple(P[i].tolist()), R9, tuple(seed[i])).reason
        return IKBatchResult(q, ok, reason, "analytic")
    use = _numeric_method(chain, name, orientations)
    if use != "lm":
        raise InputError(f"ik_batch solves with 'analytic' or 'lm', got {method!r}")
    R = None if orientations is None else rotation(orientations, "orientations", n)
    if R is not None and pitch is not None:
        raise InputError("give pitches or orientations, not both")
    if n == 0:
        return IKBatchResult(np.zeros((0, chain.dof)), np.zeros(0, bool), np.zeros(0, "<U14"), "lm")
    return solve_many(chain, P, pitch, R, seed, *tol)


def _closed_batch(chain: Chain, fam: Any, P: F64, pitch: F64 | None, seed: F64) -> IKBatchResult:
    """The vectorised closed form over cache-sized chunks of targets, with reasons."""
    free = pitch is None and len(fam.planar) == 3
    if chain.shift is not None:  # the family's frame (``Chain.shift``)
        sx, sy = chain.shift
        if pitch is not None:
            pitch = base_pitch(pitch, P[:, 0], P[:, 1], sx, sy, LANES)
        P = P - [sx, sy, 0.0]
    if free:
        q, ok = free_batch(chain, fam, P, seed)
    else:
        q, ok = np.full((len(P), chain.dof), np.nan), np.zeros(len(P), dtype=bool)
        for rows in chunks(len(P)):
            part = solve(chain, fam, P[rows], None if pitch is None else pitch[rows], seed[rows])
            q[rows], ok[rows] = best(part, seed[rows])
    reason = np.full(len(P), "", dtype="<U11")
    bad = np.flatnonzero(~ok)
    if bad.size:  # why not: the candidates at the asked (or the seed's) pitch
        at = preferred(chain, seed[bad]) if free else (None if pitch is None else pitch[bad])
        reason[bad] = reasons(fam, solve(chain, fam, P[bad], at, seed[bad]))
    return IKBatchResult(q=q, ok=ok, reason=reason, method="analytic")


def _batch_seed(chain: Chain, q_seed: ArrayLike | None, n: int) -> F64:
    if q_seed is None:
        return np.broadcast_to(chain.home_a, (n, chain.dof)).copy()
    qa = joints(q_seed, chain.dof, "q_seed")
    if qa.ndim == 2 and qa.shape[0] != n:
        raise InputError(
            f"q_seed must have shape ({chain.dof},) or ({n}, {chain.dof}), got shape {qa.shape}"
        )
    return np.broadcast_to(qa, (n, chain.dof)).copy()


def _batch_pitch(chain: Chain, pitches: ArrayLike | None, n: int) -> F64 | None:
    if pitches is None:
        return None if chain.default_pitch is None else np.full(n, chain.default_pitch)
    pa = array(pitches, "pitches", ((), (n,)), "rad")
    return np.full(n, float(pa)) if pa.ndim == 0 else pa
