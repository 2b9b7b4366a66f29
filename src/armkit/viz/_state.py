"""Where a view gets what it shows: a ``StateSource``.

A source answers "what does the arm (and the objects on the table) look like
now": joint angles, gripper opening and object poses. ``WorldSource`` reads the
simulation World's truth (``SimArm.q()``, ``SimArm.grip()``, and the cubes of a
``ScenePhysics`` observer: carried when grasped); ``DriverSource`` follows an
arm's driver: the World behind it on a simulated device
(``armkit.sim.world_of``), the driver's read-back on real hardware;
``armkit.viz.LiveSource`` follows a simulated arm that another process moves.
"""

from __future__ import annotations

import time
from dataclasses import dataclass, field
from typing import Protocol, runtime_checkable

import numpy as np
from numpy.typing import NDArray

from .._errors import InputError
from ..connect import World, world_of
from ..drivers import Driver
from ..model import ArmModel
from ..scene import ScenePhysics

F64 = NDArray[np.float64]


@dataclass(frozen=True, eq=False)
class ObjectPose:
    """A scene object's pose: ``name`` as in the scene, ``T`` world transform (4, 4) [m]."""

    name: str
    T: F64


@dataclass(frozen=True, eq=False)
class ArmState:
    """One moment of the arm and the objects it moves.

    Attributes:
        t: the source's time [s] (wall time for a driver, simulated time for a World).
        q: joint angles [rad], shape (dof,).
        grip: gripper opening [m].
        objects: poses of the objects that moved (grasped ones), empty if none.
    """

    t: float
    q: F64
    grip: float
    objects: tuple[ObjectPose, ...] = field(default=())


@runtime_checkable
class StateSource(Protocol):
    """Anything a view can follow (a driver, the simulation World, a recording)."""

    @property
    def model(self) -> ArmModel:
        """The arm being shown."""
        ...

    def now(self) -> float:
        """The source's current time [s]."""
        ...

    def state(self, t: float | None = None) -> ArmState:
        """The state at time ``t`` [s] (None: now). Live sources may answer only now."""
        ...


class Truth(Protocol):
    """What a view reads of a simulated arm (``armkit.sim.SimArm``)."""

    model: ArmModel
    name: str

    def q(self) -> F64: ...

    def grip(self) -> float: ...


class WorldSource:
    """Follow arm ``arm`` (None: the only one) of a simulation ``world``, at world time:
    the true joint angles and gripper opening, and, with ``physics`` attached to the
    world, every cube's pose (a grasped one where the gripper carries it)."""

    def __init__(
        self, world: World, arm: str | None = None, physics: ScenePhysics | None = None
    ) -> None:
        self.world = world
        self.sim: Truth = world.arm(arm)
        self.physics = physics

    @property
    def model(self) -> ArmModel:
        """The arm being shown."""
        return self.sim.model

    def now(self) -> float:
        """Simulated time [s]."""
        return self.world.now()

    def state(self, t: float | None = None) -> ArmState:
        """The truth now (``t`` other than None is refused: use ``World.recording``)."""
        if t is not None:
            raise InputError("a world is read now; give t=None (its history: World.recording)")
        with self.world.lock:
            return ArmState(self.world.now(), self.sim.q(), self.sim.grip(), cubes(self.physics))


def cubes(physics: ScenePhysics | None) -> tuple[ObjectPose, ...]:
    """Every cube's pose from ``physics`` (none without): centre transforms (4, 4) [m]
    in the scene frame, a held cube where the gripper carries it."""
    if physics is None:
        return ()
    names = [c.name for c in physics.scene.cubes]
    if physics.holding is not None:
        names.append(physics.holding.cube.name)
    return tuple(ObjectPose(n, physics.cube(n).T) for n in names)


class DriverSource:
    """Follow a driver, at wall time.

    On a simulated device this is the World's truth about the arm
    (``WorldSource``: where the servos really are, lag and a grasped object
    included). On real hardware it is the driver's read-back
    (``driver.read()``) and the last width given to ``set_grip`` (a driver
    cannot read its gripper).
    """

    def __init__(
        self, model: ArmModel, driver: Driver, physics: ScenePhysics | None = None
    ) -> None:
        self._model = model
        self.driver = driver
        self._grip = model.gripper.width_max
        self._world = _world_source(model, driver, physics)

    @property
    def model(self) -> ArmModel:
        """The arm being shown."""
        return self._model

    def now(self) -> float:
        """Wall time [s] (``time.monotonic``)."""
        return time.monotonic()

    def set_grip(self, width: float) -> None:
        """Remember a commanded gripper opening [m] for drivers that cannot read it."""
        self._grip = width

    def state(self, t: float | None = None) -> ArmState:
        """The arm now (``t`` other than None is refused: a live driver has no history)."""
        if t is not None:
            raise InputError("a driver can only be read now; give t=None")
        if self._world is not None:
            truth = self._world.state()
            return ArmState(self.now(), truth.q, truth.grip, truth.objects)
        q = np.asarray(self.driver.read(), dtype=np.float64)
        return ArmState(self.now(), q, self._grip)


def _world_source(
    model: ArmModel, driver: Driver, physics: ScenePhysics | None
) -> WorldSource | None:
    """The source of the simulated arm behind ``driver`` (its world's one arm of
    ``model``), or None on real hardware."""
    world = world_of(driver)
    if world is None:
        return None
    arms = world.arms()
    mine = [a for a in arms if a.model is model] or [a for a in arms if a.model.name == model.name]
    return WorldSource(world, mine[0].name, physics) if len(mine) == 1 else None
