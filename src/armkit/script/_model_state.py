"""What the checker knows of the arm as it follows a script, and the rules that change
it: what a job leaves in the gripper, what opening the gripper lets go, what the
arm's moves are checked against."""

from __future__ import annotations

from collections.abc import Hashable
from dataclasses import dataclass, replace
from typing import Any

import numpy as np
from numpy.typing import NDArray

from .._errors import ScriptError
from ..kinematics import fk
from ..model import ArmModel
from ..scene import Held, Scene, settle
from ._jobs import NOTHING_PICKED
from ._resolve import UNKNOWN

F64 = NDArray[np.float64]


@dataclass(frozen=True)
class ArmState:
    """What the checker knows of the arm; None = not known before it runs (``grip``:
    not set yet, the model's own grip length). ``motor_s``: motor-seconds a timed
    arm has used [s] (its battery's count). ``held``: the cube a ``pick`` job took
    (until ``place``), None, or ``UNKNOWN``; ``gripped``: it with its pose in the tool
    frame, where known (checked with the links). ``objects``: the scene as the tasks so far
    leave it (``tasks.Plan.rest``), what the next task is planned with; None: not known
    (after a job that is not planned ahead, such as ``search``)."""

    q: F64 | None
    grip: float | None
    speed: float = 1.0
    tool_speed: float = 0.05
    light: bool | None = None
    motor_s: float = 0.0
    held: Any = None
    objects: Scene | None = None
    gripped: Held | None = None


def held_after(held: Any, command: str, args: dict[str, object]) -> Any:
    """The cube held after the job ``command`` when ``held`` is held now (a name, None or
    ``UNKNOWN``); ScriptError if the job cannot be done so (``place`` with nothing, any
    other job with a cube)."""
    if held is not UNKNOWN:
        if command == "place" and held is None:
            raise ScriptError(NOTHING_PICKED)
        if command != "place" and held is not None:
            raise ScriptError(
                f"{command}: the gripper holds {held} (picked by 'pick'); "
                "put it down first with 'place WHERE'"
            )
    if command == "pick":
        cube = args.get("cube")
        return UNKNOWN if cube is None else cube
    return None if command == "place" else held


def gripped_to(s: ArmState, width: float | None, model: ArmModel) -> ArmState:
    """``s`` after opening the gripper to ``width`` [m] (None: not known): a held cube the
    jaws let go (``Held.released_by``) falls onto what is below it (``scene.settle``, as
    the simulator's does), where that is known; else where it lands is not known."""
    let_go = width is None or s.gripped is None or s.gripped.released_by(width)
    if not (isinstance(s.held, str) and let_go):
        return replace(s, grip=width)
    if width is None or s.gripped is None or s.q is None or s.objects is None:
        held = None if width is not None else UNKNOWN
        return replace(s, grip=width, held=held, objects=None, gripped=None)
    return replace(s, grip=width, held=None, objects=_dropped(s, model), gripped=None)


def _dropped(s: ArmState, model: ArmModel) -> Scene:
    """The scene with the held cube where it comes to rest when let go at ``s.q``."""
    assert s.gripped is not None and s.q is not None and s.objects is not None
    kin = model if s.grip is None else model.with_grip_width(s.grip)
    T = s.objects.T_world_base @ fk(kin, s.q) @ s.gripped.T_tool_object
    others = s.objects.without_cube(s.gripped.cube.name)
    rest = settle(others, s.gripped.cube, T).cube
    return replace(others, cubes=(*others.cubes, rest))


def obstacles(s: ArmState, fixed: Scene | None) -> Scene | None:
    """What moves are checked against, as ``Arm`` will check them: the script's scene with
    its cubes where the tasks leave them (a held one left out); ``fixed`` (the scene
    without its cubes) where that is not known (after a ``search``); None without a scene."""
    if fixed is None:
        return None
    if s.objects is None or s.held is UNKNOWN:
        return fixed
    return s.objects if s.held is None else s.objects.without_cube(s.held)


def cubes_key(scene: Scene) -> Hashable:
    """Where the scene's cubes are, to compare states (to 1 nm)."""
    return tuple((c.name, tuple(np.round(c.T, 9).ravel().tolist())) for c in scene.cubes)
