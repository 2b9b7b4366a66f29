"""002's search on the simulator: the GP2D120's curve, its reading through the SSC-32's
VA (Lynx6) and through a serial ADC board on a pty (pyserial; OpenManipulator-X), the
object found within 5 mm, picked and dropped in the bin; bad angles move nothing."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from armkit import Arm, InputError, tasks
from armkit.cli import main
from armkit.scene import load_scene
from armkit.sensing import AdcBoard, AdcEmulator, distance, volts
from armkit.sensing._adc import parse_line, reading_line
from armkit.sim import World


@settings(max_examples=50, derandomize=True)
@given(st.floats(0.04, 0.30))
def test_the_curve_inverts_inside_the_range(d: float) -> None:
    assert distance(volts(d)) == pytest.approx(d, abs=1e-6)


def test_the_datasheet_points_and_the_range() -> None:
    assert volts(0.04) == pytest.approx(2.75) and volts(0.30) == pytest.approx(0.43)
    assert distance(volts(0.5)) is None  # beyond 30 cm: no distance
    near = distance(volts(0.02))  # nearer than 3 cm the voltage of a farther one comes back
    assert near is not None and near > 0.04
    assert parse_line(reading_line([2.5, 0.0, 5.0, 1.0])) == pytest.approx(
        [2.5, 0.0, 5.0, 1.0], abs=5 / 1023
    )


def test_the_adc_board_on_a_pty_is_read_with_pyserial() -> None:
    emulator = AdcEmulator({1: lambda: 1.25})
    board = AdcBoard(emulator.port)
    try:
        assert board.read(1) == pytest.approx(1.25, abs=5 / 1023)
        with pytest.raises(InputError):
            board.read(4)
    finally:
        board.close()
        emulator.close()


@pytest.mark.parametrize(
    ("arm_name", "via"), [("lynx6", "SSC-32 VA"), ("openmanipulator_x", "ADC board")]
)
def test_search_finds_picks_and_drops(arm_name: str, via: str) -> None:
    world = World()
    arm = Arm(arm_name, "sim", world=world)
    scene = load_scene("search_002")
    result = tasks.search(arm, scene, into="bin")
    assert result.found and result.via.startswith(via)
    assert result.servos_off and result.lines()[-1] == "motors off"
    assert result.position is not None
    truth = scene.cube("object").position * 1000.0  # the scene's m, the result's mm
    assert float(np.linalg.norm(result.position[:2] - truth[:2])) < 5.0
    physics = tasks.attached(arm)
    assert physics is not None
    box = scene.container("bin")
    assert np.all(np.abs(physics.cube("object").center[:2] - box.position[:2]) < 0.04)
    assert np.allclose(world.arm().q(), arm.model.home, atol=math.radians(0.5))


def test_bad_angles_move_nothing(capsys: pytest.CaptureFixture[str]) -> None:
    world = World()
    arm = Arm("lynx6", "sim", world=world)
    q0 = world.arm().q()
    with pytest.raises(InputError, match=r"0\.\.180 deg"):
        tasks.search(arm, load_scene("search_002"), start=200.0)
    assert np.allclose(world.arm().q(), q0)
    assert main(["--scene", "search_002", "search", "--step", "0"]) == 2
    assert "step" in capsys.readouterr().err


def test_the_cli_search_keeps_the_object_in_the_bin(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["--arm", "lynx6", "--scene", "search_002", "search"]) == 0
    assert "found at 70.5 deg" in capsys.readouterr().out
    assert main(["--arm", "lynx6", "--scene", "search_002", "search"]) == 1  # nothing left
    assert "armkit: nothing found: scanned from 30 to 120 deg" in capsys.readouterr().err


def test_the_simulated_ssc32_answers_va_to_vh_with_one_byte_each() -> None:
    """SSC-32U user guide, "Read Analog Inputs": VA..VH answer one byte each, V x 256 / 5
    (saturating); an input with nothing on it reads 0; no other V query exists."""
    from armkit.sim.ssc32 import SimSSC32

    board = SimSSC32()
    board.analog = {0: lambda: 2.5, 2: lambda: 7.0}
    board.receive(b"VA VB VC\r", 0.0)
    assert board.outbox.take(1.0) == bytes([128, 0, 255])
    board.receive(b"VE VH\r", 1.0)
    assert board.outbox.take(2.0) == bytes([0, 0]) and not board.errors
    board.receive(b"VZ\r", 2.0)
    assert board.errors


@pytest.mark.parametrize("arm_name", ["lynx6", "openmanipulator_x"])
def test_reach_comes_near_the_hand_and_shakes(arm_name: str) -> None:
    world = World()
    arm = Arm(arm_name, "sim", world=world)
    scene = load_scene("reach_003")
    result = tasks.reach(arm, scene, near=60.0, shakes=2)
    hand = scene.hand("hand")
    assert result.found and result.angle is not None and result.distance is not None
    expected = math.degrees(math.atan2(hand.position[1], hand.position[0])) + 90.0
    assert result.angle == pytest.approx(expected, abs=2.0)  # deg
    assert 55.0 <= result.distance <= 62.0 and result.steps > 0 and result.shakes == 2
    assert np.allclose(world.arm().q(), arm.model.home, atol=math.radians(0.5))


def test_the_cli_reach_refuses_bad_values_before_moving(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["--scene", "reach_003", "reach", "--near", "10"]) == 2
    assert "--near: must be 40..300 mm" in capsys.readouterr().err
