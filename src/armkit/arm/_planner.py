"""Planning the motions ``Arm`` makes, in SI, from a ``Start``: a joint move, a path
followed by a streamer, waypoints stepped through, a gripper command. Each is solved
and checked whole (joint limits, the timing rule, the table, the base column and the
scene's objects at the poses and on the way there, the held cube with the links:
``scene.move_refusal``) and timed by the driver's own forecast; nothing moves."""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import replace

import numpy as np
from numpy.typing import NDArray

from .._errors import DeviceError, InputError, UnreachableError
from ..drivers import RunForecaster
from ..drivers.servo import JAWS_SPEED
from ..kinematics import fk, ik, pitch_follows, pitch_of
from ..model import MAX_MOVE_S, check_grip, check_joints, move_time
from ..motion import JointPath, NaiveStepping, Streamer, forecast_follow, plan_path
from ..scene import Scene, is_inside, move_refusal, settle
from ._plan import Plan, Step
from ._start import Start

F64 = NDArray[np.float64]
WAYPOINT_TOLERANCE = 1e-3  # [m] between the waypoints of approach and retreat


def plan_joints(
    start: Start,
    goal: F64,
    *,
    speed: float | None = None,
    duration: float | None = None,
    label: str = "move",
) -> Plan:
    """A joint move to ``goal`` [rad], shape (dof,), at ``speed`` (fraction of every
    joint's max velocity) or lasting ``duration`` [s], at most ``MAX_MOVE_S``.

    Raises:
        JointLimitError, InputError: a joint outside its limits, a bad speed or duration.
        UnreachableError: a link or the held cube would hit the table, the base column
            or an object, at the goal or on the way (naming which).
    """
    q = check_joints(start.model, goal)
    move_time(start.model, start.q, q, speed=speed, duration=duration, longest=MAX_MOVE_S)
    refuse(start, q[None, :])
    ahead = start.timer.forecast(start.q, q, duration=duration, speed=speed, motor_s=start.motor_s)
    step = Step(
        label, q=q, holding=_holding(start), speed=speed, duration=duration, seconds=ahead.seconds
    )
    return Plan(label, start, (step,), start.then(q=ahead.q, motor_s=ahead.motor_s))


def plan_follow(
    start: Start, points: F64, pitch: float | None, streamer: Streamer, label: str = "follow"
) -> Plan:
    """The tool through ``points`` [m], (N, 3), at ``pitch`` [rad] (None: see
    ``motion.plan_path``): a move onto the first, then ``streamer`` along the rest.

    Raises:
        PathError: naming the first point that cannot be followed.
        UnreachableError: as ``plan_joints``, anywhere along the path.
    """
    path = plan_path(start.kin, points, pitch, start.q)
    return _path_plan(start, path, streamer, label)


def plan_through(start: Start, points: F64, pitch: float | None, label: str) -> Plan:
    """Waypoints ``points`` [m], (N, 3), stepped through one by one (each waited for),
    1 mm apart at most between them (``approach``, ``retreat``)."""
    path = plan_path(start.kin, points, pitch, start.q, tolerance=WAYPOINT_TOLERANCE)
    return _path_plan(start, path, NaiveStepping(), label)


def _path_plan(start: Start, path: JointPath, streamer: Streamer, label: str) -> Plan:
    refuse(start, path.q)
    ahead = forecast_follow(start.timer, start.kin, start.q, path, streamer, start.motor_s)
    step = Step(
        label, q=path.q[-1].copy(), holding=_holding(start), path=path, streamer=streamer,
        kin=start.kin, seconds=ahead.seconds,
    )  # fmt: skip
    return Plan(label, start, (step,), start.then(q=ahead.q, motor_s=ahead.motor_s))


