"""``armkit emulate``: a simulated controller on a pseudo-terminal serves the official
dynamixel-sdk, a plain pyserial script and the README's commands, until Ctrl-C."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

import pytest

ARMKIT = [sys.executable, "-c", "import sys; from armkit.cli import main; sys.exit(main())"]


@contextmanager
def emulator(tmp_path: Path, *args: str) -> Iterator[tuple[str, subprocess.Popen[str]]]:
    """``armkit emulate ARGS`` in a child process; yields (pty path, process)."""
    env = {**os.environ, "ARMKIT_CONFIG_DIR": str(tmp_path / "config")}
    proc = subprocess.Popen(
        [*ARMKIT, "emulate", *args],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        env=env,
    )
    try:
        assert proc.stdout is not None
        port = proc.stdout.readline().strip()
        assert port.startswith("/dev/"), proc.stderr.read() if proc.stderr else ""
        yield port, proc
    finally:
        if proc.poll() is None:
            proc.send_signal(signal.SIGINT)
            proc.wait(timeout=10)


def _armkit(tmp_path: Path, *argv: str) -> subprocess.CompletedProcess[str]:
    env = {**os.environ, "ARMKIT_CONFIG_DIR": str(tmp_path / "config")}
    return subprocess.run(
        [*ARMKIT, *argv], capture_output=True, text=True, env=env, timeout=120, check=False
    )


def test_the_official_dynamixel_sdk_drives_the_emulated_bus(tmp_path: Path) -> None:
    sdk = pytest.importorskip("dynamixel_sdk")
    with emulator(tmp_path, "dynamixel") as (port, _):
        handler = sdk.PortHandler(port)
        assert handler.openPort() and handler.setBaudRate(1_000_000)
        ph = sdk.PacketHandler(2.0)
        try:
            assert ph.ping(handler, 11) == (1020, sdk.COMM_SUCCESS, 0)
            assert ph.write1ByteTxRx(handler, 12, 64, 1) == (sdk.COMM_SUCCESS, 0)
            assert ph.write4ByteTxRx(handler, 12, 116, 2100) == (sdk.COMM_SUCCESS, 0)
            position, result, _ = ph.read4ByteTxRx(handler, 12, 116)
            assert (position, result) == (2100, sdk.COMM_SUCCESS)
        finally:
            handler.closePort()


def test_a_plain_pyserial_script_talks_to_the_emulated_ssc32(tmp_path: Path) -> None:
    serial = pytest.importorskip("serial")
    with emulator(tmp_path, "ssc32") as (port, _), serial.Serial(port, 9600, timeout=1.0) as line:
        line.write(b"VER\r")
        assert line.read_until(b"\r") == b"SSC32-V2.50USB\r"
        line.write(b"#0P1500#1P1200T100\r")
        line.write(b"QP0QP1\r")
        assert line.read(2) == bytes([150, 120])


def test_the_readme_commands_run_against_armkit_emulate(tmp_path: Path) -> None:
    with emulator(tmp_path, "ssc32", "--arm", "lynx6") as (port, _):
        base = ["--arm", "lynx6", "--driver", "ssc32", "--port", port]
        moved = _armkit(tmp_path, *base, "move", "200", "0", "100", "--pitch", "-45")
        assert moved.returncode == 0, moved.stderr
        assert "gripper at x 200.0 y 0.0 z 100.0 mm, pitch -45.0 deg" in moved.stdout
        where = _armkit(tmp_path, *base, "where")
        assert where.returncode == 0 and "pitch -45" in where.stdout  # the board kept its pulses
    with emulator(tmp_path, "maestro") as (port, _):
        out = _armkit(tmp_path, "--driver", "maestro", "--port", port, "servo", "2", "1200")
        assert out.returncode == 0 and "controller reports 1200 µs" in out.stdout
    with emulator(tmp_path, "dynamixel", "--arm", "openmanipulator_x") as (port, _):
        out = _armkit(
            tmp_path, "--driver", "dynamixel", "--port", port, "joints", "10", "-60", "20", "40"
        )
        assert out.returncode == 0, out.stderr
        assert "waist 10.0" in out.stdout


def test_ctrl_c_stops_it_cleanly_and_mistakes_are_one_line(tmp_path: Path) -> None:
    with emulator(tmp_path, "maestro") as (_, proc):
        proc.send_signal(signal.SIGINT)
        assert proc.wait(timeout=10) == 0
        assert proc.stderr is not None and "emulator stopped" in proc.stderr.read()
    bad = _armkit(tmp_path, "emulate", "ssc32", "--arm", "openmanipulator_x")
    assert bad.returncode == 2 and bad.stderr.count("\n") == 1 and "[drivers.ssc32]" in bad.stderr
    bad = _armkit(tmp_path, "emulate", "usb")
    assert bad.returncode == 2 and "invalid choice" in bad.stderr
