"""The ROBOTIS dynamixel-sdk seen from armkit: lazy import, result codes, sync-read replies.

The SDK is imported only when a bus is opened (``dynamixel`` extra), never
when armkit is.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from .._errors import DeviceError

COMM_SUCCESS = 0
COMM_RX_CORRUPT = -3002
_COMM_FAULTS = {
    -1000: "port busy",
    -1001: "transmit failed",
    -1002: "receive failed",
    -3001: "no reply (timeout)",
    -3002: "corrupt reply (bad CRC or truncated)",
}


def import_sdk() -> Any:
    try:
        import dynamixel_sdk
    except ModuleNotFoundError:
        raise DeviceError(
            "the Dynamixel bus needs dynamixel-sdk: pip install 'armkit[dynamixel]'"
        ) from None
    return dynamixel_sdk


def comm_fault(result: int) -> str:
    """Text for an SDK communication result code."""
    return _COMM_FAULTS.get(result, f"communication result {result}")


def sized(reply: tuple[Any, int, int], size: int) -> tuple[Any, int, int]:
    """Mark a reply whose data is not the requested size as corrupt (the SDK only
    checks the ID, so a stray status of another request would pass)."""
    data, result, error = reply
    if result == COMM_SUCCESS and len(data) != size:
        return data, COMM_RX_CORRUPT, error
    return data, result, error


def sync_read_replies(
    group: Any, packet_handler: Any, port: Any, ids: Sequence[int]
) -> tuple[int, int, dict[int, tuple[bytes, int]]]:
    """Send ``group``'s SYNC_READ and collect each reply: (failing ID or -1, result,
    {ID: (data, error byte)}). GroupSyncRead's own rxPacket drops the error byte (and
    so the hardware alert), so the replies are read one by one with ``readRx``."""
    result = group.txPacket()
    replies: dict[int, tuple[bytes, int]] = {}
    for sid in ids:
        if result == COMM_SUCCESS:
            reply = packet_handler.readRx(port, sid, group.data_length)
            data, result, error = sized(reply, group.data_length)
        if result != COMM_SUCCESS:
            return sid, result, replies
        replies[sid] = (bytes(data), error)
    return -1, result, replies
