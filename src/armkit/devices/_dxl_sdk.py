"""The ROBOTIS dynamixel-sdk seen from armkit: lazy import, result codes, sync-read replies,
and the choice between the SDK and armkit's own stand-in (``_dxl_protocol``).

The SDK is imported only when a bus is opened (``dynamixel`` extra), never
when armkit is.
"""

from __future__ import annotations

import importlib.util
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any

from .._errors import DeviceError
from ._port import gone

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


@dataclass(frozen=True)
class Protocol:
    """Where a bus gets its Protocol 2.0 client: the SDK's classes or armkit's stand-ins."""

    name: str
    packet_handler: Callable[[], Any]
    group_sync_write: Callable[..., Any]
    group_sync_read: Callable[..., Any]


def sdk_protocol() -> Protocol:
    """The ROBOTIS dynamixel-sdk (DeviceError if it is not installed)."""
    sdk = import_sdk()
    return Protocol(
        "dynamixel-sdk", lambda: sdk.PacketHandler(2.0), sdk.GroupSyncWrite, sdk.GroupSyncRead
    )


def own_protocol() -> Protocol:
    """armkit's own client with the SDK's interface (``_dxl_protocol``)."""
    from . import _dxl_protocol as own

    return Protocol("armkit", own.PacketHandler, own.GroupSyncWrite, own.GroupSyncRead)


def installed_protocol() -> Protocol:
    """The SDK where it is installed, else armkit's own client."""
    has_sdk = importlib.util.find_spec("dynamixel_sdk") is not None
    return sdk_protocol() if has_sdk else own_protocol()


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


class GuardedPort:
    """An SDK port handler whose OS or pyserial failures (a vanished adapter: termios.error,
    SerialException, OSError) come out as a DeviceError naming the port."""

    def __init__(self, port: Any, device: str = "Dynamixel bus") -> None:
        object.__setattr__(self, "_inner", port)
        object.__setattr__(self, "_device", device)

    def __getattr__(self, name: str) -> Any:
        value = getattr(self._inner, name)
        if not callable(value):
            return value
        return lambda *args, **kwargs: self._call(name, value, args, kwargs)

    def __setattr__(self, name: str, value: Any) -> None:
        setattr(self._inner, name, value)

    def _call(self, name: str, method: Any, args: Any, kwargs: Any) -> Any:
        try:
            return method(*args, **kwargs)
        except DeviceError:
            raise
        except Exception as exc:
            self._inner.is_using = False  # the SDK would call the port busy from now on
            where = getattr(self._inner, "port_name", "") or f"the {self._device}'s port"
            raise gone(self._device, where, name, exc) from exc
