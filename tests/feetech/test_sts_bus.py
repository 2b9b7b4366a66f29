"""The emulated Feetech bus through Feetech's own SDK (scservo_sdk's PacketHandler(0)) and
through armkit's stand-in client: the same bytes, and the STS3215 as its table says.

Sources: Feetech's communication protocol (the FT-SCS protocol of the SMS/STS series:
instruction packet FF FF ID LEN INST PARAMS CHK, checksum ~(ID+LEN+INST+PARAMS)) and its
examples "PING ID 1: FF FF 01 02 01 FB", "READ ID 1 position (address 0x38, 2 bytes):
FF FF 01 04 02 38 02 BE"; the SMS/STS memory table (``armkit.devices.sts3215``)."""

from __future__ import annotations

from typing import Any

import pytest

from armkit.devices import PortHandler
from armkit.devices import _scs_protocol as own
from armkit.devices import scs_packet as scs
from armkit.devices import sts3215 as sts
from armkit.devices.feetech import FeetechBus
from armkit.sim import World
from armkit.sim.assembly import Wire, serial_port
from armkit.sim.feetech import SimFeetechBus

scservo_sdk = pytest.importorskip("scservo_sdk")
CLIENTS = {"sdk": scservo_sdk, "armkit": own}


@pytest.fixture(params=sorted(CLIENTS))
def rig(request: Any) -> Any:
    world = World()
    device = SimFeetechBus(clock=world.device_time)
    wire = Wire(device, world, baudrate=1_000_000, timeout=0)
    port = PortHandler(serial_port(wire), world.clock)
    bus = FeetechBus.on_port(port, clock=world.clock, sdk=CLIENTS[request.param])
    yield device, bus, world
    bus.close()
    world.close()


def test_checksum_of_the_protocol_examples() -> None:
    assert scs.frame(1, scs.Inst.PING) == bytes.fromhex("ff ff 01 02 01 fb")
    assert scs.frame(1, scs.Inst.READ, bytes((0x38, 2))) == bytes.fromhex("ff ff 01 04 02 38 02 be")


def test_ping_is_the_examples_bytes_and_answers_the_model_number(rig: Any) -> None:
    device, bus, _ = rig
    assert bus.ping(1) == sts.MODEL_NUMBER == 777
    # the SDK's ping is PING, then READ of Model Number (3, 2 bytes)
    assert list(device.frames)[-2:] == [
        bytes.fromhex("ff ff 01 02 01 fb"),
        scs.frame(1, scs.Inst.READ, bytes((3, 2))),
    ]
    assert bus.scan(range(10)) == dict.fromkeys(range(1, 7), 777)


def test_read_present_position_is_the_examples_bytes(rig: Any) -> None:
    device, bus, _ = rig
    assert bus.read(1, "Present Position") == sts.CENTER_STEP
    assert device.frames[-1] == bytes.fromhex("ff ff 01 04 02 38 02 be")


def test_write_then_sync_read_and_the_move_on_time(rig: Any) -> None:
    _device, bus, world = rig
    bus.set_torque([1, 2], True)
    block = bytes((0,)) + (3000).to_bytes(2, "little") + bytes(2) + (1000).to_bytes(2, "little")
    bus.write_block(41, 7, {1: block})  # Acceleration 0, Goal 3000, Goal Velocity 1000 step/s
    assert bus.sync_read("Moving", [1, 2]) == {1: 1, 2: 0}
    world.clock.sleep(0.95)  # 952 steps at 1000 step/s: 0.952 s
    assert bus.read(1, "Moving") == 1
    world.clock.sleep(0.01)
    assert bus.sync_read("Present Position", [1, 2, 3]) == {1: 3000, 2: 2048, 3: 2048}
    assert bus.read(1, "Moving") == 0


def test_sign_magnitude_registers() -> None:
    offset = sts.register("Homing Offset")
    assert offset.encode(-5) == bytes((5, 0x08))  # bit 11
    assert offset.decode(bytes((5, 0x08))) == -5
    velocity = sts.register("Goal Velocity")
    assert velocity.encode(-1000) == (1000 | 0x8000).to_bytes(2, "little")  # bit 15
    assert velocity.from_raw(1000 | 0x8000) == -1000


def test_eeprom_is_kept_through_a_power_cycle_only_when_unlocked(rig: Any) -> None:
    device, bus, _ = rig
    servo = device.servos[1]
    bus.write(1, "Max Temperature Limit", 60)  # Lock is 1 at power on: effective, not kept
    assert bus.read(1, "Max Temperature Limit") == 60
    servo.power_cycle()
    assert bus.read(1, "Max Temperature Limit") == 70
    bus.set_eeprom(1, "Max Temperature Limit", 60)  # Lock 0, write, Lock 1
    servo.power_cycle()
    assert bus.read(1, "Max Temperature Limit") == 60


def test_values_outside_the_table_are_not_taken(rig: Any) -> None:
    _device, bus, _ = rig
    bus.write(1, "Max Torque Limit", 1001)  # range 0..1000: the status says nothing
    assert bus.read(1, "Max Torque Limit") == 1000
    bus.write(1, "ID", 254)  # 254 is the broadcast ID
    assert bus.ping(1) == 777
    bus.set_eeprom(1, "Max Position Limit", 3000)
    bus.set_torque([1], True)
    bus.write(1, "Goal Position", 4000)  # beyond Max Position Limit: held to it
    assert bus.read(1, "Goal Position") == 3000


def test_reg_write_waits_for_action(rig: Any) -> None:
    _device, bus, world = rig
    bus.set_torque([1, 2], True)
    bus.reg_write(1, "Goal Position", 2100)
    bus.reg_write(2, "Goal Position", 2000)
    world.clock.sleep(0.2)
    assert bus.sync_read("Goal Position", [1, 2]) == {1: 2048, 2: 2048}
    bus.action()
    world.clock.sleep(0.2)
    assert bus.sync_read("Present Position", [1, 2]) == {1: 2100, 2: 2000}


def test_both_clients_send_the_same_bytes() -> None:
    sent = {}
    for name, client in CLIENTS.items():
        world = World()
        device = SimFeetechBus(clock=world.device_time)
        port = PortHandler(
            serial_port(Wire(device, world, baudrate=1_000_000, timeout=0)), world.clock
        )
        bus = FeetechBus.on_port(port, clock=world.clock, sdk=client)
        bus.ping(2)
        bus.write(2, "Torque Enable", 1)
        bus.sync_write("Goal Position", {1: 2000, 2: 2100})
        bus.sync_read("Present Position", [1, 2])
        bus.reg_write(3, "Goal Position", 1000)
        bus.action()
        sent[name] = list(device.frames)
        bus.close()
        world.close()
    assert sent["sdk"] == sent["armkit"]


def test_overload_is_in_every_status_and_named(rig: Any) -> None:
    device, bus, _ = rig
    device.inject(1, "overload")
    with pytest.raises(Exception, match="servo 1: overload"):
        bus.read(1, "Present Position")
