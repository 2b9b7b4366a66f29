"""A simulated Dynamixel bus: XM430-W350 servos answering Protocol 2.0 packets.

Frames are split and checked with armkit's own codec (``devices._dxl_packet``);
a frame with a bad CRC is ignored, like a servo does. ``unicast`` and
``instructions`` are the tables of instruction -> handler (ROBOTIS e-Manual,
"DYNAMIXEL Protocol 2.0", Instruction): PING (unicast and broadcast), READ, WRITE,
REG_WRITE + ACTION, FACTORY_RESET, REBOOT, CLEAR, Control Table Backup, SYNC_READ,
SYNC_WRITE, FAST_SYNC_READ, BULK_READ, BULK_WRITE, FAST_BULK_READ, over the
XM430-W350 control table (``sim.xm430``); another instruction, or one newer than the
servo's firmware, is an Instruction Error.

Who answers (e-Manual XM430-W350): a servo answers packets for its ID (its
present ID register) and executes, silently, packets for its Secondary ID (12),
but never an EEPROM write through it; Status Return Level (68) 0 answers only PING,
1 also the reads; a broadcast gets no status but PING's. Each servo listens at the
rate of its Baud Rate register (8): a host at another rate reaches no servo
(``hear``). Every instruction packet for a servo restarts its Bus Watchdog.

Faults (``inject``): ``"drop"`` (the servo executes but its reply is lost),
``"corrupt"`` (reply with a wrong CRC), ``"late"`` (reply after ``late_s``),
``"vanish"`` (the servo stops answering and executing until ``revive``),
``"overload"`` (Hardware Error Status overload bit, torque off, alert bit in
every status until REBOOT).
"""

from __future__ import annotations

import threading
from collections import deque
from collections.abc import Callable, Iterable

from ..devices import dxl_packet as pkt
from ..devices import xm430 as xm
from ..devices import xm430_notes as notes
from ._dxl_groups import GroupInstructions, u16
from ._outbox import Outbox, log
from ._xm430_drive import Drives
from .xm430 import XM430

FAULTS = ("drop", "corrupt", "late", "vanish", "overload")
_ID = xm.register("ID").address  # one-byte registers read on every packet, by address
_PROTOCOL_TYPE = xm.register("Protocol Type").address
_SECONDARY_ID = xm.register("Secondary ID").address
OPENMANIPULATOR_X_IDS = (11, 12, 13, 14, 15)
Reply = tuple[int, bytes, Callable[[], None] | None]  # error, data, what to do after replying
Handler = Callable[[XM430, pkt.Packet, bool], Reply]  # (servo, packet, by its secondary ID)
_READS = (pkt.Inst.PING, pkt.Inst.READ)
_FROM_FIRMWARE: dict[int, str] = {  # instruction -> the feature (``notes.FROM_FIRMWARE``) it needs
    pkt.Inst.CLEAR: "Clear",
    pkt.Inst.BACKUP: "Control Table Backup",
    pkt.Inst.FAST_SYNC_READ: "Fast Sync Read",
    pkt.Inst.FAST_BULK_READ: "Fast Bulk Read",
}


