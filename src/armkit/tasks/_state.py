"""Planning state and the moves a task is made of: each one solved (IK) and its
whole joint-space sweep checked for clearance as it is added, nothing sent."""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace

import numpy as np
from numpy.typing import NDArray

from .._errors import UnreachableError
from ..kinematics import ik
from ..model import ArmModel
from ..motion import approach
from ..scene import Held, Scene, check_clear
from ._calibration import Calibration
from ._plan import Step, TaskError

F64 = NDArray[np.float64]
SWEEP_STEP = math.radians(1.0)  # joint-space samples of every move for the clearance check
RAISES = (0.0, 0.02, 0.04)  # [m] how much higher than the clearance a transit may go
TRANSIT_STEPS = 6  # moves of an interpolated transit
TURN_IN_TRANSIT = math.radians(45.0)  # a transit turning the tool more is interpolated first


@dataclass(frozen=True)
class Options:
    """How tasks are planned.

    Attributes:
        clearance: height of the first waypoint above a grasp or release point [m]
            (001: at least 30 mm), then ``waypoints`` steps down.
        waypoints: steps from there down to the point (001: 3).
        margin: clearance required between the arm and everything [m].
        calibration: the unit's offsets.
    """

    clearance: float = 0.030
    waypoints: int = 3
    margin: float = 0.0
    calibration: Calibration = field(default_factory=Calibration)


@dataclass(frozen=True)
class State:
    """Where planning has got to: the joints [rad] (dof,), the objects at rest
    (the held cube left out), the held cube, the gripper opening [m] (None: not
    known yet), and the steps so far."""

    q: F64
    scene: Scene
    held: Held | None
    opening: float | None
    steps: tuple[Step, ...] = ()


@dataclass(frozen=True)
class Context:
    """What does not change while a task is planned."""

    model: ArmModel
    options: Options
    task: str


def grip(ctx: Context, st: State, width: float, label: str) -> State:
    """Command the gripper to ``width`` [m] (nothing is checked: the jaws move only)."""
    step = Step(label, grip=width, holding=_name(st.held), settle=True)
    return replace(st, opening=width, steps=(*st.steps, step))


def moves(
    ctx: Context,
    st: State,
    points: F64,
    pitch: float | F64,
    labels: list[str],
    *,
    kin: ArmModel,
    ignore: frozenset[str] = frozenset(),
) -> State:
    """Joint moves to the tool ``points`` (scene frame) [m], shape (K, 3), one after
    another at ``pitch`` [rad] (one for all, or shape (K,)), solved with ``kin``
    (the model at the gripper's opening); their joint-space sweeps checked in one go.

    Raises:
        TaskError: naming the step, and the link and object if it would collide.
    """
    qs, sweeps, owner = [], [], []
    prev = st.q
    pitches = np.broadcast_to(np.asarray(pitch, dtype=np.float64), (len(points),))
    for k, point in enumerate(points):
        q = solve(kin, st.scene.to_base(point), float(pitches[k]), prev, ctx.task, labels[k])
        n = max(2, math.ceil(float(np.max(np.abs(q - prev))) / SWEEP_STEP) + 1)
        sweeps.append(prev + (q - prev) * (np.arange(1, n) / (n - 1))[:, None])
        owner.extend([k] * (n - 1))
        qs.append(q)
        prev = q
    sweep = np.vstack(sweeps)
    hit = check_clear(kin, sweep, st.scene, st.held, ignore=ignore, margin=ctx.options.margin)
    if hit is not None:
        k = owner[hit.step]
        end = hit.step + 1 == len(owner) or owner[hit.step + 1] != k
        where = "" if end else " on the way"
        raise TaskError(
            f"{ctx.task}: step '{labels[k]}'{where}: {hit.describe()}",
            step=labels[k], link=hit.link, obj=hit.object, why=hit.describe(),
            remedy="give a point higher above the table" if hit.object == "table" else
            f"move the {hit.object} out of the way or choose another place",
        )  # fmt: skip
    steps = list(st.steps)
    for k, q in enumerate(qs):
        p = float(pitches[k])
        command = q if ctx.options.calibration.zero else _calibrated(ctx, kin, st, points[k], p, q)
        steps.append(Step(labels[k], q=command, point=points[k], pitch=p, holding=_name(st.held)))
    return replace(st, q=qs[-1], steps=tuple(steps))


