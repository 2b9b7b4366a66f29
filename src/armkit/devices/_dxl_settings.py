"""Servo settings on a Dynamixel bus: torque, operating mode, EEPROM writes, profiles.

Every setting is made of three functions ``DynamixelBus`` gives it: a register read,
a register write (both retried by the bus's policy) and one SYNC_WRITE of raw bytes.
Values are in the control table's units (``_xm430``).
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Iterator, Mapping, Sequence
from contextlib import contextmanager

from . import _xm430 as xm

ReadRegister = Callable[[int, str], int]  # (servo ID, register name) -> value
WriteRegister = Callable[[int, str, int], None]  # (servo ID, register name, value)
WriteBlock = Callable[[int, int, Mapping[int, bytes]], None]  # SYNC_WRITE (address, size, data)


class ServoSettings:
    """Settings made of register reads and writes.

    Args:
        read: reads one register of one servo.
        write: writes one register of one servo (an absolute value).
        write_block: one SYNC_WRITE of ``size`` bytes at ``address``: {ID: bytes}.
    """

    def __init__(self, read: ReadRegister, write: WriteRegister, write_block: WriteBlock) -> None:
        self._read, self._write, self._write_block = read, write, write_block

    def set_torque(self, ids: Iterable[int], on: bool) -> None:
        """Torque Enable on every servo in ``ids``."""
        for sid in ids:
            self._write(sid, "Torque Enable", int(on))

    @contextmanager
    def torque(self, ids: Sequence[int], on: bool) -> Iterator[None]:
        """Set torque for the block, then put every servo back as it was."""
        before = {sid: self._read(sid, "Torque Enable") for sid in ids}
        self.set_torque(ids, on)
        try:
            yield
        finally:
            for sid, state in before.items():
                self._write(sid, "Torque Enable", state)

    def set_operating_mode(self, servo_id: int, mode: int) -> None:
        """Operating Mode (3 position, 4 extended, 5 current-based position, ...)."""
        self.set_eeprom(servo_id, "Operating Mode", mode)

    def set_eeprom(self, servo_id: int, name: str, value: int) -> None:
        """Write an EEPROM register if it differs, torque off around it, then restored."""
        if self._read(servo_id, name) != value:
            with self.torque([servo_id], False):
                self._write(servo_id, name, value)

    def set_time_based(self, ids: Iterable[int], on: bool) -> None:
        """Drive Mode bit 2: profiles in ms (True) or in velocity/acceleration units."""
        for sid in ids:
            drive = self._read(sid, "Drive Mode") & ~xm.DRIVE_MODE_TIME_BASED
            self.set_eeprom(sid, "Drive Mode", drive | (xm.DRIVE_MODE_TIME_BASED if on else 0))

    def set_profiles(self, profiles: Mapping[int, tuple[int, int]]) -> None:
        """{ID: (acceleration, velocity)} in one SYNC_WRITE of Profile Acceleration..Velocity."""
        accel, velocity = xm.register("Profile Acceleration"), xm.register("Profile Velocity")
        data = {sid: accel.encode(a) + velocity.encode(v) for sid, (a, v) in profiles.items()}
        self._write_block(accel.address, accel.size + velocity.size, data)
