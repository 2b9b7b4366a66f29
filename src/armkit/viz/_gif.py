"""An animated GIF of an arm at work (drawn offscreen with Pillow: ``_raster``).

``GifRecorder`` is an Observer of a simulation World: it keeps the arm's true
state (joints, gripper, the cubes of a ``ScenePhysics``) ``fps`` times per
simulated second while any job runs (virtual time: a long job records in a
moment). ``record_path`` moves an ``Arm`` through joint poses and samples it
the same way. ``write_gif`` draws each sample from the same primitives as the
web view: the table, the scene, the arm, the cubes where they are, the trail.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import NDArray

from .._errors import ArmkitError
from .._files import check_output_path
from .._primitives import Polyline, Primitive
from ..arm import Arm
from ..kinematics import fk
from ..model import ArmModel
from ..scene import Scene, ScenePhysics, cube_primitive
from ._arm_shapes import TRAIL_COLOUR, arm_primitives, reach_of, table_primitive
from ._ink import Ink
from ._scene_shapes import scene_primitives
from ._state import Snapshot, Truth, cubes
from ._target import check_target

if TYPE_CHECKING:
    from ..connect import World

F64 = NDArray[np.float64]
HOLD = 0.3  # [s] the arm rests at each pose of the path
LONGEST = 120.0  # [s] of arm time one recording may take
MOST_FRAMES = 900  # a longer recording keeps every other frame (and halves its rate)


class GifRecorder:
    """Observer: the true state of ``arm`` every 1/``fps`` [s] of simulated time
    (``frames``), with the cubes of ``physics`` if given; at most ``MOST_FRAMES``
    (a longer job is thinned: ``fps`` halves)."""

    def __init__(self, arm: Truth, fps: float, physics: ScenePhysics | None = None) -> None:
        self.arm, self.fps, self.physics = arm, fps, physics
        self.frames: list[Snapshot] = []
        self._next = -1.0

    def on_step(self, world: World, t: float) -> None:
        """Keep a frame when one is due."""
        if t < self._next:
            return
        self._next = t + 1.0 / self.fps - 1e-9
        self.frames.append(Snapshot(t, self.arm.q(), self.arm.grip(), cubes(self.physics)))
        if len(self.frames) > MOST_FRAMES:
            self.frames = self.frames[::2]
            self.fps /= 2.0


def default_tour(model: ArmModel, scene: Scene | None = None) -> list[F64]:
    """Home, then 40 mm above each cube of ``scene`` (or three points in front of the
    arm) that the arm can reach pointing down (any pitch if not), then home [rad]."""
    reach = reach_of(model)
    points = [np.array([0.6 * reach, y * reach, model.table_z + 0.1 * reach]) for y in (-0.4, 0.0, 0.4)]  # fmt: skip
    if scene is not None and scene.cubes:
        lift = np.array([0.0, 0.0, 0.04])
        points = [
            scene.to_base(c.center + lift + np.array([0.0, 0.0, c.size / 2])) for c in scene.cubes
        ]
    tour = [model.home]
    for above in points:
        for pitch in (-math.pi / 2, None):
            check = check_target(model, above, pitch, tour[-1], scene)
            if check.q is not None:
                tour.append(check.q)
                break
    return [*tour, model.home]


def record_path(arm: Arm, poses: Sequence[F64], fps: float) -> list[Snapshot]:
    """Move the simulated ``arm`` through ``poses`` [rad] (each (dof,)), resting
    ``HOLD`` s at each, recording its truth ``fps`` times per simulated second."""
    world = arm.world
    if world is None:
        raise ArmkitError("an animation records a simulated arm; drop --driver/--port")
    recorder = GifRecorder(world.arm(), fps)
    detach = world.attach(recorder)
    try:
        start = arm.clock.now()
        for q in poses:
            arm.move_joints(np.degrees(q).tolist())
            arm.clock.sleep(HOLD)
            if arm.clock.now() - start > LONGEST:
                raise ArmkitError(f"the path takes longer than {LONGEST:.0f} s; give fewer poses")
    finally:
        detach()
    return recorder.frames


def write_gif(
    model: ArmModel,
    frames: Sequence[Snapshot],
    path: str | Path,
    *,
    scene: Scene | None = None,
    fps: float = 15.0,
    size: tuple[int, int] = (640, 480),
) -> Path:
    """Draw ``frames`` (each a moment of the arm and the cubes) into the GIF ``path``
    at ``fps`` frames per second, ``size`` (width, height) [px]: the table, ``scene``,
    the arm, the cubes where they are and the tool's trail."""
    if not frames:
        raise ArmkitError("nothing was recorded: the job did not run on a simulated arm")
    out = check_output_path(path, suffixes=(".gif",))
    raster = _raster()
    T = np.eye(4) if scene is None else scene.T_world_base
    tips = (T @ fk(model, np.array([f.q for f in frames])))[:, :3, 3]
    camera = raster.look_from_front_right(T[:3, 3], reach_of(model), *size)
    images = []
    ink, strokes = Ink(scene.sheets if scene is not None else ()), {}
    for i, state in enumerate(frames):
        stroke = ink.add(tips[i])
        if stroke is not None:
            strokes[stroke.name] = stroke
        trail = (
            [Polyline("/trail", tips[: i + 1], TRAIL_COLOUR, 2.0), *strokes.values()] if i else []
        )
        title = f"{model.name}  t = {state.t - frames[0].t:.2f} s"
        images.append(raster.render([*shapes_of(model, state, scene), *trail], camera, title))
    duration = round(1000.0 / fps)
    images[0].save(out, save_all=True, append_images=images[1:], duration=duration, loop=0)
    return out


def write_picture(
    model: ArmModel,
    state: Snapshot,
    path: str | Path,
    *,
    scene: Scene | None = None,
    title: str = "",
    size: tuple[int, int] = (800, 600),
) -> Path:
    """Draw one moment (``state``) of the arm and ``scene`` into the image file ``path``
    (PNG, ...), ``size`` (width, height) [px], offscreen. Returns the path."""
    out = check_output_path(path)
    raster = _raster()
    T = np.eye(4) if scene is None else scene.T_world_base
    camera = raster.look_from_front_right(T[:3, 3], reach_of(model), *size)
    raster.render(shapes_of(model, state, scene), camera, title).save(out)
    return out


def shapes_of(model: ArmModel, state: Snapshot, scene: Scene | None) -> list[Primitive]:
    """The table, ``scene`` with its cubes where ``state`` has them, and the arm."""
    T = np.eye(4) if scene is None else scene.T_world_base
    shapes = {p.name: p for p in [table_primitive(model, scene), *(scene_primitives(scene) if scene else [])]}  # fmt: skip
    cubes = {c.name: c for c in scene.cubes} if scene is not None else {}
    for obj in state.objects:
        if obj.name in cubes:
            shapes[f"/scene/{obj.name}"] = cube_primitive(cubes[obj.name], scene, obj.T)
    return [*shapes.values(), *arm_primitives(model, state.q, state.grip, T_world_base=T)]


def _raster() -> Any:
    try:
        from . import _raster
    except ImportError:
        raise ArmkitError("an animation needs Pillow: pip install 'armkit[plot]'") from None
    return _raster
