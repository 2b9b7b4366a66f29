"""The check's side of the plans: folded, each statement planned from where the plan
before it ends (its joints, grip, held cube, the objects at rest, the battery), its
time added up and written into the dry run's timetable (``_timetable.Timetable``). A refused
statement changes nothing, so the next one is planned from the same place."""

from __future__ import annotations

from collections.abc import Hashable, Iterator
from contextlib import contextmanager

import numpy as np
from numpy.typing import NDArray

from .._terminal import count
from ..arm import Plan, Start
from ..drivers.timed import TimingModel, plan_path_runs
from ..scene import Scene
from ._ast import Loc, Statement
from ._backend import Frame
from ._job_plans import JobPlan, task_scene
from ._planning import Pace
from ._timetable import Timetable, TimetableRow

F64 = NDArray[np.float64]


class Fold:
    """A ``Side`` that folds the plans from ``start`` (None: not known), with the tasks
    planned on ``scene`` (the script's, or the empty table) where ``start`` has none."""

    def __init__(self, start: Start | None, scene: Scene, joint_names: tuple[str, ...]) -> None:
        self.at, self.scene = start, scene
        self.table = Timetable(joint_names)
        self.time = 0.0  # the known durations so far [s]
        self._line, self._context, self._recording = 0, "", True

    def begin(self, stmt: Statement, frames: tuple[Frame, ...]) -> None:
        self._line = stmt.loc.line
        self._context = " ".join(
            f"{f.iteration}/{f.count}" if f.kind == "repeat" else f.name for f in frames
        )

    def start(self) -> Start | None:
        return self.at

    def task_scene(self, start: Start) -> Scene:
        return task_scene(start, self.scene)

    def take(self, plan: Plan, note: str = "") -> None:
        self.at = plan.end
        self._step(plan.end.q, plan.seconds, note or _runs_note(plan))

    def take_job(self, command: str, job: JobPlan) -> None:
        if job.plan is None:  # what it does is known only when it runs
            self.at = None
            self._step(None, None)
            return
        self.take(job.plan, f"{command}: {count(len(job.plan.steps), 'step')}")

    def unknown(self, seconds: float | None) -> None:
        self._step(None if self.at is None else self.at.q, seconds)

    def snapshot(self, pace: Pace) -> Hashable | None:
        """The state to compare iterations by (None: not known)."""
        s = self.at
        if s is None:
            return None
        held = None if s.held is None else s.held.cube.name
        cubes = () if s.scene is None else _cubes(s.scene)
        q = tuple(np.round(s.q, 9).tolist())
        return q, s.grip, s.jaws, round(s.motor_s, 9), held, cubes, pace

    def elapsed(self) -> float:
        return self.time

    def skip(self, iterations: int, seconds: float, loc: Loc) -> None:
        note = f"x{iterations} more iterations, each as the last"
        q = None if self.at is None else self.at.q
        if self._recording:
            self.table.rows.append(
                TimetableRow(loc.line, "", self.time, iterations * seconds, q, note)
            )
        self.time += iterations * seconds
        self.table.total += iterations * seconds

    @contextmanager
    def blind(self) -> Iterator[None]:
        """Statements walked without a known arm (a body that does not run as written):
        nothing planned, nothing recorded."""
        saved = (self.at, self.time, self._recording)
        self.at, self._recording = None, False
        try:
            yield
        finally:
            self.at, self.time, self._recording = saved

    def _step(self, q: F64 | None, duration: float | None, note: str = "") -> None:
        if not self._recording:
            return
        step = TimetableRow(self._line, self._context, self.time, duration, q, note)
        self.table.rows.append(step)
        if duration is None:
            self.table.unknown += 1
        else:
            self.table.total += duration
            self.time += duration


def _cubes(scene: Scene) -> Hashable:
    """Where the scene's cubes are, to compare states (to 1 nm)."""
    return tuple((c.name, tuple(np.round(c.T, 9).ravel().tolist())) for c in scene.cubes)


def _runs_note(plan: Plan) -> str:
    """How a timed arm's driver follows a path (a straight line) with one-joint runs:
    ``timed motors: 5 runs through 4 waypoints, up to 24.7 mm off the path`` ('' for
    any other plan)."""
    timing = getattr(plan.start.timer, "timing", None)
    paths = [s for s in plan.steps if s.path is not None]
    if not isinstance(timing, TimingModel) or len(paths) != 1:
        return ""
    path, start = paths[0].path, plan.start
    assert path is not None
    kin = paths[0].kin or start.kin
    runs = plan_path_runs(timing, kin, start.q, start.motor_s, path.q, path.points)
    return f"timed motors: {runs.describe()}"
