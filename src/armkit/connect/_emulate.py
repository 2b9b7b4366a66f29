"""A simulated controller on a pseudo-terminal, for any program (``armkit emulate``)."""

from __future__ import annotations

from ..model import ArmModel
from ..sim import World
from ..sim.emulators import Emulator
from ._kind import Emulated


def emulate(rig: Emulated, model: ArmModel | None = None) -> Emulator:
    """A driver kind's simulated controller (its ``emulate`` part, ``rig``) in a new
    real-time world on a pseudo-terminal: with ``model``, driving that arm (its channels,
    IDs and baud rate from its driver section); without, a lone controller.

    Raises:
        ModelError, ArmkitError: the model has no section for that kind.
    """
    world = World(realtime=True)
    try:
        return Emulator(rig(model, world).device, world=world)
    except BaseException:
        world.close()
        raise
