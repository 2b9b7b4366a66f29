"""Group instructions on a Dynamixel bus: SYNC_WRITE of one register to many servos
(no status packet, so sent exactly once), SYNC_READ (retried as a whole) and the
present state of many servos in one SYNC_READ. Values in the control table's units
(``_xm430``), signed registers signed.

``DynamixelBus`` holds one ``SyncInstructions``, given its client, port and packet
handler, and two functions of its own: the attempts (which settle the line between
tries) and the status check (which reads a servo's hardware error).
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass
from typing import Any

from .._errors import DeviceError
from . import _xm430 as xm
from ._dxl_sdk import COMM_SUCCESS, Protocol, comm_fault, sync_read_replies

Attempts = Callable[[], Iterable[int]]  # attempt numbers 0..retries, the line settled between
CheckStatus = Callable[[int, str, int], None]  # (servo ID, what, error byte): raises if bad


@dataclass(frozen=True, slots=True)
class ServoState:
    """Present state, signed: position [tick], velocity [0.229 rev/min], current [2.69 mA]."""

    position: int
    velocity: int
    current: int


class SyncInstructions:
    """SYNC_WRITE and SYNC_READ on one bus, the SDK's group objects kept for reuse.

    Args:
        protocol: the client (the SDK or armkit's own) whose group classes are used.
        port: the bus's port handler.
        packet_handler: the bus's packet handler (reads the SYNC_READ replies).
        attempts: the bus's attempts, for retrying a SYNC_READ.
        check: the bus's status check, for each SYNC_READ reply's error byte.
    """

    def __init__(
        self,
        protocol: Protocol,
        port: Any,
        packet_handler: Any,
        attempts: Attempts,
        check: CheckStatus,
    ) -> None:
        self._protocol, self._port, self._ph = protocol, port, packet_handler
        self._attempts, self._check = attempts, check
        self._groups: dict[tuple[Any, ...], Any] = {}

    def sync_write(self, name: str, values: Mapping[int, int]) -> None:
        """{ID: value} of one register in one SYNC_WRITE, sent exactly once."""
        reg = xm.register(name)
        self.write_block(reg.address, reg.size, {s: reg.encode(v) for s, v in values.items()})

    def sync_read(self, name: str, ids: Sequence[int]) -> dict[int, int]:
        """{ID: value} of one register, signed if the register is."""
        reg = xm.register(name)
        raw = self.read_block(reg.address, reg.size, ids)
        return {sid: reg.decode(data) for sid, data in raw.items()}

    def read_states(self, ids: Sequence[int]) -> dict[int, ServoState]:
        """Present current, velocity and position of ``ids`` in one SYNC_READ (126..135)."""
        cur, vel, pos = (xm.register(f"Present {n}") for n in ("Current", "Velocity", "Position"))
        raw = self.read_block(cur.address, pos.address + pos.size - cur.address, ids)
        return {
            sid: ServoState(pos.decode(d[6:10]), vel.decode(d[2:6]), cur.decode(d[0:2]))
            for sid, d in raw.items()
        }

    def write_block(self, address: int, size: int, data: Mapping[int, bytes]) -> None:
        """One SYNC_WRITE of ``size`` bytes at ``address``: {ID: bytes}, sent exactly once."""
        group = self._group(self._protocol.group_sync_write, address, size)
        group.clearParam()
        for sid, raw in data.items():
            group.addParam(sid, list(raw))
        result = group.txPacket()
        group.clearParam()
        if result != COMM_SUCCESS:
            raise DeviceError(f"servos {list(data)}: SYNC_WRITE failed: {comm_fault(result)}")

    def read_block(self, address: int, size: int, ids: Sequence[int]) -> dict[int, bytes]:
        """{ID: ``size`` bytes at ``address``} in one SYNC_READ, retried as a whole;
        raises naming the servo that failed."""
        failed, result, tries = ids[0], COMM_SUCCESS, 0
        for _ in self._attempts():
            tries += 1
            group = self._group(self._protocol.group_sync_read, address, size, tuple(ids))
            failed, result, replies = sync_read_replies(group, self._ph, self._port, ids)
            if result == COMM_SUCCESS:
                for sid, (_, error) in replies.items():
                    self._check(sid, f"SYNC_READ at {address}", error)
                return {sid: data for sid, (data, _) in replies.items()}
        raise DeviceError(
            f"servo {failed}: SYNC_READ at {address} failed after {tries} tries:"
            f" {comm_fault(result)}; check its power, cable and ID"
        )

    def _group(self, kind: Any, address: int, size: int, ids: tuple[int, ...] = ()) -> Any:
        key = (kind, address, size, ids)
        if key not in self._groups:
            group = kind(self._port, self._ph, address, size)
            for sid in ids:
                group.addParam(sid)
            self._groups[key] = group
        return self._groups[key]
