"""armkit's own Feetech client with the ``scservo_sdk``'s interface, on armkit's codec.

``FeetechBus`` talks through Feetech's SDK where it is installed; where it is not (the
simulator needs only numpy) these stand in for it: ``PacketHandler`` (``ping``,
``readTxRx``, ``writeTxRx``, ``regWriteTxRx``, ``action``, ``txRxPacket``, ``readRx``,
``syncReadTx``, ``syncWriteTxOnly``), ``GroupSyncWrite`` and ``GroupSyncRead``, sending
the same bytes as the SDK (tests compare them). Ports are the SDK-style port handlers
(``_dxl_protocol.PortHandler``): ``is_using``, ``clearPort``, ``writePort``,
``readPort``, ``setPacketTimeout``, ``isPacketTimeout``.
"""

from __future__ import annotations

from typing import Any

from . import _scs_packet as scs

COMM_SUCCESS, COMM_PORT_BUSY, COMM_TX_FAIL = 0, -1, -2
COMM_RX_TIMEOUT, COMM_RX_CORRUPT, COMM_NOT_AVAILABLE = -6, -7, -9


class PacketHandler:
    """The SDK's ``PacketHandler(0)`` (STS: little-endian words)."""

    def __init__(self, protocol_end: int = 0) -> None:
        self.protocol_end = protocol_end

    def txPacket(self, port: Any, packet: list[int] | bytes) -> int:
        if port.is_using:
            return COMM_PORT_BUSY
        port.is_using = True
        raw = bytes(packet)
        frame = scs.frame(raw[2], raw[4], raw[5 : 5 + raw[3] - 2])
        port.clearPort()
        if port.writePort(frame) != len(frame):
            port.is_using = False
            return COMM_TX_FAIL
        return COMM_SUCCESS

    def rxPacket(self, port: Any) -> tuple[list[int], int]:
        buffer = bytearray()
        while True:
            buffer += port.readPort(_missing(buffer))
            found, consumed = scs.split(buffer)
            if found is not None:
                port.is_using = False
                try:
                    scs.decode(found)
                except scs.PacketError:
                    return list(found), COMM_RX_CORRUPT
                return list(found), COMM_SUCCESS
            del buffer[:consumed]
            if port.isPacketTimeout():
                port.is_using = False
                return list(buffer), COMM_RX_CORRUPT if buffer else COMM_RX_TIMEOUT

    def txRxPacket(self, port: Any, packet: list[int]) -> tuple[Any, int, int]:
        result = self.txPacket(port, packet)
        if result != COMM_SUCCESS:
            return None, result, 0
        if packet[2] == scs.BROADCAST_ID:
            port.is_using = False
            return None, result, 0
        port.setPacketTimeout(packet[6] + 6 if packet[4] == scs.Inst.READ else 6)
        while True:
            reply, result = self.rxPacket(port)
            if result != COMM_SUCCESS or reply[2] == packet[2]:
                break
        return reply, result, reply[4] if result == COMM_SUCCESS else 0

    def _packet(self, servo_id: int, inst: int, params: list[int]) -> list[int]:
        return [0xFF, 0xFF, servo_id, len(params) + 2, inst, *params, 0]

    def ping(self, port: Any, scs_id: int) -> tuple[int, int, int]:
        if scs_id >= scs.BROADCAST_ID:
            return 0, COMM_NOT_AVAILABLE, 0
        _, result, error = self.txRxPacket(port, self._packet(scs_id, scs.Inst.PING, []))
        if result != COMM_SUCCESS:
            return 0, result, error
        data, result, error = self.readTxRx(port, scs_id, 3, 2)
        model = data[0] | data[1] << 8 if result == COMM_SUCCESS else 0
        return model, result, error

    def action(self, port: Any, scs_id: int) -> int:
        return self.txRxPacket(port, self._packet(scs_id, scs.Inst.ACTION, []))[1]

    def readTxRx(self, port: Any, scs_id: int, address: int, length: int) -> tuple[Any, int, int]:
        if scs_id >= scs.BROADCAST_ID:
            return [], COMM_NOT_AVAILABLE, 0
        packet = self._packet(scs_id, scs.Inst.READ, [address, length])
        reply, result, error = self.txRxPacket(port, packet)
        return (reply[5 : 5 + length] if result == COMM_SUCCESS else []), result, error

    def readRx(self, port: Any, scs_id: int, length: int) -> tuple[Any, int, int]:
        while True:
            reply, result = self.rxPacket(port)
            if result != COMM_SUCCESS or reply[2] == scs_id:
                break
        if result != COMM_SUCCESS:
            return [], result, 0
        return reply[5 : 5 + length], result, reply[4]

    def writeTxRx(
        self, port: Any, scs_id: int, address: int, length: int, data: list[int]
    ) -> tuple[int, int]:
        packet = self._packet(scs_id, scs.Inst.WRITE, [address, *data[:length]])
        _, result, error = self.txRxPacket(port, packet)
        return result, error

    def regWriteTxRx(
        self, port: Any, scs_id: int, address: int, length: int, data: list[int]
    ) -> tuple[int, int]:
        packet = self._packet(scs_id, scs.Inst.REG_WRITE, [address, *data[:length]])
        _, result, error = self.txRxPacket(port, packet)
        return result, error

    def syncReadTx(
        self, port: Any, start_address: int, data_length: int, param: list[int], param_length: int
    ) -> int:
        params = [start_address, data_length, *param[:param_length]]
        result = self.txPacket(port, self._packet(scs.BROADCAST_ID, scs.Inst.SYNC_READ, params))
        if result == COMM_SUCCESS:
            port.setPacketTimeout((6 + data_length) * param_length)
        return result

    def syncWriteTxOnly(
        self, port: Any, start_address: int, data_length: int, param: list[int], param_length: int
    ) -> int:
        params = [start_address, data_length, *param[:param_length]]
        packet = self._packet(scs.BROADCAST_ID, scs.Inst.SYNC_WRITE, params)
        return self.txRxPacket(port, packet)[1]


