"""XM430-W350 servos on a pseudo-terminal, speaking Dynamixel Protocol 2.0.

``DynamixelEmulator`` opens a pty, serves the master side in a background
thread and exposes the slave side's path as ``.port``: any client that opens a
serial port by path (the official dynamixel-sdk, unmodified; armkit's bus)
talks to it as to a U2D2 with servos on the bus. Implemented: PING (unicast
and broadcast), READ, WRITE, REBOOT, SYNC_READ, SYNC_WRITE, with CRC checks and
byte stuffing, over the XM430-W350 control table. Servos move toward their
goal in real time by their profile: trapezoidal velocity from Profile
Velocity/Acceleration, or time-based (Drive Mode bit 2: total and ramp time in
ms); a zero profile means the Velocity Limit and an instant ramp.

Faults (``inject``): ``"drop"`` (the servo executes but its reply is lost),
``"corrupt"`` (reply with a wrong CRC), ``"late"`` (reply after ``late_s``),
``"vanish"`` (the servo stops answering and executing until ``revive``),
``"overload"`` (Hardware Error Status overload bit, torque off, alert bit in
every status until REBOOT). Frames with a bad CRC are ignored, like a servo.
"""

from __future__ import annotations

import os
import select
import threading
import time
import tty
from collections.abc import Callable, Iterable
from types import TracebackType

from ..devices import _dxl_packet as pkt
from ..devices import _xm430 as xm
from ._dxl_servo import ACCESS_ERROR, Servo

FAULTS = ("drop", "corrupt", "late", "vanish", "overload")
OPENMANIPULATOR_X_IDS = (11, 12, 13, 14, 15)
_INSTRUCTION_ERROR = 2


class DynamixelEmulator:
    """XM430 servos behind a pseudo-terminal; ``.port`` is the path to open.

    Args:
        ids: servo IDs on the bus (default: the OpenManipulator-X's 11..15).
        late_s: how late a ``"late"`` reply comes [s] (longer than the SDK's ~34 ms timeout).
        clock: monotonic time source [s].
    """

    def __init__(
        self,
        ids: Iterable[int] = OPENMANIPULATOR_X_IDS,
        *,
        late_s: float = 0.08,
        clock: Callable[[], float] = time.monotonic,
    ) -> None:
        self.servos = {sid: Servo(sid, clock) for sid in ids}
        self.late_s = late_s
        self.lock = threading.RLock()
        self._pending: dict[int, list[str]] = {}
        self._vanished: set[int] = set()
        self.received = 0  # bytes the emulator has read from the bus, for tests
        self._master, self._slave = os.openpty()
        tty.setraw(self._slave)
        self.port = os.ttyname(self._slave)
        self._wake_r, self._wake_w = os.pipe()
        self._thread = threading.Thread(target=self._serve, name="dxl-emulator", daemon=True)
        self._thread.start()

    def inject(self, servo_id: int, fault: str, times: int = 1) -> None:
        """Make ``servo_id`` misbehave: one of ``FAULTS`` (reply faults hit the next ``times``)."""
        if fault not in FAULTS or servo_id not in self.servos:
            raise ValueError(f"fault must be one of {FAULTS} on a servo in {list(self.servos)}")
        with self.lock:
            if fault == "vanish":
                self._vanished.add(servo_id)
            elif fault == "overload":
                self.servos[servo_id].overload()
            else:
                self._pending.setdefault(servo_id, []).extend([fault] * times)

    def revive(self, servo_id: int) -> None:
        """Bring a vanished servo back."""
        with self.lock:
            self._vanished.discard(servo_id)

    def close(self) -> None:
        """Stop the thread and close the pty. Safe to call twice."""
        if self._wake_w < 0:
            return
        os.write(self._wake_w, b"x")
        self._thread.join(timeout=2.0)
        for fd in (self._master, self._slave, self._wake_r, self._wake_w):
            os.close(fd)
        self._wake_w = -1

    def __enter__(self) -> DynamixelEmulator:
        return self

    def __exit__(
        self,
        exc_type: type[BaseException] | None,
        exc: BaseException | None,
        tb: TracebackType | None,
    ) -> None:
        self.close()

    def _serve(self) -> None:
        buffer = bytearray()
        while True:
            ready, _, _ = select.select([self._master, self._wake_r], [], [])
            if self._wake_r in ready:
                return
            chunk = os.read(self._master, 4096)
            self.received += len(chunk)
            buffer += chunk
            self._drain(buffer)

    def _drain(self, buffer: bytearray) -> None:
        while True:
            frame, consumed = pkt.split_frame(buffer)
            del buffer[:consumed]
            if frame is None:
                return
            try:
                packet = pkt.decode(frame)
            except pkt.PacketError:
                continue
            with self.lock:
                self.handle(packet)

    def handle(self, packet: pkt.Packet) -> None:
        """Execute one instruction packet and send the replies it calls for."""
        if packet.instruction == pkt.Inst.SYNC_WRITE:
            self._sync_write(packet.params)
        elif packet.instruction == pkt.Inst.SYNC_READ:
            ids, read = packet.params[4:], pkt.Packet(0, pkt.Inst.READ, packet.params[:4])
            for servo in filter(None, map(self._present, ids)):
                self._reply(servo, *self._execute(servo, read))
        else:
            for servo in self._targets(packet):
                error, data = self._execute(servo, packet)
                if packet.id != pkt.BROADCAST_ID or packet.instruction == pkt.Inst.PING:
                    self._reply(servo, error, data)
                if packet.instruction == pkt.Inst.REBOOT:
                    servo.reboot()

    def _execute(self, servo: Servo, packet: pkt.Packet) -> tuple[int, bytes]:
        """(status error, reply data) of PING, READ, WRITE or REBOOT on one servo."""
        address = _u16(packet.params, 0)
        if packet.instruction == pkt.Inst.PING:
            return 0, servo.read(0, 2) + servo.read(6, 1)
        if packet.instruction == pkt.Inst.READ:
            size = _u16(packet.params, 2)
            if address + size > xm.CONTROL_TABLE_SIZE:
                return ACCESS_ERROR, b""
            return 0, servo.read(address, size)
        if packet.instruction == pkt.Inst.WRITE:
            return servo.write(address, packet.params[2:]), b""
        if packet.instruction == pkt.Inst.REBOOT:
            return 0, b""
        return _INSTRUCTION_ERROR, b""

    def _present(self, servo_id: int) -> Servo | None:
        return None if servo_id in self._vanished else self.servos.get(servo_id)

    def _targets(self, packet: pkt.Packet) -> list[Servo]:
        ids = sorted(self.servos) if packet.id == pkt.BROADCAST_ID else [packet.id]
        return [servo for servo in map(self._present, ids) if servo is not None]

    def _reply(self, servo: Servo, error: int = 0, data: bytes = b"") -> None:
        sid = servo.get("ID")
        frame = pkt.status(sid, error | servo.error_bits, data)
        fault = self._pending[sid].pop(0) if self._pending.get(sid) else ""
        if fault == "drop":
            return
        if fault == "corrupt":
            frame = frame[:-1] + bytes((frame[-1] ^ 0xFF,))
        if fault == "late":
            time.sleep(self.late_s)
        os.write(self._master, frame)

    def _sync_write(self, params: bytes) -> None:
        address, size, body = _u16(params, 0), _u16(params, 2), params[4:]
        for offset in range(0, len(body) - size, size + 1):
            servo = self._present(body[offset])
            if servo is not None:
                servo.write(address, body[offset + 1 : offset + 1 + size])


def _u16(params: bytes, offset: int) -> int:
    return int.from_bytes(params[offset : offset + 2], "little")
