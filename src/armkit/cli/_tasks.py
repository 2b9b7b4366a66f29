"""Task commands on a scene: pick, place, move-item, rotate-cube, stack (mm, deg).

Each task is planned whole before anything moves; ``--dry-run`` prints the plan.
"""

from __future__ import annotations

import argparse
import sys
from typing import Any

from ..jobs import job_spec
from ._jobs import add_job, job_arguments
from ._watch import watched_arm

TASKS = ("pick", "place", "move-item", "rotate-cube", "stack")
REACH_ARC = (30.0, 120.0, 5.0)  # [deg] reach's scan: from, to, step (002's base servo angles)
NEAR, FAR = "4", "30 cm"  # the sensor's range (armkit.sensing.RANGE), as a result says it


def add_commands(sub: argparse._SubParsersAction[Any]) -> None:
    """Add pick, place, move-item, rotate-cube, stack, search and reach (from their job
    specs, ``armkit.jobs.JOBS``)."""
    for name in TASKS:
        add_job(sub, name, _run)
    add_job(sub, "search", _search)
    add_job(sub, "reach", _reach)


def _reach(args: argparse.Namespace) -> int:
    from .. import tasks
    from ._scene import scene_of

    scene = scene_of(args)
    start, stop, step = REACH_ARC
    with watched_arm(args, scene) as arm:
        result = tasks.reach(arm, scene, **job_arguments(args), start=start, stop=stop, step=step)
        if not result.found:
            todo = f"hold the hand out on that arc within {FAR} of the sensor, or give --height the hand's height"  # fmt: skip
            return _nothing(args, arm, result, f"no hand found: scanned {_arc(*REACH_ARC)} at {args.height:g} mm height", todo)  # fmt: skip
        print("\n".join(result.lines()))
    return 0


def _search(args: argparse.Namespace) -> int:
    from .. import tasks
    from ._scene import scene_of

    scene = scene_of(args)
    with watched_arm(args, scene) as arm:
        result = tasks.search(arm, scene, **job_arguments(args))
        if not result.found:
            arc = _arc(args.start, args.stop, args.step)
            near, far = (round(b) for b in result.band)
            todo = (
                f"widen --from/--to (0..180), lower --step, or put the object {near}..{far} mm "
                f"from the base on that arc (nearer than {near} mm it is inside the sensor's "
                f"{NEAR} cm minimum)"
            )
            return _nothing(args, arm, result, f"nothing found: scanned {arc}", todo)
        print("\n".join(result.lines()))
    return 0


def _arc(start: float, stop: float, step: float) -> str:
    """A scan's arc as its options are written: 'from 100 to 120 deg every 5 deg (...)'."""
    return f"from {start:g} to {stop:g} deg every {step:g} deg (90 is straight ahead)"


def _nothing(args: argparse.Namespace, arm: Any, result: Any, scanned: str, todo: str) -> int:
    """A scan that found nothing: the task's lines but its last (its own 'nothing
    within 30 cm'), then one line on stderr: what was scanned, what to try; status 1."""

    print("\n".join(result.lines()[:-1]))
    sys.stdout.flush()  # the result, then the line that ends it
    said = f"armkit: {scanned}, the sensor seeing {NEAR}..{FAR}; {todo}"
    if arm.moves == "timed":  # the OWI scanned where it thinks it was
        said += (
            f"; the {arm.model.name}'s angles are only estimated from motor run times: re-home "
            f"it and scan again: armkit --arm {args.arm} --driver {args.driver_name} rehome"
        )
    print(said, file=sys.stderr)
    return 1


def _run(args: argparse.Namespace) -> int:
    from .. import tasks
    from ._scene import scene_of

    scene = scene_of(args)
    with watched_arm(args, scene) as arm:
        plan: Any = job_spec(args.job).call(arm, scene, **job_arguments(args), dry_run=True)
        if args.dry_run:
            print(plan)
            return 0
        print(plan.lines()[0])
        tasks.run_verified(
            arm, plan, say=lambda k, step: print(f"{k:4d}/{len(plan.steps)}  {step.label}")
        )
        for line in plan.lines()[len(plan.steps) + 1 :]:
            print(line)
    return 0
