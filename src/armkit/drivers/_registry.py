"""Driver names -> the module that opens them on real hardware, imported only when asked for.

Each entry points at a function ``open_driver(model, port) -> Driver`` in a
module of armkit; device SDKs are imported inside those modules, never here.
Simulated devices are the factory's business (``armkit.connect``): drivers
never know about them.
"""

from __future__ import annotations

import importlib
from typing import Protocol

from .._errors import DeviceError, InputError
from ..model import ArmModel
from ._driver import Driver


class _Opener(Protocol):
    def __call__(self, model: ArmModel, port: str | None) -> Driver: ...


# name -> (module, function, one-line help)
DRIVERS: dict[str, tuple[str, str, str]] = {
    "owi535": ("armkit.drivers.timed", "open_driver", "OWI-535 over USB (pyusb; usb extra)"),
    "ssc32": (
        "armkit.drivers.servo",
        "open_ssc32",
        "hobby servos via a Lynxmotion SSC-32 (serial extra)",
    ),
    "maestro": (
        "armkit.drivers.servo",
        "open_maestro",
        "hobby servos via a Pololu Maestro (serial extra)",
    ),
    "dynamixel": (
        "armkit.drivers.dynamixel",
        "open_driver",
        "Dynamixel Protocol 2.0 (dynamixel extra)",
    ),
}


def driver_names() -> list[str]:
    """Names of the drivers of real hardware."""
    return list(DRIVERS)


def open_driver(model: ArmModel, name: str, port: str | None = None) -> Driver:
    """Open the driver called ``name`` for ``model`` on the real device at ``port`` (the
    factory, ``armkit.connect.open_driver``, calls this for real hardware).

    Raises:
        ValueError: unknown driver name (the message lists the known ones).
        DeviceError: the driver exists but is not available or the device is not there.
    """
    if name not in DRIVERS:
        raise InputError(f"unknown driver {name!r}; drivers are sim, {', '.join(DRIVERS)}")
    module_name, func_name, _ = DRIVERS[name]
    try:
        module = importlib.import_module(module_name)
    except ModuleNotFoundError as exc:
        raise DeviceError(f"driver {name!r} is not available: {exc}") from None
    opener: _Opener = getattr(module, func_name)
    return opener(model, port)
