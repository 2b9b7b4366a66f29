"""The checker's arm: the model's kinematics and timing instead of a device.

It follows the script statement by statement, solving every target (reach,
joint limits, straight lines point by point) and checking every move's clearance
as ``Arm`` will (``scene.move_refusal``: the table, the base column and the
scene's objects where the tasks leave them), and timing every
motion with ``armkit.motion``, so a script is known good, and how long it
takes, before anything moves. An OWI-535 (timed motors) is timed as its driver
will run it instead: the runs ``armkit.drivers.timed.forecast_move`` plans with
the timing model a new unit starts with (``default_timing``), one joint at a
time, gravity, overshoot and battery included, and its straight lines through the
waypoints the driver will follow them by (``plan_path_runs``), the plan's distance
from the line noted on the step. The tasks (``pick``, ``place``, ...) are planned
whole by ``armkit.tasks`` from where the arm is, with the cubes where the tasks
before them leave them, and timed as ``tasks.run_plan`` carries them out.
"""

from __future__ import annotations

from collections.abc import Hashable, Iterator
from contextlib import contextmanager
from dataclasses import replace
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from .._errors import UnreachableError
from .._terminal import count
from ..drivers.timed import (
    TurnForecast,
    default_timing,
    forecast_move,
    forecast_run,
    grip_seconds,
    plan_path_runs,
)
from ..kinematics import fk, ik
from ..model import ArmModel, check_joints
from ..motion import line, plan_path, time_path, trapezoid
from ..scene import Held, Scene, move_refusal
from ._arm_now import ArmNow
from ._ast import Loc, Statement
from ._backend import Frame
from ._jobs import JOBS, called_with, job_function
from ._model_state import ArmState, cubes_key, gripped_to, held_after, obstacles
from ._plan import Plan, PlanStep
from ._resolve import UNKNOWN, JointPose, Point, Target

if TYPE_CHECKING:
    from ..tasks import Plan as TaskPlan

F64 = NDArray[np.float64]
GRIP_SPEED = 0.05  # gripper opening speed assumed for timing [m/s]
TOOL_ACCEL = 0.5  # tool acceleration of straight lines [m/s^2] (TimedStreaming's default)
LINE_SPACING = 0.002  # straight lines are checked every 2 mm [m]


