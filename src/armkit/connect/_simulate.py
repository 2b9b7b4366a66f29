"""The real drivers on simulated devices: build the device, wire it, open the driver on it.

Where the client library is installed the simulated device plugs in at its
lowest pluggable level (a pyusb backend; a ``serial.SerialBase`` port; a
``PortHandler`` under the dynamixel-sdk's own ``PacketHandler``); where it is
not, the same device class runs on the same simulated device through the
narrow interface armkit uses of the library (``ctrl_transfer``; ``read``/
``write``; armkit's own Protocol 2.0 client). The bytes are the same.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING, Any

from .._clock import Clock
from .._errors import DeviceError
from ..devices import PortHandler
from ..devices.dynamixel import DynamixelBus
from ..drivers import Driver
from ..drivers.dynamixel import DynamixelDriver
from ..model import ArmModel, DynamixelSection, dynamixel_section
from ..sim import SimArm, World, state_key
from ..sim.assembly import Persistence, Wire, serial_port
from ._kind import Emulated, Simulator
from ._rigs import dxl_rig, dynamixel_rig, feetech_rig, generic_config, servo_rig

if TYPE_CHECKING:
    from ..devices.owi535 import OwiDevice
    from ..sim.owi535 import SimOwiUsb

# Each kind's driver, device and simulated device are imported by its own simulate
# function below: opening one kind loads no other's (milliseconds of every command).


def simulate(model: ArmModel, build: Simulator, world: World | None, state: Path | None) -> Driver:
    """``model``'s driver on a simulated device, built by a driver kind's ``simulate`` part
    (``build``), in ``world`` (None: a new virtual-time world), its truth kept in
    ``state`` (None: in memory only)."""
    where = world or World()
    keep = Persistence(state, model, _what(model, state)) if state is not None else None
    opened: list[SimArm] = []
    try:
        driver = build(model, where, keep, opened)
    except BaseException:
        for arm in opened:
            where.remove_arm(arm.name)
        if keep is not None:
            keep.release()
        raise
    return driver


def _what(model: ArmModel, state: Path) -> str:
    source = f" ({model.source})" if model.source else ""
    return f"the simulated {model.name}{source}, state file {state},"


def _closing(world: World, arm: SimArm, keep: Persistence | None) -> Callable[[], None]:
    """What happens when the driver lets go of its device: the truth is written (kept)."""
    return keep.closer(world, arm) if keep is not None else lambda: None


def _servo(
    model: ArmModel,
    world: World,
    keep: Persistence | None,
    opened: list[SimArm],
    kind: str,
    opener: Callable[..., Driver],
) -> Driver:
    rig = servo_rig(model, world, kind, keep.truth if keep else None)
    assert rig.arm is not None
    opened.append(rig.arm)
    wire = Wire(rig.device, world, baudrate=rig.baudrate, timeout=0.1)
    wire.on_close(_closing(world, rig.arm, keep))
    return opener(model, serial_port(wire), clock=world.clock)


def _dynamixel(
    model: ArmModel,
    world: World,
    keep: Persistence | None,
    opened: list[SimArm],
    config: DynamixelSection | None = None,
) -> Driver:
    rig = dynamixel_rig(model, world, keep.truth if keep else None, config)
    assert rig.arm is not None
    opened.append(rig.arm)
    wire = Wire(rig.device, world, baudrate=rig.baudrate, timeout=0)
    wire.on_close(_closing(world, rig.arm, keep))
    bus = DynamixelBus.on_port(PortHandler(serial_port(wire), world.clock), clock=world.clock)
    return DynamixelDriver(model, bus, config=rig.config, clock=world.clock)


def simulate_generic(
    model: ArmModel, world: World, keep: Persistence | None, opened: list[SimArm]
) -> Driver:
    """An arm with no driver table: the Dynamixel driver on a generic bus of XM430s."""
    return _dynamixel(model, world, keep, opened, generic_config(model))


def simulate_owi535(
    model: ArmModel, world: World, keep: Persistence | None, opened: list[SimArm]
) -> Driver:
    import shutil
    import tempfile

    from ..drivers.timed import TimedDriver, state_path
    from ..sim.assembly import add_owi_arm
    from ..sim.owi535 import SimOwiUsb
    from ..sim.owi_sim import OwiSim

    arm, physics = add_owi_arm(world, model, truth=keep.truth if keep else None)
    opened.append(arm)
    board = SimOwiUsb(physics)
    arm.device = board
    board.on_close(_closing(world, arm, keep))
    if keep is not None:
        unit = "sim" if state_key(model) == model.name else f"sim-{state_key(model)}"
        path = state_path(unit)
    else:
        scratch = Path(tempfile.mkdtemp(prefix="armkit-owi-"))
        board.on_close(lambda: shutil.rmtree(scratch, ignore_errors=True))
        unit, path = "sim", scratch / "sim.json"
    driver = TimedDriver(model, _usb_device(board), world.clock, path, unit, durable=False)
    driver.simulation = OwiSim(world.clock, physics, board, world)
    return driver


def _usb_device(board: SimOwiUsb) -> OwiDevice:
    """The board as pyusb sees it where pyusb is installed, else directly."""
    import importlib.util

    from ..devices.owi535 import attach, open_device

    if importlib.util.find_spec("usb") is None:
        return attach(board, board.close)
    from ..sim.owi_usb import OwiUsbBackend

    return open_device(OwiUsbBackend(board=board))


def simulated_line(emulated: Emulated) -> tuple[Any, Clock]:
    """A serial line to a lone simulated controller (a driver kind's ``emulate`` part with
    no arm on it) in a new world, and that world's clock: for the raw device commands
    (``armkit servo``)."""
    world = World()
    rig = emulated(None, world)
    return serial_port(Wire(rig.device, world, baudrate=rig.baudrate, timeout=0.1)), world.clock


def simulated_bus(baudrate: int, retries: int = 3) -> DynamixelBus:
    """A Dynamixel bus with the OpenManipulator-X's five simulated XM430s (IDs 11..15)
    and no arm on them: for ``armkit dxl-scan --port emu``."""
    world = World()
    wire = Wire(dxl_rig(None, world).device, world, baudrate=baudrate, timeout=0)
    port = PortHandler(serial_port(wire), world.clock)
    if not port.setBaudRate(baudrate):
        raise DeviceError(
            f"baud rate {baudrate} is not supported by the dynamixel-sdk; use one of"
            " 57600, 115200, 1000000, 2000000, 3000000, 4000000"
        )
    return DynamixelBus.on_port(port, clock=world.clock, retries=retries)


def simulate_ssc32(
    model: ArmModel, world: World, keep: Persistence | None, opened: list[SimArm]
) -> Driver:
    """The servo driver on a simulated SSC-32 driving ``model``'s servos."""
    from ..drivers.servo import open_ssc32

    return _servo(model, world, keep, opened, "ssc32", open_ssc32)


