"""Byte-exact control transfers for every command, through pyusb to the simulated device."""

from __future__ import annotations

import math

import numpy as np
import pytest
from owi_wire import sent

from armkit.devices.owi535 import decode, encode
from armkit.drivers.timed import TimedDriver
from armkit.sim.owi_sim import OwiSim
from armkit.sim.owi_usb import Transfer

# 000's Tables 1-3: (motor, direction) -> the 3 bytes that run it (light off)
SEED_TABLE = {
    ("gripper", -1): "010000",
    ("gripper", +1): "020000",
    ("wrist", -1): "040000",
    ("wrist", +1): "080000",
    ("elbow", -1): "100000",
    ("elbow", +1): "200000",
    ("shoulder", -1): "400000",
    ("shoulder", +1): "800000",
    ("base", +1): "000100",
    ("base", -1): "000200",
}


@pytest.mark.parametrize(("motion", "hexbytes"), list(SEED_TABLE.items()))
def test_encode_matches_seed_table(motion: tuple[str, int], hexbytes: str) -> None:
    assert encode({motion[0]: motion[1]}, light=False).hex() == hexbytes
    assert decode(bytes.fromhex(hexbytes)) == ({motion[0]: motion[1]}, False)


def test_flags_or_together_base_on_byte_1_light_on_byte_2() -> None:
    data = encode({"gripper": -1, "elbow": -1, "base": -1}, light=True)
    assert data.hex() == "110201"  # 000: 0x11 = gripper close + elbow backwards


def test_base_reversed_swaps_byte_1() -> None:
    assert encode({"base": 1}, light=False, base_reversed=True).hex() == "000200"


def test_bad_motor_or_direction_is_refused() -> None:
    with pytest.raises(ValueError, match="unknown OWI-535 motor"):
        encode({"thumb": 1}, light=False)
    with pytest.raises(ValueError, match="direction"):
        encode({"base": 2}, light=False)


@pytest.mark.parametrize(("motion", "hexbytes"), list(SEED_TABLE.items()))
def test_every_timed_turn_on_the_wire(
    driver: TimedDriver, sim: OwiSim, motion: tuple[str, int], hexbytes: str
) -> None:
    if motion[0] == "gripper":
        driver.open_gripper(motion[1] > 0)
    else:
        driver.turn_for(motion[0], motion[1], 0.25)
    assert sent(sim)[-2:] == [hexbytes, "000000"]
    assert all(t == Transfer(0x40, 6, 0x0100, 0, t.data) for t in sim.backend.transfers)


def test_driver_stops_on_open_and_light_keeps_across_stops(
    driver: TimedDriver, sim: OwiSim
) -> None:
    assert sent(sim) == ["000000"]
    driver.set_light(True)
    driver.turn_for("shoulder", -1, 0.3)
    driver.set_light(False)
    assert sent(sim)[1:] == ["000001", "400001", "000001", "000000"]


def test_several_joints_start_together_and_stop_one_by_one(
    driver: TimedDriver, sim: OwiSim
) -> None:
    q = driver.read()
    report = driver.turn_many({"elbow": q[2] + math.radians(30), "base": q[0] - math.radians(45)})
    seconds = {s.joint: s.seconds for s in report.steps}
    assert seconds[0] > seconds[2]  # base turns further: its motor stops last
    assert sent(sim)[1:] == ["200200", "000200", "000000"]


def test_gripper_is_never_driven_past_open_or_closed(driver: TimedDriver, sim: OwiSim) -> None:
    driver.open_gripper(True)
    n = len(sent(sim))
    driver.open_gripper(True)
    driver.grip(0.045)
    assert len(sent(sim)) == n
    driver.grip(0.0)
    assert sent(sim)[n:] == ["010000", "000000"]
    assert sim.physics.gripper == pytest.approx(0.0, abs=0.1)


def test_device_rejects_other_requests(sim: OwiSim) -> None:
    import usb.core

    dev = usb.core.find(backend=sim.backend, idVendor=0x1267)
    dev.set_configuration()
    with pytest.raises(usb.core.USBError):
        dev.ctrl_transfer(0x40, 7, 0x100, 0, b"\x00\x00\x00")
    with pytest.raises(usb.core.USBError):
        dev.ctrl_transfer(0x40, 6, 0x100, 0, b"\x00\x00")
    assert sim.backend.transfers == []


def test_simulated_arm_moves_the_way_the_bytes_say(driver: TimedDriver, sim: OwiSim) -> None:
    before = sim.physics.true_q()
    driver.turn_for("base", 1, 1.0)
    driver.turn_for("elbow", -1, 1.0)
    delta = sim.physics.true_q() - before
    assert delta[0] > 0 and delta[2] < 0 and np.allclose(delta[[1, 3]], 0)