class ModelArm:
    """A ``Backend`` that simulates the script on the model and builds the ``Plan``."""

    def __init__(
        self, model: ArmModel, now: ArmNow, objects: Scene | None, has_scene: bool = False
    ) -> None:
        self.model, self.hardware = model, now.hardware
        # the scene's boards, containers, ... (its cubes move); None: moves are checked
        # against the table alone, as ``Arm`` checks them without a scene
        self._fixed = replace(objects, cubes=()) if has_scene and objects is not None else None
        q = np.array(model.home if now.q is None else now.q, dtype=np.float64)
        held = now.held
        gripped = held if isinstance(held, Held) else None
        name = held.cube.name if isinstance(held, Held) else held
        self.state = ArmState(
            q, now.grip, held=name, objects=objects, gripped=gripped, motor_s=now.motor_s
        )
        self.plan = Plan(model.joint_names)
        self.time = 0.0  # sum of the known durations so far [s]
        # an OWI-535's timing: its unit's, else the one a new unit starts with; None: not one
        timed = "owi535" in model.drivers
        self.timing = (now.timing or default_timing(model)) if timed else None
        self._line, self._context, self._recording = 0, "", True

    def begin(self, stmt: Statement, frames: tuple[Frame, ...]) -> None:
        self._line = stmt.loc.line
        self._context = " ".join(
            f"{f.iteration}/{f.count}" if f.kind == "repeat" else f.name for f in frames
        )

    def here(self) -> JointPose | None:
        return None if self.state.q is None else JointPose(self.state.q.copy())

    def move(self, target: Target | None, straight: bool) -> None:
        q0 = self.state.q
        if target is None:
            self._step(None, None)
        elif straight and q0 is not None:
            self._line_to(q0, self._point(target))
        else:
            self._joint_move(q0, self._solve(target))

    def turn(self, joint: str, angle: float | None, relative: bool) -> None:
        q0 = self.state.q
        j = self.model.joint_index(joint)
        if angle is not None and not relative:  # its limits, before the pose is known
            at = self.model.home.copy()
            at[j] = angle
            check_joints(self.model, at)
        if angle is None or q0 is None:
            self._step(None, None)
            return
        q1 = q0.copy()
        q1[j] = q0[j] + angle if relative else angle
        self._check_move(q1)
        self._joint_move(q0, q1)

    def grip(self, width: float | None) -> None:
        took = None if width is None else self._grip_time(width)
        self.state = gripped_to(self.state, width, self.model)
        self._step(self.state.q, took)

    def home(self) -> None:
        q1 = self.model.home
        self._check_move(q1)
        self._joint_move(self.state.q, q1)

    def wait(self, seconds: float | None) -> None:
        self._step(self.state.q, seconds)

    def speed(self, value: float | None, tool: bool) -> None:
        if tool:
            self.state = replace(self.state, tool_speed=0.05 if value is None else value)
        else:
            self.state = replace(self.state, speed=1.0 if value is None else value)

    def light(self, on: bool) -> None:
        self.state = replace(self.state, light=on)
        self._step(self.state.q, 0.0)

    def run_motor(self, joint: str, direction: int, seconds: float | None) -> None:
        q0 = self.state.q
        if q0 is None or seconds is None:
            self._step(None, seconds)
            return
        j = self.model.joint_index(joint)
        if self.timing is not None:  # a timed arm's run, as its driver will estimate it
            ahead = forecast_run(self.timing, q0, j, direction, seconds, self.state.motor_s)
            self._check_move(ahead.q)  # a run is not a move the arm checks: the check does
            self._forecast(ahead)
            return
        q1 = q0.copy()
        limit = self.model.joints[j]
        q1[j] = float(
            np.clip(q0[j] + direction * limit.max_velocity * seconds, limit.lower, limit.upper)
        )
        self._check_move(q1)
        self._step(q1, seconds)

    def job(self, command: str, args: dict[str, object]) -> None:
        held = held_after(self.state.held, command, args)
        plan = self._plan_job(command, args)
        if plan is not None:  # planned whole, as it will be when it runs
            took = self._task_time(plan)
            self.state = replace(
                self.state, grip=None, held=held, objects=plan.rest, gripped=plan.held
            )
            self._step(plan.q_end, took, note=f"{command}: {count(len(plan.steps), 'step')}")
            return
        seed = self.model.home if self.state.q is None else self.state.q
        for name, value in args.items():
            if isinstance(value, np.ndarray):
                try:
                    ik(self._kin(), value, None, seed)
                except UnreachableError as exc:
                    raise UnreachableError(f"{command} {name}: {exc}", reason=exc.reason) from None
        self.state = replace(self.state, q=None, grip=None, held=held, objects=None, gripped=None)
        self._step(None, None)

    def _plan_job(self, command: str, args: dict[str, object]) -> TaskPlan | None:
        """The job planned from where the arm is, with the objects where the tasks so far
        leave them (TaskError if it cannot be done); None if it is not planned ahead or
        either is not known."""
        s = self.state
        if not JOBS[command].plans or s.q is None or s.objects is None or s.held is UNKNOWN:
            return None
        from ..tasks import Plan as TaskPlan
        from ..tasks import Start

        called = called_with(command, args, s.held)
        plan = job_function(command)(Start(self.model, s.q), s.objects, **called)
        assert isinstance(plan, TaskPlan)
        return plan

    def _task_time(self, plan: TaskPlan) -> float:
        """How long ``tasks.run_plan`` takes to carry ``plan`` out [s]: its joint moves at
        full speed (a timed arm's as its driver runs them), each gripper command between
        two waits for the arm to stand still: ``GRIP_S`` each on hardware, on the
        simulator until the gripper has moved."""
        from ..tasks import GRIP_S

        q, took = plan.q_start, 0.0
        for step in plan.steps:
            if step.q is not None:
                took += self._onto_time(q, step.q)
                q = step.q
            elif step.grip is not None:
                took += 2.0 * GRIP_S if self.hardware else self._grip_time(step.grip)
                self.state = replace(self.state, grip=step.grip)
        return took

    def snapshot(self) -> Hashable | None:
        s = self.state
        q = None if s.q is None else tuple(np.round(s.q, 9).tolist())
        objects = None if s.objects is None else cubes_key(s.objects)
        return q, s.grip, s.speed, s.tool_speed, s.light, repr(s.held), objects

    def elapsed(self) -> float:
        return self.time

    def skip(self, iterations: int, seconds: float, loc: Loc) -> None:
        note = f"x{iterations} more iterations, each as the last"
        if self._recording:
            step = PlanStep(loc.line, "", self.time, iterations * seconds, self.state.q, note)
            self.plan.steps.append(step)
        self.time += iterations * seconds
        self.plan.total += iterations * seconds

    def lose_track(self) -> None:
        """After a failed statement: where the arm is, and what it holds, is no longer known."""
        self.state = replace(self.state, q=None, held=UNKNOWN, gripped=None)

    @contextmanager
    def blind(self) -> Iterator[None]:
        saved = (self.state, self.time, self._recording)
        self.state = ArmState(None, None, held=UNKNOWN)
        self._recording = False
        try:
            yield
        finally:
            self.state, self.time, self._recording = saved

    # -- kinematics --------------------------------------------------------
    def _kin(self) -> ArmModel:
        g = self.state.grip
        return self.model if g is None else self.model.with_grip_width(g)

    def _solve(self, target: Target) -> F64:
        if isinstance(target, JointPose):
            q = target.q
        else:
            seed = self.model.home if self.state.q is None else self.state.q
            q = np.asarray(ik(self._kin(), target.xyz, target.pitch, seed).q, dtype=np.float64)
        self._check_move(q)
        return q

    def _point(self, target: Target) -> Point:
        if isinstance(target, Point):
            return target
        T = fk(self._kin(), target.q)
        return Point(np.asarray(T[:3, 3], dtype=np.float64), None)

    def _line_to(self, q0: F64, goal: Point) -> None:
        kin = self._kin()
        start = np.asarray(fk(kin, q0)[:3, 3], dtype=np.float64)
        if np.linalg.norm(goal.xyz - start) < 1e-9:
            self._step(q0, 0.0)
            return
        points = line(start, goal.xyz, LINE_SPACING)
        path = plan_path(kin, points, goal.pitch, q0)
        self._check_move(path.q[-1], path.q)
        if self.timing is not None:  # as the timed driver follows it: waypoints, not a stream
            runs = plan_path_runs(self.timing, kin, q0, self.state.motor_s, path.q, path.points)
            self.state = replace(self.state, motor_s=runs.motor_s)
            self._step(runs.q, runs.seconds, note=f"timed motors: {runs.describe()}")
            return
        took = time_path(self.model, path, self.state.tool_speed, TOOL_ACCEL).duration
        onto = self._onto_time(q0, path.q[0])  # ``follow``'s move onto its start
        self._step(path.q[-1].copy(), onto + took)

    def _check_move(self, q: F64, path: F64 | None = None) -> None:
        """Joint limits at ``q`` [rad], and clearance as ``Arm`` checks it
        (``scene.move_refusal``): at the poses ``path`` (K, dof) [rad] (default: q) and on
        the way there from where the arm is, when that is known."""
        check_joints(self.model, q)
        poses = q[None, :] if path is None else path
        s = self.state
        refused = move_refusal(self._kin(), s.q, poses, self._obstacles(), s.gripped, s.grip)
        if refused is not None:
            raise refused

    def _obstacles(self) -> Scene | None:
        """What moves are checked against, as ``Arm`` will check them: the script's scene
        with its cubes where the tasks leave them (a held one left out); its cubes left
        out where that is not known (after a ``search``); None if it names no scene."""
        return obstacles(self.state, self._fixed)

    # -- timing ----------------------------------------------------------
    def _joint_move(self, q0: F64 | None, q1: F64) -> None:
        """Step by a joint move q0 -> q1 [rad]: a timed arm as its driver runs it (and
        where its estimate ends), any other arm's trapezoid at the script's speed."""
        if q0 is None:
            self._step(q1, None)
        elif self.timing is not None:
            self._forecast(forecast_move(self.timing, self.model, q0, q1, self.state.motor_s))
        else:
            self._step(q1, trapezoid(self.model, q0, q1, self.state.speed).duration)

    def _onto_time(self, q0: F64, q1: F64) -> float:
        """How long a full-speed joint move q0 -> q1 [rad] takes [s] (the battery count
        of a timed arm goes on)."""
        if self.timing is None:
            return trapezoid(self.model, q0, q1, 1.0).duration
        ahead = forecast_move(self.timing, self.model, q0, q1, self.state.motor_s)
        self.state = replace(self.state, motor_s=ahead.motor_s)
        return ahead.seconds

    def _grip_time(self, width: float) -> float:
        """How long opening the gripper to ``width`` [m] takes [s]."""
        before = self.state.grip
        if self.timing is not None:
            return grip_seconds(self.timing, self.model, before, width)
        return (
            abs(width - (self.model.gripper.width_max if before is None else before)) / GRIP_SPEED
        )

    def _forecast(self, ahead: TurnForecast) -> None:
        """Step to where a timed arm's driver will estimate it after ``ahead``'s runs."""
        self.state = replace(self.state, motor_s=ahead.motor_s)
        self._step(ahead.q, ahead.seconds)

    def _step(self, q: F64 | None, duration: float | None, note: str = "") -> None:
        self.state = replace(self.state, q=q)
        if not self._recording:
            return
        step = PlanStep(self._line, self._context, self.time, duration, q, note)
        self.plan.steps.append(step)
        if duration is None:
            self.plan.unknown += 1
        else:
            self.plan.total += duration
            self.time += duration
