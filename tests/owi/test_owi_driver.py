"""Joints that know their angle: estimates, limits, refusals, safety, state."""

from __future__ import annotations

import json
import math
import threading
from pathlib import Path

import numpy as np
import pytest
from owi_wire import sent

from armkit._errors import DeviceError, JointLimitError, UnreachableError
from armkit.devices.owi535 import open_device
from armkit.drivers import Driver
from armkit.drivers.timed import ShortMoveError, TimedDriver, load_state, state_path
from armkit.drivers.timed._order import _score
from armkit.model import ArmModel
from armkit.sim.owi_sim import OwiSim

DEG = math.radians


def snapshot(driver: TimedDriver, sim: OwiSim) -> tuple[int, bytes]:
    return len(sim.backend.transfers), driver.path.read_bytes()


def test_is_a_driver(driver: TimedDriver) -> None:
    assert isinstance(driver, Driver)
    assert driver.joint_names == ("base", "shoulder", "elbow", "wrist")


def test_turn_to_and_by_track_the_angle_and_the_file(driver: TimedDriver, sim: OwiSim) -> None:
    driver.turn_to("shoulder", DEG(40))
    driver.turn_by("shoulder", DEG(-15))
    assert driver.read()[1] == pytest.approx(DEG(25))
    on_disk = json.loads(driver.path.read_text())
    assert on_disk["angles_deg"][1] == pytest.approx(25.0)
    assert on_disk["pending"] is None
    assert abs(sim.physics.true_q()[1] - DEG(25)) < DEG(8)  # an uncalibrated unit: roughly


def test_beyond_a_limit_is_clamped_and_said(driver: TimedDriver) -> None:
    report = driver.turn_to("wrist", DEG(95))
    assert driver.read()[3] == pytest.approx(DEG(60))
    assert report.notes == ["wrist: 95.0 deg clamped to its limit 60.0 deg"]


def test_refused_moves_send_no_byte_and_write_no_state(driver: TimedDriver, sim: OwiSim) -> None:
    driver.turn_to("base", DEG(10))
    before = snapshot(driver, sim)
    with pytest.raises(
        JointLimitError, match=r"wrist to 95.0 deg is outside its limits -60.0..60.0 deg"
    ):
        driver.turn_to("wrist", DEG(95), clamp=False)
    with pytest.raises(JointLimitError):
        driver.move(np.array([0.0, 0.0, 0.0, DEG(90)]))
    with pytest.raises(ShortMoveError, match=r"under the 200 ms minimum; turn it further"):
        driver.turn_by("base", DEG(1))
    with pytest.raises(UnreachableError, match="below the table"):
        driver.move(np.array([0.0, DEG(110), DEG(40), 0.0]))
    with pytest.raises(ValueError, match="unknown joint"):
        driver.turn_to("thumb", 0.0)
    with pytest.raises(ShortMoveError, match="100 ms is under the 200 ms minimum"):
        driver.turn_for("base", 1, 0.1)
    with pytest.raises(ValueError, match="speed"):
        driver.move(driver.read(), speed=2.0)
    assert snapshot(driver, sim) == before


def test_move_skips_joints_within_the_resolution(driver: TimedDriver) -> None:
    q = driver.read()
    report = driver.move_report(q + np.array([DEG(0.3), DEG(30), 0.0, 0.0]))
    assert [s.joint for s in report.steps] == [1]
    assert "base: +0.30 deg is within the 0.5 deg resolution" in report.notes[0]
    assert "left where it is" in report.notes[0]


def test_a_short_move_is_made_in_two_legs(driver: TimedDriver) -> None:
    q = driver.read()
    report = driver.move_report(q + np.array([DEG(1), 0.0, 0.0, 0.0]))
    assert [s.joint for s in report.steps] == [0, 0]  # past the target, then back onto it
    assert report.steps[0].direction == -report.steps[1].direction
    assert driver.read()[0] == pytest.approx(q[0] + DEG(1), abs=DEG(0.05))


def test_move_lifts_before_travelling_and_lowers_last(driver: TimedDriver, sim: OwiSim) -> None:
    low_a = np.array([DEG(-40), DEG(70), DEG(60), DEG(-40)])
    low_b = np.array([DEG(40), DEG(70), DEG(60), DEG(-40)])
    driver.move(low_a)
    n = len(sent(sim))
    driver.move(low_b)
    assert sent(sim)[n:] == ["000100", "000000"]  # same height: only the base turns
    report = driver.move_report(np.array([DEG(-40), DEG(30), DEG(90), DEG(-30)]))
    order = [driver.joint_names[s.joint] for s in report.steps]
    assert order.index("shoulder") < order.index("base")  # lift (shoulder back) first


def test_going_home_turns_the_elbow_first(driver: TimedDriver) -> None:
    folded = np.array([0.0, DEG(108), DEG(-150), DEG(-57)])  # reaching low, elbow folded back
    driver.set_state(driver.state.with_(angles=tuple(folded)))
    report = driver.move_report(np.zeros(4))
    assert [driver.joint_names[s.joint] for s in report.steps] == ["elbow", "shoulder", "wrist"]
    lengths = driver.timing.lengths
    shoulder_first = _score(folded, np.zeros(4), [1, 2, 3], lengths, 0.07)
    assert shoulder_first[0] < 0.0  # would have swept through the table


