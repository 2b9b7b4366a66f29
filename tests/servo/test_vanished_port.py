"""Issue 10, servo buses: a port that disappears (the USB adapter pulled out) is a
DeviceError naming the port on all three buses, and under ``with Arm`` it is that
first error the user sees, not the one ``stop()`` meets afterwards."""

from __future__ import annotations

from typing import Any

import pytest

from armkit import Arm
from armkit._errors import DeviceError
from armkit.connect._rigs import dynamixel_rig, servo_rig
from armkit.devices._dxl_protocol import PortHandler
from armkit.devices.dynamixel import DynamixelBus
from armkit.drivers.dynamixel import DynamixelDriver
from armkit.drivers.servo import open_maestro, open_ssc32
from armkit.model import ArmModel, load_model
from armkit.sim import World
from armkit.sim._wire import Wire, serial_port

pytest.importorskip("serial")


def rig(kind: str) -> tuple[ArmModel, Any, Wire]:
    """The arm's real driver on a simulated controller, and the line to pull out."""
    world = World()
    if kind == "dynamixel":
        model = load_model("openmanipulator_x")
        r = dynamixel_rig(model, world, None)
        wire = Wire(r.device, world, baudrate=r.baudrate, timeout=0)
        bus = DynamixelBus.on_port(PortHandler(serial_port(wire), world.clock), clock=world.clock)
        return model, DynamixelDriver(model, bus, config=r.config, clock=world.clock), wire
    model = load_model("lynx6")
    r = servo_rig(model, world, kind, None)
    wire = Wire(r.device, world, baudrate=r.baudrate, timeout=0.1)
    opener = open_ssc32 if kind == "ssc32" else open_maestro
    return model, opener(model, serial_port(wire), clock=world.clock), wire


@pytest.mark.parametrize("kind", ["ssc32", "maestro", "dynamixel"])
def test_a_vanished_port_is_a_device_error_naming_it(kind: str) -> None:
    model, driver, wire = rig(kind)
    arm = Arm(model, driver)
    arm.home()
    wire.unplug()
    with pytest.raises(DeviceError, match=r"on sim://\w+: .*the port has gone"):
        arm.turn_by(model.joint_names[0], 10.0)
    with pytest.raises(DeviceError, match=r"sim://"):
        arm.close()


@pytest.mark.parametrize("kind", ["ssc32", "maestro", "dynamixel"])
def test_with_arm_raises_the_first_error_not_stops(kind: str) -> None:
    model, driver, wire = rig(kind)
    with pytest.raises(DeviceError) as info, Arm(model, driver) as arm:
        arm.home()
        wire.unplug()
        arm.turn_by(model.joint_names[0], 10.0)
    assert "the port has gone" in str(info.value)
    assert info.value.__context__ is None or not isinstance(info.value.__context__, DeviceError)
    assert any("stopping the arm afterwards failed" in n for n in info.value.__notes__)


def test_the_cli_shows_the_first_error_in_one_line(
    monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str], tmp_path: Any
) -> None:
    """The Maestro's port vanishes at the move: the move's own error (its position query)
    is the one line the user reads, not stop()'s (a write) that follows it."""
    from armkit.cli import main

    monkeypatch.setenv("ARMKIT_CONFIG_DIR", str(tmp_path))
    _, driver, wire = rig("maestro")
    move = driver.move

    def unplugged_move(*args: Any, **kwargs: Any) -> None:
        wire.unplug()
        move(*args, **kwargs)

    monkeypatch.setattr(driver, "move", unplugged_move)
    monkeypatch.setattr("armkit.connect.open_driver", lambda *a, **k: driver)
    code = main(["--arm", "lynx6", "joints", "100", "90", "90", "90", "90"])
    err = capsys.readouterr().err.strip()
    assert code != 0 and len(err.splitlines()) == 1
    assert err.startswith("armkit: error: Maestro on sim://maestro: reset the input buffer failed")
