"""Time along a joint path: a Cartesian trapezoidal speed profile between stops
(the ends and every corner), slowed uniformly where a joint would exceed its
acceleration limit or ``VELOCITY_SHARE`` of its velocity limit.

The share leaves room for the bus: a streamed segment sent a little late (a
status read, a USB frame) must still reach its point within its period, and
the drivers refuse a segment faster than the limit. At the full limit the
OpenManipulator-X's 100 Hz stream was refused mid-circle (a 10 ms segment
starting 0.25 ms late needed 10.25 ms).
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from .._errors import InputError
from ..model import ArmModel
from ._paths import corners
from ._plan import JointPath

F64 = NDArray[np.float64]
VELOCITY_SHARE = 0.9  # of each joint's velocity limit, at the most, along a timed path


@dataclass(frozen=True)
class TimedPath:
    """A joint path with a time for every point.

    Attributes:
        t: times [s], shape (N,), from 0, non-decreasing.
        q: joint angles [rad], shape (N, dof).
    """

    t: F64
    q: F64

    @property
    def duration(self) -> float:
        """Time of the whole path [s]."""
        return float(self.t[-1])

    def at(self, t: float) -> F64:
        """Joint angles [rad], shape (dof,), linearly interpolated at time ``t`` [s]."""
        return np.array([np.interp(t, self.t, col) for col in self.q.T])


def time_path(model: ArmModel, path: JointPath, speed: float, accel: float) -> TimedPath:
    """Times for ``path``: tool speed up to ``speed`` [m/s] with acceleration
    ``accel`` [m/s^2], stopping at every corner, then stretched until no joint
    exceeds its model acceleration limit or ``VELOCITY_SHARE`` of its velocity limit."""
    if not (speed > 0 and accel > 0):
        raise InputError(f"speed and acceleration must be > 0, got {speed}, {accel}")
    s = np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(path.points, axis=0), axis=1))])
    stops = np.unique(np.concatenate([[0], corners(path.points), [len(s) - 1]]))
    t = np.zeros_like(s)
    for a, b in itertools.pairwise(stops):
        piece = s[a : b + 1] - s[a]
        t[a : b + 1] = t[a] + _trapezoid_times(piece, speed, accel)
    return TimedPath(t * _stretch(model, t, path.q), path.q)


def _trapezoid_times(s: F64, vmax: float, amax: float) -> F64:
    """Time [s] at each arc length ``s`` [m] (from 0 to s[-1]) of a rest-to-rest trapezoid."""
    length = float(s[-1])
    if length <= 0:
        return np.zeros_like(s)
    v = min(vmax, float(np.sqrt(amax * length)))
    d_acc = v * v / (2.0 * amax)
    rise = np.sqrt(2.0 * np.clip(s, 0.0, d_acc) / amax)
    cruise = (np.clip(s, d_acc, length - d_acc) - d_acc) / v
    fall = np.sqrt(2.0 * np.clip(length - s, 0.0, d_acc) / amax)
    return np.where(s <= length - d_acc, rise + cruise, length / v + v / amax - fall)


def _stretch(model: ArmModel, t: F64, q: F64) -> float:
    """Factor >= 1 by which times must grow for every joint to keep within its limits."""
    if q.shape[0] < 3:
        return 1.0
    dt = np.diff(t)
    ok = dt > 1e-12
    vel = np.diff(q, axis=0)[ok] / dt[ok, None]
    vmax = VELOCITY_SHARE * np.array([j.max_velocity for j in model.joints])
    amax = np.array([j.max_acceleration for j in model.joints])
    by_vel = float(np.max(np.abs(vel) / vmax, initial=0.0))
    mid = (t[:-1] + t[1:])[ok] / 2.0
    dmid = np.diff(mid)
    acc = np.diff(vel, axis=0)[dmid > 1e-12] / dmid[dmid > 1e-12, None]
    by_acc = float(np.sqrt(np.max(np.abs(acc) / amax, initial=0.0)))
    return max(1.0, by_vel, by_acc)
