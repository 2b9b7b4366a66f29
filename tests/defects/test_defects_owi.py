"""Issue 10, item 3 (OWI-535): under faults a safe stop, and the truth about what
happened -- the watchdog, a signal at any instant, Ctrl-Z, short moves, an
uncertain estimate, two processes."""

from __future__ import annotations

import math
import os
import signal
import threading
from collections.abc import Iterator
from pathlib import Path

import numpy as np
import pytest

import armkit.drivers.timed._journal as journal_module
from armkit import DeviceError
from armkit.devices._owi_commands import decode
from armkit.devices.owi535 import open_device
from armkit.drivers.timed import ShortMoveError, TimedDriver, load_state, state_path
from armkit.model import ArmModel, load_model
from armkit.sim.owi_sim import OwiSim, build_sim

DEG = math.radians
MOVE = np.array([DEG(40), DEG(20), 0.0, 0.0])  # base, then shoulder: two runs


@pytest.fixture
def owi() -> ArmModel:
    return load_model("owi535")


def motions(sim: OwiSim) -> list[dict[str, int]]:
    return [decode(t.data)[0] for t in sim.backend.transfers]


class Events:
    """Counts the instants of a move (each send, sleep and save, before and after) and
    sends this process SIGINT at the chosen ones."""

    def __init__(self, at: set[int]) -> None:
        self.at, self.count, self.names = at, 0, []  # type: ignore[var-annotated]

    def __call__(self, name: str) -> None:
        self.names.append(name)
        if self.count in self.at:
            os.kill(os.getpid(), signal.SIGINT)
        self.count += 1


class EventDevice:
    def __init__(self, inner: object, events: Events) -> None:
        self.inner, self.events = inner, events

    def send(self, data: bytes) -> None:
        self.events("send")
        self.inner.send(data)  # type: ignore[attr-defined]
        self.events("sent")

    def close(self) -> None:
        self.inner.close()  # type: ignore[attr-defined]


class EventClock:
    def __init__(self, inner: object, events: Events) -> None:
        self.inner, self.events = inner, events

    def now(self) -> float:
        return self.inner.now()  # type: ignore[attr-defined, no-any-return]

    def sleep(self, seconds: float) -> None:
        self.events("sleep")
        self.inner.sleep(seconds)  # type: ignore[attr-defined]
        self.events("slept")


def interrupted_move(
    owi: ArmModel, at: set[int], monkeypatch: pytest.MonkeyPatch, unit: str
) -> tuple[TimedDriver, OwiSim, Events, int]:
    """A fresh simulated unit; MOVE with SIGINT at the instants ``at``. Returns the
    driver, the sim, the events and how many commands were sent before the move."""
    sim = build_sim(owi, seed=5)
    events = Events(set())
    real_save = journal_module.save

    def save(*args: object, **kwargs: object) -> None:
        events("save")
        real_save(*args, **kwargs)  # type: ignore[arg-type]
        events("saved")

    monkeypatch.setattr(journal_module, "save", save)
    d = TimedDriver(
        owi,
        EventDevice(open_device(sim.backend), events),
        EventClock(sim.clock, events),  # type: ignore[arg-type]
        state_path(unit),
        unit,
        durable=False,
    )
    before = len(sim.backend.transfers)
    events.at, events.count, events.names = at, 0, []
    try:
        d.move(MOVE)
    except KeyboardInterrupt:
        if not at:
            raise
    else:
        assert not at, "a signal must reach the program"
    events.at = set()  # instants after the move (close) send no signal
    return d, sim, events, before


@pytest.fixture
def baseline(owi: ArmModel, monkeypatch: pytest.MonkeyPatch) -> Iterator[tuple[list[str], float]]:
    """(the instants of an uninterrupted MOVE, its estimate error [rad]) on the same unit."""
    d, sim, events, _ = interrupted_move(owi, set(), monkeypatch, "baseline")
    error = float(np.max(np.abs(d.read() - sim.physics.true_q())))
    names = list(events.names)
    d.close()
    yield names, error


