"""One simulated XM430-W350: its control-table memory and its motion profile.

The control table is data (``armkit.devices._xm430``: address, size, sign,
access, factory default and bounding register per register; the baud rates,
the Goal Position range per operating mode), so a register the manual adds is
one row there. Writes with side effects are one row of ``Servo.effects``. The
profile (``_xm430_profile``) is evaluated from a clock, lazily: every read
refreshes the present-state registers from where the trapezoid has the servo now.

What it follows of the e-Manual (XM430-W350, Protocol 2.0 firmware):
Present Position = actual position + Homing Offset (20); Goal Position within
Min/Max Position Limit in position mode, within +-1,048,575 in extended and
current-based position mode, else data limit error (6); Goal PWM/Current/
Velocity beyond PWM/Current/Velocity Limit: error 6; EEPROM (< 64) writable
only with torque off (access error 7); Realtime Tick (120) in ms modulo 32768;
Moving (122) and Moving Status (123: in-position, profile ongoing, profile
type); Velocity/Position Trajectory (136/140) from the profile; Indirect
Address/Data (168..251, 578..661) read and write the byte their address names;
FACTORY_RESET, REBOOT (RAM back to defaults) and CLEAR (multi-turn) as
methods the bus calls.

On an arm (``feedback`` set), Present Position/Velocity are what the servo's
shaft really does (``_servo_body``: lag, speed cap); alone (``armkit emulate``)
they follow the profile exactly. Not modelled: the Following Error bit (the
simulated motor never loses its trajectory), Shutdown conditions other than an
injected overload.
"""

from __future__ import annotations

from collections.abc import Callable

from ..devices import dxl_packet as pkt
from ..devices import xm430 as xm
from ._xm430_memory import covered, merged, read_through, runs
from ._xm430_profile import (
    TICKS_PER_S2_PER_UNIT,
    TICKS_PER_S_PER_UNIT,
    Profile,
    profile_kind,
    velocity_profile_times,
)

__all__ = ["ACCESS_ERROR", "LIMIT_ERROR", "Profile", "Servo", "velocity_profile_times"]

RESULT_FAIL, LIMIT_ERROR, ACCESS_ERROR = 1, 6, 7
RESET_ALL, RESET_KEEP_ID, RESET_KEEP_ID_BAUD = 0xFF, 0x01, 0x02  # FACTORY_RESET options
_TORQUE_ENABLE = xm.register("Torque Enable").address
_REGISTERS = sorted(xm.XM430_W350.values(), key=lambda r: r.address)
_PRESENT = {  # the registers every read refreshes, looked up once
    name: xm.register(name)
    for name in (
        "Present Position", "Present Velocity", "Present Current", "Position Trajectory",
        "Velocity Trajectory", "Realtime Tick", "Moving", "Moving Status",
    )
}  # fmt: skip
_RAM = [r for r in _REGISTERS if not r.eeprom and r.writable and not r.name.startswith("Indirect")]


