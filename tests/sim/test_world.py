"""The World: one clock, the arms' truth, observers, a bounded 1 kHz recording."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from armkit import Arm, ArmkitError, InputError
from armkit.connect import open_driver
from armkit.model import load_model
from armkit.sim import SimArm, World, world_of

OMX = load_model("openmanipulator_x")


def test_virtual_time_is_exact_and_the_arms_step_on_a_1khz_grid() -> None:
    with Arm(OMX, "sim") as arm:
        world = arm.world
        assert world is not None and world.now() == 0.0
        world.clock.sleep(0.0123)
        assert world.now() == pytest.approx(0.0123, abs=1e-15)
        world.advance(0.5)
        t = world.recording().t
        assert t[0] == 0.0 and np.allclose(np.diff(t), 0.001, atol=1e-9)
        assert t[-1] <= world.now() < t[-1] + 0.001
        world.clock.sleep(-1.0)  # a deadline already passed: nothing (the Clock contract)
        assert world.now() == pytest.approx(0.5123)
        with pytest.raises(InputError, match="seconds >= 0"):
            world.advance(-1.0)  # time does not run backwards: refused, nothing changes
        assert world.now() == pytest.approx(0.5123)


def test_arms_by_name_and_two_arms_in_one_world() -> None:
    world = World()
    with pytest.raises(ArmkitError, match="has no single arm to pick; its arms: none yet"):
        world.arm()
    with Arm(OMX, "sim", world=world) as a, Arm("lynx6", "sim", world=world) as b:
        assert [x.name for x in world.arms()] == ["openmanipulator_x", "lynx6"]
        assert world.arm("lynx6").model.name == "lynx6"
        with pytest.raises(ArmkitError, match="its arms: openmanipulator_x, lynx6"):
            world.arm()
        with Arm(OMX, "sim", world=world):
            assert world.arms()[-1].name == "openmanipulator_x-2"
        assert a.world is b.world is world
        assert world_of(b.driver) is world


def test_the_truth_follows_the_driver_and_lags_the_servos() -> None:
    with Arm(OMX, "sim") as arm:
        world = arm.world
        assert world is not None
        truth = world.arm()
        arm.move_joints([30, -40, 20, 10], wait=False)
        world.advance(0.05)
        assert 0 < math.degrees(truth.q()[0]) < 30  # on the way
        world.advance(3.0)
        np.testing.assert_allclose(np.degrees(truth.q()), [30, -40, 20, 10], atol=0.05)
        assert truth.q() is not truth.q()  # copies


def test_observers_run_after_every_step_until_detached() -> None:
    world = World()
    seen: list[float] = []

    class Watch:
        def on_step(self, w: World, t: float) -> None:
            assert w is world
            seen.append(t)

    detach = world.attach(Watch())
    world.advance(0.01)
    assert seen == pytest.approx([0.001 * k for k in range(1, 11)])
    detach()
    world.advance(0.01)
    assert len(seen) == 10


def test_an_observer_can_stop_the_jaws_on_an_object() -> None:
    """A scene's grasp: when the closing jaws reach a 30 mm cube, they stop there."""
    with Arm(OMX, "sim") as arm:
        world = arm.world
        assert world is not None
        truth = world.arm()

        class Cube:
            def on_step(self, w: World, t: float) -> None:
                if truth.grip() <= 0.0301:
                    truth.grip_stop(0.030)

        world.attach(Cube())
        arm.grip(20)  # asks for 20 mm; the cube is 30 mm wide
        assert truth.grip() == pytest.approx(0.030)
        truth.grip_stop(None)
        world.advance(0.5)
        assert truth.grip() == pytest.approx(0.020, abs=0.001)


def test_the_recording_is_bounded_and_exports_csv(tmp_path: Path) -> None:
    world = World(record_s=0.5)
    with Arm("lynx6", "sim", world=world) as arm:
        arm.move_joints([100, 80, 90, 90, 90])
        world.advance(2.0)
        rec = world.recording()
        assert len(rec.t) == 500 and rec.t[-1] == pytest.approx(
            math.floor(world.now() * 1000) / 1000
        )
        assert np.all(np.diff(rec.t) > 0)
        rows = rec.write_csv(tmp_path / "r.csv")
    lines = (tmp_path / "r.csv").read_text().splitlines()
    assert lines[0] == "t_s,base_deg,shoulder_deg,elbow_deg,wrist_deg,hand_deg"
    assert rows == 500 == len(lines) - 1


def test_analog_inputs_are_the_ssc32s_on_a_lynx6() -> None:
    with Arm("lynx6", "sim") as arm:
        assert arm.world is not None
        truth: SimArm = arm.world.arm()
        truth.analog[0] = lambda: 2.5
        assert truth.device is not None
        assert truth.device.analog is truth.analog  # type: ignore[attr-defined]


def test_real_time_mode_keeps_pace_and_stops() -> None:
    world = World(realtime=True)
    try:
        with Arm(OMX, "sim", world=world) as arm:
            arm.move_joints({"waist": 5})
            assert world.now() > 0.0
            np.testing.assert_allclose(arm.angles()["waist"], 5.0, atol=0.1)
    finally:
        world.close()


def test_world_of_hardware_is_none() -> None:
    class Hardware:
        joint_names = ("a",)

    assert world_of(Hardware()) is None
    driver = open_driver(OMX, "sim")
    assert world_of(driver) is not None
    driver.close()


def test_bad_world_settings_are_refused() -> None:
    with pytest.raises(ValueError, match="rate_hz"):
        World(rate_hz=0)
    with pytest.raises(ValueError, match="record_s"):
        World(record_s=-1)
