"""The simulator: simulated devices under the real drivers, and the world they move in.

``World`` is the one place where a simulated arm's true state lives and the
documented hook for everything that needs it (a scene, grasping, a distance
sensor, music's contact detection, the pen trace, the 3D viewer): attach an
``Observer`` (called after every simulation step) or read ``SimArm.q()``,
``SimArm.grip()`` and ``World.recording()``. ``world_of(driver)`` finds the
world behind a driver opened with ``--driver sim`` (or ``port="emu"``); on real
hardware it is None. ``Arm.world`` is the same.

The devices (``ssc32``, ``maestro``, ``dynamixel`` + ``xm430``, ``owi535``) are
simulated at the wire: the real driver and the real device class send their
real bytes (through pyserial, the dynamixel-sdk or pyusb where installed) and
the simulated device answers as the hardware does. ``emulators`` serves them on
pseudo-terminals for other programs (``armkit emulate``). sim never imports
drivers or motion.
"""

from __future__ import annotations

from typing import Any

from .._clock import Clock
from ._arm import SimArm as SimArm
from ._arm import Truth as Truth
from ._recording import Recording as Recording
from ._sensor import SimulatedSensor as SimulatedSensor
from ._state import kept_key as kept_key
from ._state import state_file as state_file
from ._state import state_key as state_key
from ._world import Observer as Observer
from ._world import World as World
from ._world import WorldClock as WorldClock


def world_of(driver: Any) -> World | None:
    """The world behind ``driver`` (a driver whose clock is a world's), or None on hardware."""
    clock: Clock | None = getattr(driver, "clock", None)
    return clock.world if isinstance(clock, WorldClock) else None


__all__ = [
    "Observer",
    "Recording",
    "SimArm",
    "Truth",
    "World",
    "WorldClock",
    "kept_key",
    "state_file",
    "state_key",
    "world_of",
]
