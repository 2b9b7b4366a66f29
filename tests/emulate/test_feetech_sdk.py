"""Feetech's own ``scservo_sdk`` against ``armkit emulate feetech --arm so101`` in another
process (issue 31 Done-when): ping, read, write and sync read answer as the STS3215
documentation says, and the port is one process's at a time.

Sources: Feetech's FT-SCS communication protocol (PING answers with a status and no
parameters; READ returns the bytes asked for, low byte first on the STS series; SYNC
READ one status per servo in the order asked; WRITE answers an empty status; an ID no
servo has is silent, the SDK's COMM_RX_TIMEOUT) and the SMS/STS memory table
(``armkit.devices.sts3215``: Model Number 3 = 777 for the STS3215, ID 5, Max Torque
Limit 16 at most 1000, Torque Enable 40, Goal Position 42, Present Position 56,
Moving 66).
"""

from __future__ import annotations

import os
import subprocess
import sys
import time
from pathlib import Path
from typing import Any

import pytest
from emulated import emulate

from armkit._errors import DeviceError
from armkit.devices.feetech import FeetechBus
from armkit.model import load_model

sdk = pytest.importorskip("scservo_sdk")
OK = sdk.COMM_SUCCESS
IDS = (1, 2, 3, 4, 5, 6)
MODEL_NUMBER, ID, MAX_TORQUE, TORQUE, GOAL, PRESENT, MOVING = 3, 5, 16, 40, 42, 56, 66
WAIT_S = 30.0  # [s] longest wait for a servo to stop (not a timing assertion)
TRIES = 20  # a request the SDK gave up on (its timeout, on a busy machine) is asked again
NO_ANSWER = (sdk.COMM_RX_TIMEOUT, sdk.COMM_RX_CORRUPT)


def answer(fn: Any, *args: Any) -> Any:
    """What the SDK call ``fn(*args)`` returns, asked again while the SDK gave up waiting
    (not an answer: this machine may be busy; the late reply is let arrive and cleared
    first, or the SDK would take it for the next one's); a wrong answer is returned."""
    port = args[0] if args else fn.__self__.port
    for _ in range(TRIES):
        got = fn(*args)
        result = got if isinstance(got, int) else got[-2]
        if result not in NO_ANSWER:
            return got
        time.sleep(0.1)
        port.clearPort()
    raise AssertionError(f"no answer to {fn.__name__}{args[1:]} in {TRIES} tries")


def open_sdk(path: str) -> tuple[object, object]:
    port = sdk.PortHandler(path)
    assert port.openPort() and port.setBaudRate(1_000_000)
    return port, sdk.PacketHandler(0)


def test_the_official_sdk_pings_reads_writes_and_sync_reads_the_emulated_so101() -> None:
    cfg = load_model("so101").drivers["feetech"]
    assert [*cfg["ids"], cfg["gripper_id"]] == list(IDS)
    with emulate("feetech", "--arm", "so101") as (path, report):
        port, ph = open_sdk(path)
        for sid in IDS:  # PING: the SDK's ping is PING, then READ of Model Number
            assert answer(ph.ping, port, sid) == (777, OK, 0)  # type: ignore[attr-defined]
            assert answer(ph.read1ByteTxRx, port, sid, ID) == (sid, OK, 0)  # type: ignore[attr-defined]
            assert answer(ph.read2ByteTxRx, port, sid, MODEL_NUMBER) == (777, OK, 0)  # type: ignore[attr-defined]
        assert ph.ping(port, 7)[1] == sdk.COMM_RX_TIMEOUT  # type: ignore[attr-defined]
        group = sdk.GroupSyncRead(port, ph, PRESENT, 2)
        for sid in IDS:
            assert group.addParam(sid)
        assert answer(group.txRxPacket) == OK
        synced = {sid: group.getData(sid, PRESENT, 2) for sid in IDS}
        for sid in IDS:  # one READ each says the same
            assert answer(ph.read2ByteTxRx, port, sid, PRESENT) == (synced[sid], OK, 0)  # type: ignore[attr-defined]
            assert 0 <= synced[sid] <= 4095
        assert synced[1] == 2048  # shoulder_pan at home, 0 deg: the middle step
        # WRITE: torque is on where armkit's model puts the arm; a goal is taken and reached
        assert answer(ph.read1ByteTxRx, port, 2, TORQUE) == (1, OK, 0)  # type: ignore[attr-defined]
        goal = synced[2] + 250
        assert answer(ph.write2ByteTxRx, port, 2, GOAL, goal) == (OK, 0)  # type: ignore[attr-defined]
        assert answer(ph.read2ByteTxRx, port, 2, GOAL) == (goal, OK, 0)  # type: ignore[attr-defined]
        deadline = time.monotonic() + WAIT_S
        while answer(ph.read2ByteTxRx, port, 2, PRESENT)[0] != goal and time.monotonic() < deadline:  # type: ignore[attr-defined]
            time.sleep(0.02)
        assert answer(ph.read2ByteTxRx, port, 2, PRESENT) == (goal, OK, 0)  # type: ignore[attr-defined]
        assert answer(ph.read1ByteTxRx, port, 2, MOVING) == (0, OK, 0)  # type: ignore[attr-defined]
        # a value outside the table's range: the status says nothing, the value is not taken
        assert answer(ph.write2ByteTxRx, port, 1, MAX_TORQUE, 1001) == (OK, 0)  # type: ignore[attr-defined]
        assert answer(ph.read2ByteTxRx, port, 1, MAX_TORQUE) == (1000, OK, 0)  # type: ignore[attr-defined]
        port.closePort()  # type: ignore[attr-defined]
    assert any("answered" in line for line in report), report


def test_a_second_process_on_the_feetech_port_is_refused(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    env = {**os.environ, "ARMKIT_CONFIG_DIR": str(tmp_path)}
    monkeypatch.setenv("ARMKIT_CONFIG_DIR", str(tmp_path))
    holder = (
        "import sys\nfrom armkit.devices.feetech import FeetechBus\n"
        "bus = FeetechBus(sys.argv[1])\nprint('open', flush=True)\nsys.stdin.read()"
    )
    with emulate("feetech", "--arm", "so101") as (path, _):
        child = subprocess.Popen(
            [sys.executable, "-c", holder, path],
            stdin=subprocess.PIPE,
            stdout=subprocess.PIPE,
            text=True,
            env=env,
        )
        try:
            assert child.stdout is not None and child.stdout.readline().strip() == "open"
            with pytest.raises(DeviceError, match=rf"in use by process {child.pid}"):
                FeetechBus(path)
        finally:
            assert child.stdin is not None
            child.stdin.close()
            child.wait(timeout=30)
        FeetechBus(path).close()  # free again once the first process has gone