class Boom(Exception):
    pass


class FailingClock:
    """A clock whose sleep raises (or hangs) once armed."""

    def __init__(self, inner: object, mode: str) -> None:
        self.inner, self.mode, self.armed = inner, mode, False
        self.release = threading.Event()

    def now(self) -> float:
        return self.inner.now()  # type: ignore[attr-defined, no-any-return]

    def sleep(self, seconds: float) -> None:
        if self.armed and self.mode == "raise":
            self.inner.sleep(seconds / 2)  # type: ignore[attr-defined]
            raise Boom("program error mid-move")
        if self.armed and self.mode == "hang":
            self.release.wait(10.0)
        self.inner.sleep(seconds)  # type: ignore[attr-defined]


def test_exception_mid_move_stops_and_keeps_an_uncertain_estimate(
    owi: ArmModel, sim: OwiSim
) -> None:
    clock = FailingClock(sim.clock, "raise")
    d = TimedDriver(owi, open_device(sim.backend), clock, state_path("x"))  # type: ignore[arg-type]
    clock.armed = True
    with pytest.raises(Boom):
        d.turn_to("base", DEG(60))
    assert sent(sim)[-2:] == ["000100", "000000"]
    state = load_state(d.path)
    assert state.uncertain and state.pending is None and "cut short" in state.reason
    assert DEG(20) < state.angles[0] < DEG(40)  # about half way
    d.close()


def test_watchdog_stops_a_hung_move(owi: ArmModel, sim: OwiSim) -> None:
    clock = FailingClock(sim.clock, "hang")
    d = TimedDriver(owi, open_device(sim.backend), clock, state_path("x"))  # type: ignore[arg-type]
    d.motors.watchdog_margin_s = 0.2
    clock.armed = True
    errors: list[BaseException] = []

    def move() -> None:
        try:
            d.turn_for("elbow", 1, 0.3)
        except DeviceError as exc:
            errors.append(exc)

    worker = threading.Thread(target=move)
    worker.start()
    deadline = threading.Event()
    for _ in range(100):
        if len(sim.backend.transfers) >= 3:
            break
        deadline.wait(0.05)
    assert sent(sim)[-2:] == ["200000", "000000"]  # stopped while the main thread hangs
    assert load_state(d.path).uncertain
    clock.release.set()
    worker.join()
    assert load_state(d.path).reason == "stopped by the watchdog"
    assert len(errors) == 1 and "the watchdog stopped the arm" in str(errors[0])
    d.close()


def test_state_survives_a_new_process_and_a_new_driver(
    owi: ArmModel, sim: OwiSim, driver: TimedDriver
) -> None:
    driver.turn_to("elbow", DEG(45))
    driver.set_light(True)
    driver.open_gripper(True)
    driver.close()
    again = TimedDriver(owi, open_device(sim.backend), sim.clock, driver.path)
    assert again.read()[2] == pytest.approx(DEG(45))
    assert again.state.light and again.state.gripper == "open"
    assert sent(sim)[-1] == "000001"  # opening sends stop, light kept on
    again.close()


def test_writes_leave_no_temporary_files(driver: TimedDriver) -> None:
    for angle in (30, -30, 45):
        driver.turn_to("base", DEG(angle))
    names = sorted(p.name for p in driver.path.parent.iterdir())
    assert names == ["test.json", "test.json.lock"]  # the lock stays (flock, see armkit._lock)
    assert load_state(driver.path).angles[0] == pytest.approx(DEG(45))


def test_close_is_idempotent_and_stops(driver: TimedDriver, sim: OwiSim) -> None:
    driver.close()
    driver.close()
    assert sent(sim)[-1] == "000000"


def test_state_file_location(monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    monkeypatch.delenv("ARMKIT_CONFIG_DIR")
    monkeypatch.setenv("XDG_CONFIG_HOME", str(tmp_path / "xdg"))
    assert state_path("desk") == tmp_path / "xdg" / "armkit" / "owi535" / "desk.json"
    monkeypatch.delenv("XDG_CONFIG_HOME")
    monkeypatch.setenv("HOME", str(tmp_path))
    assert state_path("desk") == tmp_path / ".config" / "armkit" / "owi535" / "desk.json"
    with pytest.raises(ValueError, match="plain name"):
        state_path("../etc")


def test_corrupt_state_file_is_a_clear_error(owi: ArmModel, sim: OwiSim, config_dir: Path) -> None:
    from armkit._errors import ArmkitError

    path = state_path("bad")
    path.parent.mkdir(parents=True)
    path.write_text("{not json")
    with pytest.raises(ArmkitError, match=r"unreadable.*delete it"):
        TimedDriver(owi, open_device(sim.backend), sim.clock, path)


def test_relax_switches_every_motor_off(driver: TimedDriver, sim: OwiSim) -> None:
    """The tasks' 'motors off at the end' (002's search): on the OWI, stop (the light kept)."""
    driver.set_light(True)
    driver.relax()
    assert sent(sim)[-1] == "000001"
