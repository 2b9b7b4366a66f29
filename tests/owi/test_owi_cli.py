"""The OWI commands end to end on the simulated arm, and 000's moveItem."""

from __future__ import annotations

import numpy as np
import pytest
from owi_wire import sent

from armkit import Arm
from armkit._errors import UnreachableError
from armkit.cli import main
from armkit.drivers.timed import TimedDriver, load_state, state_path
from armkit.kinematics import fk
from armkit.model import ArmModel
from armkit.scene import Scene
from armkit.sim.owi_sim import OwiSim
from armkit.tasks import move_item

SIM = ["--arm", "owi535", "--driver", "sim"]


def test_light_on_and_off(capsys: pytest.CaptureFixture[str]) -> None:
    assert main([*SIM, "light", "on"]) == 0
    assert load_state(state_path("sim")).light
    assert main([*SIM, "light", "off"]) == 0
    assert not load_state(state_path("sim")).light
    assert capsys.readouterr().out.split("\n")[:2] == ["light on", "light off"]


def test_rehome_makes_the_state_certain(capsys: pytest.CaptureFixture[str]) -> None:
    assert main([*SIM, "rehome"]) == 0
    out = capsys.readouterr().out
    assert "re-homed: the joint angles are known again" in out and "| certain" in out
    assert not load_state(state_path("sim")).uncertain


def test_pick_place_command(capsys: pytest.CaptureFixture[str]) -> None:
    assert main([*SIM, "pick-place", "150", "100", "80", "150", "-100", "80"]) == 0
    out = capsys.readouterr().out
    assert out.index("grasp") < out.index("put it down at B") < out.index("release")
    assert load_state(state_path("sim")).gripper == "open"


def test_mistakes_are_one_line_and_move_nothing(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["--arm", "lynx6", "--driver", "sim", "rehome"]) == 2
    assert main([*SIM, "pick-place", "900", "0", "50", "150", "0", "80"]) == 2
    err = capsys.readouterr().err.strip().split("\n")
    assert len(err) == 2 and "is for the OWI-535" in err[0] and "too far from the arm" in err[1]
    assert not state_path("sim").exists()  # nothing moved, nothing written


def test_pick_place_grasps_at_a_and_releases_at_b(
    owi: ArmModel, driver: TimedDriver, sim: OwiSim
) -> None:
    a, b = np.array([0.15, 0.10, 0.08]), np.array([0.15, -0.10, 0.08])
    move_item(Arm(owi, driver), Scene("table"), a * 1000.0, b * 1000.0, lift=40.0, clearance=40.0)
    grips = [c for c in sent(sim) if c in ("020000", "010000")]
    assert grips == ["020000", "010000", "020000"]  # open, grasp, release
    assert np.linalg.norm(fk(owi, driver.read())[:3, 3] - (b + np.array([0, 0, 0.04]))) < 0.015
    assert sim.physics.gripper == pytest.approx(1.0, abs=0.05)


def test_pick_place_refuses_before_moving(owi: ArmModel, driver: TimedDriver, sim: OwiSim) -> None:
    n = len(sent(sim))
    with pytest.raises(UnreachableError):
        move_item(Arm(owi, driver), Scene("table"), (150.0, 100.0, 80.0), (900.0, 0.0, 50.0))
    assert len(sent(sim)) == n
