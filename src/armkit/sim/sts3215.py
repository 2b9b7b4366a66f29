"""One simulated Feetech STS3215: its memory table and its position motion.

The memory table is data (``armkit.devices._sts3215``: address, size, access, factory
default, range, sign-magnitude bit). A WRITE is taken register by register as the
servo does: a read-only register keeps its value, a value outside the register's
range is not stored, a Goal Position in position mode (Operating Mode 0) beyond Min/
Max Position Limit (9/11) is held to the limit (the limits bound "the motion stroke",
Feetech's memory table). The status byte carries no refusal (the STS error byte is
the Status register's bits, the SDK's ``ERRBIT_*``): a host finds out by reading back.

EEPROM (addresses < 40) takes effect at once; it is kept through a power cycle
(``power_cycle``) only when written while Lock (55) is 0 (Feetech: ``unLockEprom``
opens "the EEPROM save function", ``LockEprom`` closes it).

Motion: a new Goal Position (torque on) starts a trapezoid from where the servo is
driven now, at Goal Velocity [step/s] (0: the servo's top speed,
``MAX_SPEED_STEPS``) and Acceleration x 100 step/s^2 (0: no ramp); Moving (66) is 1
while it runs. Present Position = the shaft's step - Homing Offset (31). On an arm
(``feedback`` set) the shaft is the arm's joint; alone it follows the motion exactly.
Not modelled: the wheel, PWM and step modes (1..3) store the mode but move as mode 0;
a goal changed mid-move starts its trapezoid at rest; load, current, heat.
"""

from __future__ import annotations

import math
from collections.abc import Callable

from ..devices import sts3215 as sts
from ._xm430_profile import Profile, velocity_profile_times

_DEFAULTS = bytearray(sts.TABLE_SIZE)
for _reg in sts.STS3215.values():
    _DEFAULTS[_reg.address : _reg.address + _reg.size] = _reg.encode(_reg.default)


