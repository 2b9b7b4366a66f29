"""Where a view gets what it shows: a ``StateSource``.

A source answers "what did the arm (and the objects on the table) look like at
time t": joint angles, gripper opening and object poses. ``DriverSource``
reads an arm's driver (the simulator's truth, or a real arm's read-back); the
simulation ``World`` implements the same protocol for views that follow it.
"""

from __future__ import annotations

import time
from dataclasses import dataclass, field
from typing import Protocol, runtime_checkable

import numpy as np
from numpy.typing import NDArray

from .._errors import InputError
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
    """Follow a driver by reading it back (``driver.read()``), at wall time.

    The gripper opening is the driver's ``grip_width`` [m] where it keeps one (the
    simulated servo arm does), else the last width given to ``set_grip``.
    """

    def __init__(self, model: ArmModel, driver: Driver) -> None:
        self._model = model
        self.driver = driver
        self._grip = model.gripper.width_max

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
        q = np.asarray(self.driver.read(), dtype=np.float64)
        width = getattr(self.driver, "grip_width", None)
        grip = float(width) if isinstance(width, float) else self._grip
        return ArmState(self.now(), q, grip)
