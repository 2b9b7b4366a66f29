"""How a scan looks: on an arm (turn the hand, stand still, read the distance sensor) or
in a plan (plan the turn from where the last one leaves the arm, and read what the
sensor would: the GP2D120's curve at the distance the scene puts along its beam). The
search's one algorithm (``_scan.locate``) runs on either, so the plan of a search
(``plan_search``) and the search run decide the same way where the readings agree."""

from __future__ import annotations

from typing import TYPE_CHECKING, Protocol

import numpy as np
from numpy.typing import NDArray

from ..arm import Plan, Start, plan_grip, plan_joints
from ..kinematics import fk
from ..model import ArmModel
from ..scene import Scene
from ..sensing import DistanceSensor, SensorMount, distance, nearest, volts

if TYPE_CHECKING:
    from ..arm import Arm

F64 = NDArray[np.float64]


class Eye(Protocol):
    """The hand's sensor as a scan uses it."""

    def open(self) -> None:
        """Open the jaws wide (the scan is planned with them so)."""
        ...

    def move(self, q: F64, label: str) -> None:
        """Move the arm to joints ``q`` [rad] (a move called ``label``)."""
        ...

    def look(self, q: F64, label: str) -> float:
        """``move`` there, stand still, and read the sensor [V]."""
        ...

    def distance(self) -> float | None:
        """The distance the sensor reads now [m], or None outside 4..30 cm."""
        ...

    def q(self) -> F64:
        """The joints now [rad], shape (dof,)."""
        ...


class ArmEye:
    """An arm and its sensor: every turn moves the arm."""

    def __init__(self, arm: Arm, sensor: DistanceSensor) -> None:
        self.arm, self.sensor = arm, sensor

    def open(self) -> None:
        self.arm.grip(self.arm.model.gripper.width_max * 1000.0)

    def move(self, q: F64, label: str) -> None:
        self.arm.move_joints(np.degrees(q).tolist())

    def look(self, q: F64, label: str) -> float:
        self.move(q, label)
        self.arm.settle()  # the reading is taken standing still
        return self.sensor.read()

    def distance(self) -> float | None:
        return self.sensor.distance()

    def q(self) -> F64:
        return self.arm.read()


class PlanEye:
    """A scan planned from ``start``: every turn added to ``plan``, every reading what
    the sensor at ``mount`` on the hand of ``kin`` would read in ``scene`` (no noise)."""

    def __init__(self, start: Start, scene: Scene, kin: ArmModel, mount: SensorMount) -> None:
        self.plan = Plan("search", start, (), start)
        self.scene, self.kin, self.mount = scene, kin, mount

    def open(self) -> None:
        at = self.plan.end
        self.plan = self.plan.then(plan_grip(at, at.model.gripper.width_max, "open the jaws"))

    def move(self, q: F64, label: str) -> None:
        self.plan = self.plan.then(plan_joints(self.plan.end, q, label=label))

    def look(self, q: F64, label: str) -> float:
        self.move(q, label)
        return volts(self.seen())

    def distance(self) -> float | None:
        return distance(volts(self.seen()))

    def q(self) -> F64:
        return self.plan.end.q

    def seen(self) -> float:
        """The distance to what the beam meets now [m] (0.8: nothing)."""
        T = self.scene.T_world_base @ fk(self.kin, self.plan.end.q)
        origin, directions = self.mount.rays(T)
        return nearest(self.scene, origin, directions)