class STS3215:
    """An STS3215 with ID ``servo_id`` on ``clock`` [s], its Baud Rate set to ``baudrate``."""

    def __init__(
        self, servo_id: int, clock: Callable[[], float], *, baudrate: int = 1_000_000
    ) -> None:
        self.clock = clock
        self.memory = bytearray(_DEFAULTS)
        self.feedback: Callable[[], tuple[float, float]] | None = None
        self.registered: tuple[int, bytes] | None = None  # a REG WRITE waiting for ACTION
        self.motion = Profile(float(sts.CENTER_STEP), 0.0, clock())
        self.torque_on = False
        self.set("ID", servo_id)
        self.set("Baud Rate", sts.baud_index(baudrate))
        self.set("Goal Position", sts.CENTER_STEP)
        self.kept = bytes(self.memory[: sts.EEPROM_END])  # the EEPROM through a power cycle

    # -- registers ---------------------------------------------------------------
    def set(self, name: str, value: int) -> None:
        """Poke a register directly (no checks, no effects)."""
        reg = sts.register(name)
        self.memory[reg.address : reg.address + reg.size] = reg.encode(value)

    def value(self, name: str) -> int:
        """A register as stored (no refresh)."""
        reg = sts.register(name)
        return reg.decode(self.memory[reg.address : reg.address + reg.size])

    @property
    def baudrate(self) -> int:
        """The rate it listens at [bit/s]."""
        return sts.BAUD_RATES.get(self.value("Baud Rate"), 0)

    @property
    def error_bits(self) -> int:
        """The status packet's error byte: the Status register."""
        return self.value("Status")

    # -- the motion ----------------------------------------------------------------
    def _shaft(self, now: float) -> tuple[float, float]:
        """(position [step], velocity [step/s]) of the shaft."""
        return self.motion.at(now) if self.feedback is None else self.feedback()

    def refresh(self, now: float) -> None:
        """Present Position, Velocity and Moving from the shaft and the motion."""
        position, velocity = self._shaft(now)
        present = round(position) - self.value("Homing Offset")
        self.set("Present Position", max(-32767, min(32767, present)))
        self.set("Present Velocity", max(-32767, min(32767, round(velocity))))
        self.set("Moving", int(self.busy(now)))

    def setpoint(self, now: float) -> float | None:
        """Where the motor is driven at ``now`` [step, shaft]; None: torque off."""
        return self.motion.at(now)[0] if self.torque_on else None

    def busy(self, now: float) -> bool:
        """True while the motion runs (and torque is on)."""
        return self.torque_on and self.motion.running(now)

    def hold_at(self, tick: int) -> None:
        """Put the shaft at ``tick``, at rest, the goal there, torque on (an arm assembled
        with its servos holding)."""
        self.motion = Profile(float(tick), 0.0, self.clock())
        self.set("Goal Position", tick - self.value("Homing Offset"))
        self.set("Torque Enable", 1)
        self.torque_on = True

    def _go(self, goal: int) -> None:
        now = self.clock()
        start = self.motion.at(now)[0] if self.torque_on else self._shaft(now)[0]
        target = goal + self.value("Homing Offset")
        speed = abs(self.value("Goal Velocity")) or sts.MAX_SPEED_STEPS
        accel = self.value("Acceleration") * sts.ACCELERATION_UNIT or math.inf
        ramp, total = velocity_profile_times(target - start, min(speed, sts.MAX_SPEED_STEPS), accel)
        self.motion = Profile(start, target - start, now, ramp, total)

    def _torque(self, on: bool) -> None:
        now = self.clock()
        if on and not self.torque_on:  # holds where the shaft is
            self.motion = Profile(self._shaft(now)[0], 0.0, now)
        self.torque_on = on

    # -- instructions ----------------------------------------------------------------
    def read(self, address: int, size: int) -> bytes:
        """``size`` bytes from ``address`` after refreshing the present state."""
        self.refresh(self.clock())
        return bytes(self.memory[address : address + size])

    def write(self, address: int, data: bytes) -> None:
        """WRITE as the servo takes it (see the module notes); then the effects: torque
        before goals."""
        before = bytes(self.memory)
        end = min(sts.TABLE_SIZE, address + len(data))
        self.memory[address:end] = data[: end - address]
        touched = [
            reg
            for reg in sts.STS3215.values()
            if reg.address < end and reg.address + reg.size > address
        ]
        for reg in touched:
            self._settle(reg, before)
        if any(reg.eeprom for reg in touched) and not self.value("Lock"):
            self.kept = bytes(self.memory[: sts.EEPROM_END])
        names = {reg.name for reg in touched}
        if "Torque Enable" in names:
            self._torque(bool(self.value("Torque Enable")))
        if "Goal Position" in names and self.torque_on:
            self._go(self.value("Goal Position"))

    def _settle(self, reg: sts.Register, before: bytes) -> None:
        """Keep the register's old bytes unless the servo takes its new value."""
        span = slice(reg.address, reg.address + reg.size)
        value = reg.decode(self.memory[span])
        if not reg.accepts(value):
            self.memory[span] = before[span]
        elif reg.name == "Goal Position" and self.value("Operating Mode") == sts.MODE_POSITION:
            low, high = self.value("Min Position Limit"), self.value("Max Position Limit")
            if low < high:
                self.set("Goal Position", max(low, min(high, value)))

    def power_cycle(self) -> None:
        """Off and on: the kept EEPROM, RAM at its defaults, torque off."""
        self.memory[:] = _DEFAULTS
        self.memory[: sts.EEPROM_END] = self.kept
        self.registered = None
        self._torque(False)

    def reset(self) -> None:
        """RESET: the factory table, but the ID (so the servo still answers where it was:
        an assumption, Feetech's table does not say), kept as well; torque off."""
        servo_id = self.value("ID")
        self.memory[:] = _DEFAULTS
        self.set("ID", servo_id)
        self.kept = bytes(self.memory[: sts.EEPROM_END])
        self.registered = None
        self._torque(False)
