"""001's choice of how to grasp: each way tried in turn, the first whose every
step is reachable and clear wins; if none, one error naming each way's failure."""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence

import numpy as np

from .._errors import InputError
from ._grasping import SIDE, TOP, check_uncovered, how, pick, place, side_shift
from ._plan import TaskError
from ._state import Context, State

Attempt = Callable[[State], State]
TILTS = tuple(math.radians(d) for d in (-75.0, -60.0, -45.0, -30.0, -15.0))
SHOWN = 2  # failures spelt out in the error; the rest are summed up


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
    if len(failures) == 1:
        raise failures[0][1]
    text = "; ".join(
        f"{name}: {str(exc).removeprefix(ctx.task + ': ')}" for name, exc in failures[:SHOWN]
    )
    if len(failures) > SHOWN:
        text += f"; nor {', '.join(name for name, _ in failures[SHOWN:])}"
    first = failures[0][1]
    raise TaskError(
        f"{ctx.task}: cannot {what}: {text}", step=first.step, link=first.link, obj=first.object
    )


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

    def at(p: float) -> Attempt:
        return lambda s: place(ctx, s, bottom, p, where)

    held = st.held.cube.name if st.held else "?"
    return first_that_works(ctx, st, f"put {held} {where}", [(how(p), at(p)) for p in order])


def current_pitch(st: State) -> float:
    """The pitch of the last move planned [rad] (0 if none yet)."""
    for step in reversed(st.steps):
        if step.pitch is not None:
            return step.pitch
    return 0.0


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
    st = pick(ctx, st, name, first, shift)
    return place(ctx, st, cube.position, second, f"back turned {direction}")
