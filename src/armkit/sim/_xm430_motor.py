"""The simulated XM430's motor: what the shaft does for the goal of the Operating Mode.

Position modes (3, 4, 5) follow a profile to Goal Position (Profile Velocity and
Acceleration, velocity- or time-based: Drive Mode bit 2); Velocity Control Mode (1)
spins at Goal Velocity, reached with Profile Acceleration (e-Manual XM430-W350,
"Profile Velocity (112)", NOTE: t1 = 64 x Goal Velocity / Profile Acceleration [ms],
time-based: t1 = Profile Acceleration [ms]); PWM Control Mode (16) spins at the
unloaded speed of Goal PWM. Motion is kept in the shaft's own ticks; the frame (turns
folded away + Homing Offset, ``notes``) is added when a position is reported.

The Bus Watchdog is evaluated lazily: a watchdog that expired since the last
instruction packet stops the motion at the moment it expired, as the bus sees it at
its next packet and as every simulation step sees it (``setpoint`` only reads).
"""

from __future__ import annotations

import math
import struct
from collections.abc import Callable
from typing import Protocol

from ..devices import xm430 as xm
from ..devices import xm430_notes as notes
from ._xm430_drive import Drive
from ._xm430_profile import (
    TICKS_PER_S2_PER_UNIT,
    TICKS_PER_S_PER_UNIT,
    Motion,
    Profile,
    Spin,
    profile_kind,
    velocity_profile_times,
)


class Servo(Protocol):
    """What the motor needs of its servo (``sim.xm430.XM430``): the control table by
    name, the raw memory, the device clock [s] and the arm's feedback, if on an arm."""

    memory: bytearray
    clock: Callable[[], float]
    feedback: Callable[[], tuple[float, float]] | None

    def value(self, name: str) -> int: ...

    def set(self, name: str, value: int) -> None: ...


TURN = xm.TICKS_PER_TURN
NO_LOAD_TICKS_PER_S = notes.NO_LOAD_RPM * TURN / 60.0
_PRESENT = tuple(  # the registers every read refreshes, by address: one block of the table
    sorted(
        (xm.register(name) for name in (
            "Present Position", "Present Velocity", "Present Current", "Present PWM",
            "Position Trajectory", "Velocity Trajectory", "Realtime Tick", "Moving",
            "Moving Status",
        )),
        key=lambda reg: reg.address,
    )
)  # fmt: skip
_FIRST = _PRESENT[0].address
_CODE = {
    (1, False): "B",
    (1, True): "b",
    (2, False): "H",
    (2, True): "h",
    (4, False): "I",
    (4, True): "i",
}
# the block's layout, from the table (little-endian, no gaps: Realtime Tick .. Position Trajectory)
_BLOCK = struct.Struct("<" + "".join(_CODE[r.size, r.signed] for r in _PRESENT))


