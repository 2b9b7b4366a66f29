"""The one thing a walker drives: each statement's motion planned from a ``Start``
(``_planning``, ``_job_plans``) and handed to a ``Side``, which either folds it (the
check: the next statement starts where the plan ends) or carries it out (the run: the
next statement starts from the arm as it reads it). So check and run cannot disagree
on what a statement does: they make the same plan."""

from __future__ import annotations

from collections.abc import Callable, Hashable, Iterator
from contextlib import AbstractContextManager, contextmanager
from typing import Protocol

from ..arm import Plan, Start, plan_grip, plan_light, plan_motor_run, plan_wait
from ..scene import Scene
from ._ast import Loc, Statement
from ._backend import Frame
from ._job_plans import JobPlan, plan_job
from ._planning import Pace, plan_home, plan_move, plan_turn
from ._resolve import JointPose, Target


class Side(Protocol):
    """What is done with the plans: folded (check) or carried out (run)."""

    def begin(self, stmt: Statement, frames: tuple[Frame, ...]) -> None: ...
    def start(self) -> Start | None: ...
    def task_scene(self, start: Start) -> Scene: ...
    def take(self, plan: Plan) -> None: ...
    def take_job(self, command: str, job: JobPlan) -> None: ...
    def unknown(self, seconds: float | None) -> None: ...
    def snapshot(self, pace: Pace) -> Hashable | None: ...
    def elapsed(self) -> float: ...
    def skip(self, iterations: int, seconds: float, loc: Loc) -> None: ...
    def blind(self) -> AbstractContextManager[None]: ...


class Stepper:
    """A walker's backend (``_backend.Backend``): plans each motion from ``side.start()``
    at the script's pace and gives the plan to ``side``; every quantity in SI. A value
    or a start not known before the script runs (a procedure checked with unknown
    arguments) plans nothing: the side notes a step of unknown time."""

    def __init__(self, side: Side) -> None:
        self.side = side
        self.pace = Pace()

    def begin(self, stmt: Statement, frames: tuple[Frame, ...]) -> None:
        self.side.begin(stmt, frames)

    def here(self) -> JointPose | None:
        start = self.side.start()
        return None if start is None else JointPose(start.q.copy())

    def move(self, target: Target | None, straight: bool) -> None:
        if target is not None:
            self._plan(lambda s: plan_move(s, target, straight, self.pace))
        else:
            self.side.unknown(None)

    def turn(self, joint: str, angle: float | None, relative: bool) -> None:
        if angle is not None:
            self._plan(lambda s: plan_turn(s, joint, angle, relative, self.pace))
        else:
            self.side.unknown(None)

    def grip(self, width: float | None) -> None:
        if width is not None:
            self._plan(lambda s: plan_grip(s, width))
        else:
            self.side.unknown(None)

    def home(self) -> None:
        self._plan(lambda s: plan_home(s, self.pace))

    def wait(self, seconds: float | None) -> None:
        if seconds is not None:
            self._plan(lambda s: plan_wait(s, seconds))
        else:
            self.side.unknown(None)

    def speed(self, value: float | None, tool: bool) -> None:
        if tool:
            self.pace = Pace(self.pace.fraction, Pace().tool_speed if value is None else value)
        else:
            self.pace = Pace(value, self.pace.tool_speed)

    def light(self, on: bool) -> None:
        self._plan(lambda s: plan_light(s, on))

    def run_motor(self, joint: str, direction: int, seconds: float | None) -> None:
        if seconds is not None:
            self._plan(lambda s: plan_motor_run(s, joint, direction, seconds))
        else:
            self.side.unknown(None)

    def job(self, command: str, args: dict[str, object]) -> None:
        start = self.side.start()
        if start is None or any(v is None for v in args.values()):
            self.side.unknown(None)
            return
        job = plan_job(start, self.side.task_scene(start), command, args)
        self.side.take_job(command, job)

    def snapshot(self) -> Hashable | None:
        return self.side.snapshot(self.pace)

    def elapsed(self) -> float:
        return self.side.elapsed()

    def skip(self, iterations: int, seconds: float, loc: Loc) -> None:
        self.side.skip(iterations, seconds, loc)

    @contextmanager
    def blind(self) -> Iterator[None]:
        """Statements that do not run as written: the side plans nothing, and the pace
        they set is not kept."""
        pace = self.pace
        try:
            with self.side.blind():
                yield
        finally:
            self.pace = pace

    def lose_track(self) -> None:
        """After a refused statement: nothing changed (a refusal moves nothing), so the
        next one starts where this one would have."""

    def _plan(self, planner: Callable[[Start], Plan]) -> None:
        start = self.side.start()
        if start is None:
            self.side.unknown(None)
        else:
            self.side.take(planner(start))
