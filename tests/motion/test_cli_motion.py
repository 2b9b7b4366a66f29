"""The motion commands through ``armkit.cli.main``: move, joints, grip, home, where, draw."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from armkit.cli import main
from armkit.kinematics import fk, ik
from armkit.model import load_model
from armkit.sim._servo_body import ServoParams

# a blocking move ends when every servo is within its settle band
SETTLE_DEG = math.degrees(ServoParams().settle) + 1e-6
NEAR_MM = 0.5  # the tool point for joints within SETTLE_DEG


def _where(capsys: pytest.CaptureFixture[str], *arm: str) -> str:
    assert main([*arm, "where"]) == 0
    return capsys.readouterr().out


def _xyz(text: str) -> tuple[float, ...]:
    """The x, y, z [mm] of the 'gripper at x X y Y z Z mm' line."""
    words = text.split("gripper at ")[1].split()
    return tuple(float(words[i]) for i in (1, 3, 5))


def _angles(text: str) -> list[float]:
    """The angles [deg] of the 'joints NAME A NAME B ... deg' line."""
    words = text.split("joints ")[1].split("\n")[0].split()
    return [float(w) for w in words[1:-1:2]]


def test_move_then_where_in_a_new_invocation(
    capsys: pytest.CaptureFixture[str], config_dir: Path
) -> None:
    assert main(["move", "200", "0", "100", "--pitch", "-45"]) == 0
    moved = capsys.readouterr().out
    assert math.dist(_xyz(moved), (200, 0, 100)) < NEAR_MM and "pitch -45.0 deg" in moved
    assert (config_dir / "sim_openmanipulator_x.json").exists()
    # a new process reads the ticks the servos hold: the target to the nearest tick (the
    # XM430's resolution), printed to 0.1 mm
    omx = load_model("openmanipulator_x")
    target = ik(omx, np.array([0.2, 0.0, 0.1]), math.radians(-45)).q
    tick = 2 * math.pi / 4096
    held = fk(omx, np.round(target / tick) * tick)[:3, 3] * 1000
    assert math.dist(_xyz(_where(capsys)), held) < 0.09
    assert main(["home"]) == 0
    assert _angles(_where(capsys)) == pytest.approx([0.0, -60.16, 20.05, 40.11], abs=SETTLE_DEG)


def test_joints_and_grip(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["--arm", "lynx6", "joints", "80", "100", "70", "95", "90", "--speed", "50%"]) == 0
    assert _angles(capsys.readouterr().out) == pytest.approx([80, 100, 70, 95, 90], abs=SETTLE_DEG)
    assert main(["--arm", "lynx6", "grip", "25"]) == 0
    assert "25.0 mm" in capsys.readouterr().out


@pytest.mark.parametrize(
    "argv, message",
    [
        (["move", "900", "0", "100"], "cannot reach"),
        (["joints", "0", "0", "0", "200"], "wrist 200.00 deg is outside"),
        (["joints", "0", "0"], "give 4 angles"),
        (["grip", "500"], "grip width"),
        (
            ["move", "200", "0", "100", "--speed", "300"],
            "argument --speed: must be > 0 and <= 100 %, got 300",
        ),
        (
            ["draw", "circle", "--center", "250", "0", "50", "--radius", "60", "--pitch", "-90"],
            "point ",
        ),
        (["draw", "line", "150", "0", "50", "150", "0", "60", "--spacing", "0"], "spacing"),
        (["--driver", "nope", "where"], "unknown driver"),
    ],
)
def test_bad_input_is_one_line_and_moves_nothing(
    argv: list[str], message: str, capsys: pytest.CaptureFixture[str], config_dir: Path
) -> None:
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert message in err and err.count("\n") == 1
    assert not (config_dir / "sim_openmanipulator_x.json").exists()


def test_draw_circle_records_the_true_path(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    out = tmp_path / "circle.csv"
    argv = ["draw", "circle", "--center", "170", "0", "50", "--radius", "20", "--pitch", "-90"]
    assert main([*argv, "--record", str(out)]) == 0
    assert "drew circle" in capsys.readouterr().out
    table = np.loadtxt(out, delimiter=",", skiprows=1)
    assert out.read_text().splitlines()[0] == "t_s,waist_deg,shoulder_deg,elbow_deg,wrist_deg"
    np.testing.assert_allclose(np.diff(table[:, 0]), 0.001, atol=1e-6)
    tool = fk(load_model("openmanipulator_x"), np.radians(table[:, 1:]))[:, :3, 3] * 1000
    drawn = tool[tool[:, 2] < 50.5]
    radius = np.hypot(drawn[:, 0] - 170, drawn[:, 1])
    assert radius.max() == pytest.approx(20, abs=0.5)
    assert math.dist(tool[-1], (190, 0, 50)) < NEAR_MM


@pytest.mark.parametrize("mode", ["naive", "early", "timed"])
def test_draw_rect_and_line_in_every_mode(mode: str, capsys: pytest.CaptureFixture[str]) -> None:
    rect = ["draw", "rect", "--center", "170", "0", "50", "--size", "30", "20", "--pitch", "-90"]
    assert main([*rect, "--mode", mode, "--spacing", "3"]) == 0
    assert main(["draw", "line", "150", "-20", "40", "180", "20", "40", "--mode", mode]) == 0
    assert math.dist(_xyz(_where(capsys)), (180, 20, 40)) < NEAR_MM


def test_draw_cube_in_one_stroke(capsys: pytest.CaptureFixture[str]) -> None:
    argv = ["draw", "cube", "--corner", "150", "-15", "40", "--size", "30", "--pitch", "-90"]
    assert main(argv) == 0
    assert "drew cube: " in capsys.readouterr().out
    assert math.dist(_xyz(_where(capsys)), (150, -15, 70)) < NEAR_MM  # ends above the start corner


def test_record_needs_the_simulator(capsys: pytest.CaptureFixture[str]) -> None:
    argv = [
        "--arm",
        "owi535",
        "--driver",
        "owi535",
        "draw",
        "line",
        "150",
        "0",
        "50",
        "160",
        "0",
        "50",
        "--record",
        "x.csv",
    ]
    assert main(argv) == 2
    assert "--record needs a simulated arm" in capsys.readouterr().err  # before any device
