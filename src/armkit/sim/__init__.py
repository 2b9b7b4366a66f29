"""Simulated devices and arms; protocol emulators used by tests and ``--port emu``."""

from __future__ import annotations

from ..drivers._driver import Driver
from ..model import ArmModel


def open_sim_driver(model: ArmModel, port: str | None = None) -> Driver:
    """The simulated driver for ``model``: the OWI's real driver on a simulated USB
    device for timed-motor arms, a simulated servo arm for every other model."""
    if "owi535" in model.drivers:
        from ..drivers.timed import open_sim_driver as open_owi_sim

        return open_owi_sim(model, port)
    from .servo_arm import open_servo_sim

    return open_servo_sim(model, port)
