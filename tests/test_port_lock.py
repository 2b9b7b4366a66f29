"""Issue 10, two processes: a serial port is taken by one armkit process at a time; a
second one is refused at once with a message naming the first (two programs on one
line would garble each other's replies: "servo 13 is model 0")."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

from armkit._errors import DeviceError
from armkit.sim.emulators import DynamixelEmulator, Emulator, SSC32Emulator

pytest.importorskip("serial")

HOLDER = {
    "ssc32": "from armkit.devices.ssc32 import SSC32; d = SSC32(sys.argv[1], 9600)",
    "dynamixel": "from armkit.devices.dynamixel import DynamixelBus; d = DynamixelBus(sys.argv[1])",
}


def open_here(kind: str, port: str) -> None:
    if kind == "ssc32":
        from armkit.devices.ssc32 import SSC32

        SSC32(port, 9600).close()
    else:
        from armkit.devices.dynamixel import DynamixelBus

        DynamixelBus(port).close()


@pytest.mark.parametrize("kind", ["ssc32", "dynamixel"])
def test_a_second_process_on_one_port_is_refused(
    kind: str, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    if kind == "dynamixel":
        pytest.importorskip("dynamixel_sdk")
    env = {**os.environ, "ARMKIT_CONFIG_DIR": str(tmp_path)}
    monkeypatch.setenv("ARMKIT_CONFIG_DIR", str(tmp_path))
    emulator: Emulator = SSC32Emulator(9600) if kind == "ssc32" else DynamixelEmulator()
    with emulator as emu:
        script = f"import sys\n{HOLDER[kind]}\nprint('open', flush=True)\nsys.stdin.read()"
        child = subprocess.Popen(
            [sys.executable, "-c", script, emu.port],
            stdin=subprocess.PIPE,
            stdout=subprocess.PIPE,
            text=True,
            env=env,
        )
        try:
            assert child.stdout is not None and child.stdout.readline().strip() == "open"
            with pytest.raises(DeviceError, match=rf"in use by process {child.pid}"):
                open_here(kind, emu.port)
        finally:
            assert child.stdin is not None
            child.stdin.close()
            child.wait(timeout=30)
        open_here(kind, emu.port)  # free again once the first process has gone
