"""What a driver kind is: one descriptor holding every part of it, each by reference.

A driver kind (``owi535``, ``ssc32``, ``maestro``, ``dynamixel``, ...) is one kind of
controller armkit drives. Its parts live on their own floors (the model file's
section in ``armkit.model``, the device in ``armkit.devices``, the driver in
``armkit.drivers``, the simulated device in ``armkit.sim``); its ``DriverKind``
names them all, and every place that needs to know the kinds reads the registry
(``armkit.connect.driver_kinds()``) instead of keeping a table of its own.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any, Literal, Protocol

if TYPE_CHECKING:
    from .._clock import Clock
    from ..drivers import Driver, Forecaster
    from ..drivers.servo import ServoBus
    from ..model import ArmModel, Section
    from ..sim import SimArm, World
    from ..sim.assembly import Persistence
    from ._rigs import Rig

Trait = Literal["timed", "hobby", "smart"]
"""``timed``: open-loop motors run for a time (no position read back); ``hobby``: hobby
servos set by PWM pulses (no position read back); ``smart``: serial-bus servos that
report their position and can go limp."""

PortRule = Literal["serial", "usb"]
"""How ``--port`` is read: ``serial``, a serial device (``/dev/ttyUSB0``) or ``emu``, and
needed; ``usb``, the name of the unit (its state file), optional."""

Ask = Callable[[str], str]
Say = Callable[[str], None]


class Opener(Protocol):
    """Opens the kind's driver for ``model`` on the real device at ``port``."""

    def __call__(self, model: ArmModel, port: str | None) -> Driver: ...


class Simulator(Protocol):
    """Builds the kind's simulated device in ``world`` for ``model``, wires it to a
    simulated arm (kept by ``keep``; every arm added goes into ``opened``) and opens the
    kind's real driver on it."""

    def __call__(
        self, model: ArmModel, world: World, keep: Persistence | None, opened: list[SimArm]
    ) -> Driver: ...


class Forecasting(Protocol):
    """The kind's forecasts for ``model`` with no device (``armkit.drivers.Forecaster``):
    what its driver's moves will take; ``unit`` names a unit whose own calibration
    times them (None: the model file's)."""

    def __call__(self, model: ArmModel, unit: str | None) -> Forecaster: ...


class Emulated(Protocol):
    """The kind's simulated controller in ``world``, driving ``model``'s simulated arm
    (None: a lone controller), for serving on a pseudo-terminal."""

    def __call__(self, model: ArmModel | None, world: World) -> Rig: ...


class Pulses(Protocol):
    """The kind's hobby-servo controller on ``line`` (a serial device path, or a simulated
    line with its ``clock``) as the servo driver's ``ServoBus``, for one raw pulse
    (``armkit servo``): ``channel`` and ``pulse`` [µs] are checked first (InputError
    naming the controller's range), before the port is opened."""

    def __call__(self, line: Any, clock: Clock | None, channel: int, pulse: float) -> ServoBus: ...


class Calibrator(Protocol):
    """Measures the unit behind ``driver`` with a person (``ask``, ``say``) and saves it;
    returns the file written."""

    def __call__(self, model: ArmModel, driver: Any, ask: Ask, say: Say) -> Path: ...


@dataclass(frozen=True)
class CalibrationRoutine:
    """How a kind's unit is calibrated.

    Attributes:
        run: the calibration routine.
        operator: on the simulated device, an automatic person answering the routine's
            questions (``ask``), or None where it would not know the answers (then
            calibration needs the real device, or ``--port emu`` and a person).
    """

    run: Calibrator
    operator: Callable[[Driver], Ask | None] | None = None


@dataclass(frozen=True)
class DriverKind:
    """One kind of controller: every part of it, by reference.

    Attributes:
        name: the driver's name (``--driver NAME``, the script's ``driver NAME``).
        device: what it is, for sentences (``"an SSC-32U"``).
        title: its short name, for lists (``"SSC-32"``).
        section: the model file's ``[drivers.*]`` table it reads (``armkit.model``).
        traits: what its motors are (``Trait``).
        port: how its ``--port`` is read (``PortRule``).
        open: its driver on the real device.
        forecast: its driver's forecasts without a device (``armkit check`` times with them).
        simulate: its driver on its simulated device.
        emulate: its simulated controller served on a pseudo-terminal, or None for a
            device that is not a serial one (the OWI-535's USB board).
        calibrate: how a unit is measured, or None where the model file's numbers are
            the unit's (a Dynamixel servo knows its own position).
        pulses: its controller taking one raw pulse (``armkit servo``), for a kind of
            hobby servos; None for the others.
    """

    name: str
    device: str
    title: str
    section: Section[Any]
    traits: frozenset[Trait]
    port: PortRule
    open: Opener
    forecast: Forecasting
    simulate: Simulator
    emulate: Emulated | None
    calibrate: CalibrationRoutine | None
    pulses: Pulses | None = None
