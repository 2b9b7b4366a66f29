"""A simulated GP2D120 on a simulated arm's hand: its output voltage is a function
of the arm's true pose and the scene's objects as they are now (the scene's
physics), installed as one of the arm's analog inputs (``SimArm.analog``)."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Protocol

import numpy as np
from numpy.typing import NDArray

from ..kinematics import fk
from ..model import ArmModel
from ..scene import ScenePhysics
from ..sensing import NOISE_V, SensorMount, nearest, volts

F64 = NDArray[np.float64]


class Hand(Protocol):
    """What the sensor sees of the arm it is on (``SimArm``): its true joints and jaws."""

    model: ArmModel

    def q(self) -> F64: ...
    def grip(self) -> float: ...


@dataclass
class SimulatedSensor:
    """A GP2D120 on ``arm``'s hand at ``mount``, seeing ``physics``'s objects (the held
    one excepted), with Gaussian noise of ``noise`` [V] from a generator seeded ``seed``.

    Call it for the output now [V]; ``true_distance()`` is what it really sees [m].
    """

    arm: Hand
    physics: ScenePhysics
    mount: SensorMount
    noise: float = NOISE_V
    seed: int = 2
    _rng: np.random.Generator = field(init=False, repr=False)

    def __post_init__(self) -> None:
        self._rng = np.random.default_rng(self.seed)

    def tool(self) -> F64:
        """The true tool pose in the scene frame, shape (4, 4)."""
        model = self.arm.model
        g = model.gripper
        width = min(max(self.arm.grip(), g.width_min), g.width_max)
        T: F64 = self.physics.scene.T_world_base @ fk(model.with_grip_width(width), self.arm.q())
        return T

    def true_distance(self) -> float:
        """Distance to the nearest object along the beam now [m] (0.8: nothing)."""
        origin, directions = self.mount.rays(self.tool())
        return nearest(self.physics.scene, origin, directions)

    def __call__(self) -> float:
        v = volts(self.true_distance()) + self.noise * float(self._rng.standard_normal())
        return min(5.0, max(0.0, v))
