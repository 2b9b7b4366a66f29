"""Where a view gets what it shows: a ``StateSource``.

A source answers "what did the arm (and the objects on the table) look like at
time t": joint angles, gripper opening and object poses. ``DriverSource``
follows an arm's driver: on a simulated device, the simulation World's truth
about the arm (``armkit.connect.world_of``); on real hardware, the driver's
read-back.
"""

from __future__ import annotations

import time
from dataclasses import dataclass, field
from typing import Protocol, runtime_checkable

import numpy as np
from numpy.typing import NDArray

from .._errors import InputError
from ..connect import world_of
from ..drivers._driver import Driver
from ..model import ArmModel

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


class DriverSource:
    """Follow a driver, at wall time.

    On a simulated device the joint angles and the gripper opening are the
    World's truth about the arm (``SimArm.q()``, ``SimArm.grip()``: where the
    servos really are, lag and a grasped object included). On real hardware
    they are the driver's read-back (``driver.read()``) and the last width
    given to ``set_grip`` (a driver cannot read its gripper).
    """

    def __init__(self, model: ArmModel, driver: Driver) -> None:
        self._model = model
        self.driver = driver
        self._grip = model.gripper.width_max
        self._truth = _sim_arm(model, driver)

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
        """The driver's joint angles now (``t`` other than None is refused: a live
        driver has no history)."""
        if t is not None:
            raise InputError("a driver can only be read now; give t=None")
        if self._truth is not None:
            return ArmState(self.now(), self._truth.q(), self._truth.grip())
        q = np.asarray(self.driver.read(), dtype=np.float64)
        return ArmState(self.now(), q, self._grip)


class _Truth(Protocol):
    """What a view reads of ``armkit.sim.SimArm``."""

    model: ArmModel

    def q(self) -> F64: ...

    def grip(self) -> float: ...


def _sim_arm(model: ArmModel, driver: Driver) -> _Truth | None:
    """The simulated arm behind ``driver`` (its world's one arm of ``model``), or None
    on real hardware."""
    world = world_of(driver)
    if world is None:
        return None
    arms: list[_Truth] = list(world.arms())
    mine = [a for a in arms if a.model is model] or [a for a in arms if a.model.name == model.name]
    return mine[0] if len(mine) == 1 else None
