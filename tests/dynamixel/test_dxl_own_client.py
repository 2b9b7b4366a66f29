"""armkit's own Protocol 2.0 client (for when the dynamixel-sdk is not installed) sends
the SDK's bytes and reads the same results, faults included."""

from __future__ import annotations

from typing import Any

import pytest

from armkit._errors import DeviceError
from armkit.devices._dxl_protocol import PortHandler
from armkit.devices._dxl_sdk import Protocol, own_protocol, sdk_protocol
from armkit.devices.dynamixel import DynamixelBus
from armkit.sim import World
from armkit.sim._wire import Wire, serial_port
from armkit.sim.dynamixel import SimDynamixelBus

pytest.importorskip("dynamixel_sdk")


def session(protocol: Protocol) -> tuple[list[Any], list[bytes]]:
    """One fixed conversation with five simulated XM430s: (results, frames on the wire)."""
    world = World()
    device = SimDynamixelBus(clock=world.now)
    port = PortHandler(serial_port(Wire(device, world, baudrate=1_000_000, timeout=0)), world.clock)
    bus = DynamixelBus.on_port(port, clock=world.clock, retries=1, protocol=protocol)
    results: list[Any] = [bus.ping(11), bus.scan(range(9, 17))]
    bus.set_operating_mode(12, 4)
    bus.set_time_based([11, 12, 13, 14], True)
    bus.set_torque([11, 12, 13, 14, 15], True)
    bus.set_profiles({sid: (100, 400) for sid in (11, 12, 13, 14)})
    bus.sync_write("Goal Position", {11: 2100, 12: -3000, 13: 2000, 14: 4095})
    world.advance(0.5)
    results += [bus.read_states([11, 12, 13, 14]), bus.sync_read("Moving", [11, 12])]
    results.append(bus.read(13, "Present Position"))
    for sid, fault in ((13, "drop"), (14, "corrupt"), (11, "late")):
        device.inject(sid, fault)
        results.append(bus.read(sid, "Goal Position"))
    device.inject(12, "vanish")
    with pytest.raises(DeviceError) as info:
        bus.read(12, "Present Position")
    results.append(str(info.value))
    bus.reboot(14)
    results += [bus.read(14, "Torque Enable"), world.now()]
    return results, list(device.frames)


def test_same_bytes_and_same_results_as_the_sdk() -> None:
    with_sdk, sdk_frames = session(sdk_protocol())
    with_own, own_frames = session(own_protocol())
    assert own_frames == sdk_frames and len(sdk_frames) > 40
    assert with_own == with_sdk
    assert with_sdk[0] == 1020 and with_sdk[1] == {11: 1020, 12: 1020, 13: 1020, 14: 1020, 15: 1020}
    assert "servo 12: READ Present Position failed after 2 tries: no reply" in with_sdk[-3]