def simulate_maestro(
    model: ArmModel, world: World, keep: Persistence | None, opened: list[SimArm]
) -> Driver:
    """The servo driver on a simulated Maestro driving ``model``'s servos."""
    from ..drivers.servo import open_maestro

    return _servo(model, world, keep, opened, "maestro", open_maestro)


def simulate_dynamixel(
    model: ArmModel, world: World, keep: Persistence | None, opened: list[SimArm]
) -> Driver:
    """The Dynamixel driver on simulated XM430s set up by ``[drivers.dynamixel]``."""
    return _dynamixel(model, world, keep, opened, dynamixel_section(model))


def simulate_feetech(
    model: ArmModel, world: World, keep: Persistence | None, opened: list[SimArm]
) -> Driver:
    """The Feetech driver on simulated STS3215s set up by ``[drivers.feetech]``, through
    Feetech's ``scservo_sdk`` on armkit's SDK-style port handler."""
    from ..devices.feetech import FeetechBus
    from ..drivers.feetech import FeetechDriver

    rig = feetech_rig(model, world, keep.truth if keep else None)
    assert rig.arm is not None
    opened.append(rig.arm)
    wire = Wire(rig.device, world, baudrate=rig.baudrate, timeout=0)
    wire.on_close(_closing(world, rig.arm, keep))
    bus = FeetechBus.on_port(PortHandler(serial_port(wire), world.clock), clock=world.clock)
    return FeetechDriver(model, bus, clock=world.clock)
