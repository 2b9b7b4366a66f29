"""A whole simulated OWI-535: clock, motor physics and the pyusb backend that
is the device, wired together."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from .._clock import Clock
from ..model import ArmModel
from .owi_clock import SimClock
from .owi_physics import OwiPhysics, random_unit
from .owi_usb import OwiUsbBackend


@dataclass
class OwiSim:
    """The parts of one simulated arm; ``physics.true_q()`` is the truth."""

    clock: Clock
    physics: OwiPhysics
    backend: OwiUsbBackend


def build_sim(
    model: ArmModel,
    seed: int = 0,
    *,
    clock: Clock | None = None,
    q0: NDArray[np.float64] | None = None,
    log_path: Path | None = None,
) -> OwiSim:
    """A simulated unit drawn with ``seed``, at pose ``q0`` [rad] (None = home),
    on ``clock`` (None = a simulated clock: no real waiting)."""
    clk: Clock = SimClock() if clock is None else clock
    physics = OwiPhysics(model, random_unit(model, seed), clk, seed, q0)
    return OwiSim(clk, physics, OwiUsbBackend(physics, log_path=log_path))
