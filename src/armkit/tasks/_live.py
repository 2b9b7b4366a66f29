"""Tasks on a simulated arm: the scene's physics attached to the arm's World so the
objects move with the gripper, planning from where they really are, and every run
checked against its plan (a miss, a drop or a tip stops the task and names the step;
each cube must end within 1 mm and 1 deg of where the plan puts it, or within the
tolerance an open-loop arm's model file gives: ``armkit.tasks._precision``).

On real hardware (``arm.world`` is None) nothing is attached and nothing checked.
"""

from __future__ import annotations

import math
import weakref
from collections.abc import Callable
from typing import TYPE_CHECKING

from .._errors import ArmkitError, InputError
from .._inputs import shown
from ..arm import Start
from ..scene import Held, Scene, ScenePhysics, rest_scene
from ._plan import Plan, Step, TaskError, cube_text, pose_error
from ._precision import Precision, precision_of

if TYPE_CHECKING:
    from ..arm import Arm
BAD = ("missed", "dropped", "tipped")
_ATTACHED: weakref.WeakKeyDictionary[object, tuple[ScenePhysics, Callable[[], None]]] = (
    weakref.WeakKeyDictionary()
)


class TaskFailed(ArmkitError):
    """A task ran on a simulated arm and the objects did not do what the plan expected
    (the jaws missed a cube, a cube fell or tipped, or ended off its place): the task
    stopped there.

    Attributes:
        step: the label of the step where it went wrong.  detail: what happened.
    """

    def __init__(self, message: str, *, step: str, detail: str) -> None:
        super().__init__(message)
        self.step, self.detail = step, detail


def attach_scene(
    arm: Arm, scene: Scene, physics: ScenePhysics | None = None
) -> ScenePhysics | None:
    """The scene's physics on ``arm``'s World (attached now if it is not yet, or if it
    was for another scene; ``physics`` to attach a given one); None on hardware."""
    world = arm.world
    if world is None:
        return None
    old = _ATTACHED.get(world)
    if old is not None and physics is None and old[0].scene.name == scene.name:
        return old[0]
    if old is not None:
        old[1]()
    from ..physics import physics_for

    physics = physics_for(scene, physics)  # the rules', or MuJoCo's if the scene says so
    _ATTACHED[world] = (physics, world.attach(physics))
    return physics


def attached(arm: Arm) -> ScenePhysics | None:
    """The scene physics attached to ``arm``'s World by ``attach_scene``, or None."""
    world = arm.world
    found = None if world is None else _ATTACHED.get(world)
    return None if found is None else found[0]


def live_scene(
    arm: Arm | Start, scene: Scene, dry_run: bool, task: str, held: str | None = None
) -> Scene:
    """The scene to plan ``task`` with: on a simulated arm the objects where they are
    now (attaching the physics unless ``dry_run``), else (hardware, a ``Start``)
    ``scene`` as given.

    Raises:
        TaskError: the gripper holds a cube other than ``held``, or (on a simulated arm)
            nothing when ``held`` is to be put down (nothing moves).
        InputError: ``arm`` is not an Arm or a Start, ``scene`` not a Scene.
    """
    _check_inputs(arm, scene, task)
    if isinstance(arm, Start):  # it says what it holds, if it knows (else as given)
        _holds(task, None if arm.held is None else arm.held.cube.name, held, strict=False)
        return scene
    physics = attached(arm) if dry_run else attach_scene(arm, scene)
    if physics is None or physics.scene.name != scene.name:
        return scene
    _holds(task, None if physics.holding is None else physics.holding.cube.name, held)
    return rest_scene(physics)


def _holds(task: str, holding: str | None, held: str | None, strict: bool = True) -> None:
    """TaskError if the gripper ``holding`` a cube (its name, or None) cannot do ``task``,
    which puts ``held`` down (None: takes a cube); ``strict``: nothing held when ``held``
    is to be put down is refused too (a simulated arm knows it)."""
    if holding != held and holding is not None:
        raise TaskError(
            f"{task}: the gripper holds {holding}; put it down first (place {holding} TO)",
            step=task,
        )
    if holding != held and strict:
        raise TaskError(f"{task}: the gripper holds nothing; pick {held} up first", step=task)


def _check_inputs(arm: object, scene: object, task: str) -> None:
    from ..arm import Arm

    if not isinstance(arm, Arm | Start):
        raise InputError(
            f"{task}: arm must be an armkit.Arm (or a tasks.Start, a model and its joints, "
            f"to plan without one), got {shown(arm)}"
        )
    if not isinstance(scene, Scene):
        raise InputError(
            f"{task}: scene must be a Scene; load one with armkit.scene.load_scene("
            f"'board_001'), got {shown(scene)}"
        )