class Motor:
    """The motor of ``servo`` with its shaft at ``position`` [tick] at time ``now`` [s]."""

    def __init__(self, servo: Servo, position: float, now: float) -> None:
        self.servo = servo
        self.motion: Motion = Profile(position, 0.0, now)
        self.turns = 0  # [tick] added to the shaft's count by folding (whole turns)
        self.plans = 0  # position moves started (a re-sent goal starts none)
        self.heard_at = now  # the last instruction packet for this servo [s]

    # -- where it is ------------------------------------------------------------
    def frame(self) -> int:
        """Reported minus shaft position [tick]: the folded turns and the Homing Offset
        that applies (Position Control Mode ignores one beyond +-1,024)."""
        offset = self.servo.value("Homing Offset")
        position_mode = self.servo.value("Operating Mode") == xm.MODE_POSITION
        if position_mode and abs(offset) > notes.POSITION_MODE_HOMING_LIMIT:
            offset = 0
        return self.turns + offset

    def shaft(self, now: float) -> tuple[float, float]:
        """The shaft's (position [tick], velocity [tick/s]): the arm's, or the motion's."""
        feedback = self.servo.feedback
        return self.motion.at(now) if feedback is None else feedback()

    def drive(self) -> Drive:
        """What the motor is driven to until the next packet: the motion, stopped where
        an armed Bus Watchdog will stop it, torque on or off. Reads only: a simulation
        step calls it from the world's thread while the bus's thread may be answering
        the host."""
        return Drive(self.motion, self.expiry(), bool(self.servo.value("Torque Enable")))

    def refresh(self, now: float) -> None:
        """Write the present-state registers from the shaft and the motion at ``now``."""
        self.watch(now)
        servo, motion = self.servo, self.motion
        frame = self.frame()
        position, velocity = self.shaft(now)
        wanted, wanted_speed = motion.at(now)
        units = velocity / TICKS_PER_S_PER_UNIT
        running = motion.running(now)
        if isinstance(motion, Spin):
            ongoing = now < motion.t0 + motion.ramp
            arrived = not ongoing
        else:
            ongoing = running
            arrived = not running and abs(position + frame - servo.value("Goal Position")) < 1.0
        status = (xm.IN_POSITION if arrived else 0) | (xm.PROFILE_ONGOING if ongoing else 0)
        values = {
            "Present Position": round(position + frame),
            "Present Velocity": round(units),
            "Present Current": round(0.5 * units),
            "Present PWM": round(notes.FULL_PWM * velocity / NO_LOAD_TICKS_PER_S),
            "Position Trajectory": round(wanted + frame),
            "Velocity Trajectory": round(wanted_speed / TICKS_PER_S_PER_UNIT),
            "Realtime Tick": int(now * 1000.0) % 32768,
            "Moving": int(running or abs(units) > servo.value("Moving Threshold")),
            "Moving Status": status | motion.kind << xm.PROFILE_SHIFT,
        }
        try:  # the block at once
            _BLOCK.pack_into(servo.memory, _FIRST, *(values[r.name] for r in _PRESENT))
        except struct.error:  # a value that does not fit: InputError naming its register
            for reg in _PRESENT:
                reg.encode(values[reg.name])
            raise

    # -- what changes it ------------------------------------------------------------
    def place(self, position: float, now: float) -> None:
        """The shaft at ``position`` [tick], at rest, nothing folded (assembling an arm)."""
        self.motion, self.turns = Profile(position, 0.0, now), 0

    def hold(self, now: float) -> None:
        """Stop where the shaft is (an arm's shaft: where it really is)."""
        self.motion = Profile(self.shaft(now)[0], 0.0, now, kind=self.motion.kind)

    def fold(self, now: float) -> None:
        """Present Position (less Homing Offset) into one turn, 0 ~ 4,095; Goal Position
        moves with it (the shaft does not move)."""
        count = self.shaft(now)[0] + self.turns
        delta = -TURN * math.floor(round(count) / TURN)
        self.turns += delta
        self.servo.set("Goal Position", self.servo.value("Goal Position") + delta)

    def power_on(self, now: float) -> None:
        """As at power on or REBOOT: at rest, within one turn, goal where it is."""
        self.hold(now)
        self.fold(now)
        self.heard_at = now
        self.servo.set("Goal Position", round(self.shaft(now)[0] + self.frame()))

    def torque(self, on: bool) -> None:
        """Torque Enable: on (not with a hardware error latched): hold here, folded into
        one turn in Position Control Mode, then follow the mode's goal; off: free."""
        servo, now = self.servo, self.servo.clock()
        on = on and not servo.value("Hardware Error Status")
        servo.set("Torque Enable", int(on))
        self.hold(now)
        self.heard_at = now
        if not on:
            return
        mode = servo.value("Operating Mode")
        if mode == notes.ONE_TURN_MODE:
            self.fold(now)
        servo.set("Goal Position", round(self.shaft(now)[0] + self.frame()))
        if mode in notes.SPIN_MODES:
            self.goal_spin()

    def mode_changed(self, mode: int) -> None:
        """A new Operating Mode: hold; entering Position Control Mode folds the count."""
        now = self.servo.clock()
        self.hold(now)
        if mode == notes.ONE_TURN_MODE:
            self.fold(now)

    def goal_position(self, goal: int) -> None:
        """A new Goal Position [tick, reported]: a profile there, in a position mode."""
        servo = self.servo
        if not servo.value("Torque Enable"):
            return
        if servo.value("Operating Mode") not in notes.POSITION_MODES:
            return
        now = servo.clock()
        start = self.motion.at(now)[0]
        target = goal - self.frame()
        if round(start) == target:  # already there: hold, no move started
            self.motion = Profile(float(target), 0.0, now, kind=self.motion.kind)
            return
        ramp, total, kind = self._times(target - start)
        self.motion = Profile(start, target - start, now, ramp, total, kind)
        self.plans += 1

    def goal_spin(self) -> None:
        """A new Goal Velocity or Goal PWM: in its mode, spin toward its speed."""
        servo = self.servo
        mode = servo.value("Operating Mode")
        if not servo.value("Torque Enable") or mode not in notes.SPIN_MODES:
            return
        now = servo.clock()
        start, v0 = self.motion.at(now)
        if mode == xm.MODE_PWM:
            v1 = servo.value("Goal PWM") / notes.FULL_PWM * NO_LOAD_TICKS_PER_S
            self.motion = Spin(start, now, v1, v1)
            return
        v1 = servo.value("Goal Velocity") * TICKS_PER_S_PER_UNIT
        accel = servo.value("Profile Acceleration")
        if servo.value("Drive Mode") & xm.DRIVE_MODE_TIME_BASED:
            ramp = accel / 1000.0
        else:
            ramp = abs(v1 - v0) / (accel * TICKS_PER_S2_PER_UNIT) if accel else 0.0
        kind = xm.PROFILE_TRAPEZOIDAL if ramp > 0.0 else xm.PROFILE_STEP
        self.motion = Spin(start, now, v0, v1, ramp, kind)

    def _times(self, distance: float) -> tuple[float, float, int]:
        servo = self.servo
        pv, pa = servo.value("Profile Velocity"), servo.value("Profile Acceleration")
        time_based = servo.value("Drive Mode") & xm.DRIVE_MODE_TIME_BASED
        if time_based and pv > 0:  # the ramp never beyond half the total
            ramp, total = min(pa, pv / 2) / 1000.0, pv / 1000.0
            return ramp, total, profile_kind(ramp, total, True)
        if time_based:
            pa = 0
        velocity = (pv or servo.value("Velocity Limit")) * TICKS_PER_S_PER_UNIT
        accel = pa * TICKS_PER_S2_PER_UNIT if pa else float("inf")
        ramp, total = velocity_profile_times(distance, velocity, accel)
        return ramp, total, profile_kind(ramp, total, pv > 0)

    # -- the Bus Watchdog -------------------------------------------------------------
    def heard(self, now: float) -> None:
        """An instruction packet for this servo at ``now`` [s] (after ``watch``)."""
        self.heard_at = now

    def expiry(self) -> float | None:
        """When the armed Bus Watchdog expires [s] (None: not armed, or torque off)."""
        servo = self.servo
        limit = servo.value("Bus Watchdog")
        if limit <= 0 or not servo.value("Torque Enable"):
            return None
        return self.heard_at + limit * notes.WATCHDOG_UNIT_S

    def watch(self, now: float) -> None:
        """Trip the Bus Watchdog if it expired before ``now``: the motion stops where it
        was when it expired, Bus Watchdog reads -1."""
        expired = self.expiry()
        if expired is not None and now > expired:
            self.motion = self.motion.held(expired)
            self.servo.set("Bus Watchdog", notes.WATCHDOG_TRIPPED)
