"""Servo settings on a Dynamixel bus: torque, operating mode, EEPROM writes, profiles.

A mixin of ``DynamixelBus``: every method here is made of the bus's own
``read``, ``write`` and ``_sync_write`` (values in the control table's units).
"""

from __future__ import annotations

from abc import ABC, abstractmethod
from collections.abc import Iterable, Iterator, Mapping, Sequence
from contextlib import contextmanager

from . import _xm430 as xm


class ServoSettings(ABC):
    """Settings made of register reads and writes (mixed into ``DynamixelBus``)."""

    @abstractmethod
    def read(self, servo_id: int, name: str, *, alert_ok: bool = False) -> int:
        """The register ``name`` of servo ``servo_id``."""

    @abstractmethod
    def write(self, servo_id: int, name: str, value: int) -> None:
        """Write ``value`` to the register ``name`` of servo ``servo_id``."""

    @abstractmethod
    def _sync_write(self, address: int, size: int, data: Mapping[int, bytes]) -> None:
        """One SYNC_WRITE of ``size`` bytes at ``address``: servo ID -> bytes."""

    def set_torque(self, ids: Iterable[int], on: bool) -> None:
        """Torque Enable on every servo in ``ids``."""
        for sid in ids:
            self.write(sid, "Torque Enable", int(on))

    @contextmanager
    def torque(self, ids: Sequence[int], on: bool) -> Iterator[None]:
        """Set torque for the block, then put every servo back as it was."""
        before = {sid: self.read(sid, "Torque Enable") for sid in ids}
        self.set_torque(ids, on)
        try:
            yield
        finally:
            for sid, state in before.items():
                self.write(sid, "Torque Enable", state)

    def set_operating_mode(self, servo_id: int, mode: int) -> None:
        """Operating Mode (3 position, 4 extended, 5 current-based position, ...)."""
        self.set_eeprom(servo_id, "Operating Mode", mode)

    def set_eeprom(self, servo_id: int, name: str, value: int) -> None:
        """Write an EEPROM register if it differs, torque off around it, then restored."""
        if self.read(servo_id, name) != value:
            with self.torque([servo_id], False):
                self.write(servo_id, name, value)

    def set_time_based(self, ids: Iterable[int], on: bool) -> None:
        """Drive Mode bit 2: profiles in ms (True) or in velocity/acceleration units."""
        for sid in ids:
            drive = self.read(sid, "Drive Mode") & ~xm.DRIVE_MODE_TIME_BASED
            self.set_eeprom(sid, "Drive Mode", drive | (xm.DRIVE_MODE_TIME_BASED if on else 0))

    def set_profiles(self, profiles: Mapping[int, tuple[int, int]]) -> None:
        """{ID: (acceleration, velocity)} in one SYNC_WRITE of Profile Acceleration..Velocity."""
        accel, velocity = xm.register("Profile Acceleration"), xm.register("Profile Velocity")
        data = {sid: accel.encode(a) + velocity.encode(v) for sid, (a, v) in profiles.items()}
        self._sync_write(accel.address, accel.size + velocity.size, data)
