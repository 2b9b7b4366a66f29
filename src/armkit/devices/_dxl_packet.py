"""Dynamixel Protocol 2.0 packets as pure functions: bytes in, bytes out.

Frame layout (every integer little-endian)::

    FF FF FD 00 | ID | LEN_L LEN_H | INST | PARAMS... | CRC_L CRC_H

``LEN`` counts INST + PARAMS + CRC, after byte stuffing (so ``len(params) + 3``
when nothing is stuffed). The CRC is CRC-16/BUYPASS (poly 0x8005, init 0, not
reflected) over everything from the header to the last parameter, after
stuffing. Byte stuffing: wherever ``FF FF FD`` occurs in INST + PARAMS, one
extra ``FD`` follows it on the wire, so a body can never look like a header.

A status packet (the servo's reply) has INST 0x55; its first parameter is the
error byte: bit 7 = hardware alert (read Hardware Error Status), bits 0..6 =
the error number of the instruction (``STATUS_ERRORS``).

armkit's bus talks through the ROBOTIS SDK; these functions are the
independent implementation that the emulator, the tests and the benchmark use.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from enum import IntEnum

from .._errors import DeviceError, InputError

HEADER = b"\xff\xff\xfd\x00"
BROADCAST_ID = 0xFE
ALERT_BIT = 0x80
_STUFF_PATTERN = b"\xff\xff\xfd"
_MIN_FRAME = 10  # header 4 + ID + LEN 2 + INST + CRC 2


class Inst(IntEnum):
    """Instruction codes of Protocol 2.0 (the ones armkit uses or emulates)."""

    PING = 0x01
    READ = 0x02
    WRITE = 0x03
    REG_WRITE = 0x04
    ACTION = 0x05
    FACTORY_RESET = 0x06
    REBOOT = 0x08
    CLEAR = 0x10
    BACKUP = 0x20
    STATUS = 0x55
    SYNC_READ = 0x82
    SYNC_WRITE = 0x83
    FAST_SYNC_READ = 0x8A
    BULK_READ = 0x92
    BULK_WRITE = 0x93
    FAST_BULK_READ = 0x9A


# Status error numbers ("DYNAMIXEL Protocol 2.0", Status Packet, Error)
RESULT_FAIL, INSTRUCTION_ERROR, CRC_ERROR, DATA_RANGE_ERROR = 1, 2, 3, 4
DATA_LENGTH_ERROR, DATA_LIMIT_ERROR, ACCESS_ERROR = 5, 6, 7


STATUS_ERRORS: dict[int, str] = {
    0: "no error",
    1: "result fail",
    2: "instruction error",
    3: "CRC error",
    4: "data range error",
    5: "data length error",
    6: "data limit error",
    7: "access error",
}


class PacketError(DeviceError):
    """Bytes that are not a valid Protocol 2.0 packet (bad header, length or CRC)."""


@dataclass(frozen=True, slots=True)
class Packet:
    """One decoded packet: ``params`` are unstuffed; for a status the error byte is params[0]."""

    id: int
    instruction: int
    params: bytes

    @property
    def error(self) -> int:
        """Status error byte (0 for instruction packets or an empty status)."""
        return self.params[0] if self.instruction == Inst.STATUS and self.params else 0

    @property
    def alert(self) -> bool:
        """True when a status packet carries the hardware-alert bit."""
        return bool(self.error & ALERT_BIT)

    @property
    def data(self) -> bytes:
        """Status payload after the error byte; instruction parameters otherwise."""
        return self.params[1:] if self.instruction == Inst.STATUS else self.params


def _make_crc_table() -> tuple[int, ...]:
    table = []
    for byte in range(256):
        crc = byte << 8
        for _ in range(8):
            crc = ((crc << 1) ^ 0x8005) if crc & 0x8000 else crc << 1
        table.append(crc & 0xFFFF)
    return tuple(table)


_CRC_TABLE = _make_crc_table()


def crc16(data: bytes | bytearray) -> int:
    """CRC-16 of ``data`` (poly 0x8005, init 0, MSB first, no final xor)."""
    crc = 0
    for byte in data:
        crc = ((crc << 8) ^ _CRC_TABLE[((crc >> 8) ^ byte) & 0xFF]) & 0xFFFF
    return crc


def stuff(body: bytes) -> bytes:
    """Insert an ``FD`` after every ``FF FF FD`` in INST + PARAMS."""
    return body.replace(_STUFF_PATTERN, _STUFF_PATTERN + b"\xfd")


def unstuff(body: bytes) -> bytes:
    """Undo :func:`stuff`: ``FF FF FD FD`` becomes ``FF FF FD``."""
    return body.replace(_STUFF_PATTERN + b"\xfd", _STUFF_PATTERN)


def encode(servo_id: int, instruction: int, params: bytes = b"") -> bytes:
    """A complete frame for ``servo_id`` (0..253, 254 = broadcast), stuffed and CRC'd."""
    if not 0 <= servo_id <= BROADCAST_ID:
        raise InputError(f"servo ID {servo_id} is outside 0..254")
    body = stuff(bytes((instruction,)) + params)
    length = len(body) + 2
    frame = HEADER + bytes((servo_id, length & 0xFF, length >> 8)) + body
    crc = crc16(frame)
    return frame + bytes((crc & 0xFF, crc >> 8))


