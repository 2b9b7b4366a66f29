"""Feetech SCS/STS packets: instruction and status frames, the checksum, splitting a stream.

Feetech's communication protocol (the FT-SCS protocol of the SMS/STS servos, as its
``scservo_sdk`` ``protocol_packet_handler.py`` builds it):

* instruction packet: ``FF FF ID LEN INST PARAM... CHK`` with LEN = params + 2;
* status packet: ``FF FF ID LEN ERR PARAM... CHK`` (ERR = the servo's Status bits);
* CHK = ~(ID + LEN + INST/ERR + params) & 0xFF.

Instructions: PING 1, READ 2, WRITE 3, REG WRITE 4, ACTION 5, RESET 6, SYNC READ 0x82,
SYNC WRITE 0x83. Broadcast ID 0xFE (254): no status packet.
"""

from __future__ import annotations

from dataclasses import dataclass
from enum import IntEnum

HEADER = b"\xff\xff"
BROADCAST_ID = 0xFE
MAX_LENGTH = 250  # the SDK's TXPACKET_MAX_LEN / RXPACKET_MAX_LEN


class Inst(IntEnum):
    """Instruction codes."""

    PING = 0x01
    READ = 0x02
    WRITE = 0x03
    REG_WRITE = 0x04
    ACTION = 0x05
    RESET = 0x06
    SYNC_READ = 0x82
    SYNC_WRITE = 0x83


@dataclass(frozen=True)
class Packet:
    """One frame: ``code`` is the instruction (instruction packet) or the error byte
    (status packet); ``params`` the bytes between it and the checksum."""

    id: int
    code: int
    params: bytes


def checksum(body: bytes | bytearray) -> int:
    """~(sum of ID .. last parameter) & 0xFF."""
    return ~sum(body) & 0xFF


def frame(servo_id: int, code: int, params: bytes = b"") -> bytes:
    """The frame for ``servo_id`` with instruction or error ``code`` and ``params``."""
    body = bytes((servo_id, len(params) + 2, code)) + bytes(params)
    return HEADER + body + bytes((checksum(body),))


def status(servo_id: int, error: int, data: bytes = b"") -> bytes:
    """A status packet."""
    return frame(servo_id, error, data)


def split(buffer: bytes | bytearray) -> tuple[bytes | None, int]:
    """(the first whole frame in ``buffer`` or None, how many bytes to drop). Bytes before
    a header are dropped; a frame whose checksum is wrong comes back as it is (``decode``
    refuses it), so a servo ignores it."""
    start = bytes(buffer).find(HEADER)
    if start < 0:
        return None, max(0, len(buffer) - 1)
    while start + 2 < len(buffer) and buffer[start + 2] == 0xFF:  # FF FF FF: slide over
        start += 1
    if len(buffer) < start + 4:
        return None, start
    total = buffer[start + 3] + 4
    if buffer[start + 3] < 2 or buffer[start + 3] > MAX_LENGTH:
        return None, start + 2  # an impossible length: not a header after all
    if len(buffer) < start + total:
        return None, start
    return bytes(buffer[start : start + total]), start + total


class PacketError(ValueError):
    """A frame with a wrong checksum or length."""


def decode(data: bytes) -> Packet:
    """A whole frame -> Packet (PacketError if its checksum or length is wrong)."""
    if len(data) < 6 or data[:2] != HEADER or data[3] + 4 != len(data):
        raise PacketError(f"not a whole frame: {data.hex(' ')}")
    if checksum(data[2:-1]) != data[-1]:
        raise PacketError(f"bad checksum: {data.hex(' ')}")
    return Packet(data[2], data[4], bytes(data[5:-1]))
