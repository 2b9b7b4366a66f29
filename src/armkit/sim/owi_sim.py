"""A whole simulated OWI-535 for tests and tools: its motors, its USB board, its clock.

``build_sim`` puts a unit in a new virtual-time ``World`` (or, given another
clock, runs its motors on that clock alone: the exit-path tests use the wall
clock in a child process). ``OwiSim.backend`` is the same board behind pyusb.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
from numpy.typing import NDArray

from .._clock import Clock
from ..model import ArmModel
from ._arm import Truth
from ._assemble import add_owi_arm
from ._world import World
from .owi535 import SimOwiUsb
from .owi_physics import OwiPhysics, random_unit


@dataclass
class OwiSim:
    """The parts of one simulated arm; ``physics.true_q()`` is the truth."""

    clock: Clock
    physics: OwiPhysics
    board: SimOwiUsb
    world: World | None = None
    _backend: list[Any] = field(default_factory=list, repr=False)

    @property
    def backend(self) -> Any:
        """The board behind a pyusb backend (needs pyusb): ``open_device(sim.backend)``."""
        if not self._backend:
            from .owi_usb import OwiUsbBackend

            self._backend.append(OwiUsbBackend(board=self.board))
        return self._backend[0]


def build_sim(
    model: ArmModel,
    seed: int = 0,
    *,
    clock: Clock | None = None,
    q0: NDArray[np.float64] | None = None,
    log_path: Path | None = None,
) -> OwiSim:
    """A simulated unit drawn with ``seed``, at pose ``q0`` [rad] (None = home), gripper
    closed, in a new virtual-time world (or on ``clock``, without a world)."""
    start = model.home if q0 is None else np.asarray(q0, dtype=np.float64)
    if clock is None:
        world = World()
        truth = Truth(tuple(float(a) for a in start), model.gripper.width_min)
        _, physics = add_owi_arm(world, model, truth=truth, seed=seed)
        return OwiSim(world.clock, physics, SimOwiUsb(physics, log_path=log_path), world)
    physics = OwiPhysics(model, random_unit(model, seed), clock, seed, start)
    return OwiSim(clock, physics, SimOwiUsb(physics, log_path=log_path))
