"""Where a script's statements start from on an arm: the arm as it reads it now, with
the script's objects where they are now."""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..arm import Start
from ..scene import Scene
from ..tasks import obstacles_now

if TYPE_CHECKING:
    from ..arm import Arm


def start_of(arm: Arm, scene: Scene | None) -> Start:
    """``arm`` as a statement plans from it (``Arm.start``: its joints as the driver reads
    them, grip, held cube, the driver's forecasts), with ``scene``'s objects where they are
    now (a simulated arm's, at rest in its physics) and the held cube left out; ``scene``
    None: the objects the arm has (``Arm.scene``)."""
    start = arm.start()
    if scene is None:
        return start
    objects = obstacles_now(arm, scene)
    held = start.held
    if held is not None and held.cube.name in {c.name for c in objects.cubes}:
        objects = objects.without_cube(held.cube.name)
    return start.then(scene=objects)
