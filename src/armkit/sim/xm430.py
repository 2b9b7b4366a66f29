"""One simulated XM430-W350: its control-table memory and its motion profile.

The control table is data (``armkit.devices._xm430``: address, size, sign,
access, factory default per register), so a register the manual adds is one
row there. The profile is evaluated from a clock, lazily: every read of the
present-state registers computes where the trapezoid has the servo now.
Velocity-based profile: Profile Velocity [0.229 rev/min] and Profile
Acceleration [214.577 rev/min^2] (0 = Velocity Limit, instant ramp).
Time-based profile (Drive Mode bit 2): Profile Velocity = total time [ms],
Profile Acceleration = ramp time [ms], clipped to half the total.

On an arm (``feedback`` set), Present Position/Velocity are what the servo's
shaft really does (``_servo_body``: lag, speed cap); alone (``armkit emulate``)
they follow the profile exactly. Goal Position is limited by Min/Max Position
Limit in position mode and to +-1,048,575 in extended position mode.

Known differences from the real servo (issue 11, point 5: the next step):
Moving Status bits, Realtime Tick, the trajectory registers, Homing Offset,
per-mode Goal Velocity/Current limits, Status Return Level, Secondary ID,
feed-forward gains and the indirect address/data areas.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

from ..devices import _dxl_packet as pkt
from ..devices import _xm430 as xm

_TICKS_PER_S_PER_UNIT = xm.VELOCITY_UNIT_RPM * xm.TICKS_PER_TURN / 60.0
_TICKS_PER_S2_PER_UNIT = xm.ACCELERATION_UNIT_RPM2 * xm.TICKS_PER_TURN / 3600.0
LIMIT_ERROR, ACCESS_ERROR = 6, 7
EXTENDED_LIMIT = 1_048_575  # Goal Position range in extended position mode [tick]
_TORQUE_ENABLE = xm.register("Torque Enable").address


@dataclass(frozen=True, slots=True)
class Profile:
    """A trapezoidal move of ``distance`` ticks from ``start`` beginning at ``t0`` [s].

    ``ramp`` is the acceleration time and ``total`` the whole move time [s].
    """

    start: float
    distance: float
    t0: float
    ramp: float = 0.0
    total: float = 0.0

    def at(self, now: float) -> tuple[float, float]:
        """(position [tick], velocity [tick/s]) at time ``now`` [s]."""
        t = now - self.t0
        if t >= self.total or self.total <= 0.0:
            return self.start + self.distance, 0.0
        peak = self.distance / (self.total - self.ramp)
        if t < self.ramp:
            return self.start + 0.5 * peak / self.ramp * t * t, peak * t / self.ramp
        if t <= self.total - self.ramp:
            return self.start + peak * (t - 0.5 * self.ramp), peak
        left = self.total - t
        return (
            self.start + self.distance - 0.5 * peak / self.ramp * left * left,
            peak * left / self.ramp,
        )


def velocity_profile_times(distance: float, velocity: float, accel: float) -> tuple[float, float]:
    """(ramp, total) [s] for ``distance`` [tick] at ``velocity`` [tick/s], ``accel`` [tick/s^2]
    (``accel`` = inf: instant ramp); triangular when the peak velocity is not reached."""
    d = abs(distance)
    if math.isinf(accel):
        return 0.0, d / velocity
    if d < velocity * velocity / accel:
        ramp = math.sqrt(d / accel)
        return ramp, 2.0 * ramp
    return velocity / accel, d / velocity + velocity / accel


class Servo:
    """One simulated XM430-W350: control-table memory plus a lazily evaluated profile.

    Args:
        servo_id: its ID.  clock: its time [s].  position: where it starts [tick].
    """

    def __init__(self, servo_id: int, clock: Callable[[], float], position: int = 2048) -> None:
        self.memory = bytearray(xm.CONTROL_TABLE_SIZE)
        for reg in xm.XM430_W350.values():
            self.memory[reg.address : reg.address + reg.size] = reg.encode(reg.default)
        self._clock = clock
        self.profile = Profile(float(position), 0.0, clock())
        self.plans = 0  # how many moves were started (a re-sent goal must not add one)
        self.feedback: Callable[[], tuple[float, float]] | None = None  # (tick, tick/s)
        self.set("ID", servo_id)
        self.set("Goal Position", position)
        self.set("Present Position", position)

    def get(self, name: str) -> int:
        """Register value, refreshed from the motion first."""
        reg = xm.register(name)
        return reg.decode(self.read(reg.address, reg.size))

    def set(self, name: str, value: int) -> None:
        """Poke a register directly (no access checks, no side effects)."""
        reg = xm.register(name)
        self.memory[reg.address : reg.address + reg.size] = reg.encode(value)

    def value(self, name: str) -> int:
        """Register value as stored (no refresh)."""
        reg = xm.register(name)
        return reg.decode(self.memory[reg.address : reg.address + reg.size])

    def read(self, address: int, size: int) -> bytes:
        """``size`` bytes from ``address`` after updating the present-state registers."""
        now = self._clock()
        running = now < self.profile.t0 + self.profile.total
        if self.feedback is not None:
            position, velocity = self.feedback()
        else:
            position, velocity = self.profile.at(now)
        units = velocity / _TICKS_PER_S_PER_UNIT
        self.set("Present Position", round(position))
        self.set("Present Velocity", round(units))
        self.set("Present Current", round(0.5 * units))
        moving = running or abs(units) > self.value("Moving Threshold")
        self.set("Moving", int(moving))
        return bytes(self.memory[address : address + size])

    def setpoint(self, now: float) -> float | None:
        """Where the profile asks the motor to be at ``now`` [tick]; None with torque off."""
        if not self.memory[_TORQUE_ENABLE]:
            return None
        profile = self.profile
        if now >= profile.t0 + profile.total:
            return profile.start + profile.distance
        return profile.at(now)[0]

    def busy(self, now: float) -> bool:
        """True while the profile is running."""
        return now < self.profile.t0 + self.profile.total

    def write(self, address: int, data: bytes) -> int:
        """WRITE as the firmware does it; returns the status error number (0 = ok)."""
        regs = [r for r in xm.XM430_W350.values() if address <= r.address < address + len(data)]
        if not regs or any(not r.writable for r in regs):
            return ACCESS_ERROR
        if self.value("Torque Enable") and any(r.eeprom for r in regs):
            return ACCESS_ERROR
        if any(r.name == "Goal Position" for r in regs) and not self._in_limits(data, address):
            return LIMIT_ERROR
        for reg in regs:
            offset = reg.address - address
            self._apply(reg, reg.decode(data[offset : offset + reg.size]))
        return 0

    def _in_limits(self, data: bytes, address: int) -> bool:
        goal = xm.register("Goal Position")
        offset = goal.address - address
        value = goal.decode(data[offset : offset + goal.size])
        if self.value("Operating Mode") == xm.MODE_EXTENDED_POSITION:
            return -EXTENDED_LIMIT <= value <= EXTENDED_LIMIT
        return self.value("Min Position Limit") <= value <= self.value("Max Position Limit")

    def _apply(self, reg: xm.Register, value: int) -> None:
        if reg.name == "Torque Enable":
            self._torque(bool(value))
        elif reg.name == "Goal Position":
            self.set(reg.name, value)
            self._plan(value)
        else:
            self.set(reg.name, value)

    def _torque(self, on: bool) -> None:
        present = self.get("Present Position")
        on = on and not self.value("Hardware Error Status")
        self.profile = Profile(float(present), 0.0, self._clock())
        self.set("Goal Position", present)
        self.set("Torque Enable", int(on))

    def _plan(self, goal: int) -> None:
        if not self.value("Torque Enable"):
            return
        now = self._clock()
        start, _ = self.profile.at(now)
        if round(start) == goal:  # already there: hold, no move started
            self.profile = Profile(float(goal), 0.0, now)
            return
        ramp, total = self._times(goal - start)
        self.profile = Profile(start, goal - start, now, ramp, total)
        self.plans += 1

    def _times(self, distance: float) -> tuple[float, float]:
        pv, pa = self.value("Profile Velocity"), self.value("Profile Acceleration")
        if self.value("Drive Mode") & xm.DRIVE_MODE_TIME_BASED:
            if pv > 0:
                return min(pa, pv / 2) / 1000.0, pv / 1000.0
            pa = 0
        velocity = (pv or self.value("Velocity Limit")) * _TICKS_PER_S_PER_UNIT
        accel = pa * _TICKS_PER_S2_PER_UNIT if pa else math.inf
        return velocity_profile_times(distance, velocity, accel)

    def overload(self) -> None:
        """Trip the overload error: torque off, the alert bit on until REBOOT."""
        self._torque(False)
        self.set("Hardware Error Status", 0x20)

    def reboot(self) -> None:
        """REBOOT: clear the hardware error; torque comes back off."""
        self.set("Hardware Error Status", 0)
        self._torque(False)

    @property
    def error_bits(self) -> int:
        """The alert bit for every status while a hardware error is latched."""
        return pkt.ALERT_BIT if self.value("Hardware Error Status") else 0