def held_now(arm: Arm) -> Held | None:
    """The cube a simulated arm's gripper holds (its scene's physics) and its pose in the
    tool frame, else None (also on hardware, where armkit cannot know)."""
    physics = attached(arm)
    return None if physics is None else physics.holding


def obstacles_now(arm: Arm, scene: Scene) -> Scene:
    """What ``arm``'s moves are checked against: on a simulated arm with ``scene``'s
    physics attached, the objects at rest there (a held cube left out); else ``scene``."""
    physics = _physics_for(arm, scene)
    return scene if physics is None else physics.scene


def objects_now(arm: Arm, scene: Scene) -> Scene:
    """``scene`` with its objects where they are now: on a simulated arm with the
    scene's physics attached, as they rest there (a held cube in the gripper); else
    as given (what a task on ``arm`` would plan with; ``armkit check`` plans with it)."""
    physics = _physics_for(arm, scene)
    return scene if physics is None else rest_scene(physics)


def _physics_for(arm: Arm, scene: Scene) -> ScenePhysics | None:
    """The physics of ``scene`` attached to ``arm``'s world, or None (hardware, none
    attached, or another scene's)."""
    physics = attached(arm)
    return physics if physics is not None and physics.scene.name == scene.name else None


def run_plan(arm: Arm, plan: Plan, say: Callable[[int, Step], None] | None = None) -> None:
    """Move ``arm`` through ``plan`` (``Arm.run``): joint moves and gripper commands in order.

    On a simulated arm the plan's scene is simulated with it (its physics attached to
    the arm's world, as a task that runs attaches it), so the cubes move as planned.

    Raises:
        ArmkitError: the arm is not where the plan starts (it moved since planning);
            nothing moves then.
    """
    if not isinstance(plan, Plan):
        raise InputError(
            f"plan must be a Plan (from a task, e.g. tasks.pick(..., dry_run=True)), "
            f"got {shown(plan)}"
        )
    if plan.before is not None:
        attach_scene(arm, plan.before)
    scene, arm.scene = arm.scene, None  # checked when planned, with the grasps allowed
    try:
        arm.run(plan, say=say)
    finally:
        arm.scene = scene


def run_verified(
    arm: Arm,
    plan: Plan,
    say: Callable[[int, Step], None] | None = None,
    *,
    poses: bool = True,
    allow: tuple[str, ...] = (),
) -> None:
    """``run_plan``, then (on a simulated arm with the scene attached) check it.

    Raises:
        TaskFailed: the jaws missed, a cube fell or tipped (the task stops after that
            step), or a cube ended farther from its planned pose than the arm's
            precision allows (1 mm and 1 deg; the OWI's from its model file).
    """
    physics = attached(arm)
    if physics is None:
        run_plan(arm, plan, say)
        return
    seen = len(physics.events)
    last: list[Step] = []

    def check(k: int, step: Step) -> None:
        if last:
            _events(plan, physics, seen, last[-1], allow)
        last.append(step)
        if say is not None:
            say(k, step)

    run_plan(arm, plan, check)
    if last:
        _events(plan, physics, seen, last[-1], allow)
    if poses:
        _poses(plan, physics, precision_of(arm.model))


def _events(
    plan: Plan, physics: ScenePhysics, seen: int, step: Step, allow: tuple[str, ...]
) -> None:
    bad = [e for e in physics.events[seen:] if e.kind in BAD and e.kind not in allow]
    if bad:
        e = bad[0]
        hint = " (the OWI moves open loop: recalibrate it)" if plan.arm == "owi535" else ""
        raise TaskFailed(
            f"{plan.task}: stopped after step '{step.label}': {e.detail}{hint}",
            step=step.label, detail=e.detail,
        )  # fmt: skip


def _poses(plan: Plan, physics: ScenePhysics, precision: Precision) -> None:
    for want in () if plan.after is None else plan.after.cubes:
        got = physics.cube(want.name)
        distance, turn = pose_error(got, want)
        if distance > precision.tolerance or turn > precision.turn:
            raise TaskFailed(
                f"{plan.task}: {cube_text(got)}, {distance * 1000:.1f} mm and "
                f"{math.degrees(turn):.1f} deg from where planned ({cube_text(want)})",
                step=plan.steps[-1].label if plan.steps else plan.task, detail=cube_text(got),
            )  # fmt: skip
