"""001's choice of how to grasp: each way tried in turn, the first whose every
step is reachable and clear wins; if none, one error naming each way's failure."""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence

import numpy as np

from .._errors import InputError, UnreachableError
from ..kinematics import ik
from ..scene import Cube
from ._grasping import (
    OTHER_FACE,
    SIDE,
    TOP,
    check_uncovered,
    gripper_model,
    held_pitch,
    how,
    pick,
    place,
    radial,
    side_shift,
)
from ._plan import TaskError
from ._state import Context, State

Attempt = Callable[[State], State]
TILTS = tuple(math.radians(d) for d in (-75.0, -60.0, -45.0, -30.0, -15.0))


def pitches(ctx: Context, pitch: float | None) -> tuple[float, ...]:
    """The pitches to try [rad]: the one asked for; else the model's default (the
    OWI keeps its gripper level, 000); else from the top, then from the side (001),
    then tilted in between (for wrists such as the Lynx6's that reach neither)."""
    if pitch is not None:
        return (pitch,)
    if ctx.model.default_pitch is not None:
        return (ctx.model.default_pitch,)
    return (TOP, SIDE, *TILTS)


def first_that_works(
    ctx: Context, st: State, what: str, tries: Sequence[tuple[str, Attempt]]
) -> State:
    """The state after the first attempt that plans; else TaskError naming each."""
    failures: list[tuple[str, TaskError]] = []
    for name, attempt in tries:
        try:
            return attempt(st)
        except TaskError as exc:
            failures.append((name, exc))
    if len(failures) == 1 and not failures[0][1].why:
        raise failures[0][1]
    raise refusal(ctx, what, failures)


def refusal(
    ctx: Context, what: str, failures: Sequence[tuple[str, TaskError]], remedy: str | None = None
) -> TaskError:
    """One short TaskError for every way tried: the first (preferred) way's reason
    and remedy (or ``remedy``) on the line, every way's whole failure in ``details``
    (``--explain``)."""
    name, first = failures[0]
    why = first.why or str(first).removeprefix(ctx.task + ": ")
    remedy = first.remedy if remedy is None else remedy
    todo = f"; {remedy}" if remedy else ""
    details = "\n".join(f"{n}: {str(e).removeprefix(ctx.task + ': ')}" for n, e in failures)
    return TaskError(
        f"{ctx.task}: cannot {what} {name}: {why}{todo}",
        step=first.step, link=first.link, obj=first.object, reason=first.reason,
        why=why, remedy=remedy, details=details,
    )  # fmt: skip


def pick_any(ctx: Context, st: State, name: str, pitch: float | None) -> State:
    """Pick cube ``name`` at the first pitch that works (a side grasp shifted up)."""
    cube = st.scene.cube(name)
    check_uncovered(ctx, st, name)

    def at(p: float) -> Attempt:
        def attempt(s: State) -> State:
            shift = side_shift(ctx, s, cube) if abs(p - SIDE) < 1e-9 else 0.0
            return pick(ctx, s, name, p, shift)

        return attempt

    return first_that_works(ctx, st, f"pick {name}", [(how(p), at(p)) for p in pitches(ctx, pitch)])


def place_any(
    ctx: Context, st: State, bottom: np.ndarray, where: str, pitch: float | None
) -> State:
    """Put the held cube down at ``bottom`` [m], keeping the pitch it was picked at
    if that works (the cube keeps its face up), else another."""
    now = current_pitch(st)
    order = sorted(pitches(ctx, pitch), key=lambda p: abs(p - now))

    held = st.held.cube.name if st.held else "?"
    failures: list[tuple[str, TaskError]] = []
    for p in order:
        try:
            return place(ctx, st, bottom, p, where)
        except TaskError as exc:
            failures.append((how(p), exc))
    other = [p for p, (_, e) in zip(order, failures, strict=True) if e.why.endswith(OTHER_FACE)]
    remedy = None
    if other and not failures[0][1].why.endswith(OTHER_FACE):  # held the wrong way for here
        deg = round(math.degrees(other[0]))
        remedy = f"pick it again {how(other[0])} (--pitch {deg})"
    raise refusal(ctx, f"put {held} {where}", failures, remedy)


