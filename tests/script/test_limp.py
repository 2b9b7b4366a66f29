"""Teach by hand: ``limp`` (torque off), a hand moving the simulated joints
(``SimArm.push``), ``save`` reading the true angles through the Dynamixel protocol,
``hold``, ``write`` and a replay reaching the same poses; refused where servos cannot."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from script_arms import counting_arm

from armkit.script import Source, run_source
from armkit.script._resolve import JointPose
from armkit.script._session import Session
from armkit.sim import world_of


def _deg(a: np.ndarray, b: np.ndarray) -> float:
    return float(np.max(np.abs(np.degrees(a - b))))


def test_limp_moved_by_hand_saved_held_written_and_replayed(tmp_path: Path) -> None:
    a, driver = counting_arm()
    sim = world_of(driver.inner)
    assert sim is not None
    hand = sim.arm()
    s = Session(a, base_dir=tmp_path)
    q1 = a.model.home + np.radians([30.0, -20.0, 15.0, 25.0])
    q2 = a.model.home + np.radians([-40.0, 10.0, -10.0, 30.0])
    with pytest.raises(ValueError, match="torque on"):
        hand.push(q1)  # torque on: the servos hold, nothing moves
    assert _deg(a.driver.read(), a.model.home) < 0.1
    assert s.handle("limp").text.startswith("limp: torque off")
    sent = driver.sent
    hand.push(q1)
    assert s.handle("save grab").text.startswith("saved: pose grab = joints")
    got = s.resolver.poses["grab"]
    assert isinstance(got, JointPose) and _deg(got.q, q1) < 0.1  # read through the protocol
    assert s.handle("move grab").text.startswith("<shell>:3:1: error: the arm is limp")
    assert s.handle("jog").text.startswith("<shell>:4:1: error: the arm is limp")
    assert driver.sent == sent  # nothing was commanded while limp
    hand.push(q2)
    assert s.handle("hold").text.startswith("hold: torque on")
    with pytest.raises(ValueError, match="torque on"):
        hand.push(q1)
    assert _deg(a.driver.read(), q2) < 0.1  # it holds where the hand left it
    assert s.handle("move grab").text == ""
    assert _deg(a.driver.read(), q1) < 0.1
    assert s.handle("write taught.arm").text.startswith("wrote")
    a.close()

    b, _ = counting_arm()
    replayed: list[np.ndarray] = []
    path = tmp_path / "taught.arm"
    hook = lambda _st, _fr: replayed.append(b.driver.read())  # noqa: E731  before each statement
    run_source(b, Source(str(path), path.read_text()), on_step=hook)
    replayed.append(b.driver.read())
    assert min(_deg(got, q2) for got in replayed) < 0.1  # where the hand left it
    assert _deg(replayed[-1], q1) < 0.1  # the pose saved while limp
    b.close()


@pytest.mark.parametrize(
    ("name", "why"), [("lynx6", "hobby servos on the SSC-32"), ("owi535", "DC motors")]
)
def test_limp_is_refused_in_one_line_where_servos_cannot(
    name: str, why: str, tmp_path: Path
) -> None:
    a, driver = counting_arm(name)
    before = a.driver.read()
    s = Session(a, base_dir=tmp_path)
    reply = s.handle("limp").text
    assert reply.startswith(f"<shell>:1:1: error: limp: {name}: its {why}") and "\n" not in reply
    assert "jog" in reply and not s.limp
    assert driver.sent == 0 and _deg(a.driver.read(), before) == 0.0
    a.close()


def test_no_hand_turns_the_owi_gears() -> None:
    a, driver = counting_arm("owi535")
    world = world_of(driver.inner)
    assert world is not None
    before = world.arm().q()
    with pytest.raises(ValueError, match="cannot be turned by hand"):
        world.arm().push(before + 0.2)
    assert _deg(world.arm().q(), before) == 0.0
    a.close()


def test_shell_help_lists_limp_hold_and_the_prompt_says_limp(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    import io

    from armkit.cli import main
    from armkit.script._shell import Shell

    assert main(["shell", "--help"]) == 0
    text = capsys.readouterr().out
    assert "\n  limp " in text and "\n  hold " in text and "torque" in text
    a, _ = counting_arm()
    out = io.StringIO()
    Shell(Session(a, base_dir=tmp_path), stdin=io.StringIO("limp\nquit\n"), stdout=out).loop()
    assert " limp> " in out.getvalue() and "hold: torque on" in out.getvalue()  # quit holds
    a.close()
