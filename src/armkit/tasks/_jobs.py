"""The tasks: functions of an Arm and a Scene, each planned whole (every IK, every
clearance check) before anything moves, then carried out unless ``dry_run``.
Millimetres and degrees in their arguments, like ``Arm``; each returns its Plan."""

from __future__ import annotations

import itertools
import math
import time
from collections.abc import Callable, Sequence
from dataclasses import replace
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from .._errors import InputError
from .._inputs import is_number, shown
from ..arm import Start, plan_steps
from ..kinematics import fk
from ..scene import Cube, Scene
from ._calibration import Calibration, calibration_for
from ._choose import carry, pick_any, place_any, rotate
from ._live import live_scene, run_verified
from ._plan import Plan, TaskError
from ._points import move_point
from ._precision import precision_of
from ._state import Context, Options, State
from ._targets import Destination, resolve, taken_by

if TYPE_CHECKING:
    from ..arm import Arm

Body = Callable[[Context, State], State]
CalibrationLike = Calibration | str | Path | None


def plan_task(
    arm: Arm | Start,
    scene: Scene,
    task: str,
    body: Body,
    *,
    clearance: float = 30.0,
    calibration: CalibrationLike = None,
    held: str | None = None,
) -> Plan:
    """Plan ``body`` from the arm's joints now (a ``Start``'s); nothing moves.

    Args:
        clearance: height of the first waypoint above each grasp and release [mm],
            30..500 (001: at least 30), then three waypoints down (an open-loop arm:
            its model file's ``task_waypoints``, the OWI one move).
        calibration: the unit's offsets, a calibration file, or None: the arm's
            default file if there is one (``armkit.tasks.default_calibration_file``).
        held: a cube already in the gripper (picked by ``pick`` from where the scene has it).

    Raises:
        TaskError: a step is unreachable or would collide (naming the step, link, object).
        ValueError: a bad argument.
    """
    _check_clearance(clearance)
    if isinstance(calibration, Calibration):
        cal = calibration
    else:
        cal = calibration_for(arm.model.name, calibration)
    waypoints = precision_of(arm.model).waypoints  # the OWI: fewer, longer runs down
    options = Options(clearance=clearance / 1000.0, waypoints=waypoints, calibration=cal)
    ctx = Context(arm.model, options, task)
    began = time.perf_counter()
    start = arm if isinstance(arm, Start) else arm.start()
    st = State(start.q, scene, None, None)
    first = start.then(scene=scene, held=None)
    if held is not None:
        picked = pick_any(ctx, st, held, None)
        st = replace(st, held=picked.held, scene=picked.scene, opening=arm.model.gripper.width_min)
        closed = arm.model.gripper.width_min
        jaws = None if st.held is None else max(closed, st.held.cube.size)  # on the cube
        first = first.then(held=st.held, scene=st.scene, grip=st.opening, jaws=jaws)
    st = body(ctx, st)
    after = (
        st.scene
        if st.held is None
        else replace(st.scene, cubes=(*st.scene.cubes, _carried(ctx, st)))
    )
    end = first.then(held=st.held, scene=st.scene)
    took = time.perf_counter() - began
    return plan_steps(first, task, st.steps, end=end, after=after, planning_time=took)


def _carried(ctx: Context, st: State) -> Cube:
    """The held cube where the gripper holds it at the end of the plan."""
    assert st.held is not None
    kin = ctx.model.with_grip_width(st.held.cube.size)
    T = st.scene.T_world_base @ fk(kin, st.q) @ st.held.T_tool_object
    return st.held.cube.moved(T)


def _free(scene: Scene, target: Destination, moving: str | None, task: str) -> Destination:
    """``target`` if no other cube stands there; TaskError naming the one that does."""
    if moving is not None and target.label == f"on {moving}":
        raise TaskError(f"{task}: {moving} cannot go on itself; choose another place", step=task)
    other = taken_by(scene, target, moving)
    if other is None:
        return target
    top = other
    while (above := taken_by(scene, resolve(scene, top), moving)) is not None:
        top = above  # the cube the stack ends with: the one to put it on
    what = moving or "it"
    if target.label.startswith("on "):  # a stack
        why = f"{target.label.removeprefix('on ')} has {other} on it; put {what} on {top}"
    else:
        where = target.label.removeprefix("in ").removeprefix("at ")
        why = f"{where} is taken by {other}; choose a free one, or put {what} on {top}"
    raise TaskError(f"{task}: {why}", step=task)