def carry(
    ctx: Context, st: State, name: str, bottom: np.ndarray, where: str, pitch: float | None
) -> State:
    """Pick cube ``name`` and put it down at ``bottom`` [m] with the same face up: at
    the first pitch that does both (001: from the top, else from the side, then
    tilted), so that a pick that works cannot lead to a put-down that cannot."""
    cube = st.scene.cube(name)
    check_uncovered(ctx, st, name)

    def at(p: float) -> Attempt:
        def attempt(s: State) -> State:
            shift = side_shift(ctx, s, cube) if abs(p - SIDE) < 1e-9 else 0.0
            return place(ctx, pick(ctx, s, name, p, shift), bottom, p, where)

        return attempt

    tries = [(how(p), at(p)) for p in pitches(ctx, pitch)]
    return first_that_works(ctx, st, f"put {name} {where}", tries)


def current_pitch(st: State) -> float:
    """The pitch of the last move planned [rad]; with none yet, the one that puts
    the held cube down as it was picked (0 if nothing is held)."""
    for step in reversed(st.steps):
        if step.pitch is not None:
            return step.pitch
    return held_pitch(st.held) if st.held is not None else 0.0


def rotate(ctx: Context, st: State, name: str, direction: str) -> State:
    """001's rotation in place: forward = pick from the side, put down from the top;
    backward = pick from the top, put down from the side. The grasp point is
    chosen so that the side grasp is shifted up clear of the holders."""
    if direction not in ("forward", "backward"):
        raise InputError(f"direction must be 'forward' or 'backward', got {direction!r}")
    cube = st.scene.cube(name)
    check_uncovered(ctx, st, name)
    shift = side_shift(ctx, st, cube)
    first, second = (SIDE, TOP) if direction == "forward" else (TOP, SIDE)
    try:
        st = pick(ctx, st, name, first, shift)
        return place(ctx, st, cube.position, second, f"back turned {direction}", turn=True)
    except TaskError as exc:
        raise _no_turn(ctx, st, cube, shift, exc) from None


def _no_turn(ctx: Context, st: State, cube: Cube, shift: float, exc: TaskError) -> TaskError:
    """The rotation's refusal: how far out the arm reaches the cube both from the
    side and from the top (where it could turn it), or that it never does."""
    up = ctx.options.clearance
    side, top = (_band(ctx, st, cube, p, z, z + up) for p, z in ((SIDE, shift), (TOP, 0.0)))
    both = [r for r in side if r in top]
    what = f"turn {cube.name} in place"
    if not both:
        why = (
            f"the {ctx.model.name} reaches it from the side {_span(side)}, from the top "
            f"{_span(top)}, never both"
        )
        remedy = "turn it by hand"
    else:
        why = exc.why or str(exc).removeprefix(ctx.task + ": ")
        remedy = f"stand it {_span(both).removesuffix(' out')} from the arm's axis"
    return TaskError(
        f"{ctx.task}: cannot {what}: {why}; {remedy}", step=exc.step, link=exc.link,
        obj=exc.object, reason=exc.reason, why=why, remedy=remedy,
        details=str(exc).removeprefix(ctx.task + ": "),
    )  # fmt: skip


def _band(ctx: Context, st: State, cube: Cube, pitch: float, *ups: float) -> list[int]:
    """The distances from the arm's axis [mm, 5 mm apart] at which the tool reaches
    ``cube``'s centre raised by each of ``ups`` [m] at ``pitch``, along the cube's
    bearing (the grasp and the point above it)."""
    kin, _ = gripper_model(ctx, cube)
    axis, out = st.scene.T_world_base[:3, 3], radial(st, cube.center)
    found = []
    for r in range(100, 605, 5):  # nearer, the links would stand over the base
        p = axis + out * (r / 1000.0)
        try:
            for up in ups:
                p[2] = cube.center[2] + up
                ik(kin, tuple(float(v) for v in st.scene.to_base(p)), pitch, st.q)
        except UnreachableError:
            continue
        found.append(r)
    return found


def _span(rs: list[int]) -> str:
    """``"40..100 or 200..235 mm out"`` for distances 5 mm apart [mm]."""
    if not rs:
        return "nowhere"
    runs: list[list[int]] = [[rs[0], rs[0]]]
    for r in rs[1:]:
        if r - runs[-1][1] > 5:
            runs.append([r, r])
        runs[-1][1] = r
    return " or ".join(f"{a}..{b}" for a, b in runs) + " mm out"