class Servo:
    """One simulated XM430-W350: control-table memory plus a lazily evaluated profile.

    Args:
        servo_id: its ID.  clock: its time [s].  position: where it starts [tick].
        baudrate: the rate it listens at [bit/s] (its Baud Rate register).
    """

    def __init__(
        self,
        servo_id: int,
        clock: Callable[[], float],
        position: int = 2048,
        baudrate: int = 57_600,
    ) -> None:
        self.memory = bytearray(xm.CONTROL_TABLE_SIZE)
        self._clock = clock
        self._shift = 0  # reported minus actual position [tick]: Homing Offset - CLEARed turns
        self.profile = Profile(float(position), 0.0, clock())
        self.plans = 0  # how many moves were started (a re-sent goal must not add one)
        self.feedback: Callable[[], tuple[float, float]] | None = None  # (tick, tick/s)
        self.registered: tuple[int, bytes] | None = None  # REG_WRITE waiting for ACTION
        self.factory_reset(RESET_ALL)
        self.set("ID", servo_id)
        self.set("Baud Rate", xm.baud_value(baudrate))
        self.set("Goal Position", position)
        self.set("Present Position", position)
        self.effects: dict[str, Callable[[int], None]] = {
            "Torque Enable": lambda on: self._torque(bool(on)),
            "Goal Position": self._goal,
            "Homing Offset": self._homing,
        }

    # -- registers -------------------------------------------------------------
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

    @property
    def baudrate(self) -> int:
        """The rate it listens at [bit/s], from its Baud Rate register."""
        return xm.BAUD_RATES.get(self.value("Baud Rate"), 0)

    def _frame(self) -> float:
        """Reported position minus actual position [tick]: Homing Offset and any CLEAR
        (kept in ``_shift``: the setpoint asks it at every step)."""
        return self._shift

    # -- reading -----------------------------------------------------------------
    def read(self, address: int, size: int) -> bytes:
        """``size`` bytes from ``address`` after updating the present-state registers;
        Indirect Data bytes read the byte their Indirect Address names."""
        self._refresh(self._clock())
        return read_through(self.memory, address, size)

    def _refresh(self, now: float) -> None:
        profile = self.profile
        running = profile.running(now)
        wanted, wanted_speed = profile.at(now)
        if self.feedback is not None:
            actual, velocity = self.feedback()
            position = actual + self._frame()
        else:
            position, velocity = wanted, wanted_speed
        units = velocity / TICKS_PER_S_PER_UNIT
        arrived = not running and abs(position - self.value("Goal Position")) < 1.0
        status = (xm.IN_POSITION if arrived else 0) | (xm.PROFILE_ONGOING if running else 0)
        values = {
            "Present Position": round(position),
            "Present Velocity": round(units),
            "Present Current": round(0.5 * units),
            "Position Trajectory": round(wanted),
            "Velocity Trajectory": round(wanted_speed / TICKS_PER_S_PER_UNIT),
            "Realtime Tick": int(now * 1000.0) % 32768,
            "Moving": int(running or abs(units) > self.value("Moving Threshold")),
            "Moving Status": status | profile.kind << xm.PROFILE_SHIFT,
        }
        memory = self.memory
        for name, value in values.items():
            reg = _PRESENT[name]
            memory[reg.address : reg.address + reg.size] = reg.encode(value)

    def setpoint(self, now: float) -> float | None:
        """Where the profile asks the motor to be at ``now`` [tick, actual]; None: torque off."""
        if not self.memory[_TORQUE_ENABLE]:
            return None
        return self.profile.at(now)[0] - self._frame()

    def busy(self, now: float) -> bool:
        """True while the profile is running."""
        return self.profile.running(now)

    # -- writing -----------------------------------------------------------------
    def write(self, address: int, data: bytes) -> int:
        """WRITE as the firmware does it; returns the status error number (0 = ok).
        Nothing is written unless every register written may take its value."""
        pieces = runs(self.memory, address, data)
        for start, chunk in pieces:
            error = self._check(start, chunk)
            if error:
                return error
        for start, chunk in pieces:
            for reg in covered(start, len(chunk)):
                value, effect = merged(self.memory, reg, start, chunk), self.effects.get(reg.name)
                if effect is None:
                    self.set(reg.name, value)
                else:
                    effect(value)
        return 0

    def _check(self, address: int, data: bytes) -> int:
        regs = covered(address, len(data))
        if not regs or any(not r.writable for r in regs):
            return ACCESS_ERROR
        if self.value("Torque Enable") and any(r.eeprom for r in regs):
            return ACCESS_ERROR
        if any(not self._allowed(r, merged(self.memory, r, address, data)) for r in regs):
            return LIMIT_ERROR
        return 0

    def _allowed(self, reg: xm.Register, value: int) -> bool:
        if reg.limit:
            return abs(value) <= self.value(reg.limit)
        if reg.name != "Goal Position":
            return True
        mode = self.value("Operating Mode")
        if mode not in xm.GOAL_POSITION_RANGE:
            return True
        span = xm.GOAL_POSITION_RANGE[mode]
        low, high = span or (self.value("Min Position Limit"), self.value("Max Position Limit"))
        return low <= value <= high

    def _torque(self, on: bool) -> None:
        present = self.get("Present Position")
        on = on and not self.value("Hardware Error Status")
        self.profile = Profile(float(present), 0.0, self._clock())
        self.set("Goal Position", present)
        self.set("Torque Enable", int(on))

    def _homing(self, offset: int) -> None:
        """Homing Offset moves the reported frame; the shaft stays where it is."""
        delta = offset - self.value("Homing Offset")
        self.set("Homing Offset", offset)
        self._shift += delta
        p = self.profile
        self.profile = Profile(p.start + delta, p.distance, p.t0, p.ramp, p.total, p.kind)
        self.set("Goal Position", self.value("Goal Position") + delta)

    def _goal(self, goal: int) -> None:
        self.set("Goal Position", goal)
        if not self.value("Torque Enable"):
            return
        now = self._clock()
        start, _ = self.profile.at(now)
        if round(start) == goal:  # already there: hold, no move started
            self.profile = Profile(float(goal), 0.0, now, kind=self.profile.kind)
            return
        ramp, total, kind = self._times(goal - start)
        self.profile = Profile(start, goal - start, now, ramp, total, kind)
        self.plans += 1

    def _times(self, distance: float) -> tuple[float, float, int]:
        pv, pa = self.value("Profile Velocity"), self.value("Profile Acceleration")
        if self.value("Drive Mode") & xm.DRIVE_MODE_TIME_BASED and pv > 0:
            ramp, total = min(pa, pv / 2) / 1000.0, pv / 1000.0
            return ramp, total, profile_kind(ramp, total, True)
        if self.value("Drive Mode") & xm.DRIVE_MODE_TIME_BASED:
            pa = 0
        velocity = (pv or self.value("Velocity Limit")) * TICKS_PER_S_PER_UNIT
        accel = pa * TICKS_PER_S2_PER_UNIT if pa else float("inf")
        ramp, total = velocity_profile_times(distance, velocity, accel)
        return ramp, total, profile_kind(ramp, total, pv > 0)

    # -- instructions other than READ/WRITE -----------------------------------
    def overload(self) -> None:
        """Trip the overload error: torque off, the alert bit on until REBOOT."""
        self._torque(False)
        self.set("Hardware Error Status", 0x20)

    def reboot(self) -> None:
        """REBOOT: clear the hardware error; the RAM area back to its defaults (torque off)."""
        self._torque(False)
        for reg in _RAM:
            self.set(reg.name, reg.default)
        self.set("Hardware Error Status", 0)
        self.set("Goal Position", self.get("Present Position"))
        self.registered = None

    def factory_reset(self, option: int) -> None:
        """FACTORY_RESET: every register to its factory value (``RESET_KEEP_ID`` keeps the ID,
        ``RESET_KEEP_ID_BAUD`` the ID and the Baud Rate)."""
        keep = {RESET_KEEP_ID: ("ID",), RESET_KEEP_ID_BAUD: ("ID", "Baud Rate")}.get(option, ())
        kept = {name: self.value(name) for name in keep}
        for reg in _REGISTERS:
            if reg.name not in ("Present Position", "Goal Position"):
                self.memory[reg.address : reg.address + reg.size] = reg.encode(reg.default)
        for name, value in kept.items():
            self.set(name, value)
        actual = self.profile.at(self._clock())[0] - self._shift  # the shaft stays put
        self._shift = 0
        self.profile = Profile(actual, 0.0, self._clock())
        self.set("Goal Position", round(actual))

    def clear_multi_turn(self) -> int:
        """CLEAR (option 1): Present Position back into one turn (0..4095), the shaft
        unmoved; refused (result fail) while the servo moves. Returns the error number."""
        now = self._clock()
        if self.busy(now):
            return RESULT_FAIL
        present = self.get("Present Position")
        turns = present - present % xm.TICKS_PER_TURN
        self._shift -= turns
        self.profile = Profile(self.profile.goal - turns, 0.0, now, kind=self.profile.kind)
        self.set("Goal Position", self.value("Goal Position") - turns)
        return 0

    @property
    def error_bits(self) -> int:
        """The alert bit for every status while a hardware error is latched."""
        return pkt.ALERT_BIT if self.value("Hardware Error Status") else 0
