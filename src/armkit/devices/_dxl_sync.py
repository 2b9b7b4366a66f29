"""Group instructions on a Dynamixel bus: SYNC_WRITE of one register to many servos
(no status packet, so sent exactly once), SYNC_READ (retried as a whole) and the
present state of many servos in one SYNC_READ. Values in the control table's units
(``_xm430``), signed registers signed.

A mixin of ``DynamixelBus``, as ``_dxl_settings`` is: it works on the bus's protocol,
port and packet handler, with the bus's attempts and status check.
"""

from __future__ import annotations

from abc import ABC, abstractmethod
from collections.abc import Iterator, Mapping, Sequence
from dataclasses import dataclass
from typing import Any

from .._errors import DeviceError
from . import _xm430 as xm
from ._dxl_sdk import COMM_SUCCESS, Protocol, comm_fault, sync_read_replies


@dataclass(frozen=True, slots=True)
class ServoState:
    """Present state, signed: position [tick], velocity [0.229 rev/min], current [2.69 mA]."""

    position: int
    velocity: int
    current: int


class SyncInstructions(ABC):
    """SYNC_WRITE and SYNC_READ (mixed into ``DynamixelBus``)."""

    protocol: Protocol
    retries: int
    _port: Any
    _ph: Any
    _groups: dict[tuple[Any, ...], Any]

    @abstractmethod
    def _attempts(self) -> Iterator[int]:
        """Attempt numbers 0..retries, settling the line between attempts."""

    @abstractmethod
    def _check(self, servo_id: int, what: str, error: int) -> None:
        """Raise for a status error byte: refused instruction or hardware alert."""

    def sync_write(self, name: str, values: Mapping[int, int]) -> None:
        """{ID: value} of one register in one SYNC_WRITE, sent exactly once."""
        reg = xm.register(name)
        self._sync_write(reg.address, reg.size, {s: reg.encode(v) for s, v in values.items()})

    def _sync_write(self, address: int, size: int, data: Mapping[int, bytes]) -> None:
        group = self._group(self.protocol.group_sync_write, address, size)
        group.clearParam()
        for sid, raw in data.items():
            group.addParam(sid, list(raw))
        result = group.txPacket()
        group.clearParam()
        if result != COMM_SUCCESS:
            raise DeviceError(f"servos {list(data)}: SYNC_WRITE failed: {comm_fault(result)}")

    def sync_read(self, name: str, ids: Sequence[int]) -> dict[int, int]:
        """{ID: value} of one register, signed if the register is."""
        reg = xm.register(name)
        raw = self._sync_read(reg.address, reg.size, ids)
        return {sid: reg.decode(data) for sid, data in raw.items()}

    def read_states(self, ids: Sequence[int]) -> dict[int, ServoState]:
        """Present current, velocity and position of ``ids`` in one SYNC_READ (126..135)."""
        cur, vel, pos = (xm.register(f"Present {n}") for n in ("Current", "Velocity", "Position"))
        raw = self._sync_read(cur.address, pos.address + pos.size - cur.address, ids)
        return {
            sid: ServoState(pos.decode(d[6:10]), vel.decode(d[2:6]), cur.decode(d[0:2]))
            for sid, d in raw.items()
        }

    def _sync_read(self, address: int, size: int, ids: Sequence[int]) -> dict[int, bytes]:
        """SYNC_READ, retried as a whole; raises naming the servo that failed."""
        failed, result = ids[0], COMM_SUCCESS
        for _ in self._attempts():
            group = self._group(self.protocol.group_sync_read, address, size, tuple(ids))
            failed, result, replies = sync_read_replies(group, self._ph, self._port, ids)
            if result == COMM_SUCCESS:
                for sid, (_, error) in replies.items():
                    self._check(sid, f"SYNC_READ at {address}", error)
                return {sid: data for sid, (data, _) in replies.items()}
        raise DeviceError(
            f"servo {failed}: SYNC_READ at {address} failed after {self.retries + 1} tries:"
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
