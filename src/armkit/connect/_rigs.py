"""Simulated controllers wired to simulated arms: the device, its mounts, its world.

What only the factory knows, it says here: which channel or servo turns which
joint, taken from the driver's own calibration (the pulse tables of an SSC-32
or a Maestro, the tick mapping of a Dynamixel bus), so the simulated servos
answer the driver exactly as a unit calibrated like the model would.
"""

from __future__ import annotations

from dataclasses import dataclass

from .._errors import ArmkitError
from ..drivers import Forecaster
from ..drivers.dynamixel import DynamixelForecaster, dynamixel_points
from ..model import FEETECH_SECTION, ArmModel, DynamixelSection, dynamixel_section
from ..sim import SimArm, Truth, World
from ..sim.assembly import GRIPPER, ByteDevice, Mount, add_servo_arm
from ..sim.dynamixel import SimDynamixelBus

GENERIC_BAUD = 1_000_000
# A kind's driver and simulated device are imported by its rig function: a rig of one
# kind loads no other's (milliseconds of every command).


@dataclass
class Rig:
    """A simulated controller (``device``) driving ``arm`` (None: a lone controller)."""

    device: ByteDevice
    arm: SimArm | None
    baudrate: int
    config: DynamixelSection | None = None  # the Dynamixel setup used


def generic_forecaster(model: ArmModel) -> Forecaster:
    """The forecasts of the Dynamixel driver on the generic bus (``generic_config``)."""
    return DynamixelForecaster(model, generic_config(model))


def generic_config(model: ArmModel) -> DynamixelSection:
    """The generic bus's setup: servo IDs 1..dof, the gripper next (none if the model has
    no gripper), extended position mode."""
    return DynamixelSection(
        ids=tuple(range(1, model.dof + 1)),
        gripper_id=model.dof + 1 if model.gripper.present else None,
        baudrate=GENERIC_BAUD,
        gripper_ticks=(1024, 3072),
        operating_mode="extended",
    )


def servo_rig(model: ArmModel, world: World, kind: str, truth: Truth | None) -> Rig:
    """An SSC-32 (``kind="ssc32"``) or a Maestro driving ``model``'s servos through the
    model's pulse tables (and the unit's calibration file, if there is one)."""
    from ..drivers.servo import load_setup
    from ..sim.maestro import SimMaestro
    from ..sim.ssc32 import SimSSC32

    setup = load_setup(model, kind)
    device = SimSSC32(setup.baudrate) if kind == "ssc32" else SimMaestro()
    tables = list(enumerate(setup.joints))
    if setup.grip is not None:
        tables.append((GRIPPER, setup.grip))
    mounts = [Mount(t.channel, j, t.pulses_us, t.values) for j, t in tables]
    arm = add_servo_arm(world, model, device, mounts, truth=truth)
    arm.device = device
    if isinstance(device, SimSSC32):
        device.analog = arm.analog  # VA..VD read the arm's analog inputs
    else:  # a unit set up as the README's calibration flow says: each range widened
        for _, table in tables:
            device.configure(table.channel, min(table.pulses_us), max(table.pulses_us))
    return Rig(device, arm, setup.baudrate)


def dynamixel_rig(
    model: ArmModel, world: World, truth: Truth | None, config: DynamixelSection | None = None
) -> Rig:
    """XM430s on a Dynamixel bus driving ``model``'s joints and gripper, set up by its
    ``[drivers.dynamixel]`` table (or ``config``)."""
    cfg = config if config is not None else dynamixel_section(model)
    points = dynamixel_points(model, cfg)
    device = SimDynamixelBus(
        [sid for sid, *_ in points], clock=world.device_time, baudrate=cfg.baudrate
    )
    mounts = [Mount(sid, joint, ticks, values) for sid, joint, ticks, values in points]
    arm = add_servo_arm(world, model, device, mounts, truth=truth)
    arm.device = device
    return Rig(device, arm, cfg.baudrate, cfg)


def ssc32_rig(model: ArmModel | None, world: World) -> Rig:
    """An SSC-32 driving ``model``'s servos, or alone at 9600 baud (``model`` None)."""
    from ..sim.ssc32 import SimSSC32

    if model is None:
        return Rig(SimSSC32(9600), None, 9600)
    return servo_rig(model, world, "ssc32", None)


def maestro_rig(model: ArmModel | None, world: World) -> Rig:
    """A Maestro driving ``model``'s servos, or alone (``model`` None)."""
    from ..sim.maestro import SimMaestro

    if model is None:
        return Rig(SimMaestro(), None, 9600)
    return servo_rig(model, world, "maestro", None)


def dxl_rig(model: ArmModel | None, world: World) -> Rig:
    """XM430s on a Dynamixel bus driving ``model`` (its ``[drivers.dynamixel]`` table, or
    the generic setup for an arm with no driver table), or alone: the OpenManipulator-X's
    five XM430s (IDs 11..15) at 1,000,000 baud (``model`` None).

    Raises:
        ArmkitError: the model is driven by another kind of controller.
    """
    if model is None:
        return Rig(SimDynamixelBus(clock=world.device_time), None, GENERIC_BAUD)
    if "dynamixel" in model.drivers:
        return dynamixel_rig(model, world, None)
    if model.drivers:
        raise ArmkitError(
            f"{model.name} is driven by {', '.join(model.drivers)}, not a Dynamixel bus; "
            f"emulate that instead"
        )
    return dynamixel_rig(model, world, None, generic_config(model))


def feetech_rig(model: ArmModel | None, world: World, truth: Truth | None = None) -> Rig:
    """STS3215s on a Feetech bus driving ``model`` (its ``[drivers.feetech]`` table), or
    alone: the SO-101's six servos (IDs 1..6) at 1,000,000 baud (``model`` None).

    Raises:
        ModelError: the model has no ``[drivers.feetech]`` table.
    """
    from ..drivers.feetech import feetech_points
    from ..sim.feetech import SimFeetechBus

    if model is None:
        return Rig(SimFeetechBus(clock=world.device_time), None, GENERIC_BAUD)
    cfg = FEETECH_SECTION.of(model)
    points = feetech_points(model, cfg)
    device = SimFeetechBus(
        [sid for sid, *_ in points], clock=world.device_time, baudrate=cfg.baudrate
    )
    mounts = [Mount(sid, joint, ticks, values) for sid, joint, ticks, values in points]
    arm = add_servo_arm(world, model, device, mounts, truth=truth)
    arm.device = device
    return Rig(device, arm, cfg.baudrate)
