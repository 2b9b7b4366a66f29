"""Run a checked script on an ``Arm``: each statement planned as the check plans it, but
from the arm as it reads it now, then carried out by ``Arm.run`` (a job by its own
carrying out), so it runs on every driver. A failure names the line and the repeat
iteration."""

from __future__ import annotations

from collections.abc import Callable, Hashable
from contextlib import AbstractContextManager, nullcontext
from pathlib import Path

from .._errors import ScriptError
from ..arm import Arm, Plan, Start
from ..scene import Scene
from ..tasks import held_now, obstacles_now
from ._ast import Loc, Source, Statement
from ._backend import Frame
from ._check import CheckResult, check_source, looped
from ._job_plans import JobPlan, task_scene
from ._now import start_of
from ._planning import Pace
from ._resolve import Resolver, SceneInfo, job_scene
from ._stepper import Stepper
from ._walk import Walker

StepHook = Callable[[Statement, tuple[Frame, ...]], None]


class Carry:
    """A ``Side`` that carries each plan out on ``arm``; with a script's scene, the arm's
    moves are checked against its objects where they are now (a simulated arm's) or
    where the tasks left them (hardware)."""

    def __init__(self, arm: Arm, scene: SceneInfo | None, on_step: StepHook | None = None):
        self.arm, self.info, self.on_step = arm, scene, on_step
        if arm.held is None:  # a simulated arm's, from its physics
            arm.held = held_now(arm)
        self.objects: Scene | None = None  # the scene as the last task left it
        self._refresh_scene()

    def begin(self, stmt: Statement, frames: tuple[Frame, ...]) -> None:
        if self.on_step is not None:
            self.on_step(stmt, frames)

    def start(self) -> Start:
        return start_of(self.arm, None if self.info is None else self.scene_now())

    def task_scene(self, start: Start) -> Scene:
        """The scene the next task plans with: the objects where ``start`` has them (a
        simulated arm's where they are now), a held cube where it was picked from."""
        base = self.scene_now()
        if base is None:
            raise ScriptError(f"the scene {self.info and self.info.label} could not be loaded")
        return task_scene(start, base)

    def take(self, plan: Plan) -> None:
        self.arm.run(plan)

    def take_job(self, command: str, job: JobPlan) -> None:
        job.carry(self.arm)
        if job.plan is not None:  # on hardware the next task plans with the cubes moved
            self.objects = job.plan.rest
        self._refresh_scene()

    def unknown(self, seconds: float | None) -> None:
        raise ScriptError("a value of this statement is not known when it runs")

    def snapshot(self, pace: Pace) -> Hashable | None:
        return None  # every iteration runs

    def elapsed(self) -> float:
        return 0.0

    def skip(self, iterations: int, seconds: float, loc: Loc) -> None:
        """Never called: the snapshot is None, so every iteration runs."""

    def blind(self) -> AbstractContextManager[None]:
        return nullcontext()

    def scene_now(self) -> Scene | None:
        """The scene as the last task left it, else the script's (a script that names
        none works on the empty table; None: it cannot be loaded)."""
        return self.objects if self.objects is not None else job_scene(self.info)

    def _refresh_scene(self) -> None:
        """Check the arm's moves against the objects where they are now (a simulated
        arm's) or where the tasks left them (a held cube left out)."""
        scene = self.scene_now()
        if self.info is not None and scene is not None:  # else: as the arm was opened
            held = None if self.arm.held is None else self.arm.held.cube.name
            self.arm.scene = obstacles_now(
                self.arm, scene if held is None else scene.without_cube(held)
            )


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
        source, model=arm.model, scene=scene, arm=arm,
        repeat=repeat, base_dir=base_dir,
    )  # fmt: skip
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
    side = Carry(arm, result.scene, on_step)
    walker = Walker(resolver, Stepper(side), source.name, checking=False)
    try:
        walker.walk(looped(result.program.statements, repeat))
    except BaseException:
        arm.stop()
        raise