def plan_grip(start: Start, width: float, label: str = "grip") -> Plan:
    """The gripper to ``width`` [m]; a held cube or tool narrower than it by more than
    the margin is let go (``Held.released_by``, ``HeldTool.released_by``). A gripper that is only open or closed
    (the OWI's) takes its closed or its open width and nothing in between.

    Raises:
        InputError: a width outside the model's range, or between open and closed.
    """
    width = check_grip(start.model, width)
    g = start.model.gripper
    if g.kind == "timed" and min(abs(width - g.width_min), abs(width - g.width_max)) > 1e-12:
        lo, hi = g.width_min * 1000.0, g.width_max * 1000.0
        raise InputError(
            f"{start.model.name}'s gripper is only open or closed: grip {lo:g} closes it, "
            f"grip {hi:g} opens it; got {width * 1000.0:g} mm"
        )
    # a timed gripper runs unless its driver set it so itself (what it knows, not the
    # jaws' true opening); a servo gripper moves from where the jaws are
    before = start.grip if start.timer.moves == "timed" else start.opening
    held = start.held
    tool = None if start.tool is not None and start.tool.released_by(width) else start.tool
    if held is not None and not held.released_by(width):  # the jaws stop on the cube
        jaws = max(width, held.cube.size)
        seconds = start.timer.forecast_grip(before, jaws)
        step = Step(label, grip=width, holding=_holding(start), seconds=seconds)
        return Plan(label, start, (step,), start.then(grip=width, jaws=jaws, tool=tool))
    seconds = start.timer.forecast_grip(before, width)
    step = Step(label, grip=width, holding=_holding(start), seconds=seconds)
    if held is None:
        return Plan(label, start, (step,), start.then(grip=width, jaws=None, tool=tool))
    end = start.then(grip=width, jaws=None, held=None, scene=dropped(start), tool=tool)
    return Plan(label, start, (step,), end)


def dropped(start: Start) -> Scene | None:
    """``start``'s scene with the cube it holds where that cube comes to rest when the jaws
    let it go there (``scene.settle``: straight down onto what is under it, as the
    simulator's physics has it fall); None without a scene."""
    held, scene = start.held, start.scene
    if held is None or scene is None:
        return scene
    T = scene.T_world_base @ fk(start.kin, start.q) @ held.T_tool_object
    others = scene.without_cube(held.cube.name) if held.cube.name in scene.names() else scene
    rest = settle(others, held.cube, T).cube
    return replace(others, cubes=(*others.cubes, rest))


def refuse(start: Start, poses: F64) -> None:
    """Refuse (UnreachableError) a move from ``start`` through ``poses`` [rad], (K, dof),
    that is not clear (``scene.move_refusal``; from a pose already inside something, one
    that does not take the arm out)."""
    refused = move_refusal(start.kin, start.q, poses, start.scene, start.held, start.opening)
    if refused is not None:
        if start.timer.moves == "timed":  # a timed arm's angles are an estimate
            refused.args = (f"{refused}; if it is not really there: 'armkit rehome'",)
        raise refused


def inside(start: Start) -> bool:
    """Whether the arm at ``start`` is already in the table or an object."""
    return is_inside(start.kin, start.q, start.scene, start.held, start.opening) is not None


def plan_lift_out(start: Start, most: float = 0.15, label: str = "lift out") -> Plan:
    """The gripper straight up, at its pitch, by the least whole 5 mm (at most ``most``
    [m]) that leaves every link clear of the table and the scene's objects: the way out
    of where an interrupted job left the arm (``Arm.home`` takes it first).

    Raises:
        UnreachableError: no such lift, saying the way out that remains.
    """
    T = fk(start.kin, start.q)
    point, pitch = T[:3, 3], float(pitch_of(T))
    for rise in np.arange(0.005, most + 1e-9, 0.005):
        try:
            q = ik(start.kin, point + np.array([0.0, 0.0, rise]), pitch, start.q).q
        except UnreachableError:
            break
        if is_inside(start.kin, q, start.scene, start.held, start.opening) is None:
            n = max(2, round(rise / 0.002))
            line = point + np.linspace(0.0, rise, n)[:, None] * np.array([0.0, 0.0, 1.0])
            keep = None if pitch_follows(start.kin) else pitch
            return plan_through(start, line, keep, label)
    raise UnreachableError(
        f"the arm is in the table or an object and cannot be lifted straight out of it; "
        f"{_way_out(start)}",
        reason="collision",
    )


def _way_out(start: Start) -> str:
    """What gets an arm going again that cannot move out of where it is."""
    if start.timer.moves == "timed":
        return "its angles are an estimate: 'armkit rehome' drives each joint to its stop"
    name = start.scene.name if start.scene is not None else "NAME"
    return (
        f"a simulated arm: 'armkit scene reset {name}' puts it back at home; a real one: "
        "move it out by hand (torque off)"
    )


def _holding(start: Start) -> str | None:
    return None if start.held is None else start.held.cube.name


def plan_steps(
    start: Start,
    task: str,
    steps: Sequence[Step],
    *,
    end: Start | None = None,
    after: Scene | None = None,
    planning_time: float = 0.0,
) -> Plan:
    """A plan of ``steps`` solved and checked by a job's own planner (a task's grasps, a
    drawing's strokes), each timed here by the driver's forecasts. ``end``: the Start it
    leaves (its joints, grip and battery are worked out here; its held cube and scene as
    given: None, as at ``start``). A step sent at its time (``at``) keeps its ``seconds``."""
    at, timed = start, []
    for k, step in enumerate(steps):
        at, seconds = _forecast(at, step, _closing_on(steps, k, at))
        timed.append(replace(step, seconds=seconds))
    last = end or start
    done = at.then(held=last.held, scene=last.scene)
    return Plan(task, start, tuple(timed), done, after, planning_time)


