"""The factory: a driver name and a port become a driver on a real or a simulated device.

This package is the only place that knows both the drivers and the simulator
(``armkit.drivers`` never imports ``armkit.sim``, and ``armkit.sim`` never
imports drivers). ``open_driver(model, driver, port)``:

- ``driver="sim"`` (the default): the arm's OWN driver, the one its hardware
  uses, on a simulated device of its kind: the OWI-535's USB board, a Lynx6's or
  AL5D's SSC-32 (a Maestro if that is its only section), the OpenManipulator-X's
  XM430 servos on a Dynamixel bus; an arm with no driver section (puma560,
  planar2, a user's own) gets a generic bus of simulated smart servos (XM430s in
  extended position mode) and the real Dynamixel driver;
- ``driver=NAME, port="emu"``: that driver on a simulated device of its kind
  (``--driver maestro --port emu`` on a Lynx6);
- ``driver=NAME, port=PATH``: that driver on the real device at ``PATH``.

A simulated device lives in a ``World`` (``world=`` to share one, else a new
virtual-time world); ``world_of(driver)`` finds it. With ``keep=True`` (what the
CLI does) the simulated arm's truth is kept between processes in its state
file (``sim_state_file``), locked while in use.
"""

from __future__ import annotations

import os
import re
import stat
from pathlib import Path
from typing import TYPE_CHECKING, Any

from .._clock import Clock
from .._errors import InputError
from ..drivers import DRIVERS, Driver
from ..drivers import driver_names as hardware_names
from ..drivers import open_driver as open_hardware
from ..model import ArmModel
from ..sim import SimArm as SimArm
from ..sim import World as World
from ..sim import state_file
from ..sim import world_of as world_of

if TYPE_CHECKING:
    from ..devices.dynamixel import DynamixelBus
    from ..sim.emulators import Emulator
    from ..sim.owi_operator import SimOperator

# The builders (``_simulate``) import every driver and simulated device: they load
# when a simulation is opened, so ``import armkit`` stays light.


def open_driver(
    model: ArmModel,
    driver: str = "sim",
    port: str | None = None,
    *,
    world: World | None = None,
    keep: bool = False,
) -> Driver:
    """A driver for ``model`` (see the module doc).

    Args:
        driver: ``"sim"`` or a driver name (``armkit.drivers.driver_names()``).
        port: a device path, ``"emu"`` (a simulated device), or None; with ``"sim"``, a
            state file to keep the simulated arm's truth in (None: in memory).
        world: the world to put a simulated device in (None: a new one).
        keep: with ``"sim"`` and no port, keep the truth in ``sim_state_file(model)``.

    Raises:
        InputError: an unknown driver name, or ``world`` with real hardware.
        DeviceError: the device is missing or refuses, or the simulated arm is in use
            by another process (the message names it).
    """
    from ._simulate import simulate

    if world is not None and not isinstance(world, World):
        raise InputError(
            f"world must be a World (armkit.sim.World(), or another arm's arm.world) or None, "
            f"got {type(world).__name__}"
        )
    if not isinstance(driver, str):
        raise InputError(f"driver must be a driver name such as 'sim', got {driver!r}")
    if driver == "sim":
        check_sim_port(model, port)
        return simulate(model, native_kind(model), world, kept_state_file(model, port, keep))
    if driver not in DRIVERS:
        raise InputError(f"unknown driver {driver!r}; drivers are sim, {', '.join(DRIVERS)}")
    if port == "emu":
        return simulate(model, driver, world, None)
    if world is not None:
        raise InputError(
            f"a world holds simulated devices; {driver} on {port} is real hardware: "
            "drop world=, or use --port emu"
        )
    return open_hardware(model, driver, port)


def check_sim_port(model: ArmModel, port: str | None) -> None:
    """With ``driver="sim"`` a port names the simulated arm's state file; one that looks
    like a serial device (``/dev/...``, ``COM3``, an existing device file) is refused,
    so that a real port is neither silently ignored nor written over.

    Raises:
        InputError: naming the port and the drivers that would open it.
    """
    if port is None or port == "emu" or not _looks_like_a_device(port):
        return
    kind = native_kind(model)
    drivers = kind if kind in DRIVERS else "one of " + ", ".join(DRIVERS)
    raise InputError(
        f"driver sim simulates the {model.name} and opens no port, but {port} looks like a "
        f"device: for the real arm give its driver (--driver {drivers}), or leave the port "
        "out (with sim, --port names a file to keep the simulated arm in)"
    )


def _looks_like_a_device(port: str) -> bool:
    if port.startswith(("/dev/", "\\\\.\\")) or re.fullmatch(r"(?i)com\d+", port):
        return True
    try:
        mode = os.stat(port).st_mode
    except (OSError, ValueError):
        return False
    return stat.S_ISCHR(mode) or stat.S_ISBLK(mode)


def driver_names() -> list[str]:
    """Every name ``driver=`` takes: ``"sim"`` and the drivers of real hardware."""
    return ["sim", *hardware_names()]


def kept_state_file(model: ArmModel, port: str | None, keep: bool) -> Path | None:
    """The state file a simulated ``model`` (``driver="sim"``) keeps its truth in: the
    ``port`` given as a path, else with ``keep`` and no port ``sim_state_file(model)``,
    else None (in memory; also for ``port="emu"``)."""
    if port not in (None, "emu"):
        return Path(port)
    return state_file(model) if keep and port is None else None


def sim_state_file(model: ArmModel) -> Path:
    """Where the CLI keeps the simulated ``model``'s truth between processes."""
    return state_file(model)


def native_kind(model: ArmModel) -> str:
    """Which device ``--driver sim`` simulates for ``model``: ``"owi535"``, ``"dynamixel"``,
    ``"ssc32"``, ``"maestro"``, or ``"generic"`` (a bus of simulated smart servos)."""
    for kind in ("owi535", "dynamixel", "ssc32", "maestro"):
        if kind in model.drivers:
            return kind
    return "generic"


def auto_operator(driver: object) -> SimOperator | None:
    """An automatic operator for ``calibrate`` on a simulated OWI (None otherwise)."""
    from ..sim.owi_operator import auto_operator as operator

    return operator(driver)


def simulated_line(kind: str) -> tuple[Any, Clock]:
    """A serial line to a lone simulated ``"ssc32"`` or ``"maestro"`` and its world's clock
    (for ``armkit servo --port emu``)."""
    from ._simulate import simulated_line as line

    return line(kind)


def emulate(kind: str, model: ArmModel | None = None) -> Emulator:
    """A simulated ``"ssc32"``, ``"maestro"`` or ``"dynamixel"`` controller (driving ``model``,
    if given) in a real-time world on a pseudo-terminal: ``.port`` is its path."""
    from ._emulate import emulate as start

    return start(kind, model)


def simulated_bus(baudrate: int, retries: int = 3) -> DynamixelBus:
    """A bus of the OpenManipulator-X's five simulated XM430s (for ``dxl-scan --port emu``)."""
    from ._simulate import simulated_bus as bus

    return bus(baudrate, retries)


__all__ = [
    "SimArm",
    "World",
    "auto_operator",
    "check_sim_port",
    "driver_names",
    "native_kind",
    "open_driver",
    "sim_state_file",
    "world_of",
]
