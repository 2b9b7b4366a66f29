"""Where a view gets what it shows: a ``StateSource``.

A source answers "what does the arm (and the objects on the table) look like
now": joint angles, gripper opening and object poses. ``WorldSource`` reads the
simulation World's truth (``SimArm.q()``, ``SimArm.grip()``, and the cubes of a
``ScenePhysics`` observer: carried when grasped); ``ArmSource`` follows an
``Arm``: the World behind it on a simulated device, its read-back on real hardware;
``armkit.viz.LiveSource`` follows a simulated arm that another process moves.
"""

from __future__ import annotations

import time
from dataclasses import dataclass, field
from typing import Protocol, runtime_checkable

import numpy as np
from numpy.typing import NDArray

from .._errors import InputError
from ..arm import Arm
from ..connect import World
from ..model import ArmModel
from ..scene import ScenePhysics

F64 = NDArray[np.float64]


@dataclass(frozen=True, eq=False)
class ObjectPose:
    """A scene object's pose: ``name`` as in the scene, ``T`` world transform (4, 4) [m]."""

    name: str
    T: F64


@dataclass(frozen=True, eq=False)
class Snapshot:
    """One moment of the arm and the objects it moves.

    Attributes:
        t: the source's time [s] (wall time for a driver, simulated time for a World).
        q: joint angles [rad], shape (dof,).
        grip: gripper opening [m].
        objects: poses of the objects that moved (grasped ones), empty if none.
        contacts: where a physics engine's bodies touch [m], shape (n, 3), scene frame;
            None when not asked for (``WorldSource(contacts=True)``, MuJoCo only).
    """

    t: float
    q: F64
    grip: float
    objects: tuple[ObjectPose, ...] = field(default=())
    contacts: F64 | None = None


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

    def state(self, t: float | None = None) -> Snapshot:
        """The state at time ``t`` [s] (None: now). Live sources may answer only now."""
        ...


class Truth(Protocol):
    """What a view reads of a simulated arm (``armkit.sim.SimArm``)."""

    model: ArmModel
    name: str

    def q(self) -> F64: ...

    def grip(self) -> float: ...

    def recent(self, count: int) -> F64: ...


class WorldSource:
    """Follow arm ``arm`` (None: the only one) of a simulation ``world``, at world time:
    the true joint angles and gripper opening, and, with ``physics`` attached to the
    world, every cube's pose (a grasped one where the gripper carries it); with
    ``contacts`` and MuJoCo's physics, where its bodies touch."""

    def __init__(
        self,
        world: World,
        arm: str | None = None,
        physics: ScenePhysics | None = None,
        contacts: bool = False,
    ) -> None:
        self.world = world
        self.sim: Truth = world.arm(arm)
        self.physics = physics
        self.contacts = contacts

    @property
    def model(self) -> ArmModel:
        """The arm being shown."""
        return self.sim.model

    def now(self) -> float:
        """Simulated time [s]."""
        return self.world.now()

    def state(self, t: float | None = None) -> Snapshot:
        """The truth now (``t`` other than None is refused: use ``World.recording``)."""
        if t is not None:
            raise InputError("a world is read now; give t=None (its history: World.recording)")
        with self.world.lock:
            touching = self._contacts()
            return Snapshot(
                self.world.now(), self.sim.q(), self.sim.grip(), cubes(self.physics), touching
            )

    def _contacts(self) -> F64 | None:
        """MuJoCo's contact points now, if asked for and MuJoCo moves the objects."""
        from ..physics import MujocoPhysics

        physics = self.physics
        if not self.contacts or not isinstance(physics, MujocoPhysics):
            return None
        return physics.contacts()


def cubes(physics: ScenePhysics | None) -> tuple[ObjectPose, ...]:
    """Every cube's pose from ``physics`` (none without): centre transforms (4, 4) [m]
    in the scene frame, a held cube where the gripper carries it."""
    if physics is None:
        return ()
    names = [c.name for c in physics.scene.cubes]
    if physics.holding is not None:
        names.append(physics.holding.cube.name)
    return tuple(ObjectPose(n, physics.pose(n)) for n in names)


class ArmSource:
    """Follow an ``Arm``, at wall time.

    On a simulated device this is the World's truth about the arm
    (``WorldSource``: where the servos really are, lag and a grasped object
    included). On real hardware it is the arm's read-back (``Arm.read()``) and
    the last width given to ``set_grip`` (a driver cannot read its gripper).
    """

    def __init__(self, arm: Arm, physics: ScenePhysics | None = None) -> None:
        self.arm = arm
        self._grip = arm.model.gripper.width_max
        world, sim = arm.world, arm.sim
        self._world = (
            None if world is None or sim is None else WorldSource(world, sim.name, physics)
        )

    @property
    def model(self) -> ArmModel:
        """The arm being shown."""
        return self.arm.model

    def now(self) -> float:
        """Wall time [s] (``time.monotonic``)."""
        return time.monotonic()

    def set_grip(self, width: float) -> None:
        """Remember a commanded gripper opening [m] for drivers that cannot read it."""
        self._grip = width

    def state(self, t: float | None = None) -> Snapshot:
        """The arm now (``t`` other than None is refused: a live arm has no history)."""
        if t is not None:
            raise InputError("a live arm can only be read now; give t=None")
        if self._world is not None:
            truth = self._world.state()
            return Snapshot(self.now(), truth.q, truth.grip, truth.objects)
        return Snapshot(self.now(), self.arm.read(), self._grip)