def _deg(pitch: float | None) -> float | None:
    if pitch is None:
        return None
    if not (is_number(pitch) and -90.0 <= pitch <= 90.0):
        raise InputError(f"pitch must be -90..90 deg or None, got {shown(pitch)}")
    return math.radians(pitch)


def _check_clearance(clearance: float) -> None:
    """Refuse a clearance plan_task would refuse, before the scene is attached."""
    if not (is_number(clearance) and 30.0 <= clearance <= 500.0):
        raise InputError(f"clearance must be 30..500 mm (001: at least 30), got {shown(clearance)}")


def _done(arm: Arm | Start, plan: Plan, dry_run: bool) -> Plan:
    """The plan, after running it on ``arm`` unless ``dry_run`` (a ``Start`` only plans)."""
    if not dry_run and not isinstance(arm, Start):
        run_verified(arm, plan)
    return plan


def pick(
    arm: Arm | Start,
    scene: Scene,
    cube: str,
    *,
    pitch: float | None = None,
    clearance: float = 30.0,
    calibration: CalibrationLike = None,
    dry_run: bool = False,
) -> Plan:
    """Pick ``cube`` up (001: from the top where reachable, else from the side with
    the grasp point shifted up; ``pitch`` [deg] forces one) and stay above it.

    Args:
        arm: the arm, or a ``Start`` (a model, its joints, what it holds) to plan from
            with nothing moving.
        clearance: height of the first waypoint above each grasp and release [mm],
            30..500 (001: at least 30), then three waypoints down (an open-loop arm:
            its model file's ``task_waypoints``, the OWI one move).
        calibration: the unit's offsets (``Calibration``, in mm), a calibration file,
            or None: the arm's default file if there is one (``default_calibration_file``).
        dry_run: plan and check only; nothing moves.

    Returns the plan (carried out unless ``dry_run`` or planned from a ``Start``).

    Raises:
        TaskError: a step is unreachable or would collide (naming the step, link,
            object); nothing has moved.
        ValueError: a bad argument.
    """
    p = _deg(pitch)
    _check_clearance(clearance)
    scene = live_scene(arm, scene, dry_run, f"pick {cube}")
    plan = plan_task(
        arm, scene, f"pick {cube}", lambda c, s: pick_any(c, s, cube, p),
        clearance=clearance, calibration=calibration,
    )  # fmt: skip
    return _done(arm, plan, dry_run)


def place(
    arm: Arm | Start,
    scene: Scene,
    cube: str,
    to: str | Sequence[float],
    *,
    pitch: float | None = None,
    clearance: float = 30.0,
    calibration: CalibrationLike = None,
    dry_run: bool = False,
) -> Plan:
    """Put ``cube`` (in the gripper, picked by ``pick`` from where ``scene`` has it)
    down at ``to``: a place, ``board[row, col]``, a cube to stack on, a container,
    or (x, y, z) [mm]; then go back up. ``pitch`` [deg] forces the tool's pitch;
    ``clearance`` [mm], ``calibration`` and ``dry_run`` as ``pick``."""
    scene = live_scene(arm, scene, dry_run, f"place {cube}", held=cube)
    target = _free(scene, resolve(scene, to), cube, f"place {cube}")
    p = _deg(pitch) if pitch is not None else target.pitch
    plan = plan_task(
        arm, scene, f"place {cube}", lambda c, s: place_any(c, s, target.bottom, target.label, p),
        clearance=clearance, calibration=calibration, held=cube,
    )  # fmt: skip
    return _done(arm, plan, dry_run)


