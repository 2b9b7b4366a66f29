"""Run a checked script on an ``Arm``: every statement through the public ``Arm``
API (``move_to``, ``move_joints``, ``follow``, ``turn_to``, ``grip``, ``home``),
so it runs on every driver. A failure names the line and the repeat iteration."""

from __future__ import annotations

import math
from collections.abc import Callable, Hashable
from contextlib import AbstractContextManager, nullcontext
from pathlib import Path
from typing import TypeVar

import numpy as np

from .._errors import ScriptError
from ..arm import Arm
from ..kinematics import fk
from ..motion import TimedStreaming, line
from ..scene import Scene
from ..tasks import Plan, held_now, obstacles_now
from ._arm_now import ArmNow
from ._ast import Loc, Source, Statement
from ._backend import Frame
from ._check import CheckResult, check_source, looped
from ._jobs import called_with, job_function
from ._model_arm import LINE_SPACING
from ._resolve import JointPose, Point, Resolver, SceneInfo, Target, job_scene
from ._walk import Walker

T = TypeVar("T")
StepHook = Callable[[Statement, tuple[Frame, ...]], None]


class ArmBackend:
    """A ``Backend`` that moves a real (or simulated) arm; with a script's scene, the arm's
    moves are checked against its objects (where the tasks leave them)."""

    def __init__(self, arm: Arm, scene: SceneInfo | None, on_step: StepHook | None = None):
        self.arm, self.scene, self.on_step = arm, scene, on_step
        self.fraction: float | None = None  # joint moves: fraction of max speed (None: 1)
        self.tool_speed = TimedStreaming().speed  # straight lines [m/s]
        self.grip_width: float | None = None
        if arm.held is None:  # a simulated arm's, from its physics
            arm.held = held_now(arm)
        self.objects: Scene | None = None  # the scene as the last task left it
        self._refresh_scene()

    def begin(self, stmt: Statement, frames: tuple[Frame, ...]) -> None:
        if self.on_step is not None:
            self.on_step(stmt, frames)

    def here(self) -> JointPose | None:
        return JointPose(self.arm.read())

    def move(self, target: Target | None, straight: bool) -> None:
        if target is None:
            raise ScriptError("the target is not known when this statement runs")
        goal = target
        if straight:
            self._line(goal)
        elif isinstance(goal, Point):
            x, y, z = (float(v) * 1000.0 for v in goal.xyz)
            pitch = None if goal.pitch is None else math.degrees(goal.pitch)
            self.arm.move_to(x, y, z, pitch, speed=self.fraction)
        else:
            self.arm.move_joints([math.degrees(a) for a in goal.q], speed=self.fraction)

    def turn(self, joint: str, angle: float | None, relative: bool) -> None:
        deg = math.degrees(_known(angle, "the angle"))
        if relative:
            self.arm.turn_by(joint, deg, speed=self.fraction)
        else:
            self.arm.turn_to(joint, deg, speed=self.fraction)

    def grip(self, width: float | None) -> None:
        w, held = _known(width, "the width"), self.arm.held
        self.arm.grip(w * 1000.0)
        self.grip_width = w
        if held is not None and self.arm.held is None:  # ``Arm.grip`` let it go
            self.objects = None  # dropped where it was: not known where
            self._refresh_scene()

    def home(self) -> None:
        self.arm.home(speed=self.fraction)

    def wait(self, seconds: float | None) -> None:
        self.arm.clock.sleep(_known(seconds, "the time"))

    def speed(self, value: float | None, tool: bool) -> None:
        if tool:
            self.tool_speed = _known(value, "the speed")
        else:
            self.fraction = _known(value, "the speed")

    def light(self, on: bool) -> None:
        self.arm.set_light(on)

    def run_motor(self, joint: str, direction: int, seconds: float | None) -> None:
        self.arm.run_motor(joint, direction, _known(seconds, "the time"))

    def job(self, command: str, args: dict[str, object]) -> None:
        done = job_function(command)(
            self.arm, self._scene(), **called_with(command, args, self.held)
        )
        if isinstance(done, Plan):  # on hardware the next task plans with the cubes moved
            self.objects = done.rest
        self._refresh_scene()

    @property
    def held(self) -> str | None:
        """The cube in the gripper (a ``pick`` job's, until ``place``; ``Arm.held``)."""
        return None if self.arm.held is None else self.arm.held.cube.name

    def _refresh_scene(self) -> None:
        """Check the arm's moves against the objects where they are now (a simulated
        arm's) or where the tasks left them (a held cube left out)."""
        scene = self.scene_now()
        if self.scene is not None and scene is not None:  # else: as the arm was opened
            held = self.held
            self.arm.scene = obstacles_now(
                self.arm, scene if held is None else scene.without_cube(held)
            )

    def _scene(self) -> Scene:
        scene = self.scene_now()
        if scene is None:
            raise ScriptError(f"the scene {self.scene and self.scene.label} could not be loaded")
        return scene

    def scene_now(self) -> Scene | None:
        """The scene as the last task left it, else the script's (a script that names
        none works on the empty table; None: it cannot be loaded). A simulated arm's
        tasks see its objects live (``objects_on``)."""
        return self.objects if self.objects is not None else job_scene(self.scene)

    def snapshot(self) -> Hashable | None:
        return None

    def elapsed(self) -> float:
        return 0.0

    def skip(self, iterations: int, seconds: float, loc: Loc) -> None:
        """Never called: the runner's snapshot is None, so every iteration runs."""

    def blind(self) -> AbstractContextManager[None]:
        return nullcontext()

    def lose_track(self) -> None:
        """Never called: a failure stops the run."""

    def _line(self, target: Target) -> None:
        kin = (
            self.arm.model
            if self.grip_width is None
            else self.arm.model.with_grip_width(self.grip_width)
        )
        start = np.asarray(fk(kin, self.arm.read())[:3, 3], dtype=np.float64)
        if isinstance(target, Point):
            goal, pitch = target.xyz, target.pitch
        else:
            goal, pitch = np.asarray(fk(kin, target.q)[:3, 3], dtype=np.float64), None
        if np.linalg.norm(goal - start) < 1e-9:
            return
        points = line(start, goal, LINE_SPACING) * 1000.0
        pitch_deg = None if pitch is None else math.degrees(pitch)
        self.arm.follow(points, pitch_deg, streamer=TimedStreaming(speed=self.tool_speed))


