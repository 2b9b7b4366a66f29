"""``armkit view --write``: the poses recorded on the page and the moves made, as a
script ``armkit check`` accepts and ``armkit run`` replays to the same poses."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import armkit
from armkit.cli import main
from armkit.script import Source, run_source
from armkit.viz import ArmSource
from armkit.viz.web import Teach, View


def _deg(a: np.ndarray, b: np.ndarray) -> float:
    return float(np.max(np.abs(np.degrees(a - b))))


def _teach(path: Path) -> list[np.ndarray]:
    """Move the arm from the 'page' (sliders, target, gripper), record two poses, end
    somewhere else; write the script. Returns the poses the arm was taught, in order."""
    taught: list[np.ndarray] = []
    arm = armkit.Arm("openmanipulator_x")
    with arm, View(ArmSource(arm), port=0) as view:
        teach = Teach(view, arm, echo=False)
        try:
            teach.move_joints(arm.model.home + np.radians([25.0, -15.0, 10.0, 20.0]))
            assert teach.mover.wait_idle(30.0)
            teach.record("first")
            taught.append(arm.driver.read())
            assert teach.drag_target((0.2, -0.05, 0.08), -90.0)
            assert teach.mover.wait_idle(30.0)
            arm.grip(20.0)
            teach.record("above")
            taught.append(arm.driver.read())
            teach.move_joints(arm.model.home + np.radians([-30.0, 5.0, 5.0, -10.0]))
            assert teach.mover.wait_idle(30.0)
            taught.append(arm.driver.read())
            path.write_text(teach.script(), encoding="utf-8")
        finally:
            teach.close()
    return taught


def test_view_write_gives_a_script_that_checks_and_replays(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    path = tmp_path / "taught.arm"
    taught = _teach(path)
    text = path.read_text(encoding="utf-8")
    assert "taught in the armkit 3D view" in text and "\narm openmanipulator_x\n" in text
    assert "\npose first = joints " in text and "\npose above = joints " in text
    assert "\ngrip 20.0\n" in text
    assert main(["check", str(path)]) == 0, capsys.readouterr().err

    replayed: list[np.ndarray] = []
    with armkit.Arm("openmanipulator_x") as arm:
        hook = lambda _st, _fr: replayed.append(arm.driver.read())  # noqa: E731
        run_source(arm, Source(str(path), text), on_step=hook)
        replayed.append(arm.driver.read())
    for want in taught:  # every pose taught on the page is reached again
        assert min(_deg(got, want) for got in replayed) < 0.1
    assert _deg(replayed[-1], taught[-1]) < 0.1


def test_torque_off_on_the_page_lets_the_sliders_move_the_simulated_arm_by_hand(
    tmp_path: Path,
) -> None:
    hand_q = np.radians([-35.0, -10.0, 25.0, 15.0])
    arm = armkit.Arm("openmanipulator_x")
    with arm, View(ArmSource(arm), port=0) as view:
        teach = Teach(view, arm, echo=False)
        try:
            assert not teach.push_joints(hand_q)  # torque on: no hand moves it
            assert _deg(arm.driver.read(), arm.model.home) < 0.1
            assert teach.set_limp(True)
            assert not teach.drag_target((0.2, 0.0, 0.08), -90.0)  # nothing commanded
            assert teach.push_joints(hand_q)
            teach.record("by_hand")  # read over the bus: the true angles
            assert teach.set_limp(False)
            assert _deg(arm.driver.read(), hand_q) < 0.1  # it holds there
            text = teach.script()
        finally:
            teach.close()
    path = tmp_path / "hand.arm"
    path.write_text(text, encoding="utf-8")
    with armkit.Arm("openmanipulator_x") as b:
        run_source(b, Source(str(path), text))
        assert _deg(b.driver.read(), hand_q) < 0.1
