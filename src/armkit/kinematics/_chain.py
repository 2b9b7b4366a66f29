"""An ArmModel compiled once into an immutable, typed chain, held beside the model.

``chain_of(model)`` is the one accessor every kinematics function uses. The
compiled ``Chain`` lives in a module-level map keyed by the model's identity
(``ArmModel`` is frozen and compares by identity) and is dropped when the
model is garbage-collected (``weakref.finalize``). A plain dict keyed by
``id`` is used rather than a ``WeakKeyDictionary`` because the lookup sits on
the microsecond paths (a weak-key lookup builds a weak reference per call);
the finalizer removes the entry before the id can be reused.
"""

from __future__ import annotations

import math
import weakref
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from .._errors import InputError, ModelError
from .._inputs import shown
from ..model import ArmModel, JointFrame
from ._boundary_fast import pack_boundary
from ._closed_fast import FixedSolver, Q, fixed_solver
from ._closed_free import FreeSolver, free_solver
from ._family import (
    PlanarFamily,
    Range,
    base_pitch,
    base_shift,
    detect,
    joint_ranges,
    wrist_range,
)
from ._near import Near, near_of
from ._packed import pack_chain
from ._pose import pitch_scalar
from ._state import Lanes, Pose, State, compile_state
from ._steps import Fixed, Step, dense_frames, frames_of, steps_of
from ._wrist import WristFamily, WristSolver, wrist_family, wrist_solver

F64 = NDArray[np.float64]


@dataclass(frozen=True, eq=False)
class Chain:
    """Everything the kinematics functions need of one model, computed once.

    Attributes:
        name: the model's name.  dof: number of joints.
        steps, tool: the chain (see ``_steps``).
        state, lanes: the forward kinematics of one q (dof floats) [rad] and of N (dof
            lanes (N,)) [rad], each -> ``ChainState`` (see ``_state``); pose: one q -> the
            tool pose's 16 entries, row-major (``fk``'s fast path).
        lower, upper, home: joint limits and home [rad] as Python floats;
        lower_a, upper_a, home_a: the same as arrays, shape (dof,).
        joint_names: the joints' names.
        default_pitch: the model's pitch when none is given [rad], or None.
        reach: upper bound on the tool point's distance from the world origin [m];
            reach2: its square (plus a nanometre) [m^2].
        weight: metres per radian for the numeric solvers' angle rows [m/rad].
        family: the closed-form geometry, or None; why_not: why not ('' if it applies).
        home_pitch: the tool's pitch at home [rad].
        wrist_reach: (min, max) distance [m] from the first planar joint to the end of
            link 2 that the elbow's limits allow (family arms; else (0, 0)).
        ranges: the planar joints' limits as ``_pitch_range`` checks them (``joint_ranges``).
        on_axis: how many frames of ``fk_frames``, from the world frame on, keep their
            origin on the vertical axis through the base origin at every pose (checked on
            home, zero and 4 random poses, fixed seed): the base column's.
        fixed: the closed form at one pitch with this chain's constants bound
            (``_closed_fast``); None off the family.
        free: on a family arm with 3 planar joints, the closed form without a pitch (it
            chooses one; with 2 the pitch follows from the position), else None.
        boundary: with ``free``, its fallback's boundary circles packed for the compiled
            search (``_boundary_fast``; None where the last link has no length).
        shift: on a family arm whose base axis is off the world origin (a URDF's root a
            little beside it), that axis's (x, y) [m]: the family, ``home_pitch`` and the
            closed-form solvers work in the frame moved there (``based``), else None.
        wrist, wrist_solve: a spherical-wrist arm's geometry and its scalar full-pose
            closed form (``_wrist``), else None.
        near: an arm of the family up to rounding, with a last roll carrying the tool
            point beside its axis (``_near``; solved by ``_near_ik``), else None.
        packed: the chain as the compiled LM kernel reads it (``_packed``).
    """

    name: str
    dof: int
    steps: tuple[Step, ...]
    tool: Fixed
    state: State
    lanes: Lanes
    pose: Pose
    lower: tuple[float, ...]
    upper: tuple[float, ...]
    home: tuple[float, ...]
    lower_a: F64
    upper_a: F64
    home_a: F64
    joint_names: tuple[str, ...]
    default_pitch: float | None
    reach: float
    reach2: float
    weight: float
    family: PlanarFamily | None
    why_not: str
    home_pitch: float
    wrist_reach: tuple[float, float]
    ranges: tuple[Range, ...]
    on_axis: int
    fixed: FixedSolver | None
    free: FreeSolver | None
    boundary: bytes | None
    shift: tuple[float, float] | None
    wrist: WristFamily | None
    wrist_solve: WristSolver | None
    packed: bytes
    near: Near | None = None

    def based(self, x: float, y: float, pitch: float | None) -> tuple[float, float, float | None]:
        """A target's x, y [m] and pitch [rad] as the closed form takes them (see ``shift``)."""
        if self.shift is None:
            return x, y, pitch
        bx, by = self.shift
        return x - bx, y - by, None if pitch is None else base_pitch(pitch, x, y, bx, by)


