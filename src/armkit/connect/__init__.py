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

from .._errors import InputError, NoSuchName
from ._kind import Ask as Ask
from ._kind import CalibrationRoutine as CalibrationRoutine
from ._kind import DriverKind as DriverKind
from ._kind import PortRule as PortRule
from ._kind import Trait as Trait
from ._kinds import driver_kind as driver_kind
from ._kinds import driver_kinds as driver_kinds
from ._kinds import emulated_kinds as emulated_kinds
from ._kinds import kind_names
from ._kinds import kinds_of as kinds_of
from ._kinds import kinds_with as kinds_with
from ._kinds import listed as listed

if TYPE_CHECKING:
    from .._clock import Clock
    from ..devices.dynamixel import DynamixelBus
    from ..drivers import Driver, Forecaster
    from ..model import ArmModel
    from ..sim import SimArm as SimArm
    from ..sim import World as World
    from ..sim import world_of as world_of
    from ..sim.emulators import Emulator
    from ._kind import Emulated

# The builders (``_simulate``) import every driver and simulated device: they load
# when a simulation is opened, so ``import armkit`` and ``armkit --help`` stay light;
# so do the simulator's names re-exported here (loaded on first use, PEP 562).


def _sim() -> Any:
    from .. import sim

    return sim


_LAZY = {"SimArm": _sim, "World": _sim, "world_of": _sim}


def __getattr__(name: str) -> Any:
    """``SimArm``, ``World`` and ``world_of`` (``armkit.sim``'s), loaded when first asked for."""
    package = _LAZY.get(name)
    if package is None:
        raise NoSuchName(f"module 'armkit.connect' has no attribute {name!r}")
    value = getattr(package(), name)
    globals()[name] = value
    return value


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
    from ..sim import World
    from ._simulate import simulate, simulate_generic

    if world is not None and not isinstance(world, World):
        raise InputError(
            f"world must be a World (armkit.sim.World(), or another arm's arm.world) or None, "
            f"got {type(world).__name__}"
        )
    if not isinstance(driver, str):
        raise InputError(f"driver must be a driver name such as 'sim', got {driver!r}")
    if driver == "sim":
        check_sim_port(model, port)
        native = kinds_of(model)
        build = native[0].simulate if native else simulate_generic
        return simulate(model, build, world, kept_state_file(model, port, keep))
    kind = driver_kind(driver)
    if port == "emu":
        return simulate(model, kind.simulate, world, None)
    if world is not None:
        raise InputError(
            f"a world holds simulated devices; {driver} on {port} is real hardware: "
            "drop world=, or use --port emu"
        )
    return kind.open(model, port)


def forecaster(model: ArmModel, driver: str = "sim", port: str | None = None) -> Forecaster:
    """What ``open_driver(model, driver, port)``'s moves will take, with no device opened
    (``armkit.drivers.Forecaster``): ``"sim"`` forecasts the model's own driver kind.

    Raises:
        InputError: an unknown driver name.
        ModelError: the model has no section for that driver.
    """
    if driver == "sim":
        native = kinds_of(model)
        if not native:  # a generic bus of smart servos
            from ._rigs import generic_forecaster

            return generic_forecaster(model)
        return native[0].forecast(model, "sim")
    return driver_kind(driver).forecast(model, None if port == "emu" else port)


def check_sim_port(model: ArmModel, port: str | None) -> None:
    """With ``driver="sim"`` a port names the simulated arm's state file; one that looks
    like a serial device (``/dev/...``, ``COM3``, an existing device file) is refused,
    so that a real port is neither silently ignored nor written over.

    Raises:
        InputError: naming the port and the drivers that would open it.
    """
    if port is None or port == "emu" or not _looks_like_a_device(port):
        return
    native = kinds_of(model)
    drivers = native[0].name if native else "one of " + ", ".join(kind_names())
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
    """Every name ``driver=`` takes: ``"sim"`` and the driver kinds (``driver_kinds``)."""
    return ["sim", *kind_names()]


def kept_state_file(model: ArmModel, port: str | None, keep: bool) -> Path | None:
    """The state file a simulated ``model`` (``driver="sim"``) keeps its truth in: the
    ``port`` given as a path, else with ``keep`` and no port ``sim_state_file(model)``,
    else None (in memory; also for ``port="emu"``)."""
    from ..sim import state_file

    if port not in (None, "emu"):
        return Path(port)
    return state_file(model) if keep and port is None else None


def sim_state_file(model: ArmModel) -> Path:
    """Where the CLI keeps the simulated ``model``'s truth between processes."""
    from ..sim import state_file

    return state_file(model)


def native_kind(model: ArmModel) -> str:
    """Which device ``--driver sim`` simulates for ``model``: the first kind (registry
    order) whose section the model file has, or ``"generic"`` (a bus of simulated smart
    servos) for a model with none."""
    native = kinds_of(model)
    return native[0].name if native else "generic"


def simulated_line(kind: str) -> tuple[Any, Clock]:
    """A serial line to a lone simulated controller of ``kind`` (``emulated_kinds``) and
    its world's clock (for ``armkit servo --port emu``)."""
    from ._simulate import simulated_line as line

    return line(_emulated(kind))


def emulate(kind: str, model: ArmModel | None = None) -> Emulator:
    """A simulated controller of ``kind`` (``emulated_kinds``), driving ``model`` if given,
    in a real-time world on a pseudo-terminal: ``.port`` is its path.

    Raises:
        InputError: a kind that cannot be emulated.
    """
    from ._emulate import emulate as start

    return start(_emulated(kind), model)


def _emulated(name: str) -> Emulated:
    for kind in emulated_kinds():
        if kind.name == name and kind.emulate is not None:
            return kind.emulate
    names = ", ".join(kind.name for kind in emulated_kinds())
    raise InputError(f"cannot emulate {name!r}; choose one of {names}")


def simulated_bus(baudrate: int, retries: int = 3) -> DynamixelBus:
    """A bus of the OpenManipulator-X's five simulated XM430s (for ``dxl-scan --port emu``)."""
    from ._simulate import simulated_bus as bus

    return bus(baudrate, retries)


__all__ = [
    "Ask",
    "CalibrationRoutine",
    "DriverKind",
    "PortRule",
    "SimArm",
    "Trait",
    "World",
    "check_sim_port",
    "driver_kind",
    "driver_kinds",
    "driver_names",
    "emulate",
    "emulated_kinds",
    "forecaster",
    "kinds_of",
    "kinds_with",
    "listed",
    "native_kind",
    "open_driver",
    "sim_state_file",
    "world_of",
]