def _missing(buffer: bytearray) -> int:
    """How many bytes to read next: no more than the frame being read still needs (the
    next servo's reply stays in the port, as the SDK reads it)."""
    start = bytes(buffer).find(scs.HEADER)
    if start < 0 or len(buffer) < start + 4:
        return max(1, 6 - len(buffer))
    return max(1, start + buffer[start + 3] + 4 - len(buffer))


class GroupSyncWrite:
    """The SDK's ``GroupSyncWrite``: addParam per servo, then one txPacket."""

    def __init__(self, port: Any, ph: Any, start_address: int, data_length: int) -> None:
        self.port, self.ph = port, ph
        self.start_address, self.data_length = start_address, data_length
        self.data_dict: dict[int, list[int]] = {}

    def addParam(self, scs_id: int, data: list[int]) -> bool:
        if scs_id in self.data_dict or len(data) > self.data_length:
            return False
        self.data_dict[scs_id] = list(data)
        return True

    def txPacket(self) -> int:
        if not self.data_dict:
            return COMM_NOT_AVAILABLE
        param = [b for sid, data in self.data_dict.items() for b in (sid, *data)]
        return int(
            self.ph.syncWriteTxOnly(
                self.port, self.start_address, self.data_length, param, len(param)
            )
        )


class GroupSyncRead:
    """The SDK's ``GroupSyncRead`` (armkit reads its replies with ``readRx``)."""

    def __init__(self, port: Any, ph: Any, start_address: int, data_length: int) -> None:
        self.port, self.ph = port, ph
        self.start_address, self.data_length = start_address, data_length
        self.ids: list[int] = []

    def addParam(self, scs_id: int) -> bool:
        if scs_id in self.ids:
            return False
        self.ids.append(scs_id)
        return True

    def txPacket(self) -> int:
        if not self.ids:
            return COMM_NOT_AVAILABLE
        return int(
            self.ph.syncReadTx(
                self.port, self.start_address, self.data_length, self.ids, len(self.ids)
            )
        )
