"""Objects in the simulation: an Observer of the simulated World (see
``armkit.sim``) that grasps a cube when the jaws close on it, carries it with
the gripper, and lets it settle when they open (on the table, a socket floor,
another cube, a container), reporting each grasp, miss, drop and tip.

Written against the World protocol only: ``world.arm(name)`` with ``model``,
``q()``, ``grip()`` and ``grip_stop(width)``.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Literal, Protocol

import numpy as np
from numpy.typing import NDArray

from ..kinematics import fk
from ..model import ArmModel
from ._clearance import WIDTH_EPS, Held
from ._cube import Cube, settle
from ._grasp import Grasp, grasp
from ._scene import Scene

F64 = NDArray[np.float64]
EventKind = Literal["grasped", "missed", "placed", "dropped", "tipped"]
NEAR = 0.06  # [m]: a closing this close to a cube that misses it is reported
STILL = 1e-5  # [rad]: joints moving less than this per step are standing still


class SimArmView(Protocol):
    """What the scene reads and sets on a simulated arm (``armkit.sim.SimArm``)."""

    model: ArmModel

    def q(self) -> F64: ...
    def grip(self) -> float: ...
    def grip_stop(self, width: float | None) -> None: ...


class WorldView(Protocol):
    """What the scene needs of ``armkit.sim.World``."""

    def arm(self, name: str | None = None) -> SimArmView: ...


@dataclass(frozen=True)
class SceneEvent:
    """Something that happened to an object.

    Attributes:
        t: simulated time [s].  kind: grasped, missed, placed, dropped, tipped.
        object: the cube's name.  detail: one line for people.
        offset: for a grasp or miss, the cube's centre relative to the tool point in
            the tool frame [m], shape (3,) (approach, then the other two axes).
    """

    t: float
    kind: EventKind
    object: str
    detail: str
    offset: F64 | None = None


class ScenePhysics:
    """Attach with ``world.attach(ScenePhysics(scene))``; ``scene`` holds the objects
    at rest (a held cube is left out), ``events`` what happened, ``cube(name)`` any
    cube's pose now (a held one where the gripper carries it)."""

    def __init__(self, scene: Scene, arm: str | None = None) -> None:
        self.scene = scene
        self.events: list[SceneEvent] = []
        self.holding: Held | None = None
        self._arm = arm
        self._width: float | None = None
        self._opened = 0.0  # the opening when the arm last moved [m]
        self._q: F64 | None = None
        self._model: ArmModel | None = None
        self._reported = False
        self._stop_pending = False

    def restore(self, cube: Cube, T_tool_object: F64) -> None:
        """Start with ``cube`` (its pose before it was picked) in the gripper, held at
        ``T_tool_object`` (4, 4) [m] (a state kept between processes); the jaws are
        stopped at its width on the next step."""
        self.holding = Held(cube, np.asarray(T_tool_object, dtype=np.float64))
        self.scene = self.scene.without_cube(cube.name)
        self._stop_pending = True

    def on_step(self, world: WorldView, t: float) -> None:
        """Grasp, carry or release (cheap when nothing changes: no FK)."""
        sim = world.arm(self._arm)
        self._model = sim.model
        if self._stop_pending and self.holding is not None:
            self._stop_pending = False
            sim.grip_stop(self.holding.cube.size)
        width, q = sim.grip(), sim.q()
        if self._width is None or self._q is None or float(np.max(np.abs(q - self._q))) > STILL:
            self._opened = width  # the jaws come round an object at the opening they move with
        if self._width is None:
            self._width = width
        self._q = q
        last = self._width
        if abs(width - last) <= WIDTH_EPS:
            return
        self._width = width
        if width > last:
            self._reported = False
            if self.holding is not None and self.holding.released_by(width):
                self._release(sim, t)
        elif self.holding is None:
            self._closing(sim, width, t)

    def on_steps(self, world: WorldView, times: F64) -> None:
        """A stretch of steps at ``times`` [s] in which the jaws stayed still (the world
        steps those only): nothing to grasp or release, so the last step says it all."""
        self.on_step(world, float(times[-1]))

    def may_skip(self) -> bool:
        """The world may skip steps while nothing moves (a still gripper grasps nothing)."""
        return not self._stop_pending

    def pose(self, name: str) -> F64:
        """The cube ``name``'s centre pose now, shape (4, 4) [m] in the scene frame (what
        a view draws): here ``cube(name).T``; a physics engine's own pose, tilt and all."""
        T: F64 = self.cube(name).T
        return T

    def cube(self, name: str) -> Cube:
        """The cube ``name`` as last seen (centre of its lowest face, yaw, face up); a
        held one where the gripper carries it."""
        held = self.holding
        if (
            held is not None
            and held.cube.name == name
            and self._model is not None
            and self._q is not None
        ):
            T = self._tool(self._model, self._q, held.cube.size)
            return held.cube.moved(T @ held.T_tool_object)
        return self.scene.cube(name)

    def _tool(self, model: ArmModel, q: F64, width: float) -> F64:
        g = model.gripper
        kin = model.with_grip_width(min(max(width, g.width_min), g.width_max))
        T: F64 = self.scene.T_world_base @ fk(kin, q)
        return T

    def _closing(self, sim: SimArmView, width: float, t: float) -> None:
        near = [c for c in self.scene.cubes if c.size >= width - WIDTH_EPS]
        if not near or self._reported:
            return
        outcomes = []
        for cube in near:
            T = self._tool(sim.model, sim.q(), cube.size)
            outcomes.append((grasp(sim.model.gripper, T, self._opened, cube), cube, T))
        for result, cube, _ in outcomes:
            if result.ok and result.T_tool_object is not None:
                self.holding = Held(cube, result.T_tool_object)
                self.scene = self.scene.without_cube(cube.name)
                sim.grip_stop(cube.size)
                turned = (
                    f", squared up by {np.degrees(result.turn):.1f} deg"
                    if result.turn > 1e-3
                    else ""
                )
                self._add(t, "grasped", cube.name, f"grasped {cube.name}{turned}", result.offset)
                return
        self._missed(outcomes, width, t)

    def _missed(self, outcomes: list[tuple[Grasp, Cube, F64]], width: float, t: float) -> None:
        """Report the nearest cube once the jaws have closed past every cube's width."""
        if any(width > cube.size - WIDTH_EPS for _, cube, _ in outcomes):
            return
        self._reported = True
        best = min(outcomes, key=lambda o: float(np.linalg.norm(o[1].center - o[2][:3, 3])))
        result, cube, T = best
        if float(np.linalg.norm(cube.center - T[:3, 3])) > NEAR:
            return
        self._add(t, "missed", cube.name, f"missed {cube.name}: {result.reason}", result.offset)

    def _release(self, sim: SimArmView, t: float) -> None:
        assert self.holding is not None
        held, self.holding = self.holding, None
        sim.grip_stop(None)
        T_tool = self._tool(sim.model, sim.q(), held.cube.size)
        done = settle(self.scene, held.cube, T_tool @ held.T_tool_object)
        self.scene = replace(self.scene, cubes=(*self.scene.cubes, done.cube))
        fall = f", fell {done.fall * 1000:.1f} mm" if done.outcome == "dropped" else ""
        self._add(
            t, done.outcome, held.cube.name, f"{done.outcome} {held.cube.name} on {done.on}{fall}"
        )

    def _add(
        self, t: float, kind: EventKind, name: str, detail: str, offset: F64 | None = None
    ) -> None:
        self.events.append(SceneEvent(t, kind, name, detail, offset))