def move_item(
    arm: Arm | Start,
    scene: Scene,
    item: str | Sequence[float],
    to: str | Sequence[float],
    *,
    lift: float = 40.0,
    pitch: float | None = None,
    clearance: float = 30.0,
    calibration: CalibrationLike = None,
    dry_run: bool = False,
) -> Plan:
    """000's moveItem: pick ``item`` up, lift it ``lift`` [mm] (at least the
    clearance) before travelling, carry it to ``to`` (as ``place``), put it down.

    ``item`` is a cube of the scene, or the grip point (x, y, z) [mm] of an item the
    scene does not know (then ``to`` must be a point or a place too, and the grasp
    and the item's own clearance cannot be checked). ``pitch`` [deg] forces the tool's
    pitch; ``clearance`` [mm], ``calibration`` and ``dry_run`` as ``pick``.
    """
    if not (is_number(lift) and 0.0 <= lift <= 500.0):
        raise InputError(f"lift must be 0..500 mm, got {shown(lift)}")
    scene = live_scene(arm, scene, dry_run, "move")
    moving = item if isinstance(item, str) else None
    target = _free(scene, resolve(scene, to), moving, f"move {moving or 'the item'}")
    p = _deg(pitch)
    height = max(lift, clearance)
    if isinstance(item, str):
        name = item

        def body(c: Context, s: State) -> State:
            return carry(
                c, s, item, target.bottom, target.label, p if p is not None else target.pitch
            )

    else:
        name = "the item"
        start = resolve(scene, item).bottom

        def body(c: Context, s: State) -> State:
            return move_point(c, s, start, target.bottom, p)

    plan = plan_task(arm, scene, f"move {name}", body, clearance=height, calibration=calibration)
    return _done(arm, plan, dry_run)


def rotate_cube(
    arm: Arm | Start,
    scene: Scene,
    cube: str,
    direction: str = "forward",
    *,
    clearance: float = 30.0,
    calibration: CalibrationLike = None,
    dry_run: bool = False,
) -> Plan:
    """001: turn ``cube`` a quarter turn (90 deg) in place, coming down from ``clearance``
    [mm] above it (as ``pick``): ``"forward"`` picks it from the
    side (pitch 0) and puts it down from the top (pitch -90), its top face then
    facing away from the arm; ``"backward"`` the other way round."""
    scene = live_scene(arm, scene, dry_run, f"rotate {cube}")
    plan = plan_task(
        arm, scene, f"rotate {cube} {direction}", lambda c, s: rotate(c, s, cube, direction),
        clearance=clearance, calibration=calibration,
    )  # fmt: skip
    return _done(arm, plan, dry_run)


def stack_names(cubes: object) -> list[str]:
    """``stack``'s cubes checked: two or more different names (InputError otherwise)."""
    names: list[str] = []
    if isinstance(cubes, str):
        names = [cubes]  # one name: not its letters
    elif isinstance(cubes, Sequence) and all(isinstance(c, str) for c in cubes):
        names = [str(c) for c in cubes]
    if len(names) < 2 or len(set(names)) != len(names):
        given = names or shown(cubes)
        raise InputError(
            f"stack needs two or more different cubes, got {given}; give their names, "
            "e.g. ['red', 'green']"
        )
    return names


def stack(
    arm: Arm | Start,
    scene: Scene,
    cubes: Sequence[str],
    *,
    rotate_first: str | None = "forward",
    clearance: float = 30.0,
    calibration: CalibrationLike = None,
    dry_run: bool = False,
) -> Plan:
    """001: turn every cube 90 deg in place (``rotate_first``: ``"forward"``,
    ``"backward"`` or None), then stack them on the first one, each one cube
    higher than the last, coming down from ``clearance`` [mm] above each (as ``pick``)."""
    names = stack_names(cubes)
    _check_clearance(clearance)
    scene = live_scene(arm, scene, dry_run, "stack")

    def body(c: Context, s: State) -> State:
        for name in names if rotate_first else ():
            s = rotate(c, s, name, str(rotate_first))
        for below, name in itertools.pairwise(names):
            top = s.scene.cube(below)
            s = carry(
                c, s, name, top.position + np.array([0.0, 0.0, top.size]), f"on {below}", None
            )
        return s

    plan = plan_task(
        arm, scene, "stack " + " ".join(names), body, clearance=clearance, calibration=calibration
    )
    return _done(arm, plan, dry_run)
