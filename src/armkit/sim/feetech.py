"""A simulated Feetech bus: STS3215 servos answering SCS/STS packets.

Frames are split and checked with armkit's codec (``devices._scs_packet``); a frame
with a wrong checksum is ignored, as a servo does. Instructions (Feetech's protocol,
the ``INST_*`` of ``scservo_sdk``): PING, READ, WRITE, REG WRITE + ACTION, RESET,
SYNC READ, SYNC WRITE; another instruction gets no answer.

Who answers: a servo answers packets for its ID (its ID register); a broadcast (254)
gets no status; Response Status Level (8) 0 answers only PING and READ; a SYNC READ
is answered by each listed servo in the order listed. A status leaves after the
servo's Return Delay Time (7) x 2 us. Each servo listens at its Baud Rate (6): a host
at another rate reaches none. A READ past the end of the table is not answered (the
emulator's choice: Feetech's table does not say).

Faults (``inject``): ``"drop"`` (executed, reply lost), ``"corrupt"`` (wrong checksum),
``"late"`` (reply after ``late_s``), ``"vanish"`` (silent until ``revive``),
``"overload"`` (Status overload bit in every reply, torque off, until a power cycle).
"""

from __future__ import annotations

import threading
from collections import deque
from collections.abc import Callable, Iterable

from ..devices import scs_packet as scs
from ..devices import sts3215 as sts
from ._outbox import Outbox, log
from .sts3215 import STS3215

FAULTS = ("drop", "corrupt", "late", "vanish", "overload")
SO101_IDS = (1, 2, 3, 4, 5, 6)
RETURN_DELAY_S = 2e-6  # per unit of Return Delay Time (7)
_READS = (scs.Inst.PING, scs.Inst.READ)


