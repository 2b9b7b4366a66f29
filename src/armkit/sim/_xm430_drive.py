"""What a simulated XM430 drives its motor to until the host's next bytes: its motion,
cut short where an armed Bus Watchdog will stop it, or nothing with torque off.

Only a packet changes a servo's drive (a new goal, torque, a watchdog heard), so a
simulation step takes the drives once (``Drives``, one per servo of a bus) and
evaluates them at every step time instead of asking each servo at each step;
``setpoints`` evaluates a stretch of steps at once (``Profile.positions``: the same
arithmetic, so the same numbers to the bit).
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np
from numpy.typing import NDArray

from ._xm430_profile import Motion

F64 = NDArray[np.float64]


class Drive:
    """A servo's ``motion`` [tick, shaft], stopped at ``until`` [s] (an armed Bus
    Watchdog's expiry; None: never), with ``torque`` on or off. Not changed once made
    (a plain class: made for every servo before every run of steps)."""

    __slots__ = ("motion", "torque", "until")

    def __init__(self, motion: Motion, until: float | None, torque: bool) -> None:
        self.motion, self.until, self.torque = motion, until, torque

    def setpoint(self, now: float) -> float | None:
        """Where the motor is driven at ``now`` [s] [tick]; None: torque off."""
        if not self.torque:
            return None
        return self.motion.at(now if self.until is None else min(now, self.until))[0]

    def setpoints(self, times: F64) -> F64 | None:
        """``setpoint`` at every time of ``times`` [s], shape (N,) [tick]; None: torque off."""
        if not self.torque:
            return None
        return self.motion.positions(times if self.until is None else np.minimum(times, self.until))

    def busy(self, now: float) -> bool:
        """True while the motion runs at ``now`` [s] (and the watchdog has not stopped it)."""
        return self.motion.running(now) and (self.until is None or now <= self.until)

    def settled(self, now: float) -> bool:
        """True when the setpoint stays what it is at ``now`` [s] from then on."""
        return not self.torque or not self.busy(now)


class Drives:
    """A bus's servos as an arm's outputs (``_servo_body.Outputs``, channel = the key the
    bus keeps the servo under) until the host's next bytes: ``Drive``s taken at once."""

    def __init__(self, drives: Mapping[int, Drive]) -> None:
        self.drives = dict(drives)

    def setpoint(self, channel: int, t: float) -> float | None:
        """Where servo ``channel`` drives its motor at ``t`` [s] [tick]; None: torque off."""
        drive = self.drives.get(channel)
        return None if drive is None else drive.setpoint(t)

    def setpoints(self, channel: int, times: F64) -> F64 | None:
        """``setpoint`` at every time of ``times`` [s], shape (N,); None: torque off."""
        drive = self.drives.get(channel)
        return None if drive is None else drive.setpoints(times)

    def settled(self, channel: int, t: float) -> bool:
        """True when servo ``channel``'s setpoint stays what it is at ``t`` [s] from then on."""
        drive = self.drives.get(channel)
        return drive is None or drive.settled(t)

    def busy(self, t: float) -> bool:
        """True while any servo's motion runs."""
        return any(drive.busy(t) for drive in self.drives.values())

    def frozen(self) -> Drives:
        """Itself (already taken)."""
        return self