_CHAINS: dict[int, Chain] = {}


def chain_of(model: ArmModel) -> Chain:
    """The compiled chain of ``model``, built on first use (InputError if ``model`` is not
    an ``ArmModel``: checked here, where the lookup misses, off the hot path)."""
    chain = _CHAINS.get(id(model))
    if chain is None:
        if not isinstance(model, ArmModel):
            raise InputError(_not_a_model(model))
        chain = compile_chain(model)
        _CHAINS[id(model)] = chain
        weakref.finalize(model, _CHAINS.pop, id(model), None)
    return chain


def _not_a_model(model: object) -> str:
    """The refusal of a ``model`` that is not an ``ArmModel`` (a name or file: load it)."""
    name = str(model) if isinstance(model, str | Path) else "openmanipulator_x"
    return (
        f"model must be an ArmModel; load one with armkit.load_model({name!r}); got {shown(model)}"
    )


MAX_REACH = 1e4  # [m]: beyond it float arithmetic on the chain loses its metres


def joint_frames(model: ArmModel) -> tuple[tuple[JointFrame, ...], F64]:
    """The chain as URDF describes it: per joint its frame (origin from the previous joint's
    frame, axis), and the tool frame in the last joint's frame, shape (4, 4) [m]."""
    chain = chain_of(model)
    return frames_of(chain.steps), chain.tool.T