def test_a_signal_at_any_instant_leaves_a_true_state(
    owi: ArmModel, monkeypatch: pytest.MonkeyPatch, baseline: tuple[list[str], float]
) -> None:
    names, error = baseline
    instants = len(names)
    assert instants == 20  # two runs: save, start, wait, stop, save each, before and after
    for first in range(instants):
        for second in sorted(
            {first + 1, first + 2, instants - 1} & set(range(first + 1, instants))
        ):
            d, sim, _, _ = interrupted_move(owi, {first, second}, monkeypatch, "u")
            where = f"signals at {names[first]} #{first} and {names[second]} #{second}"
            truth = sim.physics.true_q()
            if not d.path.exists():  # stopped before anything was written: nothing moved
                assert all(m == {} for m in motions(sim)) and np.all(truth == owi.home), where
                d.close()
                continue
            on_disk = load_state(d.path)
            assert on_disk.pending is None, where
            assert motions(sim)[-1] == {}, where  # stopped
            assert on_disk.motor_s == pytest.approx(sim.physics.motor_s, abs=1e-9), where
            assert np.max(np.abs(np.array(on_disk.angles) - truth)) <= error + DEG(0.5), where
            d.close()
            d.path.unlink()


def test_ctrl_c_between_the_pre_move_save_and_the_first_motor_command(
    owi: ArmModel, monkeypatch: pytest.MonkeyPatch
) -> None:
    d, sim, events, start = interrupted_move(owi, {1}, monkeypatch, "u")
    assert events.names[:2] == ["save", "saved"]
    assert all(m == {} for m in motions(sim)[start:])  # no motor ever started
    on_disk = load_state(d.path)
    assert on_disk.pending is None and on_disk.motor_s == 0.0
    assert on_disk.angles == tuple(float(a) for a in owi.home)
    assert on_disk.reason == "never homed"  # the estimate is as good as before
    d.close()


class HangingClock:
    """The simulated clock, except that one sleep hangs until ``release`` (a stalled
    program): simulated time keeps pace with real time meanwhile, as a real arm's would."""

    def __init__(self, inner: object) -> None:
        self.inner = inner
        self.hang = False
        self.release = threading.Event()

    def now(self) -> float:
        return self.inner.now()  # type: ignore[attr-defined, no-any-return]

    def sleep(self, seconds: float) -> None:
        if self.hang:
            self.hang = False
            while not self.release.wait(0.01):
                self.inner.sleep(0.01)  # type: ignore[attr-defined]
            return
        self.inner.sleep(seconds)  # type: ignore[attr-defined]


def test_a_watchdog_stop_ends_the_move_with_an_error(owi: ArmModel) -> None:
    sim = build_sim(owi, seed=5)
    clock = HangingClock(sim.clock)
    d = TimedDriver(owi, open_device(sim.backend), clock, state_path("w"), "w", durable=False)  # type: ignore[arg-type]
    d.motors.watchdog_margin_s = 0.2
    start = len(sim.backend.transfers)
    clock.hang = True
    timer = threading.Timer(1.5, clock.release.set)
    timer.start()
    with pytest.raises(DeviceError, match="the watchdog stopped the arm"):
        d.move(np.array([DEG(10), DEG(20), 0.0, 0.0]))
    timer.join()
    moving = [m for m in motions(sim)[start:] if m]
    assert len(moving) == 1  # one joint started; nothing ran after the watchdog's stop
    assert motions(sim)[-1] == {}
    on_disk = load_state(d.path)
    assert on_disk.reason == "stopped by the watchdog" and on_disk.uncertain
    # the estimate is from the watchdog's stop, not from the late wake-up
    # (the late wake-up is 1.5 s after the start: some 25 deg of base turn later)
    assert np.max(np.abs(np.array(on_disk.angles) - sim.physics.true_q())) < DEG(3)
    d.close()


CHILD = Path(__file__).with_name("owi_suspend_child.py")


