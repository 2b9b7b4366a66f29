"""The group instructions of a simulated Dynamixel bus: one packet, many servos.

ROBOTIS e-Manual, "DYNAMIXEL Protocol 2.0": SYNC_READ (0x82) and SYNC_WRITE
(0x83) address one register block on many IDs; BULK_READ (0x92) and
BULK_WRITE (0x93) a block per ID; FAST_SYNC_READ (0x8A) and FAST_BULK_READ (0x9A)
answer with ONE status packet (ID 0xFE, not byte-stuffed) in which each servo's part
is ``ERR ID DATA CRC``, each CRC over the packet so far, the last part's CRC being
the packet's own. Every packet is broadcast: writes get no status; a servo whose
Status Return Level is 0 gives no read reply, one whose firmware predates the fast
reads (``notes.FROM_FIRMWARE``) takes no part in them.
"""

from __future__ import annotations

from collections.abc import Callable

from ..devices import dxl_packet as pkt
from ..devices import xm430 as xm
from .xm430 import XM430


def u16(params: bytes, offset: int) -> int:
    """The little-endian 16-bit parameter at ``offset``."""
    return int.from_bytes(params[offset : offset + 2], "little")


def answers_reads(servo: XM430) -> bool:
    """True unless the servo's Status Return Level (68) is 0 (PING only)."""
    return servo.value("Status Return Level") >= xm.STATUS_LEVEL_READ


class GroupInstructions:
    """Mixin of ``SimDynamixelBus``: the handlers of the group instructions."""

    def group_instructions(self) -> dict[int, Callable[[pkt.Packet], None]]:
        """Instruction -> handler of the group instructions."""
        return {
            pkt.Inst.SYNC_READ: self._sync_read,
            pkt.Inst.SYNC_WRITE: self._sync_write,
            pkt.Inst.FAST_SYNC_READ: self._fast_sync_read,
            pkt.Inst.BULK_READ: self._bulk_read,
            pkt.Inst.BULK_WRITE: self._bulk_write,
            pkt.Inst.FAST_BULK_READ: self._fast_bulk_read,
        }

    def by_id(self, servo_id: int) -> XM430 | None:
        """The present servo whose ID register is ``servo_id`` (the bus defines it)."""
        raise NotImplementedError

    def reply(self, servo: XM430, error: int = 0, data: bytes = b"") -> None:
        """Send ``servo``'s status packet (the bus defines it)."""
        raise NotImplementedError

    def send(self, sid: int, frame: bytes) -> None:
        """Put ``frame`` on the bus as servo ``sid`` (the bus defines it)."""
        raise NotImplementedError

    def _read_one(self, servo_id: int, address: int, size: int) -> None:
        servo = self.by_id(servo_id)
        if servo is None or not answers_reads(servo):
            return
        if address + size > xm.CONTROL_TABLE_SIZE:
            self.reply(servo, pkt.ACCESS_ERROR)
        else:
            self.reply(servo, 0, servo.read(address, size))

    def _sync_read(self, packet: pkt.Packet) -> None:
        address, size = u16(packet.params, 0), u16(packet.params, 2)
        for servo_id in packet.params[4:]:
            self._read_one(servo_id, address, size)

    def _sync_write(self, packet: pkt.Packet) -> None:
        params = packet.params
        address, size, body = u16(params, 0), u16(params, 2), params[4:]
        for offset in range(0, len(body) - size, size + 1):
            servo = self.by_id(body[offset])
            if servo is not None:
                servo.write(address, body[offset + 1 : offset + 1 + size])

    def _bulk_read(self, packet: pkt.Packet) -> None:
        params = packet.params
        for offset in range(0, len(params) - 4, 5):
            self._read_one(params[offset], u16(params, offset + 1), u16(params, offset + 3))

    def _bulk_write(self, packet: pkt.Packet) -> None:
        params, offset = packet.params, 0
        while offset + 5 <= len(params):
            servo_id, address, size = (
                params[offset],
                u16(params, offset + 1),
                u16(params, offset + 3),
            )
            data = params[offset + 5 : offset + 5 + size]
            servo = self.by_id(servo_id)
            if servo is not None and len(data) == size:
                servo.write(address, data)
            offset += 5 + size

    def _fast_sync_read(self, packet: pkt.Packet) -> None:
        address, size = u16(packet.params, 0), u16(packet.params, 2)
        self._fast_reply([(sid, address, size) for sid in packet.params[4:]], "Fast Sync Read")

    def _fast_bulk_read(self, packet: pkt.Packet) -> None:
        params = packet.params
        blocks = [
            (params[k], u16(params, k + 1), u16(params, k + 3))
            for k in range(0, len(params) - 4, 5)
        ]
        self._fast_reply(blocks, "Fast Bulk Read")

    def _fast_reply(self, blocks: list[tuple[int, int, int]], feature: str) -> None:
        """One status packet for every (ID, address, size) whose servo answers reads."""
        parts = []
        for servo_id, address, size in blocks:
            servo = self.by_id(servo_id)
            if servo is None or not answers_reads(servo) or not servo.has(feature):
                continue
            if address + size > xm.CONTROL_TABLE_SIZE:
                return
            parts.append((servo_id, servo.error_bits, servo.read(address, size)))
        if not parts:
            return
        length = sum(len(data) + 4 for _, _, data in parts) + 1  # INST + parts (+ CRC)
        frame = bytearray(pkt.HEADER + bytes((pkt.BROADCAST_ID, length & 0xFF, length >> 8)))
        frame.append(pkt.Inst.STATUS)
        for sid, error, data in parts:
            frame += bytes((error, sid)) + data
            crc = pkt.crc16(frame)
            frame += bytes((crc & 0xFF, crc >> 8))
        self.send(parts[0][0], bytes(frame))
