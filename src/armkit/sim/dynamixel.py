"""A simulated Dynamixel bus: XM430-W350 servos answering Protocol 2.0 packets.

Frames are split and checked with armkit's own codec (``devices._dxl_packet``);
a frame with a bad CRC is ignored, like a servo does. Implemented: PING
(unicast and broadcast), READ, WRITE, REBOOT, SYNC_READ, SYNC_WRITE, over the
XM430-W350 control table (``sim.xm430``). ``INSTRUCTIONS`` is the table of
instruction -> handler: a new instruction of the manual is one row and one method.

Faults (``inject``): ``"drop"`` (the servo executes but its reply is lost),
``"corrupt"`` (reply with a wrong CRC), ``"late"`` (reply after ``late_s``),
``"vanish"`` (the servo stops answering and executing until ``revive``),
``"overload"`` (Hardware Error Status overload bit, torque off, alert bit in
every status until REBOOT).

Known differences from the real bus (issue 11, point 5: the next step):
BULK_READ/BULK_WRITE, REG_WRITE + ACTION, FACTORY_RESET, CLEAR, FAST_SYNC_READ;
the Baud Rate register is not checked against the host's rate.
"""

from __future__ import annotations

from collections import deque
from collections.abc import Callable, Iterable

from ..devices import _dxl_packet as pkt
from ..devices import _xm430 as xm
from ._outbox import Outbox, log
from .xm430 import ACCESS_ERROR, Servo

FAULTS = ("drop", "corrupt", "late", "vanish", "overload")
OPENMANIPULATOR_X_IDS = (11, 12, 13, 14, 15)
_INSTRUCTION_ERROR = 2


class SimDynamixelBus:
    """XM430 servos on one bus (``ids``), on ``clock`` [s].

    Attributes:
        servos: ID -> ``Servo``.  received: bytes read from the bus (count).  frames: the
            last frames read (bounded).
        outbox: the servos' status packets.  baudrate: None (any rate is answered).
    """

    name = "dynamixel"

    def __init__(
        self,
        ids: Iterable[int] = OPENMANIPULATOR_X_IDS,
        *,
        clock: Callable[[], float],
        late_s: float = 0.08,
    ) -> None:
        self.baudrate: int | None = None
        self._clock = clock
        self.servos = {sid: Servo(sid, clock) for sid in ids}
        self.late_s = late_s
        self.outbox = Outbox()
        self.received = 0  # bytes read from the bus
        self.frames: deque[bytes] = log()  # every complete frame read, as it came
        self._buffer = bytearray()
        self._pending: dict[int, list[str]] = {}
        self._vanished: set[int] = set()
        self.instructions: dict[int, Callable[[pkt.Packet], None]] = {
            pkt.Inst.SYNC_WRITE: self._sync_write,
            pkt.Inst.SYNC_READ: self._sync_read,
        }

    def inject(self, servo_id: int, fault: str, times: int = 1) -> None:
        """Make ``servo_id`` misbehave: one of ``FAULTS`` (reply faults hit the next ``times``)."""
        if fault not in FAULTS or servo_id not in self.servos:
            raise ValueError(f"fault must be one of {FAULTS} on a servo in {list(self.servos)}")
        if fault == "vanish":
            self._vanished.add(servo_id)
        elif fault == "overload":
            self.servos[servo_id].overload()
        else:
            self._pending.setdefault(servo_id, []).extend([fault] * times)

    def revive(self, servo_id: int) -> None:
        """Bring a vanished servo back."""
        self._vanished.discard(servo_id)

    # -- the servos as an arm's outputs (``_servo_body.Outputs``), channel = ID --
    def setpoint(self, channel: int, t: float) -> float | None:
        """Where servo ``channel``'s profile asks its motor to be [tick]; None: torque off."""
        servo = self.servos.get(channel)
        return None if servo is None else servo.setpoint(t)

    def busy(self, t: float) -> bool:
        """True while any servo's profile is running."""
        return any(servo.busy(t) for servo in self.servos.values())

    # -- the wire --------------------------------------------------------------
    def receive(self, data: bytes, now: float) -> None:
        """Bytes from the host: every complete frame is executed at once."""
        self.received += len(data)
        self._buffer += data
        while True:
            frame, consumed = pkt.split_frame(self._buffer)
            del self._buffer[:consumed]
            if frame is None:
                return
            self.frames.append(frame)
            try:
                packet = pkt.decode(frame)
            except pkt.PacketError:
                continue
            self.handle(packet)

    def handle(self, packet: pkt.Packet) -> None:
        """Execute one instruction packet and send the replies it calls for."""
        special = self.instructions.get(packet.instruction)
        if special is not None:
            special(packet)
            return
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
        sid = servo.value("ID")
        frame = pkt.status(sid, error | servo.error_bits, data)
        fault = self._pending[sid].pop(0) if self._pending.get(sid) else ""
        if fault == "drop":
            return
        if fault == "corrupt":
            frame = frame[:-1] + bytes((frame[-1] ^ 0xFF,))
        self.outbox.send(frame, self._clock(), self.late_s if fault == "late" else 0.0)

    def _sync_read(self, packet: pkt.Packet) -> None:
        ids, read = packet.params[4:], pkt.Packet(0, pkt.Inst.READ, packet.params[:4])
        for servo in filter(None, map(self._present, ids)):
            self._reply(servo, *self._execute(servo, read))

    def _sync_write(self, packet: pkt.Packet) -> None:
        params = packet.params
        address, size, body = _u16(params, 0), _u16(params, 2), params[4:]
        for offset in range(0, len(body) - size, size + 1):
            servo = self._present(body[offset])
            if servo is not None:
                servo.write(address, body[offset + 1 : offset + 1 + size])


def _u16(params: bytes, offset: int) -> int:
    return int.from_bytes(params[offset : offset + 2], "little")