def decode(frame: bytes) -> Packet:
    """Parse one whole frame (as :func:`split_frame` returns it).

    Raises:
        PacketError: wrong header, length that disagrees with the frame, or bad CRC.
    """
    if len(frame) < _MIN_FRAME or frame[:4] != HEADER:
        raise PacketError(f"not a Protocol 2.0 frame: {frame.hex(' ')}")
    if int.from_bytes(frame[5:7], "little") != len(frame) - 7:
        raise PacketError(f"length field disagrees with a {len(frame)}-byte frame")
    if crc16(frame[:-2]) != int.from_bytes(frame[-2:], "little"):
        raise PacketError(f"CRC mismatch in frame {frame.hex(' ')}")
    body = unstuff(frame[7:-2])
    return Packet(id=frame[4], instruction=body[0], params=body[1:])


def split_frame(buffer: bytes | bytearray) -> tuple[bytes | None, int]:
    """Find the first complete frame in a byte stream.

    Returns:
        (frame, consumed): the frame (or None when more bytes are needed) and
        how many leading bytes of ``buffer`` to drop (garbage + the frame).
    """
    start = bytes(buffer).find(HEADER)
    if start < 0:
        return None, max(0, len(buffer) - 3)
    if len(buffer) < start + 7:
        return None, start
    end = start + 7 + int.from_bytes(buffer[start + 5 : start + 7], "little")
    if len(buffer) < end:
        return None, start
    return bytes(buffer[start:end]), end


def ping(servo_id: int) -> bytes:
    """PING instruction frame."""
    return encode(servo_id, Inst.PING)


def reboot(servo_id: int) -> bytes:
    """REBOOT instruction frame."""
    return encode(servo_id, Inst.REBOOT)


def read(servo_id: int, address: int, size: int) -> bytes:
    """READ ``size`` bytes from ``address``."""
    return encode(servo_id, Inst.READ, _u16(address) + _u16(size))


def write(servo_id: int, address: int, data: bytes) -> bytes:
    """WRITE ``data`` (already encoded, little-endian) at ``address``."""
    return encode(servo_id, Inst.WRITE, _u16(address) + data)


def sync_read(address: int, size: int, ids: Iterable[int]) -> bytes:
    """SYNC_READ of ``size`` bytes at ``address`` from each of ``ids`` (broadcast)."""
    return encode(BROADCAST_ID, Inst.SYNC_READ, _u16(address) + _u16(size) + bytes(ids))


def sync_write(address: int, size: int, data: Mapping[int, bytes]) -> bytes:
    """SYNC_WRITE: ``data`` maps servo ID -> ``size`` encoded bytes for that servo."""
    if any(len(value) != size for value in data.values()):
        raise InputError(f"every SYNC_WRITE entry must be {size} bytes")
    params = b"".join(bytes((sid,)) + value for sid, value in data.items())
    return encode(BROADCAST_ID, Inst.SYNC_WRITE, _u16(address) + _u16(size) + params)


def status(servo_id: int, error: int = 0, data: bytes = b"") -> bytes:
    """A status (reply) frame with ``error`` byte and ``data`` payload."""
    return encode(servo_id, Inst.STATUS, bytes((error,)) + data)


def describe_error(error: int) -> str:
    """Human text for a status error byte (``"data range error, hardware alert"``)."""
    text = STATUS_ERRORS.get(error & 0x7F, f"error {error & 0x7F}")
    return text + (", hardware alert" if error & ALERT_BIT else "")


def _u16(value: int) -> bytes:
    return value.to_bytes(2, "little")
