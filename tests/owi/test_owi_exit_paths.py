"""Every way out of a move stops the motors, and the state file stays honest,
in real processes: an exception, Ctrl-C (SIGINT), SIGTERM, normal exit, kill -9."""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from armkit.devices.owi535 import open_device
from armkit.drivers.timed import TimedDriver, load_state, state_path
from armkit.model import ArmModel
from armkit.sim.owi_sim import build_sim

CHILD = Path(__file__).with_name("owi_child.py")
MOVING = "000101"  # base right, light on


def start(mode: str, log: Path) -> subprocess.Popen[str]:
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path))
    return subprocess.Popen(
        [sys.executable, str(CHILD), mode, str(log)], env=env, stderr=subprocess.PIPE, text=True
    )


def wait_for_motion(proc: subprocess.Popen[str], log: Path) -> None:
    for _ in range(400):
        if log.exists() and MOVING in log.read_text().split():
            return
        if proc.poll() is not None:
            break
        time.sleep(0.025)
    raise AssertionError(
        f"the child never started moving: {proc.stderr.read() if proc.stderr else ''}"
    )


def commands(log: Path) -> list[str]:
    return log.read_text().split()


def after_motion(log: Path) -> list[str]:
    """Commands sent after the (one) move started: stops, the light kept on."""
    sent = commands(log)
    return sent[sent.index(MOVING) + 1 :]


@pytest.mark.parametrize(
    ("mode", "sig", "code"),
    [("sigint", signal.SIGINT, -signal.SIGINT), ("sigterm", signal.SIGTERM, 143)],
)
def test_signal_mid_move_sends_stop(tmp_path: Path, mode: str, sig: int, code: int) -> None:
    log = tmp_path / "usb.log"
    proc = start(mode, log)
    wait_for_motion(proc, log)
    proc.send_signal(sig)
    assert proc.wait(timeout=20) == code
    assert after_motion(log) == ["000001", "000001"]  # stop in the move's finally, then atexit
    state = load_state(state_path("child"))
    assert state.uncertain and state.pending is None and "cut short" in state.reason
    assert 0.0 < state.angles[0] < 2.2


def test_exception_mid_move_sends_stop(tmp_path: Path) -> None:
    log = tmp_path / "usb.log"
    proc = start("exception", log)
    assert proc.wait(timeout=20) == 1
    assert "simulated program error" in (proc.stderr.read() if proc.stderr else "")
    assert after_motion(log) == ["000001", "000001"]
    assert load_state(state_path("child")).uncertain


def test_normal_exit_without_close_stops_via_atexit(tmp_path: Path) -> None:
    log = tmp_path / "usb.log"
    proc = start("exit", log)
    assert proc.wait(timeout=20) == 0
    assert commands(log)[-3:] == [MOVING, "000001", "000001"]  # end of the move, then atexit


def test_kill_9_leaves_a_valid_uncertain_state(tmp_path: Path, owi: ArmModel) -> None:
    log = tmp_path / "usb.log"
    proc = start("sigkill", log)
    wait_for_motion(proc, log)
    proc.kill()
    proc.wait(timeout=20)
    assert commands(log)[-1] == MOVING  # nobody could send stop: the motor still runs
    on_disk = json.loads(state_path("child").read_text())
    assert on_disk["uncertain"] is True and on_disk["pending"]["directions"] == {"0": 1}
    sim = build_sim(owi, 3)
    again = TimedDriver(owi, open_device(sim.backend), sim.clock, state_path("child"))
    assert [t.data.hex() for t in sim.backend.transfers] == ["000001"]  # stop comes first
    assert again.state.pending is None and again.state.uncertain
    assert "died during a move" in again.state.reason
    assert again.read()[0] > 0.0  # it kept turning until now
    again.close()
