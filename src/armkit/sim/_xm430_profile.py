"""The XM430's motion: a position profile (a trapezoid in time) or a spin (velocity and
PWM control), and how Moving Status names it.

Positions here are the shaft's own [tick] (before Homing Offset and the turns folded
away); the servo adds its frame when it reports them.

Velocity-based profile: Profile Velocity [0.229 rev/min] and Profile
Acceleration [214.577 rev/min^2] (0 = instant ramp). Time-based profile (Drive
Mode bit 2): Profile Velocity = total time [ms], Profile Acceleration = ramp
time [ms], clipped to half the total (e-Manual XM430-W350, "Profile
Velocity (112)", "Profile Acceleration (108)").
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from ..devices import xm430 as xm

F64 = NDArray[np.float64]
TICKS_PER_S_PER_UNIT = xm.VELOCITY_UNIT_RPM * xm.TICKS_PER_TURN / 60.0
TICKS_PER_S2_PER_UNIT = xm.ACCELERATION_UNIT_RPM2 * xm.TICKS_PER_TURN / 3600.0


@dataclass(frozen=True, slots=True)
class Profile:
    """A trapezoidal move of ``distance`` ticks from ``start`` beginning at ``t0`` [s].

    ``ramp`` is the acceleration time and ``total`` the whole move time [s];
    ``kind`` is its Moving Status velocity-profile type (``xm.PROFILE_*``).
    """

    start: float
    distance: float
    t0: float
    ramp: float = 0.0
    total: float = 0.0
    kind: int = xm.PROFILE_STEP

    def at(self, now: float) -> tuple[float, float]:
        """(position [tick], velocity [tick/s]) at time ``now`` [s] (before ``t0``: its start)."""
        t = max(0.0, now - self.t0)
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

    def positions(self, times: F64) -> F64:
        """``at(t)[0]`` for every time of ``times`` [s], shape (N,) [tick]: the same
        arithmetic, element by element, so each equals the scalar's to the bit."""
        t = np.maximum(0.0, times - self.t0)
        end = self.start + self.distance
        if self.total <= 0.0:
            return np.full(t.shape, end)
        peak = self.distance / (self.total - self.ramp)
        left = self.total - t
        bend = 0.5 * peak / self.ramp if self.ramp > 0.0 else 0.0  # no ramp: rows unused
        rising = self.start + bend * t * t
        falling = end - bend * left * left
        cruise = self.start + peak * (t - 0.5 * self.ramp)
        conditions = [t >= self.total, t < self.ramp, t <= self.total - self.ramp]
        return np.select(conditions, [np.full(t.shape, end), rising, cruise], falling)

    def running(self, now: float) -> bool:
        """True while the profile is still generating motion."""
        return now < self.t0 + self.total

    @property
    def goal(self) -> float:
        """Where it ends [tick]."""
        return self.start + self.distance

    def held(self, now: float) -> Profile:
        """Stopped where it is at ``now`` (the profile applied as 0)."""
        return Profile(self.at(now)[0], 0.0, now, kind=self.kind)


@dataclass(frozen=True, slots=True)
class Spin:
    """Velocity control: from ``v0`` to ``v1`` [tick/s] in ``ramp`` [s] from ``t0`` [s],
    starting at ``start`` [tick], then on at ``v1`` (e-Manual XM430-W350, "Profile
    Velocity (112)", NOTE: Velocity Control Mode uses only Profile Acceleration)."""

    start: float
    t0: float
    v0: float
    v1: float
    ramp: float = 0.0
    kind: int = xm.PROFILE_STEP

    def at(self, now: float) -> tuple[float, float]:
        """(position [tick], velocity [tick/s]) at time ``now`` [s]."""
        t = max(0.0, now - self.t0)
        if t < self.ramp:
            velocity = self.v0 + (self.v1 - self.v0) * t / self.ramp
            return self.start + 0.5 * (self.v0 + velocity) * t, velocity
        return self.start + 0.5 * (self.v0 + self.v1) * self.ramp + self.v1 * (
            t - self.ramp
        ), self.v1

    def positions(self, times: F64) -> F64:
        """``at(t)[0]`` for every time of ``times`` [s], shape (N,) [tick]."""
        return np.array([self.at(t)[0] for t in times.tolist()])

    def running(self, now: float) -> bool:
        """True while it turns or still changes speed."""
        return self.v1 != 0.0 or now < self.t0 + self.ramp

    def held(self, now: float) -> Profile:
        """Stopped where it is at ``now``."""
        return Profile(self.at(now)[0], 0.0, now, kind=self.kind)


Motion = Profile | Spin


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


def profile_kind(ramp: float, total: float, velocity_set: bool) -> int:
    """Moving Status type of a profile: step (no Profile Velocity), rectangular (no ramp),
    triangular (ramps meet), trapezoidal."""
    if not velocity_set:
        return xm.PROFILE_STEP
    if ramp <= 0.0:
        return xm.PROFILE_RECTANGULAR
    if 2.0 * ramp >= total - 1e-9:
        return xm.PROFILE_TRIANGULAR
    return xm.PROFILE_TRAPEZOIDAL
