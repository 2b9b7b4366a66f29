"""armkit's own Protocol 2.0 client, with the dynamixel-sdk's interface, on armkit's codec.

``DynamixelBus`` talks through the ROBOTIS dynamixel-sdk where it is
installed. Where it is not, these classes stand in for it: the same names,
arguments and results (``PacketHandler``'s ``ping``, ``readTxRx``,
``writeTxRx``, ``reboot``, ``readRx``, ``syncReadTx``, ``syncWriteTxOnly``;
``GroupSyncWrite``, ``GroupSyncRead``), built on ``_dxl_packet``, so the bus
sends the same bytes either way (tests compare them with the SDK's).

``PortHandler`` is the SDK's port interface on an already-open serial line and a
clock: it also serves as the SDK's own ``PortHandler`` replacement for a
simulated bus (the SDK's ``PacketHandler`` runs on it unchanged, its packet
timeouts in the simulation's time).
"""

from __future__ import annotations

from typing import Any

from .._clock import Clock
from . import _dxl_packet as pkt
from ._serial import SerialPort

COMM_SUCCESS = 0
COMM_PORT_BUSY = -1000
COMM_TX_FAIL = -1001
COMM_RX_TIMEOUT = -3001
COMM_RX_CORRUPT = -3002
COMM_NOT_AVAILABLE = -9000
LATENCY_TIMER_MS = 16  # what the SDK assumes of a USB adapter [ms]
BAUDRATES = frozenset(  # the rates the SDK's PortHandler accepts [bit/s]
    {9600, 19200, 38400, 57600, 115200, 230400, 460800, 500000, 576000, 921600, 1000000}
    | {1152000, 2000000, 2500000, 3000000, 3500000, 4000000}
)
_STATUS_MIN = 11  # header 4 + ID + LEN 2 + INST + ERROR + CRC 2


class PortHandler:
    """The SDK's ``PortHandler`` on an open ``SerialPort`` ``ser``, timed by ``clock``."""

    def __init__(self, ser: SerialPort, clock: Clock, port_name: str = "") -> None:
        self.ser, self.clock = ser, clock
        self.port_name = port_name or str(getattr(ser, "port", "") or "a Dynamixel line")
        self.is_open, self.is_using = True, False
        self.baudrate = int(ser.baudrate)
        self.tx_time_per_byte = 10000.0 / self.baudrate  # [ms]
        self.packet_start_time = self.packet_timeout = 0.0
        ser.timeout = 0  # as the SDK opens its ports: reads never block

    def openPort(self) -> bool:
        return self.setBaudRate(self.baudrate)

    def closePort(self) -> None:
        self.ser.close()
        self.is_open = False

    def clearPort(self) -> None:
        self.ser.reset_input_buffer()

    def setBaudRate(self, baudrate: int) -> bool:
        if baudrate not in BAUDRATES:
            return False
        self.baudrate, self.ser.baudrate = baudrate, baudrate
        self.tx_time_per_byte = 10000.0 / baudrate
        return True

    def getBaudRate(self) -> int:
        return self.baudrate

    def getBytesAvailable(self) -> int:
        return int(getattr(self.ser, "in_waiting", 0))

    def readPort(self, length: int) -> bytes:
        return bytes(self.ser.read(length))

    def writePort(self, packet: Any) -> int:
        return int(self.ser.write(bytes(packet)) or 0)

    def setPacketTimeout(self, packet_length: int) -> None:
        self.packet_start_time = self.getCurrentTime()
        self.packet_timeout = self.tx_time_per_byte * packet_length + LATENCY_TIMER_MS * 2.0 + 2.0

    def setPacketTimeoutMillis(self, msec: float) -> None:
        self.packet_start_time, self.packet_timeout = self.getCurrentTime(), msec

    def isPacketTimeout(self) -> bool:
        if self.getTimeSinceStart() > self.packet_timeout:
            self.packet_timeout = 0
            return True
        return False

    def getCurrentTime(self) -> float:
        return self.clock.now() * 1000.0

    def getTimeSinceStart(self) -> float:
        return self.getCurrentTime() - self.packet_start_time


