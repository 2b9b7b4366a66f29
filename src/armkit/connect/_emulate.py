"""A simulated controller on a pseudo-terminal, for any program (``armkit emulate``)."""

from __future__ import annotations

from .._errors import ArmkitError, InputError
from ..model import ArmModel
from ..sim import World
from ..sim.emulators import Emulator
from ._rigs import Rig, dynamixel_rig, generic_config, lone_rig, servo_rig

EMULATED = ("ssc32", "maestro", "dynamixel")


def emulate(kind: str, model: ArmModel | None = None) -> Emulator:
    """``kind`` (``"ssc32"``, ``"maestro"``, ``"dynamixel"``) in a new real-time world on a
    pseudo-terminal: with ``model``, driving that arm (its channels, IDs and baud rate from
    its driver section; a Dynamixel bus for an arm without one gets the generic setup);
    without, a lone controller (an SSC-32 at 9600 baud, a Maestro, or the
    OpenManipulator-X's XM430s, IDs 11..15, at 1,000,000 baud).

    Raises:
        ValueError: an unknown kind.  ModelError: the model has no section for ``kind``.
    """
    if kind not in EMULATED:
        raise InputError(f"cannot emulate {kind!r}; choose one of {', '.join(EMULATED)}")
    world = World(realtime=True)
    try:
        return Emulator(_rig(kind, model, world).device, world=world)
    except BaseException:
        world.close()
        raise


def _rig(kind: str, model: ArmModel | None, world: World) -> Rig:
    if model is None:
        return lone_rig(kind, world)
    if kind in ("ssc32", "maestro"):
        return servo_rig(model, world, kind, None)
    if "dynamixel" in model.drivers:
        return dynamixel_rig(model, world, None)
    if model.drivers:
        raise ArmkitError(
            f"{model.name} is driven by {', '.join(model.drivers)}, not a Dynamixel bus; "
            f"emulate that instead"
        )
    return dynamixel_rig(model, world, None, generic_config(model))
