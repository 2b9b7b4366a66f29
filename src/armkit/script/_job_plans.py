"""A script's job planned from a ``Start``, and how it is carried out: the same plan for
``armkit check`` (its time, where it leaves the arm and the objects) and ``armkit run``
(which plans it from the arm as it is, then carries it out with the job's own watching:
a task's outcome on the simulator, a drawing's pen trace, a piece's listener)."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING

from ..arm import Plan, Start
from ..scene import Scene
from ._jobs import JOBS, called_with

if TYPE_CHECKING:
    from ..arm import Arm

Carry = Callable[["Arm"], object]


@dataclass(frozen=True)
class JobPlan:
    """A job planned whole.

    Attributes:
        plan: its motion, timed by the driver's forecasts; ``plan.end`` is where it
            leaves the arm and the objects (None: known only when it runs: a job whose
            spec has no planner).
        carry: carries it out on an arm that is where ``plan`` starts.
    """

    plan: Plan | None
    carry: Carry


def task_scene(start: Start, scene: Scene) -> Scene:
    """The scene a task plans with from ``start``: its objects at rest, a held cube where
    it was picked from (``scene``, the script's, where the start knows none)."""
    objects = start.scene if start.scene is not None else scene
    held = start.held
    if held is None or held.cube.name in {c.name for c in objects.cubes}:
        return objects
    return replace(objects, cubes=(*objects.cubes, held.cube))


def plan_job(start: Start, scene: Scene, command: str, args: dict[str, object]) -> JobPlan:
    """``command`` with the script's ``args`` planned from ``start`` on ``scene`` (the
    objects as the script's tasks so far leave them).

    Raises:
        ArmkitError: the job refuses (unreachable, a collision, a bad argument).
    """
    held = None if start.held is None else start.held.cube.name
    called = called_with(command, args, held)
    spec = JOBS[command]
    planner = _task(command) if spec.plans else PLANNERS.get(command, _unplanned(command))
    return planner(start, scene, called)


def _task(command: str) -> Callable[[Start, Scene, dict[str, object]], JobPlan]:
    def planned(start: Start, scene: Scene, called: dict[str, object]) -> JobPlan:
        from ..tasks import run_verified

        plan = JOBS[command].call(start, scene, **called)
        assert isinstance(plan, Plan)
        return JobPlan(plan, lambda arm: run_verified(arm, plan))

    return planned


def _draw(start: Start, scene: Scene, called: dict[str, object]) -> JobPlan:
    from ..drawing import plan_draw, run_job

    job = plan_draw(start, scene, **called)  # type: ignore[arg-type]
    return JobPlan(job.motion, lambda arm: run_job(arm, job))


def _play(start: Start, scene: Scene, called: dict[str, object]) -> JobPlan:
    from ..music import perform, performance_plan, plan_play

    perf = plan_play(start, scene, script=True, **called)  # type: ignore[arg-type]
    plan = performance_plan(start, perf, scene)
    return JobPlan(plan, lambda arm: perform(arm, scene, perf))


def _search(start: Start, scene: Scene, called: dict[str, object]) -> JobPlan:
    from ..tasks import plan_search, search

    plan = plan_search(start, scene, **called)  # type: ignore[arg-type]
    return JobPlan(plan, lambda arm: search(arm, scene, **called))  # type: ignore[arg-type]


def _unplanned(command: str) -> Callable[[Start, Scene, dict[str, object]], JobPlan]:
    """A job whose spec gives only its function (``JobSpec.call(arm, scene, **args)``, no
    planner from a Start): what it does is known only when it runs, so the check leaves
    its time, and the arm after it, to the run."""

    def planned(start: Start, scene: Scene, called: dict[str, object]) -> JobPlan:
        call = JOBS[command].call
        return JobPlan(None, lambda arm: call(arm, scene, **called))

    return planned


# the jobs planned by their own planner (the tasks, ``JobSpec.plans``, by ``_task``)
PLANNERS: dict[str, Callable[[Start, Scene, dict[str, object]], JobPlan]] = {
    "search": _search,
    "draw": _draw,
    "play": _play,
}