def compile_chain(model: ArmModel) -> Chain:
    """Build the ``Chain`` of a model (use ``chain_of``, which keeps it).

    Raises:
        ModelError: the chain is not finite or reaches beyond ``MAX_REACH``.
    """
    steps, tool = steps_of(model)
    reach = sum(math.hypot(*s.before.T[:3, 3]) for s in steps) + math.hypot(*tool.T[:3, 3])
    if not reach <= MAX_REACH:
        raise ModelError(
            f"{model.name}: the links add up to {reach:.3g} m; armkit's kinematics takes arms "
            f"up to {MAX_REACH / 1000:g} km (check the model's lengths are in mm)"
        )
    state, lanes, pose = compile_state(steps, tool)
    at_zero = state([0.0] * model.dof)
    shift = base_shift(at_zero.jw[0], at_zero.origins[0])
    T0 = np.eye(4)
    T0[:3, :3] = np.array(at_zero.R).T
    T0[:3, 3] = at_zero.p[0] - shift[0], at_zero.p[1] - shift[1], at_zero.p[2]
    origins = [(x - shift[0], y - shift[1], z) for x, y, z in at_zero.origins]
    family = detect(at_zero.jw, origins, T0)
    if isinstance(family, PlanarFamily) and family.lateral and shift != (0.0, 0.0):
        family = "has its base axis off the world origin and its plane beside the base axis"
    fam = family if isinstance(family, PlanarFamily) else None
    wf = None if fam else wrist_family(at_zero.jw, origins, T0, shift)
    lower = tuple(float(j.lower) for j in model.joints)
    upper = tuple(float(j.upper) for j in model.joints)
    home = tuple(float(j.home) for j in model.joints)
    at_home = state(list(home))
    home_pitch = pitch_scalar(at_home.R[0], (at_home.p[0] - shift[0], at_home.p[1] - shift[1]))
    near = _near(model, home) if fam is None and not isinstance(wf, WristFamily) else None
    wrist = wrist_range(fam, lower[fam.planar[1]], upper[fam.planar[1]]) if fam else (0.0, 0.0)
    fixed, free = _solvers(fam, lower, upper, wrist, (home, home_pitch, state, shift))
    ranges = joint_ranges(fam, lower, upper) if fam else ()
    return Chain(
        name=model.name,
        dof=model.dof,
        steps=steps,
        tool=tool,
        state=state,
        lanes=lanes,
        pose=pose,
        lower=lower,
        upper=upper,
        home=home,
        lower_a=np.array(lower),
        upper_a=np.array(upper),
        home_a=np.array(home),
        joint_names=model.joint_names,
        default_pitch=model.default_pitch,
        reach=reach,
        reach2=(reach + 1e-9) * (reach + 1e-9),
        weight=0.5 * reach,
        family=fam,
        why_not="" if fam or near else f"{model.name} {family}",
        home_pitch=home_pitch,
        wrist_reach=wrist,
        ranges=ranges,
        boundary=pack_boundary(fam, lower, upper, ranges) if fam and free else None,
        on_axis=_on_axis(steps, tool, np.array(lower), np.array(upper), np.array(home)),
        fixed=fixed,
        free=free,
        shift=shift if fam is not None and shift != (0.0, 0.0) else None,
        wrist=wf if isinstance(wf, WristFamily) else None,
        wrist_solve=wrist_solver(wf, lower, upper) if isinstance(wf, WristFamily) else None,
        packed=pack_chain(steps, tool, lower, upper, reach, 0.5 * reach),
        near=near,
    )


def _near(model: ArmModel, home: Q) -> Near | None:
    """``near_of(model)`` where its idealised chain, the roll frozen at home, is of the
    closed-form family (``Chain.near``), else None."""
    near = near_of(model)
    if near is None:
        return None
    return near if chain_of(near.at(home[-1])).family is not None else None


def _on_axis(steps: tuple[Step, ...], tool: Fixed, lower: F64, upper: F64, home: F64) -> int:
    """See ``Chain.on_axis``."""
    q = np.vstack([home, np.zeros(len(steps)), spread(lower, upper, 4)])
    p = dense_frames(steps, tool, q)[:, :, :3, 3]
    on = np.all(np.hypot(p[..., 0], p[..., 1]) < 1e-9, axis=0)
    return int(np.argmin(on)) if not on.all() else len(on)


def spread(lower: F64, upper: F64, n: int) -> F64:
    """``n`` joint vectors spread evenly over the box ``lower``..``upper`` (radians), with
    no random generator (loading numpy.random costs 10-25 ms of every command's start-up):
    Roberts' R-sequence, the d-dimensional golden ratio, starting at the box's centre."""
    d = len(lower)
    g = 2.0
    for _ in range(60):  # g = the root of g**(d+1) = g + 1 (the golden ratio for d = 1)
        g = (1.0 + g) ** (1.0 / (d + 1))
    alpha = (1.0 / g) ** np.arange(1, d + 1)
    frac: F64 = np.modf(0.5 + np.arange(1, n + 1)[:, None] * alpha[None, :])[0]
    return lower + (upper - lower) * frac


def _solvers(
    fam: PlanarFamily | None, lower: Q, upper: Q, wrist: tuple[float, float],
    at_home: tuple[Q, float, State, tuple[float, float]],
) -> tuple[FixedSolver | None, FreeSolver | None]:  # fmt: skip
    """The closed-form solvers of a family arm (``_closed_fast``), None off the family;
    ``at_home``: home [rad], the pitch there [rad], the chain's scalar state and its shift."""
    if fam is None:
        return None, None
    solve = fixed_solver(fam, lower, upper)
    if len(fam.planar) != 3:
        return solve, None
    base = (0.0, 0.0) if fam.base is None else (lower[fam.base], upper[fam.base])
    return solve, free_solver(fam, solve, wrist, base, at_home)