def down(
    ctx: Context,
    st: State,
    point: F64,
    pitch: float,
    label: str,
    *,
    kin: ArmModel,
    ignore: frozenset[str],
) -> State:
    """001's way down: to ``clearance`` above ``point`` [m], then ``waypoints``
    steps straight down to it (the last ones may touch ``ignore``). The way to
    the point above is a joint move; if that would hit something, the tool's
    point and pitch are interpolated there instead (TRANSIT_STEPS moves), and if
    that would too, the arm lifts first and comes in higher (001: "at least" the
    clearance), up to the last of RAISES higher."""
    failure: TaskError | None = None
    last = _last_pitch(st)
    turn = last is not None and abs(last - pitch) > TURN_IN_TRANSIT
    for extra in RAISES:
        for steps in (TRANSIT_STEPS, 1) if turn else (1, TRANSIT_STEPS):
            try:
                st2 = _transit(ctx, st, point, pitch, label, kin, extra, steps)
            except TaskError as exc:
                if failure is None and not exc.link:
                    raise  # the point above is out of reach: no other way helps
                failure = failure or exc
                continue
            pts = approach(point, ctx.options.clearance + extra, ctx.options.waypoints)[1:]
            labels = [f"{label}: down {k}/{len(pts)}" for k in range(1, len(pts) + 1)]
            return moves(ctx, st2, pts, pitch, labels, kin=kin, ignore=ignore)
    assert failure is not None
    raise failure


def _transit(
    ctx: Context,
    st: State,
    point: F64,
    pitch: float,
    label: str,
    kin: ArmModel,
    extra: float,
    steps: int,
) -> State:
    """From where the tool is to ``clearance + extra`` above ``point``, lifting
    ``extra`` first, in ``steps`` moves (the tool point and pitch interpolated)."""
    above = point + np.array([0.0, 0.0, ctx.options.clearance + extra])
    last = next((s for s in reversed(st.steps) if s.point is not None), None)
    if last is None or last.point is None or last.pitch is None:
        return moves(ctx, st, above[None, :], pitch, [f"{label}: above"], kin=kin)
    start = last.point
    if extra > 0:
        start = start + np.array([0.0, 0.0, extra])
        st = moves(ctx, st, start[None, :], last.pitch, [f"lift {extra * 1000:.0f} mm"], kin=kin)
    s = np.linspace(0.0, 1.0, steps + 1)[1:]
    pts = start + s[:, None] * (above - start)
    pitches = last.pitch + s * (pitch - last.pitch)
    labels = [f"{label}: on the way {k}/{steps}" for k in range(1, steps)] + [f"{label}: above"]
    return moves(ctx, st, pts, pitches, labels, kin=kin)


def up(
    ctx: Context,
    st: State,
    point: F64,
    pitch: float,
    label: str,
    *,
    kin: ArmModel,
    ignore: frozenset[str],
) -> State:
    """The way down reversed: ``waypoints`` steps up to ``clearance`` above ``point``."""
    pts = approach(point, ctx.options.clearance, ctx.options.waypoints)[::-1]
    n = len(pts) - 1
    labels = [f"{label}: up {k}/{n}" for k in range(1, n + 1)]
    return moves(ctx, st, pts[1:], pitch, labels, kin=kin, ignore=ignore)


def solve(kin: ArmModel, base: F64, pitch: float, seed: F64, task: str, label: str) -> F64:
    """IK for tool point ``base`` (base frame) [m] at ``pitch`` [rad] nearest ``seed``;
    TaskError ``"<task>: step '<label>' is unreachable: ..."`` with the reason and
    the remedy in a few words (``TaskError.why``, ``remedy``)."""
    try:
        q: F64 = ik(kin, (float(base[0]), float(base[1]), float(base[2])), pitch, seed).q
    except UnreachableError as exc:
        why, remedy = UNREACHABLE_WORDS.get(exc.reason, UNREACHABLE_WORDS["unreachable"])
        out = float(np.hypot(base[0], base[1])) * 1000.0
        raise TaskError(
            f"{task}: step '{label}' is unreachable: {exc}", step=label, reason=exc.reason,
            why=f"{why} ({out:.0f} mm out, {base[2] * 1000.0:.0f} mm up)", remedy=remedy,
        ) from None  # fmt: skip
    return q


UNREACHABLE_WORDS = {  # an IK failure's reason -> (why, remedy), in a few words
    "too_far": ("too far from the arm", "move it nearer the arm"),
    "too_close": ("too near the arm's base", "move it further out"),
    "joint_limit": ("a joint would pass its limit", "move it nearer the middle of the reach"),
    "unreachable": ("out of reach", "move it nearer the middle of the reach"),
}


def _calibrated(ctx: Context, kin: ArmModel, st: State, point: F64, pitch: float, q: F64) -> F64:
    """The joints to command so this unit lands at ``point`` (scene frame) [m]: the
    point moved by the calibration offsets (up, and away from the base axis)."""
    base = st.scene.to_base(point)
    cal = ctx.options.calibration
    radial = np.array([base[0], base[1], 0.0])
    norm = float(np.linalg.norm(radial))
    shifted = base + np.array([0.0, 0.0, cal.height / 1000.0])
    if norm > 1e-9:
        shifted = shifted + radial / norm * (cal.perpendicular / 1000.0)
    return solve(kin, shifted, pitch, q, ctx.task, "a point moved by the calibration offsets")


def _last_pitch(st: State) -> float | None:
    return next((s.pitch for s in reversed(st.steps) if s.pitch is not None), None)


def _name(held: Held | None) -> str | None:
    return None if held is None else held.cube.name
