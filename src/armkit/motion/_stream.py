"""Executing a joint path on a driver: three ways to send the waypoints.

- ``NaiveStepping``: send a waypoint, wait until the arm is there, repeat. The
  controller's own interpolation stops at every waypoint (001's stutter).
- ``EarlyStreaming``: send the next waypoint once the arm has covered
  ``fraction`` of the way to the current one (001's fix).
- ``TimedStreaming``: time the path first (tool speed and acceleration, joint
  limits), then send the interpolated point every ``1/rate`` s, each as a move
  lasting exactly one period.

All three take a ``Clock``: real time on hardware, the simulator's virtual time.

A driver that cannot follow a stream of small moves says so by being a
``PathFollower`` (its own ``follow_path(model, q, points)``): timed motors (the OWI-535) turn one joint at a
time, each turn at least their smallest reliable step, so ``follow`` hands them
the whole path and they step through waypoints they can make (a 20 mm line: 5 runs
in 1.8 s instead of 92 two-leg runs in 29.8 s); the streamer is not used.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Protocol

import numpy as np
from numpy.typing import NDArray

from .._clock import Clock
from .._errors import DeviceError, InputError
from ..drivers import Driver, Forecast, Forecaster, PathFollower, PathForecaster
from ..model import ArmModel
from ._paths import corners
from ._plan import JointPath
from ._timing import time_path

F64 = NDArray[np.float64]
WAYPOINT_TIMEOUT = 10.0  # [s] for one waypoint before the arm counts as stuck


class Streamer(Protocol):
    """A way to execute a planned path, the arm already at its first point."""

    def run(self, driver: Driver, model: ArmModel, path: JointPath, clock: Clock) -> None:
        """Move along ``path`` and return when the arm has stopped at its last point."""
        ...

    def forecast(
        self, forecaster: Forecaster, model: ArmModel, path: JointPath, motor_s: float
    ) -> Forecast:
        """What ``run`` does on a driver that forecasts as ``forecaster``, from the path's
        first point with ``motor_s`` [s] used."""
        ...


@dataclass(frozen=True)
class NaiveStepping:
    """Wait for every waypoint. ``speed``: fraction of the max joint velocity."""

    speed: float = 1.0

    def run(self, driver: Driver, model: ArmModel, path: JointPath, clock: Clock) -> None:
        """Send each waypoint with ``wait=True``."""
        for q in path.q[1:]:
            driver.move(q, speed=self.speed, wait=True)

    def forecast(
        self, forecaster: Forecaster, model: ArmModel, path: JointPath, motor_s: float
    ) -> Forecast:
        """Every waypoint's move, one after another."""
        return stepped(forecaster, path.q, self.speed, motor_s)


@dataclass(frozen=True)
class EarlyStreaming:
    """001's early waypoints: the next one goes out when the arm has covered
    ``fraction`` of the way to the current one, polling every ``poll`` [s].
    At the path's corners it waits until the arm is there (no corner cutting)."""

    fraction: float = 0.5
    speed: float = 1.0
    poll: float = 0.002

    def run(self, driver: Driver, model: ArmModel, path: JointPath, clock: Clock) -> None:
        """Stream the waypoints, then wait at the last."""
        if not 0.0 < self.fraction <= 1.0:
            raise InputError(f"fraction must be in (0, 1], got {self.fraction}")
        stops = set(corners(path.points).tolist())
        for k in range(1, path.q.shape[0] - 1):
            driver.move(path.q[k], speed=self.speed, wait=k in stops)
            self._wait_progress(driver, path.q[k - 1], path.q[k], clock)
        driver.move(path.q[-1], speed=self.speed, wait=True)

    def forecast(
        self, forecaster: Forecaster, model: ArmModel, path: JointPath, motor_s: float
    ) -> Forecast:
        """At most ``NaiveStepping``'s time (the waypoints overlap; a bound, not a forecast)."""
        return stepped(forecaster, path.q, self.speed, motor_s)

    def _wait_progress(self, driver: Driver, prev: F64, q: F64, clock: Clock) -> None:
        step = q - prev
        length2 = float(step @ step)
        deadline = clock.now() + WAYPOINT_TIMEOUT
        while length2 > 0 and float((driver.read() - prev) @ step) < self.fraction * length2:
            if clock.now() > deadline:
                raise DeviceError(
                    f"the arm did not move towards a waypoint in {WAYPOINT_TIMEOUT} s"
                )
            clock.sleep(self.poll)