class SimFeetechBus:
    """STS3215 servos on one bus (``ids``), on ``clock`` [s], at ``baudrate`` [bit/s].

    Attributes:
        servos: first ID -> ``STS3215``.  frames: the last frames read.  outbox: replies.
    """

    name = "feetech"
    baudrate: int | None = None  # per servo: see ``hear``

    def __init__(
        self,
        ids: Iterable[int] = SO101_IDS,
        *,
        clock: Callable[[], float],
        late_s: float = 0.08,
        baudrate: int = 1_000_000,
    ) -> None:
        self._clock = clock
        self.lock = threading.RLock()
        self.servos = {sid: STS3215(sid, clock, baudrate=baudrate) for sid in ids}
        self.late_s = late_s
        self.outbox = Outbox()
        self.received = 0
        self.frames: deque[bytes] = log()
        self._buffer = bytearray()
        self._pending: dict[int, list[str]] = {}
        self._vanished: set[int] = set()
        self._rate: int | None = None
        self.handlers: dict[int, Callable[[STS3215, scs.Packet], tuple[bytes, bool]]] = {
            scs.Inst.PING: lambda s, p: (b"", True),
            scs.Inst.READ: self._read,
            scs.Inst.WRITE: self._write,
            scs.Inst.REG_WRITE: self._reg_write,
            scs.Inst.ACTION: self._action,
            scs.Inst.RESET: self._reset,
        }

    def inject(self, servo_id: int, fault: str, times: int = 1) -> None:
        """Make ``servo_id`` misbehave: one of ``FAULTS``."""
        if fault not in FAULTS or servo_id not in self.servos:
            raise ValueError(f"fault must be one of {FAULTS} on a servo in {list(self.servos)}")
        if fault == "vanish":
            self._vanished.add(servo_id)
        elif fault == "overload":
            servo = self.servos[servo_id]
            servo.set("Status", 0x20)
            servo.set("Torque Enable", 0)
            servo.torque_on = False
        else:
            self._pending.setdefault(servo_id, []).extend([fault] * times)

    def revive(self, servo_id: int) -> None:
        """Bring a vanished servo back."""
        self._vanished.discard(servo_id)

    # -- the servos as an arm's outputs (channel = first ID) -----------------------
    def setpoint(self, channel: int, t: float) -> float | None:
        """Where servo ``channel`` drives its motor at ``t`` [step]; None: torque off."""
        servo = self.servos.get(channel)
        return None if servo is None else servo.setpoint(t)

    def busy(self, t: float) -> bool:
        """True while any servo moves."""
        return any(servo.busy(t) for servo in self.servos.values())

    # -- the wire ----------------------------------------------------------------
    def hear(self, data: bytes, now: float, baudrate: int | None) -> bool:
        """Bytes from a host at ``baudrate`` (None: every servo hears); False if no servo
        listens at that rate."""
        if baudrate is not None and all(s.baudrate != baudrate for s in self.servos.values()):
            return False
        self._rate = baudrate
        self.receive(data, now)
        return True

    def receive(self, data: bytes, now: float) -> None:
        """Bytes from the host: every whole frame is executed at once (a reply not read
        when the next packet comes is withdrawn, as on the Dynamixel bus)."""
        self.received += len(data)
        self._buffer += data
        while True:
            frame, consumed = scs.split(self._buffer)
            del self._buffer[:consumed]
            if frame is None:
                return
            self.frames.append(frame)
            try:
                packet = scs.decode(frame)
            except scs.PacketError:
                continue
            self.outbox.drop_due(now)
            self.handle(packet)

    def present(self) -> list[STS3215]:
        """The servos that hear the host now, by ID."""
        servos = [s for sid, s in self.servos.items() if sid not in self._vanished]
        if self._rate is not None:
            servos = [s for s in servos if s.baudrate == self._rate]
        return sorted(servos, key=lambda s: s.value("ID"))

    def by_id(self, servo_id: int) -> STS3215 | None:
        """The present servo whose ID register is ``servo_id``."""
        return next((s for s in self.present() if s.value("ID") == servo_id), None)

    def handle(self, packet: scs.Packet) -> None:
        """Execute one instruction packet; send the replies it calls for."""
        if packet.code == scs.Inst.SYNC_WRITE:
            self._sync_write(packet)
            return
        if packet.code == scs.Inst.SYNC_READ:
            self._sync_read(packet)
            return
        handler = self.handlers.get(packet.code)
        if handler is None:
            return
        broadcast = packet.id == scs.BROADCAST_ID
        servos = self.present() if broadcast else [s for s in [self.by_id(packet.id)] if s]
        for servo in servos:
            data, answer = handler(servo, packet)
            if answer and not broadcast and self._answers(servo, packet.code):
                self.reply(servo, data)
            if packet.code == scs.Inst.RESET:
                servo.reset()

    @staticmethod
    def _answers(servo: STS3215, instruction: int) -> bool:
        return bool(servo.value("Response Status Level")) or instruction in _READS

    def reply(self, servo: STS3215, data: bytes = b"", after_s: float = 0.0) -> None:
        """``servo``'s status packet, after its Return Delay Time (through its faults)."""
        sid = servo.value("ID")
        fault = self._pending[sid].pop(0) if self._pending.get(sid) else ""
        if fault == "drop":
            return
        frame = scs.status(sid, servo.error_bits, data)
        if fault == "corrupt":
            frame = frame[:-1] + bytes((frame[-1] ^ 0xFF,))
        delay = servo.value("Return Delay Time") * RETURN_DELAY_S + after_s
        self.outbox.send(frame, self._clock(), delay + (self.late_s if fault == "late" else 0.0))

    # -- instructions --------------------------------------------------------------
    @staticmethod
    def _read(servo: STS3215, packet: scs.Packet) -> tuple[bytes, bool]:
        if len(packet.params) != 2:
            return b"", False
        address, size = packet.params
        if address + size > sts.TABLE_SIZE:
            return b"", False
        return servo.read(address, size), True

    @staticmethod
    def _write(servo: STS3215, packet: scs.Packet) -> tuple[bytes, bool]:
        if packet.params:
            servo.write(packet.params[0], packet.params[1:])
        return b"", bool(packet.params)

    @staticmethod
    def _reg_write(servo: STS3215, packet: scs.Packet) -> tuple[bytes, bool]:
        servo.registered = (packet.params[0], packet.params[1:])
        return b"", True

    @staticmethod
    def _action(servo: STS3215, packet: scs.Packet) -> tuple[bytes, bool]:
        if servo.registered is not None:
            (address, data), servo.registered = servo.registered, None
            servo.write(address, data)
        return b"", True

    @staticmethod
    def _reset(servo: STS3215, packet: scs.Packet) -> tuple[bytes, bool]:
        return b"", True  # the reset itself follows the reply (``handle``)

    def _sync_write(self, packet: scs.Packet) -> None:
        """SYNC WRITE: address, length, then (ID, length bytes) per servo; no reply."""
        if len(packet.params) < 2 or packet.id != scs.BROADCAST_ID:
            return
        address, size, body = packet.params[0], packet.params[1], packet.params[2:]
        for at in range(0, len(body) - size, size + 1):
            servo = self.by_id(body[at])
            if servo is not None:
                servo.write(address, body[at + 1 : at + 1 + size])

    def _sync_read(self, packet: scs.Packet) -> None:
        """SYNC READ: address, length, IDs; each listed servo answers in turn."""
        if len(packet.params) < 2 or packet.id != scs.BROADCAST_ID:
            return
        address, size = packet.params[0], packet.params[1]
        if address + size > sts.TABLE_SIZE:
            return
        byte_s = 10.0 / (self._rate or 1_000_000)
        for k, sid in enumerate(packet.params[2:]):
            servo = self.by_id(sid)
            if servo is not None:
                self.reply(servo, servo.read(address, size), after_s=k * (size + 6) * byte_s)
