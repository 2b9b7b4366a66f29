"""002 ends by switching every servo off (its uM-PWM1 disables every channel): on the
hobby-servo controllers that is "no pulses" (SSC-32U user guide: ``#<ch>P0``; Maestro
User's Guide: Set Target 0). The controller then reports 0 on every channel, and a stop
afterwards (every exit path stops the arm) leaves them off."""

from __future__ import annotations

import pytest

from armkit import Arm


@pytest.mark.parametrize(("driver", "port"), [("sim", None), ("maestro", "emu")])
def test_relax_turns_every_pulse_off_and_a_stop_leaves_them_off(
    driver: str, port: str | None
) -> None:
    with Arm("lynx6", driver, port) as arm:
        arm.move_joints([80, 100, 85, 95, 90])
        channels = [t.channel for t in arm.driver.tables]
        joints = [t.channel for t in arm.driver.joints]
        assert all(p > 0 for p in arm.driver.bus.read(joints).values())
        arm.driver.relax()
        assert set(arm.driver.bus.read(channels).values()) == {0.0}
        arm.driver.stop()
        assert set(arm.driver.bus.read(channels).values()) == {0.0}
        arm.move_joints([90, 90, 90, 90, 90])  # the next move drives them again
        assert all(p > 0 for p in arm.driver.bus.read(joints).values())