@dataclass(frozen=True)
class TimedStreaming:
    """Time-parametrised streaming at ``rate`` [Hz]: tool speed up to ``speed`` [m/s],
    acceleration ``accel`` [m/s^2], stopping at corners, within the joint limits."""

    rate: float = 100.0
    speed: float = 0.05
    accel: float = 0.5

    def run(self, driver: Driver, model: ArmModel, path: JointPath, clock: Clock) -> None:
        """Send the point for the end of each period, lasting one period."""
        if not self.rate > 0:
            raise InputError(f"rate must be > 0 Hz, got {self.rate}")
        timed = time_path(model, path, self.speed, self.accel)
        period = 1.0 / self.rate
        start = clock.now()
        ticks = int(np.ceil(timed.duration / period - 1e-9))
        for k in range(1, ticks + 1):
            driver.move(timed.at(min(k * period, timed.duration)), duration=period, wait=False)
            clock.sleep(start + k * period - clock.now())
        driver.move(path.q[-1], wait=True)

    def forecast(
        self, forecaster: Forecaster, model: ArmModel, path: JointPath, motor_s: float
    ) -> Forecast:
        """Its periods, then the waiting move onto the last point (already there)."""
        if not self.rate > 0:
            raise InputError(f"rate must be > 0 Hz, got {self.rate}")
        duration = time_path(model, path, self.speed, self.accel).duration
        period = 1.0 / self.rate
        ticks = int(np.ceil(duration / period - 1e-9))
        end = forecaster.forecast(path.q[-1], path.q[-1], motor_s=motor_s)
        return Forecast(ticks * period + end.seconds, end.q, end.motor_s)


def stepped(forecaster: Forecaster, q: F64, speed: float, motor_s: float) -> Forecast:
    """Waiting moves through the joint path ``q`` [rad], (N, dof), at ``speed``."""
    seconds, at, used = 0.0, q[0].copy(), motor_s
    for goal in q[1:]:
        end = forecaster.forecast(at, goal, speed=speed, motor_s=used)
        seconds, at, used = seconds + end.seconds, end.q, end.motor_s
    return Forecast(seconds, at, used)


def forecast_follow(
    forecaster: Forecaster,
    model: ArmModel,
    q0: F64,
    path: JointPath,
    streamer: Streamer,
    motor_s: float = 0.0,
) -> Forecast:
    """What ``follow`` does from ``q0`` [rad]: the move onto the path's start, then the
    streamer's run; a driver that follows paths its own way, its own forecast of that."""
    if isinstance(forecaster, PathForecaster):
        return forecaster.forecast_path(model, q0, path.q, path.points, motor_s)
    onto = forecaster.forecast(q0, path.q[0], motor_s=motor_s)
    run = streamer.forecast(forecaster, model, path, onto.motor_s)
    return Forecast(onto.seconds + run.seconds, run.q, run.motor_s)


def follow(
    driver: Driver, model: ArmModel, path: JointPath, streamer: Streamer, clock: Clock
) -> None:
    """Move to the path's first point (a joint move), then run ``streamer`` along it; a
    driver with its own ``follow_path`` (timed motors) follows the path its own way."""
    if isinstance(driver, PathFollower):
        driver.follow_path(model, path.q, path.points)
        return
    driver.move(path.q[0], wait=True)
    streamer.run(driver, model, path, clock)