def _closing_on(steps: Sequence[Step], k: int, at: Start) -> float:
    """The size [m] of the cube the gripper holds after step ``k`` (the one a closing
    grip stops on: the next step's ``holding``), or 0."""
    name = steps[k + 1].holding if k + 1 < len(steps) else None
    cubes = () if at.scene is None else at.scene.cubes
    held = [c.size for c in cubes if c.name == name]
    if at.held is not None and at.held.cube.name == name:
        held.append(at.held.cube.size)
    return max(held, default=0.0)


def _forecast(at: Start, step: Step, cube: float = 0.0) -> tuple[Start, float]:
    """Where ``step`` leaves the arm from ``at``, and how long it takes [s] (a grip
    closing on a cube of size ``cube`` [m] stops on it: the jaws stay open that far)."""
    if step.grip is not None:
        jaws = max(step.grip, cube) if cube > step.grip else None
        target = step.grip if jaws is None else jaws
        seconds = at.timer.forecast_grip(at.opening, target)
        if step.settle and at.timer.moves == "hobby":  # the arm waits for the jaws to get
            before = at.model.gripper.width_max if at.opening is None else at.opening
            seconds = max(seconds, abs(target - before) / JAWS_SPEED)  # there: not its driver
        return at.then(grip=step.grip, jaws=jaws), seconds
    if step.at is not None and step.q is not None:  # sent on time: its planner timed it
        return at.then(q=step.q), step.seconds
    if step.motor is not None:
        assert isinstance(at.timer, RunForecaster)  # planned by plan_motor_run
        ahead = at.timer.forecast_run(at.q, *step.motor, at.motor_s)
        return at.then(q=ahead.q, motor_s=ahead.motor_s), ahead.seconds
    if step.path is not None:
        kin = step.kin or at.kin
        streamer = step.streamer or NaiveStepping()
        ahead = forecast_follow(at.timer, kin, at.q, step.path, streamer, at.motor_s)
    elif step.q is not None:
        ahead = at.timer.forecast(
            at.q, step.q, duration=step.duration, speed=step.speed, motor_s=at.motor_s
        )
    else:
        return at, step.seconds
    return at.then(q=ahead.q, motor_s=ahead.motor_s), ahead.seconds


def plan_wait(start: Start, seconds: float, label: str = "wait") -> Plan:
    """Standing still for ``seconds`` [s] (InputError: not a number of seconds >= 0)."""
    if not (isinstance(seconds, int | float) and math.isfinite(seconds) and seconds >= 0):
        raise InputError(f"wait takes a number of seconds >= 0, got {seconds!r}")
    return Plan(label, start, (Step(label, seconds=float(seconds)),), start)


def plan_motor_run(start: Start, joint: str, direction: int, seconds: float) -> Plan:
    """Joint ``joint``'s motor run ``seconds`` [s] in ``direction`` (+1/-1), where the
    arm is on timed motors (the OWI-535), its angle as the unit's timing model advances it;
    checked for clearance as every move is.

    Raises:
        DeviceError: the arm's motors are not timed.  ShortMoveError: a run too short.
        UnreachableError: it would put a link into the table or an object.
    """
    timer = start.timer
    if not isinstance(timer, RunForecaster):
        raise DeviceError(
            f"the {start.model.name} has no timed motors to run ({start.timer.moves} moves): "
            "move its joints instead"
        )
    ahead = timer.forecast_run(start.q, joint, direction, seconds, start.motor_s)
    refuse(start, ahead.q[None, :])
    label = f"run {joint} {'+' if direction > 0 else '-'} {seconds:g} s"
    step = Step(label, motor=(joint, direction, seconds), seconds=ahead.seconds)
    return Plan(label, start, (step,), start.then(q=ahead.q, motor_s=ahead.motor_s))


def plan_light(start: Start, on: bool) -> Plan:
    """The arm's light on or off: the OWI-535's board has one (DeviceError elsewhere)."""
    if start.timer.moves != "timed":
        raise DeviceError(f"the {start.model.name} has no light")
    label = f"light {'on' if on else 'off'}"
    return Plan(label, start, (Step(label, light=bool(on)),), start)