def _known(value: T | None, what: str) -> T:
    if value is None:  # the check resolves every value before anything runs
        raise ScriptError(f"{what} is not known when this statement runs")
    return value


def run_source(
    arm: Arm,
    source: Source,
    *,
    repeat: int = 1,
    scene: SceneInfo | None = None,
    base_dir: Path | None = None,
    on_step: StepHook | None = None,
) -> CheckResult:
    """Check ``source`` whole for ``arm`` from where it is now, then run it.

    Raises:
        ScriptCheckError: the check failed (every problem listed); nothing moved.
        ScriptRunError: a statement failed while running (its line and iteration named);
            the arm is stopped.
    """
    result = check_source(
        source,
        model=arm.model,
        scene=scene,
        now=ArmNow.of(arm),
        repeat=repeat,
        base_dir=base_dir,
    )
    result.raise_if_failed()
    run_checked(arm, result, repeat=repeat, base_dir=base_dir, on_step=on_step)
    return result


def run_checked(
    arm: Arm,
    result: CheckResult,
    *,
    repeat: int = 1,
    base_dir: Path | None = None,
    on_step: StepHook | None = None,
) -> None:
    """Run a script that passed its check (``result.ok``) on ``arm``; the arm is
    stopped if anything goes wrong (an error or Ctrl-C)."""
    result.raise_if_failed()
    source = result.program.source
    resolver = Resolver(arm.model, result.scene, base_dir or Path(source.name).parent)
    walker = Walker(resolver, ArmBackend(arm, result.scene, on_step), source.name, checking=False)
    statements = looped(result.program.statements, repeat)
    try:
        walker.walk(statements)
    except BaseException:
        arm.stop()
        raise
