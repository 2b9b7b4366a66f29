"""Open a servo arm on an SSC-32 or a Maestro: a serial device path, or an open serial line."""

from __future__ import annotations

from collections.abc import Callable

from ..._clock import Clock
from ..._errors import DeviceError
from ...devices import SerialPort
from ...model import ArmModel
from ._arm import ServoArmDriver
from ._bus import MaestroBus, ServoBus, SSC32Bus
from ._config import ServoSetup, load_setup


def open_ssc32(
    model: ArmModel,
    port: str | SerialPort | None,
    *,
    clock: Clock | None = None,
    on_close: Callable[[], None] | None = None,
) -> ServoArmDriver:
    """The servo driver for ``model`` on an SSC-32 at ``port`` (a serial device path, or an
    open ``SerialPort``: a simulated line). ``clock``: real time unless given.

    Raises:
        ModelError: the model's ``[drivers.ssc32]`` section or the unit's file is wrong.
        DeviceError: no port given, pyserial missing, or the board does not answer.
    """
    from ...devices.ssc32 import SSC32

    setup = load_setup(model, "ssc32")

    def make_bus(line: str | SerialPort) -> ServoBus:
        return SSC32Bus(SSC32(line, setup.baudrate, clock=clock))

    return _open(model, port, setup, make_bus, clock, on_close)


def open_maestro(
    model: ArmModel,
    port: str | SerialPort | None,
    *,
    clock: Clock | None = None,
    on_close: Callable[[], None] | None = None,
) -> ServoArmDriver:
    """The servo driver for ``model`` on a Pololu Maestro at ``port`` (as ``open_ssc32``)."""
    from ...devices.maestro import Maestro

    setup = load_setup(model, "maestro")

    def make_bus(line: str | SerialPort) -> ServoBus:
        return MaestroBus(Maestro(line, setup.baudrate, clock=clock))

    return _open(model, port, setup, make_bus, clock, on_close)


def ssc32_pulses(
    line: str | SerialPort, clock: Clock | None, channel: int, pulse: float
) -> ServoBus:
    """An SSC-32 on ``line`` at its factory 9600 baud for one raw ``pulse`` [µs] on
    ``channel`` (both checked before the port opens: channels 0..31, 500..2500 µs)."""
    from ...devices import ssc32

    ssc32.check_channel(channel)
    ssc32.check_pulse(channel, round(pulse))
    return SSC32Bus(ssc32.SSC32(line, clock=clock))


def maestro_pulses(
    line: str | SerialPort, clock: Clock | None, channel: int, pulse: float
) -> ServoBus:
    """A Maestro on ``line`` for one raw ``pulse`` [µs] on ``channel`` (both checked
    before the port opens: channels 0..23, a target it takes)."""
    from ...devices import maestro, ssc32

    ssc32.check_channel(channel, maestro.CHANNELS)
    maestro.target_bytes(channel, pulse)
    return MaestroBus(maestro.Maestro(line, clock=clock))


def _open(
    model: ArmModel,
    port: str | SerialPort | None,
    setup: ServoSetup,
    make_bus: Callable[[str | SerialPort], ServoBus],
    clock: Clock | None,
    on_close: Callable[[], None] | None,
) -> ServoArmDriver:
    """Check everything, open the port, read the servos."""
    if not port:
        raise DeviceError(
            "this driver needs a port: --port /dev/ttyUSB0 (your controller) or --port emu"
        )
    bus = make_bus(port)
    try:
        return ServoArmDriver(
            model, bus, setup.joints, setup.grip, on_close, clock, settle_s=setup.settle_s
        )
    except BaseException:
        bus.close()
        raise