class PacketHandler:
    """The SDK's ``Protocol2PacketHandler`` (the calls armkit's bus makes), on ``_dxl_packet``."""

    def getProtocolVersion(self) -> float:
        return 2.0

    def txPacket(self, port: Any, frame: bytes) -> int:
        if port.is_using:
            return COMM_PORT_BUSY
        port.is_using = True
        port.clearPort()
        if port.writePort(frame) != len(frame):
            port.is_using = False
            return COMM_TX_FAIL
        return COMM_SUCCESS

    def rxPacket(self, port: Any) -> tuple[pkt.Packet | None, int]:
        """One status packet (garbage before it skipped), or (None, timeout/corrupt)."""
        buffer, result, packet = bytearray(), COMM_RX_TIMEOUT, None
        while True:
            _skip_garbage(buffer)
            frame, _ = pkt.split_frame(buffer)
            if frame is not None:
                try:
                    packet, result = pkt.decode(frame), COMM_SUCCESS
                except pkt.PacketError:
                    result = COMM_RX_CORRUPT
                break
            chunk = port.readPort(_missing(buffer))
            buffer += chunk
            if not chunk and port.isPacketTimeout():
                result = COMM_RX_CORRUPT if buffer else COMM_RX_TIMEOUT
                break
        port.is_using = False
        return packet, result

    def txRxPacket(self, port: Any, frame: bytes, read_length: int = 0) -> tuple[Any, int, int]:
        result = self.txPacket(port, frame)
        if result != COMM_SUCCESS:
            return None, result, 0
        if frame[4] == pkt.BROADCAST_ID:
            port.is_using = False
            return None, result, 0
        port.setPacketTimeout(read_length + _STATUS_MIN)
        return self._status_of(port, frame[4])

    def _status_of(self, port: Any, servo_id: int) -> tuple[pkt.Packet | None, int, int]:
        while True:
            packet, result = self.rxPacket(port)
            if packet is None or packet.id == servo_id:
                break
        return packet, result, packet.error if packet is not None else 0

    def ping(self, port: Any, dxl_id: int) -> tuple[int, int, int]:
        if dxl_id >= pkt.BROADCAST_ID:
            return 0, COMM_NOT_AVAILABLE, 0
        packet, result, error = self.txRxPacket(port, pkt.ping(dxl_id))
        model = int.from_bytes(packet.data[:2], "little") if packet is not None else 0
        return model, result, error

    def readTxRx(self, port: Any, dxl_id: int, address: int, length: int) -> tuple[Any, int, int]:
        if dxl_id >= pkt.BROADCAST_ID:
            return [], COMM_NOT_AVAILABLE, 0
        packet, result, error = self.txRxPacket(port, pkt.read(dxl_id, address, length), length)
        return (list(packet.data[:length]) if packet is not None else []), result, error

    def writeTxRx(
        self, port: Any, dxl_id: int, address: int, length: int, data: Any
    ) -> tuple[int, int]:
        _, result, error = self.txRxPacket(port, pkt.write(dxl_id, address, bytes(data[:length])))
        return result, error

    def reboot(self, port: Any, dxl_id: int) -> tuple[int, int]:
        _, result, error = self.txRxPacket(port, pkt.reboot(dxl_id))
        return result, error

    def readRx(self, port: Any, dxl_id: int, length: int) -> tuple[Any, int, int]:
        packet, result, error = self._status_of(port, dxl_id)
        return (list(packet.data[:length]) if packet is not None else []), result, error

    def syncReadTx(
        self, port: Any, start_address: int, data_length: int, param: Any, param_length: int
    ) -> int:
        frame = pkt.sync_read(start_address, data_length, bytes(param[:param_length]))
        result = self.txPacket(port, frame)
        if result == COMM_SUCCESS:
            port.setPacketTimeout((_STATUS_MIN + data_length) * param_length)
        return result

    def syncWriteTxOnly(
        self, port: Any, start_address: int, data_length: int, param: Any, param_length: int
    ) -> int:
        body = pkt._u16(start_address) + pkt._u16(data_length) + bytes(param[:param_length])
        _, result, _ = self.txRxPacket(
            port, pkt.encode(pkt.BROADCAST_ID, pkt.Inst.SYNC_WRITE, body)
        )
        return result


def _skip_garbage(buffer: bytearray) -> None:
    """Drop what cannot start a status packet: bytes before a header, a header of
    anything but a status."""
    while True:
        start = bytes(buffer).find(pkt.HEADER)
        if start < 0:
            del buffer[: max(0, len(buffer) - 3)]
            return
        del buffer[:start]
        if len(buffer) < 8 or buffer[7] == pkt.Inst.STATUS:
            return
        del buffer[0]


def _missing(buffer: bytearray) -> int:
    """How many more bytes the status packet in ``buffer`` needs (at least 1)."""
    if len(buffer) >= 7 and buffer[:4] == pkt.HEADER:
        return max(1, 7 + int.from_bytes(buffer[5:7], "little") - len(buffer))
    return max(1, _STATUS_MIN - len(buffer))


class _Group:
    """What the SDK's group classes share: a port, a packet handler, one register span."""

    def __init__(self, port: Any, ph: Any, start_address: int, data_length: int) -> None:
        self.port, self.ph = port, ph
        self.start_address, self.data_length = start_address, data_length
        self.data_dict: dict[int, list[int]] = {}

    def clearParam(self) -> None:
        self.data_dict.clear()


class GroupSyncWrite(_Group):
    """The SDK's ``GroupSyncWrite``: one SYNC_WRITE of ``data_length`` bytes per servo."""

    def addParam(self, dxl_id: int, data: Any) -> bool:
        if dxl_id in self.data_dict or len(data) > self.data_length:
            return False
        self.data_dict[dxl_id] = list(data)
        return True

    def txPacket(self) -> int:
        if not self.data_dict:
            return COMM_NOT_AVAILABLE
        param = [b for sid, data in self.data_dict.items() for b in (sid, *data)]
        address, size = self.start_address, self.data_length
        return int(self.ph.syncWriteTxOnly(self.port, address, size, param, len(param)))


class GroupSyncRead(_Group):
    """The SDK's ``GroupSyncRead`` (the transmit half; replies are read with ``readRx``)."""

    def addParam(self, dxl_id: int) -> bool:
        if dxl_id in self.data_dict:
            return False
        self.data_dict[dxl_id] = []
        return True

    def txPacket(self) -> int:
        if not self.data_dict:
            return COMM_NOT_AVAILABLE
        ids = list(self.data_dict)
        address, size = self.start_address, self.data_length
        return int(self.ph.syncReadTx(self.port, address, size, ids, len(ids)))
