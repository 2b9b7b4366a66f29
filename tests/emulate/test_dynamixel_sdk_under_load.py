"""The official dynamixel-sdk against ``armkit emulate dynamixel`` in another process
while every core is busy twice over (issue 27 Done-when; ``emulated`` says how).

The stress test sends ``REQUESTS`` requests (10,000 with ARMKIT_TEST_PROFILE=large)
through the SDK's PacketHandler as ROBOTIS's examples do, each with an answer known in
advance and different from the one before, so a reply to an earlier request taken for
this one (a stale reply, as the SDK takes any status from the right ID) is seen. A
request the SDK gave up on (its timeout, on a machine this busy) is counted, not
failed: it is not an answer.
"""

from __future__ import annotations

import os

import pytest
from emulated import cpu_load, emulate

sdk = pytest.importorskip("dynamixel_sdk")
OK = sdk.COMM_SUCCESS
IDS = (11, 12, 13, 14, 15)
REQUESTS = 10_000 if os.environ.get("ARMKIT_TEST_PROFILE") == "large" else 2_000
# (address, size, value for servo sid): registers whose values differ between neighbours
KNOWN = (
    (112, 4, lambda sid: 1000 + sid),  # Profile Velocity, written first
    (7, 1, lambda sid: sid),  # ID
    (0, 2, lambda sid: 1020),  # Model Number
    (24, 4, lambda sid: 500 + sid),  # Moving Threshold, written first
    (6, 1, lambda sid: 46),  # Firmware Version
)


def read(ph: object, port: object, sid: int, address: int, size: int) -> tuple[int, int]:
    """(result, value) of one READ through the SDK; a short reply (another request's
    status) counts as a wrong value."""
    fn = {1: ph.read1ByteTxRx, 2: ph.read2ByteTxRx, 4: ph.read4ByteTxRx}[size]  # type: ignore[attr-defined]
    try:
        value, result, _ = fn(port, sid, address)
    except IndexError:  # the SDK indexes a shorter status than it asked for
        return OK, -1
    return result, value


def test_the_sdk_never_takes_a_stale_reply_under_load() -> None:
    with cpu_load(), emulate("dynamixel", "--arm", "openmanipulator_x") as (path, report):
        port = sdk.PortHandler(path)
        assert port.openPort() and port.setBaudRate(1_000_000)
        ph = sdk.PacketHandler(2.0)
        for sid in IDS:
            for address, _size, value in KNOWN:
                if address in (112, 24):
                    assert ph.write4ByteTxRx(port, sid, address, value(sid)) == (OK, 0)
        stale, timeouts = [], 0
        for k in range(REQUESTS):
            sid = IDS[k % len(IDS)]
            address, size, value = KNOWN[k % len(KNOWN)]
            result, got = read(ph, port, sid, address, size)
            if result != OK:
                timeouts += 1
            elif got != value(sid):
                stale.append((k, sid, address, got))
        port.closePort()
    assert not stale, f"{len(stale)} stale replies of {REQUESTS} ({timeouts} timeouts): {stale[:5]}"
    assert any("answered" in line for line in report), report
