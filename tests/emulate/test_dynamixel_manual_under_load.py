"""The e-Manual's answers from ``armkit emulate dynamixel`` in another process, through
the official dynamixel-sdk, while every core is busy twice over (issue 27 Done-when).

The same Range column as tests/dynamixel/test_dxl_ranges.py (copied from ROBOTIS's
e-Manual, "XM430-W350", control table) and the Protocol 2.0 errors, on five XM430s
at 1 Mbit/s; a request the SDK timed out on is asked again (a timeout is no answer).
Between cases the servo is reset (Factory Reset 0x02: all but ID and baud rate).
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import Any

import pytest
from emulated import cpu_load, emulate
from test_dxl_ranges import RANGE_COLUMN

sdk = pytest.importorskip("dynamixel_sdk")
OK = sdk.COMM_SUCCESS
TRIES = 5


class Line:
    """The SDK on the emulator's pty; every call asked again after a timeout."""

    def __init__(self, path: str) -> None:
        self.port = sdk.PortHandler(path)
        assert self.port.openPort() and self.port.setBaudRate(1_000_000)
        self.ph = sdk.PacketHandler(2.0)

    def ask(self, fn: Any, *args: Any) -> Any:
        for _ in range(TRIES):
            answer = fn(self.port, *args)
            result = answer if isinstance(answer, int) else answer[-2]
            if result != sdk.COMM_RX_TIMEOUT:
                return answer
        raise AssertionError(f"no answer to {fn.__name__}{args} in {TRIES} tries")

    def w(self, sid: int, address: int, size: int, value: int) -> tuple[int, int]:
        data = list((value & (256**size - 1)).to_bytes(size, "little"))
        return tuple(self.ask(self.ph.writeTxRx, sid, address, size, data))  # type: ignore[return-value]

    def r(self, sid: int, address: int, size: int) -> int:
        data, result, _ = self.ask(self.ph.readTxRx, sid, address, size)
        assert result == OK
        return int.from_bytes(bytes(data), "little", signed=size > 1)


@pytest.fixture(scope="module")
def line() -> Iterator[Line]:
    with cpu_load(), emulate("dynamixel") as (path, _):
        on = Line(path)
        yield on
        on.port.closePort()


@pytest.mark.parametrize(("name", "address", "size", "low", "high", "safe"), RANGE_COLUMN)
def test_the_range_column(
    line: Line, name: str, address: int, size: int, low: int, high: int, safe: bool
) -> None:
    """XM430-W350 control table, Range column: one beyond either end is a Data Range
    Error (4) and changes nothing; the ends are taken."""
    before = line.r(12, address, size)
    for beyond in (low - 1, high + 1):
        if beyond.bit_length() < 8 * size:
            assert line.w(12, address, size, beyond) == (OK, 4), beyond
    assert line.r(12, address, size) == before
    if safe:
        for end in (low, high):
            assert line.w(12, address, size, end) == (OK, 0)
            assert line.r(12, address, size) == end
    assert line.ask(line.ph.factoryReset, 12, 0x02) == (OK, 0)


def test_protocol_errors(line: Line) -> None:
    """Protocol 2.0 Status Packet errors: 5 Data Length (2 of Goal Position's 4 bytes),
    7 Access (read-only; EEPROM with torque on), 6 Data Limit (Goal Position beyond Max
    Position Limit), 2 Instruction (ACTION with nothing registered is checked in-process:
    the SDK's action() reads no status); PING answers Model Number 1020."""
    assert line.ask(line.ph.ping, 13) == (1020, OK, 0)
    assert tuple(line.ask(line.ph.writeTxRx, 13, 116, 2, [0, 1])) == (OK, 5)
    assert line.w(13, 132, 4, 0) == (OK, 7)
    assert line.w(13, 64, 1, 1) == (OK, 0)
    assert line.w(13, 9, 1, 100) == (OK, 7)
    assert line.w(13, 116, 4, 4096) == (OK, 6)
    assert line.w(13, 64, 1, 0) == (OK, 0)
    undefined = [0] * 10
    undefined[sdk.PKT_ID], undefined[sdk.PKT_LENGTH_L], undefined[sdk.PKT_INSTRUCTION] = 13, 3, 7
    _, result, error = line.ask(line.ph.txRxPacket, undefined)
    assert (result, error) == (OK, 2)


def test_id_254_and_baud_rate_8_are_refused(line: Line) -> None:
    """XM430-W350 "ID (7)" 0 ~ 252, "Baud Rate (8)" 0 ~ 7: Data Range Error, and the
    servo still answers at its ID and rate."""
    assert line.w(14, 7, 1, 254) == (OK, 4)
    assert line.w(14, 8, 1, 8) == (OK, 4)
    assert line.ask(line.ph.ping, 14) == (1020, OK, 0)


def test_fast_bulk_read(line: Line) -> None:
    """ "Fast Bulk Read (0x9A)": one status packet for every servo asked."""
    for _ in range(TRIES):
        bulk = sdk.GroupBulkRead(line.port, line.ph)
        bulk.addParam(11, 0, 2), bulk.addParam(15, 7, 1)
        if bulk.fastBulkRead() == OK:
            break
    assert bulk.getData(11, 0, 2) == 1020 and bulk.getData(15, 7, 1) == 15
