"""The registry of driver kinds: one ``DriverKind`` entry each, read by every place that
needs to know the kinds (the factory, ``--driver``, ``emulate``, ``calibrate``,
``servo``, the script's ``driver`` line, music, teach).

Adding a controller is its parts on their floors and one entry here (see
docs/adding-a-controller.md). The parts are referenced by small functions that
import the real one when called, so that reading the registry (``armkit --help``)
loads no driver, device or simulator.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Any

from .._errors import InputError
from ..model import (
    DYNAMIXEL_SECTION,
    FEETECH_SECTION,
    MAESTRO_SECTION,
    OWI535_SECTION,
    SSC32_SECTION,
)
from ._kind import Ask, CalibrationRoutine, DriverKind, Say, Trait

if TYPE_CHECKING:
    from .._clock import Clock
    from ..drivers import Driver, Forecaster
    from ..drivers.servo import ServoBus
    from ..model import ArmModel
    from ..sim import SimArm, World
    from ..sim.assembly import Persistence
    from ._rigs import Rig

# The OWI-535: four DC motors and a gripper run for a time from a USB board.


def _open_owi535(model: ArmModel, port: str | None) -> Driver:
    from ..drivers.timed import open_owi535

    return open_owi535(model, port)


def _forecast_owi535(model: ArmModel, unit: str | None) -> Forecaster:
    from ..drivers.timed import TimedForecaster, default_timing, load_state, state_path

    path = state_path(unit or "default")
    timing = load_state(path).timing if path.exists() else default_timing(model)
    return TimedForecaster(model, timing)


def _simulate_owi535(
    model: ArmModel, world: World, keep: Persistence | None, opened: list[SimArm]
) -> Driver:
    from ._simulate import simulate_owi535

    return simulate_owi535(model, world, keep, opened)


def _calibrate_owi535(model: ArmModel, driver: Any, ask: Ask, say: Say) -> Path:
    from ..drivers.timed import calibrate_owi535

    return calibrate_owi535(model, driver, ask, say)


def _owi535_operator(driver: Driver) -> Ask | None:
    from ..sim.owi_operator import auto_operator

    operator = auto_operator(driver)
    return operator.ask if operator is not None else None


# Hobby servos on an SSC-32 or a Maestro, through pulse tables.


def _open_ssc32(model: ArmModel, port: str | None) -> Driver:
    from ..drivers.servo import open_ssc32

    return open_ssc32(model, port)


def _open_maestro(model: ArmModel, port: str | None) -> Driver:
    from ..drivers.servo import open_maestro

    return open_maestro(model, port)


def _forecast_ssc32(model: ArmModel, unit: str | None) -> Forecaster:
    from ..drivers.servo import servo_forecaster

    return servo_forecaster(model, "ssc32")


def _forecast_maestro(model: ArmModel, unit: str | None) -> Forecaster:
    from ..drivers.servo import servo_forecaster

    return servo_forecaster(model, "maestro")


def _simulate_ssc32(
    model: ArmModel, world: World, keep: Persistence | None, opened: list[SimArm]
) -> Driver:
    from ._simulate import simulate_ssc32

    return simulate_ssc32(model, world, keep, opened)


def _simulate_maestro(
    model: ArmModel, world: World, keep: Persistence | None, opened: list[SimArm]
) -> Driver:
    from ._simulate import simulate_maestro

    return simulate_maestro(model, world, keep, opened)


def _emulate_ssc32(model: ArmModel | None, world: World) -> Rig:
    from ._rigs import ssc32_rig

    return ssc32_rig(model, world)


def _emulate_maestro(model: ArmModel | None, world: World) -> Rig:
    from ._rigs import maestro_rig

    return maestro_rig(model, world)


def _pulses_ssc32(line: Any, clock: Clock | None, channel: int, pulse: float) -> ServoBus:
    from ..drivers.servo import ssc32_pulses

    return ssc32_pulses(line, clock, channel, pulse)


def _pulses_maestro(line: Any, clock: Clock | None, channel: int, pulse: float) -> ServoBus:
    from ..drivers.servo import maestro_pulses

    return maestro_pulses(line, clock, channel, pulse)


def _calibrate_servos(model: ArmModel, driver: Any, ask: Ask, say: Say) -> Path:
    from ..drivers.servo import calibrate_servos

    return calibrate_servos(model, driver, ask, say)


# Dynamixel smart servos on one Protocol 2.0 bus.


def _open_dynamixel(model: ArmModel, port: str | None) -> Driver:
    from ..drivers.dynamixel import open_dynamixel

    return open_dynamixel(model, port)


def _forecast_dynamixel(model: ArmModel, unit: str | None) -> Forecaster:
    from ..drivers.dynamixel import DynamixelForecaster
    from ..model import dynamixel_section

    return DynamixelForecaster(model, dynamixel_section(model))


def _simulate_dynamixel(
    model: ArmModel, world: World, keep: Persistence | None, opened: list[SimArm]
) -> Driver:
    from ._simulate import simulate_dynamixel

    return simulate_dynamixel(model, world, keep, opened)


def _emulate_dynamixel(model: ArmModel | None, world: World) -> Rig:
    from ._rigs import dxl_rig

    return dxl_rig(model, world)


# Feetech STS3215 smart servos on one bus (the SO-101, SO-100).


def _open_feetech(model: ArmModel, port: str | None) -> Driver:
    from ..drivers.feetech import open_feetech

    return open_feetech(model, port)


def _forecast_feetech(model: ArmModel, unit: str | None) -> Forecaster:
    from ..drivers.feetech import FeetechForecaster, unit_config

    cfg = FEETECH_SECTION.of(model)
    real = unit is not None and unit != "sim"  # a unit's file calibrates its real port
    return FeetechForecaster(model, unit_config(model, cfg) if real else cfg)


def _calibrate_feetech(model: ArmModel, driver: Any, ask: Ask, say: Say) -> Path:
    from ..drivers.feetech import calibrate_feetech

    return calibrate_feetech(model, driver, ask, say)


def _feetech_operator(driver: Driver) -> Ask | None:
    from ..sim.feetech_operator import FeetechOperator

    world = getattr(getattr(driver, "clock", None), "world", None)
    arm = world.arm() if world is not None else None
    return FeetechOperator(arm).ask if arm is not None else None


def _simulate_feetech(
    model: ArmModel, world: World, keep: Persistence | None, opened: list[SimArm]
) -> Driver:
    from ._simulate import simulate_feetech

    return simulate_feetech(model, world, keep, opened)


def _emulate_feetech(model: ArmModel | None, world: World) -> Rig:
    from ._rigs import feetech_rig

    return feetech_rig(model, world)


KINDS: tuple[DriverKind, ...] = (
    DriverKind(
        name="owi535",
        device="an OWI-535's USB board",
        title="OWI-535",
        section=OWI535_SECTION,
        traits=frozenset({"timed"}),
        port="usb",
        open=_open_owi535,
        forecast=_forecast_owi535,
        simulate=_simulate_owi535,
        emulate=None,
        calibrate=CalibrationRoutine(_calibrate_owi535, operator=_owi535_operator),
    ),
    DriverKind(
        name="ssc32",
        device="an SSC-32U",
        title="SSC-32",
        section=SSC32_SECTION,
        traits=frozenset({"hobby"}),
        port="serial",
        open=_open_ssc32,
        forecast=_forecast_ssc32,
        simulate=_simulate_ssc32,
        emulate=_emulate_ssc32,
        calibrate=CalibrationRoutine(_calibrate_servos),
        pulses=_pulses_ssc32,
    ),
    DriverKind(
        name="maestro",
        device="a Pololu Maestro",
        title="Maestro",
        section=MAESTRO_SECTION,
        traits=frozenset({"hobby"}),
        port="serial",
        open=_open_maestro,
        forecast=_forecast_maestro,
        simulate=_simulate_maestro,
        emulate=_emulate_maestro,
        calibrate=CalibrationRoutine(_calibrate_servos),
        pulses=_pulses_maestro,
    ),
    DriverKind(
        name="dynamixel",
        device="a Dynamixel bus",
        title="Dynamixel bus",
        section=DYNAMIXEL_SECTION,
        traits=frozenset({"smart"}),
        port="serial",
        open=_open_dynamixel,
        forecast=_forecast_dynamixel,
        simulate=_simulate_dynamixel,
        emulate=_emulate_dynamixel,
        calibrate=None,
    ),
    DriverKind(
        name="feetech",
        device="a Feetech bus",
        title="Feetech bus",
        section=FEETECH_SECTION,
        traits=frozenset({"smart"}),
        port="serial",
        open=_open_feetech,
        forecast=_forecast_feetech,
        simulate=_simulate_feetech,
        emulate=_emulate_feetech,
        calibrate=CalibrationRoutine(_calibrate_feetech, operator=_feetech_operator),
    ),
)


def driver_kinds() -> tuple[DriverKind, ...]:
    """Every driver kind, registry order (read at each call: the registry is ``KINDS``)."""
    return KINDS


def kind_names() -> list[str]:
    """The names of the driver kinds, registry order."""
    return [kind.name for kind in driver_kinds()]


def driver_kind(name: str) -> DriverKind:
    """The kind called ``name``.

    Raises:
        InputError: no such kind (the message lists them).
    """
    for kind in driver_kinds():
        if kind.name == name:
            return kind
    raise InputError(f"unknown driver {name!r}; drivers are sim, {', '.join(kind_names())}")


def kinds_with(trait: Trait) -> tuple[DriverKind, ...]:
    """The kinds whose motors have ``trait``, registry order."""
    return tuple(kind for kind in driver_kinds() if trait in kind.traits)


def kinds_of(model: ArmModel) -> tuple[DriverKind, ...]:
    """The kinds ``model``'s file has a section for, registry order."""
    return tuple(kind for kind in driver_kinds() if kind.section.name in model.drivers)


def emulated_kinds() -> tuple[DriverKind, ...]:
    """The kinds whose simulated controller can be served on a pseudo-terminal."""
    return tuple(kind for kind in driver_kinds() if kind.emulate is not None)


def listed(words: list[str], last: str = "or") -> str:
    """``"ssc32, maestro or dynamixel"``: words in a sentence."""
    return words[0] if len(words) == 1 else f"{', '.join(words[:-1])} {last} {words[-1]}"