class SimDynamixelBus(GroupInstructions):
    """XM430 servos on one bus (``ids``), on ``clock`` [s], listening at ``baudrate`` [bit/s].

    Attributes:
        servos: first ID -> ``XM430``.  received: bytes read from the bus (count).  frames:
            the last frames read (bounded).  outbox: the servos' status packets.
    """

    name = "dynamixel"
    baudrate: int | None = None  # per servo: see ``hear``

    def __init__(
        self,
        ids: Iterable[int] = OPENMANIPULATOR_X_IDS,
        *,
        clock: Callable[[], float],
        late_s: float = 0.08,
        baudrate: int = 1_000_000,
    ) -> None:
        self._clock = clock
        self.lock = threading.RLock()  # held while the host's bytes are handled
        self.servos = {sid: XM430(sid, clock, baudrate=baudrate) for sid in ids}
        self.late_s = late_s
        self.outbox = Outbox()
        self.received = 0  # bytes read from the bus
        self.frames: deque[bytes] = log()  # every complete frame read, as it came
        self._buffer = bytearray()
        self._pending: dict[int, list[str]] = {}
        self._vanished: set[int] = set()
        self._rate: int | None = None  # the host's rate for the bytes being read
        self.unicast: dict[int, Handler] = {
            pkt.Inst.PING: lambda s, p, sec: (0, s.read(0, 2) + s.read(6, 1), None),
            pkt.Inst.READ: self._read,
            pkt.Inst.WRITE: lambda s, p, sec: (
                s.write(u16(p.params, 0), p.params[2:], secondary=sec),
                b"",
                None,
            ),
            pkt.Inst.REG_WRITE: self._reg_write,
            pkt.Inst.ACTION: self._action,
            pkt.Inst.FACTORY_RESET: self._factory_reset,
            pkt.Inst.REBOOT: lambda s, p, sec: (0, b"", s.reboot),
            pkt.Inst.CLEAR: self._clear,
            pkt.Inst.BACKUP: self._backup,
        }
        self.instructions: dict[int, Callable[[pkt.Packet], None]] = self.group_instructions()

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

    def frozen(self) -> Drives:
        """The servos' outputs as they stand until the host's next bytes (one ``Drive``
        per servo, taken now): what a run of simulation steps evaluates."""
        return Drives({sid: servo.drive() for sid, servo in self.servos.items()})

    # -- the wire --------------------------------------------------------------
    def hear(self, data: bytes, now: float, baudrate: int | None) -> bool:
        """Bytes from a host at ``baudrate`` [bit/s] (None: unknown, every servo hears);
        False when no servo listens at that rate (the bytes are noise to all)."""
        if baudrate is not None and all(s.baudrate != baudrate for s in self.servos.values()):
            return False
        self._rate = baudrate
        self.receive(data, now)
        return True

    def receive(self, data: bytes, now: float) -> None:
        """Bytes from the host: every complete frame is executed at once.

        A reply still unsent when the host's next packet arrives is withdrawn: on the
        half-duplex bus the servo's reply (due within its Return Delay Time) would have
        been on the line before that packet, and the host clears its input before each
        packet (the SDK's clearPort). Only an emulator that read late sees the next packet
        first; sending the older reply then would hand the host a stale answer (a reply
        made late on purpose, the ``"late"`` fault, is not yet due and stays)."""
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
            self.outbox.drop_due(now)
            self.handle(packet)

    def handle(self, packet: pkt.Packet) -> None:
        """Execute one instruction packet and send the replies it calls for."""
        now = self._clock()
        addressed = self._addressed(packet.id)
        for servo, _ in addressed:
            servo.hear(now)  # the Bus Watchdog's "communication"
        group = self.instructions.get(packet.instruction)
        if group is not None:
            group(packet)
            return
        handler = self.unicast.get(packet.instruction)
        broadcast = packet.id == pkt.BROADCAST_ID and packet.instruction != pkt.Inst.PING
        for servo, primary in addressed:
            feature = _FROM_FIRMWARE.get(packet.instruction)
            if handler is None or (feature is not None and not servo.has(feature)):
                error, data, after = pkt.INSTRUCTION_ERROR, b"", None
            else:
                error, data, after = handler(servo, packet, not primary)
            if primary and not broadcast and self._answers(servo, packet.instruction):
                self.reply(servo, error, data)
            if after is not None:
                after()

    def _addressed(self, target: int) -> list[tuple[XM430, bool]]:
        """(servo, by its primary ID) for every present servo a packet to ``target`` reaches
        (e-Manual XM430-W350, "Secondary(Shadow) ID (12)": its ID first; 253 ~ 255 off)."""
        found = []
        for servo in self.present():
            if target in (pkt.BROADCAST_ID, servo.memory[_ID]):
                found.append((servo, True))
            elif servo.memory[_SECONDARY_ID] == target < notes.SECONDARY_ID_OFF:
                found.append((servo, False))
        return found

    def present(self) -> list[XM430]:
        """The servos that hear the host now (not vanished, at the host's baud rate, speaking
        Protocol 2.0: Protocol Type (13) 1 is not emulated), by ID."""
        servos = [s for sid, s in self.servos.items() if self._hears(sid, s)]
        return sorted(servos, key=lambda s: s.memory[_ID])

    def _hears(self, sid: int, servo: XM430) -> bool:
        """Whether the servo kept under ``sid`` is present (see ``present``)."""
        return (
            sid not in self._vanished
            and servo.memory[_PROTOCOL_TYPE] == 2
            and (self._rate is None or servo.baudrate == self._rate)
        )

    def by_id(self, servo_id: int) -> XM430 | None:
        """The present servo whose ID register is ``servo_id`` (the first of ``present``'s
        order: of several with that ID, the first kept; found without sorting them all,
        as a sync instruction asks for each of its IDs)."""
        return next(
            (
                s
                for sid, s in self.servos.items()
                if s.memory[_ID] == servo_id and self._hears(sid, s)
            ),
            None,
        )

    @staticmethod
    def _answers(servo: XM430, instruction: int) -> bool:
        level = servo.value("Status Return Level")
        if instruction == pkt.Inst.PING or level >= xm.STATUS_LEVEL_ALL:
            return True
        return level == xm.STATUS_LEVEL_READ and instruction in _READS

    def reply(self, servo: XM430, error: int = 0, data: bytes = b"") -> None:
        """Send ``servo``'s status packet (through its injected faults)."""
        sid = servo.value("ID")
        self.send(sid, pkt.status(sid, error | servo.error_bits, data))

    def send(self, sid: int, frame: bytes) -> None:
        """Put ``frame`` on the bus as servo ``sid`` says it (through its injected faults)."""
        fault = self._pending[sid].pop(0) if self._pending.get(sid) else ""
        if fault == "drop":
            return
        if fault == "corrupt":
            frame = frame[:-1] + bytes((frame[-1] ^ 0xFF,))
        self.outbox.send(frame, self._clock(), self.late_s if fault == "late" else 0.0)

    # -- per-servo instructions (e-Manual "DYNAMIXEL Protocol 2.0", Instruction Details) --
    @staticmethod
    def _read(servo: XM430, packet: pkt.Packet, secondary: bool) -> Reply:
        address, size = u16(packet.params, 0), u16(packet.params, 2)
        if address + size > xm.CONTROL_TABLE_SIZE:
            return pkt.ACCESS_ERROR, b"", None
        return 0, servo.read(address, size), None

    @staticmethod
    def _reg_write(servo: XM430, packet: pkt.Packet, secondary: bool) -> Reply:
        """Reg Write: kept until ACTION; Registered Instruction (69) reads 1."""
        servo.registered = (u16(packet.params, 0), packet.params[2:])
        servo.set("Registered Instruction", 1)
        return 0, b"", None

    @staticmethod
    def _action(servo: XM430, packet: pkt.Packet, secondary: bool) -> Reply:
        """Action: the registered write; Instruction Error without a Reg Write ("Status
        Packet", Error 0x02: Action has been used without Reg Write)."""
        if servo.registered is None:
            return pkt.INSTRUCTION_ERROR, b"", None
        (address, data), servo.registered = servo.registered, None
        servo.set("Registered Instruction", 0)
        return servo.write(address, data, secondary=secondary), b"", None

    @staticmethod
    def _factory_reset(servo: XM430, packet: pkt.Packet, secondary: bool) -> Reply:
        """Factory Reset: 0xFF all, 0x01 all but the ID, 0x02 all but ID and Baud Rate;
        from firmware 42 a broadcast 0xFF is not executed; another option: Data Range
        Error. Done after the status packet is sent."""
        option = packet.params[0] if packet.params else -1
        if option not in notes.FACTORY_RESET_KEEPS:
            return pkt.DATA_RANGE_ERROR, b"", None
        ignored = servo.has("broadcast Factory Reset 0xFF ignored")
        if packet.id == pkt.BROADCAST_ID and option == notes.RESET_ALL and ignored:
            return 0, b"", None
        return 0, b"", lambda: servo.factory_reset(option)

    @staticmethod
    def _clear(servo: XM430, packet: pkt.Packet, secondary: bool) -> Reply:
        """Clear: option 1 with its fixed bytes folds the multi-turn count; else Data Range
        Error."""
        option, key = packet.params[:1], packet.params[1:5]
        if option != bytes((notes.CLEAR_MULTI_TURN,)) or key != notes.CLEAR_KEY:
            return pkt.DATA_RANGE_ERROR, b"", None
        return servo.clear_multi_turn(), b"", None

    @staticmethod
    def _backup(servo: XM430, packet: pkt.Packet, secondary: bool) -> Reply:
        """Control Table Backup: store (1) or restore (2, then the servo reboots)."""
        if packet.params[1:5] != notes.BACKUP_KEY or not packet.params:
            return pkt.DATA_RANGE_ERROR, b"", None
        option = packet.params[0]
        error = servo.backup_table(option)
        restored = not error and option == notes.BACKUP_RESTORE
        return error, b"", servo.reboot if restored else None
