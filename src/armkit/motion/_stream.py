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
from ..drivers import Driver, PathFollower
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


@dataclass(frozen=True)
class NaiveStepping:
    """Wait for every waypoint. ``speed``: fraction of the max joint velocity."""

    speed: float = 1.0

    def run(self, driver: Driver, model: ArmModel, path: JointPath, clock: Clock) -> None:
        """Send each waypoint with ``wait=True``."""
        for q in path.q[1:]:
            driver.move(q, speed=self.speed, wait=True)


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
