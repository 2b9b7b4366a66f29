"""The official dynamixel-sdk's packet handler on simulated XM430s, in virtual time.

``Bench`` puts XM430-W350 servos (the OpenManipulator-X's IDs 11..15 unless told)
on a simulated line (``sim._wire.Wire``, a pyserial port where pyserial is
installed) and drives them with ``dynamixel_sdk.PacketHandler(2.0)``, unmodified:
what the tests see is what a ROBOTIS example program sees. Time is the world's
(``b.world.advance``), so nothing depends on the machine's load.
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

import pytest

from armkit.devices._dxl_protocol import PortHandler
from armkit.sim import World
from armkit.sim._wire import Wire, serial_port
from armkit.sim.dynamixel import OPENMANIPULATOR_X_IDS, SimDynamixelBus

sdk = pytest.importorskip("dynamixel_sdk")
OK = sdk.COMM_SUCCESS
TORQUE, GOAL, PRESENT, MOVING_STATUS = 64, 116, 132, 123


class Bench:
    """XM430s (``ids``, at ``baudrate``) and the SDK's packet handler on them.

    ``firmware``: the Firmware Version every servo reports (their features).
    """

    def __init__(
        self,
        baudrate: int = 1_000_000,
        ids: Iterable[int] = OPENMANIPULATOR_X_IDS,
        firmware: int | None = None,
    ) -> None:
        self.world = World()
        self.bus = SimDynamixelBus(ids, clock=self.world.now)
        if firmware is not None:
            for servo in self.bus.servos.values():
                servo.memory[6] = firmware
        self.wire = Wire(self.bus, self.world, baudrate=baudrate, timeout=0)
        self.port = PortHandler(serial_port(self.wire), self.world.clock)
        self.ph = sdk.PacketHandler(2.0)

    def w(self, sid: int, address: int, size: int, value: int) -> tuple[int, int]:
        """WRITE ``value`` (``size`` bytes, two's complement) -> (comm result, error)."""
        fn = {1: self.ph.write1ByteTxRx, 2: self.ph.write2ByteTxRx, 4: self.ph.write4ByteTxRx}
        return tuple(fn[size](self.port, sid, address, value & (256**size - 1)))  # type: ignore[return-value]

    def r(self, sid: int, address: int, size: int) -> Any:
        """READ ``size`` bytes; 2 and 4 bytes as signed values (the SDK's are unsigned)."""
        fn = {1: self.ph.read1ByteTxRx, 2: self.ph.read2ByteTxRx, 4: self.ph.read4ByteTxRx}
        value, result, _ = fn[size](self.port, sid, address)
        assert result == OK, self.ph.getTxRxResult(result)
        return (
            value
            if size == 1
            else int.from_bytes(value.to_bytes(size, "little"), "little", signed=True)
        )

    def raw(self, sid: int, address: int, data: bytes) -> tuple[int, int]:
        """WRITE exactly ``data`` (any length) -> (comm result, error)."""
        return tuple(self.ph.writeTxRx(self.port, sid, address, len(data), list(data)))  # type: ignore[return-value]
