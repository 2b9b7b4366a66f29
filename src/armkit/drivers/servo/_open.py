"""Open a servo arm on an SSC-32 or a Maestro (``port="emu"``: on its emulator)."""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING

from ..._errors import DeviceError
from ...model import ArmModel
from ._arm import ServoArmDriver
from ._bus import MaestroBus, ServoBus, SSC32Bus
from ._config import ServoSetup, load_setup

if TYPE_CHECKING:
    from ...sim.ssc32_emulator import PtyEmulator


def open_ssc32(model: ArmModel, port: str | None) -> ServoArmDriver:
    """The servo driver for ``model`` on an SSC-32 at ``port``: a serial device, or
    ``"emu"`` for an emulator that lives as long as the driver.

    Raises:
        ModelError: the model's ``[drivers.ssc32]`` section or the unit's file is wrong.
        DeviceError: no port given, pyserial missing, or the board does not answer.
    """
    from ...devices.ssc32 import SSC32
    from ...sim.ssc32_emulator import SSC32Emulator

    setup = load_setup(model, "ssc32")

    def make_bus(path: str) -> ServoBus:
        return SSC32Bus(SSC32(path, setup.baudrate))

    return _open(model, port, setup, lambda: SSC32Emulator(setup.baudrate), make_bus)


def open_maestro(model: ArmModel, port: str | None) -> ServoArmDriver:
    """The servo driver for ``model`` on a Pololu Maestro at ``port`` (or ``"emu"``)."""
    from ...devices.maestro import Maestro
    from ...sim.maestro_emulator import MaestroEmulator

    setup = load_setup(model, "maestro")

    def make_bus(path: str) -> ServoBus:
        return MaestroBus(Maestro(path, setup.baudrate))

    return _open(model, port, setup, MaestroEmulator, make_bus)


def _open(
    model: ArmModel,
    port: str | None,
    setup: ServoSetup,
    make_emulator: Callable[[], PtyEmulator],
    make_bus: Callable[[str], ServoBus],
) -> ServoArmDriver:
    """Check everything, start the emulator if asked, open the port, read the servos."""
    if not port:
        raise DeviceError(
            "this driver needs a port: --port /dev/ttyUSB0 (your controller) or --port emu"
        )
    emulator = make_emulator() if port == "emu" else None
    try:
        bus = make_bus(emulator.port if emulator else port)
        try:
            on_close = emulator.close if emulator else None
            return ServoArmDriver(model, bus, setup.joints, setup.grip, on_close)
        except BaseException:
            bus.close()
            raise
    except BaseException:
        if emulator:
            emulator.close()
        raise