def test_ctrl_z_stops_the_motors_before_suspending(tmp_path: Path, config_dir: Path) -> None:
    import subprocess
    import sys
    import time

    log, out = tmp_path / "usb.log", tmp_path / "out.txt"
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path))
    child = subprocess.Popen([sys.executable, str(CHILD), str(log), str(out)], env=env)
    try:
        for _ in range(400):
            if log.exists() and "000101" in log.read_text().split():
                break
            time.sleep(0.025)
        child.send_signal(signal.SIGTSTP)
        for _ in range(400):
            if Path(f"/proc/{child.pid}/stat").read_text().split()[2] == "T":
                break
            time.sleep(0.025)
        assert Path(f"/proc/{child.pid}/stat").read_text().split()[2] == "T"
        sent = log.read_text().split()
        assert sent[-1] == "000001"  # stopped (light kept on) before it suspended
        time.sleep(1.0)  # suspended for a while: nothing moves
        assert log.read_text().split() == sent
        child.send_signal(signal.SIGCONT)
        assert child.wait(timeout=30) == 3
    finally:
        child.kill()
        child.wait()
    estimate, truth, motor_s = (float(v) for v in out.read_text().split())
    assert abs(estimate - truth) < DEG(3) and truth < DEG(100)  # it did not run on
    on_disk = load_state(state_path("suspend"))
    assert on_disk.pending is None and on_disk.uncertain and on_disk.motor_s == motor_s


def test_short_moves_are_made_or_refused_with_the_smallest_step(cli, config_dir: Path) -> None:  # type: ignore[no-untyped-def]
    got = cli("--arm", "owi535", "joints", "3", "0", "0", "0")
    assert got.code == 0 and "base 3.00" in got.out
    assert cli("--arm", "owi535", "move", "250", "0", "60").code == 0
    got = cli("--arm", "owi535", "move", "250", "10", "60")
    assert got.code == 0 and "y 10.0" in got.out
    got = cli("--arm", "owi535", "draw", "line", "250", "0", "60", "250", "-50", "60")
    assert got.code == 0
    where = cli("--arm", "owi535", "where").out
    y = float(where.split(" y ")[1].split()[0])
    assert abs(y + 50) < 3.0  # within the 0.5 deg resolution at 250 mm


def test_a_short_move_with_no_room_is_refused(owi: ArmModel) -> None:
    from dataclasses import replace

    from armkit.drivers.timed import default_timing
    from armkit.drivers.timed._short import legs

    timing = default_timing(owi)
    narrow = replace(timing, lower=(DEG(-1),) * 4, upper=(DEG(1),) * 4)
    with pytest.raises(ShortMoveError, match=r"under the smallest step it makes \(\d+\.\d deg\)"):
        legs(narrow, "base", np.zeros(4), 0, DEG(1), 0.0, None)
    assert legs(timing, "base", np.zeros(4), 0, DEG(0.2), 0.0, None) == []
    two = legs(timing, "base", np.zeros(4), 0, DEG(2), 0.0, None)
    assert len(two) == 2 and two[-1] == DEG(2)


def test_where_shows_an_uncertain_estimate_and_moves_warn(cli) -> None:  # type: ignore[no-untyped-def]
    got = cli("--arm", "owi535", "where")
    assert "uncertain: these are estimates (never homed)" in got.out
    assert "'armkit --arm owi535 --driver sim rehome'" in got.out
    got = cli("--arm", "owi535", "joints", "20", "0", "0", "0")
    assert got.code == 0 and got.err.startswith("armkit: warning: the OWI-535's joint angles")
    assert got.err.strip().endswith("armkit --arm owi535 --driver sim rehome")
    assert cli("--arm", "owi535", "--driver", "sim", "rehome").code == 0
    got = cli("--arm", "owi535", "joints", "20", "0", "0", "0")
    assert got.code == 0 and got.err == "" and "uncertain" not in got.out


def test_grip_on_an_open_or_closed_gripper(cli) -> None:  # type: ignore[no-untyped-def]
    assert cli("--arm", "owi535", "grip", "45").out == "gripper open 45.0 mm\n"
    assert cli("--arm", "owi535", "grip", "0").out == "gripper closed\n"
    got = cli("--arm", "owi535", "grip", "20")
    assert got.one_line_refusal and "only open or closed" in got.err


def test_a_second_user_of_one_unit_is_refused_before_a_byte(owi: ArmModel) -> None:
    first_sim, second_sim = build_sim(owi, seed=1), build_sim(owi, seed=1)
    first = TimedDriver(owi, open_device(first_sim.backend), first_sim.clock, state_path("one"))
    with pytest.raises(DeviceError, match=rf"in use by process {os.getpid()}"):
        TimedDriver(owi, open_device(second_sim.backend), second_sim.clock, state_path("one"))
    assert second_sim.backend.transfers == []
    first.close()
    TimedDriver(owi, open_device(second_sim.backend), second_sim.clock, state_path("one")).close()
